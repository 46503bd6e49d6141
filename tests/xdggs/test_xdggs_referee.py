"""xdggs's own grid-info tests (its tests/test_h3.py and tests/test_healpix.py, ``TestH3Info`` and
``TestHealpixInfo``), written again for the dggs_split26 grid and run on the installed xdggs.

Expected values come from outside the code under test (dggs/xdggs.py and the kernel behind it): ids and the
hierarchy from the layout docs/grid.md writes out, geometry from the icosahedron in PROJ's isea orientation
and textbook authalic latitudes (tests/xdggs/_xdggs_reference.py), areas from pyproj.Geod, and
round trips from xdggs's API contract (``from_dict(to_dict())``, ``to_dict() == attrs``).
"""

from __future__ import annotations

import numpy as np
import pyproj
import pytest
import shapely
from hypothesis import given
from hypothesis import strategies as st

from tests.strategies import cells

from . import _xdggs_reference as ref

xdggs = pytest.importorskip("xdggs")

from xdggs.ellipsoid import Ellipsoid, Sphere  # noqa: E402

from dggs import xdggs as dx  # noqa: E402

from .test_xdggs import geoarrow_to_shapely  # noqa: E402

GRID = "dggs_split26"
WGS84_AXES = {"semimajor_axis": 6378137.0, "inverse_flattening": 298.257223563}
ELLIPSOID_SPELLINGS = ["WGS84", "wgs84", WGS84_AXES, {"name": "WGS84", **WGS84_AXES}]


class strategies:
    levels = st.integers(min_value=0, max_value=28)
    invalid_levels = st.integers(max_value=-1) | st.integers(min_value=29)
    id_formats = st.sampled_from(["int", "str"])
    invalid_id_formats = st.text().filter(lambda x: x not in ("int", "str"))
    ellipsoids = st.sampled_from(ELLIPSOID_SPELLINGS)

    @staticmethod
    @st.composite
    def attrs(draw, level_names=("level",)):
        """Grid attributes as a file may hold them: the level, and id_format / ellipsoid or not."""
        mapping = {"grid_name": GRID, draw(st.sampled_from(level_names)): draw(strategies.levels)}
        if draw(st.booleans()):
            mapping["id_format"] = draw(strategies.id_formats)
        if draw(st.booleans()):
            mapping["ellipsoid"] = draw(strategies.ellipsoids)
        return mapping


