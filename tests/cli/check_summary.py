#!/usr/bin/python3
"""Validates a run folder's summary.json against docs/summary.schema.json.

Usage: check_summary.py SUMMARY_JSON [--schema SCHEMA] [--method NAME] [--status STATUS]

Exit code 0 when the file is valid JSON (no NaN/Infinity tokens) that the schema accepts (and,
when given, has that method and status); 1 with one line per problem otherwise. The validator is
this file's own small subset of JSON Schema 2020-12 (type, enum, const, required, properties,
additionalProperties, items, minimum, minLength, pattern), so no package is needed; a schema
keyword outside that subset is reported rather than ignored.
"""
import argparse
import json
import pathlib
import re
import sys

ANNOTATIONS = {"$schema", "$id", "title", "description"}
KEYWORDS = {"type", "enum", "const", "required", "properties", "additionalProperties", "items",
            "minimum", "minLength", "pattern"} | ANNOTATIONS


def json_type_matches(value, name):
    if name == "null":
        return value is None
    if name == "boolean":
        return isinstance(value, bool)
    if name == "integer":  # 2020-12: a number with zero fractional part
        return (isinstance(value, int) and not isinstance(value, bool)) or (
            isinstance(value, float) and value.is_integer())
    if name == "number":
        return isinstance(value, (int, float)) and not isinstance(value, bool)
    if name == "string":
        return isinstance(value, str)
    if name == "array":
        return isinstance(value, list)
    if name == "object":
        return isinstance(value, dict)
    raise ValueError(f"unknown type '{name}' in the schema")


def same_json(a, b):
    """JSON equality: booleans are not numbers."""
    return type(a) is type(b) and a == b if isinstance(a, bool) or isinstance(b, bool) else a == b


def validate(value, schema, where, errors):
    unknown = set(schema) - KEYWORDS
    if unknown:
        errors.append(f"{where}: the schema uses keywords this validator lacks: {sorted(unknown)}")
        return
    if "type" in schema:
        names = schema["type"] if isinstance(schema["type"], list) else [schema["type"]]
        if not any(json_type_matches(value, n) for n in names):
            errors.append(f"{where}: expected {' or '.join(names)}, got {json.dumps(value)[:60]}")
            return
    if "const" in schema and not same_json(value, schema["const"]):
        errors.append(f"{where}: expected {json.dumps(schema['const'])}, got {json.dumps(value)[:60]}")
    if "enum" in schema and not any(same_json(value, e) for e in schema["enum"]):
        errors.append(f"{where}: expected one of {json.dumps(schema['enum'])}, got {json.dumps(value)[:60]}")
    if "minimum" in schema and json_type_matches(value, "number") and value < schema["minimum"]:
        errors.append(f"{where}: expected a number >= {schema['minimum']}, got {value}")
    if isinstance(value, str):
        if len(value) < schema.get("minLength", 0):
            errors.append(f"{where}: expected at least {schema['minLength']} characters")
        if "pattern" in schema and not re.search(schema["pattern"], value):
            errors.append(f"{where}: '{value[:60]}' does not match {schema['pattern']}")
    if isinstance(value, dict):
        for key in schema.get("required", []):
            if key not in value:
                errors.append(f"{where}: missing required key '{key}'")
        properties = schema.get("properties", {})
        extra = schema.get("additionalProperties", True)
        for key, member in value.items():
            if key in properties:
                validate(member, properties[key], f"{where}.{key}", errors)
            elif extra is False:
                errors.append(f"{where}: unknown key '{key}'")
            elif isinstance(extra, dict):
                validate(member, extra, f"{where}.{key}", errors)
    if isinstance(value, list) and "items" in schema:
        for i, item in enumerate(value):
            validate(item, schema["items"], f"{where}[{i}]", errors)


def reject_constant(name):
    raise ValueError(f"{name} is not JSON (non-finite numbers must be written as null)")


def check(path, schema, method=None, status=None):
    """The list of problems of the summary file at `path` (empty when it is valid)."""
    try:
        text = pathlib.Path(path).read_text(encoding="utf-8")
        summary = json.loads(text, parse_constant=reject_constant)
    except (OSError, UnicodeDecodeError, ValueError) as e:
        return [f"{path}: cannot read it as JSON: {e}"]
    errors = []
    validate(summary, schema, "$", errors)
    if method is not None and isinstance(summary, dict) and summary.get("method") != method:
        errors.append(f"$.method: expected '{method}', got {json.dumps(summary.get('method'))}")
    if status is not None and isinstance(summary, dict) and summary.get("status") != status:
        errors.append(f"$.status: expected '{status}', got {json.dumps(summary.get('status'))}")
    return [f"{path}: {e}" if not e.startswith(str(path)) else e for e in errors]


def main():
    default_schema = pathlib.Path(__file__).resolve().parents[2] / "docs" / "summary.schema.json"
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("summary", help="summary.json of a run folder")
    parser.add_argument("--schema", default=str(default_schema), help="the JSON schema (default: %(default)s)")
    parser.add_argument("--method", help="the method the summary must name")
    parser.add_argument("--status", help="the status the summary must have")
    args = parser.parse_args()
    schema = json.loads(pathlib.Path(args.schema).read_text(encoding="utf-8"))
    errors = check(args.summary, schema, args.method, args.status)
    for e in errors:
        print(e)
    if not errors:
        print(f"{args.summary}: valid summary.json")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
