"""xarray through xdggs: the dggs_split26 grid (dggs/xdggs.py).

The first part is the conformance suite of xdggs's own H3 tests (its tests/test_h3.py: the grid-info class,
the index class, join / reindex / equals), rewritten for this grid with expected values taken from the plain
``dggs`` functions (tested on their own elsewhere) and from ids written out in docs/grid.md. The second part
checks the ``.dggs`` accessor, the encode/decode round trips (xdggs, CF and zarr conventions, in memory and
through a zarr store), ``explore``, that ``import dggs`` stays free of xarray, and docs/xarray.md.
"""

from __future__ import annotations

import itertools
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import shapely
import shapely.testing

xdggs = pytest.importorskip("xdggs")
xr = pytest.importorskip("xarray")

from xarray.indexes import PandasIndex  # noqa: E402

import dggs  # noqa: E402
from dggs import xdggs as dx  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
GRID = dx.GRID_NAME

# Level-3 cells: "C401" (docs/grid.md writes its integer id out), its three edge neighbours, and the cells
# under three points: Calgary, Cape Town and one on the equator next to the antimeridian (a MultiPolygon).
C401 = 4996743786567565312
_points = (np.array([51.05, -33.9, 0.0]), np.array([-114.07, 18.4, 179.99]))
cell_ids = [
    np.array([C401], dtype=np.uint64),
    np.sort(np.asarray(dggs.edge_neighbors(np.array([C401], dtype=np.uint64))).ravel())[:2],
    np.asarray(dggs.latlng_to_cell(*_points, 3, as_int=True)),
]
cell_centers = [np.column_stack(dggs.cell_to_latlng(ids)[::-1]) for ids in cell_ids]  # (lon, lat) rows
dims = ["cells", "zones"]
levels = [1, 5, 15]
variable_names = ["cell_ids", "zonal_ids", "zone_ids"]


def _ids_at(level: int, n: int = 3) -> np.ndarray:
    """n distinct cells of a level (ints), from spread-out points."""
    lat = np.array([51.05, -33.9, 10.0, 45.0, -60.0][:n])
    lng = np.array([-114.07, 18.4, 100.0, 7.0, -40.0][:n])
    return np.asarray(dggs.latlng_to_cell(lat, lng, level, as_int=True))


variables = [
    xr.Variable(dims[0], _ids_at(levels[0], 1), {"grid_name": GRID, "level": levels[0]}),
    xr.Variable(dims[1], _ids_at(levels[0], 1), {"grid_name": GRID, "level": levels[0]}),
    xr.Variable(dims[0], _ids_at(levels[1], 2), {"grid_name": GRID, "level": levels[1]}),
    xr.Variable(dims[1], _ids_at(levels[2], 3), {"grid_name": GRID, "level": levels[2]}),
]
variable_combinations = list(itertools.product(variables, repeat=2))


def geoarrow_to_shapely(arr) -> np.ndarray:
    """Decode a geoarrow polygon / multipolygon array (any Arrow C-data array) into shapely geometries."""
    import pyarrow as pa

    array = pa.array(arr)
    field = pa.field(arr)
    name = (field.metadata or {}).get(b"ARROW:extension:name", b"").decode()
    offsets = []
    while pa.types.is_list(array.type) or pa.types.is_large_list(array.type):
        offsets.append(np.asarray(array.offsets))
        array = array.flatten()
    coords = np.asarray(array.flatten()).reshape(-1, 2)
    kind = {"geoarrow.polygon": shapely.GeometryType.POLYGON, "geoarrow.multipolygon": shapely.GeometryType.MULTIPOLYGON}
    # shapely wants the offsets innermost first
    return shapely.from_ragged_array(kind[name], coords, tuple(reversed(offsets)))


