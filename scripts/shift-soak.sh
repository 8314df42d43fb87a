#!/usr/bin/env bash
# A shift at full load, compressed: ocu-sim (1,000 trucks at 10 Hz, 20 UGVs, the paver and 3 rollers) and the
# console against it, with the flight recorder, the OSYRIS ribbon store file and (where the PostgreSQL server
# binaries are installed) the shared control-room history on a throwaway server. Every 15 s it samples the
# console's RSS, threads and file descriptors, the recording folder, the SQLite WAL files, the events and
# alarms printed; after the warm-up it fits the growth per hour (least squares) and fails when RSS grows by
# more than OCU_SOAK_RSS_MB_PER_H (default 5) or threads or file descriptors grow at all.
#   scripts/shift-soak.sh [SECONDS] [headless|window]     default: 3600 headless
# Environment: OCU_SOAK_WARMUP_S (default 600), OCU_SOAK_SAMPLE_S (15), OCU_BUILD_DIR (build), OCU_SOAK_DIR
# (where the run's files and samples go; default a new folder under /tmp, kept for inspection),
# OCU_SOAK_OSYRIS_SPEEDUP (the paving train's time-lapse, default 1: real pace), OCU_SOAK_WRAPPER (a tool the
# console runs under, e.g. "heaptrack -o /tmp/soak-heap"; its RSS then includes the tool's).
# Not in CI (it runs for an hour). Loopback only; everything it starts it ends, also on Ctrl-C.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
duration="${1:-3600}"
mode="${2:-headless}"
warmup="${OCU_SOAK_WARMUP_S:-600}"
every="${OCU_SOAK_SAMPLE_S:-15}"
bound="${OCU_SOAK_RSS_MB_PER_H:-5}"
speedup="${OCU_SOAK_OSYRIS_SPEEDUP:-1}"
build="${OCU_BUILD_DIR:-$root/build}"
dir="${OCU_SOAK_DIR:-$(mktemp -d /tmp/ocu-soak.XXXXXX)}"
mkdir -p "$dir"
if [ "$duration" -le "$warmup" ]; then
  echo "shift-soak: the duration ($duration s) must be longer than the warm-up ($warmup s)" >&2
  exit 2
fi
case "$mode" in headless | window) ;; *)
  echo "shift-soak: mode is headless or window, not $mode" >&2
  exit 2
  ;;
esac
[ -x "$build/app/ocu" ] && [ -x "$build/app/ocu-sim" ] || {
  echo "shift-soak: build first ($build/app/ocu, ocu-sim)" >&2
  exit 2
}

pids=()
pgdir=""
console=""
cleanup() {
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
  [ -n "$console" ] && kill "$console" 2>/dev/null || true # under a wrapper or xvfb-run: not in pids
  wait "${pids[@]}" 2>/dev/null || true
  if [ -n "$pgdir" ] && [ -f "$pgdir/data/postmaster.pid" ]; then
    runuser -u "$pguser" -- "$pgbin/pg_ctl" -D "$pgdir/data" -m immediate stop >/dev/null 2>&1 || true
  fi
}
trap cleanup EXIT INT TERM

# The simulated site at full load; it writes the console's site configuration.
# The paving train at its real pace (ocu-sim's default is a 30x time-lapse for demos, which paves, counts and
# sends crew messages 30 hours' worth per hour: the pass-count grid and the event log then grow 30 times
# faster than in any shift; see docs/reliability.md).
"$build/app/ocu-sim" --trucks 1000 --position-rate 10 --ugvs 20 --rollers 3 --speedup "$speedup" \
  --write-config "$dir/sim-site.json" --duration $((duration + 120)) >"$dir/ocu-sim.log" 2>&1 &
pids+=($!)
for _ in $(seq 1 120); do [ -s "$dir/sim-site.json" ] && break; sleep 0.5; done
[ -s "$dir/sim-site.json" ] || { echo "shift-soak: ocu-sim wrote no configuration (see $dir/ocu-sim.log)" >&2; exit 1; }

# A throwaway PostgreSQL server on a Unix socket in $dir (initdb refuses root: run it as postgres/nobody).
history=""
pgbin="$(ls -d /usr/lib/postgresql/*/bin 2>/dev/null | sort -V | tail -1 || true)"
if [ -n "$pgbin" ] && [ -x "$pgbin/initdb" ]; then
  pgdir="$dir/pg"
  mkdir -p "$pgdir"
  pguser="$(id -un)"
  if [ "$(id -u)" -eq 0 ]; then
    pguser="$(getent passwd postgres >/dev/null && echo postgres || echo nobody)"
    chown "$pguser" "$pgdir"
  fi
  runuser -u "$pguser" -- "$pgbin/initdb" -D "$pgdir/data" -A trust -U ocu -E UTF8 --locale=C --no-sync \
    >"$pgdir/initdb.log" 2>&1
  runuser -u "$pguser" -- "$pgbin/pg_ctl" -D "$pgdir/data" -l "$pgdir/server.log" -w -t 60 \
    -o "-k $pgdir -c listen_addresses= -p 5432 -c fsync=off" start >/dev/null
  history="host=$pgdir port=5432 user=ocu dbname=postgres"
else
  echo "shift-soak: no PostgreSQL server binaries: the run has no shared history"
fi

