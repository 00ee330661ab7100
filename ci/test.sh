#!/usr/bin/env bash
# The README's test command: install what is missing, build with warnings as errors, and run
# every test on lavapipe with the Khronos validation layer (any validation error fails a test).
set -euo pipefail
cd "$(dirname "$0")/.."
bash ci/install-deps.sh
# The C++ lines the last commit changed follow .clang-format (skips, saying why, where it cannot tell).
bash ci/check-format.sh
start=$(date +%s)
cmake --preset ci
cmake --build --preset ci
built=$(date +%s)
# Tests pick lavapipe (VSGL_TEST_DEVICE overrides) even when a GPU is present.
ctest --preset ci -j "$(nproc)"
echo "ci/test.sh: build $((built - start)) s, tests $(( $(date +%s) - built )) s"
