#!/usr/bin/env python3
"""Checks docs/openapi.json against what the API tests sent and got
(ctest serve.openapi; issue 47, item 6).

  openapi_check.py OPENAPI RECORDS

RECORDS is the JSON-lines file tests/serve/serve_client.mjs writes under
NCK_API_RECORD. Every answer of a documented path must be one of its
documented statuses with a body of the documented schema; every command
the server accepted must match the Command schema; every documented path
but the stream must have been exercised. Exit 1 on any difference.
"""
import json
import re
import sys
from urllib.parse import urlsplit

import jsonschema


def resolver_for(spec):
    return jsonschema.RefResolver.from_schema(spec)


def validate(instance, schema, spec):
    jsonschema.Draft202012Validator(schema, resolver=resolver_for(spec)).validate(instance)


def answer_schema(spec, responses, status):
    r = responses.get(str(status))
    if r is None:
        return None
    if "$ref" in r:
        r = spec["components"]["responses"][r["$ref"].rsplit("/", 1)[1]]
    return r.get("content", {}).get("application/json", {}).get("schema")


def documented_path(spec, path):
    """The documented path `path` is, templates too (/api/v1/tools/{n} for /api/v1/tools/1)."""
    if path in spec["paths"]:
        return path
    for p in spec["paths"]:
        if "{" in p and re.fullmatch(re.sub(r"\\{[^}]+\\}", "[^/]+", re.escape(p)), path):
            return p
    return path


def main():
    spec = json.load(open(sys.argv[1]))
    jsonschema.Draft202012Validator.check_schema(spec["components"]["schemas"]["Command"])
    problems, seen, checked = [], set(), 0
    for line in open(sys.argv[2]):
        rec = json.loads(line)
        path = documented_path(spec, urlsplit(rec["target"]).path)
        item = spec["paths"].get(path, {}).get(rec["method"].lower())
        if item is None:
            continue  # the page, unknown paths (404 tests)
        seen.add(path)
        if rec["status"] not in (200,) and str(rec["status"]) not in item["responses"]:
            problems.append(f"{rec['method']} {path}: status {rec['status']} is not documented")
            continue
        schema = answer_schema(spec, item["responses"], rec["status"])
        if schema is not None and rec["answer"] is not None and "json" in rec["type"]:
            try:
                validate(json.loads(rec["answer"]), schema, spec)
                checked += 1
            except (jsonschema.ValidationError, json.JSONDecodeError) as e:
                problems.append(f"{rec['method']} {rec['target'][:80]} -> {rec['status']}: {getattr(e, 'json_path', '')} {str(e).splitlines()[0]}")
        if path == "/api/v1/command" and rec["status"] == 200:
            try:
                validate(json.loads(rec["request"]), {"$ref": "#/components/schemas/Command"}, spec)
                checked += 1
            except (jsonschema.ValidationError, json.JSONDecodeError) as e:
                problems.append(f"accepted command {rec['request'][:80]} does not match Command: {str(e).splitlines()[0]}")
    unseen = sorted(set(spec["paths"]) - seen - {"/api/v1/stream"})
    if unseen:
        problems.append(f"documented but never exercised: {unseen}")
    for p in problems[:30]:
        print("FAIL", p)
    print(f"{checked} answers and commands checked against {sys.argv[1]}; {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
