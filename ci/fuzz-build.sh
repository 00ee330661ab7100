#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz) with clang into build/fuzz, apart from the g++ build.
# Exit 0: built. Exit 77: no clang with libFuzzer on this machine (nothing built; says why).
# Usage: bash ci/fuzz-build.sh          (CLANGXX=clang++-15 to pick another clang)
#        bash ci/fuzz-build.sh --check  (only whether clang can build them: 0 or 77; builds nothing)
set -euo pipefail
cd "$(dirname "$0")/.."
check_only=0
if [[ "${1:-}" == --check ]]; then check_only=1; elif [[ $# -gt 0 ]]; then
  echo "ci/fuzz-build.sh: unknown argument '$1' (usage: bash ci/fuzz-build.sh [--check])" >&2; exit 2
fi
clangxx=${CLANGXX:-}
if [[ -z "$clangxx" ]]; then
  for c in clang++ clang++-16 clang++-15 clang++-14; do
    if command -v "$c" >/dev/null 2>&1; then clangxx=$(command -v "$c"); break; fi
  done
fi
if [[ -z "$clangxx" ]]; then
  echo "ci/fuzz-build.sh: SKIPPED: no clang++ on PATH; the fuzz targets need clang with libFuzzer (Debian: apt-get install clang)" >&2
  exit 77
fi
# clang without its libFuzzer runtime (Debian splits it into libclang-rt-*-dev on newer releases).
probe=$(mktemp -d)
trap 'rm -rf "$probe"' EXIT
printf '#include <cstdint>\n#include <cstddef>\nextern "C" int LLVMFuzzerTestOneInput(const uint8_t*, size_t) { return 0; }\n' > "$probe/p.cpp"
if ! "$clangxx" -fsanitize=fuzzer,address,undefined "$probe/p.cpp" -o "$probe/p" 2>"$probe/err"; then
  echo "ci/fuzz-build.sh: SKIPPED: $clangxx cannot link a libFuzzer target with ASan/UBSan:" >&2
  sed 's/^/  /' "$probe/err" | head -5 >&2
  exit 77
fi
[[ $check_only -eq 1 ]] && exit 0
# One build at a time (the suite's fuzz_smoke and a long ci/fuzz.sh may start together).
mkdir -p build
exec 9>build/fuzz-build.lock
flock 9
# Configured once; after that ninja regenerates the build itself when tests/fuzz/CMakeLists.txt
# changes, so an up-to-date build costs a second.
if [[ ! -f build/fuzz/build.ninja ]]; then
  cmake -S tests/fuzz -B build/fuzz -G Ninja -DCMAKE_CXX_COMPILER="$clangxx" >/dev/null
fi
cmake --build build/fuzz
