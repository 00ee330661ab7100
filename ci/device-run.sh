#!/usr/bin/env bash
# The whole run on a lent GPU machine, from a pack made here by ci/device-pack.sh, in one command
# and inside a wall-time budget. Steps run most valuable first, so a run cut short still brings
# back what matters most:
#   1 devices (--json) and nvidia-smi     5 tables with --pyramid buffer
#   2 record sponza and conference-room    6 vsgl-mipbench (the three mipmapping strategies)
#   3 verify both captures: both pyramid   7 vsgl-gbench
#     paths, every generator               8 the test suite under the validation layer
#   4 tables (texture path, the default)  7b a short sweep: N x PDF sharpness (90 s at most)
# The paper's scenes come from the pack's scenes.tar.xz (ci/device-pack.sh); a pack without them
# records the procedural stand-ins atrium and conference instead, and run.log says so. run.log
# lists the model files carried (size, SHA-256).
# Each step runs under its own limit and what is left of the budget; a step that would start with
# less than a minimum left is skipped, and run.log says so. Whatever ran comes back as
# OUT/results.tar.gz (everything the steps wrote) and OUT/run.log (each step: start, seconds, exit).
#
# Usage (repository root, pack in .device-pack/):
#   bash ci/device-run.sh OUT [--quick] [--budget SECONDS]
#   --quick       the rehearsal on lavapipe: 480x272 captures with a 128^2 RSM, tables --quick,
#                 3 replays per benchmark on Table 1 only, vsgl-gbench for the FIS generators
#   --budget S    wall-time budget of the whole run [540: the 10 minutes a lent machine's command gets,
#                 less the machine's start-up and the transfers]
# Exit: 0 if every step ran and passed, 1 otherwise (run.log names the steps).
#
# Through this workplace's device tool: here `bash ci/device-pack.sh --gl`, then one call of
#   run(command="bash ci/device-run.sh $OUT", carry=[".device-pack", ".gl"], timeout_s=600)
# brings back $OUT/results.tar.gz and $OUT/run.log; give the machine back after it.
set -uo pipefail
cd "$(dirname "$0")/.."
out=${1:?usage: bash ci/device-run.sh OUT [--quick] [--budget SECONDS]}
shift
quick=false
budget=540
while [[ $# -gt 0 ]]; do
  case "$1" in
    --quick) quick=true ;;
    --budget) budget=${2:?--budget takes seconds}; shift ;;
    *) echo "ci/device-run.sh: unknown option '$1' (--quick, --budget S)" >&2; exit 2 ;;
  esac
  shift
done
pack=$PWD/.device-pack
# The pack travels compressed (ci/device-pack.sh): unpack the tools once.
if [[ -f $pack/tools.tar.xz && ! -x $pack/bin/vsgl-bench ]]; then xz -dc "$pack/tools.tar.xz" | tar xf - -C "$pack"; fi
[[ -x $pack/bin/vsgl-bench && -f $pack/build.env ]] || { echo "ci/device-run.sh: no pack in $pack: run bash ci/device-pack.sh first (here, not on the GPU machine)" >&2; exit 2; }
mkdir -p "$out"
out=$(cd "$out" && pwd)
run=$(mktemp -d)
captures=$(mktemp -d)
log=$out/run.log
: > "$log"
start=$SECONDS
status=0
say() { echo "$*" | tee -a "$log" >&2; }
# Whatever happens, what was measured comes back (and the captures, too big to return, do not).
trap 'tar czf "$out/results.tar.gz" -C "$run" . ; rm -rf "$captures"; say "== $((SECONDS - start)) s in all; results in $out/results.tar.gz"' EXIT

