"""Many fills at once (dggs.index._many.each, gdf.dggs.polyfill): a loop's results and errors, on threads or not."""

from __future__ import annotations

import doctest
import threading

import numpy as np
import pytest
from shapely.geometry import Point, box

import dggs
from dggs.index import _many

SHAPES = [box(0, 0, 10, 10), box(0, 0, 20, 20), Point(5, 5).buffer(3), box(170, -5, 190, 5), box(-180, 80, 180, 90)]


def test_the_example_runs():
    assert doctest.testmod(_many).failed == 0


@pytest.mark.parametrize("threads", [1, 2])
def test_each_gives_a_loops_results_in_order(threads, monkeypatch):
    monkeypatch.setattr(_many, "default_threads", lambda: threads)
    got = _many.each(lambda g: dggs.polygon_to_cells(g, 5, as_int=True), SHAPES)
    want = [dggs.polygon_to_cells(g, 5, as_int=True) for g in SHAPES]
    assert [g.tolist() for g in got] == [w.tolist() for w in want]


@pytest.mark.parametrize("threads", [1, 2])
def test_each_stops_at_the_first_error_in_order(threads, monkeypatch):
    monkeypatch.setattr(_many, "default_threads", lambda: threads)

    def fill(g):
        return dggs.polygon_to_cells(g, 6, max_cells=150)

    got = _many.each(fill, [SHAPES[2], SHAPES[1], SHAPES[0]])  # the second is the first refused
    assert len(got) == 2 and len(got[0]) == 17 and isinstance(got[1], dggs.TooManyCellsError)


def test_one_thread_starts_no_thread(monkeypatch):
    monkeypatch.setattr(_many, "default_threads", lambda: 1)
    seen = _many.each(lambda g: threading.get_ident(), SHAPES)
    assert set(seen) == {threading.get_ident()}


def test_a_frame_raises_the_first_bad_row_as_a_loop_would(monkeypatch):
    gpd = pytest.importorskip("geopandas")
    import dggs.pandas  # noqa: F401 - registers df.dggs

    monkeypatch.setattr(_many, "default_threads", lambda: 2)
    frame = gpd.GeoDataFrame({"n": [1, 2, 3]}, geometry=[box(0, 0, 1, 1), box(-20, -20, 20, 20), Point(0, 0)],
                             index=["a", "b", "c"])
    with pytest.raises(dggs.TooManyCellsError, match="row 'b'"):  # before the Point of row 'c'
        frame.dggs.polyfill(8, max_cells=1000)
    with pytest.raises(dggs.DggsValueError, match="row 'c': a Point"):
        frame.dggs.polyfill(3)
    cells = frame.iloc[:2].dggs.polyfill(6, as_int=True)
    assert cells["cell_6"].tolist() == np.concatenate(
        [dggs.polygon_to_cells(g, 6, as_int=True) for g in frame.geometry[:2]]).tolist()
