#!/usr/bin/env bash
# Checks the built Debian package on a fresh Debian 12 root (docs/packaging.md): debootstrap from the Debian
# mirror, the .deb installed there with apt (its dependencies from Debian, not from this machine), then
#   ocu --version; an offscreen screenshot of the built-in site; a 10-second headless run;
#   systemd-analyze verify on the unit (the root's own systemd);
#   the service by hand as systemd would start it (systemd itself cannot run as PID 1 in a chroot): user ocu,
#   the unit's resource limits and environment, ExecStartPre, ExecStart; `list` through the command socket;
#   SIGTERM and the time until it has stopped (at most 2 s);
#   lintian on the .deb (no error); apt-get purge (user, state and /etc/ocu gone).
# Needs root (debootstrap, chroot, mounts). Usage: scripts/package-check.sh [path/to/ocu_*.deb]
# Prints each stage's time; the whole output is also in build-pkgcheck/package-check.log.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
work="${OCU_PKGCHECK_DIR:-$root/build-pkgcheck}"
mirror="${OCU_DEBIAN_MIRROR:-http://deb.debian.org/debian}"
deb="${1:-$(ls "$root"/build-release/packages/ocu_*.deb 2>/dev/null | head -1)}"
[ -f "$deb" ] || { echo "package-check: no .deb (run scripts/package.sh first)" >&2; exit 2; }
deb="$(cd "$(dirname "$deb")" && pwd)/$(basename "$deb")"
mkdir -p "$work"
log="$work/package-check.log"
exec > >(tee "$log") 2>&1

chroot_dir="$work/root"
t0=$(date +%s.%N)
stage_start=$t0
stage() { # prints the time of the stage that ended, names the next
  local now; now=$(date +%s.%N)
  [ -n "${stage_name:-}" ] && printf 'package-check: %-34s %6.1f s\n' "$stage_name" "$(echo "$now - $stage_start" | bc)"
  stage_name="$1"; stage_start=$now
  [ -n "$1" ] && echo "== $1"
  return 0
}
fail() { echo "package-check: FAILED: $*"; exit 1; }
in_root() { chroot "$chroot_dir" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin LANG=C.UTF-8 "$@"; }
mounted=()
cleanup() {
  [ -n "${ocu_pid:-}" ] && kill "$ocu_pid" 2>/dev/null || true
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do umount -l "${mounted[$i]}" 2>/dev/null || true; done
}
trap cleanup EXIT

stage "tools on this machine"
need=()
for t in debootstrap:debootstrap lintian:lintian bc:bc python3:python3; do
  command -v "${t%%:*}" >/dev/null || need+=("${t##*:}")
done
if [ ${#need[@]} -gt 0 ]; then
  apt-get update -q && DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${need[@]}"
fi
echo "package: $deb ($(stat -c %s "$deb") bytes)"
echo "Depends: $(dpkg-deb -f "$deb" Depends)"
# Nothing outside /usr, /etc/ocu, /var/lib/ocu (the unit and the menu entry are under /usr).
outside=$(dpkg-deb -c "$deb" | awk '{print $6}' | grep -vE '^\./(usr/.*)?$|^\./etc/ocu/|^\./var/lib/ocu/' || true)
[ -z "$outside" ] || fail "files outside /usr, /etc/ocu, /var/lib/ocu: $outside"
if dpkg-deb -f "$deb" Depends | tr ',' '\n' | grep -qE -- '-dev( |$)'; then fail "depends on a -dev package"; fi

stage "debootstrap bookworm (minbase)"
rm -rf "$chroot_dir"
debootstrap --variant=minbase bookworm "$chroot_dir" "$mirror" >"$work/debootstrap.log" 2>&1 ||
  { tail -20 "$work/debootstrap.log"; fail "debootstrap"; }
for m in proc sys dev dev/pts; do
  case $m in
  proc) mount -t proc proc "$chroot_dir/proc" ;;
  sys) mount -t sysfs sys "$chroot_dir/sys" ;;
  dev) mount --bind /dev "$chroot_dir/dev" ;;
  dev/pts) mount --bind /dev/pts "$chroot_dir/dev/pts" ;;
  esac
  mounted+=("$chroot_dir/$m")
