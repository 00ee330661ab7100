#!/usr/bin/env bash
# The programs run wherever they are copied (DESIGN.md §10): nothing is read from the checkout
# or the build directory at run time. vsgl-bench, vsgl-gbench and vsgl-mipbench are copied into a
# temporary directory and run in a mount namespace where an empty tmpfs hides both the build
# directory and the checkout, so any read of either fails: record (the tiny scene; sponza when its
# model is on VSGL_ASSETS), verify, tables --quick, sweep --quick, dashboard, vsgl-gbench on a
# capture, and --version. The binaries must not even name the checkout or the build directory.
# Exit 77 (skipped, saying why) where mount namespaces are not allowed.
# Usage: relocation.sh VSGL_BENCH VSGL_GBENCH|- VSGL_MIPBENCH|- SOURCE_DIR BUILD_DIR
set -euo pipefail
if [[ ${1:-} == --inside ]]; then
  shift
  tmp=$1 src=$2 build=$3
  cd "$tmp"
  # The build directory first: it may lie inside the checkout, which the second mount hides.
  mount -t tmpfs relocation "$build"
  mount -t tmpfs relocation "$src"
  if [[ -e $src/CMakeLists.txt || -e $build/CMakeCache.txt ]]; then
    echo "relocation.sh: the checkout is still visible; the test would prove nothing" >&2
    exit 1
  fi
  run() {  # run NAME COMMAND...: runs it, failing the test with its output when it fails
    local name=$1
    shift
    echo "== $name: $*"
    local rc=0
    "$@" >"log/$name.txt" 2>&1 || rc=$?
    if [[ $rc != 0 ]]; then
      echo "relocation.sh: '$name' failed (exit $rc) with the checkout out of reach:" >&2
      cat "log/$name.txt" >&2
      exit 1
    fi
  }
  mkdir -p log
  run version bin/vsgl-bench --version
  grep -q '^commit ' log/version.txt && grep -q '^compiler ' log/version.txt || {
    echo "relocation.sh: --version names no commit or compiler:" >&2
    cat log/version.txt >&2
    exit 1
  }
  run record_tiny bin/vsgl-bench record --scene tiny --gbuffer 96x64 --rsm 64 --out caps/tiny
  if VSGL_ASSETS= bin/vsgl-bench record --scene sponza --out caps/none >log/sponza_probe.txt 2>&1; then
    echo "relocation.sh: sponza was found without --assets or VSGL_ASSETS" >&2
    exit 1
  fi
  assets=${VSGL_ASSETS:-}
  assets=${assets%%:*}
  VSGL_ASSETS= bin/vsgl-bench record --scene sponza --assets "${assets:-/nonexistent}" --gbuffer 96x64 --rsm 64 \
    --out caps/sponza >log/record_sponza.txt 2>&1 && sponza=1 || sponza=0
  if [[ $sponza == 0 ]]; then
    if grep -q 'model was not found' log/record_sponza.txt; then
      echo "SKIPPED record --scene sponza --assets: the paper scene's model is not on VSGL_ASSETS ('${assets}')"
    else
      echo "relocation.sh: record --scene sponza --assets failed:" >&2
      cat log/record_sponza.txt >&2
      exit 1
    fi
  fi
  run verify bin/vsgl-bench verify --capture caps/tiny
  run tables bin/vsgl-bench tables --capture caps/tiny --quick --no-progress --generators fis_tok15,fis_modified \
    --out out/tables
  grep -q '"lines_of_code"' out/tables/tiny.json || { echo "relocation.sh: no Table 3 lines in the table" >&2; exit 1; }
  run sweep bin/vsgl-bench sweep --capture caps/tiny --axis vsgls=8,16 --generators fis_modified --quick \
    --no-progress --time-budget 10 --out out/sweep
  run dashboard bin/vsgl-bench dashboard out --out site
  [[ -s site/index.html ]] || { echo "relocation.sh: the dashboard wrote no page" >&2; exit 1; }
  if [[ -x bin/vsgl-gbench ]]; then
    run gbench bin/vsgl-gbench --vsgl_capture=caps/tiny --vsgl_generators=fis_modified --vsgl_replays=2 \
      --benchmark_format=json --benchmark_out=out/gbench.json
    grep -q '"vsgl_git_commit"' out/gbench.json || { echo "relocation.sh: gbench names no commit" >&2; exit 1; }
  fi
  [[ ! -x bin/vsgl-mipbench ]] || run mipbench_help bin/vsgl-mipbench --help
  echo "relocation.sh: every program ran with the checkout out of reach$([[ $sponza == 1 ]] && echo ', sponza included')"
  exit 0
fi

bench=$1 gbench=$2 mipbench=$3 src=$(realpath "$4") build=$(realpath "$5")
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vsgl-relocation.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
case "$tmp/" in "$src/"* | "$build/"*)
  echo "relocation.sh: SKIPPED: the temporary directory $tmp is inside the checkout or the build"
  exit 77 ;;
esac
mkdir -p "$tmp/bin"
for program in "$bench" "$gbench" "$mipbench"; do
  [[ $program == - ]] || cp "$program" "$tmp/bin/"
done
# The binaries hold no path of the build directory or of the checkout's data (no compiled-in
# place to read from). Source file names in VK_CHECK's messages (__FILE__) are only printed, and
# debug information (a debug build's compilation directory is the build's) is never read by the
# program, so its sections are left out of the check; everything the program can read stays in.
for program in "$tmp"/bin/*; do
  if command -v strings >/dev/null; then
    text=$program
    if command -v objcopy >/dev/null; then
      objcopy --strip-debug "$program" "$tmp/checked" && text=$tmp/checked
    fi
    # Source file names (a sanitizer's or an assertion's __FILE__, unity sources in the build) are
    # only printed, like VK_CHECK's: left out. The matches are collected whole before they are
    # judged, so no pipe closed early can hide one.
    strings -a "$text" | grep -v -E '\.(c|cc|cpp|cxx|h|hpp)$' >"$tmp/strings.txt" || true
    found=$({
      grep -x -F "$src" "$tmp/strings.txt"
      grep -F -e "$build" -e "$src/results" -e "$src/harness/scene/presets" -e "$src/kernels" "$tmp/strings.txt"
    } || true)
    if [[ -n $found ]]; then
      head -3 <<<"$found"
      echo "relocation.sh: $(basename "$program") holds a path of the checkout or the build (above)" >&2
      exit 1
    fi
  else
    echo "relocation.sh: strings (binutils) is not installed; the binaries' text is not checked"
  fi
done
unshare_with=()
if unshare --mount true 2>/dev/null; then
  unshare_with=(unshare --mount)
elif unshare --mount --map-root-user true 2>/dev/null; then
  unshare_with=(unshare --mount --map-root-user)
else
  echo "relocation.sh: SKIPPED: mount namespaces are not allowed here (unshare --mount failed), so the checkout cannot be hidden"
  exit 77
fi
"${unshare_with[@]}" bash "$0" --inside "$tmp" "$src" "$build"
