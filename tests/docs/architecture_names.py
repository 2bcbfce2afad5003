#!/usr/bin/env python3
"""Every type and function docs/architecture.md names in `code` exists in
the source tree: a name in backticks that looks like C++ (Type, Type::member,
Type::member(args), ns::Type) must appear as a word in src/, include/, apps/
or python/src/. Prints each missing name with its line; exit 1 if any."""
import pathlib
import re
import sys

root = pathlib.Path(__file__).resolve().parents[2]
doc = root / "docs" / "architecture.md"
words = set()
for folder in ("src", "include", "apps", "python/src"):
    for path in (root / folder).rglob("*"):
        if path.suffix in (".hpp", ".cpp", ".h") and path.is_file():
            words.update(re.findall(r"[A-Za-z_][A-Za-z0-9_]*", path.read_text(errors="replace")))

cpp_name = re.compile(r"^(?:[A-Za-z_][A-Za-z0-9_]*::)*[A-Za-z_][A-Za-z0-9_]*(?:\(.*\))?$")
missing = []
for number, line in enumerate(doc.read_text().splitlines(), 1):
    for token in re.findall(r"`([^`]+)`", line):
        if not cpp_name.match(token):
            continue  # options, paths, values, code snippets
        parts = token.split("(")[0].split("::")
        is_code = len(parts) > 1 or re.match(r"^[A-Z][a-z0-9]+[A-Z]", parts[0]) or "(" in token
        if is_code:
            missing += [f"docs/architecture.md:{number}: `{token}`: no `{p}` in the code"
                        for p in parts if p not in words]
print("\n".join(missing) if missing else f"architecture names: every name in {doc.name} exists")
sys.exit(1 if missing else 0)
