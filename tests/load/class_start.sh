#!/usr/bin/env bash
# tests/load/class_start.sh (part of make loadtest): the start of a class.
# 300 browsers (CLASS_CLIENTS) open one exercise page within one second
# (CLASS_SPREAD): the HTML, what it links, KaTeX's module and fonts, the
# catalog, the exercise's metadata and its default solve, as browsers do
# (gzip, several connections each; tests/load/loadtool.c "class").  First
# on one instance directly, then through nginx in front of two installed
# instances (deploy/nginx/mechmat.conf).  Each after one browser has opened
# the page (the instructor, a minute before).  Passes when every request is
# answered 200 and the p99 of the requests is under CLASS_P99_MS (200).
# Besides the figures it prints how long the client and the instances'
# threads waited for a CPU (Linux schedstat): on a loaded machine the p99
# is made there, not in the server (its own time per request, from the
# first callback to the answer queued, is under 0.1 ms at the p99).
set -uo pipefail
cd "$(dirname "$0")/../.."
BUILD=${BUILD:-build}
N=${CLASS_CLIENTS:-300}
SPREAD=${CLASS_SPREAD:-1}
P99=${CLASS_P99_MS:-200}
EX=${CLASS_EXERCISE:-vib-sdof-forced}
work=$(mktemp -d)
source tests/load/stack.sh
trap 'stack_stop; rm -rf "$work"' EXIT
ulimit -n 20000 2>/dev/null || true
fail=0
tool="$BUILD/load/loadtool"

# ms on a CPU and ms waiting for one, summed over the threads of the pids
cpu_wait() {
  local p
  for p in "$@"; do cat /proc/"$p"/task/*/schedstat 2>/dev/null; done | awk '{r += $1; w += $2} END {printf "%d %d", r / 1e6, w / 1e6}'
}

run() {   # $1 label, $2 base URL, then the instances' pids
  local label=$1 url=$2
  shift 2
  "$tool" class "$url" 1 0.1 "$EX" > /dev/null 2>&1          # the instructor's visit
  local out c0 c1
  c0=($(cpu_wait "$@"))
  out=$("$tool" class "$url" "$N" "$SPREAD" "$EX" 2>&1)
  c1=($(cpu_wait "$@"))
  echo "$out" | sed "s/^/   /" | grep -v figures
  echo "   class: the server's threads ran $((c1[0] - c0[0])) ms and waited $((c1[1] - c0[1])) ms for a CPU (load average $(cut -d' ' -f1 /proc/loadavg))"
  local p99 failed
  p99=$(echo "$out" | sed -n 's/.*p99_ms=\([0-9.]*\) .*/\1/p')
  failed=$(echo "$out" | sed -n 's/.*failed=\([0-9]*\).*/\1/p')
  echo "class-start $label: failed=${failed:-?} p99_ms=${p99:-?}"
  [[ "${failed:-1}" == 0 ]] || { echo "FAIL ($label): requests failed"; fail=1; }
  awk -v p="${p99:-1e9}" -v lim="$P99" 'BEGIN{exit !(p < lim)}' || { echo "FAIL ($label): p99 ${p99} ms >= $P99 ms"; fail=1; }
}

stack_install || exit 1
echo "== class start, directly: one installed instance"
stack_instance pid0 port0 || exit 1
run direct "http://127.0.0.1:$port0" "$pid0"
stack_stop
echo "== class start through nginx: two instances"
stack_instance pid1 port1 || exit 1
stack_instance pid2 port2 || exit 1
stack_nginx "$port1" "$port2" || exit 1
run nginx "http://127.0.0.1:$nginx_port" "$pid1" "$pid2"
if ((fail)); then echo "class-start: FAILED"; exit 1; fi
echo "class-start: passed"
