#!/usr/bin/env bash
# make ref: the chapter-1 reference harness (tests/ref/num_ref.py) against a
# server started here on a free port, stopped at the end.  Not part of
# `make test` (minutes of 60-digit arithmetic); a developer tool for issue 10's
# "every printed digit true".  Extra arguments go to num_ref.py, e.g.
#   REF_ARGS="--only num-eigen --draws 20" make ref
set -euo pipefail
cd "$(dirname "$0")/../.."
BUILD=${BUILD:-build}
mkdir -p test-output
log=test-output/ref-server.log
"$BUILD/mechmat-server" --port 0 > "$log" 2>&1 &
pid=$!
trap 'kill "$pid" 2>/dev/null || true' EXIT
url=""
for _ in $(seq 50); do
  url=$(grep -o 'http://[0-9.]*:[0-9]*' "$log" | head -1 || true)
  [[ -n "$url" ]] && break
  sleep 0.1
done
[[ -n "$url" ]] || { echo "ref: the server did not start"; cat "$log"; exit 1; }
# shellcheck disable=SC2086
python3 tests/ref/num_ref.py --url "$url" --draws-bin "$BUILD/ref/num_draws" \
  --json test-output/ref.json ${REF_ARGS:-} | tee test-output/ref.log
