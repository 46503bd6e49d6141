"""Bad thread settings at import (issue 17, item 14): a DggsValueError naming the value; the CLI prints one line.

DGGS_THREADS is dggs's one thread setting (the compiled core's OpenMP threads, dggs.geometry._parallel).
Each case is a fresh process (the setting is read once, at import).
"""

from __future__ import annotations

import os
import subprocess
import sys

import pytest

CASES = [("DGGS_THREADS", v) for v in ("abc", "0", "-3", "2.5")]
API = (
    "import dggs\n"
    "try:\n"
    "    dggs.cell_to_latlng('C401')\n"
    "except dggs.DggsValueError as exc:\n"
    "    print(type(exc).__name__, exc)\n"
)
CLI = "from dggs.cli import main; main()"


def _run(args: list[str], name: str, value: str) -> subprocess.CompletedProcess:
    env = {k: v for k, v in os.environ.items() if not k.startswith(("NUMBA_", "DGGS_"))}
    env[name] = value
    return subprocess.run([sys.executable, *args], env=env, capture_output=True, text=True, timeout=600)


@pytest.mark.parametrize(("name", "value"), CASES)
def test_the_api_raises_a_typed_error_naming_the_setting(name, value):
    proc = _run(["-c", API], name, value)
    assert proc.returncode == 0, proc.stderr[-2000:]
    assert proc.stdout.strip() == f"DggsValueError {name} {value!r} must be a positive integer"


@pytest.mark.parametrize(("name", "value"), CASES)
def test_the_cli_prints_one_line_and_fails(name, value):
    proc = _run(["-c", CLI, "cell", "info", "C401"], name, value)
    assert proc.returncode != 0
    assert "Traceback" not in proc.stderr, proc.stderr[-2000:]
    assert proc.stderr.strip().splitlines() == [f"Error: {name} {value!r} must be a positive integer"]


def test_a_good_setting_still_works():
    proc = _run(["-c", "import dggs; print(dggs.get_level('C401'))"], "DGGS_THREADS", "1")
    assert proc.returncode == 0 and proc.stdout.strip() == "3", proc.stderr[-2000:]
