#!/usr/bin/env python3
"""The golden test's canonical outputs (tests/golden/expected/NAME/) and a
readable comparison of a run's outputs with them (check_examples.sh).

  diff_outputs.py write EVENTS TRACE DIR        write DIR's canonical files
  diff_outputs.py check NAME EVENTS TRACE DIR   compare; exit 1 on a difference

The canonical files of one run:
  events.jsonl    the events file without its `state` lines (the lines
                  examples.sha256 hashes). When it holds more than 2,000
                  lines, only every m-th block event (by the block events'
                  count: the 1st, (m+1)-th, ...) and the last one are kept,
                  every other event always; m = ceil(block events / 1,000).
  trace.csv       the header, then every k-th row (rows 0, k, 2k, ...) and
                  the last row; k = ceil(rows / 750), so at most 751 rows.
  trace.segments  (k > 1 only) per k rows (rows 0..k-1, k..2k-1, ...) the
                  first 8 hex digits of their SHA-256: a difference in rows
                  that are not stored is still placed within k rows.
  meta            `events_lines=N events_block_every=m trace_rows=R
                  trace_every=k`: the counts and steps the check selects by.

Line numbers in messages: the trace's are those of the run's trace file
(line 1 = header, row i = line i+2); the events' are those of the run's
events without its `state` lines (= lines of events.jsonl when it is kept
whole). Only the first few differences of each file are printed.
"""
import difflib
import hashlib
import json
import math
import os
import sys

EVENTS_WHOLE = 2000      # events kept whole up to this many lines
EVENTS_BLOCKS = 1000     # else about this many block events are kept
TRACE_ROWS = 750         # trace rows kept at most (plus the last)
SHOWN = 5                # differing lines printed per file
BYTES = "surrogateescape"  # any byte read is written back as it was


def read_lines(path):
    try:
        with open(path, encoding="utf-8", errors=BYTES, newline="") as f:
            return f.read().splitlines(keepends=True)
    except FileNotFoundError:
        return []


def events_of(path):
    """The events as examples.sha256 hashes them: without `state` lines."""
    return [l for l in read_lines(path) if '"ev":"state"' not in l]


def is_block(line):
    return '"ev":"block"' in line


def kept_events(lines, m):
    """(index, line) of the events kept: all but the block events that are
    neither every m-th nor the last block event."""
    blocks = [i for i, l in enumerate(lines) if is_block(l)]
    last = blocks[-1] if blocks else -1
    out, b = [], 0
    for i, l in enumerate(lines):
        if not is_block(l):
            out.append((i, l))
            continue
        if b % m == 0 or i == last:
            out.append((i, l))
        b += 1
    return out


def kept_rows(n, k):
    return [i for i in range(n) if i % k == 0 or i == n - 1]


def segments(rows, k):
    return [hashlib.sha256("".join(rows[s:s + k]).encode("utf-8", BYTES)).hexdigest()[:8]
            for s in range(0, len(rows), k)]


def read_meta(d):
    meta = {}
    for word in open(os.path.join(d, "meta"), encoding="utf-8").read().split():
        key, _, value = word.partition("=")
        meta[key] = int(value)
    return meta


def write(events_path, trace_path, d):
    os.makedirs(d, exist_ok=True)
    ev = events_of(events_path)
    m = 1
    if len(ev) > EVENTS_WHOLE:
        m = max(1, math.ceil(sum(map(is_block, ev)) / EVENTS_BLOCKS))
    with open(os.path.join(d, "events.jsonl"), "w", encoding="utf-8", errors=BYTES,
              newline="") as f:
        f.writelines(l for _, l in kept_events(ev, m))
    tr = read_lines(trace_path)
    rows = tr[1:]
    k = max(1, math.ceil(len(rows) / TRACE_ROWS))
    with open(os.path.join(d, "trace.csv"), "w", encoding="utf-8", errors=BYTES,
              newline="") as f:
        f.writelines(tr[:1] + [rows[i] for i in kept_rows(len(rows), k)])
    if k > 1:
        with open(os.path.join(d, "trace.segments"), "w", encoding="utf-8") as f:
            f.writelines(h + "\n" for h in segments(rows, k))
    with open(os.path.join(d, "meta"), "w", encoding="utf-8") as f:
        f.write(f"events_lines={len(ev)} events_block_every={m} "
                f"trace_rows={len(rows)} trace_every={k}\n")


