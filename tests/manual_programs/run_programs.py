#!/usr/bin/env python3
"""Programs after the TF5200 manual's examples (issue 44): each runs unchanged
on an example machine to a normal end and shows the observable that
programs.tsv expects of it.

  run_programs.py NCK SOURCE_DIR [--only NAME ...] [-v]

For every row of SOURCE_DIR/tests/manual_programs/programs.tsv the program
(in that folder) runs as

  NCK run SOURCE_DIR/examples/<machine> <file> --final F --events E --no-progress

and passes when the exit code is 0, no `error` event was written, the final
state has no errors and ends at the program end, and every check of the row's
last column holds. The checks (space-separated):

  X=40, X.mcs=110    final position of an axis (program / machine coordinates)
  plc_out:H50=3      a plc_out event of that function with that value
  plc_out:M10        a plc_out event of that function (any value)
  blocks=6           the number of block events
  block_n=10,100,13  the block numbers (N) of the block events, in order
                     (blocks without N left out)
  S1.rpm=-1100       a field of a spindle in the final state (rpm, act_rpm,
                     pos, mode, homed, gear)
  modal.feed_mode=G94, trc=G40   a field of channel 1's final state
  time>=2.95         the run's simulated time in seconds

Numbers compare within 1e-3 (spindle rpm and pos within 0.05). Also checked:
every .nc file in this folder is in the manifest and its first line names
the TF5200 manual page it mirrors. A summary line per program, then the
totals; exit 1 on any failure. Python 3 standard library only.
"""
import argparse
import json
import pathlib
import subprocess
import sys
import tempfile
import time

TOL = 1e-3
SPINDLE_TOL = 0.05
WALL_LIMIT_S = 60.0  # a hung run fails; the programs take well under a second


def read_manifest(path):
    rows = []
    for n, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
        if not line.strip() or line.startswith("#"):
            continue
        cols = line.split("\t")
        if len(cols) != 5:
            raise SystemExit(f"{path}:{n}: 5 tab-separated columns expected, found {len(cols)}")
        rows.append({"file": cols[0], "machine": cols[1], "page": cols[2], "what": cols[3],
                     "expect": cols[4].split(), "line": n})
    return rows


def number(text):
    try:
        return float(text)
    except ValueError:
        return None


def same(actual, expected, tol=TOL):
    """Numbers within tol; booleans and strings as written (true/false)."""
    if isinstance(actual, bool):
        return str(actual).lower() == expected.lower()
    e = number(expected)
    if e is not None and isinstance(actual, (int, float)):
        return abs(actual - e) <= tol
    return str(actual) == expected


def check(token, final, events):
    """None when the check holds, else what was found."""
    ch = final["channels"][0]
    if token.startswith("time>="):
        want = float(token[len("time>="):])
        return None if final["time"] >= want - TOL else f"time {final['time']}"
    key, _, want = token.partition("=")
    if key.startswith("plc_out:"):
        fn = key[len("plc_out:"):]
        values = [e.get("value") for e in events if e["ev"] == "plc_out" and e.get("fn") == fn]
        if not values:
            return f"no plc_out {fn}"
        if not want:
            return None
        return None if any(v is not None and same(v, want) for v in values) else f"{fn} values {values}"
    if key == "blocks":
        n = sum(1 for e in events if e["ev"] == "block")
        return None if n == int(want) else f"{n} block events"
    if key == "block_n":
        ns = [e["n"] for e in events if e["ev"] == "block" and e.get("n") is not None]
        return None if ns == [int(x) for x in want.split(",")] else f"block numbers {ns}"
    head, _, field = key.partition(".")
    if head in final.get("spindles", {}):
        sp = final["spindles"][head]
        if field not in sp:
            return f"no spindle field {field}"
        tol = SPINDLE_TOL if field in ("rpm", "act_rpm", "pos") else TOL
        return None if same(sp[field], want, tol) else f"{key} = {sp[field]}"
    if head in ch["axes"]:
        coord = field or "pcs"
        value = ch["axes"][head].get(coord)
        return None if value is not None and same(value, want) else f"{head}.{coord} = {value}"
    if head == "modal":
        value = ch["modal"].get(field)
        return None if value is not None and same(value, want) else f"{key} = {value}"
    if not field and head in ch:
        return None if same(ch[head], want) else f"{key} = {ch[head]}"
    return "unknown check"


