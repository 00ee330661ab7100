#!/usr/bin/env bash
# CTest fuzz_smoke_gate: both sides of fuzz_smoke's rule (tests/fuzz/smoke.sh) where the fuzz
# targets are not built (an empty fuzz folder): in a build never asked to fuzz it must exit 77
# (Skipped), never fail, and name the command that builds the targets; in a build asked to fuzz
# (the mark of vsgl_fuzz_targets present, as in ci/test.sh) it must fail, never pass or skip.
# Usage: smoke_gate.sh BUILD_COMMAND
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
if [[ $# -ne 1 ]]; then
  echo "usage: smoke_gate.sh BUILD_COMMAND" >&2
  exit 2
fi
build_cmd=$1
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
mkdir "$scratch/fuzz"
failures=0

run_smoke() {  # mark: the output in $scratch/out, the exit code echoed
  local rc=0
  bash "$here/smoke.sh" "$scratch/asked" "$build_cmd" "$scratch/fuzz" >"$scratch/out" 2>&1 || rc=$?
  echo "$rc"
}

expect() {  # what rc wanted_rc wanted_text
  if [[ $2 -ne $3 ]] || ! grep -qF -- "$4" "$scratch/out"; then
    echo "smoke_gate: FAILED: $1: exit $2 (wanted $3), output (wanted it to hold '$4'):"
    sed 's/^/  /' "$scratch/out"
    failures=$((failures + 1))
  else
    echo "smoke_gate: $1: exit $2: $(head -1 "$scratch/out")"
  fi
}

rc=$(run_smoke)
expect "a build not asked to fuzz" "$rc" 77 "SKIPPED"
expect "a build not asked to fuzz names the build command" "$rc" 77 "$build_cmd"

touch "$scratch/asked"
rc=$(run_smoke)
expect "a build asked to fuzz (CI)" "$rc" 1 "FAILED"
expect "a build asked to fuzz names the build command" "$rc" 1 "$build_cmd"

[[ $failures -eq 0 ]] || exit 1
