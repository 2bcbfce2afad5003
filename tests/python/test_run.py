"""Machine.run: the same run as `nck run`, in memory."""
import json
import os
import re
import subprocess
import threading

import numpy as np
import pytest

import nck
from conftest import EXAMPLES, ROOT

# (machine folder, programs): every example folder, one program per channel.
EXAMPLE_RUNS = [
    ("mill", ["contour.nc"]),
    ("lathe", ["turn.nc"]),
    ("cutter", ["contour.nc"]),
    ("two-channel", ["channel1.nc", "channel2.nc"]),
    ("twin-spindle", ["twin.nc"]),
]


def cli_run(nck_binary, tmp_path, folder, programs, *extra):
    events, final, trace = tmp_path / "e.jsonl", tmp_path / "f.json", tmp_path / "t.csv"
    cmd = [nck_binary, "run", str(folder), *map(str, programs), "--events", str(events), "--final", str(final),
           "--trace", str(trace), *extra]
    rc = subprocess.run(cmd, capture_output=True, text=True).returncode
    return rc, [json.loads(line) for line in events.read_text().splitlines()], json.loads(final.read_text()), trace


@pytest.mark.parametrize("folder,programs", EXAMPLE_RUNS)
def test_an_example_runs_as_the_command_line_runs_it(nck_binary, tmp_path, folder, programs):
    paths = [EXAMPLES / folder / p for p in programs]
    r = nck.Machine(EXAMPLES / folder).run(paths if len(paths) > 1 else paths[0])
    rc, events, final, _ = cli_run(nck_binary, tmp_path, EXAMPLES / folder, paths)
    assert r.exit == rc == 0
    assert r.end == "program_end" and r.errors == []
    assert r.time_s == pytest.approx(final["time"]) and r.time_s > 0
    assert r.events == events
    assert r.final == final
    assert r.trace is None
    assert r.summary().startswith("nck: ") and r.summary() == r.messages[-1]


def test_the_trace_holds_the_csv_columns_at_full_precision(nck_binary, tmp_path):
    prog = EXAMPLES / "mill" / "contour.nc"
    r = nck.Machine(EXAMPLES / "mill").run(prog, trace_every=10)
    # Python's trace has path.v by default: the CSV has it with --trace-columns
    _, _, _, trace = cli_run(nck_binary, tmp_path, EXAMPLES / "mill", [prog], "--trace-every", "10",
                             "--trace-columns", "path.v")
    header = trace.read_text().splitlines()[0].split(",")
    csv = np.loadtxt(trace, delimiter=",", skiprows=1, ndmin=2)
    assert list(r.trace) == header
    for i, name in enumerate(header):
        column = r.trace[name]
        assert column.dtype == np.float64 and column.shape == (csv.shape[0],)
        assert np.allclose(column, csv[:, i], atol=1e-3), name
    assert r.trace["t"][1] - r.trace["t"][0] == pytest.approx(0.010)


def test_the_trace_memory_limit_ends_the_run_with_an_id(mill):
    r = mill.run(EXAMPLES / "mill" / "contour.nc", trace_every=1, max_trace_mb=0.01)
    assert r.exit == 1 and r.end == "max_trace"
    assert [e["id"] for e in r.errors] == [940200]
    rows = len(r.trace["t"])
    assert 0 < rows * len(r.trace) * 8 <= 0.01 * 1024 * 1024


def test_stop_at_and_max_time_end_the_run_where_asked(mill):
    prog = EXAMPLES / "mill" / "contour.nc"
    full = mill.run(prog)
    stopped = mill.run(prog, max_time=full.time_s / 2)
    assert stopped.end == "max_time" and stopped.exit == 1
    assert stopped.time_s == pytest.approx(full.time_s / 2, abs=0.002)
    assert mill.run(prog, stop_at="event:wait").end in ("stop_at", "program_end")


