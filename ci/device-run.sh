#!/usr/bin/env bash
# The whole run on a GPU machine, from a pack made here by ci/device-pack.sh, in one command
# and inside a wall-time budget. Steps run most valuable first, so a run cut short still brings
# back what matters most:
#   1 devices (--json) and nvidia-smi     5 tables with --pyramid buffer
#                                          5b frame: the paper's frame phase by phase, each scene
#   2 record sponza and conference-room    6 vsgl-mipbench (the three mipmapping strategies)
#   3 verify both captures: both pyramid   7 vsgl-gbench
#     paths, every generator               7b a short sweep: N x PDF sharpness (--time-budget)
#   4 tables (texture path, the default)   8 the GPU test suites under the validation layer
#                                          9 quality per scene against a reference capture
#                                            with a 4096^2 RSM (--reference-rsm)
# The paper's scenes come from the pack's scenes.tar.xz (ci/device-pack.sh); a pack without them
# records the procedural stand-ins atrium and conference instead, and run.log says so. run.log
# lists the model files carried (size, SHA-256).
#
# The run explains itself (run.log): the loader and the ICD it was given (VK_DRIVER_FILES, every
# icd.d folder, the Vulkan and NVIDIA libraries found); when `devices` finds no usable device, or
# only a CPU one beside nvidia-smi, it searches the usual places for NVIDIA's ICD, retries with what
# it found, and otherwise reruns `devices` with VK_LOADER_DEBUG=all into loader_debug.txt and stops
# there rather than spend the budget on steps that cannot work. Every external command runs under
# `timeout`; tables and the sweep get a --time-cap / --time-budget that fits their step's limit; a
# step that would start with less than its minimum left is skipped; a failed step's last lines are
# copied into run.log. The results are packed after every step (OUT/results.tar.gz, or .tar.xz when
# gzip is missing or fails, else a plain .tar), so even a run killed outright brings back every
# step that finished; run.log, and build.env with the commit the pack was built from, are in it.
#
# The tests (step 8): only the GPU suites (the `gpu` label's filter of tests/CMakeLists.txt; the
# CPU ones are CI's), one process and one gtest JSON per suite (tests/SUITE.json, SUITE.txt), so a
# crash loses only that suite; GpuAssistedValidation last, in its own process.
#
# Usage (repository root, pack in .device-pack/):
#   bash ci/device-run.sh OUT [--quick] [--budget SECONDS] [--reference-rsm SIDE]
#   --quick       the rehearsal on lavapipe: 480x272 captures with a 128^2 RSM, tables --quick,
#                 3 replays per benchmark on Table 1 only, vsgl-gbench for the FIS generators,
#                 quality on 4 frames against a 256^2 reference capture at G-buffer stride 8
#   --budget S    wall-time budget of the whole run [540: nine minutes, so that a run given ten
#                 has time left to start and to copy its results back]
#   --reference-rsm SIDE  the reference capture's RSM side for quality (DESIGN.md §11a) [4096]
# Exit: 0 if every step ran and passed, 1 otherwise (run.log names the steps), 2 on bad usage or
# no pack. Bring OUT/results.tar.* back and file it with ci/import-device-results.sh.
set -uo pipefail
cd "$(dirname "$0")/.." || exit 2
out=${1:?usage: bash ci/device-run.sh OUT [--quick] [--budget SECONDS] [--reference-rsm SIDE]}
shift
quick=false
budget=540
reference_rsm=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --quick) quick=true ;;
    --budget) budget=${2:?--budget takes seconds}; shift ;;
    --reference-rsm) reference_rsm=${2:?--reference-rsm takes a side in texels}; shift ;;
    *) echo "ci/device-run.sh: unknown option '$1' (--quick, --budget S, --reference-rsm SIDE)" >&2; exit 2 ;;
  esac
  shift
done
[[ $budget =~ ^[0-9]+$ ]] || { echo "ci/device-run.sh: --budget takes whole seconds, not '$budget'" >&2; exit 2; }
[[ -z $reference_rsm || $reference_rsm =~ ^[1-9][0-9]*$ ]] ||
  { echo "ci/device-run.sh: --reference-rsm takes a side in texels, not '$reference_rsm'" >&2; exit 2; }
