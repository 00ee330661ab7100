#!/usr/bin/env python3
"""Release notes drawn from the committed results (ci/release.sh writes them into dist/).

Every figure and verdict is read from the JSON under results/, none is typed here:
  - the headline figures: each tableN.json's median total time per generator beside the paper's,
    and the k-means / modified FIS ratio;
  - the paper's claims: each row of the README's claims table (between <!-- claims:begin --> and
    <!-- claims:end -->) with its verdicts read from the files the row cites, as
    tests/test_readme_claims.cpp reads them: tableN.json `claims` (T1, T2), quality/<scene>/
    quality.json `claims` ("quality: MEASURE") and sweep/pdf-sharpness_<scene>/sweep.json
    ("sweep: ID").
Usage: python3 ci/release_notes.py --version V --commit C [--source DIR]   (markdown on stdout)
Exit 1, naming the file, when a result the notes need is missing or unreadable.
"""
import argparse
import json
import pathlib
import re
import sys

# The columns of the README's claims table: the committed lavapipe results on the paper's scenes
# and on the procedural stand-ins, and the scenes of each (as tests/test_readme_claims.cpp has them).
# The third member says whether the column's scenes are Tables 1 and 2 (Sibenik, the paper's Fig. 5
# lower-row scene, is no table's).
CLAIM_COLUMNS = [
    ("paper scenes", "results/lavapipe", ["sponza", "conference-room"], True),
    ("Sibenik", "results/lavapipe", ["sibenik"], False),
    ("stand-ins", "results/lavapipe/stand-ins", ["atrium", "conference"], True),
]


class NotesError(Exception):
    pass


def load(path):
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except OSError as e:
        raise NotesError(f"{path}: cannot read it ({e.strerror})")
    except json.JSONDecodeError as e:
        raise NotesError(f"{path}: not JSON ({e})")


def verdict_of(holds):
    return "inconclusive" if holds is None else "holds" if holds else "does not hold"


def scene_text(doc):
    scene = doc.get("scene")
    if isinstance(scene, dict):
        return f"{scene.get('name', '?')} ({scene.get('kind', '?')})"
    if isinstance(scene, str):
        return scene
    return "scene not named (schema 1)"


def headline(source, table_file):
    doc = load(table_file)
    rel = table_file.relative_to(source)
    try:
        gens = doc["generators"]
        device = doc["device"]["name"]
        rows = []
        modified = gens["fis_modified"]["total"]["median_ms"]
        for gid, g in gens.items():
            total = g["total"]
            paper = total.get("paper_ms")
            rows.append(
                f"| {g.get('label', gid)} | {total['median_ms']:.3f} | "
                f"{'' if paper is None else f'{paper:.3f}'} | {total['median_ms'] / modified:.2f} |"
            )
    except (KeyError, TypeError, ZeroDivisionError) as e:
        raise NotesError(f"{rel}: no median total of the generators ({e!r})")
    lines = [
        f"### Table {doc.get('table', '?')}, {scene_text(doc)}, on {device} (`{rel}`)",
        "",
        f"Median total per run (ms), {doc.get('timing', {}).get('repetitions', '?')} repetitions; "
        f"paper: {doc.get('paper', {}).get('gpu', '?')}.",
        "",
        "| generator | median total (ms) | paper (ms) | × modified FIS |",
        "| --- | ---: | ---: | ---: |",
        *rows,
        "",
    ]
    return lines


def table_verdict(source, column_dir, table, claim_id):
    path = source / column_dir / f"table{table}.json"
    for c in load(path).get("claims", []):
        if c.get("id") == claim_id:
            return verdict_of(c.get("holds"))
    raise NotesError(f"{path.relative_to(source)}: no claim {claim_id}")


def quality_verdict(source, column_dir, scene, measure):
    path = source / column_dir / "quality" / scene / "quality.json"
    doc = load(path)
    found = [c for c in doc.get("claims", []) if str(c.get("measure", "")).startswith(measure)]
    # Fig. 7 is measured only with visibility (DESIGN.md 11a.2), as tests/test_readme_claims.cpp reads it.
    if not found and measure.startswith("Fig. 7 ") and doc.get("config", {}).get("visibility", "none") == "none":
        return "not measured (--visibility none)"
    if len(found) != 1:
        raise NotesError(f"{path.relative_to(source)}: {len(found)} claims whose measure starts with '{measure}'")
    return found[0]["verdict"]


