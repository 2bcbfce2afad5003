"""One shape per concept on every surface (issue 47 item 5): a diagnostic is
{id, severity, name, message, remedy, file, line, column, channel} in
`nck check --json`, the events of `nck run`, --final, the HTTP API and the
Python module; the state document is one (Session.state() and
GET /api/v1/state); exceptions carry the specific ID."""
import json
import re
import subprocess
import time
import urllib.request

import pytest

import nck
from conftest import EXAMPLES

SHAPE = {"id", "severity", "name", "message", "remedy", "file", "line", "column", "channel"}
MILL = str(EXAMPLES / "mill")
# 930003: X 650 lies beyond the mill's software limit (a planning error at line 2)
BEYOND = "G90 G1 X10 F3000\nG0 X650\nM30\n"


def shape_of(d):
    return {k for k in d if k in SHAPE}


def test_a_diagnostic_has_the_same_shape_on_every_surface(nck_binary, mill, program, tmp_path):
    prog = program(BEYOND)
    check = json.loads(subprocess.run([nck_binary, "check", MILL, prog, "--json"], capture_output=True,
                                      text=True).stdout)
    found = next(d for d in check if d["id"] == 930003)
    assert set(found) <= SHAPE and {"id", "severity", "name", "message", "remedy"} <= set(found)

    events, final = tmp_path / "ev.jsonl", tmp_path / "final.json"
    subprocess.run([nck_binary, "run", MILL, prog, "--events", str(events), "--final", str(final)],
                   capture_output=True)
    event = next(e for e in map(json.loads, events.read_text().splitlines()) if e["ev"] == "error")
    in_final = json.loads(final.read_text())["errors"][0]
    run_errors = mill.run(prog).errors
    session = mill.session(prog)
    session.run_until(event="error")
    last = session.state()["last_error"]
    served = served_last_error(nck_binary, prog)

    surfaces = {"check": found, "event": event, "final": in_final, "Run.errors": run_errors[0],
                "Session.state": last, "HTTP": served}
    for name, d in surfaces.items():
        assert d["id"] == 930003, name
        assert shape_of(d) == shape_of(found), name
        for key in ("severity", "name", "remedy", "file", "line", "channel"):
            assert d[key] == found[key], (name, key)
    assert found["channel"] == 1 and found["line"] == 2 and found["file"] == prog
    assert "column" not in found  # a planning error is at a block: no column, and no placeholder


