#!/usr/bin/env python3
"""Stress test of the Python module (issue 45's campaign): threads sharing
sessions, runs, machines and batches (nck's exceptions, never a crash or a
hang), many runs in one process (RSS reaches a plateau), Ctrl-C during
every long call (KeyboardInterrupt within a second, the object usable
afterwards).

  PYTHONPATH=build/default/python /usr/bin/python3 tests/stress/py_stress.py \\
      [--threads 8] [--rounds 400] [--runs 1000] [--part threads,runs,ctrl_c] [--json out.json]

Each part runs in a child process of its own, so a crash is an exit by a
signal, not the end of the test. The short form runs in ctest
(tests/python/test_stress.py); the long form's figures are in
docs/robustness.md.
"""
import argparse
import gc
import json
import os
import pathlib
import random
import signal
import subprocess
import sys
import tempfile
import threading
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
MILL = ROOT / "examples" / "mill"
CONTOUR = MILL / "contour.nc"
# Calls a shared session may answer with (the operator's refusals, an MDI error).
SESSION_ERRORS = ("ActionError", "ProgramError")


def nck_module():
    import nck
    return nck


def write_programs(folder):
    """The long and the endless programs the Ctrl-C cases and runs use."""
    folder = pathlib.Path(folder)
    (folder / "slow.nc").write_text("G1 X100 F0.01\nM30\n")  # ends at max_time (86,400 s) only
    (folder / "loop.nc").write_text("#VAR\nV.L.I = 0\n#ENDVAR\n$WHILE 1 == 1\nV.L.I = V.L.I + 1\n$ENDWHILE\nM30\n")
    (folder / "many.nc").write_text("G90 G1 F60000\n" + "".join(f"N{i} X{i % 2}.0 Y{i % 3 * 0.5}\n"
                                                              for i in range(10, 3010)) + "M30\n")
    (folder / "bad.nc").write_text("G1 X10 F1000\nG1 Q=\nM30\n")
    return folder


def rss_mb():
    """Resident memory now (not the peak), MB."""
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1]) / 1024
    return 0.0


# -- threads ------------------------------------------------------------------
def session_call(nck, s, rng):
    """One random operation on a shared session; its name."""
    op = rng.choice(["step", "run_until", "state", "events", "errors", "override", "hold", "mdi", "reset",
                     "cycle_start", "time"])
    if op == "step":
        s.step(rng.randint(1, 300))
    elif op == "run_until":
        s.run_until(time_s=s.time_s + rng.random(), max_cycles=500)
    elif op == "state":
        s.state()
    elif op == "events":
        s.events()
    elif op == "errors":
        s.errors()
    elif op == "override":
        s.override(feed=rng.choice([10, 50, 100, 120]))
    elif op == "hold":
        s.hold(rng.random() < 0.5)
    elif op == "mdi":
        s.mdi(rng.choice(["G0 X1", "G1 Q=", "G4 F0.01"]))
    elif op == "reset":
        s.reset()
    elif op == "cycle_start":
        s.cycle_start()
    else:
        _ = s.time_s, s.cycles
    return op


