#!/usr/bin/env bash
# The heaviest translation units: takes the N slowest object files of the last build from build/.ninja_log
# (wall time, disturbed by whatever else ran), compiles each again alone with ccache off and prints its CPU
# time (user + sys), heaviest first: "seconds object". Usage: scripts/tu-times.sh [BUILD_DIR] [CANDIDATES] [TOP]
set -euo pipefail
build="${1:-build}"
candidates="${2:-40}"
top="${3:-10}"
python3 - "$build" "$candidates" "$top" <<'PY'
import json, os, resource, shlex, subprocess, sys
build, candidates, top = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
last = {}
with open(os.path.join(build, ".ninja_log")) as f:
    next(f)
    for line in f:
        start, end, _, out, _ = line.rstrip("\n").split("\t")
        if out.endswith(".o"):
            last[out] = int(end) - int(start)
cmds = {}
for c in json.load(open(os.path.join(build, "compile_commands.json"))):
    args = shlex.split(c["command"])
    out = args[args.index("-o") + 1]
    cmds[out] = (c["directory"], args)
rows = []
for out, _ in sorted(last.items(), key=lambda kv: -kv[1])[:candidates]:
    if out not in cmds:
        continue
    directory, args = cmds[out]
    args = [a for a in args if not a.endswith("ccache")]
    if args[0] == "/usr/bin/env":  # the PCH launcher: env VAR=... compiler ...
        args = [a for a in args[1:] if "=" not in a or a.startswith("-")]
    args[args.index("-o") + 1] = "/dev/null"
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(args, cwd=directory, check=True, env=dict(os.environ, CCACHE_DISABLE="1"))
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    rows.append((cpu, out))
for cpu, out in sorted(rows, reverse=True)[:top]:
    print(f"{cpu:6.1f} s  {out}")
PY
