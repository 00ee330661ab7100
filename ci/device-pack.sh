#!/usr/bin/env bash
# Packs what a run on another machine (e.g. a lent GPU machine without this project's build
# dependencies) needs into .device-pack/: the release binaries, the shared libraries they link
# (all but the C runtime), and the captures. The captures are carried, not re-recorded there, so
# every device times the very same input bytes (SPEC §2: content hashes).
# Usage: bash ci/device-pack.sh          (after `bash ci/reproduce.sh` or a release build + captures)
#        bash ci/device-pack.sh --tests  the GoogleTest binary and the Khronos validation layer
#                                        instead of the captures, to run the test suite there:
#   VK_LAYER_PATH=.device-pack/layer LD_LIBRARY_PATH=.device-pack/lib VSGL_TEST_DEVICE=<name> \
#     .device-pack/bin/vsgl_tests --gtest_filter=-'Cli*:*Cli.*:ValidationLayer.CountsErrorsOfInvalidCalls'
#   (the CLI tests run the binary at its build path; that validation test asks for lavapipe)
set -euo pipefail
cd "$(dirname "$0")/.."
pack=.device-pack
tests=false
[[ "${1:-}" == "--tests" ]] && tests=true
rm -rf "$pack"
mkdir -p "$pack/bin" "$pack/lib" "$pack/captures"
executables=(vsgl-bench vsgl-gbench)
$tests && executables=(../tests/vsgl_tests)
for exe in "${executables[@]}"; do
  [[ -x build/release/bench/$exe ]] || { echo "ci/device-pack.sh: build/release/bench/$exe is missing: build the release preset first" >&2; exit 1; }
  cp build/release/bench/$exe "$pack/bin/"
  ldd "build/release/bench/$exe" | awk '$3 ~ /^\// {print $3}' | while read -r lib; do
    case "$(basename "$lib")" in
      libc.so.*|libm.so.*|ld-linux*|libpthread.so.*|libdl.so.*|librt.so.*) ;;  # the target's own C runtime
      *) cp -L "$lib" "$pack/lib/" ;;
    esac
  done
done
if $tests; then
  mkdir -p "$pack/layer"
  cp /usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json "$pack/layer/"
  cp /usr/lib/x86_64-linux-gnu/libVkLayer_khronos_validation.so "$pack/lib/"
  du -sh "$pack"
  exit 0
fi
for scene in atrium conference; do
  [[ -f captures/$scene/capture.json ]] || { echo "ci/device-pack.sh: captures/$scene is missing: run vsgl-bench record first" >&2; exit 1; }
  cp -r "captures/$scene" "$pack/captures/"
done
du -sh "$pack"
