#!/usr/bin/env bash
# make loadtest: the server under wrk on 127.0.0.1 only, bounded in time.
#   1. /api/health at 256 connections: the ceiling;
#   2. a warm-up, then LOAD_SECONDS (default 60) at 256 connections on a mix
#      of every exercise at its defaults and at random valid parameters,
#      while loadtool compares sampled answers with the same requests made
#      alone before the load;
#   3. resident memory after the warm-up and after the run.
# Passes when: no socket errors, no 5xx, no differing answer, and resident
# memory within 10 % of its size after the warm-up.
set -uo pipefail
cd "$(dirname "$0")/../.."
BUILD=${BUILD:-build}
SECS=${LOAD_SECONDS:-60}
CONNS=${LOAD_CONNECTIONS:-256}
tool="$BUILD/load/loadtool"
paths=$(mktemp)
"$tool" gen 2000 "$paths" || { echo "loadtest: could not make the request mix"; exit 1; }
echo "loadtest: $(wc -l < "$paths") requests in the mix, $CONNS connections, ${SECS}s"

out=$(mktemp)
"$BUILD/mechmat-server" --port 0 --quiet --max-connections 1024 > "$out" &
pid=$!
for _ in $(seq 50); do grep -q listening "$out" && break; sleep 0.1; done
port=$(sed -n 's/.*127\.0\.0\.1:\([0-9]*\).*/\1/p' "$out" | head -1)
rss() { awk '/VmRSS/ {print $2}' "/proc/$pid/status"; }
fail=0

echo "== ceiling: /api/health"
wrk -t2 -c"$CONNS" -d10s --latency "http://127.0.0.1:$port/api/health" | grep -E "Requests/sec|Latency|50%|99%|Socket errors|Non-2xx"

echo "== warm-up (10 s)"
MM_PATHS="$paths" wrk -t2 -c"$CONNS" -d10s -s tests/load/mix.lua "http://127.0.0.1:$port" > /dev/null
rss0=$(rss)

echo "== mix for ${SECS}s"
"$tool" verify "$port" "$paths" "$SECS" > "$out.verify" &
vpid=$!
res=$(MM_PATHS="$paths" wrk -t2 -c"$CONNS" -d"${SECS}s" --timeout 10s -s tests/load/mix.lua "http://127.0.0.1:$port")
wait $vpid || fail=1
echo "$res" | grep -E "Requests/sec|requests in|statuses|socket errors|latency p"
cat "$out.verify"
rss1=$(rss)
echo "resident memory: ${rss0} kB after warm-up, ${rss1} kB after the run"

echo "$res" | grep -q "statuses: .* 0 5xx" || { echo "FAIL: 5xx answers"; fail=1; }
echo "$res" | grep -q "socket errors: connect 0, read 0, write 0, timeout 0" || { echo "FAIL: socket errors"; fail=1; }
awk -v a="$rss0" -v b="$rss1" 'BEGIN{exit !(b <= 1.10 * a)}' || { echo "FAIL: memory grew over 10 %"; fail=1; }
kill "$pid"; wait "$pid" 2>/dev/null
rm -f "$paths" "$out" "$out.verify"
if ((fail)); then echo "loadtest: FAILED"; exit 1; fi
echo "loadtest: passed"
