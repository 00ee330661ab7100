#!/usr/bin/env bash
# CTest shipped_programs_hold_no_test_hooks: the shipped programs and the libraries they are made
# of hold none of the test hooks (tests/hooks/, docs/testing.md "Test hooks"): no pause-at-write
# environment variable, no --debug-slow option, no symbol of either, no test kernel
# (kernels/test_*.comp). The test build of vsgl-bench,
# which links the hooks, is the control: each needle must be found in it, so a needle that the
# hooks no longer leave (a renamed variable, a stripped symbol) fails here instead of passing
# unseen.
# Usage: shipped_hooks.sh TEST_BUILD_PROGRAM SHIPPED_FILE...
set -euo pipefail
if [[ $# -lt 2 ]]; then
  echo "usage: shipped_hooks.sh TEST_BUILD_PROGRAM SHIPPED_FILE..." >&2
  exit 2
fi
control=$1
shift
needles=(VSGL_TEST_PAUSE_AT VSGL_TEST_PAUSE_NOTIFY debug-slow debug_slowdown DebugSlow pause_at_write
  test_workload.comp test_division.comp test_vsgl_math.comp test_ism_lookup.comp)
failures=0
for needle in "${needles[@]}"; do
  if ! grep -aqF -- "$needle" "$control"; then
    echo "shipped_hooks: FAILED: the control $control does not hold '$needle': the check would see nothing"
    failures=$((failures + 1))
  fi
done
for file in "$@"; do
  [[ -f "$file" ]] || { echo "shipped_hooks: FAILED: $file is not there"; failures=$((failures + 1)); continue; }
  for needle in "${needles[@]}"; do
    if grep -aqF -- "$needle" "$file"; then
      echo "shipped_hooks: FAILED: $file holds the test hook '$needle'"
      failures=$((failures + 1))
    fi
  done
done
[[ $failures -eq 0 ]] || exit 1
echo "shipped_hooks: none of ${needles[*]} in the $# shipped files; all of them in the control"
