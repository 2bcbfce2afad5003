"""nck.parse, nck.errors, nck.params, and the fuzz findings fed through the
module: an exception of nck's classes or a result, never a crash or a hang."""
import json
import pathlib
import shutil
import subprocess

import pytest

import nck
from conftest import EXAMPLES, ROOT

FINDINGS = ROOT / "fuzz" / "findings"


def test_parse_gives_the_blocks_of_nck_parse_json(nck_binary):
    prog = EXAMPLES / "mill" / "contour.nc"
    out = subprocess.run([nck_binary, "parse", "--json", str(prog)], capture_output=True, text=True, check=True)
    assert nck.parse(prog) == [json.loads(line) for line in out.stdout.splitlines()]


def test_parse_raises_program_error_with_every_diagnostic(program):
    with pytest.raises(nck.ProgramError) as e:
        nck.parse(program("G1 X1 F100\nG1 Q=\nG1 Q=\nM30\n"))
    assert e.value.line == 2 and len(e.value.diagnostics) >= 2
    with pytest.raises(nck.ProgramError) as e:
        nck.parse("/no/such/program.nc")
    assert e.value.id == 940202


def test_errors_and_params_list_the_tables():
    ids = {e["id"]: e for e in nck.errors()}
    assert ids[940200]["name"] == "AppTraceMemoryLimit" and ids[940200]["remedy"]
    params = nck.params()
    assert any(p["id"].startswith("P-AXIS-") for p in params) and all(p["key"] for p in params)


@pytest.mark.parametrize("path", sorted((FINDINGS / "decoder").iterdir()), ids=lambda p: p.name)
def test_decoder_findings_parse_and_run_without_a_crash(mill, path):
    try:
        nck.parse(path, max_wall=5)
    except nck.Error as e:
        assert e.id > 0
    r = mill.run(path, max_wall=5, max_time=60)
    assert r.exit in (0, 1)


@pytest.mark.parametrize("path", sorted((FINDINGS / "scenario").iterdir()), ids=lambda p: p.name)
def test_scenario_findings_run_without_a_crash(mill, path):
    try:
        r = mill.run(EXAMPLES / "mill" / "contour.nc", plc=path, max_wall=5, max_time=60)
        assert r.exit in (0, 1)
    except nck.Error as e:
        assert e.id > 0


@pytest.mark.parametrize("path", sorted((FINDINGS / "list").iterdir()), ids=lambda p: p.name)
def test_list_findings_load_without_a_crash(tmp_path, path):
    folder = tmp_path / "m"
    shutil.copytree(EXAMPLES / "mill", folder)
    shutil.copy(path, folder / "x.lis")
    try:
        nck.Machine(folder)
    except nck.ConfigError as e:
        assert e.id > 0 and e.diagnostics
