#!/usr/bin/env bash
# Builds the libraries of the Windows cross build (the windows-cross preset, DESIGN.md §13) into
# a prefix in the build tree, from Debian packages only:
#   - Imath, OpenEXR and Google Benchmark from Debian's source packages (apt-get source; needs
#     the deb-src line ci/install-deps.sh adds), GoogleTest from /usr/src/googletest;
#   - nlohmann-json, GLM, CLI11, stb, tinygltf, tinyobjloader from the headers in /usr/include
#     (cmake/windows-deps: symlinks to just those headers, never /usr/include itself, whose
#     glibc headers would shadow mingw's; stb, tinygltf and tinyobjloader compiled as static
#     libraries, as Debian compiles them as shared ones);
#   - an import library for the Vulkan loader vulkan-1.dll, made with gendef/dlltool from Wine's
#     vulkan-1.dll (the programs load the GPU driver's loader at run time);
#   - zlib is Debian's libz-mingw-w64-dev (its static libz.a).
# Everything is static, built with cmake/toolchains/mingw-w64-x86_64.cmake. Each step leaves a
# stamp; a step whose stamp exists is skipped, so a second run does nothing.
# Usage: bash ci/windows-deps.sh [PREFIX]     (default build/windows-deps)
set -euo pipefail
src=$(cd "$(dirname "$0")/.." && pwd)
prefix=${1:-$src/build/windows-deps}
mkdir -p "$prefix"
prefix=$(cd "$prefix" && pwd)
toolchain=$src/cmake/toolchains/mingw-w64-x86_64.cmake
triple=x86_64-w64-mingw32
jobs=$(nproc)

need() {  # need COMMAND PACKAGE
  command -v "$1" >/dev/null 2>&1 && return 0
  echo "ci/windows-deps.sh: $1 is missing (Debian package $2); run: bash ci/install-deps.sh" >&2
  exit 1
}
need $triple-g++-posix g++-mingw-w64-x86-64-posix
need gendef mingw-w64-tools
need $triple-dlltool binutils-mingw-w64-x86-64
need dpkg-source dpkg-dev
need ninja ninja-build
[[ -f /usr/$triple/lib/libz.a ]] || need /usr/$triple/lib/libz.a libz-mingw-w64-dev

stamps=$prefix/stamps
mkdir -p "$stamps" "$prefix/src" "$prefix/build"
done_step() { [[ -f $stamps/$1 ]]; }
mark() { date -u +%FT%TZ >"$stamps/$1"; }

cmake_build() {  # cmake_build NAME SOURCE_DIR [CMAKE ARGS...]: configure, build, install into $prefix
  local name=$1 source=$2
  shift 2
  local t0=$SECONDS
  rm -rf "$prefix/build/$name"
  cmake -S "$source" -B "$prefix/build/$name" -G Ninja -Wno-dev \
    -DCMAKE_TOOLCHAIN_FILE="$toolchain" -DVSGL_WINDOWS_DEPS="$prefix" \
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$prefix" -DBUILD_SHARED_LIBS=OFF \
    -DBUILD_TESTING=OFF "$@" >"$prefix/build/$name.configure.log" ||
    { cat "$prefix/build/$name.configure.log" >&2; echo "ci/windows-deps.sh: configuring $name failed" >&2; exit 1; }
  cmake --build "$prefix/build/$name" -j "$jobs" >"$prefix/build/$name.build.log" ||
    { tail -50 "$prefix/build/$name.build.log" >&2; echo "ci/windows-deps.sh: building $name failed" >&2; exit 1; }
  cmake --install "$prefix/build/$name" >/dev/null
  echo "ci/windows-deps.sh: $name built in $((SECONDS - t0)) s"
}

debian_source() {  # debian_source PACKAGE: prints the unpacked source directory (Debian's patches applied)
  local package=$1 dir
  dir=$(find "$prefix/src" -mindepth 1 -maxdepth 1 -type d -name "$package-*" | head -1)
  if [[ -z $dir ]]; then
    (cd "$prefix/src" && apt-get source -qq "$package" >"$prefix/src/$package.log" 2>&1) || {
      cat "$prefix/src/$package.log" >&2
      echo "ci/windows-deps.sh: apt-get source $package failed; the deb-src line for Debian's main" >&2
      echo "  archive is missing (run: bash ci/install-deps.sh) or the archive cannot be reached." >&2
      exit 1
    }
    dir=$(find "$prefix/src" -mindepth 1 -maxdepth 1 -type d -name "$package-*" | head -1)
  fi
  echo "$dir"
}

