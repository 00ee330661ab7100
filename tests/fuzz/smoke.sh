#!/usr/bin/env bash
# CTest fuzz_smoke (DESIGN.md §12): per libFuzzer target (built with clang into build/fuzz by
# ci/fuzz-build.sh, the build's target vsgl_fuzz_targets, which ci/test.sh builds before the
# tests; not part of the default build) replays the committed corpus (tests/fuzz/corpus/TARGET:
# seeds and the regression inputs of every bug found) and runs a bounded number of new inputs
# from a fixed seed, a few seconds each. Any crash, sanitizer report, leak or uncaught exception
# fails it, and so do targets missing or older than their sources. Without clang + libFuzzer it
# exits 77, which CTest shows as Skipped, with the reason.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
runs=${VSGL_FUZZ_SMOKE_RUNS:-2000}
status=0
bash ci/fuzz-build.sh --check || status=$?
if [[ $status -eq 77 ]]; then
  echo "fuzz_smoke: SKIPPED (no clang with libFuzzer): the fuzz targets were not built or run"
  exit 77
elif [[ $status -ne 0 ]]; then
  echo "fuzz_smoke: FAILED: ci/fuzz-build.sh --check exited $status"
  exit 1
fi
# Built here, the targets would stretch the test's time past any limit on a busy machine; so the
# build is a step of its own, and this only checks that it was done and is current.
build_cmd="cmake --build --preset ci --target vsgl_fuzz_targets (or bash ci/fuzz-build.sh; ci/test.sh does it)"
if [[ ! -f build/fuzz/build.ninja ]]; then
  echo "fuzz_smoke: FAILED: the fuzz targets are not built (no build/fuzz); build them with $build_cmd"
  exit 1
fi
pending=$(cmake --build build/fuzz -- -n 2>&1) || {
  echo "$pending"; echo "fuzz_smoke: FAILED: cannot read the state of build/fuzz"; exit 1; }
if ! grep -q 'no work to do' <<<"$pending"; then
  echo "$pending" | head -20
  echo "fuzz_smoke: FAILED: the fuzz targets in build/fuzz are out of date (above: what would be rebuilt); build them with $build_cmd"
  exit 1
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
  if ! "build/fuzz/$target" "$scratch/$target" "$corpus" "${dict[@]}" -seed=12345 \
      -runs="$((seeds + runs))" -max_total_time=60 -timeout=20 -rss_limit_mb=4096 \
      -artifact_prefix="$scratch/" -print_final_stats=1 >"$scratch/$target.log" 2>&1; then
    tail -n 60 "$scratch/$target.log"
    echo "fuzz_smoke: $target FAILED (the input that failed is printed above as base64 / in the log)"
    exit 1
  fi
  echo "fuzz_smoke: $target: $seeds corpus inputs replayed + up to $runs new: $(grep -E '^#[0-9]+.*DONE' "$scratch/$target.log" | tail -1)"
done
