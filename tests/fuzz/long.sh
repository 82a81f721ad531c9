#!/usr/bin/env bash
# make fuzz-long: every libFuzzer target (or those named) in turn, each until
# it has had FUZZ_CPU_SECONDS (default 3600) of CPU time, under nice 19, one
# at a time.  CPU time, not wall time: on a shared machine a niced fuzzer
# may get a small share of a core, and the figure that says how much
# fuzzing was done is the CPU it used.
#
#   tests/fuzz/long.sh [NAME...]
#
# The binary is copied before it runs, so that a rebuild meanwhile does not
# change it under the fuzzer.  New inputs go to build/fuzz/corpus-NAME,
# crashes to build/fuzz/crash-NAME-*.  The timeout (1800 s) is wall time:
# a fuzzer at nice 19 on a busy machine can be starved for seconds on one
# input (10 s gave false "timeouts" on 3-byte inputs at load 7), while a
# real hang still stops it; likewise a "slow unit" is reported only past
# 1800 s (at the default 10 s, starved inputs that run in 0.2 s were filed;
# at 300 s, a vib-beam-transient solve of 0.7 s, 3.5 s under the fuzz
# build's sanitizers, was filed as a timeout after 309 s at load 5).  The closing line of each target:
#   fuzz NAME: S CPU-s, N executions, C crashes
set -uo pipefail
cd "$(dirname "$0")/../.."
cpu=${FUZZ_CPU_SECONDS:-3600}
tick=$(getconf CLK_TCK)
names=("$@")
if ((${#names[@]} == 0)); then
  for b in build/fuzz/fuzz/fuzz_*; do names+=("${b##*/fuzz_}"); done
fi
status=0
mkdir -p build/fuzz/long
for name in "${names[@]}"; do
  src="build/fuzz/fuzz/fuzz_$name"
  [[ -x "$src" ]] || { echo "fuzz $name: no binary $src (make fuzz-bins first)"; status=1; continue; }
  bin="build/fuzz/long/fuzz_$name"
  cp "$src" "$bin"
  work="build/fuzz/corpus-$name"
  log="build/fuzz/long/$name.log"
  mkdir -p "$work"
  setsid nice -n 19 "$bin" -max_total_time=1000000 -timeout=1800 -report_slow_units=1800 -rss_limit_mb=2048 -max_len=4096 \
    -artifact_prefix="build/fuzz/crash-$name-" -print_final_stats=1 \
    "$work" "tests/fuzz/corpus/$name" > "$log" 2>&1 &
  pid=$!
  # nice 19 holds only inside a session: with the kernel's autogroups a
  # session competes as a whole at nice 0.  So the fuzzer gets a session of
  # its own (setsid) and that session is made nice 19 as well (where the
  # kernel has autogroups), leaving the caller's session as it was.  The
  # autogroup is the one of the session the process is in when it is
  # written: wait until setsid has made the fuzzer a session of its own
  # (its session id is its pid), or the caller's session is reniced instead
  for _ in $(seq 100); do
    [[ "$(awk '{print $6}' "/proc/$pid/stat" 2>/dev/null)" == "$pid" ]] && break
    sleep 0.05
  done
  echo 19 > "/proc/$pid/autogroup" 2>/dev/null || true
  used=0
  while kill -0 "$pid" 2>/dev/null; do
    sleep 20
    t=$(awk '{print $14 + $15}' "/proc/$pid/stat" 2>/dev/null) || break
    used=$((t / tick))
    ((used >= cpu)) && kill -INT "$pid"
  done
  wait "$pid"
  execs=$(grep -Eo 'stat::number_of_executed_units: [0-9]+' "$log" | awk '{print $2}')
  crashes=$(ls build/fuzz/crash-"$name"-* 2>/dev/null | wc -l)
  echo "fuzz $name: $used CPU-s, ${execs:-?} executions, $crashes crashes"
  ((crashes == 0 && used >= cpu)) || status=1
done
exit $status