# The console's site file: the simulator's plus the ribbon store file and the history.
python3 - "$dir" "$history" <<'EOF'
import json, sys
d, history = sys.argv[1], sys.argv[2]
site = json.load(open(d + "/sim-site.json"))
site.setdefault("osyris", {})["sqliteFile"] = d + "/ribbons.sqlite"
if history:
    site["history"] = {"postgres": {"conninfo": history, "console": "soak", "outbox": d + "/outbox.sqlite"}}
json.dump(site, open(d + "/site.json", "w"), indent=1)
EOF

mkdir -p "$dir/recordings"
args=(--config "$dir/site.json" --no-sim --record "$dir/recordings")
# OCU_SOAK_WRAPPER runs the console under a tool that execs it, e.g. "heaptrack -o $dir/heaptrack".
read -r -a wrapper <<<"${OCU_SOAK_WRAPPER:-}"
if [ "$mode" = headless ]; then
  # The headless monitor ends at end of input: its stdin is a FIFO this script holds open, so the console
  # also ends when the script does, however it ends.
  mkfifo "$dir/console.in"
  "${wrapper[@]}" "$build/app/ocu" --headless "${args[@]}" <"$dir/console.in" >"$dir/console.out" \
    2>"$dir/console.err" &
  pids+=($!)
  exec 3>"$dir/console.in"
  pattern="^$build/app/ocu --headless"
else
  command -v xvfb-run >/dev/null || { echo "shift-soak: window mode needs xvfb-run (package xvfb)" >&2; exit 2; }
  xvfb-run -a -s "-screen 0 1920x1080x24 -nolisten tcp" "${wrapper[@]}" "$build/app/ocu" "${args[@]}" \
    >"$dir/console.out" 2>"$dir/console.err" &
  pids+=($!)
  pattern="^$build/app/ocu --config $dir/"
fi
for _ in $(seq 1 60); do
  console="$(pgrep -n -f "$pattern" || true)"
  [ -n "$console" ] && break
  sleep 0.5
done
[ -n "$console" ] || { echo "shift-soak: the console did not start (see $dir/console.err)" >&2; exit 1; }
echo "shift-soak: $mode console pid $console, $duration s, warm-up $warmup s, samples every $every s in $dir"

samples="$dir/samples.tsv"
echo -e "t_s\trss_kb\tthreads\tfds\trecording_kb\twal_kb\tevents\talarms" >"$samples"
start=$(date +%s)
while :; do
  now=$(date +%s)
  t=$((now - start))
  [ -d "/proc/$console" ] || { echo "shift-soak: the console ended after $t s (see $dir/console.err)" >&2; exit 1; }
  rss=$(awk '/VmRSS/ {print $2}' "/proc/$console/status")
  threads=$(ls "/proc/$console/task" | wc -l)
  fds=$(ls "/proc/$console/fd" | wc -l)
  rec=$(du -sk "$dir/recordings" | cut -f1)
  # A WAL file that does not exist (yet) counts 0.
  wal=$({ cat "$dir"/*.sqlite-wal "$dir"/recordings/*.sqlite-wal 2>/dev/null || true; } | wc -c)
  events=$(grep -c '"type":"event"' "$dir/console.out" 2>/dev/null || true)
  alarms=$(grep -c '"requires_ack":true' "$dir/console.out" 2>/dev/null || true)
  echo -e "$t\t$rss\t$threads\t$fds\t$rec\t$((wal / 1024))\t${events:-0}\t${alarms:-0}" >>"$samples"
  [ "$t" -ge "$duration" ] && break
  sleep "$every"
done

# Growth per hour after the warm-up: least-squares slope of each column.
python3 - "$samples" "$warmup" "$bound" <<'EOF'
import sys
path, warmup, bound = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
rows = [l.rstrip("\n").split("\t") for l in open(path)]
head, data = rows[0], [[float(x) for x in r] for r in rows[1:]]
data = [r for r in data if r[0] >= warmup]
if len(data) < 3:
    print("shift-soak: fewer than 3 samples after the warm-up"); sys.exit(1)
def slope(i):
    xs = [r[0] / 3600 for r in data]; ys = [r[i] for r in data]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
print(f"after the warm-up: {len(data)} samples over {(data[-1][0] - data[0][0]) / 60:.1f} min")
units = {"rss_kb": ("RSS", 1 / 1024, "MB"), "recording_kb": ("recording folder", 1 / 1024, "MB"),
         "wal_kb": ("SQLite WAL files", 1 / 1024, "MB"), "threads": ("threads", 1, ""),
         "fds": ("file descriptors", 1, ""), "events": ("events", 1, ""), "alarms": ("alarms", 1, "")}
fail = False
for i, name in enumerate(head[1:], start=1):
    label, scale, unit = units[name]
    first, last = data[0][i] * scale, data[-1][i] * scale
    print(f"  {label:18s} {first:10.1f} -> {last:10.1f} {unit:2s}  growth {slope(i) * scale:+9.2f} {unit}/h")
rss_growth = slope(1) / 1024
if rss_growth > bound:
    print(f"shift-soak: FAIL: RSS grows {rss_growth:.2f} MB/h (bound {bound} MB/h)"); fail = True
for i, label in ((2, "threads"), (3, "file descriptors")):
    if max(r[i] for r in data) > data[0][i]:
        print(f"shift-soak: FAIL: {label} grew ({data[0][i]:.0f} -> {max(r[i] for r in data):.0f})"); fail = True
print("shift-soak: " + ("FAIL" if fail else "PASS"))
sys.exit(1 if fail else 0)
EOF
