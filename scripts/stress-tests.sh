#!/usr/bin/env bash
# Runs the whole test suite RUNS times (default 5) with `ctest -j8` (the test command's slots, see
# cmake/OcuTargets.cmake) while CPU hogs keep every core busy, and
# prints every test that failed in any run (failures/RUNS) with each run's wall time. A test that fails only
# here waits on a real clock or asserts before an asynchronous state has arrived: fix the test, do not retry.
#   scripts/stress-tests.sh [RUNS] [ctest arguments...]   e.g. scripts/stress-tests.sh 3 -R jaus
# Builds first like scripts/test.sh (into OCU_BUILD_DIR, default build/); OCU_STRESS_NO_BUILD=1 reuses the
# build directory as it is. OCU_STRESS_HOGS sets the number of hogs (default: one per core). The tests run at
# nice OCU_STRESS_NICE (default 10) so that the hogs win the CPU the way a busy CI machine's compilers do:
# beside hogs of equal priority the scheduler still favours the tests' short wake-ups and hides races.
# Exit status: 0 when every run passed, 1 otherwise. Logs: <build>/stress/run-N.log.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
runs="${1:-5}"
[ $# -gt 0 ] && shift
if ! [[ "$runs" =~ ^[1-9][0-9]*$ ]]; then
  echo "usage: $0 [RUNS] [ctest arguments...]   (RUNS: a positive number, default 5)" >&2
  exit 2
fi
build="${OCU_BUILD_DIR:-$root/build}"

if [ "${OCU_STRESS_NO_BUILD:-0}" != 1 ]; then
  "$root/scripts/install-deps.sh"
  OCU_BUILD_DIR="$build" "$root/scripts/build.sh"
elif [ ! -f "$build/CTestTestfile.cmake" ]; then
  echo "stress-tests: $build is not a configured build directory (unset OCU_STRESS_NO_BUILD to build)" >&2
  exit 2
fi

unset DISPLAY # as in scripts/test.sh: GUI tests offscreen, xvfb tests start their own server
export QT_QPA_PLATFORM=offscreen

# The hogs: ended on every exit path (normal end, error, Ctrl-C, kill).
hogs=()
stop_hogs() {
  local pid
  for pid in "${hogs[@]}"; do
    kill "$pid" 2>/dev/null || true
  done
  for pid in "${hogs[@]}"; do
    wait "$pid" 2>/dev/null || true
  done
  hogs=()
}
trap stop_hogs EXIT
trap 'stop_hogs; trap - INT; kill -INT $$' INT
trap 'stop_hogs; exit 143' TERM

nhogs="${OCU_STRESS_HOGS:-$(nproc)}"
niceness="${OCU_STRESS_NICE:-10}"
for ((i = 0; i < nhogs; ++i)); do
  yes >/dev/null &
  hogs+=("$!")
done

logs="$build/stress"
mkdir -p "$logs"
declare -A failures=()
times=()
echo "stress-tests: $runs run(s) of ctest -j8 at nice $niceness beside $nhogs CPU hog(s) on $(nproc) core(s);" \
  "load:$(uptime | sed 's/.*load average://')"
cd "$build"
for ((run = 1; run <= runs; ++run)); do
  log="$logs/run-$run.log"
  start=$(date +%s%N)
  rc=0
  nice -n "$niceness" ctest -j8 --output-on-failure --timeout 300 "$@" >"$log" 2>&1 || rc=$?
  ms=$((($(date +%s%N) - start) / 1000000))
  secs=$(printf '%d.%d' $((ms / 1000)) $((ms % 1000 / 100)))
  times+=("$secs")
  # ctest's summary: "The following tests FAILED:" then lines like "  12 - test_x (Failed)".
  failed=$(sed -n '/The following tests FAILED:/,$p' "$log" | sed -n 's/^[[:space:]]*[0-9]\+ - \([^ ]*\) .*/\1/p')
  summary=$(grep -E '^[0-9]+% tests passed' "$log" || echo "ctest exited with $rc")
  printf 'run %d/%d: %6s s  %s  load:%s\n' "$run" "$runs" "$secs" "$summary" \
    "$(uptime | sed 's/.*load average://')"
  for t in $failed; do
    failures[$t]=$((${failures[$t]:-0} + 1))
  done
  if [ "$rc" -ne 0 ] && [ -z "$failed" ]; then
    key="(ctest exited with $rc)"
    failures[$key]=$((${failures[$key]:-0} + 1))
  fi
done
stop_hogs

echo
printf 'wall time per run (s):'
printf ' %s' "${times[@]}"
echo
if [ ${#failures[@]} -eq 0 ]; then
  echo "stress-tests: 0 failures in $runs run(s)"
  exit 0
fi
echo "stress-tests: tests that failed (logs in $logs):"
printf '  %-40s %s\n' "test" "failures/runs"
while IFS= read -r t; do
  printf '  %-40s %d/%d\n' "$t" "${failures[$t]}" "$runs"
done < <(printf '%s\n' "${!failures[@]}" | sort)
exit 1
