#!/usr/bin/env bash
# A long fuzzing run of one target: bash ci/fuzz.sh TARGET SECONDS [extra libFuzzer flags]
# TARGET: one of tests/fuzz/fuzz_*.cpp (fuzz_capture, fuzz_run_json, fuzz_sweep_json, fuzz_paper_tables,
# fuzz_gltf, fuzz_obj). Builds build/fuzz
# (clang, libFuzzer + ASan + UBSan) if needed, starts from the committed seed corpus
# (tests/fuzz/corpus/TARGET, read only) and keeps what it finds in build/fuzz/corpus/TARGET;
# crash / leak / timeout inputs land in build/fuzz/artifacts/TARGET/. Minimize one with
#   build/fuzz/TARGET -minimize_crash=1 -runs=10000 ARTIFACT
# and keep the result in tests/fuzz/corpus/TARGET/regression-<what>. The final stats line
# (cov: / ft: / exec/s) is the coverage of the run. Exit: libFuzzer's (0 = nothing found).
set -euo pipefail
cd "$(dirname "$0")/.."
# The targets are the sources in tests/fuzz/, so a new target needs no edit here.
targets=$(cd tests/fuzz && ls fuzz_*.cpp | sed 's/\.cpp$//' | paste -sd '|' -)
if [[ $# -lt 2 ]]; then
  echo "usage: bash ci/fuzz.sh $targets SECONDS [libFuzzer flags]" >&2
  exit 2
fi
target=$1 seconds=$2
shift 2
if [[ ! -f "tests/fuzz/$target.cpp" || "$target" != fuzz_* ]]; then
  echo "ci/fuzz.sh: unknown target '$target' ($targets)" >&2; exit 2
fi
[[ "$seconds" =~ ^[0-9]+$ && "$seconds" -gt 0 ]] || { echo "ci/fuzz.sh: SECONDS must be a positive whole number" >&2; exit 2; }
bash ci/fuzz-build.sh
dict=()
[[ -f "tests/fuzz/$target.dict" ]] && dict=("-dict=tests/fuzz/$target.dict")
mkdir -p "build/fuzz/corpus/$target" "build/fuzz/artifacts/$target"
# rss limit: a capture view may hold up to 2^25 texels (kMaxViewTexels, capture_sidecar.cpp).
exec "build/fuzz/$target" "build/fuzz/corpus/$target" "tests/fuzz/corpus/$target" \
  "${dict[@]}" -max_total_time="$seconds" -print_final_stats=1 -timeout=25 -rss_limit_mb=4096 \
  -artifact_prefix="build/fuzz/artifacts/$target/" "$@"
