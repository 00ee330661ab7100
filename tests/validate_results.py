#!/usr/bin/env python3
"""Validates the committed results with Debian's python3-jsonschema, a second validator beside
harness/core/json_schema_subset (tests/test_json_schema_subset.cpp runs the same files through
it). Each schema in results/schema/ is checked against the meta-schema its $schema names; every
results/**/tableN.json against the table schema of its version (table.schema.json, or a frozen\nolder one such as table.v2.schema.json); and every deliberately broken
table of tests/data/table_schema_mutations.json must be rejected, as the subset validator
rejects it.

Usage: validate_results.py SOURCE_DIR. Exit 0: all conform; 1: a failure; 77: python3-jsonschema
is not installed (the test is then reported as skipped).
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


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    try:
        import jsonschema
    except ImportError:
        print("SKIPPED: python3-jsonschema is not installed (apt-get install python3-jsonschema)")
        return SKIP
    root = pathlib.Path(sys.argv[1])
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

    # Each table schema (the current one and the frozen older versions) by its schema_version.
    by_version = {v.schema["properties"]["schema_version"]["const"]: name
                  for name, v in schemas.items() if name.startswith("table.")}
    tables = sorted(p for p in (root / "results").rglob("*.json") if re.fullmatch(r"table\d+\.json", p.name))
    if not tables:
        print("FAIL no results/**/tableN.json found")
        return 1
    for path in tables:
        doc = json.loads(path.read_text())
        name = by_version.get(doc.get("schema_version"))
        if name is None:
            # Tables of a version without a committed schema (the C++ test lists each, with the reason).
            print(f"skip {path.relative_to(root)}: schema_version {doc.get('schema_version')} has no schema")
            continue
        errors = list(schemas[name].iter_errors(doc))
        for e in errors:
            print(f"FAIL {path.relative_to(root)}: /{'/'.join(map(str, e.absolute_path))}: {e.message}")
        failures += bool(errors)
        if not errors:
            print(f"ok   {path.relative_to(root)} conforms to {name}")

    spec = json.loads((root / "tests/data/table_schema_mutations.json").read_text())
    base = json.loads((root / spec["base"]).read_text())
    validator = schemas[pathlib.Path(spec["schema"]).name]
    for mutation in spec["mutations"]:
        if validator.is_valid(apply_mutation(base, mutation)):
            print(f"FAIL accepted a table with {mutation['what']}")
            failures += 1
        else:
            print(f"ok   rejected a table with {mutation['what']}")

    print(f"{failures} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
