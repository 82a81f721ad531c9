#!/usr/bin/env bash
# make bench: every benchmark binary, then the server under wrk (loopback
# only, bounded in time), then the page in the browser.  Prints figures;
# judging them is for people (see PERFORMANCE.md for the yardsticks).
set -uo pipefail
cd "$(dirname "$0")/../.."
BUILD=${BUILD:-build}
DUR=${MM_BENCH_SECONDS:-5}

for b in "$BUILD"/bench/bench_*; do
  [[ -x "$b" ]] || continue
  echo
  echo "######## $(basename "$b")"
  "$b"
done

echo
echo "######## server: CPU per request under wrk (127.0.0.1, ${DUR}s each, 2 threads, 16 connections)"
if ! command -v wrk >/dev/null; then echo "wrk missing"; exit 0; fi
out=$(mktemp)
"$BUILD/mechmat-server" --port 0 --quiet --threads 2 > "$out" &
pid=$!
for _ in $(seq 50); do grep -q listening "$out" && break; sleep 0.1; done
port=$(sed -n 's/.*127\.0\.0\.1:\([0-9]*\).*/\1/p' "$out" | head -1)
hz=$(getconf CLK_TCK)
cpu() { awk '{print $14 + $15}' "/proc/$pid/stat"; }

measure() {  # $1 name, $2 path -> prints req/s and server CPU us per request
  wrk -t2 -c16 -d1s "http://127.0.0.1:$port$2" > /dev/null 2>&1   # warm up
  local c0 c1 res reqs rps
  c0=$(cpu)
  res=$(wrk -t2 -c16 -d"${DUR}s" --latency "http://127.0.0.1:$port$2" 2>&1)
  c1=$(cpu)
  reqs=$(echo "$res" | awk '/requests in/ {print $1}')
  rps=$(echo "$res" | awk '/Requests\/sec/ {print $2}')
  p50=$(echo "$res" | awk '$1=="50%" {print $2}')
  p99=$(echo "$res" | awk '$1=="99%" {print $2}')
  local us
  us=$(awk -v c=$((c1 - c0)) -v hz="$hz" -v n="$reqs" 'BEGIN{printf "%.1f", c / hz * 1e6 / n}')
  printf "%-44s %10s req/s  %8s us CPU/request  p50 %s  p99 %s\n" "$1" "$rps" "$us" "$p50" "$p99"
  eval "$3=$us"
}
measure "/api/health" "/api/health" health_us
measure "vib-sdof-forced solve (defaults)" "/api/exercises/vib-sdof-forced/solve" solve_us
awk -v h="$health_us" -v s="$solve_us" 'BEGIN{printf "solve / health CPU ratio: %.2f   (goal: solve <= 60 us of server CPU; PERFORMANCE.md: naive 720 us, ceiling ~9 us)\n", s / h}'
kill "$pid"; wait "$pid" 2>/dev/null; rm -f "$out"

if [[ -f tests/web/bench.mjs ]]; then
  echo
  echo "######## browser: redraw and first plot"
  MM_SERVER="$BUILD/mechmat-server" node tests/web/bench.mjs
fi