class Raw(str):
    """A JSON number kept as its text (1.0 and 1 differ, as in the hash)."""


def fields(line):
    """The event's fields, nested objects and lists flattened (values.X)."""
    try:
        obj = json.loads(line, parse_float=Raw, parse_int=Raw)
    except ValueError:
        return None
    flat = {}

    def walk(prefix, v):
        if isinstance(v, dict):
            for key, sub in v.items():
                walk(f"{prefix}.{key}" if prefix else key, sub)
        elif isinstance(v, list):
            for i, sub in enumerate(v):
                walk(f"{prefix}[{i}]", sub)
        else:
            flat[prefix] = v
    walk("", obj)
    return flat


NONE = object()  # a field the event does not have


def show(v):
    if v is NONE:
        return "(none)"
    return str(v) if isinstance(v, Raw) else json.dumps(v)


def describe_event(line):
    f = fields(line) or {}
    ev = f.get("ev", "?")
    return f"{ev}, t={f['t']}" if "t" in f else str(ev)


def event_change(old, new):
    """(the names of the fields that differ, old → new per field)"""
    a, b = fields(old), fields(new)
    if a is None or b is None:
        return None, f"{old.strip()} → {new.strip()}"
    keys = [k for k in list(a) + [k for k in b if k not in a]
            if k not in a or k not in b
            or type(a[k]) is not type(b[k]) or a[k] != b[k]]
    if not keys:  # same fields and values, other text (order, spacing)
        return None, f"same fields, other text: {old.strip()} → {new.strip()}"
    return tuple(keys), ", ".join(
        f"{k}: {show(a.get(k, NONE))} → {show(b.get(k, NONE))}" for k in keys)


def check_events(events_path, d, out):
    meta = read_meta(d)
    old = read_lines(os.path.join(d, "events.jsonl"))
    ev = events_of(events_path)
    m = meta["events_block_every"]
    new = kept_events(ev, m)
    if len(ev) != meta["events_lines"]:
        out.append(f"events: {meta['events_lines']} lines → {len(ev)} "
                   "(without `state` lines)")
    where = lambda j: new[j][0] + 1 if j < len(new) else len(ev) + 1
    kind = lambda line: (fields(line) or {}).get("ev")
    # The differences in order: a changed line (paired with the new line at
    # its place when both are events of one kind), a missing or a new one.
    items = []
    sm = difflib.SequenceMatcher(None, old, [l for _, l in new], autojunk=False)
    for op, i1, i2, j1, j2 in sm.get_opcodes():
        for n in range(max(i2 - i1, j2 - j1) if op != "equal" else 0):
            o = old[i1 + n] if i1 + n < i2 else None
            j = j1 + n if j1 + n < j2 else None
            if o and j is not None and kind(o) == kind(new[j][1]):
                keys, change = event_change(o, new[j][1])
                items.append(("change", j, keys, f"line {where(j)} "
                              f"({describe_event(o)}): {change}"))
                continue
            if o:
                items.append(("missing", None, None, f"missing before line "
                              f"{where(j if j is not None else j2)} "
                              f"({describe_event(o)}): {o.strip()}"))
            if j is not None:
                items.append(("new", None, None, f"line {where(j)}: new "
                              f"({describe_event(new[j][1])}): {new[j][1].strip()}"))
    # A run of changed lines in a row in which the same fields differ (a time
    # shift: t) is one item, said by its first and last line.
    found, n = [], 0
    while n < len(items):
        r = n + 1
        while (r < len(items) and items[n][0] == items[r][0] == "change"
               and items[n][2] and items[r][2] == items[n][2]
               and items[r][1] == items[r - 1][1] + 1):
            r += 1
        if r - n == 1:
            found.append(f"events.jsonl{':' * (items[n][0] == 'missing')} {items[n][3]}")
        else:
            found.append(f"events.jsonl lines {where(items[n][1])}–"
                         f"{where(items[r - 1][1])}, {r - n} events in a row "
                         f"that differ in {', '.join(items[n][2])}: "
                         f"{items[n][3]} … {items[r - 1][3]}")
        n = r
    out.extend(found[:SHOWN])
    if len(found) > SHOWN:
        out.append(f"... and {len(found) - SHOWN} more differing event lines")
    return bool(out)