def run_one(nck, source_dir, row, tmp, verbose):
    prog = source_dir / "tests" / "manual_programs" / row["file"]
    machine = source_dir / "examples" / row["machine"]
    fails = []
    first = prog.read_text(encoding="utf-8").splitlines()[0] if prog.exists() else ""
    if not first.startswith("; TF5200 manual"):
        fails.append("first line does not name the TF5200 manual page")
    final_path = tmp / (prog.stem + ".final.json")
    events_path = tmp / (prog.stem + ".events.jsonl")
    cmd = [str(nck), "run", str(machine), str(prog), "--final", str(final_path), "--events", str(events_path),
           "--no-progress"]
    t0 = time.monotonic()
    try:
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=WALL_LIMIT_S)
    except subprocess.TimeoutExpired:
        return [f"no end within {WALL_LIMIT_S:.0f} s of wall time"], WALL_LIMIT_S
    wall = time.monotonic() - t0
    if r.returncode != 0:
        fails.append(f"exit code {r.returncode}: {r.stderr.strip().splitlines()[:3]}")
    try:
        final = json.loads(final_path.read_text(encoding="utf-8"))
        events = [json.loads(line) for line in events_path.read_text(encoding="utf-8").splitlines() if line.strip()]
    except (OSError, ValueError) as e:
        return fails + [f"outputs unreadable: {e}"], wall
    errors = [e for e in events if e["ev"] == "error"]
    if errors:
        fails.append("error events: " + "; ".join(f"{e.get('id')} line {e.get('line')}: {e.get('msg')}" for e in errors))
    if final.get("errors"):
        fails.append(f"final state lists errors: {final['errors']}")
    if final.get("end") != "program_end":
        fails.append(f"end is {final.get('end')}, not program_end")
    for token in row["expect"]:
        found = check(token, final, events)
        if found is not None:
            fails.append(f"expected {token}, found {found}")
    if verbose:
        warnings = sorted({e.get("id") for e in events if e["ev"] == "warning"})
        print(f"  {row['file']}: {len(events)} events, time {final.get('time')} s, warnings {warnings}")
    return fails, wall


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("nck")
    ap.add_argument("source_dir")
    ap.add_argument("--only", nargs="*", default=None, help="program files to run (default: all)")
    ap.add_argument("-v", "--verbose", action="store_true")
    a = ap.parse_args()
    nck = pathlib.Path(a.nck).resolve()
    source_dir = pathlib.Path(a.source_dir).resolve()
    prog_dir = source_dir / "tests" / "manual_programs"
    rows = read_manifest(prog_dir / "programs.tsv")

    problems = []
    listed = {r["file"] for r in rows}
    for f in sorted(prog_dir.glob("*.nc")):
        if f.name not in listed:
            problems.append(f"{f.name} is not in programs.tsv")
    for r in rows:
        if not (prog_dir / r["file"]).exists():
            problems.append(f"programs.tsv line {r['line']}: {r['file']} does not exist")
        if not (source_dir / "examples" / r["machine"] / "startup.lis").exists():
            problems.append(f"programs.tsv line {r['line']}: no machine examples/{r['machine']}")
    if a.only:
        rows = [r for r in rows if r["file"] in a.only or pathlib.Path(r["file"]).stem in a.only]

    passed = 0
    with tempfile.TemporaryDirectory(prefix="nck-manual-") as d:
        for r in rows:
            fails, wall = run_one(nck, source_dir, r, pathlib.Path(d), a.verbose)
            status = "ok  " if not fails else "FAIL"
            print(f"{status} {r['file']:<34} {r['machine']:<6} {wall:5.2f} s  {' '.join(r['expect'])}")
            for f in fails:
                print(f"       {f}")
            passed += not fails
    for p in problems:
        print(f"FAIL {p}")
    total = len(rows)
    print(f"manual programs: {passed}/{total} passed" + (f", {len(problems)} manifest problem(s)" if problems else ""))
    return 0 if passed == total and not problems else 1


if __name__ == "__main__":
    sys.exit(main())