start=$SECONDS
pack=$PWD/.device-pack
# The pack travels compressed (ci/device-pack.sh): unpack the tools once.
if [[ -f $pack/tools.tar.xz && ! -x $pack/bin/vsgl-bench ]]; then
  timeout 120 bash -c 'xz -dc "$1" | tar xf - -C "$2"' _ "$pack/tools.tar.xz" "$pack"
fi
[[ -x $pack/bin/vsgl-bench && -f $pack/build.env ]] || { echo "ci/device-run.sh: no pack in $pack: run bash ci/device-pack.sh first (where the build is, not on the GPU machine)" >&2; exit 2; }
mkdir -p "$out"
out=$(cd "$out" && pwd)
run=$(mktemp -d)
captures=$(mktemp -d)
log=$out/run.log
: > "$log"
status=0
say() { echo "$*" | tee -a "$log" >&2; }
cp "$pack/build.env" "$run/build.env"

# bundle: OUT/results.tar.gz (else .tar.xz, else .tar) from everything the steps wrote so far and
# run.log, written beside and renamed, so a kill mid-way leaves the previous bundle whole.
bundle() {
  cp "$log" "$run/run.log" 2>/dev/null
  local kind
  for kind in gz xz tar; do
    local file=$out/results.tar
    [[ $kind == tar ]] || file+=.$kind
    case "$kind" in
      gz) command -v gzip > /dev/null && timeout 60 bash -c 'tar cf - -C "$1" . | gzip -1 > "$2"' _ "$run" "$file.part" ;;
      xz) command -v xz > /dev/null && timeout 60 bash -c 'tar cf - -C "$1" . | xz -1 > "$2"' _ "$run" "$file.part" ;;
      tar) timeout 60 tar cf "$file.part" -C "$run" . ;;
    esac
    if (($? == 0)); then
      mv -f "$file.part" "$file"
      rm -f "$out"/results.tar*.part
      [[ $kind == gz ]] || rm -f "$out/results.tar.gz"
      [[ $kind == xz ]] || rm -f "$out/results.tar.xz"
      [[ $kind == tar ]] || rm -f "$out/results.tar"
      bundled=$file
      return 0
    fi
    rm -f "$file.part"
  done
  echo "ci/device-run.sh: could not pack the results (tar failed)" | tee -a "$log" >&2
  return 1
}
bundled=""
# Whatever happens short of SIGKILL, what was measured comes back (the captures, too big to
# return, do not); a SIGKILL leaves the bundle of the last finished step.
finish() {
  say "== $((SECONDS - start)) s in all"
  bundle && echo "ci/device-run.sh: results in $bundled, log in $log" >&2 && rm -rf "$run"
  rm -rf "$captures"
}
trap finish EXIT
trap 'say "== stopped by a signal"; exit 1' TERM INT HUP
say "== $(date -u +%FT%TZ) ci/device-run.sh, budget $budget s$($quick && echo ', --quick'); pack: $(tr '\n' ' ' < "$pack/build.env")"