def test_an_nc_error_is_a_result_not_an_exception(mill, program):
    r = mill.run(program("G1 X10 F1000\nG1 Q=\nM30\n"))
    assert r.exit == 1 and r.end == "error"
    assert r.errors and r.errors[0]["line"] == 2 and r.errors[0]["id"] > 0
    assert any(e["ev"] == "error" for e in r.events)


def test_a_missing_machine_folder_raises_config_error(tmp_path):
    with pytest.raises(nck.ConfigError) as e:
        nck.Machine(tmp_path / "nowhere")
    assert e.value.id > 0 and e.value.message and e.value.diagnostics


def test_bad_machine_data_raises_config_error_with_file_and_line(tmp_path):
    import shutil
    folder = tmp_path / "mill"
    shutil.copytree(EXAMPLES / "mill", folder)
    lines = (folder / "x.lis").read_text().splitlines(keepends=True)
    lines.insert(4, "kenngr.achs_typ   KEIN_TYP\n")  # a value that is no axis type, on line 5
    (folder / "x.lis").write_text("".join(lines))
    with pytest.raises(nck.ConfigError) as e:
        nck.Machine(folder)
    err = e.value
    assert isinstance(err, nck.Error)
    assert err.file.endswith("x.lis") and err.line == 5
    assert str(err.id) in str(err)


def test_bad_arguments_raise_documented_classes(mill, tmp_path):
    prog = EXAMPLES / "mill" / "contour.nc"
    with pytest.raises(nck.ProgramError) as e:
        mill.run(tmp_path / "missing.nc")
    assert e.value.id == 940202 and e.value.file.endswith("missing.nc")
    with pytest.raises(nck.ArgumentError) as e:
        mill.run(prog, stop_at="somewhere")
    assert e.value.id == 940201
    with pytest.raises(ValueError):  # ArgumentError is a ValueError too
        mill.run(prog, trace_every=-1)
    with pytest.raises(nck.ArgumentError):
        mill.run(prog, max_time=-5)
    with pytest.raises(TypeError):
        mill.run(prog, no_such_option=1)
    with pytest.raises(nck.ProgramError) as e:
        mill.run(prog, plc=tmp_path / "missing.plc")
    assert e.value.id == 940003


def test_events_false_keeps_none_and_changes_nothing_else(mill):
    prog = EXAMPLES / "mill" / "contour.nc"
    with_events, without = mill.run(prog), mill.run(prog, events=False)
    assert with_events.events and without.events == []
    assert without.final == with_events.final and without.summary() == with_events.summary()


def test_start_at_runs_a_block_search(mill):
    prog = EXAMPLES / "mill" / "contour.nc"
    full, searched = mill.run(prog), mill.run(prog, start_at="N170")
    assert searched.exit == 0 and searched.time_s < full.time_s
    assert searched.final["channels"][0]["axes"] == full.final["channels"][0]["axes"]
    with pytest.raises(nck.ArgumentError):
        mill.run(prog, start_at="N")


def test_threads_may_share_a_machine(mill):
    # each run has its own simulation over the machine's data, which no run
    # changes: four at once give the run alone's events
    alone = mill.run(EXAMPLES / "mill" / "contour.nc").events
    runs = [None] * 4

    def run(i):
        runs[i] = mill.run(EXAMPLES / "mill" / "contour.nc").events

    threads = [threading.Thread(target=run, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert all(r == alone for r in runs)


def test_the_version_is_cmakes():
    """nck.__version__ is CMake's project(VERSION), as `nck --version` prints it (issue 47, item 2)."""
    cmake = re.search(r"project\(nck VERSION ([0-9.]+)", (ROOT / "CMakeLists.txt").read_text()).group(1)
    assert nck.__version__ == cmake
    cli = subprocess.run([os.environ.get("NCK_BINARY", str(ROOT / "build/default/nck")), "--version"],
                         capture_output=True, text=True, check=True)
    assert cli.stdout.startswith(f"nck {cmake} (git ")
