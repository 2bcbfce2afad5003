#!/usr/bin/env bash
# Runs every example of examples.txt and compares the SHA-256 of its events
# and trace (every cycle) and its exit code with examples.sha256, made by the
# binary before the architecture step 2 (issue 24: "every example's trace and
# events identical before and after"). Event kinds added since then (`state`)
# are left out of the events' hash; nothing else is.
#   check_examples.sh NCK                 compare (exit 1 on any difference)
#   check_examples.sh NCK --prep-thread   the same with preparation in its own thread
#   check_examples.sh NCK --write         write examples.sha256 anew
set -euo pipefail
nck=$(realpath "$1")
mode=${2:-check}
threading=()
[ "$mode" = --prep-thread ] && threading=(--prep-thread)
here="$(cd "$(dirname "$0")" && pwd)"
cd "$here/../.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
: >"$tmp/now"
while IFS='|' read -r name machine programs extra; do
  name=$(echo $name)
  [ -z "$name" ] || [ "${name:0:1}" = "#" ] && continue
  # common:N = bench/common_program.py's program of N blocks (dense: the
  # look-ahead's case), run from the temporary folder so that its events
  # name it as common.nc.
  dir=.
  if [[ $(echo $programs) == common:* ]]; then
    python3 bench/common_program.py "$tmp/common.nc" "$(echo $programs | cut -d: -f2)"
    programs=common.nc machine="$PWD/$(echo $machine)" dir="$tmp"
  fi
  rc=0
  # shellcheck disable=SC2086  # programs and options are word lists
  (cd "$dir" && "$nck" run $machine $programs $extra "${threading[@]}" --no-progress --events "$tmp/ev" \
    --trace "$tmp/tr" >/dev/null 2>"$tmp/err") || rc=$?
  ev=$(grep -v '"ev":"state"' "$tmp/ev" | sha256sum | cut -c1-64)
  tr=$(sha256sum <"$tmp/tr" | cut -c1-64)
  echo "$name exit=$rc events=$ev trace=$tr" >>"$tmp/now"
done <"$here/examples.txt"
if [ "$mode" = --write ]; then
  cp "$tmp/now" "$here/examples.sha256"
  cat "$here/examples.sha256"
  exit 0
fi
if diff -u "$here/examples.sha256" "$tmp/now"; then
  echo "golden: $(wc -l <"$tmp/now") example runs identical"
else
  echo "golden: the lines above differ (- pinned, + now)" >&2
  exit 1
fi
