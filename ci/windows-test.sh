#!/usr/bin/env bash
# The Windows check (DESIGN.md §13.1; ci/test.sh runs it after the Linux tests): cross-builds the
# windows-cross preset and runs the .exe files under Wine on the host's lavapipe (Wine's
# vulkan-1.dll forwards to the host's Vulkan). Wine's Vulkan needs an X display, so everything
# runs under xvfb-run, with one persistent wineserver (else each process pays Wine's start-up again).
#   1. the programs need no DLL but Windows' own and vulkan-1.dll;
#   2. the test suite vsgl_tests.exe: the CPU tests, then the device tests on lavapipe (without
#      the validation layer, which Wine's vulkan-1.dll cannot load: VSGL_TEST_VALIDATION=off);
#   3. an end-to-end run of vsgl-bench.exe in a folder with a non-ASCII name: devices (lists
#      llvmpipe), record --scene tiny, verify, tables --quick, dashboard;
#   4. the tiny capture hashes alike from the Windows and the Linux program, and each program
#      verifies the other's capture (where a Linux build is here).
# Without mingw-w64, Wine or Xvfb it is skipped, and says so (exit 0).
# Usage: bash ci/windows-test.sh [--no-device-tests]   (the CPU tests and the end-to-end run only)
set -euo pipefail
cd "$(dirname "$0")/.."
skip() {
  echo "ci/windows-test.sh: the Windows step is skipped: $*"
  exit 0
}

device_tests=true
for arg in "$@"; do
  case "$arg" in
    --under-x) ;;
    --no-device-tests) device_tests=false ;;
    *) echo "ci/windows-test.sh: unknown option '$arg' (--no-device-tests)" >&2; exit 2 ;;
  esac
done

if [[ ${1:-} != --under-x ]]; then
  command -v x86_64-w64-mingw32-g++-posix >/dev/null 2>&1 || skip "no mingw-w64 (g++-mingw-w64-x86-64-posix)"
  command -v wine >/dev/null 2>&1 || skip "no Wine (wine, wine64)"
  command -v xvfb-run >/dev/null 2>&1 || skip "no xvfb-run (xvfb)"
  start=$SECONDS
  cmake --preset windows-cross
  cmake --build --preset windows-cross
  echo "ci/windows-test.sh: Windows build $((SECONDS - start)) s"
  args=(--under-x)
  $device_tests || args+=(--no-device-tests)
  exec xvfb-run -a bash "$0" "${args[@]}"
fi

bin=build/windows-cross/bench
export WINEPREFIX=$PWD/build/windows-cross/wine WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml="
fail() {
  echo "ci/windows-test.sh: FAILED: $*" >&2
  exit 1
}

# 1. Only Windows' DLLs and the Vulkan loader: everything else is linked statically.
for exe in "$bin"/vsgl-bench.exe "$bin"/vsgl-gbench.exe "$bin"/vsgl-mipbench.exe build/windows-cross/tests/vsgl_tests.exe; do
  [[ -f $exe ]] || fail "$exe was not built"
  others=$(x86_64-w64-mingw32-objdump -p "$exe" | sed -n 's/^\s*DLL Name: //p' | tr 'A-Z' 'a-z' |
    grep -vxE 'kernel32.dll|msvcrt.dll|user32.dll|advapi32.dll|shell32.dll|shlwapi.dll|ws2_32.dll|vulkan-1.dll' || true)
  [[ -z $others ]] || fail "$exe needs DLLs beyond Windows' own and vulkan-1.dll: $others"
done

t0=$SECONDS
# A fresh prefix takes about 11 s, much longer on a loaded machine. wineboot's status is not
# reliable, the prefix's registry is; the registry is written when the wineserver ends, hence
# `wineserver -w` before looking. A try that fails is retried from an empty prefix.
for attempt in 1 2 3; do
  [[ -f $WINEPREFIX/system.reg ]] && break
  wineserver -k >/dev/null 2>&1 || true
  rm -rf "$WINEPREFIX"
  timeout 300 wineboot -i </dev/null >/dev/null 2>&1 || true
  timeout 120 wineserver -w >/dev/null 2>&1 || true
  [[ -f $WINEPREFIX/system.reg ]] || echo "ci/windows-test.sh: wineboot try $attempt made no Wine prefix in $WINEPREFIX"
