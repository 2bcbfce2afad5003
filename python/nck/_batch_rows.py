"""One batch job -> its result row, in a worker process (or thread): never
raises on a bad job; the machine folders it loaded, cached while unchanged."""
import json
import os
import time

#: The columns of a batch result, in this order (also the CSV's): the job
#: (machine, program and the options a sweep varies), then its outcome.
COLUMNS = ["machine", "program", "override", "feedhold", "plc", "start_at", "exit", "end", "time_s", "errors",
           "error_ids", "warnings", "worst_axis", "worst_axis_share", "wall_s", "message"]

BAD_ARGUMENT = 940201  # an option Machine.run does not take, of the wrong type or value
WORKER_LOST = 940005   # the worker process ended while it ran the job (killed, out of memory)

# Machines loaded once per worker process (a sweep runs many programs on few
# machines): folder -> (its files' signature, Machine); reloaded when a file changed.
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


def folder_signature(folder):
    """Every file under the machine folder with its size and modification
    time (ns): a list edited, added or removed changes it."""
    files = []
    for top, dirs, names in os.walk(folder):
        dirs.sort()
        for name in sorted(names):
            path = os.path.join(top, name)
            try:
                st = os.stat(path)
            except OSError:
                continue
            files.append((os.path.relpath(path, folder), st.st_size, st.st_mtime_ns))
    return hash(tuple(files))


def machine(folder):
    """The folder's Machine, loaded again when one of its files changed."""
    from . import Machine
    key = os.path.abspath(os.fspath(folder))
    signature = folder_signature(key)
    cached = _machines.get(key)
    if cached is None or cached[0] != signature:
        cached = (signature, Machine(key))
        _machines[key] = cached
    return cached[1]


def _text(value):
    """An option as a table cell: a number stays one, a path str, a list or
    dict its JSON; None (not given) stays None."""
    if value is None or isinstance(value, (int, float, str)):
        return value
    if isinstance(value, os.PathLike):
        return os.fspath(value)
    try:
        return json.dumps(value)
    except (TypeError, ValueError):
        return repr(value)


def job_row(job):
    """The row's job columns; never raises on a malformed job."""
    parts = tuple(job) if isinstance(job, (tuple, list)) else (job,)
    machine_, program = (parts + (None, None))[:2]
    options = parts[2] if len(parts) > 2 and isinstance(parts[2], dict) else {}
    if isinstance(program, (list, tuple)):
        program = ";".join(str(_text(p)) for p in program)
    plc = options.get("plc")
    if isinstance(plc, (list, tuple)):
        plc = "; ".join(str(line) for line in plc)
    return {"machine": _text(machine_), "program": _text(program), "override": _text(options.get("override")),
            "feedhold": _text(options.get("feedhold")), "plc": _text(plc), "start_at": _text(options.get("start_at"))}


def failed_row(job, error_id, end, message):
    """The row of a job that did not run (exit 2)."""
    row = job_row(job)
    row.update(exit=2, end=end, time_s=0.0, errors=1, error_ids=str(error_id), warnings=0, worst_axis="",
               worst_axis_share=0.0, wall_s=0.0, message=message)
    return {k: row[k] for k in COLUMNS}


def run_job(job):
    """One job -> its result row (runs in a worker). Never raises: an
    nck.Error is exit 2 with its ID, anything else a job could get wrong
    (an option Machine.run does not take, a malformed job) exit 2 with 940201."""
    from . import Error
    start = time.perf_counter()
    try:
        if not isinstance(job, (tuple, list)) or len(job) not in (2, 3):
            raise TypeError(f"a job is (machine, program) or (machine, program, options), not {job!r}")
        options = job[2] if len(job) == 3 and job[2] is not None else {}
        if not isinstance(options, dict):
            raise TypeError(f"a job's options are a dict of Machine.run's arguments, not {options!r}")
        r = machine(job[0]).run(job[1], **{"events": False, **options})
    except Error as e:
        return {**failed_row(job, e.id, "not_run", str(e)), "wall_s": time.perf_counter() - start}
    except Exception as e:  # noqa: BLE001 - one bad job is one failed row, never the batch
        return {**failed_row(job, BAD_ARGUMENT, "not_run", f"{type(e).__name__}: {e}"),
                "wall_s": time.perf_counter() - start}
    axis, share = worst_axis(r.final)
    row = job_row(job)
    row.update(exit=r.exit, end=r.end, time_s=r.time_s, errors=len(r.errors),
               error_ids=" ".join(str(e["id"]) for e in r.errors), warnings=len(r.warnings),
               worst_axis=axis, worst_axis_share=share, wall_s=time.perf_counter() - start,
               message=r.errors[0]["msg"] if r.errors else "")
    return {k: row[k] for k in COLUMNS}
