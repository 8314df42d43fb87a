#!/usr/bin/env bash
# The test command: installs what is missing, builds, and runs every test headless (GUI tests on Qt's
# offscreen platform, OpenGL/VTK tests under xvfb-run). CTest prints the summary line.
#   scripts/test.sh               the whole suite
#   scripts/test.sh --sanitize    protocol and simulator tests again under AddressSanitizer + UBSan
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
unset DISPLAY # every test must run without an X server of the user's; xvfb tests start their own
export QT_QPA_PLATFORM=offscreen
if [ "${1:-}" = "--sanitize" ]; then
  # Only the protocol and simulator tests (plain C++ under test): configure, build exactly those, run them.
  build="$root/build-asan"
  labels="protocols|jaus|osyris|iso23725|sim"
  export CCACHE_DIR="${CCACHE_DIR:-$root/.cache/ccache}"
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DOCU_SANITIZE=address,undefined \
    -DOCU_WITH_VTK=OFF -DOCU_BUILD_BENCH=OFF >/dev/null
  cd "$build"
  mapfile -t targets < <(ctest -N -L "$labels" | sed -n 's/^ *Test *#[0-9]*: *//p')
  cmake --build . -j "$(nproc)" --target "${targets[@]}"
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  exec ctest -j2 --output-on-failure --timeout 600 -L "$labels"
fi
build="${OCU_BUILD_DIR:-$root/build}"
OCU_BUILD_DIR="$build" "$root/scripts/build.sh"
cd "$build"
exec ctest -j2 --output-on-failure --timeout 300
