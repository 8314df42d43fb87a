#!/usr/bin/env bash
# CPU of the real console window under Xvfb at 1920x1080 with `ocu-sim` driving
# 1,000 trucks at 10 Hz, 20 UGVs and 3 rollers. Prints CPU % of one core per thread of `ocu` over a window
# (from /proc/<pid>/task/*/stat), the GUI thread first, plus the load average.
# Usage: scripts/gui-load.sh [BUILD_DIR] [WARMUP_S] [MEASURE_S]
# WORKSPACE=<dispatch|compaction|ugv|monitor|all> (default dispatch: the dispatcher's view of the fleet).
# With PERF_OUT=<file>, after the measurement the GUI thread is sampled for 15 s more with
# `perf record --call-graph dwarf` (Qt is built without frame pointers):
#   PERF_OUT=/tmp/gui.perf scripts/gui-load.sh build 40 30 && perf report -i /tmp/gui.perf --no-children
set -euo pipefail
build=${1:-build}
warmup=${2:-40}
measure=${3:-30}
workspace=${WORKSPACE:-dispatch}
work=$(mktemp -d)
pid=""
trap 'kill ${pid:+"$pid"} $(jobs -p) 2>/dev/null || true; rm -rf "$work"' EXIT
"$build/app/ocu-sim" --trucks 1000 --position-rate 10 --ugvs 20 --rollers 3 --write-config "$work/site.json" \
  >"$work/sim.log" 2>&1 &
sim=$!
for _ in $(seq 100); do
  [ -s "$work/site.json" ] && python3 -c "import json,sys; json.load(open(sys.argv[1]))" "$work/site.json" 2>/dev/null && break
  sleep 0.2
done
# A fresh settings directory: the first start (maximized at the screen's size, default layout: 2D map shown,
# 3D view a hidden tab).
XDG_CONFIG_HOME="$work/config" xvfb-run -a -s "-screen 0 1920x1080x24" \
  "$build/app/ocu" --config "$work/site.json" --no-sim --workspace "$workspace" >"$work/ocu.log" 2>&1 &
for _ in $(seq 100); do
  pid=""
  for p in $(pgrep -f -- "--config $work/site.json" || true); do # our ocu, not another one on the host
    [ "$(cat /proc/"$p"/comm 2>/dev/null)" = ocu ] && pid=$p
  done
  [ -n "$pid" ] && break
  sleep 0.2
done
[ -n "$pid" ] || { echo "ocu did not start"; cat "$work/ocu.log"; exit 1; }
sleep "$warmup"
hz=$(getconf CLK_TCK)
snap() { for t in /proc/"$pid"/task/*; do
  echo "$(basename "$t") $(cat "$t/comm" | tr ' ' '_') $(awk '{print $14+$15}' "$t/stat")"; done; }
snap >"$work/a"
sleep "$measure"
snap >"$work/b"
[ -d /proc/"$pid" ] || { echo "ocu ended early"; cat "$work/ocu.log"; exit 1; }
echo "ocu pid $pid, workspace $workspace, ${measure} s window after ${warmup} s warm-up; $(uptime | sed 's/.*load/load/')"
join <(sort "$work/a") <(sort "$work/b") | awk -v hz="$hz" -v s="$measure" -v pid="$pid" '
  { cpu = ($5 - $3) / hz / s * 100; name = ($1 == pid ? "GUI(main)" : $2);
    tot[name] += cpu; n[name]++; all += cpu }
  END { printf "  %-22s %6.1f %%\n", "GUI(main)", tot["GUI(main)"];
        for (k in tot) if (k != "GUI(main)") printf "  %-22s %6.1f %% (%d threads)\n", k, tot[k], n[k];
        printf "  %-22s %6.1f %%\n", "process total", all }'
if [ -n "${PERF_OUT:-}" ]; then
  perf record -F 199 --call-graph dwarf,16384 -t "$pid" -o "$PERF_OUT" -- sleep 15 >/dev/null 2>&1 || echo "perf record failed"
  echo "perf samples of the GUI thread in $PERF_OUT"
fi
kill "$sim" 2>/dev/null || true
