#!/usr/bin/env bash
# The run command: installs what is missing, builds, and starts the console. Without arguments it opens
# the built-in simulated site; any arguments are passed to `ocu` (e.g. --config site.json).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
OCU_BUILD_DIR="${OCU_BUILD_DIR:-$root/build}" "$root/scripts/build.sh"
exec "${OCU_BUILD_DIR:-$root/build}/app/ocu" "$@"
