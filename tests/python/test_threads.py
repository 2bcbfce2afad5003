"""Threads sharing the module's objects (issue 45, item 1): nck's own
exceptions, never a crash or a hang. A case that crashed or hung before runs
in a child process with a time limit, so that it fails instead of ending
the test run. (Sessions shared by stepping threads: test_session.py;
machines: test_run.py.)"""
import concurrent.futures
import subprocess
import sys
import textwrap
import threading

import nck
from conftest import EXAMPLES, ROOT

MILL, CONTOUR = EXAMPLES / "mill", EXAMPLES / "mill" / "contour.nc"


def child(code, timeout_s=120):
    """Runs code in a fresh interpreter (cwd: the repository); (exit code, stdout), exit None when it hung."""
    try:
        p = subprocess.run([sys.executable, "-c", textwrap.dedent(code)], capture_output=True, text=True,
                           timeout=timeout_s, cwd=ROOT)
    except subprocess.TimeoutExpired:
        return None, "hung"
    return p.returncode, p.stdout + p.stderr


MANY_BLOCKS = """
    import pathlib, tempfile
    prog = pathlib.Path(tempfile.mkdtemp()) / "many.nc"
    prog.write_text("G90 G1 F60000\\n" + "".join(f"N{i} X{i % 2}.0 Y{i % 3 * 0.5}\\n" for i in range(10, 3010)) + "M30\\n")
"""


def test_threads_may_share_a_run():
    # Run.events took the C++ events over while converting them; a gc
    # callback lets another thread in, which converted them too and freed
    # them under the first: SIGSEGV or a UnicodeDecodeError of freed bytes
    # in 3 of 3 runs before
    rc, out = child(MANY_BLOCKS + """
    import gc, sys, threading, time
    import nck
    sys.setswitchinterval(1e-6)
    gc.set_threshold(50)
    gc.callbacks.append(lambda phase, info: time.sleep(0))
    m = nck.Machine("examples/mill")
    for _ in range(5):
        r = m.run(prog, trace_every=10)
        seen = []
        ts = [threading.Thread(target=lambda: seen.append((len(r.events), len(r.event_records), len(r.trace["t"]))))
              for _ in range(4)]
        for t in ts: t.start()
        for t in ts: t.join()
        assert len(set(seen)) == 1 and len(seen) == 4, seen
    print("ok")
    """)
    assert rc == 0 and out.strip().endswith("ok"), out[-2000:]


def test_threads_reading_numpy_values_first_at_once_do_not_deadlock():
    # pybind11 found numpy's C API on first use under a static guard held
    # across numpy's import, which lets other threads run: one that came for
    # the guard holding the GIL deadlocked both (5 of 5 runs hung before)
    rc, out = child("""
    import sys, threading
    import nck
    sys.setswitchinterval(1e-6)
    r = nck.Machine("examples/mill").run("examples/mill/contour.nc", trace_every=10)
    seen = []
    ts = [threading.Thread(target=lambda: seen.append(len(r.trace["t"]))) for _ in range(4)]
    for t in ts: t.start()
    for t in ts: t.join()
    assert len(seen) == 4 and len(set(seen)) == 1, seen
    print("ok")
    """, timeout_s=60)
    assert rc == 0 and out.strip().endswith("ok"), out[-2000:]


def test_a_session_called_inside_its_own_call_raises_session_busy():
    # a gc callback calling the session while its events() converts waited
    # for its own thread's turn for ever (hung before); now SessionBusy 940203
    rc, out = child(MANY_BLOCKS + """
    import gc
    import nck
    s = nck.Machine("examples/mill").session(prog)
    s.step(20000)
    seen = []
    def callback(phase, info):
        if phase == "start" and len(seen) < 3:
            try:
                s.state()
                seen.append("ran")
            except nck.SessionBusy as e:
                seen.append((e.id, isinstance(e, nck.Error), isinstance(e, RuntimeError)))
    gc.set_threshold(10)
    gc.callbacks.append(callback)
    events = s.events()
    gc.callbacks.remove(callback)
    s.step(10)
    busy = (940203, True, True)  # a collection may come before events() takes the session: "ran"
    assert len(events) > 100 and busy in seen and set(seen) <= {busy, "ran"}, seen
    print("ok")
    """, timeout_s=60)
    assert rc == 0 and out.strip().endswith("ok"), out[-2000:]


def test_threads_may_share_batches():
    # nck.batch from four threads at once on one thread pool: every row as
    # a batch alone gives it (passed before too: batch objects live in
    # Python; the cached machines are shared read-only)
    jobs = [(str(MILL), str(CONTOUR)), (str(MILL), str(MILL / "nowhere.nc"))]
    rows = [None] * 4
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        alone = nck.batch(jobs, scheduler=pool)

        def run(i):
            rows[i] = nck.batch(jobs, scheduler=pool)

        threads = [threading.Thread(target=run, args=(i,)) for i in range(4)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
    assert [r["exit"] for r in alone] == [0, 2]
    strip = [[{k: v for k, v in row.items() if k != "wall_s"} for row in rs] for rs in rows + [alone]]
    assert all(s == strip[-1] for s in strip)