def _promote(polygons: np.ndarray) -> np.ndarray:
    """Polygons as MultiPolygons when any of them is a MultiPolygon (what one geoarrow array holds)."""
    if not any(g.geom_type == "MultiPolygon" for g in polygons):
        return polygons
    multi = [g if g.geom_type == "MultiPolygon" else shapely.MultiPolygon([g]) for g in polygons]
    return np.array(multi, dtype=object)


def _as_str(ids: np.ndarray) -> np.ndarray:
    return np.asarray(dggs.int_to_str(ids))


class TestSplit26Info:
    @pytest.mark.parametrize(
        ["level", "error"],
        (
            (0, None),
            (1, None),
            (dggs.MAX_LEVEL, None),
            (-1, ValueError("level must be an integer between")),
            (dggs.MAX_LEVEL + 1, ValueError("level must be an integer between")),
            (True, ValueError("level must be an integer between")),
            (2.0, ValueError("level must be an integer between")),
        ),
    )
    def test_init(self, level, error):
        if error is not None:
            with pytest.raises(type(error), match=str(error)):
                dx.Split26Info(level=level)
            return

        actual = dx.Split26Info(level=level)

        assert actual.level == level
        assert actual.id_format == "int"
        assert actual.ellipsoid == "WGS84"

    @pytest.mark.parametrize(
        ["kwargs", "message"],
        (
            ({"id_format": "hex"}, "id_format must be"),
            ({"ellipsoid": "sphere"}, "WGS84 only"),
        ),
    )
    def test_init_errors(self, kwargs, message):
        with pytest.raises(ValueError, match=message):
            dx.Split26Info(level=3, **kwargs)

    @pytest.mark.parametrize(
        ["mapping", "expected"],
        (
            ({"level": 0}, 0),
            ({"level": np.int64(2)}, 2),
            ({"resolution": 1}, 1),
            ({"refinement_level": 7}, 7),
            ({"grid_name": GRID, "level": 4, "ellipsoid": "WGS84"}, 4),
            ({"level": -1}, ValueError("level must be an integer between")),
            ({"level": 2.5}, ValueError("level must be an integer between")),
            ({"level": 1, "resolution": 1}, "duplicate"),
            ({"level": 1, "flavour": "x"}, ValueError("unknown parameters")),
            ({"id_format": "int"}, ValueError("needs a level")),
            ({"level": 1, "ellipsoid": "GRS80"}, ValueError("WGS84 only")),
        ),
    )
    def test_from_dict(self, mapping, expected):
        if expected == "duplicate":  # xdggs raises an ExceptionGroup for a parameter given twice
            with pytest.raises(Exception, match="received multiple values"):
                dx.Split26Info.from_dict(mapping)
            return
        if isinstance(expected, Exception):
            with pytest.raises(type(expected), match=str(expected)):
                dx.Split26Info.from_dict(mapping)
            return

        actual = dx.Split26Info.from_dict(mapping)
        assert actual.level == expected and type(actual.level) is type(expected)

    @pytest.mark.parametrize("id_format", ["int", "str"])
    def test_roundtrip(self, id_format):
        mapping = {"grid_name": GRID, "level": 0, "id_format": id_format}

        grid = dx.Split26Info.from_dict(mapping)
        actual = grid.to_dict()

        assert actual == mapping

    @pytest.mark.parametrize("as_str", [False, True])
    @pytest.mark.parametrize(["cell_ids", "cell_centers"], list(zip(cell_ids, cell_centers, strict=True)))
    def test_cell_ids2geographic(self, cell_ids, cell_centers, as_str):
        grid = dx.Split26Info(level=3, id_format="str" if as_str else "int")

        actual = grid.cell_ids2geographic(_as_str(cell_ids) if as_str else cell_ids)
        expected = cell_centers.T

        assert isinstance(actual, tuple) and len(actual) == 2
        np.testing.assert_allclose(actual, expected)

    def test_cell_ids2geographic_known_cell(self):
        # a centre is inside its cell: the level-9 Calgary cell of the README holds its centre
        grid = dx.Split26Info(level=9, id_format="str")
        lon, lat = grid.cell_ids2geographic(np.array(["F200021102"]))
        assert dggs.latlng_to_cell(lat[0], lon[0], 9) == "F200021102"
        assert abs(lat[0] - 51.05) < 0.5 and abs(lon[0] + 114.07) < 0.5

    @pytest.mark.parametrize("as_str", [False, True])
    @pytest.mark.parametrize(["cell_centers", "cell_ids"], list(zip(cell_centers, cell_ids, strict=True)))
    def test_geographic2cell_ids(self, cell_centers, cell_ids, as_str):
        grid = dx.Split26Info(level=3, id_format="str" if as_str else "int")

        actual = grid.geographic2cell_ids(lon=cell_centers[:, 0], lat=cell_centers[:, 1])
        expected = _as_str(cell_ids) if as_str else cell_ids

        np.testing.assert_equal(actual, expected)
        assert actual.dtype.kind == ("U" if as_str else "u")

    @pytest.mark.parametrize(["level", "cell_ids"], [(3, ids) for ids in cell_ids] + [(1, _ids_at(1)), (9, _ids_at(9))])
    @pytest.mark.parametrize("backend", ["shapely", "geoarrow"])
    def test_cell_boundaries(self, level, cell_ids, backend):
        grid = dx.Split26Info(level=level)
        densify = 4
        expected = np.asarray(dggs.cell_to_polygon(cell_ids, densify=densify))

        backends = {"shapely": lambda arr: arr, "geoarrow": geoarrow_to_shapely}
        actual = backends[backend](grid.cell_boundaries(cell_ids, backend=backend, densify=densify))
        if backend == "geoarrow":  # one geoarrow type for all: promoted to MultiPolygons if any cell is split
            expected = _promote(expected)

        shapely.testing.assert_geometries_equal(actual, expected)
        # each cell's three corners (dggs.cell_to_boundary, (lat, lng)) are on its polygon, which holds the centre
        corners = np.asarray(dggs.cell_to_boundary(cell_ids))
        lat, lng = dggs.cell_to_latlng(cell_ids)
        for polygon, cell_corners, y, x in zip(actual, corners, lat, lng, strict=True):
            assert shapely.covers(polygon.buffer(1e-9), shapely.points(cell_corners[:, ::-1])).all()
            assert polygon.contains(shapely.Point(x, y))

    def test_cell_boundaries_defaults(self):
        grid = dx.Split26Info(level=3)
        ids = cell_ids[2]  # includes the antimeridian cell
        shapely.testing.assert_geometries_equal(grid.cell_boundaries(ids), np.asarray(dggs.cell_to_polygon(ids)))
        from_arrow = geoarrow_to_shapely(grid.cell_boundaries(ids, backend="geoarrow"))
        expected = _promote(np.asarray(dggs.cell_to_polygon(ids, densify=dx.GEOARROW_DENSIFY)))
        shapely.testing.assert_geometries_equal(from_arrow, expected)
        assert shapely.get_type_id(from_arrow).tolist() == [6, 6, 6]  # promoted to MultiPolygon
        with pytest.raises(ValueError, match="invalid backend"):
            grid.cell_boundaries(ids, backend="wkt")

    @pytest.mark.parametrize(
        ["level", "new_level"],
        (
            pytest.param(5, 4, id="parents"),
            pytest.param(5, 3, id="grandparents"),
            pytest.param(5, 0, id="faces"),
            pytest.param(5, 5, id="same"),
        ),
    )
    @pytest.mark.parametrize("as_str", [False, True])
    def test_zoom_to(self, level, new_level, as_str):
        grid = dx.Split26Info(level=level)
        ids = _ids_at(level)
        ids = _as_str(ids) if as_str else ids

        actual = grid.zoom_to(ids, level=new_level)
        expected = np.array([dggs.cell_to_parent(c, new_level) if new_level < level else c for c in ids.tolist()])

        np.testing.assert_equal(actual, expected)
        if as_str:  # string parents are prefixes (docs/grid.md)
            assert [c[: new_level + 1] for c in ids.tolist()] == actual.tolist()

    @pytest.mark.parametrize(["level", "new_level", "per_cell"], [(0, 1, 6), (0, 2, 18), (4, 5, 3), (4, 6, 9)])
    @pytest.mark.parametrize("as_str", [False, True])
    def test_zoom_to_children(self, level, new_level, per_cell, as_str):
        grid = dx.Split26Info(level=level)
        ids = _ids_at(level) if level else np.asarray(dggs.str_to_int(np.array(["A", "K", "T"])))
        ids = _as_str(ids) if as_str else ids

        actual = grid.zoom_to(ids, level=new_level)

        assert actual.shape == (3, per_cell)
        for cell, children in zip(ids.tolist(), actual.tolist(), strict=True):
            assert children == list(dggs.cell_to_children(cell, new_level))
            assert all(dggs.cell_to_parent(c, level) == cell for c in children)

    def test_zoom_to_too_many_children(self):
        grid = dx.Split26Info(level=0)
        with pytest.raises(dggs.TooManyCellsError):
            grid.zoom_to(np.asarray(dggs.str_to_int(np.array(["A"]))), level=17)  # 2 * 3**17 children

    @pytest.mark.parametrize("new_level", [-1, dggs.MAX_LEVEL + 1])
    def test_zoom_to_invalid_level(self, new_level):
        grid = dx.Split26Info(level=3)
        with pytest.raises(ValueError, match="level must be"):
            grid.zoom_to(cell_ids[0], level=new_level)


