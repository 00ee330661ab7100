#!/usr/bin/env bash
# The README's main command: install what is missing, build, then reproduce Tables 1 and 2 on the
# default device (a real GPU when present, lavapipe otherwise). `vsgl-bench tables` records the
# paper's captures first if they are missing or stale (Crytek Sponza = Table 1, the Conference room
# = Table 2, when their models are found; else the procedural stand-ins atrium and conference),
# prints the tables beside the paper's numbers and writes them to results/<device>/.
# Extra arguments go to `vsgl-bench tables` (e.g. --assets DIR for the scene models, --device NAME,
# --repetitions 30). Usage: bash ci/reproduce.sh --assets DIR
set -euo pipefail
cd "$(dirname "$0")/.."
bash ci/install-deps.sh
cmake --preset release
cmake --build --preset release --target vsgl-bench   # the tests are ci/test.sh's job
bin=build/release/bench/vsgl-bench
"$bin" devices
# The models are looked for under --assets, VSGL_ASSETS and assets/ here, never beside the checkout;
# without them `tables` warns, before timing, that it times the stand-ins and where to get the models.
"$bin" tables "$@"
