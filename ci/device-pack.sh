#!/usr/bin/env bash
# Packs what ci/device-run.sh needs on a machine without this project's build dependencies (a lent
# GPU machine) into .device-pack/: the four binaries (vsgl-bench, vsgl-gbench, vsgl-mipbench,
# vsgl_tests), the shared libraries they link (all but the C runtime), the Khronos validation
# layer, and where the tests were built (they hold absolute paths to the sources and binaries).
#
# The captures are not packed: the paper-size captures with surface detail are 67 + 51 MiB, over
# the 64 MiB a lent machine's working tree may carry, so ci/device-run.sh records them there. Their
# channel hashes land in the tables' JSON, so any difference from lavapipe's bytes is on record.
#
# Usage: bash ci/device-pack.sh [BUILD_DIR]   a release build: build/release, else build/ci
#        bash ci/device-pack.sh --gl          also fetch the Vulkan loader and GL dispatch .debs
#                                             into .gl/ for a bare machine (needs apt here)
set -euo pipefail
cd "$(dirname "$0")/.."
pack=.device-pack
gl=false
build=""
for a in "$@"; do
  case "$a" in
    --gl) gl=true ;;
    -*) echo "ci/device-pack.sh: unknown option '$a' (BUILD_DIR, --gl)" >&2; exit 2 ;;
    *) build=$a ;;
  esac
done
if [[ -z "$build" ]]; then
  for b in build/release build/ci; do [[ -x $b/bench/vsgl-bench ]] && { build=$b; break; }; done
fi
[[ -n "$build" ]] || { echo "ci/device-pack.sh: no release build (build/release or build/ci): cmake --preset release && cmake --build build/release" >&2; exit 1; }
build=$(cd "$build" && pwd)
binaries=(bench/vsgl-bench bench/vsgl-gbench bench/vsgl-mipbench tests/vsgl_tests)
for exe in "${binaries[@]}"; do
  [[ -x $build/$exe ]] || { echo "ci/device-pack.sh: $build/$exe is missing: build every target of $build first" >&2; exit 1; }
done
layer_json=/usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json
layer_lib=$(ldconfig -p | awk '/libVkLayer_khronos_validation.so/ {print $NF; exit}')
[[ -f $layer_json && -n "$layer_lib" ]] || { echo "ci/device-pack.sh: the Khronos validation layer is not installed (bash ci/install-deps.sh)" >&2; exit 1; }

rm -rf "$pack"
mkdir -p "$pack/bin" "$pack/lib" "$pack/layer"
for exe in "${binaries[@]}"; do
  cp "$build/$exe" "$pack/bin/"
  ldd "$build/$exe" | awk '$3 ~ /^\// {print $3}' | while read -r lib; do
    case "$(basename "$lib")" in
      libc.so.*|libm.so.*|ld-linux*|libpthread.so.*|libdl.so.*|librt.so.*) ;;  # the target's own C runtime
      *) cp -L "$lib" "$pack/lib/" ;;
    esac
  done
done
strip --strip-unneeded "$pack"/bin/*  # symbols only; a third of the pack
cp "$layer_json" "$pack/layer/"
cp -L "$layer_lib" "$pack/lib/"
# The tests find the sources (seed corpora, paper tables) and vsgl-bench by the absolute paths
# they were built with; ci/device-run.sh recreates both there.
{
  echo "source_dir=$(pwd)"
  echo "build_dir=$build"
  echo "commit=$(git rev-parse HEAD 2>/dev/null || echo unknown)"
} > "$pack/build.env"
if $gl; then
  # The packages the device tool's README names for a bare machine: the loader and GL dispatch
  # that NVIDIA's ICD links against.
  rm -rf .gl && mkdir -p .gl /tmp/amd64/partial
  o=(-oAPT::Architecture=amd64 -oAPT::Architectures=amd64 -oDir::State::Lists=/tmp/amd64)
  apt-get "${o[@]}" update >/dev/null
  (cd .gl && apt-get "${o[@]}" download libvulkan1 libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2 >/dev/null)
fi
size=$(du -sm "$pack" | cut -f1)
echo "ci/device-pack.sh: $pack holds $size MiB (from $build)"
du -sh "$pack"/* .gl 2>/dev/null || true
if (( size > 48 )); then
  echo "ci/device-pack.sh: $pack is over 48 MiB; with the working tree it would pass the 64 MiB a lent machine takes" >&2
  exit 1
fi
