#!/usr/bin/env bash
# Run every test suite and print one closing line: "N passed, N failed".
# Each cmocka binary prints its own summary; we add the counts up.
# BUILD selects the build directory (build, or build/asan for make asan).
set -uo pipefail
cd "$(dirname "$0")/.."
BUILD=${BUILD:-build}
export MM_BUILD=$BUILD
export MM_SERVER="$BUILD/mechmat-server"
mkdir -p test-output

passed=0; failed=0; broken=()

count() {  # $1 = log file; add the cmocka summary lines to the totals
  local p f
  p=$(grep -Eo '^\[  PASSED  \] [0-9]+' "$1" | awk '{s+=$4} END{print s+0}')
  f=$(grep -Eo '^\[  FAILED  \] [0-9]+' "$1" | awk '{s+=$4} END{print s+0}')
  passed=$((passed + p)); failed=$((failed + f))
}

for t in "$BUILD"/tests/test_*; do
  [[ -x "$t" ]] || continue
  name=$(basename "$t")
  log="test-output/$name.log"
  echo "== $name"
  start=$SECONDS
  "$t" > "$log" 2>&1
  rc=$?
  tail -n 3 "$log" | grep -E 'PASSED|FAILED' | sed "s/\$/ ($((SECONDS - start)) s)/; s/^/   /"
  count "$log"
  if ((rc != 0)); then
    grep -E '^\[  (FAILED|ERROR)|error|Error' "$log" | head -20 | sed 's/^/   /'
    if ! grep -q '^\[  FAILED  \]' "$log"; then
      broken+=("$name (exit $rc)"); failed=$((failed + 1))
    fi
  fi
done

# Browser tests (Playwright on Debian's Chromium), unless asked not to.
if [[ -z "${ASAN:-}" && -z "${MM_NO_BROWSER:-}" && -f tests/web/run.mjs ]]; then
  echo "== browser"
  log=test-output/browser.log
  node tests/web/run.mjs > "$log" 2>&1
  rc=$?
  # a failure is named wherever it falls in the log, not only in its tail
  grep -E -A8 '^FAIL ' "$log" | head -60 | sed 's/^/   /'
  tail -n 5 "$log" | sed 's/^/   /'
  p=$(grep -Eo '^browser: [0-9]+ passed' "$log" | awk '{print $2}' | tail -1)
  f=$(grep -Eo '^browser: [0-9]+ passed, [0-9]+ failed' "$log" | awk '{print $4}' | tail -1)
  passed=$((passed + ${p:-0})); failed=$((failed + ${f:-0}))
  if ((rc != 0)) && [[ -z "$f" || "$f" == 0 ]]; then
    broken+=("browser (exit $rc)"); failed=$((failed + 1))
  fi
fi

for b in "${broken[@]}"; do echo "broken: $b"; done
echo "$passed passed, $failed failed"
((failed == 0))
