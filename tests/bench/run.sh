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
echo "######## server against a bare libmicrohttpd endpoint (127.0.0.1, wrk -t2 -c16, ${DUR}s a run, 3 rounds interleaved, medians)"
if ! command -v wrk >/dev/null; then echo "wrk missing"; exit 0; fi
work=$(mktemp -d)
start() {  # $1 name, then the command; sets ${name}_pid, ${name}_port
  "${@:2}" > "$work/$1.out" 2>&1 &
  eval "${1}_pid=$!"
  for _ in $(seq 100); do grep -q listening "$work/$1.out" && break; sleep 0.05; done
  eval "${1}_port=$(sed -n 's/.*127\.0\.0\.1:\([0-9]*\).*/\1/p' "$work/$1.out" | head -1)"
}
start bare "$BUILD/bench/bare_mhd" pool
start srv "$BUILD/mechmat-server" --port 0 --quiet --threads 2
trap 'kill $bare_pid $srv_pid 2>/dev/null; rm -rf "$work"' EXIT
hz=$(getconf CLK_TCK)
cpu() { awk '{print $14 + $15}' "/proc/$1/stat"; }
rps() {  # $1 url, further args to wrk -> req/s
  wrk -t2 -c16 -d"${DUR}s" "${@:2}" "$1" 2>&1 | awk '/Requests\/sec/ {print $2}'
}
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END{print a[int((NR+1)/2)]}'; }
solve="http://127.0.0.1:$srv_port/api/exercises/vib-sdof-forced/solve"
curl -s -o /dev/null "$solve"; curl -s -o /dev/null -H 'Accept-Encoding: gzip' "$solve"      # cached, both forms
wrk -t2 -c16 -d1s "http://127.0.0.1:$bare_port/" > /dev/null 2>&1                           # warm-up
b=() h=() r=() z=()
for round in 1 2 3; do
  b+=("$(rps "http://127.0.0.1:$bare_port/")")
  h+=("$(rps "http://127.0.0.1:$srv_port/api/health")")
  r+=("$(rps "$solve")")
  z+=("$(rps "$solve" -H 'Accept-Encoding: gzip')")
done
B=$(median "${b[@]}") H=$(median "${h[@]}") R=$(median "${r[@]}") Z=$(median "${z[@]}")
size=$(curl -s "$solve" | wc -c); zsize=$(curl -s -H 'Accept-Encoding: gzip' "$solve" | wc -c)
printf "%-58s %10s req/s\n" "bare libmicrohttpd endpoint (200 bytes, 2 epoll threads)" "$B"
printf "%-58s %10s req/s  ratio %.2f  (goal >= 0.8)\n" "/api/health" "$H" "$(awk -v a="$H" -v b="$B" 'BEGIN{print a/b}')"
printf "%-58s %10s req/s  ratio %.2f  (%d bytes)\n" "repeated vib-sdof-forced (cache hit, plain)" "$R" \
  "$(awk -v a="$R" -v b="$B" 'BEGIN{print a/b}')" "$size"
printf "%-58s %10s req/s  ratio %.2f  (goal >= 0.8; %d bytes gzip)\n" "repeated vib-sdof-forced (cache hit, gzip, as browsers)" "$Z" \
  "$(awk -v a="$Z" -v b="$B" 'BEGIN{print a/b}')" "$zsize"
echo "   rounds: bare ${b[*]} | health ${h[*]} | plain ${r[*]} | gzip ${z[*]}"

# distinct requests: every one a miss (omega moves by 1e-9 each time), so
# each is resolved, solved, written and put in the cache (and evicts)
cat > "$work/distinct.lua" <<'LUA'
local n = 0
function setup(thread) thread:set("base", math.random(1, 1000000) * 1000) end
function request()
  n = n + 1
  return wrk.format("GET", string.format("/api/exercises/vib-sdof-forced/solve?omega=%.9f", 8 + (base + n) * 1e-9),
                    { Host = "127.0.0.1" })
end
LUA
distinct() {  # $1 label, more wrk args
  local c0 c1 res reqs
  c0=$(cpu "$srv_pid")
  res=$(wrk -t2 -c16 -d"${DUR}s" -s "$work/distinct.lua" "${@:2}" "http://127.0.0.1:$srv_port" 2>&1)
  c1=$(cpu "$srv_pid")
  reqs=$(echo "$res" | awk '/requests in/ {print $1}')
  printf "%-58s %10s req/s  %7.1f us server CPU/request\n" "$1" "$(echo "$res" | awk '/Requests\/sec/ {print $2}')" \
    "$(awk -v c=$((c1 - c0)) -v hz="$hz" -v n="$reqs" 'BEGIN{print c / hz * 1e6 / n}')"
}
distinct "distinct vib-sdof-forced requests (plain)"
distinct "distinct vib-sdof-forced requests (gzip, as browsers)" -H 'Accept-Encoding: gzip'
echo "   (goal: <= 60 us server CPU per distinct request; bench_server above splits one request into its parts)"
kill $bare_pid $srv_pid 2>/dev/null; wait $bare_pid $srv_pid 2>/dev/null
trap - EXIT
rm -rf "$work"

if [[ -f tests/web/bench.mjs ]]; then
  echo
  echo "######## browser: redraw and first plot"
  MM_SERVER="$BUILD/mechmat-server" node tests/web/bench.mjs
fi
