#!/usr/bin/env bash
# tests/load/stall_hunt.sh — look for a server that stops answering under
# load (127.0.0.1 only, bounded: ROUNDS x SECONDS).
#
#   tests/load/stall_hunt.sh [SERVER_BINARY] [ROUNDS] [SECONDS] [MIX_FILE]
#
# Each round starts the server, loads it with wrk (256 connections, the
# mix of `make loadtest`, made with `loadtool gen` when no file is given)
# and samples the server's CPU time every 0.5 s.  When the server uses no
# CPU for 1.5 s while wrk still runs, it prints what the sockets hold (a
# request waiting unread in the server's receive queue means the server
# lost track of it) and the server threads' stacks (gdb, when installed).
#
# It found that libmicrohttpd 0.9.75 in epoll thread-pool mode
# (MHD_USE_EPOLL_INTERNAL_THREAD + MHD_OPTION_THREAD_POOL_SIZE, with or
# without MHD_USE_TURBO) sometimes stops serving every connection at once:
# 256 requests unread in the receive queues, both workers in epoll_wait
# until the 30 s connection timeout.  About once in 150-200 s of saturated
# load; mm_http.c now runs a thread per connection instead.
set -uo pipefail
cd "$(dirname "$0")/../.."
BUILD=${BUILD:-build}
bin=${1:-$BUILD/mechmat-server}
rounds=${2:-10}
secs=${3:-8}
mix=${4:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if [[ -z "$mix" ]]; then
  mix="$work/mix"
  "$BUILD/load/loadtool" gen 2000 "$mix" || exit 1
fi
stalls=0
for r in $(seq "$rounds"); do
  "$bin" --port 0 --quiet > "$work/out" 2>/dev/null &
  pid=$!
  for _ in $(seq 100); do grep -q listening "$work/out" && break; sleep 0.05; done
  port=$(sed -n 's/.*127\.0\.0\.1:\([0-9]*\).*/\1/p' "$work/out" | head -1)
  MM_PATHS="$mix" wrk -t2 -c256 -d"${secs}s" --timeout 10s -s tests/load/mix.lua \
    "http://127.0.0.1:$port" > "$work/wrk" 2>&1 &
  wpid=$!
  idle=0 seen=0
  c0=$(awk '{print $14 + $15}' "/proc/$pid/stat")
  while kill -0 "$wpid" 2>/dev/null; do
    sleep 0.5
    c1=$(awk '{print $14 + $15}' "/proc/$pid/stat" 2>/dev/null)
    if [[ "$c1" == "$c0" ]]; then idle=$((idle + 1)); else idle=0; fi
    c0=$c1
    if ((idle >= 3 && !seen)) && kill -0 "$wpid" 2>/dev/null; then
      seen=1 stalls=$((stalls + 1))
      echo "== STALL in round $r (port $port) at $(date +%T)"
      ss -tn "( sport = :$port )" | awk 'NR > 1 {n++; if ($2 > 0) q++} END {print "   server side: " n+0 " connections, " q+0 " with a request unread (Recv-Q > 0)"}'
      ss -tn "( dport = :$port )" | awk 'NR > 1 {n++; if ($2 > 0) q++} END {print "   client side: " n+0 " connections, " q+0 " with an answer unread"}'
      if command -v gdb > /dev/null; then
        gdb -p "$pid" -batch -ex 'thread apply all bt 3' 2>/dev/null | grep -E "^Thread|^#0" | head -12 | sed 's/^/   /'
      fi
    fi
  done
  echo "round $r: $(awk '/Requests\/sec/ {print $2 " req/s"}' "$work/wrk")$( ((seen)) && echo " (stalled)")"
  kill "$pid"; wait "$pid" 2>/dev/null
done
echo "stall_hunt: $stalls stalls in $rounds rounds of ${secs}s"
((stalls == 0))
