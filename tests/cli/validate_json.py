#!/usr/bin/env python3
"""validate_json.py SCHEMA.json FILE.json: checks a JSON output of tessera against its schema
(doc/schemas/*.schema.json). Prints "valid: FILE" and exits 0 when FILE validates; prints the first
error (its path in FILE and the message) and exits 1 otherwise, and also when an argument is
missing or a file cannot be read. Needs the Python module jsonschema (Debian: python3-jsonschema)."""
import json
import sys


def fail(message):
    print("validate_json.py: " + message, file=sys.stderr)
    sys.exit(1)


def read_json(path, what):
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except OSError as e:
        fail("cannot read %s %s (%s)" % (what, path, e.strerror or e))
    except ValueError as e:
        fail("%s %s is not valid JSON (%s)" % (what, path, e))


def location(error):
    """The error's place in the instance as a JSON Pointer ("/polygons/0/word"), "/" for the root."""
    parts = [str(p).replace("~", "~0").replace("/", "~1") for p in error.absolute_path]
    return "/" + "/".join(parts)


def validator(cls, schema, schema_path):
    """A validator of `schema` whose "$ref"s to a file name ("check-report.schema.json") resolve to
    the schemas beside it."""
    import os
    folder = os.path.dirname(os.path.abspath(schema_path))
    beside = {}
    for name in os.listdir(folder):
        if name.endswith(".schema.json"):
            beside[name] = read_json(os.path.join(folder, name), "schema")
    try:
        from referencing import Registry, Resource
        from referencing.jsonschema import DRAFT202012
    except ImportError:  # jsonschema before 4.18
        import jsonschema
        resolver = jsonschema.RefResolver(base_uri="", referrer=schema, store=beside)
        return cls(schema, resolver=resolver)
    registry = Registry().with_resources(
        (name, Resource.from_contents(s, default_specification=DRAFT202012))
        for name, s in beside.items())
    return cls(schema, registry=registry)


def main(argv):
    if len(argv) != 3:
        fail("usage: validate_json.py SCHEMA.json FILE.json")
    try:
        import jsonschema
        from jsonschema import validators
    except ImportError:
        fail("the Python module 'jsonschema' is missing: install python3-jsonschema (Debian) "
             "or run 'pip install jsonschema'")
    default = getattr(jsonschema, "Draft202012Validator", None)
    if default is None:
        fail("jsonschema %s has no Draft 2020-12 validator: version 4.0 or later is needed"
             % getattr(jsonschema, "__version__", "(unknown version)"))
    schema_path, instance_path = argv[1], argv[2]
    schema = read_json(schema_path, "schema")
    instance = read_json(instance_path, "file")
    # The validator of the draft the schema names in "$schema" (2020-12 for Tessera's schemas).
    cls = validators.validator_for(schema, default=default)
    try:
        cls.check_schema(schema)
    except jsonschema.exceptions.SchemaError as e:
        fail("%s is not a valid schema: %s" % (schema_path, e.message))
    errors = sorted(validator(cls, schema, schema_path).iter_errors(instance),
                    key=lambda e: ([str(p) for p in e.absolute_path], e.message))
    if not errors:
        print("valid: " + instance_path)
        return 0
    first = errors[0]
    more = " (and %d more)" % (len(errors) - 1) if len(errors) > 1 else ""
    print("invalid: %s: at %s: %s%s" % (instance_path, location(first), first.message, more),
          file=sys.stderr)
    return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv))
