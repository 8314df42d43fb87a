#!/usr/bin/env bash
# The test command: installs what is missing, builds, and runs every test headless (GUI tests on Qt's
# offscreen platform, OpenGL/VTK tests under xvfb-run). CTest prints the summary line.
#   scripts/test.sh               the whole suite
#   scripts/test.sh --sanitize    protocol, simulator, model and bridge tests under AddressSanitizer + UBSan
#   scripts/test.sh --tsan        the stacks' and bridges' threaded tests under ThreadSanitizer
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/install-deps.sh"
unset DISPLAY # every test must run without an X server of the user's; xvfb tests start their own
export QT_QPA_PLATFORM=offscreen
# Sanitizer runs: their own build directory, only the tests asked for (built and run), the rest untouched.
sanitized_run() { # build-dir sanitizers ctest-selection...
  local build="$1" sanitize="$2"
  shift 2
  export CCACHE_DIR="${CCACHE_DIR:-$root/.cache/ccache}"
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DOCU_SANITIZE="$sanitize" \
    -DOCU_WITH_VTK=OFF -DOCU_BUILD_BENCH=OFF >/dev/null
  cd "$build"
  mapfile -t targets < <(ctest -N "$@" | sed -n 's/^ *Test *#[0-9]*: *//p')
  cmake --build . -j "$(nproc)" --target "${targets[@]}"
  exec ctest -j4 --output-on-failure --timeout 900 "$@"
}
if [ "${1:-}" = "--sanitize" ]; then
  # AddressSanitizer + UBSan: the protocol stacks, the simulators, the models and the bridges (plain C++ and
  # the Qt models over it).
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  sanitized_run "$root/build-asan" address,undefined -L "protocols|jaus|osyris|iso23725|sim|models"
fi
if [ "${1:-}" = "--tsan" ]; then
  # ThreadSanitizer: the tests where io threads and the GUI thread meet (the stacks over loopback, the
  # bridges). Debian's Qt is not built with TSan: scripts/tsan.supp names the few Qt internals whose
  # synchronisation TSan cannot see (each entry says why); nothing of ours is suppressed.
  export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 suppressions=$root/scripts/tsan.supp"
  # The list: every *_stack, *_transport and *bridge* test, and the end-to-end tests that start io threads
  # (simulators, foreign peers, the OSYRIS hostile station, the three stacks under malformed frames). Left
  # out: test_iso_dispatch, which links the whole application (widgets) for the same IsoStack/IsoBridge
  # threads that the ISO bridge tests run.
  sanitized_run "$root/build-tsan" thread -R "^test_(common|jaus_transport|jaus_stack|jaus_foreign|\
iso_e2e|iso_e2e_tls|iso_foreign_dispatch|iso_ws_urgent|sim_ahs_services|\
osyris_stack|osyris_hostile|osyris_snapshot|osyris_site|osyris_pass_count_layer|console_hostile_frames|\
iso_bridge|iso_bridge_positions|jaus_bridge_threads|iso_bridge_threads|osyris_bridge_threads|jaus_bridge_foreign)$"
fi
build="${OCU_BUILD_DIR:-$root/build}"
OCU_BUILD_DIR="$build" "$root/scripts/build.sh"
cd "$build"
exec ctest -j8 --output-on-failure --timeout 300
