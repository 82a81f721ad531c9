#!/usr/bin/env bash
# make loadtest: the server under wrk on 127.0.0.1 only, bounded in time.
#   1. /api/health at 256 connections for 10 s: the ceiling;
#   2. a warm-up (10 s), then LOAD_SECONDS (default 60) at 256 connections
#      on a mix of every exercise at its defaults and at random valid
#      parameters, while loadtool compares sampled answers with the same
#      requests made alone, before any load (byte for byte, elapsed_us aside);
#   3. resident memory after the warm-up and after the run.
# Passes when: no socket errors, no 5xx, no differing answer, no verify
# error, and resident memory within 10 % of its size after the warm-up.
# LOAD_SECONDS, LOAD_CONNECTIONS and LOAD_THREADS (server threads, default:
# the server's own choice, one per core) change the figures.
set -uo pipefail
cd "$(dirname "$0")/../.."
BUILD=${BUILD:-build}
SECS=${LOAD_SECONDS:-60}
CONNS=${LOAD_CONNECTIONS:-256}
tool="$BUILD/load/loadtool"
work=$(mktemp -d)
paths="$work/paths"
"$tool" gen 2000 "$paths" || { echo "loadtest: could not make the request mix"; exit 1; }
echo "/api/health" > "$work/health"
echo "loadtest: $(wc -l < "$paths") requests in the mix ($(grep -c '^POST' "$paths") by POST," \
     "$(grep -vcE '^/api/exercises/[^?]*$|^POST [^ ]* \{"params":\{\}\}$' "$paths") with random parameters)," \
     "$CONNS connections, ${SECS}s, $(nproc) cores"

threads=()
[[ -n "${LOAD_THREADS:-}" ]] && threads=(--threads "$LOAD_THREADS")
"$BUILD/mechmat-server" --port 0 --quiet --max-connections 1024 "${threads[@]}" > "$work/server" &
pid=$!
for _ in $(seq 100); do grep -q listening "$work/server" && break; sleep 0.1; done
port=$(sed -n 's/.*127\.0\.0\.1:\([0-9]*\).*/\1/p' "$work/server" | head -1)
[[ -n "$port" ]] || { echo "loadtest: the server did not start"; kill "$pid"; exit 1; }
rss() { awk '/VmRSS/ {print $2}' "/proc/$pid/status"; }
fail=0
stop() { kill "$pid" 2>/dev/null; wait "$pid" 2>/dev/null; rm -rf "$work"; }
trap stop EXIT

# wrk's own figures plus mix.lua's (statuses, socket errors, percentiles)
rps() { echo "$1" | awk '/Requests\/sec/ {print $2}'; }
pct() { echo "$1" | awk -v p="p$2:" '$1 == "latency" && $2 == p {print $3; exit}'; }

echo "== ceiling: /api/health, 10 s, against a bare libmicrohttpd endpoint in the same run"
"$BUILD/bench/bare_mhd" pool > "$work/bare" 2>&1 &
bpid=$!
for _ in $(seq 100); do grep -q listening "$work/bare" && break; sleep 0.1; done
bport=$(sed -n 's/.*127\.0\.0\.1:\([0-9]*\).*/\1/p' "$work/bare" | head -1)
bare=$(MM_PATHS="$work/health" wrk -t2 -c"$CONNS" -d10s --timeout 10s -s tests/load/mix.lua \
       "http://127.0.0.1:$bport" 2>&1)
kill "$bpid"; wait "$bpid" 2>/dev/null
health=$(MM_PATHS="$work/health" wrk -t2 -c"$CONNS" -d10s --timeout 10s -s tests/load/mix.lua \
         "http://127.0.0.1:$port" 2>&1)
echo "$health" | grep -E "Requests/sec|requests in|statuses|socket errors|latency p"
awk -v h="$(echo "$health" | awk '/Requests\/sec/ {print $2}')" -v b="$(echo "$bare" | awk '/Requests\/sec/ {print $2}')" \
  'BEGIN{printf "/api/health %.0f req/s, bare libmicrohttpd endpoint %.0f req/s: ratio %.2f (goal >= 0.8)\n", h, b, h / b}'

echo "== warm-up: the mix, 10 s"
MM_PATHS="$paths" wrk -t2 -c"$CONNS" -d10s --timeout 10s -s tests/load/mix.lua "http://127.0.0.1:$port" \
  > "$work/warmup" 2>&1
grep -E "statuses|socket errors" "$work/warmup" | sed 's/^/   /'
sleep 1
rss0=$(rss)

echo "== the mix, ${SECS}s"
# the sampled requests are asked alone first; the load starts once verify
# says it has them
"$tool" verify "$port" "$paths" "$SECS" > "$work/verify" 2>&1 &
vpid=$!
for _ in $(seq 600); do
  grep -q "now comparing" "$work/verify" && break
  kill -0 "$vpid" 2>/dev/null || break
  sleep 0.1
done
res=$(MM_PATHS="$paths" wrk -t2 -c"$CONNS" -d"${SECS}s" --timeout 10s -s tests/load/mix.lua \
      "http://127.0.0.1:$port" 2>&1)
wait $vpid || fail=1
echo "$res" | grep -E "Requests/sec|requests in|statuses|socket errors|latency p"
cat "$work/verify"
sleep 1
rss1=$(rss)
kill -0 "$pid" 2>/dev/null || { echo "FAIL: the server died"; fail=1; }

echo
echo "== figures ($CONNS connections, server threads: ${LOAD_THREADS:-one per core})"
printf "%-22s %10s %9s %9s %9s %9s\n" "" "req/s" "p50 ms" "p90 ms" "p99 ms" "p99.9 ms"
for name in health res; do
  out=${!name}
  printf "%-22s %10s %9s %9s %9s %9s\n" "$([[ $name == health ]] && echo "/api/health (ceiling)" || echo "mix of exercises")" \
    "$(rps "$out")" "$(pct "$out" 50)" "$(pct "$out" 90)" "$(pct "$out" 99)" "$(pct "$out" 99.9)"
done
echo "verified: $(grep -o '[0-9]* compared, [0-9]* differed, [0-9]* errors' "$work/verify")"
awk -v a="$rss0" -v b="$rss1" 'BEGIN{printf "resident memory: %d kB after warm-up, %d kB after the run (%+.1f %%)\n", a, b, 100 * (b - a) / a}'

for out in "$health" "$res"; do
  echo "$out" | grep -q "statuses: .* 0 5xx" || { echo "FAIL: 5xx answers"; fail=1; }
  echo "$out" | grep -q "socket errors: connect 0, read 0, write 0, timeout 0" || { echo "FAIL: socket errors"; fail=1; }
done
grep -q " 0 differed, 0 errors" "$work/verify" || { echo "FAIL: answers differed under load, or errors"; fail=1; }
awk -v a="$rss0" -v b="$rss1" 'BEGIN{exit !(b <= 1.10 * a)}' || { echo "FAIL: memory grew over 10 %"; fail=1; }
if ((fail)); then echo "loadtest: FAILED"; exit 1; fi
echo "loadtest: passed"
