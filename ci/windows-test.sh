#!/usr/bin/env bash
# The Windows check (DESIGN.md §13.1; not yet part of ci/test.sh): cross-builds the windows-cross preset and runs
# the .exe files under Wine on the host's lavapipe (Wine's vulkan-1.dll forwards to the host's
# Vulkan). Wine's Vulkan needs an X display, so everything runs under xvfb-run, with one
# persistent wineserver (else each process pays Wine's start-up again).
#   1. the programs need no DLL but Windows' own and vulkan-1.dll;
#   2. an end-to-end run of vsgl-bench.exe in a folder with a non-ASCII name: devices (lists
#      llvmpipe), record --scene tiny, verify, tables --quick, dashboard;
#   3. the tiny capture hashes alike from the Windows and the Linux program (where one is built).
# Without mingw-w64, Wine or Xvfb it is skipped, and says so (exit 0).
set -euo pipefail
cd "$(dirname "$0")/.."
skip() {
  echo "ci/windows-test.sh: the Windows step is skipped: $*"
  exit 0
}

if [[ ${1:-} != --under-x ]]; then
  command -v x86_64-w64-mingw32-g++-posix >/dev/null 2>&1 || skip "no mingw-w64 (g++-mingw-w64-x86-64-posix)"
  command -v wine >/dev/null 2>&1 || skip "no Wine (wine, wine64)"
  command -v xvfb-run >/dev/null 2>&1 || skip "no xvfb-run (xvfb)"
  start=$SECONDS
  cmake --preset windows-cross
  cmake --build --preset windows-cross
  echo "ci/windows-test.sh: Windows build $((SECONDS - start)) s"
  exec xvfb-run -a bash "$0" --under-x
fi

bin=build/windows-cross/bench
export WINEPREFIX=$PWD/build/windows-cross/wine WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml="
fail() {
  echo "ci/windows-test.sh: FAILED: $*" >&2
  exit 1
}

# 1. Only Windows' DLLs and the Vulkan loader: everything else is linked statically.
for exe in "$bin"/vsgl-bench.exe "$bin"/vsgl-gbench.exe "$bin"/vsgl-mipbench.exe; do
  [[ -f $exe ]] || fail "$exe was not built"
  others=$(x86_64-w64-mingw32-objdump -p "$exe" | sed -n 's/^\s*DLL Name: //p' | tr 'A-Z' 'a-z' |
    grep -vxE 'kernel32.dll|msvcrt.dll|user32.dll|advapi32.dll|shell32.dll|shlwapi.dll|ws2_32.dll|vulkan-1.dll' || true)
  [[ -z $others ]] || fail "$exe needs DLLs beyond Windows' own and vulkan-1.dll: $others"
done

t0=$SECONDS
# A fresh prefix (about 11 s); wineboot's status is not reliable, the prefix's registry is.
[[ -f $WINEPREFIX/system.reg ]] || wineboot -i </dev/null >/dev/null 2>&1 || true
[[ -f $WINEPREFIX/system.reg ]] || fail "wineboot could not create the Wine prefix $WINEPREFIX"
wineserver -p  # persistent until killed below: later processes start in a fraction of a second
trap 'wineserver -k >/dev/null 2>&1 || true' EXIT
# Wine's background services start with the first program and inherit its output: started here,
# they hold /dev/null, not the pipe of a captured run (which would then never see its end).
wineboot </dev/null >/dev/null 2>&1 || true
echo "ci/windows-test.sh: Wine ready in $((SECONDS - t0)) s"

run() {  # run ARGS...: vsgl-bench.exe under Wine; its output is shown and kept in $out
  echo "+ vsgl-bench.exe $*"
  local rc=0
  out=$(wine "$bin/vsgl-bench.exe" "$@" 2>&1) || rc=$?
  printf '%s\n' "$out"
  [[ $rc -eq 0 ]] || fail "vsgl-bench.exe $* exited $rc"
}

# 2. End to end, in a folder whose name needs more than one code page (UTF-16 names on Windows).
t0=$SECONDS
work=build/windows-cross/e2e/données-Φγ
rm -rf build/windows-cross/e2e
mkdir -p "$work"
run devices
grep -q llvmpipe <<<"$out" || fail "devices lists no llvmpipe"
run record --scene tiny --out "$work/capture-µ"
run verify --capture "$work/capture-µ"
# 3. The same capture on both hosts (DESIGN.md §13.1): every channel hash of the Windows program's
#    tiny capture equals the Linux program's, when a Linux build is here to record it.
linux_bin=""
for b in build/ci/bench/vsgl-bench build/release/bench/vsgl-bench; do [[ -x $b ]] && { linux_bin=$b; break; }; done
if [[ -n $linux_bin ]]; then
  "$linux_bin" record --scene tiny --out build/windows-cross/e2e/linux-tiny >/dev/null
  python3 - "$work/capture-µ/capture.json" build/windows-cross/e2e/linux-tiny/capture.json <<'PY' || fail "the Windows and Linux captures of tiny differ"
import json, sys
w, l = (json.load(open(p, encoding="utf-8")) for p in sys.argv[1:3])
differ = [f"{v}.{c}" for v in ("gbuffer", "rsm") for c in l[v]["channels"] if w[v]["channels"].get(c) != l[v]["channels"][c]]
print(f"ci/windows-test.sh: {len(differ)} channel hashes differ between the Windows and Linux captures of tiny", *differ)
sys.exit(1 if differ else 0)
PY
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
