#!/usr/bin/env bash
# The README's test command: install what is missing, build with warnings as errors, and run
# every test on lavapipe with the Khronos validation layer (any validation error fails a test),
# then the device tests again on SwiftShader (a second Vulkan implementation with other limits:
# 16 storage images per stage, subgroup size 4) when Debian's chromium provides its ICD; and last
# the Windows build, its tests and programs under Wine and Xvfb on lavapipe (ci/windows-test.sh,
# DESIGN.md §13.1; skipped, saying so, without mingw-w64, Wine or Xvfb, or with
# VSGL_WINDOWS_TEST=0).
set -euo pipefail
cd "$(dirname "$0")/.."
bash ci/install-deps.sh
# The C++ lines the last commit changed follow .clang-format (skips, saying why, where it cannot tell).
bash ci/check-format.sh
start=$(date +%s)
cmake --preset ci
cmake --build --preset ci
# The libFuzzer targets (clang), outside the default build; building them asks the suite's
# fuzz_smoke to run them (it fails, never skips, without them: tests/CMakeLists.txt).
cmake --build --preset ci --target vsgl_fuzz_targets
built=$(date +%s)
# Tests pick lavapipe (VSGL_TEST_DEVICE overrides) even when a GPU is present.
ctest --preset ci -j "$(nproc)"
tested=$(date +%s)
swiftshader_icd=/usr/lib/chromium/vk_swiftshader_icd.json
if [ -f "$swiftshader_icd" ]; then
  VK_ICD_FILENAMES="$swiftshader_icd" VSGL_TEST_DEVICE=SwiftShader ctest --preset ci -L gpu -j "$(nproc)"
  swift="SwiftShader gpu tests $(( $(date +%s) - tested )) s"
else
  swift="SwiftShader gpu tests skipped: $swiftshader_icd not found (install Debian's chromium)"
  echo "ci/test.sh: $swift"
fi
linux_done=$(date +%s)
if [[ ${VSGL_WINDOWS_TEST:-1} != 0 ]]; then
  bash ci/windows-test.sh
else
  echo "ci/test.sh: the Windows step is skipped: VSGL_WINDOWS_TEST=0 (bash ci/windows-test.sh runs it alone)"
fi
echo "ci/test.sh: build $((built - start)) s, tests $((tested - built)) s, $swift," \
  "Windows step $(( $(date +%s) - linux_done )) s"