def hammer(n_threads, work):
    """work(i) in n threads at once; their results, or the exception that
    escaped (a failure)."""
    results, escaped = [None] * n_threads, []

    def body(i):
        try:
            results[i] = work(i)
        except BaseException as e:  # noqa: B902 - anything that escapes is the finding
            escaped.append(f"{type(e).__name__}: {e}")

    threads = [threading.Thread(target=body, args=(i,)) for i in range(n_threads)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    return results, escaped


def shared_session(nck, n_threads, rounds):
    s = nck.Machine(MILL).session(CONTOUR, max_events_mb=1)  # small: the ring drops now and then

    def work(i):
        rng, calls, refused = random.Random(i), 0, {}
        for _ in range(rounds):
            try:
                session_call(nck, s, rng)
            except nck.Error as e:
                name = type(e).__name__
                if name not in SESSION_ERRORS:
                    raise
                refused[name] = refused.get(name, 0) + 1
            calls += 1
        return calls, refused

    results, escaped = hammer(n_threads, work)
    refused = {}
    for r in filter(None, results):
        for k, v in r[1].items():
            refused[k] = refused.get(k, 0) + v
    return {"calls": sum(r[0] for r in results if r), "refused": refused, "escaped": escaped,
            "cycles": s.cycles}


def shared_run(nck, n_threads, rounds, programs):
    """Threads reading one Run while gc callbacks hand the GIL around (the
    dicts of its events took the C++ events over: freed memory was read)."""
    m = nck.Machine(MILL)
    sys.setswitchinterval(1e-6)
    gc.set_threshold(50)
    gc.callbacks.append(lambda phase, info: time.sleep(0))
    lengths = set()
    try:
        for _ in range(max(1, rounds // 100)):
            r = m.run(programs / "many.nc", trace_every=10)
            results, escaped = hammer(n_threads, lambda i: (len(r.events), len(r.event_records), len(r.trace["t"]),
                                                            r.final["end"]))
            if escaped:
                return {"escaped": escaped}
            lengths.update(results)
    finally:
        gc.callbacks.clear()
        gc.set_threshold(700)
        sys.setswitchinterval(0.005)
    return {"escaped": [], "distinct_results": len(lengths)}


def shared_machine(nck, n_threads):
    m = nck.Machine(MILL)
    alone = m.run(CONTOUR).time_s
    results, escaped = hammer(n_threads, lambda i: m.run(CONTOUR).time_s)
    return {"escaped": escaped, "all_equal": all(t == alone for t in results)}


def shared_batch(nck, n_threads):
    """nck.batch from several threads at once, each on a thread pool."""
    import concurrent.futures
    jobs = [(str(MILL), str(CONTOUR)), (str(MILL), str(MILL / "nowhere.nc"))]
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        results, escaped = hammer(n_threads, lambda i: [r["exit"] for r in nck.batch(jobs, scheduler=pool)])
    return {"escaped": escaped, "all_equal": all(r == [0, 2] for r in results)}


def reentered_session(nck, programs):
    """A gc callback calling the session inside its own events(): SessionBusy, not a hang."""
    s = nck.Machine(MILL).session(programs / "many.nc")
    s.step(20000)
    seen = []

    def callback(phase, info):
        if phase == "start" and len(seen) < 5:
            try:
                s.state()
                seen.append("ran")
            except nck.SessionBusy as e:
                seen.append(e.id)

    gc.set_threshold(10)
    gc.callbacks.append(callback)
    try:
        s.events()
    finally:
        gc.callbacks.remove(callback)
        gc.set_threshold(700)
    s.step(10)  # usable afterwards
    return {"busy": seen.count(940203), "ran": seen.count("ran")}


def part_threads(args):
    nck = nck_module()
    with tempfile.TemporaryDirectory() as tmp:
        programs = write_programs(tmp)
        return {"threads": args.threads, "rounds": args.rounds,
                "session": shared_session(nck, args.threads, args.rounds),
                "run": shared_run(nck, args.threads, args.rounds, programs),
                "machine": shared_machine(nck, args.threads),
                "batch": shared_batch(nck, min(args.threads, 4)),
                "reentered": reentered_session(nck, programs)}


# -- runs -----------------------------------------------------------------------
def one_run(nck, m, i, programs):
    """Run i of the mix: events, a trace, an NC error, a session, a bad argument."""
    kind = i % 5
    if kind == 0:
        return len(m.run(CONTOUR).events)
    if kind == 1:
        return len(m.run(CONTOUR, trace_every=1, events=False).trace["t"])
    if kind == 2:
        return m.run(programs / "bad.nc").exit
    if kind == 3:
        s = m.session(CONTOUR)
        s.run_until(line=20)
        return len(s.events())
    try:
        m.run(CONTOUR, max_time=float("inf"))
    except nck.ArgumentError as e:
        return e.id


def part_runs(args):
    """RSS after every tenth of the runs: it should climb during the first
    runs (allocator pools, caches) and then stay."""
    nck = nck_module()
    with tempfile.TemporaryDirectory() as tmp:
        programs = write_programs(tmp)
        m = nck.Machine(MILL)
        one_run(nck, m, 0, programs)
        samples, start = [], time.monotonic()
        first = rss_mb()
        for i in range(args.runs):
            one_run(nck, m, i, programs)
            if (i + 1) % max(1, args.runs // 10) == 0:
                gc.collect()
                samples.append(round(rss_mb(), 1))
        half = samples[len(samples) // 2 - 1] if len(samples) >= 2 else first
        return {"runs": args.runs, "rss_start_mb": round(first, 1), "rss_samples_mb": samples,
                "rss_growth_second_half_mb": round(samples[-1] - half, 1), "wall_s": round(time.monotonic() - start, 1)}


# -- Ctrl-C -----------------------------------------------------------------------
CTRL_C_CASES = ["run", "step", "run_until", "parse", "busy_session", "batch"]
# Known to wait for the decoder's budget (docs/robustness.md): long form only.
CTRL_C_SLOW = ["session_decoder_loop"]


def long_call(nck, kind, programs):
    """(the call to interrupt, a check that what it used still works)."""
    m = nck.Machine(MILL)
    if kind == "run":
        return lambda: m.run(programs / "slow.nc"), lambda: m.run(CONTOUR).exit == 0
    if kind == "parse":
        return lambda: nck.parse(programs / "loop.nc"), lambda: len(nck.parse(CONTOUR)) > 0
    if kind == "batch":
        return (lambda: nck.batch([(str(MILL), str(programs / "slow.nc"))] * 2, workers=2),
                lambda: nck.batch([(str(MILL), str(CONTOUR))], workers=1)[0]["exit"] == 0)
    s = m.session(programs / ("loop.nc" if kind == "session_decoder_loop" else "slow.nc"))
    usable = lambda: (s.step(10), s.state()["cycle"] > 0)[1]  # noqa: E731
    if kind == "step" or kind == "session_decoder_loop":
        return lambda: s.step(10**12), usable
    if kind == "run_until":
        return lambda: s.run_until(line=99), usable
    # busy_session: another thread steps for long; this one waits for its turn
    threading.Thread(target=lambda: s.step(300_000_000), daemon=True).start()
    time.sleep(0.2)
    return lambda: s.state(), lambda: True


def child_ctrl_c(kind):
    """In the child: start the long call, say so, report how it ended."""
    nck = nck_module()
    with tempfile.TemporaryDirectory() as tmp:
        call, usable = long_call(nck, kind, write_programs(tmp))
        print("ready", flush=True)
        outcome = "returned"
        try:
            call()
        except KeyboardInterrupt:
            outcome = "KeyboardInterrupt"
        except nck.Error as e:
            outcome = f"nck.{type(e).__name__} {e.id}"
        ended = time.monotonic()
        import multiprocessing
        ok = usable() and not multiprocessing.active_children()  # a batch's workers are gone too
        print(json.dumps({"outcome": outcome, "ended": ended, "usable": ok}), flush=True)


def ctrl_c_case(kind, delay_s=None, limit_s=120):
    """Runs child_ctrl_c(kind), sends SIGINT after delay_s; how it ended,
    and the seconds from the signal to the call's end."""
    if delay_s is None:  # a batch's workers need a few seconds to start and take their jobs
        delay_s = 4.0 if kind == "batch" else 0.7
    # a group of its own: SIGINT to the child alone (as Jupyter's interrupt
    # sends it; a terminal's reaches the whole group), and whatever it
    # leaves behind (a batch's workers held its pipes open) killed with it
    p = subprocess.Popen([sys.executable, __file__, "--child-ctrl-c", kind], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True, start_new_session=True)
    try:
        if p.stdout.readline().strip() != "ready":
            p.wait(timeout=limit_s)
            return {"case": kind, "outcome": "no start", "stderr": p.stderr.read()[-2000:]}
        time.sleep(delay_s)
        sent = time.monotonic()
        p.send_signal(signal.SIGINT)
        out, err = p.communicate(timeout=limit_s)
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        p.wait()
        return {"case": kind, "outcome": f"hung over {limit_s} s", "returncode": None}
    finally:
        try:
            os.killpg(p.pid, signal.SIGKILL)  # nothing of the case outlives it
        except ProcessLookupError:
            pass
    last = (out.strip().splitlines() or ["{}"])[-1]
    try:
        report = json.loads(last)
    except json.JSONDecodeError:
        return {"case": kind, "outcome": "crashed", "returncode": p.returncode, "stderr": err[-2000:]}
    return {"case": kind, "outcome": report["outcome"], "seconds": round(report["ended"] - sent, 2),
            "usable": report["usable"], "returncode": p.returncode}


def part_ctrl_c(args):
    cases = CTRL_C_CASES + (CTRL_C_SLOW if args.slow_cases else [])
    return [ctrl_c_case(kind) for kind in cases]


# -- main -------------------------------------------------------------------------
def run_part(name, args):
    """A part in a child process: a crash is its exit code."""
    cmd = [sys.executable, __file__, "--child-part", name, "--threads", str(args.threads), "--rounds",
           str(args.rounds), "--runs", str(args.runs)] + (["--slow-cases"] if args.slow_cases else [])
    start = time.monotonic()
    p = subprocess.run(cmd, capture_output=True, text=True)
    out = {"part": name, "returncode": p.returncode, "wall_s": round(time.monotonic() - start, 1)}
    try:
        out["result"] = json.loads(p.stdout.strip().splitlines()[-1])
    except (IndexError, json.JSONDecodeError):
        out["stderr"] = p.stderr[-3000:]
    return out


PARTS = {"threads": part_threads, "runs": part_runs, "ctrl_c": part_ctrl_c}


def main(argv=None):
    a = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    a.add_argument("--threads", type=int, default=8)
    a.add_argument("--rounds", type=int, default=400, help="calls per thread on the shared session")
    a.add_argument("--runs", type=int, default=1000)
    a.add_argument("--part", default="threads,runs,ctrl_c")
    a.add_argument("--slow-cases", action="store_true", help="also the Ctrl-C cases known to be slow")
    a.add_argument("--json", help="write the results here too")
    a.add_argument("--child-part", help=argparse.SUPPRESS)
    a.add_argument("--child-ctrl-c", help=argparse.SUPPRESS)
    args = a.parse_args(argv)
    if args.child_ctrl_c:
        return child_ctrl_c(args.child_ctrl_c)
    if args.child_part:
        print(json.dumps(PARTS[args.child_part](args)), flush=True)
        return 0
    results = [run_part(p, args) for p in args.part.split(",")]
    text = json.dumps(results, indent=1)
    print(text)
    if args.json:
        pathlib.Path(args.json).write_text(text)
    return 0 if all(r["returncode"] == 0 for r in results) else 1


if __name__ == "__main__":
    sys.exit(main())
