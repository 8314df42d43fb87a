#!/usr/bin/env bash
# Lists function definitions longer than N lines (default 120) in our non-generated sources, longest first:
# "lines file:line name". Universal Ctags gives each definition's first and last line.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
limit="${1:-120}"
git ls-files -- 'app/*.cpp' 'models/*.cpp' 'widgets/*.cpp' 'protocols/*.cpp' 'sim/*.cpp' 'app/*.h' 'models/*.h' \
    'widgets/*.h' 'protocols/*.h' 'sim/*.h' |
    ctags -L - -x --language-force=C++ --kinds-C++=f --fields=+ne --_xformat='%n %e %F %N' -o - 2>/dev/null |
    awk -v lim="$limit" '$2 != "" { len = $2 - $1 + 1; if (len > lim) printf "%5d %s:%d %s\n", len, $3, $1, $4 }' |
    sort -rn
