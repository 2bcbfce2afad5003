"""nck.batch: many (machine, program, options) runs, on local processes or
a Dask cluster, summarised as a list of dicts (or a pandas DataFrame).

A job that fails is one failed row, never the batch: a bad option or a
missing file (run_job catches it), a worker process that dies (the jobs it
took down run again, each alone, and the one that kills its worker alone
is the failed row)."""
import collections
import os

from ._batch_rows import COLUMNS, WORKER_LOST, failed_row, run_job, worst_axis  # noqa: F401 (public names)
from ._errors import ArgumentError


def batch(jobs, scheduler=None, workers=None, as_frame=False):
    """Runs many jobs and returns one dict per job, in the jobs' order.

    Args:
        jobs: iterable of (machine, program) or (machine, program, options):
            machine a folder path, program a path (or a list, one per
            channel), options a dict of ``Machine.run`` keyword arguments
            (override, feedhold, plc, start_at ...). Paths are made absolute
            here, before the jobs go to the workers.
        scheduler: a Dask distributed scheduler address ("tcp://host:8786")
            or a ``distributed.Client``; a ``concurrent.futures.Executor``
            of the caller's; None: local processes (started and ended here).
        workers: local processes (default: os.cpu_count()); unused with a
            scheduler.
        as_frame: return a pandas DataFrame with the columns of
            ``nck._batch.COLUMNS`` (ArgumentError 940201 when pandas is not
            installed, before anything runs).

    Each dict has the keys of ``nck._batch.COLUMNS``: the job's machine,
    program, override, feedhold, plc, start_at (None when not given); exit,
    end, time_s, errors (count), error_ids, warnings (count), worst_axis,
    worst_axis_share (0..1, see ``worst_axis``), wall_s, message (why a
    job did not run, or its first error). A job that cannot run has exit 2,
    end "not_run" (or "worker_lost": its worker process died, 940005) and
    its ID in error_ids.

    Local processes are spawned: a script calling this needs the
    ``if __name__ == "__main__":`` guard (docs/python.md). Dask workers must
    be able to ``import nck``.
    """
    pandas = _pandas() if as_frame else None
    jobs = [_absolute(job) for job in jobs]
    import concurrent.futures
    if isinstance(scheduler, concurrent.futures.Executor):  # a pool kept by the caller (bench/)
        rows = _on_executor(scheduler, jobs)
    elif scheduler is None:
        rows = _on_local_processes(jobs, workers)
    else:
        rows = _on_dask(scheduler, jobs)
    return pandas.DataFrame(rows, columns=COLUMNS) if pandas else rows


def _pandas():
    try:
        import pandas
    except ImportError:
        raise ArgumentError("as_frame=True needs pandas, which is not installed (Debian: apt install "
                            "python3-pandas; or pip install pandas); without it the rows are dicts", 940201) from None
    return pandas


def _absolute(job):
    """The job with absolute paths (a worker's current folder may be another),
    or as it is when it is malformed: its row says so."""
    if not isinstance(job, (tuple, list)) or len(job) not in (2, 3):
        return job

    def path(p):
        return os.path.abspath(p) if isinstance(p, (str, os.PathLike)) else p

    machine, program = path(job[0]), job[1]
    program = [path(p) for p in program] if isinstance(program, (list, tuple)) else path(program)
    if len(job) == 2:
        return (machine, program)
    options = job[2]
    if isinstance(options, dict) and isinstance(options.get("plc"), (str, os.PathLike)):
        options = {**options, "plc": path(options["plc"])}
    return (machine, program, options)


def _on_executor(pool, jobs):
    futures = [pool.submit(run_job, job) for job in jobs]
    return [_row(f, job) for f, job in zip(futures, jobs)]


def _row(future, job):
    """A finished future's row; its exception (the job never reached
    run_job, or its process died) as the job's failed row."""
    try:
        return future.result()
    except Exception as e:  # noqa: BLE001
        return failed_row(job, WORKER_LOST, "worker_lost", f"{type(e).__name__}: {e}")


def _on_dask(scheduler, jobs):
    import distributed
    client = scheduler if isinstance(scheduler, distributed.Client) else distributed.Client(scheduler)
    futures = []
    try:
        futures = client.map(run_job, jobs, pure=False)
        distributed.wait(futures)  # a killed worker's task goes to another; KilledWorker after three
        return [_row(f, job) for f, job in zip(futures, jobs)]
    except BaseException:  # Ctrl-C too: the cluster should not go on with them
        client.cancel(futures)
        raise
    finally:
        if client is not scheduler:
            client.close()


def _on_local_processes(jobs, workers):
    """At most `workers` jobs in flight, so that the jobs a dying worker
    takes down are known: they run again, each in a process of its own."""
    rows = [None] * len(jobs)
    todo = collections.deque(range(len(jobs)))
    while todo:
        for i in _run_pool(jobs, todo, rows, workers or os.cpu_count()):
            rows[i] = _run_alone(jobs[i])
    return rows


def _pool(workers):
    import concurrent.futures
    import multiprocessing
    # spawn: a forked child would inherit the parent's threads' state
    return concurrent.futures.ProcessPoolExecutor(max_workers=workers, mp_context=multiprocessing.get_context("spawn"))


def _run_pool(jobs, todo, rows, workers):
    """Runs jobs from `todo` into `rows`; the jobs in flight when a worker
    died (the pool is lost with it), or [] when all are done."""
    import concurrent.futures
    from concurrent.futures.process import BrokenProcessPool
    pool = _pool(workers)
    running = {}
    try:
        while todo or running:
            while todo and len(running) < workers:
                try:
                    running[pool.submit(run_job, jobs[todo[0]])] = todo[0]
                except BrokenProcessPool:  # a worker died since the last wait: the jobs in flight went with it
                    return list(running.values())
                todo.popleft()
            done, _ = concurrent.futures.wait(running, return_when=concurrent.futures.FIRST_COMPLETED)
            for f in done:
                i = running.pop(f)
                try:
                    rows[i] = f.result()
                except BrokenProcessPool:
                    return [i] + list(running.values())
                except Exception:  # noqa: BLE001 - the job never reached run_job (it did not pickle)
                    rows[i] = _row(f, jobs[i])
        return []
    except BaseException:
        _end(pool)
        raise
    finally:
        pool.shutdown(wait=True)


def _run_alone(job):
    """A job in a process of its own: its row, or the failed row when the
    process dies (then it was this job that killed it)."""
    pool = _pool(1)
    try:
        return _row(pool.submit(run_job, job), job)
    except BaseException:
        _end(pool)
        raise
    finally:
        pool.shutdown(wait=True)


def _end(pool):
    # Ctrl-C (or a job's exception): the pool's own shutdown waits for
    # every running job, a long run's minutes (50 s in the stress test);
    # the queued ones are cancelled and the workers ended instead.
    processes = list((getattr(pool, "_processes", None) or {}).values())  # shutdown forgets them
    pool.shutdown(wait=False, cancel_futures=True)
    for process in processes:
        process.terminate()


def write_csv(rows, path):
    """The rows as CSV with a header (COLUMNS); None is an empty cell."""
    import csv
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS)
        w.writeheader()
        w.writerows(rows)
