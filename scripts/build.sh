#!/usr/bin/env bash
# Configures and builds the OCU into build/ (RelWithDebInfo, Ninja, ccache). Extra arguments go to cmake.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${OCU_BUILD_DIR:-$root/build}"
jobs="${OCU_JOBS:-$(nproc)}"
export CCACHE_DIR="${CCACHE_DIR:-$root/.cache/ccache}"
# The Qt targets use precompiled headers (cmake/OcuPch.cmake); ccache caches their TUs only with this sloppiness.
export CCACHE_SLOPPINESS="${CCACHE_SLOPPINESS:-pch_defines,time_macros}"
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo "$@" >/dev/null
start=$(date +%s)
cmake --build "$build" -j "$jobs"
echo "build: done in $(( $(date +%s) - start )) s ($build)"
