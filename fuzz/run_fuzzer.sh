#!/usr/bin/env bash
# Runs one libFuzzer target for SECONDS over its seed corpus and prints
# libFuzzer's final statistics. The seeds come from examples/ and tests/
# (tests/data/isg-samples holds the ISG sample corpus).
# usage: fuzz/run_fuzzer.sh FUZZER decoder|list|scenario|api SECONDS [CORPUS_DIR]
set -euo pipefail
fuzzer=$1 kind=$2 seconds=$3
root="$(cd "$(dirname "$0")/.." && pwd)"
corpus=${4:-"$(mktemp -d)"}
seeds="$(mktemp -d)"
case "$kind" in
  decoder)
    find "$root/examples" "$root/tests" -type f -name '*.nc' -exec cp -t "$seeds" --backup=numbered {} +
    dict="$root/fuzz/nc.dict" ;;
  list)
    find "$root/examples" "$root/tests" -type f -name '*.lis' -exec cp -t "$seeds" --backup=numbered {} +
    dict="$root/fuzz/list.dict" ;;
  scenario)
    find "$root/examples" "$root/tests" -type f -name '*.plc' -exec cp -t "$seeds" --backup=numbered {} +
    dict="$root/fuzz/plc.dict" ;;
  api)
    cp -t "$seeds" "$root/fuzz/api_seeds"/*
    dict="$root/fuzz/api.dict" ;;
  *) echo "fuzz: unknown target kind $kind" >&2; exit 2 ;;
esac
mkdir -p "$corpus"
log="$seeds.log"
trap 'rm -rf "$seeds" "$log"' EXIT
# -timeout: seconds one input may take before it counts as a hang (NCK_FUZZ_INPUT_TIMEOUT,
# default 60 so that a loaded CI machine does not report a slow input; use 10 on an
# idle machine); -rss_limit_mb: memory per input.
cp -t "$seeds" --backup=numbered "$root/fuzz/findings/$kind"/*
rc=0
"$fuzzer" -max_total_time="$seconds" -timeout="${NCK_FUZZ_INPUT_TIMEOUT:-60}" -rss_limit_mb=2048 -max_len=8192 \
  -dict="$dict" -print_final_stats=1 -artifact_prefix="$corpus/" "$corpus" "$seeds" >"$log" 2>&1 || rc=$?
# libFuzzer's final statistics, and everything a failure said (a crash or slow
# input is kept in CORPUS as crash-*, timeout-*, slow-unit-*).
if [ "$rc" -eq 0 ]; then grep -E '^(stat::|Done [0-9]+ runs)' "$log" || true; else tail -n 60 "$log"; fi
exit "$rc"