# Headers: symlinks to exactly the Debian headers the build uses.
if ! done_step headers; then
  mkdir -p "$prefix/include"
  for h in nlohmann glm CLI stb vulkan vk_video tiny_gltf.h tiny_obj_loader.h; do
    [[ -e /usr/include/$h ]] || { echo "ci/windows-deps.sh: /usr/include/$h is missing; run: bash ci/install-deps.sh" >&2; exit 1; }
    ln -sfn "/usr/include/$h" "$prefix/include/$h"
  done
  mark headers
fi

# The Vulkan loader's import library, from the exports of Wine's vulkan-1.dll.
if ! done_step vulkan; then
  dll=$(find /usr/lib/x86_64-linux-gnu/wine /usr/lib/wine /usr/lib64/wine -path '*x86_64-windows*' \
    -name vulkan-1.dll 2>/dev/null | head -1 || true)
  [[ -n $dll ]] || { echo "ci/windows-deps.sh: Wine's 64-bit vulkan-1.dll is missing (Debian package wine64); run: bash ci/install-deps.sh" >&2; exit 1; }
  mkdir -p "$prefix/lib" "$prefix/build/vulkan"
  (cd "$prefix/build/vulkan" && gendef - "$dll" >vulkan-1.def 2>/dev/null)
  grep -q vkCreateInstance "$prefix/build/vulkan/vulkan-1.def" ||
    { echo "ci/windows-deps.sh: gendef found no vkCreateInstance in $dll" >&2; exit 1; }
  $triple-dlltool -d "$prefix/build/vulkan/vulkan-1.def" -D vulkan-1.dll -l "$prefix/lib/libvulkan-1.a"
  mark vulkan
fi

if ! done_step header-libraries; then
  cmake_build header-libraries "$src/cmake/windows-deps"
  mark header-libraries
fi

if ! done_step googletest; then
  cmake_build googletest /usr/src/googletest -DBUILD_GMOCK=OFF -DINSTALL_GTEST=ON
  mark googletest
fi

if ! done_step benchmark; then
  # GIT_VERSION: Debian's patch reads no git tags; its rules pass the upstream version.
  source=$(debian_source benchmark)
  cmake_build benchmark "$source" -DGIT_VERSION="${source##*/benchmark-}" -DBENCHMARK_ENABLE_TESTING=OFF \
    -DBENCHMARK_ENABLE_GTEST_TESTS=OFF -DBENCHMARK_ENABLE_WERROR=OFF -DBENCHMARK_ENABLE_LTO=OFF \
    -DBENCHMARK_INSTALL_DOCS=OFF
  mark benchmark
fi

if ! done_step imath; then
  cmake_build imath "$(debian_source imath)" -DIMATH_INSTALL_PKG_CONFIG=OFF -DPYTHON=OFF -DDOCS=OFF
  mark imath
fi

if ! done_step openexr; then
  cmake_build openexr "$(debian_source openexr)" -DOPENEXR_BUILD_TOOLS=OFF -DOPENEXR_INSTALL_TOOLS=OFF \
    -DOPENEXR_INSTALL_EXAMPLES=OFF -DOPENEXR_INSTALL_PKG_CONFIG=OFF -DDOCS=OFF
  mark openexr
fi
# The licences of everything linked into the programs, for the zip (cmake/WindowsZip.cmake):
# Debian's copyright file of each package.
if ! done_step licences; then
  mkdir -p "$prefix/licences"
  for p in nlohmann-json3-dev libglm-dev libcli11-dev libstb-dev libtinygltf-dev libtinyobjloader-dev \
    libz-mingw-w64-dev mingw-w64-common gcc-mingw-w64-base; do
    [[ -f /usr/share/doc/$p/copyright ]] || { echo "ci/windows-deps.sh: /usr/share/doc/$p/copyright is missing" >&2; exit 1; }
    cp "/usr/share/doc/$p/copyright" "$prefix/licences/$p.txt"
  done
  for p in benchmark imath openexr; do cp "$(debian_source $p)/debian/copyright" "$prefix/licences/$p.txt"; done
  mark licences
fi
echo "ci/windows-deps.sh: the Windows libraries are in $prefix"
