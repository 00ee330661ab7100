#!/usr/bin/env bash
# CTest fuzz_smoke (DESIGN.md §12): per libFuzzer target (built with clang into build/fuzz by
# ci/fuzz-build.sh, the build's target vsgl_fuzz_targets, which ci/test.sh builds before the
# tests; not part of the default build) replays the committed corpus (tests/fuzz/corpus/TARGET:
# seeds and the regression inputs of every bug found) and runs a bounded number of new inputs
# from a fixed seed, a few seconds each. Any crash, sanitizer report, leak or uncaught exception
# fails it.
#
# Usage: smoke.sh ASKED_MARK BUILD_COMMAND [FUZZ_DIR]
#   ASKED_MARK     the file the build's target vsgl_fuzz_targets creates when it is built: its build
#                  was asked to fuzz. Then targets that are missing, out of date or cannot be built
#                  (no clang with libFuzzer) fail the test, so a CI run never passes without them.
#                  Without it (a plain build) the test never fails for them: it exits 77 (CTest
#                  shows Skipped) and names BUILD_COMMAND, which builds them.
#   FUZZ_DIR       where the targets are (default: build/fuzz of the checkout).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
if [[ $# -lt 2 || $# -gt 3 ]]; then
  echo "usage: smoke.sh ASKED_MARK BUILD_COMMAND [FUZZ_DIR]" >&2
  exit 2
fi
asked_mark=$1
build_cmd=$2
fuzz_dir=${3:-build/fuzz}
runs=${VSGL_FUZZ_SMOKE_RUNS:-2000}
# Not run: fails in a build that was asked to fuzz, is Skipped (77) in any other.
not_run() {
  if [[ -e "$asked_mark" ]]; then
    echo "fuzz_smoke: FAILED: $1 ($asked_mark says this build was asked to fuzz); build them with $build_cmd"
    exit 1
  fi
  echo "fuzz_smoke: SKIPPED: $1; this build was not asked to fuzz: $build_cmd builds them, and then this test runs them"
  exit 77
}
status=0
bash ci/fuzz-build.sh --check >/dev/null 2>&1 || status=$?
if [[ $status -eq 77 ]]; then
  not_run "no clang with libFuzzer here (bash ci/fuzz-build.sh --check says why)"
elif [[ $status -ne 0 ]]; then
  echo "fuzz_smoke: FAILED: ci/fuzz-build.sh --check exited $status"
  exit 1
fi
# Built here, the targets would stretch the test's time past any limit on a busy machine; so the
# build is a step of its own, and this only checks that it was done and is current.
[[ -f "$fuzz_dir/build.ninja" ]] || not_run "the fuzz targets are not built (no $fuzz_dir/build.ninja)"
pending=$(cmake --build "$fuzz_dir" -- -n 2>&1) || {
  echo "$pending"; echo "fuzz_smoke: FAILED: cannot read the state of $fuzz_dir"; exit 1; }
if ! grep -q 'no work to do' <<<"$pending"; then
  echo "$pending" | head -20
  not_run "the fuzz targets in $fuzz_dir are out of date (above: what would be rebuilt)"
fi
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
for target in fuzz_capture fuzz_run_json fuzz_sweep_json fuzz_paper_tables fuzz_gltf fuzz_obj; do
  corpus="tests/fuzz/corpus/$target"
  seeds=$(find "$corpus" -type f | wc -l)
  mkdir -p "$scratch/$target"
  # New inputs go to the scratch directory (first), never into the committed corpus.
  dict=()
  [[ -f "tests/fuzz/$target.dict" ]] && dict=(-dict="tests/fuzz/$target.dict")
  if ! "$fuzz_dir/$target" "$scratch/$target" "$corpus" "${dict[@]}" -seed=12345 \
      -runs="$((seeds + runs))" -max_total_time=60 -timeout=20 -rss_limit_mb=4096 \
      -artifact_prefix="$scratch/" -print_final_stats=1 >"$scratch/$target.log" 2>&1; then
    tail -n 60 "$scratch/$target.log"
    echo "fuzz_smoke: $target FAILED (the input that failed is printed above as base64 / in the log)"
    exit 1
  fi
  echo "fuzz_smoke: $target: $seeds corpus inputs replayed + up to $runs new: $(grep -E '^#[0-9]+.*DONE' "$scratch/$target.log" | tail -1)"
done
