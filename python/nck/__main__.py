"""python3 -m nck batch MACHINES PROGRAMS... [sweep options] [--scheduler tcp://...] [--workers N] --out results.csv

Every program runs on every machine, and with every value of each sweep
option (--override 50,100,150 runs each program three times); MACHINES is
one machine folder or several separated by commas.
"""
import argparse
import itertools
import sys

from ._batch import batch, write_csv


def _floats(text):
    try:
        return [float(v) for v in text.split(",")]
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a comma-separated list of numbers") from None


def _hold(text):
    try:
        on, off = (float(v) for v in text.split(":"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not ON:OFF in seconds (1.5:3)") from None
    return (on, off)


def parser():
    p = argparse.ArgumentParser(prog="python3 -m nck", description="nck from Python")
    sub = p.add_subparsers(dest="command", required=True)
    b = sub.add_parser("batch", help="run programs x machines x sweep values, write a CSV table")
    b.add_argument("machines", help="machine folder(s), comma-separated")
    b.add_argument("programs", nargs="+", help="NC programs")
    b.add_argument("--scheduler", help="Dask scheduler address (tcp://host:port); default: local processes")
    b.add_argument("--workers", type=int, help="local worker processes (default: the CPU count)")
    b.add_argument("--max-time", type=float, default=86400.0, help="simulated-time limit per run, s")
    sweep = b.add_argument_group("sweep options (Machine.run's; each value is a run of its own)")
    sweep.add_argument("--override", type=_floats, default=[None],
                       help="feed override(s) in %%, comma-separated: 50,100,150")
    sweep.add_argument("--feedhold", type=_hold, action="append", help="hold from ON to OFF s (1.5:3); repeatable")
    sweep.add_argument("--plc", action="append", help="a --plc scenario file; repeat for several")
    sweep.add_argument("--start-at", action="append", help="a block search mark (N100, block:7, offset:B); repeatable")
    sweep.add_argument("--stop-at", help="where every run ends (N100, line:12, event:wait)")
    b.add_argument("--out", required=True, help="the CSV file to write")
    return p


def jobs_of(a):
    """Every machine x program x override x plc x start_at; feedhold and
    stop_at are the same for every run."""
    jobs = []
    for m, prog, ovr, plc, start in itertools.product(a.machines.split(","), a.programs, a.override,
                                                      a.plc or [None], a.start_at or [None]):
        options = {"max_time": a.max_time}
        for key, value in (("override", ovr), ("plc", plc), ("start_at", start), ("feedhold", a.feedhold),
                           ("stop_at", a.stop_at)):
            if value is not None:
                options[key] = value
        jobs.append((m, prog, options))
    return jobs


def main(argv=None):
    p = parser()
    a = p.parse_args(argv)
    if a.workers is not None and a.workers < 1:
        p.error("--workers must be 1 or more")
    rows = batch(jobs_of(a), scheduler=a.scheduler, workers=a.workers)
    write_csv(rows, a.out)
    failed = sum(1 for r in rows if r["exit"] != 0)
    print(f"nck batch: {len(rows)} run(s), {failed} not at program end; {a.out}", file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
