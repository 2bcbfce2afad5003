#!/usr/bin/env python3
"""nck.batch throughput: 40 runs of the 20,000-block common program on the
mill, on 1 and on 2 workers, local processes and a Dask LocalCluster.
Start-up (processes spawned, nck imported, the machine loaded once per
worker) is excluded from the throughput and reported apart.

  PYTHONPATH=build/default/python /usr/bin/python3 bench/batch_bench.py [--runs 40] [--blocks 20000]
"""
import argparse
import concurrent.futures
import multiprocessing
import os
import pathlib
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]


def timed(fn):
    start = time.perf_counter()
    out = fn()
    return out, time.perf_counter() - start


def local(workers, jobs):
    import nck
    from nck._batch import run_job
    pool, startup_s = timed(lambda: concurrent.futures.ProcessPoolExecutor(
        workers, mp_context=multiprocessing.get_context("spawn")))
    with pool:
        _, warm_s = timed(lambda: list(pool.map(run_job, jobs[:workers])))  # spawn, import, load
        rows, run_s = timed(lambda: nck.batch(jobs, scheduler=pool))
    return rows, startup_s + warm_s, run_s


def dask(workers, jobs):
    import distributed
    import nck
    from nck._batch import run_job
    cluster, startup_s = timed(lambda: distributed.LocalCluster(
        n_workers=workers, threads_per_worker=1, processes=True, host="127.0.0.1", dashboard_address=None))
    with cluster, distributed.Client(cluster) as client:
        _, warm_s = timed(lambda: client.gather(client.map(run_job, jobs[:workers], pure=False)))
        rows, run_s = timed(lambda: nck.batch(jobs, scheduler=client))
    return rows, startup_s + warm_s, run_s


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--runs", type=int, default=40)
    p.add_argument("--blocks", type=int, default=20000)
    p.add_argument("--engines", default="local,dask")
    a = p.parse_args()
    prog = pathlib.Path(tempfile.mkdtemp()) / f"common_{a.blocks}.nc"
    subprocess.run([sys.executable, str(ROOT / "bench" / "common_program.py"), str(prog), str(a.blocks)], check=True)
    jobs = [(str(ROOT / "examples" / "mill"), str(prog))] * a.runs
    print(f"{a.runs} runs of the {a.blocks}-block common program on examples/mill, {os.cpu_count()} CPU(s)")
    for engine in a.engines.split(","):
        rate = {}
        for workers in (1, 2):
            rows, startup_s, run_s = (local if engine == "local" else dask)(workers, jobs)
            assert all(r["exit"] == 0 for r in rows), rows[0]
            rate[workers] = a.runs / run_s
            print(f"{engine:5} {workers} worker(s): {run_s:6.2f} s for {a.runs} runs = {rate[workers]:5.2f} runs/s "
                  f"(one run {rows[0]['time_s']:.1f} s simulated, {rows[0]['wall_s']:.3f} s wall); "
                  f"start-up {startup_s:.2f} s, not counted")
        print(f"{engine:5} throughput 2 workers / 1 worker: {rate[2] / rate[1]:.2f}x")


if __name__ == "__main__":
    main()