class TestSplit26Info:
    @given(strategies.invalid_levels)
    def test_init_invalid_levels(self, level):
        with pytest.raises(ValueError, match="level must be an integer between 0 and 28"):
            dx.Split26Info(level=level)

    @given(strategies.invalid_id_formats)
    def test_init_invalid_id_format(self, id_format):
        with pytest.raises(ValueError, match="id_format must be 'int' or 'str'"):
            dx.Split26Info(level=0, id_format=id_format)

    @pytest.mark.parametrize(
        "ellipsoid",
        [
            "sphere",
            "GRS80",
            {"semimajor_axis": 6378137.0, "inverse_flattening": 298.257222101},  # GRS80: 1e-8 apart
            {"name": "WGS84", "semimajor_axis": 6378000.0, "inverse_flattening": 298.257223563},
            {"radius": 6371007.1809},
            Sphere(radius=6371007.1809, name="authalic"),
            Ellipsoid(semimajor_axis=6378137.0, inverse_flattening=298.257222101, name="GRS80"),
        ],
    )
    def test_init_invalid_ellipsoid(self, ellipsoid):
        with pytest.raises(ValueError, match="WGS84 only"):
            dx.Split26Info(level=0, ellipsoid=ellipsoid)

    @given(strategies.levels, strategies.id_formats, strategies.ellipsoids)
    def test_init(self, level, id_format, ellipsoid):
        grid = dx.Split26Info(level=level, id_format=id_format, ellipsoid=ellipsoid)

        assert grid.level == level
        assert grid.id_format == id_format
        assert grid.ellipsoid == "WGS84"  # one spelling, so that infos of one grid are equal
        assert grid == dx.Split26Info(level=level, id_format=id_format)

    def test_init_in_memory_ellipsoid(self):
        grid = dx.Split26Info(level=2, ellipsoid=Ellipsoid(**WGS84_AXES, name="WGS84"))
        assert grid.ellipsoid == "WGS84"

    @given(strategies.attrs(level_names=("level", "resolution", "refinement_level")))
    def test_from_dict(self, mapping):
        level = next(v for k, v in mapping.items() if k in ("level", "resolution", "refinement_level"))

        grid = dx.Split26Info.from_dict(mapping)

        assert grid.level == level and type(grid.level) is int
        assert grid.id_format == mapping.get("id_format", "int")

    @pytest.mark.parametrize(
        ["mapping", "duplicated"],
        (
            ({"level": 1, "resolution": 1}, "['level', 'resolution']"),
            ({"refinement_level": 3, "level": 3}, "['level', 'refinement_level']"),
        ),
    )
    def test_from_dict_duplicated(self, mapping, duplicated):
        # xdggs's translate_parameters contract: an ExceptionGroup naming the spellings
        with pytest.raises(Exception, match="received multiple values for parameters") as info:
            dx.Split26Info.from_dict(mapping)
        assert type(info.value).__name__ == "ExceptionGroup"
        (error,) = info.value.exceptions
        assert isinstance(error, ValueError)
        assert str(error) == f"Parameter level received multiple values: {duplicated}"

    @pytest.mark.parametrize(
        ["mapping", "message"],
        (
            ({"grid_name": GRID}, "needs a level"),
            ({"level": 3, "indexing_scheme": "nested"}, "unknown parameters"),
            ({"level": True}, "level must be an integer"),
            ({"level": "3"}, "level must be an integer"),
            ({"level": 3, "id_format": "hex"}, "id_format must be"),
            ({"level": 3, "ellipsoid": "sphere"}, "WGS84 only"),
        ),
    )
    def test_from_dict_errors(self, mapping, message):
        with pytest.raises(ValueError, match=message):
            dx.Split26Info.from_dict(mapping)

    @given(strategies.levels, strategies.id_formats, strategies.ellipsoids)
    def test_to_dict(self, level, id_format, ellipsoid):
        actual = dx.Split26Info(level=level, id_format=id_format, ellipsoid=ellipsoid).to_dict()

        # built directly: the grid name, the level and the id format (WGS84 is the grid's only ellipsoid)
        assert actual == {"grid_name": GRID, "level": level, "id_format": id_format}

    @given(strategies.attrs())
    def test_roundtrip(self, mapping):
        # what xdggs's decode test asserts: grid_info.to_dict() == the attributes it was decoded from
        assert dx.Split26Info.from_dict(mapping).to_dict() == mapping

    @given(strategies.attrs(level_names=("resolution", "refinement_level")))
    def test_roundtrip_synonyms(self, mapping):
        # synonyms are read and written back as "level", as xdggs's h3 and healpix grids do
        (name,) = set(mapping) & {"resolution", "refinement_level"}
        expected = {("level" if k == name else k): v for k, v in mapping.items()}
        assert dx.Split26Info.from_dict(mapping).to_dict() == expected

    @given(strategies.levels, strategies.id_formats, st.none() | strategies.attrs())
    def test_roundtrip_info(self, level, id_format, mapping):
        grid = dx.Split26Info(level, id_format=id_format) if mapping is None else dx.Split26Info.from_dict(mapping)

        again = dx.Split26Info.from_dict(grid.to_dict())

        assert again == grid
        assert again.to_dict() == grid.to_dict()

    def test_stated_is_checked(self):
        with pytest.raises(ValueError, match="stated id_format 'str' is not 'int'"):
            dx.Split26Info(level=1, id_format="int", stated={"id_format": "str"})
        with pytest.raises(ValueError, match="id_format and ellipsoid only"):
            dx.Split26Info(level=1, stated={"level": 1})

    @pytest.mark.parametrize("as_str", [False, True])
    @pytest.mark.parametrize("level", [0, 1])
    def test_cell_ids2geographic(self, level, as_str):
        names = ref.LEVEL0 if level == 0 else ref.LEVEL1
        grid = dx.Split26Info(level=level, id_format="str" if as_str else "int")

        lon, lat = grid.cell_ids2geographic(np.array(names) if as_str else ref.doc_ints(names))
        points = ref.to_xyz(lon, lat)

        assert lon.shape == lat.shape == (len(names),)
        if level == 0:  # each face's centre, one per face
            face, angle = ref.nearest(ref.FACE_CENTRES, points)
            assert sorted(face) == list(range(20))
            np.testing.assert_allclose(angle, 0.0, atol=1e-12)
            return
        # one centre inside each of the 120 (vertex, face centre, edge midpoint) triangles, on its face
        inside = ref.containing(ref.LEVEL1_TRIANGLES, points, margin=1e-6)
        assert (inside.sum(axis=1) == 1).all()
        triangle = inside.argmax(axis=1)
        assert sorted(triangle) == list(range(120))
        faces, _ = ref.nearest(ref.FACE_CENTRES, ref.to_xyz(*grid.cell_ids2geographic(ref.doc_ints(ref.LEVEL0))))
        np.testing.assert_equal(ref.LEVEL1_FACE[triangle], np.repeat(faces, 6))  # prefixes are parents

    @pytest.mark.parametrize("level", [0, 1])
    @pytest.mark.parametrize("as_str", [False, True])
    def test_geographic2cell_ids(self, level, as_str):
        # brute force: the cell holding a point is the one whose spherical triangle holds it
        names = np.array(ref.LEVEL0 if level == 0 else ref.LEVEL1)
        triangles = ref.FACE_TRIANGLES if level == 0 else ref.LEVEL1_TRIANGLES
        grid = dx.Split26Info(level=level, id_format="str" if as_str else "int")
        labels = ref.containing(triangles, ref.to_xyz(*grid.cell_ids2geographic(names)), 1e-6).argmax(axis=1)
        by_triangle = dict(zip(labels.tolist(), names.tolist(), strict=True))
        rng = np.random.default_rng(20)
        xyz = rng.normal(size=(2000, 3))
        xyz /= np.linalg.norm(xyz, axis=1, keepdims=True)
        inside = ref.containing(triangles, xyz, margin=1e-9)
        xyz = xyz[inside.sum(axis=1) == 1]  # away from the sides
        lon, lat = ref.to_lonlat(xyz)

        actual = grid.geographic2cell_ids(lon=lon, lat=lat)

        expected = [by_triangle[t] for t in ref.containing(triangles, xyz, 1e-9).argmax(axis=1)]
        assert len(expected) > 1900
        np.testing.assert_equal(actual, np.array(expected) if as_str else ref.doc_ints(expected))
        assert actual.dtype.kind == ("U" if as_str else "u")

    @given(cells(min_level=0, max_level=16), st.booleans())
    def test_cell_center_roundtrip(self, cell, as_str):
        level = len(cell) - 1
        cell_ids = np.array([cell]) if as_str else ref.doc_ints([cell])
        grid = dx.Split26Info(level=level, id_format="str" if as_str else "int")

        lon, lat = grid.cell_ids2geographic(cell_ids)
        roundtripped = grid.geographic2cell_ids(lon=lon, lat=lat)

        np.testing.assert_equal(roundtripped, cell_ids)

    @pytest.mark.parametrize("backend", ["shapely", "geoarrow"])
    @pytest.mark.parametrize("level", [0, 1])
    def test_cell_boundaries(self, level, backend):
        names = ref.LEVEL0 if level == 0 else ref.LEVEL1
        triangles = ref.FACE_TRIANGLES if level == 0 else ref.LEVEL1_TRIANGLES
        grid = dx.Split26Info(level=level)
        ids = ref.doc_ints(names)
        labels = ref.containing(triangles, ref.to_xyz(*grid.cell_ids2geographic(ids)), 1e-6).argmax(axis=1)

        actual = grid.cell_boundaries(ids, backend=backend)
        polygons = geoarrow_to_shapely(actual) if backend == "geoarrow" else actual

        assert len(polygons) == len(names)
        assert set(shapely.get_type_id(polygons).tolist()) <= {3, 6}  # (Multi)Polygons
        for polygon, triangle in zip(polygons, triangles[labels], strict=True):
            vertices = ref.to_xyz(*shapely.get_coordinates(polygon).T)
            _, angle = ref.nearest(vertices, triangle)
            assert angle.max() < 1e-9  # the three corners are polygon vertices (within 6 cm)
        geod = pyproj.Geod(ellps="WGS84")
        areas = np.array([abs(geod.geometry_area_perimeter(p)[0]) for p in polygons])
        np.testing.assert_allclose(areas, ref.ELLIPSOID_AREA / ref.num_cells(level), rtol=2e-5)

    def test_cell_boundaries_invalid_backend(self):
        with pytest.raises(ValueError, match="invalid backend"):
            dx.Split26Info(level=0).cell_boundaries(ref.doc_ints(["A"]), backend="wkb")

    @pytest.mark.parametrize(
        ["cells_", "new_level"],
        (
            pytest.param(["C401", "T512", "A012"], 0, id="faces"),
            pytest.param(["C401", "T512", "A012"], 1, id="level1-parents"),
            pytest.param(["C4012", "T5120", "A0122"], 3, id="parents"),
            pytest.param(["C4012", "T5120", "A0122"], 2, id="grandparents"),
            pytest.param(["C4012", "T5120", "A0122"], 4, id="same"),
        ),
    )
    @pytest.mark.parametrize("as_str", [False, True])
    def test_zoom_to_parents(self, cells_, new_level, as_str):
        level = len(cells_[0]) - 1
        grid = dx.Split26Info(level=level, id_format="str" if as_str else "int")
        expected = [c[: new_level + 1] for c in cells_]

        actual = grid.zoom_to(np.array(cells_) if as_str else ref.doc_ints(cells_), level=new_level)

        np.testing.assert_equal(actual, np.array(expected) if as_str else ref.doc_ints(expected))

    @pytest.mark.parametrize(
        ["cells_", "new_level", "per_cell"],
        (
            pytest.param(["A", "K", "T"], 1, 6, id="level0-children"),
            pytest.param(["A", "T"], 2, 18, id="level0-grandchildren"),
            pytest.param(["C4", "T5"], 2, 3, id="level1-children"),
            pytest.param(["C401", "T512"], 5, 9, id="grandchildren"),
        ),
    )
    @pytest.mark.parametrize("as_str", [False, True])
    def test_zoom_to_children(self, cells_, new_level, per_cell, as_str):
        grid = dx.Split26Info(level=len(cells_[0]) - 1, id_format="str" if as_str else "int")
        expected = [ref.doc_children(c, new_level) for c in cells_]

        actual = grid.zoom_to(np.array(cells_) if as_str else ref.doc_ints(cells_), level=new_level)

        assert actual.shape == (len(cells_), per_cell)
        expected_ids = np.array(expected) if as_str else np.array([ref.doc_ints(row) for row in expected])
        np.testing.assert_equal(actual, expected_ids)

    @pytest.mark.parametrize("new_level", [-1, 29, 2.5])
    def test_zoom_to_invalid_level(self, new_level):
        with pytest.raises(ValueError, match="level must be an integer between 0 and 28"):
            dx.Split26Info(level=3).zoom_to(ref.doc_ints(["C401"]), level=new_level)
