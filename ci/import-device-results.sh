#!/usr/bin/env bash
# Files a run of ci/device-run.sh (its results.tar.gz, .tar.xz or .tar, brought back from the GPU
# machine) under results/<device slug>/, keeping the run's own layout (devices.json, verify_*,
# texture/ and buffer/ tables, frame/, mipbench.json, gbench.json, sweep/, tests/ with one gtest JSON per
# suite, run.log, build.env, each step's output), then regenerates results/dashboard/index.html
# with `vsgl-bench dashboard` so the run shows there.
#
# Before anything is written it refuses (exit 1, saying why):
#   - a run whose build is not this checkout: build.env's commit must be `git rev-parse HEAD`, and
#     the pack must not have been built from a tree with uncommitted changes (dirty=true);
#   - a run with a JSON file that does not parse, is of no kind, or does not conform to its
#     kind's schema (tests/data/result_kinds.json, checked by tests/validate_results.py with
#     python3-jsonschema);
#   - a run without build.env or devices.json, or whose device folder already exists.
# The slug is the name of the run's default device in devices.json (the device the run timed),
# lower-cased with every other run of characters a '-', as `vsgl-bench tables` names its folder:
# "NVIDIA H100 80GB HBM3" -> nvidia-h100-80gb-hbm3.
#
# Usage: bash ci/import-device-results.sh TARBALL [options]
#   --results DIR          the results folder to file into [results/ of this checkout]; DIR/dashboard
#                          is regenerated
#   --slug NAME            the device folder's name [from devices.json, as above]
#   --replace              replace an existing DIR/NAME/ (the old one stays in git's history)
#   --allow-other-commit   file a run built from another commit or a dirty tree; the mismatch is
#                          written to DIR/NAME/IMPORT.txt (compare its numbers knowing that)
# VSGL_BENCH=path/to/vsgl-bench picks the build that draws the dashboard [build/release, else build/ci].
# Exit: 0 filed; 1 refused or failed (nothing left half-written); 2 bad usage.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
me=ci/import-device-results.sh
usage="usage: bash $me TARBALL [--results DIR] [--slug NAME] [--replace] [--allow-other-commit]"
tarball=""
results=$repo/results
slug=""
replace=false
other_commit=false
while [[ $# -gt 0 ]]; do
  case "$1" in
    --results) results=${2:?--results takes a directory}; shift ;;
    --slug) slug=${2:?--slug takes a name}; shift ;;
    --replace) replace=true ;;
    --allow-other-commit) other_commit=true ;;
    -*) echo "$me: unknown option '$1'"$'\n'"$usage" >&2; exit 2 ;;
    *) [[ -z $tarball ]] || { echo "$me: one TARBALL only"$'\n'"$usage" >&2; exit 2; }; tarball=$1 ;;
  esac
  shift
done
[[ -n $tarball ]] || { echo "$usage" >&2; exit 2; }
refuse() { echo "$me: $*" >&2; exit 1; }
[[ -f $tarball ]] || refuse "$tarball: no such file (ci/device-run.sh leaves OUT/results.tar.gz)"
[[ -z $slug || $slug =~ ^[a-z0-9][a-z0-9._-]*$ ]] || { echo "$me: --slug '$slug': lower-case letters, digits, '.', '_', '-' only" >&2; exit 2; }
command -v python3 > /dev/null || refuse "python3 is not installed: it checks the run's JSON (bash ci/install-deps.sh)"
bench=${VSGL_BENCH:-}
if [[ -z $bench ]]; then
  for b in "$repo/build/release/bench/vsgl-bench" "$repo/build/ci/bench/vsgl-bench"; do [[ -x $b ]] && { bench=$b; break; }; done
fi
[[ -n $bench && -x $bench ]] && bench=$(cd "$(dirname "$bench")" && pwd)/$(basename "$bench") || refuse "no vsgl-bench to draw the dashboard with: build one (cmake --preset release && cmake --build build/release) or set VSGL_BENCH"

stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
mkdir "$stage/run"
# GNU tar reads gzip, xz or plain archives alike; it drops leading '/' and refuses '..' members.
tar xf "$tarball" -C "$stage/run" 2> "$stage/tar.err" || refuse "$tarball: not a readable tar archive: $(head -3 "$stage/tar.err")"
run=$stage/run
for f in build.env devices.json; do
  [[ -f $run/$f ]] || refuse "$tarball holds no $f: not a run of ci/device-run.sh, or one that stopped before it wrote it"