def served_last_error(nck_binary, prog):
    """nck serve on a free port: cycle start, then /api/v1/state's last_error."""
    proc = subprocess.Popen([nck_binary, "serve", MILL, prog, "--port", "0", "--max-wall", "60", "--no-realtime"],
                            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    try:
        m = re.search(r"http://127\.0\.0\.1:(\d+)/\?token=([0-9a-f]+)", proc.stdout.readline())
        port, token = m.group(1), m.group(2)

        def call(path, body=None):
            req = urllib.request.Request(f"http://127.0.0.1:{port}{path}", data=body,
                                         headers={"Authorization": f"Bearer {token}"})
            with urllib.request.urlopen(req, timeout=5) as r:
                return json.loads(r.read())
        call("/api/v1/command", json.dumps({"command": "cycle_start"}).encode())
        for _ in range(250):
            st = call("/api/v1/state")
            if st["last_error"]:
                return st["last_error"]
            time.sleep(0.02)
        raise AssertionError("no last_error in /api/v1/state")
    finally:
        proc.terminate()
        proc.wait(10)


def test_the_session_state_is_the_servers_document_with_its_own_fields(mill, program):
    s = mill.session(program(BEYOND))
    s.step(10)
    st = s.state()
    # the server's document (docs/api.md) ...
    assert {"t_s", "cycle", "run", "paused", "speed", "channels", "spindles", "lateness", "events_lost",
            "last_error"} <= set(st)
    ch = st["channels"][0]
    assert {"channel", "state", "program_state", "mcs", "pcs", "axes", "path_velocity_mm_s", "feed_mm_s",
            "distance_to_go_mm", "cause", "wait", "modal", "block", "feed_override_pct", "rapid_override_pct",
            "feedhold", "single_step", "optional_stop", "manual_mode", "skip_mask", "last_error"} <= set(ch)
    assert ch["state"] == ch["program_state"] == "running" and ch["axes"]["X"]["mcs"] == ch["mcs"]["X"]
    assert {"set_rpm", "act_rpm", "pos_deg", "gear", "override_pct", "speed_reached", "stopped"} <= set(st["spindles"]["S1"])
    # ... and the session's fields from before it stay
    assert {"t", "hli", "links"} <= set(st) and {"ch", "status", "line", "n", "file", "offsets", "tool"} <= set(ch)
    assert st["last_error"] is None and ch["last_error"] is None and st["run"] == 1


def test_an_error_stays_in_the_state_until_reset(mill, program):
    s = mill.session(program(BEYOND))
    assert s.run_until(event="error")
    st = s.state()
    assert st["last_error"]["id"] == 930003 and st["channels"][0]["last_error"] == st["last_error"]
    s.reset()
    s.step(2)
    assert s.state()["last_error"] is None and s.state()["channels"][0]["last_error"] is None


def test_an_mdi_error_is_in_the_state_and_raised_with_its_id(mill):
    s = mill.session()
    with pytest.raises(nck.ProgramError) as e:
        s.mdi("G0 X1 ?")
    assert e.value.id == 920003 and e.value.name == "NcUnexpectedCharacter" and e.value.remedy
    assert s.state()["last_error"]["id"] == 920003
    assert shape_of(e.value.diagnostics[0]) <= SHAPE and e.value.diagnostics[0]["file"] == "MDI"
    assert s.state()["channels"][0]["program_state"] == "idle"  # an MDI error leaves the channel idle
    s.reset()  # ... and the reset of the idle channel clears the error (no state change says so)
    s.step(1)
    assert s.state()["last_error"] is None


@pytest.mark.parametrize("call, wanted", [
    (lambda s: s.override(feed=201), 960003),
    (lambda s: s.action("feed_override 201"), 960003),
    (lambda s: s.jog("Q", "+"), 960013),
    (lambda s: s.action("ch=7 feedhold on"), 960008),
])
def test_action_errors_carry_their_own_id_and_no_placeholder_place(mill, call, wanted):
    s = mill.session()
    with pytest.raises(nck.ActionError) as e:
        call(s)
    assert e.value.id == wanted  # the grammar's own ID, not 960040 with it in the text
    d = e.value.diagnostics[0]
    assert d["id"] == e.value.id and "file" not in d and "line" not in d  # no "python", 1
    assert {"id", "severity", "name", "message", "remedy"} <= set(d) and set(d) <= SHAPE | {"msg"}


def test_the_catalogue_is_one_shape_too(mill):
    first = nck.errors()[0]
    assert list(first)[:5] == ["id", "severity", "name", "cause", "remedy"] and first["text"] == first["cause"]


def test_the_state_gives_each_axis_its_distance_to_go(mill, program):
    # issue 47 item 5 / issue 48 item 7: per axis the motion's end minus the set point
    s = mill.session(program("G90 G1 X10 Y5 F600\nM30\n"))
    assert s.run_until(time_s=0.5)
    ch = s.state()["channels"][0]
    dtg = ch["dtg"]
    # (at the state's resolution, 0.1 µm)
    assert 0 < dtg["X"] < 12 and dtg["X"] == pytest.approx(2 * dtg["Y"], abs=3e-4) and dtg["Z"] == 0
    assert (dtg["X"] ** 2 + dtg["Y"] ** 2) ** 0.5 == pytest.approx(ch["distance_to_go_mm"], abs=3e-4)
    assert all(ch["axes"][a]["dtg"] == dtg[a] for a in dtg)
    assert s.run_until(event="end")
    assert all(v == 0 for v in s.state()["channels"][0]["dtg"].values())


def test_a_lathe_shows_x_as_a_diameter_under_g51(program):
    # P-CHAN-00256 display_diameter_pos 1 in examples/lathe: under G51 the
    # face axis reads as a diameter (pcs_diameter), under G52 as a radius
    lathe = nck.Machine(str(EXAMPLES / "lathe"))
    s = lathe.session(program("G90 G52 G0 X20 Z5\nM0\nG51 G0 X30\nM0\nM30\n"))
    assert s.run_until(event="stop")
    ch = s.state()["channels"][0]
    assert ch["diameter_display"] is False and ch["modal"]["diameter"] == "G52"
    s.cycle_start()
    assert s.run_until(event="stop")
    ch = s.state()["channels"][0]
    assert ch["diameter_display"] is True and ch["modal"]["diameter"] == "G51"
    assert ch["axes"]["X"]["pcs"] == pytest.approx(15) and ch["axes"]["X"]["pcs_diameter"] == pytest.approx(30)
    assert "pcs_diameter" not in ch["axes"]["Z"]


def test_state_numbers_are_at_the_controls_resolution(mill, program):
    # issue 48 item 4: 0.1 µm / 0.0001°, no floating-point noise in the document
    s = mill.session(program("G90 G2 X10 Y0 I5 J0 F777\nM30\n"))
    assert s.run_until(time_s=0.37)
    ch = s.state()["channels"][0]
    values = [*ch["mcs"].values(), *ch["pcs"].values(), *ch["dtg"].values(), ch["path_velocity_mm_s"],
              ch["feed_mm_s"], ch["distance_to_go_mm"]]
    assert all(round(v, 4) == v and len(repr(v).split(".")[-1]) <= 4 for v in values), values
    assert ch["feed_mm_s"] == 12.95  # F777 mm/min
