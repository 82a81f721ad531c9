#!/usr/bin/env bash
# make valgrind: every unit test that does not start a server, under
# valgrind's memcheck; any leak or error fails it.  Closing line as usual.
set -uo pipefail
cd "$(dirname "$0")/.."
BUILD=${BUILD:-build}
mkdir -p test-output
export MM_VALGRIND=1   # tests that need a fused multiply-add skip those assertions
passed=0; failed=0
for t in "$BUILD"/tests/test_*; do
  name=$(basename "$t")
  [[ "$name" == test_http* || "$name" == test_badinput* ]] && continue   # these run the server binary
  log="test-output/valgrind-$name.log"
  if valgrind --quiet --leak-check=full --show-leak-kinds=definite,indirect,possible \
       --errors-for-leak-kinds=definite,indirect,possible --error-exitcode=99 \
       "$t" > "$log" 2>&1; then
    echo "valgrind clean: $name"; passed=$((passed + 1))
  else
    echo "valgrind FAILED: $name (see $log)"; grep -E "==[0-9]+== (Invalid|.*definitely|.*indirectly|.*possibly|Conditional)" "$log" | head -5
    failed=$((failed + 1))
  fi
done
echo "$passed passed, $failed failed"
((failed == 0))
