#!/usr/bin/env python3
"""Validates results with Debian's python3-jsonschema, a second validator beside
harness/core/json_schema_subset (tests/test_json_schema_subset.cpp runs the same files through
it). Each schema in results/schema/ is checked against the meta-schema its $schema names; every
JSON file under results/ by its kind (tests/data/result_kinds.json): a table against the table
schema of its version (table.schema.json, or a frozen older one such as table.v2.schema.json), a
sweep against sweep.schema.json, a quality report against quality.schema.json, a kind without a
schema only parsed; and every deliberately broken table and quality report of
tests/data/{table,quality}_schema_mutations.json must be rejected, as the subset validator
rejects it.

Usage: validate_results.py SOURCE_DIR            the committed results
       validate_results.py SOURCE_DIR --run DIR  the JSON files of one run's folder, by the same
                                                 kinds (ci/import-device-results.sh, before filing it)
Exit 0: all conform; 1: a failure (a file of no kind, one that does not parse or does not conform);
2: bad usage; 77: python3-jsonschema is not installed (the test is then reported as skipped).
"""
import copy
import json
import pathlib
import re
import sys

SKIP = 77


def pointer_tokens(pointer):
    return [t.replace("~1", "/").replace("~0", "~") for t in pointer.split("/")[1:]]


def apply_mutation(doc, mutation):
    """The document with one member set or removed (the `set`/`remove` JSON pointer)."""
    out = copy.deepcopy(doc)
    tokens = pointer_tokens(mutation["set"] if "set" in mutation else mutation["remove"])
    parent = out
    for t in tokens[:-1]:
        parent = parent[int(t)] if isinstance(parent, list) else parent[t]
    if "set" in mutation:
        parent[tokens[-1]] = mutation["value"]
    else:
        del parent[tokens[-1]]
    return out


def load_kinds(root):
    spec = json.loads((root / "tests/data/result_kinds.json").read_text())
    kinds = [(k["kind"], re.compile("(^|/)(" + k["path"] + ")$"), k.get("schema", ""), k.get("none", ""))
             for k in spec["kinds"]]
    return kinds, spec["exceptions"]


def check_files(root, base, shown_prefix, schemas, kinds, exceptions):
    """Each JSON file under `base` by its kind; the number of failures. `shown_prefix` + the path
    relative to `base` is how a file is named and matched (results/... for the committed ones)."""
    failures = 0
    by_version = {v.schema["properties"]["schema_version"]["const"]: name
                  for name, v in schemas.items() if name.startswith("table.")}
    for path in sorted(base.rglob("*.json")):
        rel = shown_prefix + path.relative_to(base).as_posix()
        if rel.startswith("results/schema/"):
            continue
        try:
            doc = json.loads(path.read_text())
        except (ValueError, UnicodeDecodeError) as e:
            print(f"FAIL {rel}: not JSON: {e}")
            failures += 1
            continue
        if rel in exceptions:
            print(f"skip {rel}: {exceptions[rel]}")
            continue
        kind = next((k for k in kinds if k[1].search(rel)), None)
        if kind is None:
            print(f"FAIL {rel}: of no kind: add its kind to tests/data/result_kinds.json")
            failures += 1
            continue
        name, _, schema, none = kind
        if not schema:
            print(f"ok   {rel} parses ({name}: {none})")
            continue
        if schema == "by schema_version":
            schema = by_version.get(doc.get("schema_version") if isinstance(doc, dict) else None)
            if schema is None:
                print(f"FAIL {rel}: a {name} of schema_version {doc.get('schema_version')}, which has no committed schema")
                failures += 1
                continue
        if schema not in schemas:
            print(f"FAIL {rel}: its schema results/schema/{schema} is missing or invalid")
            failures += 1
            continue
        errors = list(schemas[schema].iter_errors(doc))
        for e in errors:
            print(f"FAIL {rel}: /{'/'.join(map(str, e.absolute_path))}: {e.message}")
        failures += bool(errors)
        if not errors:
            print(f"ok   {rel} conforms to {schema}")
    return failures


def main():
    args = sys.argv[1:]
    run_dir = None
    if len(args) == 3 and args[1] == "--run":
        run_dir = pathlib.Path(args[2])
    elif len(args) != 1:
        print(__doc__, file=sys.stderr)
        return 2
    try:
        import jsonschema
    except ImportError:
        print("SKIPPED: python3-jsonschema is not installed (apt-get install python3-jsonschema)")
        return SKIP
    root = pathlib.Path(args[0])
    failures = 0

    schemas = {}
    for path in sorted((root / "results/schema").glob("*.json")):
        schema = json.loads(path.read_text())
        cls = jsonschema.validators.validator_for(schema)
        try:
            cls.check_schema(schema)
        except jsonschema.exceptions.SchemaError as e:
            print(f"FAIL {path.relative_to(root)}: not a valid {cls.__name__} schema: {e.message}")
            failures += 1
            continue
        schemas[path.name] = cls(schema)
        print(f"ok   {path.relative_to(root)} is a valid {cls.__name__} schema")
    if "table.schema.json" not in schemas:
        print("FAIL results/schema/table.schema.json is missing or invalid")
        return 1
    kinds, exceptions = load_kinds(root)

    if run_dir is not None:
        if not run_dir.is_dir():
            print(f"FAIL {run_dir}: not a directory")
            return 1
        failures += check_files(root, run_dir, "", schemas, kinds, {})
        print(f"{failures} failure(s)")
        return 1 if failures else 0

    if not any(re.fullmatch(r"table\d+\.json", p.name) for p in (root / "results").rglob("*.json")):
        print("FAIL no results/**/tableN.json found")
        return 1
    failures += check_files(root, root / "results", "results/", schemas, kinds, exceptions)

    mutation_specs = (("table", "table_schema_mutations.json"), ("quality report", "quality_schema_mutations.json"))
    for kind, spec_file in mutation_specs:
        spec = json.loads((root / "tests/data" / spec_file).read_text())
        base = json.loads((root / spec["base"]).read_text())
        validator = schemas[pathlib.Path(spec["schema"]).name]
        for mutation in spec["mutations"]:
            if validator.is_valid(apply_mutation(base, mutation)):
                print(f"FAIL accepted a {kind} with {mutation['what']}")
                failures += 1
            else:
                print(f"ok   rejected a {kind} with {mutation['what']}")

    print(f"{failures} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