def split(line):
    return line.rstrip("\r\n").split(",")


def row_change(cols_old, old, cols_new, new):
    """(the columns that differ, old → new per column), by column name"""
    a, b = dict(zip(cols_old, split(old))), dict(zip(cols_new, split(new)))
    cols = [c for c in cols_old if c in b and a.get(c) != b[c]]
    return cols, ", ".join(f"{c}: {a.get(c, '(none)')} → {b[c]}" for c in cols)


def check_trace(trace_path, d, out):
    meta = read_meta(d)
    k, n_old = meta["trace_every"], meta["trace_rows"]
    old = read_lines(os.path.join(d, "trace.csv"))
    tr = read_lines(trace_path)
    head_old, stored = (split(old[0]) if old else []), old[1:]
    head_new, rows = (split(tr[0]) if tr else []), tr[1:]
    idx = kept_rows(n_old, k)
    if len(idx) != len(stored):
        out.append(f"trace.csv: {d} holds {len(stored)} rows, its meta says "
                   f"{len(idx)} (rewrite it with --write)")
        return True
    n = len(out)
    if head_old != head_new:
        gone = [c for c in head_old if c not in head_new]
        added = [c for c in head_new if c not in head_old]
        out.append("trace.csv line 1 (columns): "
                   + (f"removed {', '.join(gone)}; " if gone else "")
                   + (f"added {', '.join(added)}; " if added else "")
                   + ("" if gone or added else "order changed; ")
                   + "the values compare by column name")
    if len(rows) != n_old:
        t_old = split(stored[-1])[0] if stored else "-"
        t_new = split(rows[-1])[0] if rows else "-"
        out.append(f"trace.csv: {n_old} rows → {len(rows)} "
                   f"(last row's t {t_old} → {t_new})")
    t = lambda line: split(line)[0]
    found, cols = [], []
    for i, line in zip(idx, stored):
        if i == n_old - 1 and len(rows) != n_old:
            if rows:
                _, change = row_change(head_old, line, head_new, rows[-1])
                if change:
                    found.append(f"trace.csv last row (line {i + 2} → "
                                 f"{len(rows) + 1}): {change}")
            continue
        if i >= len(rows):
            continue
        changed, change = row_change(head_old, line, head_new, rows[i])
        if change:
            found.append(f"trace.csv line {i + 2} (t={t(line)}): {change}")
            cols += [c for c in changed if c not in cols]
    if k > 1 and head_old == head_new:
        seg_old = read_lines(os.path.join(d, "trace.segments"))
        seg_new = segments(rows, k)
        for s, (a, b) in enumerate(zip(seg_old, seg_new)):
            if a.strip() != b:
                first, last = s * k, min(s * k + k, len(rows), n_old) - 1
                out.append(f"trace.csv: the first difference lies in lines "
                           f"{first + 2}–{last + 2} (t={t(rows[first])}–"
                           f"{t(rows[last])}; one row in {k} is stored)")
                break
    out.extend(found[:SHOWN])
    if len(found) > SHOWN:
        out.append(f"... and {len(found) - SHOWN} more of the stored rows differ")
    if cols:
        cols = [c for c in head_old if c in cols]
        out.append(f"trace.csv: the columns that differ in stored rows: {', '.join(cols)}")
    return len(out) > n


def check(name, events_path, trace_path, d):
    if not os.path.exists(os.path.join(d, "meta")):
        print(f"  {name}: no canonical files in {d} (write them with --write)")
        return 1
    out_ev, out_tr = [], []
    differ = check_events(events_path, d, out_ev)
    differ = check_trace(trace_path, d, out_tr) or differ
    for line in out_ev + out_tr:
        print(f"  {name}: {line}")
    return 1 if differ else 0


def main(argv):
    if len(argv) == 5 and argv[1] == "write":
        write(argv[2], argv[3], argv[4])
        return 0
    if len(argv) == 6 and argv[1] == "check":
        return check(argv[2], argv[3], argv[4], argv[5])
    print(__doc__, file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.stdout.reconfigure(errors="backslashreplace")
    sys.exit(main(sys.argv))
