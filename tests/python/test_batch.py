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
