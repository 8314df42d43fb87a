#!/usr/bin/env bash
# Fuzzing (docs/reliability.md): builds the libFuzzer harnesses of tests/fuzz with clang, ASan and
# UBSan in build-fuzz/, then runs every harness (or those named) for SECONDS each on its corpus.
#   scripts/fuzz.sh [SECONDS] [HARNESS...]   default 60 s each; exits non-zero when any harness found something
#   scripts/fuzz.sh --seed                   rewrites the seed corpora from the tests' vectors (then commit them)
# New inputs go to a scratch directory ($OCU_FUZZ_OUT, default /tmp/ocu-fuzz), never into the repository; a
# finding (crash, sanitizer report, broken invariant, timeout, out-of-memory) is minimised there and reported.
# The committed corpora are replayed by the ordinary build's tests: ctest -R fuzz.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
corpus_root="$here/tests/fuzz/corpus"
build="${OCU_FUZZ_BUILD:-$here/build-fuzz}"
out="${OCU_FUZZ_OUT:-/tmp/ocu-fuzz}"
harnesses_all=(judp_datagram jtcp_stream jaus_messages osyris_codec osyris_station osyris_xml iso_fast_path
               iso_dom_path iso_fms_session osm_map site_config headless_commands landxml)

seed_text() {
  # Text corpora from the tests' data; binary ones from fuzz_make_seeds (tests/fuzz/MakeSeeds.cpp).
  local data="$here/tests/protocols/iso23725/data" d n line
  for h in iso_fast_path iso_dom_path iso_fms_session osm_map site_config headless_commands osyris_xml; do
    mkdir -p "$corpus_root/$h"
  done
  n=0
  while IFS= read -r line; do
    [ -z "$line" ] && continue
    n=$((n + 1))
    printf '%s' "$line" > "$corpus_root/iso_fast_path/catalogue_$n.json"
    printf '%s' "$line" > "$corpus_root/iso_dom_path/catalogue_$n.json"
    printf '%s\n#tick\n' "$line" > "$corpus_root/iso_fms_session/catalogue_$n.txt"
  done < "$data/catalogue_examples.jsonl"
  # Whole sessions: every catalogue frame in order with time passing, then all-stop, reconnect and map fetch.
  d="$corpus_root/iso_fms_session"
  { sed '/^$/d; a #tick' "$data/catalogue_examples.jsonl"; printf '#stop\n#tick\n#wait\n#release\n#own\n'; } > "$d/session_all.txt"
  { head -n 3 "$data/catalogue_examples.jsonl"; printf '#stop\n#close\n#wait\n#open\n'; tail -n 5 "$data/catalogue_examples.jsonl"; printf '#fetchmap\n#wait\n#binary\n'; } > "$d/session_reconnect.txt"
  cp "$data/map_example.osm" "$corpus_root/osm_map/map_example.osm"
  cp "$data/site_iso_full.json" "$data/site_iso_bad.json" "$corpus_root/site_config/"
  cp "$here"/resources/sites/*.json "$corpus_root/site_config/"
  d="$corpus_root/headless_commands"
  printf '%s\n' '{"cmd":"list"}' '{"cmd":"stop_all","req":1}' '{"cmd":"clear_stop","id":"jaus:126","confirm":true}' > "$d/stop_clear.jsonl"
  printf '%s\n' '{"cmd":"stop","id":"osyris:7"}' '{"cmd":"stop","id":"nobody"}' '{"command":"list","req":"x"}' > "$d/stop_one.jsonl"
  printf '%s\n' '{"cmd":"request_control","id":"jaus:126"}' '{"cmd":"drive","id":"jaus:126","mode":"velocity","linear":0.5,"angular":0.1,"duration":0.2}' '{"cmd":"release_control","id":"jaus:126"}' > "$d/control_drive.jsonl"
  printf '%s\n' '{"cmd":"counters"}' 'not json' '[1,2]' '{"cmd":42}' '{}' > "$d/odd.jsonl"
  # The OSYRIS §7 XML configuration: the forms tests/protocols/osyris/test_osyris_store.cpp imports.
  d="$corpus_root/osyris_xml"
  printf '%s' '<Multi><MultiAddr>233.1.1.1:50002</MultiAddr><Beat>200</Beat><MinLen>100</MinLen><MaxLen>1000</MaxLen><SendPeriod>4000</SendPeriod><TailPos>50</TailPos><TTL>10</TTL><Active>7</Active><MaxRange>150.5</MaxRange></Multi>' > "$d/elements.xml"
  printf '%s' '<config MultiAddr="192.168.1.255" Port="50003" Beat="100"/>' > "$d/attributes.xml"
  printf '%s' '<Multi><MultiAddr>233.1.1.1</MultiAddr><MultiPort>50009</MultiPort><TTL>5</TTL></Multi>' > "$d/port_element.xml"
  printf '%s' '<?xml version="1.0"?><osyris><net><multiaddr value="10.0.0.7"/><beat value="50"/></net><Active>15</Active></osyris>' > "$d/nested_value.xml"
  printf '%s' '<Multi><Beat>fast</Beat><MinLen>2000</MinLen><MaxLen>100</MaxLen></Multi>' > "$d/bad_values.xml"
}

if [ "${1:-}" = "--seed" ]; then
  cmake --build "$here/build" --target fuzz_make_seeds >/dev/null
  "$here/build/tests/fuzz/fuzz_make_seeds" "$corpus_root"
  seed_text
  for h in "${harnesses_all[@]}"; do
    echo "seed corpus $h: $(find "$corpus_root/$h" -type f | wc -l) files"
  done
  exit 0
fi

seconds="${1:-60}"
shift || true
harnesses=("$@")
[ ${#harnesses[@]} -eq 0 ] && harnesses=("${harnesses_all[@]}")

cxx="$(command -v clang++-14 || command -v clang++ || true)"
cc="$(command -v clang-14 || command -v clang || true)"
if [ -z "$cxx" ] || ! "$cxx" -print-file-name=libclang_rt.fuzzer-x86_64.a | grep -q /; then
  echo "fuzz: clang with libFuzzer is missing (Debian 12: clang-14 libclang-rt-14-dev; scripts/install-deps.sh)" >&2
  exit 2
fi
if [ ! -f "$build/CMakeCache.txt" ]; then
  launcher=()
  [ -x /work/tools/cc-slot ] && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=/work/tools/cc-slot
                                          -DCMAKE_C_COMPILER_LAUNCHER=/work/tools/cc-slot)
  cmake -S "$here" -B "$build" -G Ninja -DOCU_FUZZ=ON -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_C_COMPILER="$cc" \
    -DOCU_WITH_VTK=OFF -DOCU_BUILD_BENCH=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only" \
    "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only" "${launcher[@]}"
fi
targets=()
for h in "${harnesses[@]}"; do targets+=("fuzz_$h"); done
cmake --build "$build" --target "${targets[@]}" # only the harnesses asked for

mkdir -p "$out"
summary="$out/summary.txt"
printf '%-18s %8s %14s %8s %8s %10s  %s\n' harness seconds executions cov ft corpus result | tee "$summary"
findings=0
for h in "${harnesses[@]}"; do
  bin="$build/tests/fuzz/fuzz_$h"
  [ -x "$bin" ] || { echo "fuzz: no harness $h" >&2; exit 2; }
  work="$out/$h"
  mkdir -p "$work/new" "$work/artifacts"
  log="$work/fuzz.log"
  # The scratch corpus first (libFuzzer writes new inputs into the first directory), the committed one read.
  set +e
  ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1}" UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
    nice -n 19 "$bin" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=4096 -print_final_stats=1 \
    -artifact_prefix="$work/artifacts/" "$work/new" "$corpus_root/$h" >"$log" 2>&1
  rc=$?
  set -e
  execs="$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)"
  last="$(grep -E '^#[0-9]+' "$log" | grep -E 'cov: ' | tail -n 1 || true)"
  cov="$(sed -nE 's/.*cov: ([0-9]+).*/\1/p' <<<"$last")"
  ft="$(sed -nE 's/.* ft: ([0-9]+).*/\1/p' <<<"$last")"
  corp="$(sed -nE 's/.* corp: ([0-9]+\/[0-9]+[a-zA-Z]*).*/\1/p' <<<"$last")"
  result=ok
  artifacts=("$work"/artifacts/*)
  if [ $rc -ne 0 ] || [ -e "${artifacts[0]}" ]; then
    result="FINDING (exit $rc, log $log)"
    findings=$((findings + 1))
    for a in "$work"/artifacts/*; do
      [ -e "$a" ] || continue
      case "$a" in *minimized*) continue ;; esac
      nice -n 19 "$bin" -minimize_crash=1 -runs=20000 -exact_artifact_path="$a.minimized" "$a" \
        >"$a.minimize.log" 2>&1 || true
      echo "  $h: $a (minimised: $a.minimized)" >&2
    done
  fi
  printf '%-18s %8s %14s %8s %8s %10s  %s\n' "$h" "$seconds" "${execs:-0}" "${cov:--}" "${ft:--}" \
    "${corp:--}" "$result" | tee -a "$summary"
done
echo "fuzz: summary in $summary; scratch inputs in $out/<harness>/new"
[ $findings -eq 0 ] || { echo "fuzz: $findings harness(es) found something" >&2; exit 1; }