@pytest.mark.parametrize("level", levels)
@pytest.mark.parametrize("name", variable_names)
@pytest.mark.parametrize("dim", dims)
@pytest.mark.parametrize("cell_ids", cell_ids)
def test_init(cell_ids, dim, name, level):
    grid = dx.Split26Info(level)
    index = dx.Split26Index(cell_ids, dim, name, grid)

    assert index._grid == grid
    assert index._dim == dim

    assert index._index.dim == dim
    assert index._index.index.name == name
    assert np.all(index._index.index.values == cell_ids)


@pytest.mark.parametrize("level", levels)
def test_grid(level):
    grid = dx.Split26Info(level)

    index = dx.Split26Index([0], "cells", "cell_ids", grid)

    assert index.grid_info is grid


@pytest.mark.parametrize("variable", variables)
@pytest.mark.parametrize("variable_name", variable_names)
@pytest.mark.parametrize("options", [{}, {"id_format": "int"}])
def test_from_variables(variable_name, variable, options):
    expected_level = variable.attrs["level"]

    variables = {variable_name: variable}
    index = dx.Split26Index.from_variables(variables, options=options)

    assert index._grid.level == expected_level
    assert index._grid.id_format == "int"
    assert (index._dim,) == variable.dims

    assert (index._index.dim,) == variable.dims
    assert np.all(index._index.index.values == variable.data)