done
[[ -f $WINEPREFIX/system.reg ]] || fail "wineboot could not create the Wine prefix $WINEPREFIX (3 tries)"
wineserver -p  # persistent until killed below: later processes start in a fraction of a second
trap 'wineserver -k >/dev/null 2>&1 || true' EXIT
# Wine's background services start with the first program and inherit its output: started here,
# they hold /dev/null, not the pipe of a captured run (which would then never see its end).
wineboot </dev/null >/dev/null 2>&1 || true
echo "ci/windows-test.sh: Wine ready in $((SECONDS - t0)) s"
# The paper's scenes for the tests that want them: the build's VSGL_TEST_ASSETS (tests/CMakeLists.txt;
# ctest passes it as VSGL_ASSETS in the Linux build), each directory as Wine names it (Z:\...),
# joined by ';' as VSGL_ASSETS is on Windows. Without them those tests skip, saying so.
IFS=: read -r -a dirs <<<"$(sed -n 's/^VSGL_TEST_ASSETS:[A-Z]*=//p' build/windows-cross/CMakeCache.txt)"
asset_dirs=()
for d in "${dirs[@]}"; do
  if [[ -d $d ]]; then asset_dirs+=("$(winepath -w "$d" 2>/dev/null)"); fi
done
test_assets=$(IFS=';'; echo "${asset_dirs[*]}")
echo "ci/windows-test.sh: the paper's scenes for the tests: ${test_assets:-none (VSGL_TEST_ASSETS names no directory here)}"

# 2. The test suite. Its suites that need a device are named as tests/CMakeLists.txt labels them
#    `gpu`; the rest run without Vulkan. Wine's vulkan-1.dll loads no layer: no validation.
gpu_suites='*Test.*:*Cli.*:DeviceProbe.*:ValidationLayer.*'
# The tests that cannot hold under Wine or on a Windows file system, each with why.
not_here=(
  # VK_ICD_FILENAMES does not reach the host's loader behind Wine's vulkan-1.dll: the device is
  # still there, so the driver-less controls cannot be made (the last one's test build would run
  # a whole table instead of stopping at "no driver").
  CliUsage.ControlWithoutADriverAnyCommandReachingTheDeviceExitsFour CliUsage.DocumentedOptionsAreAccepted
  CliUsage.DebugSlowIsAnOptionOfTheTestBuildOnly
  # Two file names that differ only in case, and a control character in a file name: Windows'
  # file systems refuse both.
  ObjImport.ModelImportChoosesByExtension ObjImport.BadFilesNameTheFileAndLine
  # The layer check reads the source tree's include lines with POSIX paths: a check of the
  # sources, which the Linux build runs.
  'Layering.*'
)
excluded=$(IFS=:; echo "${not_here[*]}")
shards=$(nproc)
suite() {  # suite NAME FILTER: vsgl_tests.exe on the tests FILTER selects, in $shards processes at once
  local name=$1 filter=$2 t=$SECONDS pids=() rc=0 i
  echo "+ vsgl_tests.exe --gtest_filter='$filter'  ($shards shards; logs: build/windows-cross/vsgl_tests-$name-*.log)"
  for ((i = 0; i < shards; i++)); do
    GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$i VSGL_TEST_VALIDATION=off VSGL_ASSETS=$test_assets \
      wine build/windows-cross/tests/vsgl_tests.exe --gtest_filter="$filter" --gtest_brief=1 \
      </dev/null >"build/windows-cross/vsgl_tests-$name-$i.log" 2>&1 &
    pids+=($!)
  done
  for ((i = 0; i < shards; i++)); do
    wait "${pids[i]}" || { rc=$?; echo "ci/windows-test.sh: shard $i of the $name tests exited $rc"; }
  done
  for ((i = 0; i < shards; i++)); do
    local log=build/windows-cross/vsgl_tests-$name-$i.log
    grep -E '^\[ *(PASSED|FAILED|SKIPPED) *\]' "$log" | sed "s/^/  shard $i: /" || true
    # A child whose Wine start-up died before it ran is started again (tests/child_process.hpp): say so.
    grep -E '^cannot start .*, try [0-9]+ of' "$log" | sed "s/^/  shard $i: note: /" || true
    [[ $rc -eq 0 ]] || tail -30 "$log"
  done
  echo "ci/windows-test.sh: $name tests $((SECONDS - t)) s"
  [[ $rc -eq 0 ]] || fail "vsgl_tests.exe ($name tests) failed"
}
suite cpu "-$gpu_suites:$excluded"
if $device_tests; then
  suite device "$gpu_suites-$excluded"