# ---- The machine: a bare lent one lacks the Vulkan loader; NVIDIA keeps its ICD apart ---------
if [[ -d .gl ]] && ! ldconfig -p 2>/dev/null | grep -q libGLdispatch; then
  for f in .gl/*.deb; do dpkg -x "$f" /; done
  ldconfig
fi
export LD_LIBRARY_PATH="$pack/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export VK_LAYER_PATH="$pack/layer${VK_LAYER_PATH:+:$VK_LAYER_PATH}"
nvidia_icd=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
if [[ -z "${VK_DRIVER_FILES:-}" && -f $nvidia_icd ]]; then export VK_DRIVER_FILES=$nvidia_icd; fi
bin=$pack/bin
export pack bin run captures  # read by the step functions, which run in a child bash
paper=(--paper results/paper/paper_tables.json --schema results/schema/table.schema.json)

# step NAME LIMIT MIN COMMAND...: runs COMMAND with stdout and stderr in $run/NAME.txt, killed
# after LIMIT s or when the budget runs out; skipped when less than MIN s are left.
step() {
  local name=$1 limit=$2 min=$3
  shift 3
  local left=$((budget - (SECONDS - start)))
  if ((left < min)); then
    say "-- $name: SKIPPED ($left s of the budget left, needs $min)"
    status=1
    return
  fi
  ((limit > left)) && limit=$left
  local t0=$SECONDS
  say "== $(date -u +%T) $name (limit $limit s)"
  # A shell function of this script runs in a child bash (timeout runs programs only).
  if declare -F "$1" > /dev/null; then set -- bash -c "$(declare -f "$1"); $(printf '%q ' "$@")"; fi
  timeout --kill-after=5 "$limit" "$@" > "$run/$name.txt" 2>&1
  local rc=$?
  local what="exit $rc"
  ((rc == 124 || rc == 137)) && what="STOPPED at its $limit s limit"
  say "   $name: $what after $((SECONDS - t0)) s"
  ((rc == 0)) || status=1
}

if $quick; then
  size="--gbuffer 480x272 --rsm 128"
  tables_quick=(--quick)
  replays=(--vsgl_replays=3 --vsgl_tables=1)
  gbench_quick=(--vsgl_generators=fis_tok15,fis_modified)
  sweep_args=(--quick --generators fis_tok15,fis_modified --axis vsgls=256,1024 --axis pdf-sharpness=1,2)
else
  size=""
  tables_quick=()
  replays=()
  gbench_quick=()
  sweep_args=(--axis vsgls=256:16384:x4 --axis pdf-sharpness=0.5,1,2,4 --time-budget 60)
fi
export size

# 1. The device, as Vulkan and the driver see it.
step devices 30 5 "$bin/vsgl-bench" devices
"$bin/vsgl-bench" devices --json > "$run/devices.json" 2>> "$log" || status=1
command -v nvidia-smi > /dev/null && nvidia-smi -q > "$run/nvidia-smi.txt" 2>&1

# 2. The captures, recorded here from the carried models: the paper-size captures are too big to
# carry (ci/device-pack.sh).
assets=$captures/assets
if [[ -f $pack/scenes.tar.xz ]] && mkdir -p "$assets" && xz -dc "$pack/scenes.tar.xz" | tar xf - -C "$assets"; then
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

# 4-5. Tables 1 and 2 on the texture path (the default), then on the buffer path.
step tables_texture 150 30 "$bin/vsgl-bench" tables "${table_captures[@]}" --out "$run/texture" \
  "${paper[@]}" --no-progress "${tables_quick[@]}"
step tables_buffer 120 30 "$bin/vsgl-bench" tables "${table_captures[@]}" --out "$run/buffer" --pyramid buffer \
  "${paper[@]}" --no-progress "${tables_quick[@]}"

# 6-7. The Google Benchmark binaries, JSON out.
step mipbench 60 15 "$bin/vsgl-mipbench" --vsgl_captures="$captures" --vsgl_assets="$assets" "${replays[@]}" \
  --benchmark_out="$run/mipbench.json" --benchmark_out_format=json
step gbench 90 20 "$bin/vsgl-gbench" --vsgl_captures="$captures" --vsgl_assets="$assets" "${replays[@]}" "${gbench_quick[@]}" \
  --benchmark_out="$run/gbench.json" --benchmark_out_format=json

# 7b. A short sweep (DESIGN.md §10.1) on Table 1's capture: N on both views times the PDF's
# sharpness gamma, with the fitted growth of every phase; 60 s of timing split over its points.
step sweep 90 30 "$bin/vsgl-bench" sweep --capture "$captures/${scenes[0]}" "${sweep_args[@]}" --out "$run/sweep" \
  --schema results/schema/sweep.schema.json --no-progress

# 8. The test suite, last, on this machine's default device under the validation layer (the
# fixture fails a test on any validation message). The tests hold the absolute paths they were
# built with (sources, vsgl-bench): recreate both if this machine lacks them.
run_tests() {
  local source_dir build_dir
  source_dir=$(sed -n 's/^source_dir=//p' "$pack/build.env")
  build_dir=$(sed -n 's/^build_dir=//p' "$pack/build.env")
  if [[ ! -e $source_dir ]]; then
    mkdir -p "$(dirname "$source_dir")" && ln -s "$PWD" "$source_dir" || return 1
  fi
  if [[ ! -x $build_dir/bench/vsgl-bench ]]; then
    mkdir -p "$build_dir/bench" "$build_dir/tests" || return 1
    cp "$bin"/vsgl-bench "$bin"/vsgl-gbench "$bin"/vsgl-mipbench "$build_dir/bench/" && cp "$bin/vsgl_tests" "$build_dir/tests/" || return 1
  fi
  local device=${VSGL_TEST_DEVICE:-}
  if [[ -z $device ]]; then
    device=$(sed -n 's/^ *"default": \([0-9]*\),$/\1/p' "$run/devices.json")  # its index
  fi
  [[ -n $device ]] || { echo "no default device in devices.json"; return 1; }
  echo "test device: $device (vsgl-bench devices)"
  # Not here unless installed: Debian's assimp-testmodels, which these tests read (CI runs them).
  local skip=""
  [[ -d /usr/share/assimp/models/glTF2 ]] ||
    skip="-GltfImport.BadNormalsAreRepairedAndSaidSo:GltfImport.BrokenSampleFilesGiveTheirExpectedOutcome"
  [[ -z $skip ]] || skip+=":GltfImport.EngineWithManyNodesKeepsItsTransformsAndCamera:GltfImport.TexturedBoxIsTheSameInEveryContainer"
  [[ -z $skip ]] || skip+=":GltfRecordTest.SampleModelsRecordWithTheirTextures:GltfRecordCli.RecordsTheRoomWithItsSourceInTheSidecar"
  VSGL_TEST_DEVICE=$device "$build_dir/tests/vsgl_tests" --gtest_output="json:$run/tests.json" \
    ${skip:+--gtest_filter="$skip"}
}
step tests 240 30 run_tests
if [[ -f $run/tests.txt ]]; then
  say "   tests: $(grep -c '^\[       OK \]' "$run/tests.txt") passed, $(grep -c '^\[  FAILED  \] .*(' "$run/tests.txt") failed, $(grep -c '^\[  SKIPPED \] .*(' "$run/tests.txt") skipped; validation errors outside the GPU-AV positive control: $(grep 'Validation Error' "$run/tests.txt" | grep -vc 'positive control')"
fi
exit $status
