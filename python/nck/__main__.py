"""python3 -m nck batch MACHINES PROGRAMS... [--scheduler tcp://...] [--workers N] --out results.csv

Every program runs on every machine; MACHINES is one machine folder or
several separated by commas.
"""
import argparse
import sys

from ._batch import batch, write_csv


def main(argv=None):
    p = argparse.ArgumentParser(prog="python3 -m nck", description="nck from Python")
    sub = p.add_subparsers(dest="command", required=True)
    b = sub.add_parser("batch", help="run programs x machines, write a CSV table")
    b.add_argument("machines", help="machine folder(s), comma-separated")
    b.add_argument("programs", nargs="+", help="NC programs")
    b.add_argument("--scheduler", help="Dask scheduler address (tcp://host:port); default: local processes")
    b.add_argument("--workers", type=int, help="local worker processes (default: the CPU count)")
    b.add_argument("--max-time", type=float, default=86400.0, help="simulated-time limit per run, s")
    b.add_argument("--out", required=True, help="the CSV file to write")
    a = p.parse_args(argv)
    if a.workers is not None and a.workers < 1:
        p.error("--workers must be 1 or more")
    jobs = [(m, prog, {"max_time": a.max_time}) for m in a.machines.split(",") for prog in a.programs]
    rows = batch(jobs, scheduler=a.scheduler, workers=a.workers)
    write_csv(rows, a.out)
    failed = sum(1 for r in rows if r["exit"] != 0)
    print(f"nck batch: {len(rows)} run(s), {failed} not at program end; {a.out}", file=sys.stderr)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