else
  echo "ci/windows-test.sh: the device tests are not run (--no-device-tests)"
fi

run() {  # run ARGS...: vsgl-bench.exe under Wine; its output is shown and kept in $out
  echo "+ vsgl-bench.exe $*"
  local rc=0
  out=$(wine "$bin/vsgl-bench.exe" "$@" 2>&1) || rc=$?
  printf '%s\n' "$out"
  [[ $rc -eq 0 ]] || fail "vsgl-bench.exe $* exited $rc"
}

# 3. End to end, in a folder whose name needs more than one code page (UTF-16 names on Windows).
t0=$SECONDS
work=build/windows-cross/e2e/données-Φγ
rm -rf build/windows-cross/e2e
mkdir -p "$work"
run devices
grep -q llvmpipe <<<"$out" || fail "devices lists no llvmpipe"
run record --scene tiny --out "$work/capture-µ"
run verify --capture "$work/capture-µ"
# 4. The same capture on both hosts (DESIGN.md §13.1): every channel hash of the Windows program's
#    tiny capture equals the Linux program's, when a Linux build is here to record it, and each
#    program verifies the other's capture.
linux_bin=""
for b in build/ci/bench/vsgl-bench build/release/bench/vsgl-bench; do [[ -x $b ]] && { linux_bin=$b; break; }; done
if [[ -n $linux_bin ]]; then
  linux_capture=build/windows-cross/e2e/linux-tiny
  "$linux_bin" record --scene tiny --out "$linux_capture" >/dev/null
  python3 - "$work/capture-µ/capture.json" "$linux_capture/capture.json" <<'PY' || fail "the Windows and Linux captures of tiny differ"
import json, sys
w, l = (json.load(open(p, encoding="utf-8")) for p in sys.argv[1:3])
differ = []
for v in ("gbuffer", "rsm"):
    for c in l[v]["channels"]:
        same = w[v]["channels"].get(c) == l[v]["channels"][c]
        print(f"  {v}.{c}: {l[v]['channels'][c]} {'same' if same else 'differs: Windows ' + str(w[v]['channels'].get(c))}")
        if not same:
            differ.append(f"{v}.{c}")
print(f"ci/windows-test.sh: {len(differ)} channel hashes differ between the Windows and Linux captures of tiny", *differ)
sys.exit(1 if differ else 0)
PY
  run verify --capture "$linux_capture"
  echo "+ $linux_bin verify --capture $work/capture-µ"
  "$linux_bin" verify --capture "$work/capture-µ" || fail "the Linux program does not verify the Windows capture"
else
  echo "ci/windows-test.sh: no Linux build (build/ci or build/release): the Windows and Linux captures are not compared"
fi
run tables --quick --capture "$work/capture-µ" --out "$work/results"
ls "$work/results"/*.json >/dev/null 2>&1 || fail "tables wrote no JSON into $work/results"
run dashboard results/lavapipe --out "$work/dashboard"  # the committed tables (tableN.json)
[[ -s $work/dashboard/index.html ]] || fail "dashboard wrote no $work/dashboard/index.html"
# A second run replaces the existing results atomically (MoveFileExW over the old files).
run tables --quick --capture "$work/capture-µ" --out "$work/results"
echo "ci/windows-test.sh: end-to-end run $((SECONDS - t0)) s"
echo "ci/windows-test.sh: passed"
