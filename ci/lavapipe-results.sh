#!/usr/bin/env bash
# Regenerates every committed lavapipe result from freshly recorded captures, in the order of
# their importance: captures, verify, Tables 1-2, quality (every scene, with its sequence), the
# reference ladder (Sponza against 2048^2 reference VPLs),
# the shading pictures, the frame table, the two compare reports, and the dashboard (+ screenshot when a headless
# Chromium is there). Each step's wall time goes to OUT/regenerate.log. Long: about 3 hours on
# lavapipe on a 2-core machine (Sibenik's sequence and quality about 25 minutes of it). Not part of
# .ci/run.
#
# The scenes are the paper's own, Crytek Sponza (Table 1) and the Conference room (Table 2), from
# their models on the asset search path (docs/scenes.md, "The paper's scenes"); the results go to
# results/lavapipe. The Sibenik cathedral (Fig. 5's lower row, no paper table) is recorded too and
# measured by the quality step only. With --stand-ins the procedural stand-ins atrium and conference
# are used (Sibenik has none) and the results go to results/lavapipe/stand-ins, so both stay side
# by side.
# The sweep step times every generator along each axis of `vsgl-bench sweep` (N, G-buffer and RSM
# size, K, k-means iterations on Sponza; PDF sharpness on both scenes) into OUT/sweep/<axis>/, at a
# 960x544 G-buffer (480x272 along rsm) and a 256 RSM where the axis does not set them, 5-8 rounds per point, so that the
# whole sweep stays under 30 minutes on a 2-core machine (its wall time goes to the log). At a
# 3840x2176 G-buffer k-means binds ranges past lavapipe's 128 MiB maxStorageBufferRange (178 MB):
# those cases are recorded as beyond the device and FIS is timed. VSGL_SWEEPS="rsm K" runs only
# the sweeps named.
# Usage: bash ci/lavapipe-results.sh [--stand-ins] [STEP...]   steps: record verify tables quality
#        reference-ladder shade frame compare sweep dashboard (default: all, in that order). VSGL_BENCH=path/to/vsgl-bench to pick
#        a build; the compare step's slowed run needs the test build of vsgl-bench beside it
#        (tests/vsgl-bench-test-build of the same build folder, VSGL_BENCH_TEST_BUILD to pick it:
#        the shipped program has no --debug-slow, docs/testing.md); --assets DIR is passed on to record and sweep (repeatable): the paper's scenes' models
#        are looked for there and in VSGL_ASSETS, never beside the checkout, so one of the two is
#        needed unless --stand-ins.
set -euo pipefail
cd "$(dirname "$0")/.."
bench=${VSGL_BENCH:-build/release/bench/vsgl-bench}
test_build_bench=${VSGL_BENCH_TEST_BUILD:-$(dirname "$bench")/../tests/vsgl-bench-test-build}
out=results/lavapipe
caps=captures/paper
scenes=(sponza conference-room)
# Scenes of no paper table that the record and quality steps take as well (not the tables).
quality_only=(sibenik)
assets=()
steps=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --stand-ins) out=results/lavapipe/stand-ins; caps=captures/stand-ins; scenes=(atrium conference); quality_only=() ;;
    --assets) assets+=(--assets "$2"); shift ;;
    *) steps+=("$1") ;;
  esac
  shift
