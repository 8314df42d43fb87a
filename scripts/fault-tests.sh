#!/usr/bin/env bash
# Network faults between the console and its simulators (docs/reliability.md "Network faults"). As root: the
# headless console and ocu-sim in network namespaces of their own, joined through a middle namespace that
# makes the faults: tc netem where the kernel has it, else tests/tools/fault_proxy (the same faults in user
# space). For each row a fresh simulated site (2 JAUS UGVs, an ISO 23725 AHS with 5 trucks, the OSYRIS paving
# train), the fault, the checks per protocol; a table (row, protocol, fault, expected, measured, PASS/FAIL).
# A second console beside the simulators (no fault between them) receives the same OSYRIS job: the faulted
# console's pass counts after recovery must equal its counts, cell by cell.
#
#   sudo scripts/fault-tests.sh [--quick] [--rows base,a,b,c,d1,d2,d3,e] [--keep DIR] [--seed N] [--proxy]
#
# Rows: base (no fault), a (loss, duplication, reordering), b (delay), c (20 kbit/s, OSYRIS), d1-d3 (partitions
# of 5, 30, 120 s), e (100 flaps). --quick shortens faults and partitions (5, 10, 20 s) and flaps faster, for a
# smoke run (about 8 minutes; the full run about 16). --proxy uses the fault proxy even where netem exists.
# Everything ends within a bound and is cleaned up on exit (namespaces, processes). Exit status 0 only when
# every row passed. Not in CI.
set -uo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${OCU_BUILD_DIR:-$root/build}"
OCU="$build/app/ocu"
SIM="$build/app/ocu-sim"
PROXY="$build/tests/tools/fault_proxy"

quick=0
rows="base,a,b,c,d1,d2,d3,e"
keep=""
seed=$RANDOM
force_proxy=0
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1 ;;
    --rows) rows="$2"; shift ;;
    --keep) keep="$2"; shift ;;
    --seed) seed="$2"; shift ;;
    --proxy) force_proxy=1 ;;
    -h | --help) sed -n 2,16p "$0"; exit 0 ;;
    *) echo "fault-tests: unknown argument $1 (see --help)" >&2; exit 2 ;;
  esac
  shift
done
[ "$(id -u)" = 0 ] || { echo "fault-tests: needs root (network namespaces)" >&2; exit 2; }
for b in "$OCU" "$SIM" "$PROXY"; do
  [ -x "$b" ] || { echo "fault-tests: $b missing: ninja -C $build ocu ocu-sim fault_proxy" >&2; exit 2; }
done
for t in ip jq; do command -v $t >/dev/null || { echo "fault-tests: needs $t" >&2; exit 2; }; done
RANDOM=$seed

# Durations (s): fault windows, partitions, flaps (up and down ranges in ms), recovery bounds.
if [ $quick = 1 ]; then
  fault_s=25; partitions=(5 10 20); flap_down=(100 500); flap_up=(200 1000)
else
  fault_s=60; partitions=(5 30 120); flap_down=(200 2000); flap_up=(500 3000)
fi
flaps=100
# Documented times: JAUS link_lost_s 5 (docs/jaus.md), ISO 23725 link dead after 15 s without a frame and
# reconnect backoff 1 … 30 s ± 20 % (docs/iso23725.md), stop confirmation fleet.stop_confirm_timeout_s 3.
jaus_lost_s=5
iso_dead_s=15
iso_backoff_max_s=36 # 30 s + 20 % jitter
stop_confirm_s=3
osyris_silent_s=13 # degraded after 2.5 SendPeriods without a station (docs/osyris.md; the console's SendPeriod 5 s)

P="ft$$"
NS_CON="$P-con"; NS_MID="$P-mid"; NS_SIM="$P-sim"
CON_IP=10.77.0.1; SIM_IP=10.77.0.2
work="${keep:-$(mktemp -d /tmp/fault-tests.XXXXXX)}"
mkdir -p "$work"
table="$work/table.tsv"
: >"$table"
pids=()
use_netem=0
proxy_pid=""
current_faults=""

log() { printf '%s %s\n' "$(date -u +%H:%M:%S)" "$*" >&2; }
now() { printf '%s' "$EPOCHREALTIME"; }
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f", b - a }'; }

watchdog=""
cleanup() {
  local p
  [ -n "$watchdog" ] && pkill -TERM -P "$watchdog" 2>/dev/null
  for p in "${pids[@]}"; do kill -TERM "$p" 2>/dev/null; done
  sleep 1
  for p in "${pids[@]}"; do kill -KILL "$p" 2>/dev/null; done
  for ns in "$NS_CON" "$NS_MID" "$NS_SIM"; do ip netns del "$ns" 2>/dev/null; done
  [ -n "$keep" ] || rm -rf "$work"
}
trap cleanup EXIT
trap 'log "interrupted"; exit 130' INT TERM

# ---------------------------------------------------------------- the three namespaces

netem_available() {
  local ns="$P-probe" ok=1
  ip netns add "$ns" && ip -n "$ns" link set lo up &&
    ip netns exec "$ns" tc qdisc add dev lo root netem delay 1ms 2>/dev/null && ok=0
  ip netns del "$ns" 2>/dev/null
  return $ok
}