done
cp /etc/resolv.conf "$chroot_dir/etc/resolv.conf"
printf 'deb %s bookworm main\ndeb %s bookworm-updates main\ndeb http://deb.debian.org/debian-security bookworm-security main\n' \
  "$mirror" "$mirror" >"$chroot_dir/etc/apt/sources.list"

stage "apt install the .deb"
cp "$deb" "$chroot_dir/tmp/"
in_root apt-get update -q >/dev/null
in_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "/tmp/$(basename "$deb")" \
  >"$work/apt-install.log" 2>&1 || { tail -30 "$work/apt-install.log"; fail "apt-get install"; }
echo "installed: $(in_root dpkg-query -W -f='${Package} ${Version}' ocu), $(grep -c '^Setting up' "$work/apt-install.log") packages set up"
in_root getent passwd ocu || fail "no user ocu"
in_root stat -c '%n %U:%G %a' /etc/ocu /var/lib/ocu

stage "ocu --version"
in_root ocu --version
in_root ocu-sim --version

stage "offscreen screenshot 1366x768"
in_root env HOME=/tmp/home QT_QPA_PLATFORM=offscreen ocu --screenshot /tmp/site.png --size 1366x768 \
  --no-record >"$work/screenshot.log" 2>&1 || { cat "$work/screenshot.log"; fail "screenshot"; }
cp "$chroot_dir/tmp/site.png" "$work/site-1366x768.png"
python3 - "$work/site-1366x768.png" <<'PY'
import struct, sys
with open(sys.argv[1], 'rb') as f:
    head = f.read(24)
w, h = struct.unpack('>II', head[16:24])
print(f"screenshot: {sys.argv[1]} {w}x{h}")
sys.exit(0 if (w, h) == (1366, 768) else 1)
PY

stage "headless run, 10 s"
in_root env HOME=/tmp/home ocu --headless --duration 10 --no-record </dev/null >"$work/headless.jsonl" \
  2>"$work/headless.log" || { cat "$work/headless.log"; fail "headless run"; }
echo "headless: $(wc -l <"$work/headless.jsonl") JSON lines, $(grep -c '"type":"machine"' "$work/headless.jsonl") machine lines"
[ "$(grep -c '"type":"machine"' "$work/headless.jsonl")" -gt 0 ] || fail "no machine line"

stage "systemd-analyze verify (root's systemd)"
in_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends systemd man-db \
  >"$work/apt-systemd.log" 2>&1 || { tail -20 "$work/apt-systemd.log"; fail "apt-get install systemd"; }
cp "$chroot_dir/usr/share/doc/ocu/examples/demo-site.json" "$chroot_dir/etc/ocu/demo.json"
in_root systemd-analyze verify /usr/lib/systemd/system/ocu-monitor@demo.service 2>&1 | tee "$work/verify.log"
[ ! -s "$work/verify.log" ] || fail "systemd-analyze verify reported the above"
echo "systemd-analyze verify: no finding"

stage "service by hand: start, list, SIGTERM"
unit="$chroot_dir/usr/lib/systemd/system/ocu-monitor@.service"
unit_value() { sed -n "s/^$1=//p" "$unit" | sed 's/%i/demo/g'; }
envs=$(grep '^Environment=' "$unit" | sed 's/^Environment=//; s/%i/demo/g' | tr '\n' ' ')
# What systemd would create: RuntimeDirectory (0750 ocu:ocu), StateDirectory.
install -d -m 0750 -o "$(stat -c %u "$chroot_dir/var/lib/ocu")" -g "$(stat -c %g "$chroot_dir/var/lib/ocu")" \
  "$chroot_dir/run/ocu" "$chroot_dir/run/ocu/demo" "$chroot_dir/var/lib/ocu/demo"
# ExecStartPre as the service user, with the unit's environment.
in_root $envs setpriv --reuid=ocu --regid=ocu --init-groups $(unit_value ExecStartPre) || fail "ExecStartPre"
rtprio=$(unit_value LimitRTPRIO)
nice=$(unit_value LimitNICE)
# The unit's limits (LimitNICE=-10 is RLIMIT_NICE 30), then the user, umask, no new privileges, no stdin/stdout.
# Raising a hard limit needs CAP_SYS_RESOURCE, which some containers withhold even from root: then without them.
limits=(prlimit --rtprio="$rtprio:$rtprio" --nice="$((20 - nice)):$((20 - nice))")
if ! "${limits[@]}" true 2>/dev/null; then
  echo "service: this machine cannot raise RLIMIT_RTPRIO/RLIMIT_NICE (no CAP_SYS_RESOURCE): started without them"
  limits=()