def sweep_verdict(path, source, claim_id):
    for c in load(path).get("claims", []):
        if c.get("id") == claim_id:
            return verdict_of(c.get("holds"))
    raise NotesError(f"{path.relative_to(source)}: no claim {claim_id}")


def claim_rows(source):
    readme = source / "README.md"
    try:
        text = readme.read_text(encoding="utf-8")
    except OSError as e:
        raise NotesError(f"{readme}: cannot read it ({e.strerror})")
    m = re.search(r"<!-- claims:begin -->(.*?)<!-- claims:end -->", text, re.S)
    if not m:
        raise NotesError("README.md: no claims table (<!-- claims:begin --> ... <!-- claims:end -->)")
    rows = []
    for line in m.group(1).splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        key = re.fullmatch(r"`([^`]+)`", cells[0]) if len(cells) == 2 + len(CLAIM_COLUMNS) else None
        if not key:
            continue
        key, says = key.group(1), cells[1]
        verdicts = []
        for _, column_dir, scenes, tables in CLAIM_COLUMNS:
            if key.startswith("sweep: "):
                parts = []
                for scene in scenes:
                    path = source / column_dir / "sweep" / f"pdf-sharpness_{scene}" / "sweep.json"
                    if path.exists():
                        parts.append(f"{scene} {sweep_verdict(path, source, key[7:])}")
                verdicts.append(", ".join(parts) or "not run")
            elif key.startswith("quality: "):
                verdicts.append(
                    ", ".join(f"{s} {quality_verdict(source, column_dir, s, key[9:])}" for s in scenes)
                )
            elif not tables:
                verdicts.append("not a table scene")
            else:
                verdicts.append(
                    f"T1 {table_verdict(source, column_dir, 1, key)}, T2 {table_verdict(source, column_dir, 2, key)}"
                )
        rows.append(f"| `{key}` | {says} | {' | '.join(verdicts)} |")
    if not rows:
        raise NotesError("README.md: the claims table has no row with a claim key")
    return rows


def notes(source, version, commit):
    tables = sorted(p for p in (source / "results").rglob("table[0-9].json"))
    if not tables:
        raise NotesError(f"{source / 'results'}: no tableN.json")
    out = [
        f"# vsgl-bench {version}",
        "",
        f"Built from commit `{commit}`. Licensed under the Apache License, Version 2.0 (LICENSE, NOTICE).",
        "",
        "Artefacts: the Debian package (`.deb`), the Linux `.tar.gz` and the Windows `.zip`; their",
        "SHA-256 sums are in `SHA256SUMS` (`sha256sum -c SHA256SUMS`). Installing: docs/install.md.",
        "",
        "## Headline figures",
        "",
        "From the committed results under `results/` (each file's device, scene and run are in it;",
        "results/README.md says how each was made). lavapipe and SwiftShader are CPU drivers: their",
        "times say how the generators compare there, not on a GPU.",
        "",
    ]
    for t in tables:
        out += headline(source, t)
    out += [
        "## The paper's claims",
        "",
        "The README's claims table, each verdict read from the committed lavapipe results it cites.",
        "",
        "| claim | the paper says | " + " | ".join(name for name, _, _, _ in CLAIM_COLUMNS) + " |",
        "|---|---|" + "---|" * len(CLAIM_COLUMNS),
        *claim_rows(source),
        "",
    ]
    return "\n".join(out)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--version", required=True)
    parser.add_argument("--commit", required=True)
    parser.add_argument("--source", default=str(pathlib.Path(__file__).resolve().parent.parent))
    args = parser.parse_args()
    try:
        sys.stdout.write(notes(pathlib.Path(args.source), args.version, args.commit))
    except NotesError as e:
        print(f"ci/release_notes.py: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