# console [c]──[mc] middle [ms]──[s] simulators: one subnet; the middle forwards frames (a bridge with netem,
# or the fault proxy), so unicast, multicast and TCP cross it untouched apart from the faults.
make_topology() {
  ip netns add "$NS_CON" && ip netns add "$NS_MID" && ip netns add "$NS_SIM" || return 1
  ip link add "${P}c" type veth peer name "${P}mc" || return 1
  ip link add "${P}s" type veth peer name "${P}ms" || return 1
  ip link set "${P}c" netns "$NS_CON"; ip link set "${P}mc" netns "$NS_MID"
  ip link set "${P}s" netns "$NS_SIM"; ip link set "${P}ms" netns "$NS_MID"
  for ns in "$NS_CON" "$NS_MID" "$NS_SIM"; do
    ip -n "$ns" link set lo up
    ip netns exec "$ns" sysctl -qw net.ipv6.conf.all.disable_ipv6=1 net.ipv6.conf.default.disable_ipv6=1
  done
  ip -n "$NS_CON" addr add $CON_IP/24 dev "${P}c"; ip -n "$NS_CON" link set "${P}c" up
  ip -n "$NS_SIM" addr add $SIM_IP/24 dev "${P}s"; ip -n "$NS_SIM" link set "${P}s" up
  ip -n "$NS_CON" route add 224.0.0.0/4 dev "${P}c"
  ip -n "$NS_SIM" route add 224.0.0.0/4 dev "${P}s"
  # Fixed neighbours: address resolution is not what is under test, and a lost ARP would stretch every fault.
  local mc ms
  mc=$(ip -n "$NS_CON" -j link show "${P}c" | jq -r '.[0].address')
  ms=$(ip -n "$NS_SIM" -j link show "${P}s" | jq -r '.[0].address')
  ip -n "$NS_CON" neigh add $SIM_IP lladdr "$ms" dev "${P}c" nud permanent
  ip -n "$NS_SIM" neigh add $CON_IP lladdr "$mc" dev "${P}s" nud permanent
  ip -n "$NS_MID" link set "${P}mc" up promisc on
  ip -n "$NS_MID" link set "${P}ms" up promisc on
  if [ $use_netem = 1 ]; then
    ip -n "$NS_MID" link add "${P}br" type bridge
    ip -n "$NS_MID" link set "${P}mc" master "${P}br"
    ip -n "$NS_MID" link set "${P}ms" master "${P}br"
    ip -n "$NS_MID" link set "${P}br" up
  fi
}

