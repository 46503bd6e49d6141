"""Progress on every long step (issue 38, item 2): a bar with a total on a terminal or when forced, nothing else.

The terminal is a real pseudo-terminal (``pty``) given to a child process as its stderr, with a window size as
terminals have; "not a terminal" is a pipe. The child sets ``AUTO_DELAY = 0`` so that the default bar (which
waits 2 s on a terminal) draws at once on a small input.
"""

from __future__ import annotations

import fcntl
import os
import pty
import struct
import subprocess
import sys
import termios
import textwrap

import numpy as np
import pytest

from dggs.errors import DggsValueError
from dggs.storage import CellStore

CHILD = textwrap.dedent("""
    import sys
    import numpy as np
    import dggs.storage.progress as progress
    from dggs.storage import CellStore
    progress.AUTO_DELAY = 0
    arg = {"None": None, "True": True, "False": False}[sys.argv[1]]
    rng = np.random.default_rng(3)
    with CellStore(":memory:") as store:
        store.ingest_points(rng.uniform(-60, 60, 1500), rng.uniform(-180, 180, 1500), 7, {"v": rng.random(1500)},
                            batch_size=500, progress=arg)
        store.aggregate(3, "v", progress=arg)
        store.export(sys.argv[2], 3, "v", progress=arg)
""")


def _run(tmp_path, arg: str, terminal: bool) -> str:
    """Run CHILD with ``progress=arg``, its stderr a pseudo-terminal or a pipe; return what it wrote there."""
    cmd = [sys.executable, "-c", CHILD, arg, str(tmp_path / "out.geojson")]
    if not terminal:
        done = subprocess.run(cmd, capture_output=True, timeout=300, check=True)
        return done.stderr.decode()
    parent, child = pty.openpty()
    fcntl.ioctl(child, termios.TIOCSWINSZ, struct.pack("HHHH", 24, 120, 0, 0))  # a window, as a terminal has
    proc = subprocess.Popen(cmd, stderr=child, stdout=subprocess.DEVNULL)
    os.close(child)
    out = b""
    while True:
        try:
            chunk = os.read(parent, 4096)
        except OSError:  # the child closed the terminal
            break
        if not chunk:
            break
        out += chunk
    os.close(parent)
    assert proc.wait(timeout=300) == 0
    return out.decode(errors="replace")


def test_default_draws_bars_with_totals_on_a_terminal(tmp_path):
    text = _run(tmp_path, "None", terminal=True)
    assert "binning:   0%" in text and "1.50k/1.50k" in text  # the ingest's total, from the arrays' length
    assert "sorting into the store" in text  # the bar covers the final merge, not only the reading
    assert "rolling up to level 3" in text
    assert "exporting: writing: 100%" in text and "3/3" in text


@pytest.mark.parametrize("arg", ["None", "True"])
def test_forced_bars_draw_anywhere_and_the_default_not_on_a_pipe(tmp_path, arg):
    text = _run(tmp_path, arg, terminal=False)
    if arg == "None":
        assert text == ""
    else:
        assert "1.50k/1.50k" in text and "exporting: writing: 100%" in text


def test_false_is_silent_even_on_a_terminal(tmp_path):
    assert _run(tmp_path, "False", terminal=True).strip() == ""


def test_csv_ingest_counts_its_rows_for_the_total(tmp_path, capsys):
    path = tmp_path / "p.csv"
    path.write_text("lat,lng\n" + "".join(f"{i % 80},{i % 170}\n" for i in range(2345)))
    with CellStore(tmp_path / "s.db") as store:
        store.ingest_csv(path, level=5, batch_size=1000, progress=True)
    err = capsys.readouterr().err
    assert "binning:   0%" in err and "2.35k/2.35k" in err


def test_a_callable_is_given_every_row_once(tmp_path):
    seen: list[int] = []
    with CellStore(tmp_path / "s.db") as store:
        store.ingest_points(np.zeros(2500), np.zeros(2500), 5, batch_size=1000, progress=seen.append)
    assert seen == [1000, 1000, 500]


def test_polyfill_counts_its_features():
    gpd = pytest.importorskip("geopandas")
    from shapely.geometry import box

    import dggs.pandas  # noqa: F401 - the accessor

    frame = gpd.GeoDataFrame({"k": range(7)}, geometry=[box(i, 0, i + 5, 5) for i in range(7)], crs="EPSG:4326")
    seen: list[int] = []
    frame.dggs.polyfill(5, progress=seen.append)
    assert seen == [1] * 7


@pytest.mark.parametrize("call", ["aggregate", "export", "ingest"])
def test_a_bad_progress_names_itself(tmp_path, call):
    with CellStore(tmp_path / "s.db") as store:
        store.ingest_points([1.0], [2.0], 5, progress=False)
        with pytest.raises(DggsValueError, match="progress must be True, False, None or a callable.*'yes'"):
            if call == "aggregate":
                store.aggregate(3, progress="yes")
            elif call == "export":
                store.export(tmp_path / "o.geojson", 3, progress="yes")
            else:
                store.ingest_points([1.0], [2.0], 5, progress="yes")
    assert not (tmp_path / "o.geojson").exists()
