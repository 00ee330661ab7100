#!/usr/bin/env bash
# The README's main command: install what is missing, build, record the paper's two captures
# (atrium = Table 1, conference = Table 2) if they are not there yet, and show the devices.
# Extra arguments go to `vsgl-bench record` (e.g. --device NAME).
set -euo pipefail
cd "$(dirname "$0")/.."
bash ci/install-deps.sh
cmake --preset release
cmake --build --preset release
bin=build/release/bench/vsgl-bench
"$bin" devices
for scene in atrium conference; do
  if [[ -f "captures/$scene/capture.json" ]]; then
    echo "captures/$scene exists (delete it to record again)"
  else
    "$bin" record --scene "$scene" --out "captures/$scene" "$@"
  fi
done
