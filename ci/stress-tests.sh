#!/usr/bin/env bash
# A flake hunt you can rerun: builds once (the CI preset), then runs the whole test
# suite N times (default 10) the way ci/test.sh does, with a CPU hog (a busy loop pinned to one
# core) running all along, and prints each run's failures and a final count. Not part of .ci/run.
# Usage: bash ci/stress-tests.sh [N]       Exit 0 only when every run was green.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-10}
if ! [[ "$runs" =~ ^[0-9]+$ ]] || [[ "$runs" -lt 1 ]]; then
  echo "usage: bash ci/stress-tests.sh [N]   (N >= 1 runs of the suite, default 10)" >&2
  exit 2
fi
cmake --preset ci >/dev/null
cmake --build --preset ci

# The hog: one busy loop, on the last core when taskset is there; killed however this ends.
pin=()
if command -v taskset >/dev/null 2>&1; then pin=(taskset -c "$(( $(nproc) - 1 ))"); fi
"${pin[@]}" bash -c 'while :; do :; done' &
hog=$!
trap 'kill "$hog" 2>/dev/null || true; wait "$hog" 2>/dev/null || true' EXIT
trap 'exit 130' INT TERM
echo "ci/stress-tests.sh: CPU hog pid $hog${pin:+ on core $(( $(nproc) - 1 ))}; $runs runs of the suite (ctest -j $(nproc))"

logs=build/ci/stress
mkdir -p "$logs"
green=0
for ((i = 1; i <= runs; i++)); do
  start=$(date +%s)
  log="$logs/run-$i.log"
  if ctest --preset ci -j "$(nproc)" >"$log" 2>&1; then
    status=green
    green=$((green + 1))
  else
    status=RED
  fi
  summary=$(grep -E '^[0-9]+% tests passed' "$log" || echo "no summary (see $log)")
  echo "run $i/$runs: $status in $(( $(date +%s) - start )) s: $summary"
  # The failing tests (ctest lists them after "The following tests FAILED:"), and the skipped.
  sed -n '/The following tests FAILED:/,/^Errors while running CTest/p' "$log" | grep -E '^\s+[0-9]+ - ' | sed 's/^/  FAILED /' || true
  grep -E '\*\*\*Skipped|Not Run' "$log" | sed -E 's/^ *[0-9]+\/[0-9]+ Test +#[0-9]+: /  skipped /; s/ \.{3,}.*//' || true
done
echo "ci/stress-tests.sh: $green of $runs runs green (logs: $logs/run-N.log)"
[[ "$green" -eq "$runs" ]]
