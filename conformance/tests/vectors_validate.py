#!/usr/bin/env python3
"""Validates files against spec/vectors.schema.json or spec/results.schema.json (python3-jsonschema).

    vectors_validate.py SCHEMA FILE...     exit 0 if every file is valid, 1 otherwise, 77 without jsonschema
"""
import json
import sys

try:
    import jsonschema
except ImportError:
    print("python3-jsonschema is not installed")
    sys.exit(77)


def main(argv):
    with open(argv[0]) as f:
        schema = json.load(f)
    validator = jsonschema.Draft7Validator(schema)
    bad = 0
    for path in argv[1:]:
        with open(path) as f:
            doc = json.load(f)
        errors = sorted(validator.iter_errors(doc), key=lambda e: list(e.absolute_path))
        for e in errors[:5]:
            print("%s: /%s: %s" % (path, "/".join(str(p) for p in e.absolute_path), e.message[:300]))
        bad += bool(errors)
    print("%d of %d files valid" % (len(argv) - 1 - bad, len(argv) - 1))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
