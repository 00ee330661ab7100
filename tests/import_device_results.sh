#!/usr/bin/env bash
# ci/import-device-results.sh end to end on a small run made here (vsgl-bench devices --json, a
# --quick Table 1 on a tiny atrium capture, one suite's gtest JSON, build.env at this checkout's
# commit), filed into scratch results folders, never the checkout's results/: the run lands under
# its device's slug with its layout and the dashboard shows it; a second import of the same device,
# a build of another commit, a table that breaks its schema, a JSON file of no kind and a tarball
# without build.env are refused, leaving nothing behind; --allow-other-commit, --slug and an xz
# tarball are taken. Exit 77 (skipped, saying why) outside a git checkout or without
# python3-jsonschema.
# Usage: import_device_results.sh SOURCE_DIR VSGL_BENCH VSGL_TESTS
set -euo pipefail
src=$1
export VSGL_BENCH=$2
tests=$3
import=$src/ci/import-device-results.sh
head=$(git -C "$src" rev-parse HEAD 2>/dev/null) || { echo "SKIPPED: $src is not a git checkout, so the commit check has nothing to compare"; exit 77; }
python3 -c 'import jsonschema' 2>/dev/null || { echo "SKIPPED: python3-jsonschema is not installed (the import checks the JSON with it)"; exit 77; }
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# The run, as ci/device-run.sh lays it out.
run=$scratch/run
mkdir -p "$run/texture" "$run/tests"
"$VSGL_BENCH" devices --json > "$run/devices.json"
"$VSGL_BENCH" record --scene atrium --gbuffer 96x64 --rsm 32 --out "$scratch/cap" > "$scratch/record.txt" 2>&1 ||
  { cat "$scratch/record.txt"; exit 1; }
"$VSGL_BENCH" tables --capture "$scratch/cap" --out "$run/texture" --quick --generators fis_tok15,fis_modified \
  --camera-vsgls 48 --light-vsgls 24 --no-progress > "$run/tables_texture.txt" 2>&1 || { cat "$run/tables_texture.txt"; exit 1; }
[[ -f $run/texture/table1.json ]] || { echo "tables wrote no table1.json:"; ls "$run/texture"; exit 1; }
"$tests" --gtest_filter=Layering.FlagsUpwardSidewaysDetailAndTestingIncludes \
  --gtest_output="json:$run/tests/Layering.json" > "$run/tests/Layering.txt" 2>&1
printf 'source_dir=%s\nbuild_dir=%s\ncommit=%s\ndirty=false\n' "$src" "$(dirname "$(dirname "$tests")")" "$head" > "$run/build.env"
echo "== a run made by tests/import_device_results.sh" > "$run/run.log"
tar czf "$scratch/run.tar.gz" -C "$run" .
slug=$(python3 -c '
import json, sys
d = json.load(open(sys.argv[1]))
print(next(x["name"] for x in d["devices"] if x["index"] == d["default"]))' "$run/devices.json" |
  tr 'A-Z' 'a-z' | sed 's/[^a-z0-9]\{1,\}/-/g; s/^-//; s/-$//')
echo "device slug: $slug"

# expect NAME CODE TEXT COMMAND...: COMMAND exits CODE and says TEXT.
expect() {
  local name=$1 code=$2 text=$3 rc=0
  shift 3
  "$@" > "$scratch/out.txt" 2>&1 || rc=$?
  if ((rc != code)); then fail "$name: exit $rc, expected $code:"; cat "$scratch/out.txt"; return; fi
  grep -qF -- "$text" "$scratch/out.txt" || { fail "$name: does not say '$text':"; cat "$scratch/out.txt"; return; }
  echo "ok   $name"
}

# Filed under the slug, with its layout, and on the dashboard.
res=$scratch/results
expect "import" 0 "filed $scratch/run.tar.gz as $res/$slug" bash "$import" "$scratch/run.tar.gz" --results "$res"
for f in devices.json texture/table1.json texture/table1.md tests/Layering.json build.env run.log tables_texture.txt; do
  [[ -f $res/$slug/$f ]] || fail "import: $slug/$f was not placed"
