#!/usr/bin/env bash
# Packs what ci/device-run.sh needs on a GPU machine that lacks this project's build
# dependencies, into .device-pack/ (as tools.tar.xz): the four binaries (vsgl-bench, vsgl-gbench,
# vsgl-mipbench, vsgl_tests) with the layer table the tests check (harness_layers.txt), the shared
# libraries they link (all but the C runtime), the Khronos validation layer; and build.env: where
# the tests were built (they hold absolute paths to the sources and binaries) and the commit they
# were built from (with `dirty=true` when tracked files differed from it), which ci/device-run.sh
# puts into its results and ci/import-device-results.sh compares with the checkout.
#
# The captures are not packed: the paper-size captures with surface detail are 67 + 51 MiB, more
# than the whole pack may hold (48 MiB, so that it travels with a copy of the checkout), so
# ci/device-run.sh records them there. Their channel hashes land in the tables' JSON, so any
# difference from lavapipe's bytes is on record.
# The paper's scenes' models (37 MiB as glTF: Sponza and the Conference room) are packed instead,
# xz-compressed (11 MiB) as scenes.tar.xz, from the first asset directory that holds both
# (--assets DIR, then the directories of VSGL_ASSETS, then those the packed build's tests use,
# its VSGL_TEST_ASSETS, then assets/); scenes.txt lists what was packed with each file's size and
# SHA-256, and the tables' JSON names each model by its content hash. Without them the pack holds
# no models and the run times the procedural stand-ins, and says so.
#
# Usage: bash ci/device-pack.sh [BUILD_DIR]   a release build: build/release, else build/ci
#        bash ci/device-pack.sh --gl          also fetch the Vulkan loader and GL dispatch .debs
#                                             into .gl/ for a bare GPU machine (needs apt here)
#        bash ci/device-pack.sh --assets DIR  where the paper's scenes are (DIR/sponza, DIR/conference)
set -euo pipefail
cd "$(dirname "$0")/.."
pack=.device-pack
gl=false
build=""
assets=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --gl) gl=true ;;
    --assets) assets+=("${2:?--assets takes a directory}"); shift ;;
    -*) echo "ci/device-pack.sh: unknown option '$1' (BUILD_DIR, --gl, --assets DIR)" >&2; exit 2 ;;
    *) build=$1 ;;
  esac
  shift
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
[[ -f $build/harness_layers.txt ]] || { echo "ci/device-pack.sh: $build/harness_layers.txt is missing: configure $build with cmake first" >&2; exit 1; }
# Where else the paper's scenes may be: the asset search path of the programs (VSGL_ASSETS, then
# assets/), with the build's test scenes (VSGL_TEST_ASSETS in its CMake cache) before assets/.
IFS=: read -r -a more <<< "${VSGL_ASSETS:-}"
assets+=("${more[@]}")
IFS=: read -r -a more <<< "$(sed -n 's/^VSGL_TEST_ASSETS:[A-Z]*=//p' "$build/CMakeCache.txt" 2>/dev/null)"
assets+=("${more[@]}" assets)
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
cp "$build/harness_layers.txt" "$pack/bin/"  # beside vsgl_tests, where Layering looks for it
cp "$layer_json" "$pack/layer/"
cp -L "$layer_lib" "$pack/lib/"
# The tests find the sources (seed corpora, paper tables) and vsgl-bench by the absolute paths
# they were built with; ci/device-run.sh recreates both there.
{
  echo "source_dir=$(pwd)"
  echo "build_dir=$build"
  echo "commit=$(git rev-parse HEAD 2>/dev/null || echo unknown)"
  if [[ -n $(git status --porcelain --untracked-files=no 2>/dev/null) ]]; then echo "dirty=true"; else echo "dirty=false"; fi
  echo "packed=$(date -u +%FT%TZ)"
} > "$pack/build.env"
if $gl; then
  # What a bare GPU machine lacks: the loader and the GL dispatch that NVIDIA's ICD links against.
  rm -rf .gl && mkdir -p .gl /tmp/amd64/partial
  o=(-oAPT::Architecture=amd64 -oAPT::Architectures=amd64 -oDir::State::Lists=/tmp/amd64)
  apt-get "${o[@]}" update >/dev/null
  (cd .gl && apt-get "${o[@]}" download libvulkan1 libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2 >/dev/null)
fi
# The paper's scenes: the preset files' model paths, relative to an asset directory.
scene_files=(sponza/Sponza.gltf sponza/Sponza.bin sponza/textures conference/conference.gltf conference/conference.bin
  conference/textures)
for dir in "${assets[@]}"; do
  have=true
  for f in "${scene_files[@]}"; do [[ -e $dir/$f ]] || have=false; done
  if $have; then
    tar cf - -C "$dir" "${scene_files[@]}" | xz -6 -T2 > "$pack/scenes.tar.xz"
    (cd "$dir" && find "${scene_files[@]}" -type f -print0 | sort -z | xargs -0 sha256sum |
      while read -r sum f; do echo "$f $(stat -c %s "$f") sha256:$sum"; done) > "$pack/scenes.txt"
    echo "ci/device-pack.sh: packed the paper's scenes from $dir ($(du -sm "$pack/scenes.tar.xz" | cut -f1) MiB compressed)"
    break
  fi
done
[[ -f $pack/scenes.tar.xz ]] || echo "ci/device-pack.sh: the paper's scenes are in none of ${assets[*]}: the run will time the stand-ins" >&2
# The binaries, libraries and layer travel xz-compressed too (47 MiB, most of it the validation
# layer, become about 12): ci/device-run.sh unpacks them first.
tar cf - -C "$pack" bin lib layer | xz -6 -T2 > "$pack/tools.tar.xz"
rm -rf "$pack/bin" "$pack/lib" "$pack/layer"
size=$(du -sm "$pack" | cut -f1)
echo "ci/device-pack.sh: $pack holds $size MiB (from $build)"
du -sh "$pack"/* .gl 2>/dev/null || true
if (( size > 48 )); then
  echo "ci/device-pack.sh: $pack is over 48 MiB, the most it may hold to travel with a copy of the checkout" >&2
  exit 1
fi