done
[[ ${#steps[@]} -gt 0 ]] || steps=(record verify tables quality reference-ladder shade frame compare sweep dashboard)
if [[ $out == results/lavapipe && ${#assets[@]} -eq 0 && -z ${VSGL_ASSETS:-} && " ${steps[*]} " =~ " "(record|sweep|reference-ladder)" " ]]; then
  echo "ci/lavapipe-results.sh: where are the paper's scenes? pass --assets DIR or set VSGL_ASSETS (DIR/sponza, DIR/conference, DIR/sibenik), or use --stand-ins" >&2
  exit 2
fi
[[ -x "$bench" ]] || { echo "ci/lavapipe-results.sh: no $bench (build it: cmake --preset release && cmake --build --preset release)" >&2; exit 2; }
# Only lavapipe: these are the lavapipe results (a GPU run goes to results/<its slug>).
export VK_ICD_FILENAMES=${VK_ICD_FILENAMES:-/usr/share/vulkan/icd.d/lvp_icd.x86_64.json}
mkdir -p "$out"
log=$out/regenerate.log
echo "# ci/lavapipe-results.sh at $(git rev-parse --short HEAD) on $(date -u +%FT%TZ): ${scenes[*]}: ${steps[*]}" >>"$log"
# The tables time exactly these captures (Table 1 from the first scene, Table 2 from the second).
table_captures=(--capture "$caps/${scenes[0]}" --capture "$caps/${scenes[1]}")

step() {  # step NAME COMMAND...: runs it, logs its wall time
  local name=$1 start
  shift
  start=$(date +%s)
  echo "== $name: $*" >&2
  "$@"
  echo "$name: $(( $(date +%s) - start )) s" | tee -a "$log" >&2
}

for s in "${steps[@]}"; do
  case "$s" in
    record)
      for scene in "${scenes[@]}" "${quality_only[@]}"; do
        step "record $scene" "$bench" record --scene "$scene" "${assets[@]}" --out "$caps/$scene"
      done ;;
    verify)
      for scene in "${scenes[@]}"; do
        # The text report is the console output; exit 1 (a check failed) stops the script.
        step "verify $scene" bash -c "\"$bench\" verify --capture $caps/$scene --json $out/verify_$scene.json > $out/verify_$scene.txt"
      done ;;
    tables)
      step tables "$bench" tables "${table_captures[@]}" --out "$out" --no-progress ;;
    quality)
      for scene in "${scenes[@]}" "${quality_only[@]}"; do
        step "sequence $scene" "$bench" record --scene "$scene" "${assets[@]}" --frames 32 --gbuffer 480x272 --rsm 256 \
          --out "$caps/sequences/$scene"
        # Fig. 7 (DESIGN.md §11a.2) is judged on Sponza: its frames with imperfect shadow maps, its
        # exact-visibility reference from a 128^2 RSM (every VPL of the 512^2 one traced to every
        # pixel is about 2 hours on lavapipe; the reference's ladder decides whether 128^2 is
        # enough). The other scenes leave it out.
        visibility=(--visibility none)
        [[ $scene == sponza ]] && visibility=(--visibility ism --visibility-reference-rsm 128)
        step "quality $scene" "$bench" quality --capture "$caps/$scene" --sequence "$caps/sequences/$scene" \
          "${visibility[@]}" --out "$out/quality"
      done ;;
    reference-ladder)
      # How the reference converges with its RSM (DESIGN.md §11a): each paper scene recorded again
      # with a 2048^2 RSM (a reference capture), its VPLs at 256^2, 512^2, 1024^2 and 2048^2 (the
      # rungs at strides 8, 4, 2 and 1 of one quality run: each against the next, the rate per
      # doubling and the remaining error), shading the same 120x68 pixels.
      for scene in "${scenes[@]}"; do
        ladder_capture=$caps/$scene-reference-2048
        step "reference capture $scene" "$bench" record --scene "$scene" "${assets[@]}" --rsm 2048 \
          --out "$ladder_capture"
        step "reference ladder $scene" "$bench" quality --capture "$caps/$scene" --reference-capture "$ladder_capture" \
          --reference-rsm 0 --error-stride 16 --frames 2 --k-sweep 1 --generators fis_tok15 --visibility none \
          --out "$out/reference-ladder"
      done ;;
    shade)
      # Fig. 5 as the paper renders it: a 64^2 imperfect shadow map per VSGL (DESIGN.md §8.1), from
      # the points the record step stores with each capture; and the same without visibility, to
      # see what the maps take away.
      for scene in "${scenes[@]}"; do
        step "shade $scene" "$bench" shade --capture "$caps/$scene" --stride 4 --validate --visibility ism \
          --out "$out/shade-ism"
        step "shade $scene, no visibility" "$bench" shade --capture "$caps/$scene" --stride 4 --validate \
          --visibility none --out "$out"
      done ;;
    frame)
      # The paper's frame phase by phase (DESIGN.md §9.2): N 1024, 64^2 maps, the 512^2 RSM as
      # recorded; the shading at G-buffer stride 8 (240x136), which frame.json records as not the
      # paper's size: at 1920x1088 lavapipe shades one frame in about 4 minutes.
      for scene in "${scenes[@]}"; do
        step "frame $scene" "$bench" frame --capture "$caps/$scene" --stride 8 --quick --time-cap 60 \
          --out "$out/frame/$scene" --no-progress
      done ;;
    compare)
      [[ -x "$test_build_bench" ]] || { echo "ci/lavapipe-results.sh: no $test_build_bench for the slowed run (build it: cmake --build --preset release --target vsgl-bench-test-build)" >&2; exit 2; }
      tmp=$(mktemp -d)
      for run in A B; do
        step "compare run $run" "$bench" tables "${table_captures[@]}" --generators fis_tok15,fis_modified \
          --out "$tmp/$run" --json-only --no-progress
      done
      step "compare run slowed" "$test_build_bench" tables "${table_captures[@]}" --generators fis_tok15,fis_modified \
        --debug-slow fis_modified --out "$tmp/S" --json-only --no-progress
      step "compare same" "$bench" compare "$tmp/A" "$tmp/B" --out "$out/compare_same_commit.md"
      # The slowed run must come out SLOWER: exit 1 from --fail-on is the expected answer here.
      step "compare slowed" bash -c "\"$bench\" compare $tmp/A $tmp/S --fail-on slower --out $out/compare_debug_slow_fis_modified.md; [[ \$? -eq 1 ]]"
      rm -rf "$tmp" ;;
    sweep)
      sweep_start=$(date +%s)
      sweep() {  # [gbuffer=WxH] [reps=N] sweep OUTNAME SCENE AXIS [FLAGS...]; VSGL_SWEEPS="NAME ..." runs only those
        local name=$1 scene=$2 axis=$3
        shift 3
        [[ -z ${VSGL_SWEEPS:-} || " $VSGL_SWEEPS " == *" $name "* ]] || return 0
        step "sweep $name" "$bench" sweep --scene "$scene" "${assets[@]}" --captures "$caps/sweep" --axis "$axis" \
          --gbuffer "${gbuffer:-960x544}" --rsm 256 --warmup 2 --repetitions "${reps:-5}" --max-repetitions 8 --time-budget 60 \
          --out "$out/sweep/$name" --no-progress "$@"
      }
      sweep vsgls "${scenes[0]}" vsgls=64:16384:x4
      sweep gbuffer "${scenes[0]}" gbuffer=480x272:3840x2176:x2
      # The camera view does not change along rsm: its smaller G-buffer keeps k-means' camera
      # rounds short, so the whole sweep stays within its 30 minutes.
      gbuffer=480x272 sweep rsm "${scenes[0]}" rsm=128:2048:x4
      # PDF independence (DESIGN.md §10.1): γ timed in 4 drawn blocks of 3 rounds, 12 rounds a point;
      # the smaller camera view keeps k-means' camera rounds, and so the 4 visits, short.
      gbuffer=480x272 reps=3 sweep "pdf-sharpness_${scenes[0]}" "${scenes[0]}" pdf-sharpness=0,0.5,1,2,4 --blocks 4
      gbuffer=480x272 reps=3 sweep "pdf-sharpness_${scenes[1]}" "${scenes[1]}" pdf-sharpness=0,0.5,1,2,4 --blocks 4
      sweep K "${scenes[0]}" K=1:16:x2
      sweep kmeans-iterations "${scenes[0]}" kmeans-iterations=1:8:x2
      echo "sweep (all axes): $(( $(date +%s) - sweep_start )) s" | tee -a "$log" >&2 ;;
    dashboard)
      step dashboard "$bench" dashboard results --out results/dashboard
      if chromium=$(bash ci/find-chromium.sh 2>/dev/null); then
        shoot() {  # shoot PNG PAGE HEIGHT
          "$chromium" --headless --no-sandbox --disable-gpu --hide-scrollbars --user-data-dir="$(mktemp -d)" \
            --window-size=1280,"$3" --screenshot="$1" "file://$2"
        }
        step screenshot shoot results/dashboard/screenshot.png "$PWD/results/dashboard/index.html" 1400
        # The scaling section sits far down the page (headless Chromium does not scroll to a
        # fragment before its screenshot): it is shot from a page of the sweeps alone.
        if [[ -d $out/sweep ]]; then
          page=$(mktemp -d)
          step "dashboard scaling" "$bench" dashboard "$out/sweep" --out "$page"
          step "screenshot scaling" shoot results/dashboard/screenshot-scaling.png "$page/index.html" 1600
          rm -rf "$page"
        fi
      else
        echo "ci/lavapipe-results.sh: no headless Chromium (ci/find-chromium.sh); screenshot not refreshed" >&2
      fi ;;
    *) echo "ci/lavapipe-results.sh: unknown step '$s'" >&2; exit 2 ;;
  esac
done
