#!/usr/bin/env bash
# Proves that each protocol is a module the console can do without: for each protocol (default: every one of
# OCU_ALL_PROTOCOLS in CMakeLists.txt, or those given as arguments) it configures a build that leaves it out
# (build-seams/<protocol>, ccache on), builds everything and runs the tests of that build. First it checks that
# the shared app files name no protocol (the same check test_include_rules makes, tests/ProtocolNames.cpp).
#   scripts/check-protocol-seams.sh [protocol...]     OCU_JOBS=N (default 2) compile jobs, OCU_CTEST_JOBS=N (8, the test command's slots)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
jobs="${OCU_JOBS:-2}"
ctest_jobs="${OCU_CTEST_JOBS:-8}"
export CCACHE_DIR="${CCACHE_DIR:-$root/.cache/ccache}"
export CCACHE_SLOPPINESS="${CCACHE_SLOPPINESS:-pch_defines,time_macros}"
# The builds differ only in their folder for most objects: share them in the cache.
export CCACHE_BASEDIR="$root" CCACHE_NOHASHDIR=1

all=$(sed -n 's/^set(OCU_ALL_PROTOCOLS \(.*\))$/\1/p' CMakeLists.txt)
[ -n "$all" ] || { echo "check-protocol-seams: no OCU_ALL_PROTOCOLS in CMakeLists.txt" >&2; exit 2; }
protocols=("$@")
[ ${#protocols[@]} -gt 0 ] || read -r -a protocols <<<"$all"
for p in "${protocols[@]}"; do
    tr ' ' '\n' <<<"$all" | grep -qx "$p" || { echo "check-protocol-seams: unknown protocol $p (known: $all)" >&2; exit 2; }
done

# The shared app files (tests/ProtocolNames.cpp lists them) name no protocol.
files=$(grep -o 'QStringLiteral("app/[^"]*")' tests/ProtocolNames.cpp | sed 's/QStringLiteral("\(.*\)")/\1/')
pattern='jaus|osyris|iso[ _-]?23725|\bahs\b|\bfms\b|\bugvs?\b|\bcrew|dispatch|teleop'
# shellcheck disable=SC2086
if grep -inHE "$pattern" $files; then
    echo "check-protocol-seams: the shared app files above name a protocol" >&2
    exit 1
fi
echo "check-protocol-seams: the shared app files name no protocol ($(echo $files | wc -w) files)"

failed=()
for p in "${protocols[@]}"; do
    keep=$(tr ' ' '\n' <<<"$all" | grep -vx "$p" | paste -sd';')
    build="$root/build-seams/$p"
    echo "== without $p (OCU_PROTOCOLS=$keep) in $build"
    start=$(date +%s)
    ok=1
    cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DOCU_PROTOCOLS=$keep" >/dev/null &&
        cmake --build "$build" -j "$jobs" &&
        built=$(date +%s) &&
        (cd "$build" && ctest -j "$ctest_jobs" --output-on-failure) || ok=0
    end=$(date +%s)
    if [ "$ok" = 1 ]; then
        echo "== without $p: passed (build $((built - start)) s, tests $((end - built)) s, total $((end - start)) s)"
    else
        echo "== without $p: FAILED after $((end - start)) s"
        failed+=("$p")
    fi
done
if [ ${#failed[@]} -gt 0 ]; then
    echo "check-protocol-seams: failed without: ${failed[*]}" >&2
    exit 1
fi
echo "check-protocol-seams: every protocol can be left out"
