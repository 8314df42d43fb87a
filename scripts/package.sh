#!/usr/bin/env bash
# Builds the Debian package `ocu` (docs/packaging.md): a Release build in its own folder (build-release/, beside
# the developers' build/), man pages from --help, then CPack's DEB generator. Prints the .deb's path, size and
# Depends line. Not part of build.sh or test.sh. Extra arguments go to cmake.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${OCU_RELEASE_DIR:-$root/build-release}"
jobs="${OCU_JOBS:-$(nproc)}"
export CCACHE_DIR="${CCACHE_DIR:-$root/.cache/ccache}"
export CCACHE_SLOPPINESS="${CCACHE_SLOPPINESS:-pch_defines,time_macros}"
"$root/scripts/install-deps.sh"
start=$(date +%s)
# No tests or benchmarks: the package holds ocu and ocu-sim only.
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX=/usr -DOCU_PACKAGE=ON \
  -DOCU_BUILD_TESTS=OFF -DOCU_BUILD_BENCH=OFF "$@" >/dev/null
cmake --build "$build" -j "$jobs"
built=$(date +%s)
rm -rf "$build/packages"
(cd "$build" && cpack -G DEB >/dev/null)
deb=$(ls "$build"/packages/ocu_*.deb)
echo "package: $deb ($(du -h "$deb" | cut -f1), $(stat -c %s "$deb") bytes)"
echo "package: $(dpkg-deb -f "$deb" Depends | sed 's/^/Depends: /')"
echo "package: build $((built - start)) s, cpack $(($(date +%s) - built)) s"
