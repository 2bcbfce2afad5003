#!/usr/bin/env bash
# Runs every example of examples.txt and compares its exit code and the
# SHA-256 of its events and trace (every cycle) with examples.sha256, made by
# the binary before the architecture step 2 (issue 24: "every example's trace
# and events identical before and after"). Event kinds added since then
# (`state`) are left out of the events' hash; nothing else is.
# The hashes decide; expected/NAME/ is the readable part: each run's outputs
# as compared, cut down to stay small (diff_outputs.py's header says how):
# events.jsonl (the events without `state` lines; of a run with more than
# 2,000, every other event and about 1,000 of its block events), trace.csv
# (the header, every k-th row and the last: at most 751 rows),
# trace.segments (a short hash per k rows) and meta (the counts and steps).
# When a run differs from examples.sha256, the message says which of exit,
# events and trace differ (with nck's first lines on stderr when the exit
# code does), and diff_outputs.py compares the outputs with expected/NAME/:
# for the first few differences, the file, the line and the event fields or
# trace columns, old → new. --write rewrites both; `git diff
# tests/golden/expected` then shows the change in the stored lines.
#   check_examples.sh NCK                 compare (exit 1 on any difference)
#   check_examples.sh NCK --prep-thread   the same with preparation in its own thread
#   check_examples.sh NCK --write         write examples.sha256 and expected/ anew
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
differ=0
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
  now="$name exit=$rc events=$ev trace=$tr"
  echo "$now" >>"$tmp/now"
  if [ "$mode" = --write ]; then
    python3 "$here/diff_outputs.py" write "$tmp/ev" "$tmp/tr" "$tmp/expected/$name"
    continue
  fi
  pinned=$(grep -m1 "^$name " "$here/examples.sha256" || true)
  [ "$now" = "$pinned" ] && continue
  differ=$((differ + 1))
  if [ -z "$pinned" ]; then
    echo "golden: $name: not in examples.sha256 (write it with --write)" >&2
    continue
  fi
  what=()
  for part in exit events trace; do
    old=$(grep -o " $part=[^ ]*" <<<"$pinned")
    [ "$old" = "$(grep -o " $part=[^ ]*" <<<"$now")" ] && continue
    if [ $part = exit ]; then what+=("exit ${old# exit=} → $rc"); else what+=("$part"); fi
  done
  echo "golden: $name differs from examples.sha256: ${what[*]}" >&2
  [[ ${what[*]:-} == exit* ]] && sed -n '1,5s/^/  stderr: /p' "$tmp/err" >&2
  [[ " ${what[*]:-} " == *" events "* || " ${what[*]:-} " == *" trace "* ]] || continue
  if python3 "$here/diff_outputs.py" check "$name" "$tmp/ev" "$tmp/tr" "$here/expected/$name" >&2; then
    echo "  $name: the lines expected/$name keeps are the same: the difference lies in others" >&2
  fi
done <"$here/examples.txt"
if [ "$mode" = --write ]; then
  cp "$tmp/now" "$here/examples.sha256"
  rm -rf "$here/expected"
  cp -r "$tmp/expected" "$here/expected"
  cat "$here/examples.sha256"
  exit 0
fi
# A run pinned in examples.sha256 that examples.txt no longer lists
gone=$(cut -d' ' -f1 "$here/examples.sha256" | grep -vxF -f <(cut -d' ' -f1 "$tmp/now") || true)
if [ -n "$gone" ]; then
  echo "golden: pinned in examples.sha256 but not run: $(tr "\n" " " <<<"$gone")" >&2
  differ=$((differ + 1))
fi
if [ $differ = 0 ]; then
  echo "golden: $(wc -l <"$tmp/now") example runs identical"
else
  echo "golden: $differ of $(wc -l <"$tmp/now") example runs differ (above); if the change is meant," \
    "tests/golden/check_examples.sh NCK --write pins it and git diff tests/golden/expected shows it" >&2
  exit 1
fi