def test_from_variables_string_ids():
    ids = _as_str(_ids_at(5))
    variable = xr.Variable("cells", ids, {"grid_name": GRID, "level": 5})

    index = dx.Split26Index.from_variables({"cell_ids": variable}, options={})

    assert index.grid_info == dx.Split26Info(level=5, id_format="str")
    assert index._index.index.tolist() == ids.tolist()


@pytest.mark.parametrize(
    ["data", "attrs", "message"],
    (
        (_ids_at(5), {"level": 4}, "is of level 5, not 4"),
        (np.array([0, 1], dtype=np.uint64), {"level": 4}, "invalid cell id"),
        (np.array(["F2000", "Z"]), {"level": 4}, "invalid cell id"),
        (_ids_at(5), {"level": 5, "id_format": "str"}, "id_format='str' but"),
    ),
)
def test_from_variables_checks_ids(data, attrs, message):
    variable = xr.Variable("cells", data, {"grid_name": GRID} | attrs)
    with pytest.raises(ValueError, match=message):
        dx.Split26Index.from_variables({"cell_ids": variable}, options={})


@pytest.mark.parametrize(["old_variable", "new_variable"], variable_combinations)
def test_replace(old_variable, new_variable):
    name = "cell_ids"

    grid = dx.Split26Info(level=old_variable.attrs["level"])
    index = dx.Split26Index(cell_ids=old_variable.data, dim=old_variable.dims[0], name=name, grid_info=grid)
    new_pandas_index = PandasIndex.from_variables({name: new_variable}, options={})

    new_index = index._replace(new_pandas_index)

    assert new_index._grid == index._grid
    assert new_index._dim == index._dim
    assert new_index._index == new_pandas_index
    assert new_index._name == name


