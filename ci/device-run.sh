#!/usr/bin/env bash
# Runs the suite on a GPU machine from a pack made by ci/device-pack.sh: the device list, verify
# of both captures, Tables 1-2, and the Google Benchmark JSON; everything lands in one tarball.
# Usage (repository root on the GPU machine): bash ci/device-run.sh OUTDIR [extra tables options]
set -uo pipefail
cd "$(dirname "$0")/.."
out=${1:?usage: ci/device-run.sh OUTDIR}
shift
pack=$PWD/.device-pack
run=$(mktemp -d)
export LD_LIBRARY_PATH="$pack/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
# Lent NVIDIA machines keep their ICD here; elsewhere the loader finds the installed drivers.
nvidia_icd=/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json
if [[ -z "${VK_DRIVER_FILES:-}" && -f $nvidia_icd ]]; then export VK_DRIVER_FILES=$nvidia_icd; fi
bin=$pack/bin
status=0
step() { echo "== $(date -u +%T) $*" >&2; }
# Whatever happens, what was measured comes back.
trap 'mkdir -p "$out"; tar czf "$out/results.tar.gz" -C "$run" .' EXIT
step devices
"$bin/vsgl-bench" devices | tee "$run/devices.txt" || status=1
"$bin/vsgl-bench" devices --json > "$run/devices.json" || status=1
for scene in atrium conference; do
  step "verify $scene"
  timeout 240 "$bin/vsgl-bench" verify --capture "$pack/captures/$scene" --json "$run/verify_$scene.json" \
    | tee "$run/verify_$scene.txt" || status=1
done
step tables
timeout 300 "$bin/vsgl-bench" tables --captures "$pack/captures" --out "$run/tables" \
  --paper results/paper/paper_tables.json --schema results/schema/table.schema.json "$@" || status=1
step gbench
timeout 240 "$bin/vsgl-gbench" --vsgl_captures="$pack/captures" --benchmark_format=json \
  --benchmark_out="$run/gbench.json" --benchmark_out_format=json > "$run/gbench.txt" || status=1
step done
echo "ci/device-run.sh: results in $out/results.tar.gz (exit $status)"
exit $status
