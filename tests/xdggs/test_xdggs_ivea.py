"""The xdggs grid's ``projection`` attribute: a cell-id coordinate on dggs.Grid("IVEA").

The references are the Grid's own verbs (tests/index/test_projection_grid.py checks those against
independent oracles); here the attribute must select them, round-trip, and be checked.
"""

from __future__ import annotations

import numpy as np
import pytest

xr = pytest.importorskip("xarray")
xdggs = pytest.importorskip("xdggs")

import dggs  # noqa: E402
import dggs.xdggs as dx  # noqa: E402

IVEA = dggs.Grid("IVEA")


def _decoded(ids, attrs):
    return xdggs.decode(xr.Dataset(coords={"cell_ids": ("cells", ids, attrs)}))


@pytest.mark.parametrize("id_format", ["int", "str"])
def test_ivea_attribute_selects_the_ivea_grid(id_format):
    lat, lng = np.array([51.05, -33.9, 89.5, 0.0]), np.array([-114.07, 18.4, 0.0, 180.0])
    ids = IVEA.latlng_to_cell(lat, lng, 7, as_int=id_format == "int")
    ds = _decoded(ids, {"grid_name": "dggs_split26", "level": 7, "projection": "IVEA"})
    info = ds.dggs.grid_info
    assert info.projection == "IVEA" and info.to_dict()["projection"] == "IVEA"
    centres = ds.dggs.cell_centers()
    want_lat, want_lng = IVEA.cell_to_latlng(ids)
    np.testing.assert_allclose(centres["latitude"], want_lat, atol=0)
    np.testing.assert_allclose(centres["longitude"], want_lng, atol=0)
    assert not np.allclose(centres["latitude"], dggs.cell_to_latlng(ids)[0])  # not ISEA's places
    assert np.array_equal(info.geographic2cell_ids(lng, lat), ids)
    polys = info.cell_boundaries(ids)
    assert all(p.equals(q) for p, q in zip(polys, IVEA.cell_to_polygon(ids), strict=True))
    assert len(info.cell_boundaries(ids, backend="geoarrow")) == len(ids)


def test_isea_is_implied_and_round_trips():
    info = dx.Split26Info.from_dict({"grid_name": "dggs_split26", "level": 3})
    assert info.projection == "ISEA" and "projection" not in info.to_dict()
    stated = dx.Split26Info.from_dict({"grid_name": "dggs_split26", "level": 3, "projection": "isea"})
    assert stated == info and stated.to_dict()["projection"] == "ISEA"
    assert dx.Split26Info(level=3, projection="IVEA").to_dict() == {
        "grid_name": "dggs_split26", "level": 3, "id_format": "int", "projection": "IVEA"}
    assert dx.Split26Info(level=3, projection="IVEA") != info


def test_bad_projection_named():
    with pytest.raises(ValueError, match="projection must be 'ISEA' or 'IVEA', got 'HEALPix'"):
        dx.Split26Info.from_dict({"grid_name": "dggs_split26", "level": 3, "projection": "HEALPix"})
    with pytest.raises(ValueError, match="got 3"):
        dx.Split26Info(level=3, projection=3)
