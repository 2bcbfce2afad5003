#!/usr/bin/env bash
# The report's browser checks on the full 200,000-block benchmark program
# (ctest runs them on 20,000 blocks): file size and load-time caps
# (docs/performance.md), backplot extents, no console errors, screenshots in
# build/default/tests/browser-full/. Needs a built build/default/nck.
set -euo pipefail
cd "$(dirname "$0")/.."
out=build/default/tests/browser-full
mkdir -p "$out"
node tests/browser/report_test.mjs --nck build/default/nck --source . --out "$out" --blocks 200000 "$@"
