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

run() {   # $1 label, $2 base URL
  "$tool" class "$2" 1 0.1 "$EX" > /dev/null 2>&1          # the instructor's visit
  local out
  out=$("$tool" class "$2" "$N" "$SPREAD" "$EX" 2>&1)
  echo "$out" | sed "s/^/   /" | grep -v figures
  local p99 failed
  p99=$(echo "$out" | sed -n 's/.*p99_ms=\([0-9.]*\) .*/\1/p')
  failed=$(echo "$out" | sed -n 's/.*failed=\([0-9]*\).*/\1/p')
  echo "class-start $1: failed=${failed:-?} p99_ms=${p99:-?}"
  [[ "${failed:-1}" == 0 ]] || { echo "FAIL ($1): requests failed"; fail=1; }
  awk -v p="${p99:-1e9}" -v lim="$P99" 'BEGIN{exit !(p < lim)}' || { echo "FAIL ($1): p99 ${p99} ms >= $P99 ms"; fail=1; }
}

stack_install || exit 1
echo "== class start, directly: one installed instance"
stack_instance pid0 port0 || exit 1
run direct "http://127.0.0.1:$port0"
stack_stop
echo "== class start through nginx: two instances"
stack_instance pid1 port1 || exit 1
stack_instance pid2 port2 || exit 1
stack_nginx "$port1" "$port2" || exit 1
run nginx "http://127.0.0.1:$nginx_port"
if ((fail)); then echo "class-start: FAILED"; exit 1; fi
echo "class-start: passed"
