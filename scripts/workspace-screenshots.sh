#!/usr/bin/env bash
# Screenshots of every workspace at 1366x768 and 1920x1080 on the built-in simulated site and on the paving
# demo (which runs OSYRIS only: its Dispatch and UGV workspaces are not offered), offscreen, into
# docs/screenshots/workspaces/.
# Usage: scripts/workspace-screenshots.sh [BUILD_DIR]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
ocu=$(cd "${1:-$root/build}" && pwd)/app/ocu
out=$root/docs/screenshots/workspaces
mkdir -p "$out"
cd "$(mktemp -d)"
# The default arrangements: no arrangement saved by an earlier run or by the user is restored.
export XDG_CONFIG_HOME=$PWD/config
shot() { # FILE SETTLE ARGS...
  local file=$1 settle=$2
  shift 2
  env -u DISPLAY QT_QPA_PLATFORM=offscreen timeout 90 "$ocu" --screenshot "$out/$file" --settle "$settle" \
    --no-record "$@" >/dev/null 2>&1 || echo "failed: $file"
}
for size in 1366x768 1920x1080; do
  for ws in dispatch compaction ugv monitor all; do
    shot "site-$ws-$size.png" 6 --workspace "$ws" --size "$size"
  done
  for ws in compaction monitor all; do
    shot "paving-$ws-$size.png" 8 --config "$root/resources/sites/paving-demo.json" --workspace "$ws" --size "$size"
  done
done