@pytest.mark.parametrize("max_width", [20, 50, 80, 120])
@pytest.mark.parametrize("level", levels)
def test_repr_inline(level, max_width):
    grid = dx.Split26Info(level=level)
    index = dx.Split26Index(cell_ids=[0], dim="cells", name="cell_ids", grid_info=grid)

    actual = index._repr_inline_(max_width)

    assert f"level={level}" in actual


def _level2(n: int) -> np.ndarray:
    return np.sort(np.unique(_ids_at(2, 5)))[:n]


def test_join():
    data1 = _level2(4)
    data2 = data1[[0, 2, 3]]

    dim = "cells"
    name = "cell_ids"
    grid_info = dx.Split26Info(level=2)

    index1 = dx.Split26Index(data1, dim=dim, name=name, grid_info=grid_info)
    index2 = dx.Split26Index(data2, dim=dim, name=name, grid_info=grid_info)

    actual = index1.join(index2, how="inner")
    expected = dx.Split26Index(data2, dim=dim, name=name, grid_info=grid_info)

    assert actual._grid == expected._grid
    assert actual._dim == expected._dim
    assert np.all(actual._index.index == expected._index.index)


def test_join_error():
    dim = "cells"
    name = "cell_ids"

    index1 = dx.Split26Index(_ids_at(1), dim=dim, name=name, grid_info=dx.Split26Info(level=1))
    index2 = dx.Split26Index(_ids_at(6, 2), dim=dim, name=name, grid_info=dx.Split26Info(level=6))

    with pytest.raises(ValueError, match="different grid parameters"):
        index1.join(index2, how="inner")


def test_reindex_like():
    grid = dx.Split26Info(level=2)
    data = _level2(4)
    index1 = dx.Split26Index(cell_ids=data[[0, 2, 3]], dim="cells", name="cell_ids", grid_info=grid)
    index2 = dx.Split26Index(cell_ids=data, dim="cells", name="cell_ids", grid_info=grid)

    actual = index1.reindex_like(index2)

    np.testing.assert_equal(actual["cells"], np.array([0, -1, 1, 2]))


def test_reindex_like_error():
    index1 = dx.Split26Index(_ids_at(1), dim="cells", name="cell_ids", grid_info=dx.Split26Info(level=1))
    index2 = dx.Split26Index(_ids_at(6, 2), dim="cells", name="cell_ids", grid_info=dx.Split26Info(level=6))

    with pytest.raises(ValueError, match="different grid parameters"):
        index1.reindex_like(index2)


