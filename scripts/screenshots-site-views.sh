#!/usr/bin/env bash
# Screenshots of the 2D map and the 3D view of the built-in simulated site and of `ocu-sim`
# with 1,000 trucks (10 Hz), 20 UGVs and 3 rollers, at 1366x768 and 1920x1080, written to docs/.
# Usage: scripts/screenshots-site-views.sh [BUILD_DIR] [SETTLE_S]
set -euo pipefail
build=${1:-build}
settle=${2:-15}
work=$(mktemp -d)
sim=""
trap 'kill ${sim:+"$sim"} 2>/dev/null || true; rm -rf "$work"' EXIT
shot() { # out view size [extra args...]
  local out=$1 view=$2 size=$3
  shift 3
  XDG_CONFIG_HOME="$work/config" env -u DISPLAY QT_QPA_PLATFORM=offscreen "$build/app/ocu" "$@" \
    --screenshot "$out" --view "$view" --settle "$settle" --size "$size" >>"$work/ocu.log" 2>&1 ||
    { echo "screenshot $out failed"; tail -20 "$work/ocu.log"; exit 1; }
  echo "$out"
}
for size in 1366x768 1920x1080; do
  shot "docs/map-2d-site-$size.png" map "$size"
  shot "docs/view-3d-$size.png" 3d "$size"
done
"$build/app/ocu-sim" --trucks 1000 --position-rate 10 --ugvs 20 --rollers 3 --write-config "$work/site.json" \
  >"$work/sim.log" 2>&1 &
sim=$!
for _ in $(seq 100); do
  [ -s "$work/site.json" ] && python3 -c "import json,sys; json.load(open(sys.argv[1]))" "$work/site.json" 2>/dev/null && break
  sleep 0.2
done
for size in 1366x768 1920x1080; do
  shot "docs/map-2d-1000trucks-$size.png" map "$size" --config "$work/site.json" --no-sim
  shot "docs/view-3d-1000trucks-$size.png" 3d "$size" --config "$work/site.json" --no-sim
done
