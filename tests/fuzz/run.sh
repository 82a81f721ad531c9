#!/usr/bin/env bash
# make fuzz: run every libFuzzer target for FUZZ_SECONDS from its committed
# seed corpus.  A crash leaves its input in build/fuzz/crash-NAME-*: fix the
# bug, then copy the input into tests/fuzz/corpus/NAME/ so that `make test`
# replays it forever after.
set -uo pipefail
cd "$(dirname "$0")/../.."
secs=${FUZZ_SECONDS:-60}
status=0
for bin in build/fuzz/fuzz/fuzz_*; do
  name=${bin##*/fuzz_}
  work="build/fuzz/corpus-$name"
  mkdir -p "$work"
  echo "== fuzz $name for ${secs}s"
  if ! "$bin" -max_total_time="$secs" -timeout=10 -rss_limit_mb=2048 -max_len=4096 \
       -artifact_prefix="build/fuzz/crash-$name-" -print_final_stats=1 \
       "$work" "tests/fuzz/corpus/$name" 2>&1 | grep -E "^(#[0-9]+.*DONE|stat::number_of_executed_units|stat::new_units_added|==.*ERROR|SUMMARY)"; then
    :
  fi
  if ls build/fuzz/crash-"$name"-* >/dev/null 2>&1; then
    echo "   CRASH: $(ls build/fuzz/crash-"$name"-* | head -3)"; status=1
  fi
done
exit $status