done

# The build must be this checkout's.
commit=$(sed -n 's/^commit=//p' "$run/build.env")
dirty=$(sed -n 's/^dirty=//p' "$run/build.env")
head=$(git -C "$repo" rev-parse HEAD 2>/dev/null || echo "")
mismatch=""
if [[ -z $head ]]; then
  mismatch="this checkout's commit cannot be read (not a git checkout), so the run's build ($commit) cannot be matched to it"
elif [[ $commit != "$head" ]]; then
  mismatch="the run was built from commit ${commit:-(none in build.env)}, this checkout is at $head"
elif [[ $dirty == true ]]; then
  mismatch="the run was built from commit $commit with uncommitted changes (build.env: dirty=true)"
fi
if [[ -n $mismatch ]]; then
  $other_commit || refuse "$mismatch: check out the run's commit (git checkout $commit) and import there, or pass --allow-other-commit to file it anyway"
  echo "$me: warning: $mismatch; filing it anyway (--allow-other-commit), noted in IMPORT.txt" >&2
fi

# Every JSON file by its kind, against its schema.
set +e
check=$(python3 "$repo/tests/validate_results.py" "$repo" --run "$run" 2>&1)
rc=$?
set -e
case $rc in
  0) ;;
  77) refuse "python3-jsonschema is not installed, so the run's JSON cannot be checked (apt-get install python3-jsonschema)" ;;
  *) refuse "the run's JSON does not pass its checks (tests/data/result_kinds.json names each kind's schema):"$'\n'"$(grep -v '^ok' <<< "$check")" ;;
esac
checked=$(grep -c '^ok   .* \(conforms to\|parses (\)' <<< "$check" || true)

if [[ -z $slug ]]; then
  slug=$(python3 - "$run/devices.json" << 'EOF'
import json, re, sys
d = json.load(open(sys.argv[1]))
dev = next((x for x in d.get("devices", []) if x.get("index") == d.get("default")), None)
if dev is None:
    sys.exit(f"devices.json names no default device")
print(re.sub(r"[^a-z0-9]+", "-", dev["name"].lower()).strip("-") or "device")
EOF
  ) || refuse "$run/devices.json: cannot tell the run's device (pass --slug NAME)"
fi

mkdir -p "$results"
results=$(cd "$results" && pwd)
dest=$results/$slug
if [[ -e $dest ]] && ! $replace; then
  refuse "$dest already exists: pass --replace to replace it, or --slug NAME to file the run beside it"
fi
if [[ -n $mismatch ]]; then
  printf 'Filed with --allow-other-commit: %s.\nImported %s at %s.\n' "$mismatch" "$(date -u +%FT%TZ)" "$head" > "$run/IMPORT.txt"
fi

# Into place: copied beside the destination, then renamed; a replaced folder is kept aside until
# the dashboard is drawn, and put back if it cannot be.
incoming=$results/.incoming-$slug.$$
old=$stage/replaced  # outside DIR, so the dashboard does not read it
cp -r "$run" "$incoming"
[[ ! -e $dest ]] || mv "$dest" "$old"
mv "$incoming" "$dest"
# From beside DIR, so the page names it by its own name (results), never by a path of this machine.
if ! (cd "$(dirname "$results")" && "$bench" dashboard "$(basename "$results")" --out "$(basename "$results")/dashboard" \
  --paper "$repo/results/paper/paper_tables.json") 2> "$stage/dashboard.err"; then
  rm -rf "$dest"
  [[ ! -e $old ]] || mv "$old" "$dest"
  refuse "vsgl-bench dashboard failed, so nothing was filed:"$'\n'"$(cat "$stage/dashboard.err")"
fi
rm -rf "$old"
echo "$me: filed $tarball as $dest ($(find "$dest" -type f | wc -l) files, $checked JSON files checked against their schema or kind; commit ${commit:-unknown})"
echo "$me: $(tail -1 "$stage/dashboard.err")"
[[ $results != "$repo/results" ]] || echo "$me: to keep it: git add results/$slug results/dashboard/index.html"
