#!/usr/bin/env python3
"""ci/release_notes.py on the committed results (ci/release.sh's RELEASE-NOTES.md).

  - every committed tableN.json under results/ has its section, naming the file, with each
    generator's median total and the paper's figure as the file has them;
  - every row of the README's claims table is in the notes, and each verdict cell of the notes is
    where the README's cell begins (the README may say more after it; tests/test_readme_claims.cpp
    checks the README against the same files), so the notes say what the results say;
  - without results it exits 1 and names the folder.
Usage: release_notes_check.py SOURCE_DIR
"""
import glob
import json
import os
import re
import subprocess
import sys
import tempfile

src = sys.argv[1]
script = os.path.join(src, "ci", "release_notes.py")
failures = []


def cells(line):
    return [c.strip() for c in line.strip().strip("|").split("|")]


run = subprocess.run([sys.executable, script, "--version", "9.8.7+gabc", "--commit", "abc123", "--source", src],
                     capture_output=True, text=True)
if run.returncode != 0:
    sys.exit(f"ci/release_notes.py exited {run.returncode}: {run.stderr}")
notes = run.stdout
if not notes.startswith("# vsgl-bench 9.8.7+gabc\n") or "`abc123`" not in notes:
    failures.append("the notes do not start with the version and name the commit")

sections = re.split(r"\n(?=### )", notes)
tables = sorted(glob.glob(os.path.join(src, "results", "**", "table[0-9].json"), recursive=True))
if not tables:
    failures.append("no committed tableN.json under results/")
for path in tables:
    rel = os.path.relpath(path, src)
    section = next((s for s in sections if s.startswith("### ") and f"(`{rel}`)" in s.split("\n", 1)[0]), None)
    if section is None:
        failures.append(f"no section for {rel}")
        continue
    with open(path, encoding="utf-8") as f:
        doc = json.load(f)
    rows = {cells(l)[0]: cells(l) for l in section.splitlines() if l.startswith("| ")}
    for gid, g in doc["generators"].items():
        row = rows.get(g.get("label", gid))
        total = g["total"]
        want = f"{total['median_ms']:.3f}"
        if row is None or row[1] != want:
            failures.append(f"{rel}: {gid}: the notes say {row}, the file's median total is {want}")
        elif total.get("paper_ms") is not None and row[2] != f"{total['paper_ms']:.3f}":
            failures.append(f"{rel}: {gid}: paper {row[2]}, the file says {total['paper_ms']:.3f}")

with open(os.path.join(src, "README.md"), encoding="utf-8") as f:
    readme = f.read()
block = re.search(r"<!-- claims:begin -->(.*?)<!-- claims:end -->", readme, re.S).group(1)
readme_rows = {cells(l)[0]: cells(l) for l in block.splitlines() if re.match(r"\|\s*`", l)}
notes_rows = {cells(l)[0]: cells(l) for l in notes.splitlines() if re.match(r"\|\s*`", l)}
if not readme_rows:
    failures.append("the README's claims table has no rows")
for key, row in readme_rows.items():
    mine = notes_rows.get(key)
    if mine is None:
        failures.append(f"claim {key}: not in the notes")
        continue
    for column in range(2, len(row)):
        if not row[column].startswith(mine[column]) or not mine[column]:
            failures.append(f"claim {key}, column {column}: notes '{mine[column]}', README '{row[column]}'")

with tempfile.TemporaryDirectory() as empty:
    run = subprocess.run([sys.executable, script, "--version", "1", "--commit", "c", "--source", empty],
                         capture_output=True, text=True)
    if run.returncode != 1 or "results" not in run.stderr:
        failures.append(f"without results: exit {run.returncode}, '{run.stderr.strip()}' (expected 1, naming results)")

for f in failures:
    print("FAILED:", f)
if failures:
    sys.exit(1)
print(f"release notes: {len(tables)} tables and {len(readme_rows)} claims as the committed results have them")
