"""nck.batch on local processes and on a Dask LocalCluster of two workers."""
import csv
import os
import subprocess
import sys

import pytest

import nck
from conftest import EXAMPLES, ROOT

MILL, LATHE = str(EXAMPLES / "mill"), str(EXAMPLES / "lathe")
JOBS = [(MILL, str(EXAMPLES / "mill" / "contour.nc")),
        (LATHE, str(EXAMPLES / "lathe" / "turn.nc"), {"max_time": 600}),
        (MILL, str(EXAMPLES / "mill" / "nowhere.nc"))]


def check(rows):
    assert [r["program"] for r in rows] == [j[1] for j in JOBS]  # the jobs' order
    good = nck.Machine(MILL).run(JOBS[0][1])
    assert rows[0]["exit"] == 0 and rows[0]["time_s"] == pytest.approx(good.time_s)
    assert rows[0]["errors"] == 0 and 0 <= rows[0]["worst_axis_share"] <= 1
    assert rows[1]["exit"] == 0 and rows[1]["end"] == "program_end"
    assert rows[2]["exit"] == 2 and rows[2]["error_ids"] == "940202"


def test_batch_on_local_processes():
    check(nck.batch(JOBS, workers=2))


def test_batch_on_a_dask_local_cluster_of_two_workers():
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  dashboard_address=None) as cluster:
        check(nck.batch(JOBS, scheduler=cluster.scheduler_address))


def test_python_m_nck_batch_writes_the_csv(tmp_path):
    out = tmp_path / "results.csv"
    env = dict(os.environ)
    rc = subprocess.run([sys.executable, "-m", "nck", "batch", f"{MILL},{LATHE}",
                         str(EXAMPLES / "mill" / "contour.nc"), "--workers", "2", "--out", str(out)],
                        env=env, capture_output=True, text=True)
    rows = list(csv.DictReader(out.open()))
    assert len(rows) == 2 and rows[0]["machine"] == MILL and rows[1]["machine"] == LATHE
    assert rows[0]["exit"] == "0"
    assert rc.returncode == (0 if rows[1]["exit"] == "0" else 1), rc.stderr


def test_worst_axis_reads_time_by_cause():
    from nck._batch import worst_axis
    final = {"time_by_cause": {"channels": [{"time_s": 2.0, "causes": [
        {"cause": "axis_velocity", "axis": "X", "time_s": 0.5},
        {"cause": "acceleration", "axis": "X", "time_s": 0.3},
        {"cause": "acceleration", "axis": "Y", "time_s": 0.6},
        {"cause": "feed", "time_s": 0.6}]}]}}
    assert worst_axis(final) == ("X", pytest.approx(0.4))
    assert worst_axis({}) == ("", 0.0)


class _KillsItsWorker:
    """Unpickled in the worker, it ends that process at once (as a kill or
    the OOM killer would): the job that carries it is the one that dies."""

    def __reduce__(self):
        return (os._exit, (9,))


def test_one_failing_job_is_one_failed_row():
    good = (MILL, str(EXAMPLES / "mill" / "contour.nc"))
    jobs = [good, (MILL, good[1], {"no_such_option": 1}), (MILL, good[1], {"override": "fast"}),
            (MILL, "nowhere.nc"), ("no/machine", good[1]), ("just one thing",), good]
    rows = nck.batch(jobs, workers=2)
    assert [r["exit"] for r in rows] == [0, 2, 2, 2, 2, 2, 0]
    assert [r["error_ids"] for r in rows[1:4]] == ["940201", "940201", "940202"]
    assert "no_such_option" in rows[1]["message"] and rows[4]["error_ids"] and rows[5]["end"] == "not_run"


