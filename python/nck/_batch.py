"""nck.batch: many (machine, program, options) runs, on local processes or
a Dask cluster, summarised as a list of dicts."""
import os

#: The columns of a batch result, in this order (also the CSV's).
COLUMNS = ["machine", "program", "exit", "end", "time_s", "errors", "error_ids", "warnings",
           "worst_axis", "worst_axis_share", "wall_s"]

# Machines loaded once per worker process (a sweep runs many programs on few machines).
_machines = {}


def worst_axis(final):
    """The axis whose limits held the path back longest, and that share of
    its channel's time: time_by_cause's axis_velocity and acceleration
    classes summed per axis (docs/outputs.md). ("", 0.0) when none did."""
    best, best_share = "", 0.0
    for channel in final.get("time_by_cause", {}).get("channels", []):
        total = channel.get("time_s") or 0.0
        per_axis = {}
        for c in channel.get("causes", []):
            if c.get("cause") in ("axis_velocity", "acceleration") and c.get("axis"):
                per_axis[c["axis"]] = per_axis.get(c["axis"], 0.0) + c.get("time_s", 0.0)
        for axis, t in per_axis.items():
            share = t / total if total > 0 else 0.0
            if share > best_share:
                best, best_share = axis, share
    return best, best_share


def run_job(job):
    """One job -> its result row (runs in a worker; never raises on bad
    input: an nck.Error becomes exit 2 and its ID)."""
    import time
    from . import Error, Machine
    machine, program, options = (tuple(job) + ({},))[:3]
    row = {"machine": os.fspath(machine), "program": os.fspath(program) if not isinstance(program, (list, tuple))
           else ";".join(os.fspath(p) for p in program)}
    start = time.perf_counter()
    try:
        key = os.path.abspath(os.fspath(machine))
        if key not in _machines:
            _machines[key] = Machine(machine)
        r = _machines[key].run(program, **{"events": False, **(options or {})})
        axis, share = worst_axis(r.final)
        row.update(exit=r.exit, end=r.end, time_s=r.time_s, errors=len(r.errors),
                   error_ids=" ".join(str(e["id"]) for e in r.errors), warnings=len(r.warnings),
                   worst_axis=axis, worst_axis_share=share)
    except Error as e:
        row.update(exit=2, end="not_run", time_s=0.0, errors=1, error_ids=str(e.id), warnings=0,
                   worst_axis="", worst_axis_share=0.0)
    row["wall_s"] = time.perf_counter() - start
    return {k: row[k] for k in COLUMNS}


def batch(jobs, scheduler=None, workers=None):
    """Runs many jobs and returns one dict per job, in the jobs' order.

    Args:
        jobs: iterable of (machine, program) or (machine, program, options):
            machine a folder path, program a path (or a list, one per
            channel), options a dict of ``Machine.run`` keyword arguments.
        scheduler: a Dask distributed scheduler address ("tcp://host:8786")
            or a ``distributed.Client``; a ``concurrent.futures.Executor``
            of the caller's; None: local processes (started and ended here).
        workers: local processes (default: os.cpu_count()); unused with a
            scheduler.

    Each dict has the keys of ``nck._batch.COLUMNS``: machine, program,
    exit, end, time_s, errors (count), error_ids, warnings (count),
    worst_axis, worst_axis_share (0..1, see ``worst_axis``), wall_s.

    Dask workers must be able to ``import nck`` (docs/python.md).
    """
    jobs = [tuple(j) for j in jobs]
    import concurrent.futures
    if isinstance(scheduler, concurrent.futures.Executor):  # a pool kept by the caller (bench/)
        return list(scheduler.map(run_job, jobs))
    if scheduler is None:
        return _on_local_processes(jobs, workers)
    from distributed import Client
    client = scheduler if isinstance(scheduler, Client) else Client(scheduler)
    futures = []
    try:
        futures = client.map(run_job, jobs, pure=False)
        return client.gather(futures)
    except BaseException:  # Ctrl-C too: the cluster should not go on with them
        client.cancel(futures)
        raise
    finally:
        if client is not scheduler:
            client.close()


def _on_local_processes(jobs, workers):
    import concurrent.futures
    import multiprocessing
    # spawn: a forked child would inherit the parent's threads' state
    pool = concurrent.futures.ProcessPoolExecutor(max_workers=workers or os.cpu_count(),
                                                  mp_context=multiprocessing.get_context("spawn"))
    try:
        return list(pool.map(run_job, jobs))
    except BaseException:
        # Ctrl-C (or a job's exception): the pool's own shutdown waits for
        # every running job, a long run's minutes (50 s in the stress test);
        # the queued ones are cancelled and the workers ended instead.
        processes = list((getattr(pool, "_processes", None) or {}).values())  # shutdown forgets them
        pool.shutdown(wait=False, cancel_futures=True)
        for process in processes:
            process.terminate()
        raise
    finally:
        pool.shutdown(wait=True)


def write_csv(rows, path):
    """The rows as CSV with a header (COLUMNS)."""
    import csv
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS)
        w.writeheader()
        w.writerows(rows)
