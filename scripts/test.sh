#!/usr/bin/env bash
# README command (2): install, build, and run every test (under ASan/UBSan by
# default; NCK_TEST_PRESET=default for a plain build). The last line printed
# is ctest's summary.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
preset="${NCK_TEST_PRESET:-asan}"
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)"
log=$(mktemp)
set +e
ctest --preset "$preset" -j "$(nproc)" >"$log" 2>&1
rc=$?
set -e
grep -v -E 'tests passed, [0-9]+ tests? failed|^Total Test time' "$log" || true
grep -E 'tests passed, [0-9]+ tests? failed' "$log" | tail -1
exit $rc