def test_a_killed_worker_is_one_failed_row():
    good = (MILL, str(EXAMPLES / "mill" / "contour.nc"))
    jobs = [good, good, (MILL, good[1], {"kill": _KillsItsWorker()}), good, good]
    rows = nck.batch(jobs, workers=2)
    assert [r["exit"] for r in rows] == [0, 0, 2, 0, 0]
    assert rows[2]["end"] == "worker_lost" and rows[2]["error_ids"] == "940005"


def test_paths_are_made_absolute_on_the_client(monkeypatch):
    monkeypatch.chdir(ROOT)
    row = nck.batch([("examples/mill", "examples/mill/contour.nc", {"plc": "examples/mill/spindle.plc"})],
                    workers=1)[0]
    assert row["machine"] == MILL and row["program"] == str(EXAMPLES / "mill" / "contour.nc")
    assert row["plc"] == str(EXAMPLES / "mill" / "spindle.plc") and row["exit"] == 0


def test_a_changed_machine_folder_is_loaded_again(tmp_path):
    import concurrent.futures
    import shutil
    folder = tmp_path / "mill"
    shutil.copytree(MILL, folder)
    job = (str(folder), str(EXAMPLES / "mill" / "contour.nc"))
    with concurrent.futures.ThreadPoolExecutor(1) as pool:  # one process: its cache is this one
        assert nck.batch([job], scheduler=pool)[0]["exit"] == 0
        lines = (folder / "x.lis").read_text().splitlines(keepends=True)
        lines.insert(4, "kenngr.achs_typ   KEIN_TYP\n")
        (folder / "x.lis").write_text("".join(lines))
        row = nck.batch([job], scheduler=pool)[0]
    assert row["exit"] == 2 and row["end"] == "not_run"  # the bad data, not the machine cached before


def test_each_row_carries_its_jobs_options():
    prog = str(EXAMPLES / "mill" / "contour.nc")
    rows = nck.batch([(MILL, prog, {"override": 50, "feedhold": (1, 2)}),
                      (MILL, prog, {"plc": ["0.5 feedhold on", "1 feedhold off"], "start_at": "N170"}),
                      (MILL, prog)], workers=2)
    assert (rows[0]["override"], rows[0]["feedhold"], rows[0]["plc"]) == (50, "[1, 2]", None)
    assert rows[1]["plc"] == "0.5 feedhold on; 1 feedhold off" and rows[1]["start_at"] == "N170"
    assert rows[2]["override"] is None and rows[0]["time_s"] > rows[2]["time_s"]


def test_as_frame_without_pandas_raises_an_nck_error(monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)  # import pandas raises ImportError
    with pytest.raises(nck.ArgumentError) as e:
        nck.batch([JOBS[0]], workers=1, as_frame=True)
    assert e.value.id == 940201 and "pandas" in e.value.message


def test_as_frame_is_a_dataframe_of_the_rows():
    pandas = pytest.importorskip("pandas")
    frame = nck.batch(JOBS, workers=2, as_frame=True)
    assert isinstance(frame, pandas.DataFrame) and list(frame.columns) == nck._batch.COLUMNS
    assert list(frame["exit"]) == [0, 0, 2]


def test_python_m_nck_batch_takes_the_sweep_options(tmp_path):
    out = tmp_path / "sweep.csv"
    rc = subprocess.run([sys.executable, "-m", "nck", "batch", MILL, str(EXAMPLES / "mill" / "contour.nc"),
                         "--override", "50,100", "--start-at", "N170", "--start-at", "N10", "--workers", "2",
                         "--out", str(out)], capture_output=True, text=True)
    rows = list(csv.DictReader(out.open()))
    assert rc.returncode == 0, rc.stderr
    assert [(r["override"], r["start_at"]) for r in rows] == [("50.0", "N170"), ("50.0", "N10"),
                                                             ("100.0", "N170"), ("100.0", "N10")]


def test_the_docs_warn_about_the_main_guard():
    guard = 'if __name__ == "__main__":'
    assert guard in (ROOT / "docs" / "python.md").read_text() and guard in nck.batch.__doc__
