#!/usr/bin/env bash
# README command (2): install, build, and run every test (under ASan/UBSan by
# default, with a plain nck for the memory figures; NCK_TEST_PRESET=default
# for a plain build only), then each libFuzzer
# target for NCK_FUZZ_SECONDS (default 20) over its seed corpus (clang 14,
# preset fuzz; NCK_FUZZ_SECONDS=0 skips it). The last line printed is
# ctest's summary.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
preset="${NCK_TEST_PRESET:-asan}"
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset" -j "$(nproc)"
# The report's memory figures (issue 26: 5,000,000 lines within 64 MiB) hold
# for a plain build; under ASan the tests check growth only. A plain nck is
# built beside the ASan suite and named to them (report_memory_test.cpp).
if [ "$preset" = asan ]; then
  cmake --preset default >/dev/null
  cmake --build --preset default -j "$(nproc)" --target nck
  export NCK_PLAIN_BINARY="$PWD/build/default/nck"
fi
fuzz_rc=0
if [ "${NCK_FUZZ_SECONDS:-20}" != 0 ]; then
  cmake --preset fuzz -DNCK_FUZZ_SECONDS="${NCK_FUZZ_SECONDS:-20}" >/dev/null
  cmake --build --preset fuzz -j "$(nproc)"
  ctest --preset fuzz -j "$(nproc)" || fuzz_rc=$?
fi
log=$(mktemp)
set +e
ctest --preset "$preset" -j "$(nproc)" >"$log" 2>&1
rc=$?
set -e
[ "$rc" -eq 0 ] && rc=$fuzz_rc
grep -v -E 'tests passed, [0-9]+ tests? failed|^Total Test time' "$log" || true
grep -E 'tests passed, [0-9]+ tests? failed' "$log" | tail -1
exit $rc
