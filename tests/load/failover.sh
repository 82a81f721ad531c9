#!/usr/bin/env bash
# make failover: nginx (deploy/nginx/mechmat.conf) in front of two installed
# instances, on 127.0.0.1 ports chosen free; a load of distinct solves (the
# mix of make loadtest, so that nginx's cache does not answer them) for
# FAILOVER_SECONDS (default 8); after a third of it one instance is killed
# (SIGKILL).  Passes when every request was answered 2xx/4xx, except at most
# the requests that were in flight on the killed instance (its
# mechmat_requests_in_flight just before the kill): nginx retries a request
# that the dead instance never answered on the other (proxy_next_upstream).
# Also checks, through nginx: a second request for the same answer is an
# nginx cache HIT, answers come gzip, static files from nginx with their
# ETag and a year's Cache-Control under ?v=, and the systemd units verify.
set -uo pipefail
cd "$(dirname "$0")/../.."
BUILD=${BUILD:-build}
SECS=${FAILOVER_SECONDS:-8}
work=$(mktemp -d)
source tests/load/stack.sh
trap 'stack_stop; rm -rf "$work"' EXIT
fail=0
command -v nginx > /dev/null || { echo "failover: nginx is missing (make deps)"; exit 1; }
ulimit -n 20000 2>/dev/null || true

stack_install || exit 1
stack_instance pid1 port1 --threads 1 || exit 1
stack_instance pid2 port2 --threads 1 || exit 1
stack_nginx "$port1" "$port2" || exit 1
base="http://127.0.0.1:$nginx_port"
echo "failover: nginx on $nginx_port, instances on $port1 and $port2 (installed in $share)"

# ---- what nginx does besides balancing
h=$(curl -s -D - -o /dev/null -H 'Accept-Encoding: gzip' "$base/api/exercises/vib-sdof-free/solve?m=3")
h=$(curl -s -D - -o /dev/null -H 'Accept-Encoding: gzip' "$base/api/exercises/vib-sdof-free/solve?m=3")
echo "$h" | grep -qi '^X-Cache-Status: HIT' || { echo "FAIL: the second answer was not an nginx cache hit"; fail=1; }
echo "$h" | grep -qi '^Content-Encoding: gzip' || { echo "FAIL: the answer was not compressed"; fail=1; }
v=$(cat "$share/web/.asset-version")
h=$(curl -s -D - -o /dev/null -H 'Accept-Encoding: gzip' "$base/js/exercise.js?v=$v")
echo "$h" | grep -qi '^Cache-Control: public, max-age=31536000, immutable' || { echo "FAIL: no long Cache-Control on a versioned file"; fail=1; }
echo "$h" | grep -qi '^ETag:' || { echo "FAIL: no ETag on a static file"; fail=1; }
echo "$h" | grep -qi '^Server: nginx' || { echo "FAIL: the static file did not come from nginx"; fail=1; }
grep -q "__MM_ASSET_VERSION__" -r "$share/web" && { echo "FAIL: make install left the version token in web/"; fail=1; }
if command -v systemd-analyze > /dev/null; then
  for u in mechmat.service mechmat@.service; do
    sed "s|/usr/local/bin/mechmat-server|$server_bin|" "deploy/systemd/$u" > "$work/$u"
    out=$(systemd-analyze verify "$work/$u" 2>&1 | grep -v "Failed to load configuration\|cannot be accessed" || true)
    [[ -z "$out" ]] || { echo "FAIL: systemd-analyze verify $u: $out"; fail=1; }
  done
fi

# ---- the load, and a kill
"$BUILD/load/loadtool" gen 2000 "$work/mix" > /dev/null || exit 1
MM_PATHS="$work/mix" wrk -t2 -c64 -d"${SECS}s" --timeout 20s -s tests/load/mix.lua "$base" > "$work/wrk" 2>&1 &
wpid=$!
kill_at=$(awk -v s="$SECS" 'BEGIN{print s / 3}')
sleep "$kill_at"
inflight=$(curl -s "http://127.0.0.1:$port1/api/metrics" | awk '$1 == "mechmat_requests_in_flight" {print $2}')
kill -9 "$pid1"
echo "failover: killed the instance on $port1 after ${kill_at}s with ${inflight:-?} requests in flight on it"
wait "$wpid"
cat "$work/wrk" | grep -E "requests in|Requests/sec|statuses|socket errors|latency p99:"
lost=$(awk '/^statuses:/ {print $6} ' "$work/wrk")
errs=$(awk -F'[ ,]+' '/^socket errors:/ {print $4 + $6 + $8 + $10}' "$work/wrk")
total_lost=$(( ${lost:-0} + ${errs:-0} ))
echo "failover: $total_lost requests lost (5xx or socket errors), ${inflight:-0} were in flight on the killed instance"
(( total_lost <= ${inflight:-0} )) || { echo "FAIL: more requests lost than were in flight on the killed instance"; fail=1; }
# and the survivor serves alone
s=$(curl -s -o /dev/null -w '%{http_code}' "$base/api/exercises/vib-sdof-forced/solve?m=7")
[[ "$s" == 200 ]] || { echo "FAIL: after the kill, a new solve got $s"; fail=1; }
if ((fail)); then echo "failover: FAILED"; exit 1; fi
echo "failover: passed"
