#!/usr/bin/env bash
# Installs the Debian packages vsgl-bench needs, only those that are missing. Idempotent.
# Usage: bash ci/install-deps.sh                (as root, or as a user with sudo)
#        bash ci/install-deps.sh --no-windows   without the Windows cross build's tools and Wine
#                                               (windows-cross preset, ci/windows-test.sh, which
#                                               ci/test.sh then skips, saying so)
# (--windows, the default, is still taken.)
set -euo pipefail
windows=true
for arg in "$@"; do
  case "$arg" in
    --windows) windows=true ;;
    --no-windows) windows=false ;;
    *) echo "ci/install-deps.sh: unknown option '$arg' (--no-windows)" >&2; exit 2 ;;
  esac
done

packages=(
  cmake ninja-build g++ pkg-config        # build
  libvulkan-dev glslang-tools             # Vulkan loader + headers, GLSL -> SPIR-V compiler
  mesa-vulkan-drivers                     # lavapipe: the CPU Vulkan device (works without a GPU)
  vulkan-validationlayers                 # Khronos validation layer (tests, --validate)
  libbenchmark-dev libgtest-dev           # Google Benchmark, GoogleTest
  nlohmann-json3-dev libglm-dev           # JSON, vector maths
  libcli11-dev                            # command-line parsing (bench/cli/)
  libopenexr-dev                          # EXR captures
  libstb-dev                              # PNG output of the shading pass
  clang                                   # libFuzzer targets (tests/fuzz; the suite's fuzz smoke test)
  libtinygltf-dev                         # glTF 2.0 import (record --gltf)
  libtinyobjloader-dev                    # Wavefront OBJ + MTL import
  assimp-testmodels                       # sample glTF and OBJ files the tests import
  python3-jsonschema                      # second validator of the committed results (tests/validate_results.py)
  clang-format                            # ci/check-format.sh: the changed lines follow .clang-format
  help2man                                # the manual pages, made from each program's --help at build time
  dpkg-dev                                # dpkg-shlibdeps: the .deb's dependencies (cpack, the package_deb test)
  lintian                                 # ci/release.sh checks the .deb
  debootstrap                             # ci/package-trial.sh: a minimal Debian to install the .deb on
)
if $windows; then
  packages+=(
    # The Windows build (windows-cross preset, ci/windows-deps.sh) and its run under Wine (ci/windows-test.sh)
    g++-mingw-w64-x86-64-posix mingw-w64-tools libz-mingw-w64-dev  # cross compiler, gendef, zlib
    # (dpkg-dev, above, also unpacks the OpenEXR, Imath and Benchmark sources apt-get source fetches)
    wine wine64 xvfb xauth                # Wine runs the .exe files; its Vulkan needs an X display
  )
fi

# Headless Chromium renders results/dashboard in the dashboard test. Debian's `chromium` is a real
# browser; Ubuntu's `chromium` / `chromium-browser` are transitional packages that install a snap,
# which does not run in containers, so there nothing is installed for it: ci/find-chromium.sh
# looks for one that runs (or $VSGL_CHROMIUM), and without one the dashboard test is skipped
# and says why.
os_id=unknown os_name="this system"
if [[ -r /etc/os-release ]]; then
  os_id=$(. /etc/os-release && echo "${ID:-unknown}")
  os_name=$(. /etc/os-release && echo "${PRETTY_NAME:-$os_id}")
fi
if [[ "$os_id" == "debian" ]]; then
  packages+=(chromium)
elif ! bash "$(dirname "$0")/find-chromium.sh" >/dev/null 2>&1; then
  echo "ci/install-deps.sh: no headless Chromium on $os_name, and none is installed for it (on Ubuntu the" >&2
  echo "  chromium package is a snap, which fails in containers): the dashboard test will be skipped." >&2
  echo "  For it, install Google Chrome or chrome-headless-shell and set VSGL_CHROMIUM=/path/to/it." >&2
fi

if ! command -v dpkg-query >/dev/null 2>&1 || ! command -v apt-get >/dev/null 2>&1; then
  echo "ci/install-deps.sh: this is not a Debian-family system (no dpkg/apt-get)." >&2
  echo "Install the equivalents of: ${packages[*]}" >&2
  exit 1
fi

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done
# ci/windows-deps.sh builds OpenEXR, Imath and Google Benchmark for Windows from Debian's source
# packages, which `apt-get source` fetches only with a deb-src source for Debian's main archive.
# It is added for the mirror this machine's apt already uses (ci/debian-mirror.sh), never another.
deb_src_file=/etc/apt/sources.list.d/vsgl-deb-src.sources
need_deb_src=false
if $windows && [[ "$os_id" == "debian" ]] &&
   ! grep -rqsE '^[[:space:]]*(Types:.*deb-src|deb-src )' /etc/apt/sources.list /etc/apt/sources.list.d/; then
  need_deb_src=true
  mirror=$(bash "$(dirname "$0")/debian-mirror.sh") || {
    echo "ci/install-deps.sh: the Windows build needs Debian's source packages (a deb-src source), and" >&2
    echo "  this machine's apt sources name no Debian archive to take them from (see above). Add a deb-src" >&2
    echo "  source for your mirror by hand, or run with --no-windows." >&2
    exit 1
  }
  keyring=$(bash "$(dirname "$0")/debian-mirror.sh" --signed-by)
  [[ -n $keyring ]] || keyring=/usr/share/keyrings/debian-archive-keyring.gpg
fi
if [[ ${#missing[@]} -eq 0 && $need_deb_src == false ]]; then
  echo "ci/install-deps.sh: all ${#packages[@]} packages are installed."
  exit 0
fi

[[ ${#missing[@]} -eq 0 ]] || echo "ci/install-deps.sh: installing ${missing[*]}"
if [[ $(id -u) -eq 0 ]]; then
  sudo=()
elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
  sudo=(sudo -n)
else
  echo "ci/install-deps.sh: need root to install packages, and sudo is not available without a password." >&2
  echo "Run as root:  apt-get update && apt-get install -y ${missing[*]}" >&2
  exit 1
fi
if [[ $need_deb_src == true ]]; then
  codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-bookworm}")
  echo "ci/install-deps.sh: adding $deb_src_file (Debian's source packages from $mirror, for ci/windows-deps.sh)"
  printf 'Types: deb-src\nURIs: %s\nSuites: %s\nComponents: main\nSigned-By: %s\n' \
    "$mirror" "$codename" "$keyring" | "${sudo[@]}" tee "$deb_src_file" >/dev/null
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
[[ ${#missing[@]} -eq 0 ]] || "${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
