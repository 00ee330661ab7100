#!/usr/bin/env bash
# CTest fuzz_smoke (DESIGN.md §12): builds the libFuzzer targets with clang (ci/fuzz-build.sh, into
# build/fuzz), then per target replays the committed corpus (tests/fuzz/corpus/TARGET: seeds
# and the regression inputs of every bug found) and runs a bounded number of new inputs from a
# fixed seed, a few seconds each. Any crash, sanitizer report, leak or uncaught exception fails
# it. Without clang + libFuzzer it exits 77, which CTest shows as Skipped, with the reason.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
cd "$root"
runs=${VSGL_FUZZ_SMOKE_RUNS:-2000}
status=0
mkdir -p build
bash ci/fuzz-build.sh >build/fuzz-smoke-build.log 2>&1 || status=$?
if [[ $status -eq 77 ]]; then
  cat build/fuzz-smoke-build.log
  rm -f build/fuzz-smoke-build.log
  echo "fuzz_smoke: SKIPPED (no clang with libFuzzer): the fuzz targets were not built or run"
  exit 77
elif [[ $status -ne 0 ]]; then
  cat build/fuzz-smoke-build.log
  rm -f build/fuzz-smoke-build.log
  echo "fuzz_smoke: FAILED to build the fuzz targets"
  exit 1
fi
rm -f build/fuzz-smoke-build.log
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