fi
chroot "$chroot_dir" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin $envs \
  "${limits[@]}" \
  setpriv --reuid=ocu --regid=ocu --init-groups --no-new-privs --inh-caps=-all --bounding-set=-all \
  sh -c "umask $(unit_value UMask); exec $(unit_value ExecStart)" </dev/null >/dev/null 2>"$work/service.log" &
ocu_pid=$!
sock="$chroot_dir/run/ocu/demo.sock"
for _ in $(seq 100); do [ -S "$sock" ] && break; sleep 0.2; done
[ -S "$sock" ] || { cat "$work/service.log"; fail "no command socket"; }
echo "socket: $(in_root stat -c '%n %U:%G %a' /run/ocu/demo.sock) (run folder $(in_root stat -c '%U:%G %a' /run/ocu))"
[ "$(stat -c %a "$sock")" = 660 ] || fail "socket mode is not 0660"
python3 - "$sock" <<'PY' || fail "list through the socket"
import json, socket, sys, time
s = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
s.connect(sys.argv[1])
s.settimeout(10)
s.sendall(b'{"cmd":"list","req":1}\n')
buf, deadline = b"", time.time() + 10
while time.time() < deadline:
    buf += s.recv(65536)
    for line in buf.split(b"\n")[:-1]:
        o = json.loads(line)
        if o.get("type") == "result" and o.get("req") == 1:
            print("socket answer:", json.dumps(o))
            sys.exit(0 if o.get("ok") else 1)
sys.exit(1)
PY
t_term=$(date +%s.%N)
kill -TERM "$ocu_pid"
# The chroot's `sh` exec'd ocu: $ocu_pid is ocu itself.
stopped=""
for _ in $(seq 100); do
  if ! kill -0 "$ocu_pid" 2>/dev/null; then stopped=1; break; fi
  sleep 0.02
done
wait "$ocu_pid" && rc=0 || rc=$?
ocu_pid=""
stop_s=$(echo "$(date +%s.%N) - $t_term" | bc)
printf 'service: stopped %s, exit status %s, %.2f s after SIGTERM\n' "${stopped:+yes}" "$rc" "$stop_s"
grep -E 'stop-path|SIGTERM' "$work/service.log" || true
[ -n "$stopped" ] && [ "$rc" = 0 ] && [ "$(echo "$stop_s <= 2" | bc)" = 1 ] || fail "stop on SIGTERM"
[ ! -e "$sock" ] || fail "socket file left behind"

stage "lintian"
lintian --info --tag-display-limit 0 "$deb" >"$work/lintian.log" 2>&1 || true
grep -E '^[EW]: ' "$work/lintian.log" | sort -u || true
echo "lintian: $(grep -c '^E: ' "$work/lintian.log" || true) errors, $(grep -c '^W: ' "$work/lintian.log" || true) warnings"
if grep -q '^E: ' "$work/lintian.log"; then fail "lintian errors"; fi

stage "apt-get purge"
in_root env DEBIAN_FRONTEND=noninteractive apt-get purge -y -q ocu >"$work/apt-purge.log" 2>&1 ||
  { tail -20 "$work/apt-purge.log"; fail "purge"; }
for p in /usr/bin/ocu /usr/bin/ocu-sim /etc/ocu /var/lib/ocu /usr/share/ocu /usr/lib/systemd/system/ocu-monitor@.service; do
  [ ! -e "$chroot_dir$p" ] || fail "left after purge: $p"
done
! in_root getent passwd ocu >/dev/null || fail "user ocu left after purge"
echo "purge: binaries, /etc/ocu, /var/lib/ocu and the user ocu are gone"

stage ""
printf 'package-check: PASSED in %.0f s\n' "$(echo "$(date +%s.%N) - $t0" | bc)"
