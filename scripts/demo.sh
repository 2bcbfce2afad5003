#!/usr/bin/env bash
# README command (1): install, build, and run the mill example end to end.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake --preset default >/dev/null
cmake --build --preset default --target nck _nck
out=out/mill
mkdir -p "$out"
set +e
./build/default/nck run examples/mill examples/mill/contour.nc \
  --events "$out/events.jsonl" --trace "$out/trace.csv" --trace-every 10 --final "$out/final.json"
rc=$?
set -e
echo
echo "nck run exited with $rc. Outputs:"
echo "  events:      $out/events.jsonl"
echo "  trace:       $out/trace.csv"
echo "  final state: $out/final.json"
echo "The Python module (docs/python.md):"
echo "  PYTHONPATH=build/default/python /usr/bin/python3 -c \"import nck; print(nck.Machine('examples/mill').run('examples/mill/contour.nc').time_s)\""
exit $rc