# A fault specification as the proxy reads it ("loss=0.3,dup=0.1,reorder=0.1,delay=300,jitter=100,rate=20000")
# in netem's words. netem reorders by sending a share at once and delaying the rest (10 ms here).
netem_args() {
  local spec="$1" loss=0 dup=0 reorder=0 delay=0 jitter=0 rate=0 k v
  IFS=, read -ra items <<<"$spec"
  for it in "${items[@]}"; do
    k="${it%%=*}"; v="${it#*=}"
    case "$k" in
      loss) loss=$v ;; dup) dup=$v ;; reorder) reorder=$v ;; delay) delay=$v ;; jitter) jitter=$v ;; rate) rate=$v ;;
    esac
  done
  local a=()
  [ "$delay" != 0 ] && a+=(delay "${delay}ms" "${jitter}ms")
  [ "$delay" = 0 ] && [ "$reorder" != 0 ] && a+=(delay 10ms)
  [ "$loss" != 0 ] && a+=(loss "$(awk -v p="$loss" 'BEGIN{print p*100}')%")
  [ "$dup" != 0 ] && a+=(duplicate "$(awk -v p="$dup" 'BEGIN{print p*100}')%")
  [ "$reorder" != 0 ] && a+=(reorder "$(awk -v p="$reorder" 'BEGIN{print (1-p)*100}')%")
  [ "$rate" != 0 ] && a+=(rate "${rate}bit" limit 1000)
  [ ${#a[@]} = 0 ] && a=(delay 0ms)
  printf '%s ' "${a[@]}"
}

# The faults of both directions from now on (the partition switch stays off).
set_faults() {
  current_faults="$1"
  if [ $use_netem = 1 ]; then
    local dev
    for dev in "${P}mc" "${P}ms"; do
      # shellcheck disable=SC2046
      ip netns exec "$NS_MID" tc qdisc replace dev "$dev" root netem $(netem_args "$1")
    done
    return
  fi
  stop_proxy
  local plog="$work/proxy.log"
  ip netns exec "$NS_MID" "$PROXY" --a "${P}mc" --b "${P}ms" --faults "$1" --seed "$seed" >>"$plog" 2>&1 &
  proxy_pid=$!
  pids+=("$proxy_pid")
  local i
  for i in $(seq 50); do
    grep -q '"ready":true' "$plog" 2>/dev/null && [ "$(grep -c '"ready":true' "$plog")" -ge "$proxy_starts" ] && break
    sleep 0.1
  done
  proxy_starts=$((proxy_starts + 1))
}
proxy_starts=1

stop_proxy() {
  [ -n "$proxy_pid" ] || return 0
  kill -TERM "$proxy_pid" 2>/dev/null
  wait "$proxy_pid" 2>/dev/null
  proxy_pid=""
}

partition() { # on | off
  if [ $use_netem = 1 ]; then
    local dev
    for dev in "${P}mc" "${P}ms"; do
      if [ "$1" = on ]; then
        ip netns exec "$NS_MID" tc qdisc replace dev "$dev" root netem loss 100%
      else
        # shellcheck disable=SC2046
        ip netns exec "$NS_MID" tc qdisc replace dev "$dev" root netem $(netem_args "$current_faults")
      fi
    done
  else
    kill "-$([ "$1" = on ] && echo USR1 || echo USR2)" "$proxy_pid"
  fi
}

# ---------------------------------------------------------------- one simulated site and its consoles

stamp() { while IFS= read -r l; do printf '%s\t%s\n' "$EPOCHREALTIME" "$l"; done; }

# start_site ROW SIM_ARGS... : ocu-sim in its namespace, the console under test in its own (every protocol
# the simulators serve, commands from a FIFO) and the reference console beside the simulators (OSYRIS only).
only_osyris=0 # 1: the console under test gets the OSYRIS section only
start_site() {
  row="$1"; shift
  local d="$work/$row"
  mkdir -p "$d/home" "$d/refhome"
  ip netns exec "$NS_SIM" "$SIM" --interface $SIM_IP --write-config "$d/site.json" --duration 900 "$@" \
    >"$d/sim.log" 2>&1 &
  sim_pid=$!
  pids+=("$sim_pid")
  local i
  for i in $(seq 100); do [ -s "$d/site.json" ] && break; sleep 0.2; done
  [ -s "$d/site.json" ] || { log "ocu-sim wrote no configuration"; return 1; }
  jq --arg ip $CON_IP --argjson only "$only_osyris" '(if .jaus then .jaus.interface_address = $ip else . end)
      | (if .osyris then .osyris.interface = $ip else . end)
      | (if $only == 1 then del(.jaus, .iso23725) else . end)' "$d/site.json" >"$d/console.json"
  if jq -e .osyris "$d/site.json" >/dev/null; then
    jq --arg ip $SIM_IP '{site, osyris: (.osyris + {interface: $ip, stationIndex: 201})}' "$d/site.json" \
      >"$d/reference.json"
    mkfifo "$d/ref.cmd"
    exec {ref_fd}<>"$d/ref.cmd"
    HOME="$d/refhome" XDG_RUNTIME_DIR="$d/refhome" ip netns exec "$NS_SIM" "$OCU" --headless \
      --config "$d/reference.json" --no-sim --no-record --duration 900 <"$d/ref.cmd" \
      > >(stamp >"$d/reference.log") 2>"$d/reference.err" &
    ref_pid=$!
    pids+=("$ref_pid")
  else
    ref_pid=""
  fi
  mkfifo "$d/con.cmd"
  exec {con_fd}<>"$d/con.cmd"
  HOME="$d/home" XDG_RUNTIME_DIR="$d/home" ip netns exec "$NS_CON" "$OCU" --headless \
    --config "$d/console.json" --no-sim --no-record --duration 900 <"$d/con.cmd" \
    > >(stamp >"$d/console.log") 2>"$d/console.err" &
  con_pid=$!
  pids+=("$con_pid")
  con_log="$d/console.log"
  ref_log="$d/reference.log"
  sim_log="$d/sim.log"
  row_dir="$d"
}

stop_site() {
  local p
  for p in "$con_pid" "$ref_pid" "$sim_pid"; do [ -n "$p" ] && kill -TERM "$p" 2>/dev/null; done
  for p in "$con_pid" "$ref_pid" "$sim_pid"; do
    [ -n "$p" ] || continue
    for _ in $(seq 50); do kill -0 "$p" 2>/dev/null || break; sleep 0.1; done
    kill -KILL "$p" 2>/dev/null
  done
  exec {con_fd}>&-
  [ -n "$ref_pid" ] && exec {ref_fd}>&-
  stop_proxy
}

cmd() { printf '%s\n' "$1" >&"$con_fd"; }
ref_cmd() { printf '%s\n' "$1" >&"$ref_fd"; }

# Every line of a console's log as JSON with its arrival time .t (epoch seconds).
records() { jq -cR 'split("\t") as $p | ($p[1:] | join("\t") | fromjson? // empty) + {t: ($p[0] | tonumber)}' "$1"; }

# first FILE FROM JQ_CONDITION: the time of the first line at or after FROM that matches, or empty.
first() { records "$1" | jq -s --argjson from "$2" "[.[] | select(.t >= \$from) | select($3)][0].t // empty"; }

# wait_for FILE FROM JQ_CONDITION TIMEOUT_S: the time of the first match (waiting for it), or empty.
wait_for() {
  local deadline t
  deadline=$(awk -v a="$(now)" -v b="$4" 'BEGIN { printf "%.3f", a + b }')
  while :; do
    t=$(first "$1" "$2" "$3")
    [ -n "$t" ] && { printf '%s' "$t"; return 0; }
    awk -v a="$(now)" -v b="$deadline" 'BEGIN { exit !(a > b) }' && return 1
    sleep 0.5
  done
}

# The latest state of one machine up to time T: a JSON object or null.
machine_at() {
  records "$1" | jq -s --arg id "$2" --argjson t "$3" \
    '[.[] | select(.type == "machine" and .id == $id and .t <= $t)] | last'
}

# A command's result line (by "req"), waiting up to 5 s.
result_of() {
  local req="$1" t
  t=$(wait_for "$con_log" 0 ".type == \"result\" and .req == \"$req\"" 5) || { echo null; return; }
  records "$con_log" | jq -s --arg r "$req" '[.[] | select(.type == "result" and .req == $r)][0]'
}

add_row() { # row protocol fault expected measured pass(0/1)
  local verdict=FAIL
  [ "$6" = 0 ] && verdict=PASS
  printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$1" "$2" "$3" "$4" "$5" "$verdict" >>"$table"
  log "$verdict $1 $2: $5"
}

# Console threads, fds and RSS (kB) from /proc.
proc_sample() {
  local th fd rss
  th=$(awk '/^Threads:/ {print $2}' "/proc/$con_pid/status")
  fd=$(ls "/proc/$con_pid/fd" | wc -l)
  rss=$(awk '/^VmRSS:/ {print $2}' "/proc/$con_pid/status")
  printf '%s %s %s' "$th" "$fd" "$rss"
}

# ---------------------------------------------------------------- what each row checks

# Every link and machine of the site is up: the JAUS UGVs, the AHS link, the OSYRIS stations.
links_up_cond='.type == "link" and .state == "up"'
wait_site_up() { # FROM TIMEOUT: time when all three protocols (those configured) were last seen coming up
  local from="$1" limit="$2" t tmax="$1" proto
  for proto in $(jq -r 'keys[] | select(. == "jaus" or . == "iso23725" or . == "osyris")' "$row_dir/console.json"); do
    t=$(wait_for "$con_log" "$from" "$links_up_cond and .protocol == \"$proto\"" "$limit") || return 1
    tmax=$(awk -v a="$tmax" -v b="$t" 'BEGIN { print (b > a ? b : a) }')
  done
  printf '%s' "$tmax"
}

# wait_site_up_now TIMEOUT: the time when every configured protocol's link was last up (waiting for it).
wait_site_up_now() {
  local deadline proto all
  deadline=$(awk -v a="$(now)" -v b="$1" 'BEGIN { printf "%.3f", a + b }')
  while :; do
    all=1
    for proto in $(jq -r 'keys[] | select(. == "jaus" or . == "iso23725" or . == "osyris")' "$row_dir/console.json"); do
      [ "$(link_state_at "$proto" "$(now)")" = up ] || { all=0; break; }
    done
    [ $all = 1 ] && { now; return 0; }
    awk -v a="$(now)" -v b="$deadline" 'BEGIN { exit !(a > b) }' && return 1
    sleep 0.5
  done
}

# The state of a link (by protocol) at time T: "up", "degraded", "down" or "unknown".
link_state_at() {
  records "$con_log" | jq -rs --arg p "$1" --argjson t "$2" \
    '[.[] | select(.type == "link" and .protocol == $p and .t <= $t)] | last | .state // "unknown"'
}

# OSYRIS: the faulted console's pass counts equal the reference console's, cell by cell. Both write the CSV
# of coverage_report after the simulators stopped (nothing more can change), minus the comment lines.
compare_pass_counts() { # -> "equal N cells, P passes" or "differ: ..."; status 0 when equal
  local d="$row_dir"
  cmd "{\"cmd\":\"coverage_report\",\"csv\":\"$d/test.csv\",\"req\":\"cov\"}"
  ref_cmd "{\"cmd\":\"coverage_report\",\"csv\":\"$d/ref.csv\"}"
  for _ in $(seq 50); do [ -s "$d/test.csv" ] && [ -s "$d/ref.csv" ] && break; sleep 0.2; done
  [ -s "$d/test.csv" ] && [ -s "$d/ref.csv" ] || { echo "no pass counts written"; return 1; }
  sleep 0.5
  grep -v '^#' "$d/test.csv" | sort >"$d/test.cells"
  grep -v '^#' "$d/ref.csv" | sort >"$d/ref.cells"
  local n passes diff
  n=$(($(wc -l <"$d/ref.cells") - 1))
  passes=$(awk -F, 'NR > 1 { s += $4 } END { print s + 0 }' "$d/ref.cells")
  if cmp -s "$d/test.cells" "$d/ref.cells"; then
    echo "pass counts equal the fault-free console's: $n cells, $passes passes"
    return 0
  fi
  diff=$(diff "$d/test.cells" "$d/ref.cells" | grep -c '^[<>]')
  echo "pass counts differ from the fault-free console's in $diff lines ($n cells, $passes passes there)"
  return 1
}

# ISO 23725: every session the AHS saw began with the FMS's FleetDefinitionV2.
check_fleet_first() { # -> text; status 0 when every session did
  local sessions first fleet
  sessions=$(grep -c 'FMS connected from' "$sim_log")
  first=$(grep -c "FMS session's first message" "$sim_log")
  fleet=$(grep -c "FMS session's first message: FleetDefinitionV2" "$sim_log")
  echo "$sessions session(s), $fleet began with FleetDefinitionV2"
  [ "$sessions" -ge 1 ] && [ "$fleet" = "$first" ] && [ "$first" -ge "$sessions" ]
}

# A stop_all's honesty: every target sent or refused with a reason; a machine shown stopped only once its own
# report said so, never before its link could carry it (EARLIEST); each sent stop either confirmed or the
# "has not confirmed" alarm raised within stop_confirm_timeout_s + 1.
check_stop_result() { # REQ SENT_AT EARLIEST PROTOCOL -> text; status 0 when honest
  local req="$1" sent_at="$2" earliest="$3" proto="$4" res bad=0 out=""
  res=$(result_of "$req")
  [ "$res" = null ] && { echo "no result for stop_all"; return 1; }
  local ids
  ids=$(jq -r --arg p "$proto" '.targets[] | select(.id | startswith($p)) | "\(.id)|\(.sent)|\(.reason // "")"' <<<"$res")
  local sent=0 refused=0 confirmed=0 alarmed=0 early=0 noreason=0 silent=0 id s reason t_stop t_alarm cond
  while IFS='|' read -r id s reason; do
    [ -n "$id" ] || continue
    if [ "$s" != true ]; then
      refused=$((refused + 1))
      [ -n "$reason" ] || noreason=$((noreason + 1))
      continue
    fi
    sent=$((sent + 1))
    # What confirms it: the machine's own report (stop "stopped"); for a link target (an id with a space: "iso23725
    # link ahs") any of its machines'; OSYRIS carries no stop state, so its drivers' answers to the STOP text.
    if [ "$proto" = osyris ]; then
      cond='.type == "event" and .kind == "text_message" and (.text | test("STOP ALL"))'
    elif [[ "$id" == *" "* ]]; then
      cond=".type == \"machine\" and .protocol == \"$proto\" and .stop == \"stopped\""
    else
      cond=".type == \"machine\" and .id == \"$id\" and .stop == \"stopped\""
    fi
    t_stop=$(first "$con_log" "$sent_at" "$cond")
    if [ "$proto" = osyris ]; then
      t_alarm=$(first "$con_log" "$sent_at" '.type == "event" and (.text | test("no machine can confirm"))')
    else
      t_alarm=$(first "$con_log" "$sent_at" ".type == \"event\" and (.text | test(\"has not (confirmed|reported being stopped)\"))")
    fi
    if [ -n "$t_stop" ] && awk -v a="$t_stop" -v b="$earliest" 'BEGIN { exit !(a < b) }'; then
      early=$((early + 1))
    elif [ -n "$t_stop" ]; then
      confirmed=$((confirmed + 1))
    elif [ -n "$t_alarm" ]; then
      alarmed=$((alarmed + 1))
    else
      silent=$((silent + 1))
    fi
  done <<<"$ids"
  # OSYRIS machines are never shown stopped: nothing of theirs could say so.
  [ "$proto" = osyris ] && [ -n "$(first "$con_log" "$sent_at" '.type == "machine" and .protocol == "osyris" and .stop == "stopped"')" ] &&
    early=$((early + 1))
  out="stop_all: $sent sent ($confirmed confirmed by the machines, none before it could arrive; $alarmed unconfirmed and said so)"
  out="$out, $refused refused with reason"
  [ $early -gt 0 ] && { out="$out, $early SHOWN STOPPED BEFORE IT COULD ARRIVE"; bad=1; }
  [ $noreason -gt 0 ] && { out="$out, $noreason refused without reason"; bad=1; }
  [ $silent -gt 0 ] && { out="$out, $silent neither confirmed nor alarmed"; bad=1; }
  [ $((sent + refused)) = 0 ] && { out="$out, no $proto target"; bad=1; }
  echo "$out"
  return $bad
}

# JAUS control after a fault: held by us and the vehicle's own ReportControl agrees, or reported lost.
check_control() { # AT -> text; status 0 when consistent
  local m ctl ctlr lost
  m=$(machine_at "$con_log" jaus:126 "$1")
  ctl=$(jq -r '.control // "none"' <<<"$m")
  ctlr=$(jq -r '.controller // ""' <<<"$m")
  lost=$(first "$con_log" "$control_at" '.type == "event" and .machine == "jaus:126" and (.text | test("control"; "i")) and (.text | test("lost|preempt|timeout|rejected"; "i"))')
  if [ "$ctl" = me ]; then
    echo "control of UGV-126 held (controller $ctlr)${lost:+, a loss reported and regained}"
    return 0
  fi
  if [ -n "$lost" ]; then
    echo "control of UGV-126 reported lost (now: $ctl)"
    return 0
  fi
  echo "control of UGV-126 silently gone (now: $ctl, controller $ctlr, no event)"
  return 1
}

take_control() {
  control_at=$(now)
  cmd '{"cmd":"request_control","id":"jaus:126","req":"ctl"}'
  wait_for "$con_log" "$control_at" '.type == "machine" and .id == "jaus:126" and .control == "me"' 15 >/dev/null
}

# Ends the simulators (their last positions drained through the fault-free link), then compares pass counts.
finish_osyris() { # ROW FAULT
  kill -TERM "$sim_pid" 2>/dev/null
  for _ in $(seq 50); do kill -0 "$sim_pid" 2>/dev/null || break; sleep 0.1; done
  sleep 6 # queued frames drained, a late slot's recount (at most every 5 s) done
  local text status
  text=$(compare_pass_counts); status=$?
  add_row "$1" OSYRIS "$2" "after recovery, pass counts = the fault-free console's (same job, same time)" \
    "$text" $status
}

# ---------------------------------------------------------------- the rows

site_args=(--ugvs 2 --trucks 5 --rollers 3 --speedup 1)

run_row_faults() { # ROW SPEC FAULT_TEXT: a fault for fault_s seconds, then healed
  local r="$1" spec="$2" what="$3"
  log "row $r: $what for ${fault_s} s"
  set_faults ""
  start_site "$r" "${site_args[@]}"
  local up t0
  up=$(wait_site_up 0 30) || { add_row "$r" all "$what" "site up" "links did not come up fault-free" 1; stop_site; return; }
  take_control
  set_faults "$spec"
  t0=$(now)
  # Nothing may be shown down for a fault that never silences a link for link_lost_s / 15 s.
  sleep $((fault_s / 2))
  local stop_at; stop_at=$(now)
  cmd '{"cmd":"stop_all","req":"stop"}'
  sleep $((fault_s - fault_s / 2))
  local t1; t1=$(now)
  local jdown idown
  jdown=$(first "$con_log" "$t0" '.type == "machine" and .protocol == "jaus" and .link == "down"')
  idown=$(first "$con_log" "$t0" '.type == "link" and .protocol == "iso23725" and .state == "down"')
  local text st ctext cst
  text=$(check_stop_result stop "$stop_at" "$t0" jaus); st=$?
  ctext=$(check_control "$t1"); cst=$?
  add_row "$r" JAUS "$what" "links never down; stop_all honest; control held or reported lost" \
    "$([ -z "$jdown" ] && echo "never down" || echo "DOWN at +$(elapsed "$t0" "$jdown") s"); $text; $ctext" \
    $(( st || ${#jdown} > 0 || cst ))
  set_faults ""
  local back; back=$(wait_site_up_now 40)
  local ftext fst
  ftext=$(check_fleet_first); fst=$?
  text=$(check_stop_result stop "$stop_at" "$t0" iso23725); st=$?
  add_row "$r" "ISO 23725" "$what" "link up or reconnected; sessions begin with FleetDefinitionV2; stop_all honest" \
    "$([ -z "$idown" ] && echo "never down" || echo "down at +$(elapsed "$t0" "$idown") s"); all up $([ -n "$back" ] && echo "$(elapsed "$t1" "$back") s after" || echo "NOT") ; $ftext; $text" \
    $(( st || fst || ${#back} == 0 ))
  sleep 10
  finish_osyris "$r" "$what"
  stop_site
}

run_row_rate() { # c: 20 kbit/s on the OSYRIS radio, the paving train alone
  local r=c what="20 kbit/s both ways (queue 2 s)"
  log "row $r: $what for ${fault_s} s"
  set_faults ""
  only_osyris=1
  start_site "$r" --ugvs 0 --trucks 0 --rollers 3 --speedup 1
  only_osyris=0
  local up
  up=$(wait_site_up 0 30) || { add_row $r OSYRIS "$what" "site up" "link did not come up" 1; stop_site; return; }
  set_faults "rate=20000,queue=2000"
  local t0; t0=$(now)
  sleep "$fault_s"
  local down; down=$(first "$con_log" "$t0" '.type == "link" and .protocol == "osyris" and .state == "down"')
  local st; st=$(link_state_at osyris "$(now)")
  set_faults ""
  # What the limit did (the proxy's counters as it ended: frames dropped because the queue was full).
  local queued=""
  [ $use_netem = 0 ] && queued=$(grep '"direction"' "$work/proxy.log" | tail -2 |
    jq -rs '"\(map(.in) | add) frames offered, \(map(.overflow) | add) dropped by the full queue"')
  sleep 15
  add_row $r OSYRIS "$what" "station link never down" \
    "$([ -z "$down" ] && echo "never down" || echo "DOWN at +$(elapsed "$t0" "$down") s"), $st at the end of the limit${queued:+; $queued}" \
    ${#down}
  finish_osyris $r "$what, then lifted"
  stop_site
}

run_row_partition() { # ROW SECONDS
  local r="$1" secs="$2" what="partition ${2} s"
  log "row $r: $what"
  set_faults ""
  start_site "$r" "${site_args[@]}"
  wait_site_up 0 30 >/dev/null || { add_row "$r" all "$what" "site up" "links did not come up fault-free" 1; stop_site; return; }
  take_control
  sleep 2
  partition on
  local t0; t0=$(now)
  local stop_in=$((secs > 4 ? secs - 2 : 1))
  sleep $stop_in
  local stop_at; stop_at=$(now)
  cmd '{"cmd":"stop_all","req":"stop"}'
  sleep $((secs - stop_in))
  partition off
  local t1; t1=$(now)
  # JAUS: degraded at once, down after link_lost_s of silence; up again after the first report.
  local jdeg jdown jup
  jdeg=$(first "$con_log" "$t0" '.type == "machine" and .id == "jaus:126" and (.link == "degraded" or .link == "down")')
  jdown=$(first "$con_log" "$t0" '.type == "machine" and .id == "jaus:126" and .link == "down"')
  jup=$(wait_for "$con_log" "$t1" '.type == "machine" and .id == "jaus:126" and .link == "up"' 10)
  local ok=0 text m
  if [ "$secs" -gt $jaus_lost_s ]; then
    m="down $([ -n "$jdown" ] && echo "+$(elapsed "$t0" "$jdown") s" || echo NEVER)"
    [ -n "$jdown" ] && awk -v a="$(elapsed "$t0" "$jdown")" -v b=$((jaus_lost_s + 2)) 'BEGIN { exit !(a <= b) }' || ok=1
  else
    m="degraded $([ -n "$jdeg" ] && echo "+$(elapsed "$t0" "$jdeg") s" || echo NEVER)"
    [ -n "$jdeg" ] || ok=1
  fi
  m="$m, up $([ -n "$jup" ] && echo "$(elapsed "$t1" "$jup") s after" || echo "NOT within 10 s")"
  [ -n "$jup" ] || ok=1
  sleep 5
  local ctext cst stext sst
  ctext=$(check_control "$(now)"); cst=$?
  stext=$(check_stop_result stop "$stop_at" "$t1" jaus); sst=$?
  add_row "$r" JAUS "$what" "$([ "$secs" -gt $jaus_lost_s ] && echo "down ≤ ${jaus_lost_s}+2 s" || echo "degraded"), up ≤ 10 s after; stop honest; control held or reported lost" \
    "$m; $stext; $ctext" $((ok || cst || sst))
  # ISO 23725: down after 15 s of silence; reconnected within the backoff; the fleet definition first.
  local idown iup=""
  idown=$(first "$con_log" "$t0" '.type == "link" and .protocol == "iso23725" and .state != "up"')
  [ -n "$idown" ] &&
    iup=$(wait_for "$con_log" "$idown" '.type == "link" and .protocol == "iso23725" and .state == "up"' $((iso_backoff_max_s + 5)))
  local istate; istate=$(link_state_at iso23725 "$(now)")
  ok=0
  if [ "$secs" -gt $iso_dead_s ]; then
    m="down $([ -n "$idown" ] && echo "+$(elapsed "$t0" "$idown") s" || echo NEVER)"
    [ -n "$idown" ] && awk -v a="$(elapsed "$t0" "$idown")" -v b=$((iso_dead_s + 2)) 'BEGIN { exit !(a <= b) }' || ok=1
    m="$m, up $([ -n "$iup" ] && echo "$(elapsed "$t1" "$iup") s after" || echo "NOT within $((iso_backoff_max_s + 5)) s")"
    [ -n "$iup" ] || ok=1
  else
    m="$([ -n "$idown" ] && echo "down +$(elapsed "$t0" "$idown") s" || echo "stayed up (TCP kept the session)"), $istate at the end"
    [ "$istate" = up ] || ok=1
  fi
  local ftext fst
  ftext=$(check_fleet_first); fst=$?
  stext=$(check_stop_result stop "$stop_at" "$t1" iso23725); sst=$?
  add_row "$r" "ISO 23725" "$what" "$([ "$secs" -gt $iso_dead_s ] && echo "down ≤ ${iso_dead_s}+2 s, up ≤ ${iso_backoff_max_s}+5 s after (backoff)" || echo "up at the end"); fleet definition first; stop honest" \
    "$m; $ftext; $stext" $((ok || fst || sst))
  # OSYRIS: the station link degraded after 2.5 SendPeriods of silence, up again when a station is heard.
  local odown oup
  odown=$(first "$con_log" "$t0" '.type == "link" and .protocol == "osyris" and .state != "up"')
  oup=""
  [ -n "$odown" ] && oup=$(wait_for "$con_log" "$odown" '.type == "link" and .protocol == "osyris" and .state == "up"' 15)
  ok=0
  if [ "$secs" -gt $((osyris_silent_s + 1)) ]; then
    m="degraded $([ -n "$odown" ] && echo "+$(elapsed "$t0" "$odown") s" || echo NEVER)"
    [ -n "$odown" ] && awk -v a="$(elapsed "$t0" "$odown")" -v b=$((osyris_silent_s + 2)) 'BEGIN { exit !(a <= b) }' || ok=1
  else
    m="$([ -n "$odown" ] && echo "degraded +$(elapsed "$t0" "$odown") s" || echo "shorter than 2.5 SendPeriods: stayed up")"
  fi
  [ "$(link_state_at osyris "$(now)")" = up ] || ok=1
  m="$m, up $([ -n "$odown" ] && [ -n "$oup" ] && echo "$(elapsed "$t1" "$oup") s after" || echo "at the end: $(link_state_at osyris "$(now)")")"
  stext=$(check_stop_result stop "$stop_at" "$t1" osyris); sst=$?
  add_row "$r" "OSYRIS" "$what" "$([ "$secs" -gt $((osyris_silent_s + 1)) ] && echo "degraded ≤ ${osyris_silent_s}+2 s, " || echo "")up ≤ 15 s after; stop honest" \
    "$m; $stext" $((ok || sst))
  sleep 20
  finish_osyris "$r" "$what"
  stop_site
}

run_row_flaps() {
  local r=e what="$flaps flaps (down ${flap_down[0]}–${flap_down[1]} ms, up ${flap_up[0]}–${flap_up[1]} ms)"
  log "row $r: $what"
  set_faults ""
  start_site "$r" "${site_args[@]}"
  wait_site_up 0 30 >/dev/null || { add_row "$r" all "$what" "site up" "links did not come up fault-free" 1; stop_site; return; }
  take_control
  local i first_sample="" down up t_first
  for i in $(seq $flaps); do
    down=$((flap_down[0] + RANDOM % (flap_down[1] - flap_down[0] + 1)))
    up=$((flap_up[0] + RANDOM % (flap_up[1] - flap_up[0] + 1)))
    partition on
    sleep "$(awk -v m=$down 'BEGIN { printf "%.3f", m / 1000 }')"
    partition off
    if [ "$i" = 1 ]; then
      t_first=$(now)
      wait_site_up_now 40 >/dev/null
      sleep 5
      first_sample=$(proc_sample)
    fi
    sleep "$(awk -v m=$up 'BEGIN { printf "%.3f", m / 1000 }')"
  done
  local t1; t1=$(now)
  # Back to the state after the first flap: every link up, then the same resources.
  sleep 5
  local back; back=$(wait_site_up_now 45)
  sleep 5
  local last_sample; last_sample=$(proc_sample)
  read -r th0 fd0 rss0 <<<"$first_sample"
  read -r th1 fd1 rss1 <<<"$last_sample"
  local ok=0
  [ "$th1" = "$th0" ] || ok=1
  [ $((fd1 - fd0)) -le 2 ] || ok=1
  [ $((rss1 - rss0)) -le 8192 ] || ok=1
  add_row $r console "$what" "after the last flap threads = after the first, fds ≤ +2, RSS ≤ +8 MB" \
    "threads $th0 → $th1, fds $fd0 → $fd1, RSS $((rss0 / 1024)) → $((rss1 / 1024)) MB" $ok
  local jst ist ost
  jst=$(machine_at "$con_log" jaus:126 "$(now)" | jq -r .link)
  ist=$(link_state_at iso23725 "$(now)"); ost=$(link_state_at osyris "$(now)")
  local ftext fst ctext cst
  ftext=$(check_fleet_first); fst=$?
  ctext=$(check_control "$(now)"); cst=$?
  add_row $r JAUS "$what" "up at the end; control held or reported lost" "UGV-126 link $jst; $ctext" \
    $(( cst || $([ "$jst" = up ]; echo $?) ))
  add_row $r "ISO 23725" "$what" "up at the end; every session began with the fleet definition" \
    "link $ist $([ -n "$back" ] && echo "(all up $(elapsed "$t1" "$back") s after the last flap)"); $ftext" \
    $(( fst || $([ "$ist" = up ]; echo $?) ))
  add_row $r OSYRIS "$what" "station link up at the end" "link $ost" $([ "$ost" = up ]; echo $?)
  sleep 15
  finish_osyris $r "$what"
  stop_site
}

run_row_base() {
  local r=base what="none (control run)"
  log "row $r: $what"
  set_faults ""
  start_site "$r" "${site_args[@]}"
  local up
  up=$(wait_site_up 0 30)
  add_row $r all "$what" "every link up ≤ 30 s after start" \
    "$([ -n "$up" ] && echo "up" || echo "NOT up")" "$([ -n "$up" ]; echo $?)"
  [ -n "$up" ] || { stop_site; return; }
  take_control
  local stop_at; stop_at=$(now)
  cmd '{"cmd":"stop_all","req":"stop"}'
  sleep $((stop_confirm_s + 2))
  local text st
  for p in jaus iso23725 osyris; do
    text=$(check_stop_result stop "$stop_at" "$stop_at" $p); st=$?
    add_row $r "$p" "$what" "stop_all honest" "$text" $st
  done
  sleep 10
  finish_osyris $r "$what"
  stop_site
}

# ---------------------------------------------------------------- main

if [ $force_proxy = 0 ] && netem_available; then use_netem=1; fi
make_topology || { log "could not make the namespaces"; exit 1; }
start_time=$(date -u '+%Y-%m-%d %H:%M UTC')
log "fault-tests: $([ $use_netem = 1 ] && echo "tc netem" || echo "fault_proxy (no netem in this kernel)"), seed $seed, work $work"
# A bound on the whole run, whatever hangs.
( sleep $((quick ? 900 : 1800)) && kill -TERM $$ ) >/dev/null 2>&1 &
watchdog=$!

IFS=, read -ra wanted <<<"$rows"
for r in "${wanted[@]}"; do
  case "$r" in
    base) run_row_base ;;
    a) run_row_faults a "loss=0.3,dup=0.1,reorder=0.1" "30 % loss, 10 % duplicated, 10 % reordered" ;;
    b) run_row_faults b "delay=300,jitter=100" "delay 300 ± 100 ms" ;;
    c) run_row_rate ;;
    d1) run_row_partition "d${partitions[0]}" "${partitions[0]}" ;;
    d2) run_row_partition "d${partitions[1]}" "${partitions[1]}" ;;
    d3) run_row_partition "d${partitions[2]}" "${partitions[2]}" ;;
    e) run_row_flaps ;;
    *) log "unknown row $r" ;;
  esac
done

echo
echo "Network faults, $start_time, $([ $use_netem = 1 ] && echo "tc netem" || echo "fault_proxy"), seed $seed: $0 $([ $quick = 1 ] && echo --quick) --rows $rows"
echo
echo "| row | protocol | fault | expected | measured | result |"
echo "|---|---|---|---|---|---|"
awk -F'\t' '{ printf "| %s | %s | %s | %s | %s | %s |\n", $1, $2, $3, $4, $5, $6 }' "$table"
fails=$(grep -c 'FAIL$' "$table")
echo
echo "fault-tests: $(wc -l <"$table") rows, $fails failed"
[ "$fails" = 0 ]