@pytest.mark.parametrize("variant", ("identical", "all-different", "dim", "grid-info", "values", "id-format"))
def test_equals(variant):
    values = [_ids_at(1), _ids_at(6, 2)]
    grid_info = [dx.Split26Info(level=1), dx.Split26Info(level=6), dx.Split26Info(level=1, id_format="str")]

    variants = {
        "identical": (dims[0], values[0], grid_info[0]),
        "all-different": (dims[1], values[1], grid_info[1]),
        "dim": (dims[1], values[0], grid_info[0]),
        "grid-info": (dims[0], values[0], grid_info[1]),
        "values": (dims[0], values[1], grid_info[0]),
        "id-format": (dims[0], values[0], grid_info[2]),
    }
    expected = variant == "identical"
    dim2, values2, grid_info2 = variants[variant]

    index1 = dx.Split26Index(values[0], dim=dims[0], name="cell_ids", grid_info=grid_info[0])
    index2 = dx.Split26Index(values2, dim=dim2, name="cell_ids", grid_info=grid_info2)

    assert index1.equals(index2) == expected


# --- the accessor and the conventions -------------------------------------------------------------------

LAT = np.array([51.05, -33.9, 0.0, 89.9, -89.9])
LNG = np.array([-114.07, 18.4, 179.99, 3.0, -150.0])


def _dataset(as_str: bool, level: int = 5) -> xr.Dataset:
    ids = np.asarray(dggs.latlng_to_cell(LAT, LNG, level, as_int=not as_str))
    return xr.Dataset(
        {"temperature": ("cells", np.arange(len(ids), dtype=float), {"units": "K"})},
        coords={"cell_ids": ("cells", ids, {"grid_name": GRID, "level": level})},
    )


@pytest.fixture(params=["int", "str"])
def decoded(request) -> xr.Dataset:
    return xdggs.decode(_dataset(request.param == "str"))


def test_registered():
    from xdggs.utils import GRID_REGISTRY

    assert GRID_REGISTRY[GRID] is dx.Split26Index


@pytest.mark.parametrize("as_str", [False, True])
def test_decode(as_str):
    ds = _dataset(as_str)

    decoded = xdggs.decode(ds)

    index = decoded.dggs.index
    assert isinstance(index, dx.Split26Index)
    assert decoded.dggs.grid_info == dx.Split26Info(level=5, id_format="str" if as_str else "int")
    assert decoded.cell_ids.values.tolist() == ds.cell_ids.values.tolist()
    xr.testing.assert_identical(ds.dggs.decode(), decoded)


def test_decode_with_grid_info():
    ids = dggs.latlng_to_cell(LAT, LNG, 5, as_int=True)
    ds = xr.Dataset(coords={"cell_ids": ("cells", ids)})  # no grid attributes on the coordinate
    decoded = xdggs.decode(ds, grid_info={"grid_name": GRID, "level": 5})
    assert decoded.dggs.grid_info.level == 5
    decoded = xdggs.decode(ds, grid_info=dx.Split26Info(level=5))
    assert decoded.dggs.grid_info.level == 5


def test_cell_centers(decoded):
    lat, lng = dggs.cell_to_latlng(decoded.cell_ids.values)

    centers = decoded.dggs.cell_centers()

    np.testing.assert_allclose(centers.latitude.values, lat)
    np.testing.assert_allclose(centers.longitude.values, lng)
    assert centers.latitude.dims == ("cells",)
    with_coords = decoded.dggs.assign_latlon_coords()
    np.testing.assert_allclose(with_coords.latitude.values, lat)
    assert isinstance(with_coords.dggs.index, dx.Split26Index)


def test_cell_boundaries_accessor(decoded):
    boundaries = decoded.dggs.cell_boundaries()

    assert boundaries.dims == ("cells",)
    assert boundaries.cell_ids.values.tolist() == decoded.cell_ids.values.tolist()
    expected = np.asarray(dggs.cell_to_polygon(np.asarray(decoded.cell_ids.values.tolist())))
    shapely.testing.assert_geometries_equal(boundaries.values, expected)
    assert boundaries.values[2].geom_type == "MultiPolygon"  # the cell at the antimeridian is split