# ---- The machine: a bare one lacks the Vulkan loader; NVIDIA keeps its ICD apart ---------------
if [[ -d .gl ]] && ! ldconfig -p 2>/dev/null | grep -q libGLdispatch; then
  for f in .gl/*.deb; do timeout 60 dpkg -x "$f" /; done
  timeout 60 ldconfig
fi
export LD_LIBRARY_PATH="$pack/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export VK_LAYER_PATH="$pack/layer${VK_LAYER_PATH:+:$VK_LAYER_PATH}"
icd_dirs=(/usr/local/nvidia/share/vulkan/icd.d /usr/local/nvidia/etc/vulkan/icd.d /etc/vulkan/icd.d
  /usr/local/etc/vulkan/icd.d /usr/share/vulkan/icd.d /usr/local/share/vulkan/icd.d /run/nvidia/driver/etc/vulkan/icd.d
  /run/nvidia/driver/usr/share/vulkan/icd.d)
nvidia_icd=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
if [[ -z "${VK_DRIVER_FILES:-}" && -z "${VK_ICD_FILENAMES:-}" && -f $nvidia_icd ]]; then export VK_DRIVER_FILES=$nvidia_icd; fi

# The loader's view of the machine, into loader.txt (a summary in run.log): what it is told, what
# the icd.d folders hold, which libraries it and NVIDIA's ICD would load.
describe_loader() {
  echo "VK_DRIVER_FILES=${VK_DRIVER_FILES:-(unset)}"
  echo "VK_ICD_FILENAMES=${VK_ICD_FILENAMES:-(unset)}"
  echo "VK_ADD_DRIVER_FILES=${VK_ADD_DRIVER_FILES:-(unset)}"
  echo "VK_LAYER_PATH=$VK_LAYER_PATH"
  echo "LD_LIBRARY_PATH=$LD_LIBRARY_PATH"
  echo "XDG_DATA_DIRS=${XDG_DATA_DIRS:-(unset)}"
  local d f
  for d in "${icd_dirs[@]}"; do
    [[ -d $d ]] || { echo "icd.d: $d (absent)"; continue; }
    echo "icd.d: $d"
    for f in "$d"/*; do
      [[ -e $f ]] || continue
      echo "  $(basename "$f"): $(grep -o '"library_path"[^,}]*' "$f" 2>/dev/null | head -1)"
    done
  done
  echo "libraries (ldconfig):"
  timeout 20 ldconfig -p 2>/dev/null | grep -E 'libvulkan\.so|libGLX_nvidia|libnvidia-|libGLdispatch|libEGL_nvidia' | sed 's/^/  /'
  echo "libraries (the pack's lib/):"
  ls "$pack/lib" 2>/dev/null | grep -E 'vulkan|nvidia|VkLayer' | sed 's/^/  /'
  for d in /usr/local/nvidia/lib64 /usr/local/nvidia/lib /usr/lib/x86_64-linux-gnu /usr/lib64 /run/nvidia/driver/usr/lib/x86_64-linux-gnu; do
    [[ -d $d ]] || continue
    f=$(ls "$d" 2>/dev/null | grep -E '^(libvulkan\.so|libGLX_nvidia\.so|libnvidia-glvkspirv|libnvidia-gpucomp)' | tr '\n' ' ')
    [[ -z $f ]] || echo "  in $d: $f"
  done
}
describe_loader > "$run/loader.txt" 2>&1
say "   loader: VK_DRIVER_FILES=${VK_DRIVER_FILES:-(unset)} VK_ICD_FILENAMES=${VK_ICD_FILENAMES:-(unset)}"
grep -E '^icd.d: [^(]*$|^  [^ ]+\.json' "$run/loader.txt" | sed 's/^/   /' | tee -a "$log" >&2
say "   libraries: $(grep -oE '(libvulkan\.so\.[0-9.]*|libGLX_nvidia\.so\.[0-9.]*)' "$run/loader.txt" | sort -u | tr '\n' ' ')(loader.txt has the rest)"

bin=$pack/bin
export pack bin run captures  # read by the step functions, which run in a child bash

# The tests and the binaries hold the absolute paths they were built with (the sources: the scene
# presets, the paper's tables, the seed corpora; vsgl-bench for the tests): recreate both when this
# machine lacks them, before the first step that reads them.
source_dir=$(sed -n 's/^source_dir=//p' "$pack/build.env")
build_dir=$(sed -n 's/^build_dir=//p' "$pack/build.env")
if [[ -n $source_dir && ! -e $source_dir ]]; then
  if mkdir -p "$(dirname "$source_dir")" && ln -s "$PWD" "$source_dir"; then
    say "   linked $source_dir -> $PWD (the sources the binaries were built with)"
  else
    say "   could not link $source_dir -> $PWD: steps that read the sources will fail"
  fi
fi
if [[ -n $build_dir && ! -x $build_dir/bench/vsgl-bench ]]; then
  mkdir -p "$build_dir/bench" "$build_dir/tests" &&
    cp "$bin"/vsgl-bench "$bin"/vsgl-gbench "$bin"/vsgl-mipbench "$build_dir/bench/" &&
    cp "$bin/vsgl_tests" "$build_dir/tests/" &&
    { [[ ! -f $bin/harness_layers.txt ]] || cp "$bin/harness_layers.txt" "$build_dir/"; } &&
    say "   placed the binaries at $build_dir (where the tests look for them)" ||
    say "   could not place the binaries at $build_dir: the tests that run vsgl-bench will fail"
fi
export build_dir
paper=(--paper results/paper/paper_tables.json --schema results/schema/table.schema.json)

# step NAME LIMIT MIN COMMAND...: runs COMMAND with stdout and stderr in $run/NAME.txt, killed
# after LIMIT s or when the budget runs out; skipped when less than MIN s are left. A failed
# step's last lines go to run.log; the results are bundled after every step.
step() {
  local name=$1 limit=$2 min=$3
  shift 3
  local left=$((budget - (SECONDS - start)))
  if ((left < min)); then
    say "-- $name: SKIPPED ($left s of the budget left, needs $min)"
    status=1
    return 1
  fi
  ((limit > left)) && limit=$left
  local t0=$SECONDS
  say "== $(date -u +%T) $name (limit $limit s)"
  # A shell function of this script runs in a child bash (timeout runs programs only).
  if declare -F "$1" > /dev/null; then
    export -f "$1"
    set -- bash -c '"$@"' _ "$@"
  fi
  STEP_LIMIT=$limit timeout --kill-after=5 "$limit" "$@" > "$run/$name.txt" 2>&1
  local rc=$?
  local what="exit $rc"
  ((rc == 124 || rc == 137)) && what="STOPPED at its $limit s limit"
  say "   $name: $what after $((SECONDS - t0)) s"
  if ((rc != 0)); then
    status=1
    tail -n 15 "$run/$name.txt" | sed 's/^/   | /' >> "$log"
  fi
  bundle
  return $rc
}

if $quick; then
  # The reference capture must have the capture's G-buffer (quality refuses any other).
  gbuffer="--gbuffer 480x272"
  size="$gbuffer --rsm 128"
  reference_size="$gbuffer --rsm ${reference_rsm:-256}"
  # Fig. 7's exact-visibility reference from a 64^2 RSM (of the reference capture's): every VPL
  # traced to every pixel.
  quality_args=(--frames 4 --k-sweep 1,2 --error-stride 8 --visibility ism --visibility-reference-rsm 64)
  tables_quick=(--quick)
  replays=(--vsgl_replays=3 --vsgl_tables=1)
  gbench_quick=(--vsgl_generators=fis_tok15,fis_modified)
  sweep_args=(--quick --generators fis_tok15,fis_modified --axis vsgls=256,1024 --axis pdf-sharpness=1,2 --time-budget 20)
  # lavapipe shades about 2e7 VSGL evaluations a second: every 8th pixel per axis (recorded in
  # frame.json as not the paper's size) keeps a frame near a second.
  frame_args="--quick --stride 8 --time-cap 10"
else
  size=""
  reference_size="--rsm ${reference_rsm:-4096}"
  # G-buffer stride 4 (480x272 of 1920x1088): the per-frame FLIP and pixel statistics run on the
  # CPU, about 2 s a frame at full size, and a run judges some 400 frames per scene.
  # Fig. 7's exact-visibility reference (DESIGN.md §11a.2) from a 512^2 RSM (every 8th texel of
  # the reference capture's): every VPL of it traced to every one of the 480x272 pixels, some 3e10
  # segments.
  quality_args=(--error-stride 4 --visibility ism --visibility-reference-rsm 512)
  tables_quick=()
  replays=()
  gbench_quick=()
  sweep_args=(--axis vsgls=256:16384:x4 --axis pdf-sharpness=0.5,1,2,4 --time-budget 50)
  frame_args="--time-cap 25"
fi
export size reference_size frame_args

# 1. The device, as Vulkan and the driver see it. The run stops here when the loader finds no
# usable device, or (without --quick, whose rehearsal is on lavapipe) only CPU ones.
devices_ok() {
  [[ -s $run/devices.json ]] && grep -q '"usable": true' "$run/devices.json" || return 1
  $quick || grep -q '"type": "\(discrete\|integrated\|virtual\)"' "$run/devices.json"
}
if command -v nvidia-smi > /dev/null; then
  timeout 30 nvidia-smi -q > "$run/nvidia-smi.txt" 2>&1 || say "   nvidia-smi -q failed (exit $?): see nvidia-smi.txt"
  say "   nvidia-smi: $(grep -m1 'Driver Version' "$run/nvidia-smi.txt" | tr -s ' ') $(grep -m1 'Product Name' "$run/nvidia-smi.txt" | tr -s ' ')"
else
  say "   no nvidia-smi on PATH"
fi
list_devices() {
  step devices 30 5 "$bin/vsgl-bench" devices
  timeout 30 "$bin/vsgl-bench" devices --json > "$run/devices.json" 2> "$run/devices_json.err"
}
list_devices
if ! devices_ok; then
  say "   the loader found no usable GPU (devices: $(grep -o '"name": "[^"]*"\|"type": "[^"]*"' "$run/devices.json" 2>/dev/null | sed 's/"[a-z]*": //' | tr '\n' ' ')$($quick || echo '; only --quick rehearses on a CPU device'))"
  say "   searching the usual places for NVIDIA's ICD and its library"
  found_icds=$(timeout 30 find "${icd_dirs[@]}" /usr/local/nvidia /etc /usr/share /opt -maxdepth 6 -name 'nvidia_icd*.json' 2>/dev/null | sort -u)
  found_libs=$(timeout 30 find /usr/local/nvidia /usr/lib /usr/lib64 /lib /opt /run/nvidia -maxdepth 5 -name 'libGLX_nvidia.so.*' 2>/dev/null | sort -u)
  say "   ICD files found: ${found_icds:-none}"
  say "   libGLX_nvidia found: ${found_libs:-none}"
  for lib in $found_libs; do
    d=$(dirname "$lib")
    [[ :$LD_LIBRARY_PATH: == *:$d:* ]] || export LD_LIBRARY_PATH="$LD_LIBRARY_PATH:$d"
  done
  # The ICDs found, else the one given again, now with the libraries found on the path.
  for icd in ${found_icds:-${VK_DRIVER_FILES:-}}; do
    export VK_DRIVER_FILES=$icd
    say "   retrying with VK_DRIVER_FILES=$icd"
    list_devices
    devices_ok && break
  done
  if ! devices_ok; then
    say "   still no usable GPU: the loader's own account (VK_LOADER_DEBUG=all) is in loader_debug.txt"
    VK_LOADER_DEBUG=all timeout 30 "$bin/vsgl-bench" devices > "$run/loader_debug.txt" 2>&1
    grep -E 'ERROR|WARNING|Found ICD manifest|ICD drivers named|[Ff]ailed|[Cc]ould not|[Uu]nable' "$run/loader_debug.txt" |
      awk '!seen[$0]++' | head -n 30 | sed 's/^/   | /' >> "$log"
    describe_loader > "$run/loader.txt" 2>&1
    say "   stopping: the remaining steps need the device"
    exit 1
  fi
fi
say "   devices: $(grep -o '"name": "[^"]*"' "$run/devices.json" | sed 's/"name": //' | tr '\n' ' ')(default $(sed -n 's/^ *"default": \([0-9]*\),$/\1/p' "$run/devices.json"))"
bundle

# 2. The captures, recorded here from the carried models: the paper-size captures are too big to
# carry (ci/device-pack.sh).
assets=$captures/assets
if [[ -f $pack/scenes.tar.xz ]] && mkdir -p "$assets" && timeout 120 bash -c 'xz -dc "$1" | tar xf - -C "$2"' _ "$pack/scenes.tar.xz" "$assets"; then
  scenes=(sponza conference-room)
  say "   carried the paper's scenes ($(du -sm "$pack/scenes.tar.xz" | cut -f1) MiB xz, $(du -sm "$assets" | cut -f1) MiB unpacked):"
  sed 's/^/     /' "$pack/scenes.txt" | tee -a "$log" >&2
  cp "$pack/scenes.txt" "$run/scenes_carried.txt"
else
  scenes=(atrium conference)
  say "   no paper scenes in the pack (ci/device-pack.sh found none): timing the procedural stand-ins"
fi
export assets
record_scenes() {
  # $size unquoted: it is empty or options
  for scene in "$@"; do
    "$bin/vsgl-bench" record --scene "$scene" --assets "$assets" --out "$captures/$scene" $size || return 1
  done
}
step record 120 20 record_scenes "${scenes[@]}"
table_captures=(--capture "$captures/${scenes[0]}" --capture "$captures/${scenes[1]}")

# 3. verify: both pyramid paths (its default) and every generator's checks, each capture.
for scene in "${scenes[@]}"; do
  step "verify_$scene" 120 20 "$bin/vsgl-bench" verify --capture "$captures/$scene" --json "$run/verify_$scene.json"
done

# 4-5. Tables 1 and 2 on the texture path (the default), then on the buffer path. Each table's
# timing stops at its --time-cap; two tables, recording and the copy bandwidth fit the limit.
step tables_texture 150 30 "$bin/vsgl-bench" tables "${table_captures[@]}" --out "$run/texture" \
  "${paper[@]}" --no-progress --time-cap 45 "${tables_quick[@]}"
step tables_buffer 120 30 "$bin/vsgl-bench" tables "${table_captures[@]}" --out "$run/buffer" --pyramid buffer \
  "${paper[@]}" --no-progress --time-cap 35 "${tables_quick[@]}"

# 5b. The paper's frame phase by phase (DESIGN.md §9.2) on each scene's capture, at the paper's
# sizes (N 1024, ISM 64^2, as recorded): per scene, its timing stops at the --time-cap in
# $frame_args, leaving the step's limit room for the captures' uploads and the warm-ups.
frame_scenes() {
  # $frame_args unquoted: options
  for scene in "$@"; do
    "$bin/vsgl-bench" frame --capture "$captures/$scene" --out "$run/frame/$scene" \
      --schema results/schema/frame.schema.json --no-progress $frame_args || return 1
  done
}
step frame 120 30 frame_scenes "${scenes[@]}"

# 6-7. The Google Benchmark binaries, JSON out. Their --vsgl_captures is a cache of the paper-size
# captures: where a capture there has other sizes they record over it, so the --quick rehearsal,
# whose captures are small, gives them a folder of their own.
bench_captures=$captures
! $quick || bench_captures=$captures/benchmarks
step mipbench 60 15 "$bin/vsgl-mipbench" --vsgl_captures="$bench_captures" --vsgl_assets="$assets" "${replays[@]}" \
  --benchmark_out="$run/mipbench.json" --benchmark_out_format=json
step gbench 90 20 "$bin/vsgl-gbench" --vsgl_captures="$bench_captures" --vsgl_assets="$assets" "${replays[@]}" "${gbench_quick[@]}" \
  --benchmark_out="$run/gbench.json" --benchmark_out_format=json

# 7b. A short sweep (DESIGN.md §10.1) on Table 1's capture: N on both views times the PDF's
# sharpness gamma, with the fitted growth of every phase; its --time-budget of timing is split
# over its points, leaving the step's 90 s room for recording the points' inputs.
step sweep 90 30 "$bin/vsgl-bench" sweep --capture "$captures/${scenes[0]}" "${sweep_args[@]}" --out "$run/sweep" \
  --schema results/schema/sweep.schema.json --no-progress

# 8. The GPU test suites, on this machine's default device under the validation layer (the
# fixture fails a test on any validation message): one process and one gtest JSON per suite, so
# a crash costs that suite alone; GpuAssistedValidation (a driver it has never met) runs last.
run_tests() {
  local t0=$SECONDS device tests=$build_dir/tests/vsgl_tests
  [[ -x $tests ]] || tests=$bin/vsgl_tests
  device=${VSGL_TEST_DEVICE:-$(sed -n 's/^ *"default": \([0-9]*\),$/\1/p' "$run/devices.json")}  # its index
  [[ -n $device ]] || { echo "no default device in devices.json"; return 1; }
  echo "test device: $device (vsgl-bench devices)"
  # The `gpu` label's filter, from where CMake takes it.
  local gpu_filter
  gpu_filter=$(sed -n 's/^set(VSGL_GPU_SUITES "\(.*\)")$/\1/p' tests/CMakeLists.txt)
  [[ -n $gpu_filter ]] || { echo "no VSGL_GPU_SUITES in tests/CMakeLists.txt"; return 1; }
  # Not here unless installed: Debian's assimp-testmodels, which these tests read (CI runs them).
  local skip=""
  [[ -d /usr/share/assimp/models/glTF2 ]] ||
    skip="GltfRecordTest.SampleModelsRecordWithTheirTextures:GltfRecordCli.RecordsTheRoomWithItsSourceInTheSidecar"
  local suites
  local list='s/^\([A-Za-z0-9_]*\)\.$/\1/p'
  suites=$(timeout 60 "$tests" --gtest_list_tests --gtest_filter="$gpu_filter-GpuAssistedValidation.*" | sed -n "$list")
  [[ -n $suites ]] || { echo "vsgl_tests lists no GPU suite"; return 1; }
  suites+=$'\n'$(timeout 60 "$tests" --gtest_list_tests --gtest_filter='GpuAssistedValidation.*' | sed -n "$list")
  mkdir -p "$run/tests"
  # GpuAssistedValidation keeps 30 s for itself: a slow suite before it cannot crowd it out.
  local suite rc failed=0 left reserve
  for suite in $suites; do
    reserve=30
    [[ $suite != GpuAssistedValidation ]] || reserve=0
    left=$((STEP_LIMIT - (SECONDS - t0) - 2 - reserve))
    if ((left < 5)); then
      echo "$suite: not run (the step's time is up)"
      failed=1
      continue
    fi
    VSGL_TEST_DEVICE=$device timeout --kill-after=3 "$left" "$tests" --gtest_filter="$suite.*${skip:+-$skip}" \
      --gtest_output="json:$run/tests/$suite.json" > "$run/tests/$suite.txt" 2>&1
    rc=$?
    if ((rc != 0)); then
      failed=1
      [[ -f $run/tests/$suite.json ]] || echo "$suite: no JSON (crashed or killed: exit $rc)"
    fi
    echo "$suite: exit $rc, $(grep -c '^\[       OK \]' "$run/tests/$suite.txt") passed, $(grep -c '^\[  FAILED  \] .*(' "$run/tests/$suite.txt") failed, $(grep -c '^\[  SKIPPED \] .*(' "$run/tests/$suite.txt") skipped"
  done
  return $failed
}
step tests 240 30 run_tests
if [[ -d $run/tests ]]; then
  say "   tests: $(cat "$run"/tests/*.txt | grep -c '^\[       OK \]') passed, $(cat "$run"/tests/*.txt | grep -c '^\[  FAILED  \] .*(') failed, $(cat "$run"/tests/*.txt | grep -c '^\[  SKIPPED \] .*(') skipped in $(ls "$run"/tests/*.txt | wc -l) suites, $(ls "$run"/tests/*.json 2>/dev/null | wc -l) with JSON; validation errors outside the GPU-AV positive control: $(cat "$run"/tests/*.txt | grep 'Validation Error' | grep -vc 'positive control')"
  grep -h '^\[  FAILED  \] .*(' "$run"/tests/*.txt | sed 's/^/   /' | tee -a "$log" >&2
fi

# 9. Quality (DESIGN.md §11a) per scene against a reference capture: the same frame recorded again
# with a larger RSM, whose texels are the reference's VPLs; it extends the reference's convergence
# ladder past what lavapipe can shade. Last: the steps above are the run's deliverables, and each
# scene's quality.json is written whole or not.
record_reference() {
  # $reference_size unquoted: options
  "$bin/vsgl-bench" record --scene "$1" --assets "$assets" --out "$captures/$1-reference" $reference_size
}
for scene in "${scenes[@]}"; do
  # Its minimum leaves quality's: a reference capture with no time to use it is not recorded.
  step "reference_capture_$scene" 90 60 record_reference "$scene" &&
    step "quality_$scene" 180 40 "$bin/vsgl-bench" quality --capture "$captures/$scene" \
      --reference-capture "$captures/$scene-reference" "${quality_args[@]}" --out "$run/quality"
  rm -rf "$captures/$scene-reference"  # up to 1 GiB each at 4096^2
done

exit $status
