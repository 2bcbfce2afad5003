"""Shared fixtures: the repo root, the nck binary, and nck imported from the
build tree (ctest sets PYTHONPATH and NCK_BINARY; see tests/CMakeLists.txt)."""
import os
import pathlib

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"


@pytest.fixture(scope="session")
def nck_binary():
    return os.environ.get("NCK_BINARY", str(ROOT / "build" / "default" / "nck"))


@pytest.fixture(scope="session")
def mill():
    import nck
    return nck.Machine(EXAMPLES / "mill")


@pytest.fixture
def program(tmp_path):
    """Writes an NC program into tmp_path and returns its path."""
    def write(text, name="p.nc"):
        p = tmp_path / name
        p.write_text(text)
        return str(p)
    return write