def test_sel_latlon(decoded):
    subset = decoded.dggs.sel_latlon(LAT[[1, 3]], LNG[[1, 3]])

    np.testing.assert_equal(subset.temperature.values, [1.0, 3.0])
    assert subset.cell_ids.values.tolist() == decoded.cell_ids.values[[1, 3]].tolist()
    # any point of a cell selects it: its centre does
    lon, lat = decoded.dggs.index.cell_centers()
    np.testing.assert_equal(decoded.dggs.sel_latlon(lat, lon).temperature.values, decoded.temperature.values)
    with pytest.raises(KeyError):
        decoded.dggs.sel_latlon([10.0], [10.0])  # a cell not in the dataset


def test_zoom_to_accessor(decoded):
    ids = decoded.cell_ids.values.tolist()

    parents = decoded.dggs.zoom_to(3)
    children = decoded.dggs.zoom_to(7)

    assert parents.dims == ("cells",)
    assert parents.values.tolist() == [dggs.cell_to_parent(c, 3) for c in ids]
    assert children.dims == ("cells", "children") and children.shape == (5, 9)
    assert children.values.tolist() == [list(dggs.cell_to_children(c, 7)) for c in ids]


def test_isel_keeps_index(decoded):
    subset = decoded.isel(cells=[0, 2])
    assert isinstance(subset.dggs.index, dx.Split26Index)
    assert subset.dggs.grid_info == decoded.dggs.grid_info


@pytest.mark.parametrize("convention", ["xdggs", "cf", "zarr"])
def test_encode_decode_roundtrip(decoded, convention):
    encoded = decoded.dggs.encode(convention)

    assert not any(isinstance(i, dx.Split26Index) for i in encoded.xindexes.values()) or convention == "xdggs"
    # xdggs 0.6's zarr decoder needs the coordinate's name
    roundtripped = xdggs.decode(encoded, convention=convention, name="cell_ids")

    xr.testing.assert_identical(roundtripped, decoded)


def test_cf_attributes(decoded):
    encoded = decoded.dggs.encode("cf")

    # the attributes decoded left id_format to the dtype: the encoding does too (to_dict writes what was read)
    assert encoded.crs.attrs == {"grid_mapping_name": GRID, "refinement_level": 5}
    assert encoded.cell_ids.attrs == {"standard_name": f"{GRID}_index", "units": "1"}
    assert encoded.temperature.attrs["grid_mapping"] == GRID
    xr.testing.assert_identical(xdggs.decode(encoded, convention="cf"), decoded)


@pytest.mark.parametrize("convention", ["xdggs", "cf", "zarr"])
def test_zarr_store_roundtrip(decoded, convention, tmp_path):
    pytest.importorskip("zarr")
    path = tmp_path / "cells.zarr"

    decoded.dggs.encode(convention).to_zarr(path, consolidated=False)
    with xr.open_zarr(path, consolidated=False) as stored:
        roundtripped = xdggs.decode(stored.load(), convention=convention, name="cell_ids")

    xr.testing.assert_identical(roundtripped, decoded)


def test_explore(decoded):
    pytest.importorskip("lonboard")
    from xdggs.plotting import MapWithControls

    widget = decoded.temperature.dggs.explore()

    assert isinstance(widget, MapWithControls)
    (layer,) = widget.layers
    assert layer.table.num_rows == decoded.sizes["cells"]
    assert isinstance(decoded.dggs.explore(cmap="plasma"), MapWithControls)


def test_import_dggs_does_not_import_xarray():
    code = "import sys, dggs; print(sorted(m for m in ('xarray', 'xdggs', 'lonboard') if m in sys.modules))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


def test_docs_xarray_md_runs():
    text = (ROOT / "docs" / "xarray.md").read_text()
    blocks = re.findall(r"^```python\n(.*?)^```", text, flags=re.S | re.M)
    assert len(blocks) >= 2
    namespace: dict = {}
    for block in blocks:
        exec(compile(block, "docs/xarray.md", "exec"), namespace)


def test_module_doctests():
    import doctest

    result = doctest.testmod(dx, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE)
    assert result.attempted > 0 and result.failed == 0
