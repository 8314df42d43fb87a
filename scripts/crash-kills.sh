#!/usr/bin/env bash
# Kills the console with SIGKILL N times (default 20) at random moments while it records, keeps the OSYRIS
# ribbon store and sends the control-room history through its outbox, and prints one row per kill (see
# docs/reliability.md "Crash safety"). It runs tests/app/test_crash_safety, which CI runs with 8 kills:
#   scripts/crash-kills.sh [N]            OCU_CRASH_SEED=S repeats a run's random delays
# Builds ocu, ocu-sim and the test into OCU_BUILD_DIR (default build/, configured already); OCU_CRASH_NO_BUILD=1
# uses them as they are. Exit status: the test's (0 when every kill passed). Log: <build>/crash-kills.log.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
kills="${1:-20}"
if ! [[ "$kills" =~ ^[1-9][0-9]*$ ]]; then
  echo "usage: $0 [N]   (N: a positive number of kills, default 20)" >&2
  exit 2
fi
build="${OCU_BUILD_DIR:-$root/build}"
if [ ! -f "$build/CMakeCache.txt" ]; then
  echo "crash-kills: $build is not a configured build directory (run scripts/build.sh first)" >&2
  exit 2
fi
if [ "${OCU_CRASH_NO_BUILD:-0}" != 1 ]; then
  cmake --build "$build" -j"$(nproc)" --target ocu ocu-sim test_crash_safety
fi

unset DISPLAY
export QT_QPA_PLATFORM=offscreen
export OCU_CRASH_KILLS="$kills"
# Qt Test ends a test function after 5 minutes by default; a kill takes a few seconds, give each 30.
export QTEST_FUNCTION_TIMEOUT=$(((kills * 30 + 120) * 1000))
log="$build/crash-kills.log"
echo "crash-kills: $kills kill(s) of ocu; load:$(uptime | sed 's/.*load average://')"
start=$(date +%s)
status=0
"$build/tests/app/test_crash_safety" >"$log" 2>&1 || status=$?
end=$(date +%s)
# The seed, the table and any failure, from the test's own lines.
grep -E 'crash safety:|history:|^QINFO.*\|' "$log" | sed -E 's/^QINFO *: *[^ ]+ *//' || true
grep -E '^(FAIL|QFATAL|QWARN)' -A3 "$log" || true
echo "crash-kills: $kills kill(s), $((end - start)) s, $([ $status = 0 ] && echo passed || echo "FAILED (status $status)")"
exit $status