done
[[ ! -e $res/$slug/IMPORT.txt ]] || fail "import: IMPORT.txt written for a run of this commit"
[[ -f $res/dashboard/index.html ]] || fail "import: no dashboard"
grep -qF "$slug/texture/table1.json" "$res/dashboard/index.html" 2>/dev/null || fail "import: the dashboard does not show $slug/texture/table1.json"
[[ -z $(find "$res" -name '.incoming-*') ]] || fail "import: left its incoming folder"
! grep -qF "$scratch" "$res/dashboard/index.html" || fail "import: the dashboard names a path of this machine ($scratch)"
expect "a second run of the device" 1 "already exists" bash "$import" "$scratch/run.tar.gz" --results "$res"
expect "--replace" 0 "filed" bash "$import" "$scratch/run.tar.gz" --results "$res" --replace
expect "--slug" 0 "as $res/beside" bash "$import" "$scratch/run.tar.gz" --results "$res" --slug beside

# Another commit's build: refused, then filed with the override and noted.
other=$scratch/other
cp -r "$run" "$other"
sed -i 's/^commit=.*/commit=0123456789abcdef0123456789abcdef01234567/' "$other/build.env"
tar czf "$scratch/other.tar.gz" -C "$other" .
expect "another commit" 1 "built from commit 0123456789abcdef0123456789abcdef01234567, this checkout is at $head" \
  bash "$import" "$scratch/other.tar.gz" --results "$scratch/r2"
[[ ! -e $scratch/r2/$slug ]] || fail "another commit: filed anyway"
sed -i 's/^commit=.*/commit='"$head"'/; s/^dirty=.*/dirty=true/' "$other/build.env"
tar czf "$scratch/dirty.tar.gz" -C "$other" .
expect "a dirty build" 1 "uncommitted changes" bash "$import" "$scratch/dirty.tar.gz" --results "$scratch/r2"
expect "--allow-other-commit" 0 "filed" bash "$import" "$scratch/dirty.tar.gz" --results "$scratch/r2" --allow-other-commit
grep -q 'dirty=true' "$scratch/r2/$slug/IMPORT.txt" 2>/dev/null || fail "--allow-other-commit: IMPORT.txt does not say why"

# JSON that breaks its schema, or of no kind: refused, naming the file.
broken=$scratch/broken
cp -r "$run" "$broken"
python3 -c '
import json, sys
d = json.load(open(sys.argv[1])); del d["scene"]; json.dump(d, open(sys.argv[1], "w"))' "$broken/texture/table1.json"
tar czf "$scratch/broken.tar.gz" -C "$broken" .
expect "a table against its schema" 1 "texture/table1.json" bash "$import" "$scratch/broken.tar.gz" --results "$scratch/r3"
cp -r "$run" "$scratch/unknown"
echo '{}' > "$scratch/unknown/notes.json"
tar czf "$scratch/unknown.tar.gz" -C "$scratch/unknown" .
expect "a JSON file of no kind" 1 "notes.json: of no kind" bash "$import" "$scratch/unknown.tar.gz" --results "$scratch/r3"
[[ ! -e $scratch/r3 ]] || [[ -z $(ls -A "$scratch/r3") ]] || fail "refused runs left files in $scratch/r3: $(ls -A "$scratch/r3")"

# A tarball without build.env; an xz one (device-run.sh's fallback).
tar czf "$scratch/bare.tar.gz" -C "$run" devices.json
expect "no build.env" 1 "holds no build.env" bash "$import" "$scratch/bare.tar.gz" --results "$scratch/r4"
tar cf - -C "$run" . | xz -1 > "$scratch/run.tar.xz"
expect "an xz tarball" 0 "filed" bash "$import" "$scratch/run.tar.xz" --results "$scratch/r4"

echo "$failures failure(s)"
((failures == 0))
