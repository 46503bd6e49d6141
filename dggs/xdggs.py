"""xarray support through xdggs: the Split (2:6) grid as a registered xdggs grid.

Importing this module registers the grid under the name ``"dggs_split26"`` (:data:`GRID_NAME`) with xdggs,
so that ``xdggs.decode(ds)`` builds a :class:`Split26Index` on a cell-id coordinate whose attributes are
``{"grid_name": "dggs_split26", "level": L}`` and the ``ds.dggs`` accessor works on it (``cell_centers``,
``cell_boundaries``, ``sel_latlon``, ``zoom_to``, ``assign_latlon_coords``, ``explore``, ``encode``).
xdggs (0.6 and its main branch) has no plug-in discovery (no entry-point group): its grids live in a
registry that imports fill, so ``import dggs.xdggs`` must run before decoding (``import dggs`` alone does not
import xarray or xdggs).

Cell ids are the uint64 ids of :func:`dggs.latlng_to_cell` (``as_int=True``) or the string ids; the
grid parameter ``id_format`` (``"int"`` or ``"str"``) says which, and is inferred from the coordinate's
dtype when the attributes leave it out. The grid is always on WGS84 (``ellipsoid="WGS84"``); the optional
``projection`` (``"ISEA"``, implied, or ``"IVEA"``) names the grid's projection (``dggs.Grid``, docs/grid.md).

Examples
--------
>>> import numpy as np, xarray as xr, xdggs
>>> import dggs, dggs.xdggs
>>> ids = dggs.latlng_to_cell(np.array([51.05, -33.9]), np.array([-114.07, 18.4]), 5, as_int=True)
>>> ds = xr.Dataset(coords={"cell_ids": ("cells", ids, {"grid_name": "dggs_split26", "level": 5})})
>>> xdggs.decode(ds).dggs.grid_info
Split26Info(level=5, ellipsoid='WGS84', id_format='int', projection='ISEA')
"""

from __future__ import annotations

import dataclasses
import json
import math
from collections.abc import Hashable, Mapping
from dataclasses import dataclass, field
from typing import Any, ClassVar

import numpy as np

try:
    import xarray as xr
    from xdggs.ellipsoid import Ellipsoid, Sphere
    from xdggs.grid import DGGSInfo, translate_parameters
    from xdggs.index import DGGSIndex
    from xdggs.utils import register_dggs
except ImportError as _exc:  # the optional extra: say which
    raise ImportError(
        f"dggs.xdggs needs xarray and xdggs ({_exc.name or _exc} is missing): pip install 'dggs[xarray]' "
        "(Python 3.11 or later)"
    ) from _exc

import dggs

__all__ = ["GRID_NAME", "Split26Info", "Split26Index", "GEOARROW_DENSIFY"]

GRID_NAME = "dggs_split26"
"""The name of the grid in xdggs (the ``grid_name`` attribute of the cell-id coordinate)."""

GEOARROW_DENSIFY = 16
"""Points per curved edge of the ``"geoarrow"`` boundaries (what ``explore`` draws) unless told otherwise."""

_ID_FORMATS = ("int", "str")
_OPTIONAL = frozenset({"id_format", "ellipsoid", "projection"})
_WGS84_AXES = {"semimajor_axis": 6378137.0, "inverse_flattening": 298.257223563}


def _parse_level(value: Any) -> int:
    if isinstance(value, bool | np.bool_):
        raise ValueError(f"level must be an integer between 0 and {dggs.MAX_LEVEL}, got {value!r}")
    try:
        level = int(value)
    except (TypeError, ValueError):
        raise ValueError(f"level must be an integer between 0 and {dggs.MAX_LEVEL}, got {value!r}") from None
    if level != value:
        raise ValueError(f"level must be an integer between 0 and {dggs.MAX_LEVEL}, got {value!r}")
    return level


def _parse_ellipsoid(value: Any) -> str:
    """``"WGS84"`` for any spelling of WGS84 xdggs has: a name, an ``Ellipsoid`` or its mapping form."""
    if isinstance(value, Ellipsoid | Sphere):
        value = value.to_dict()
    if isinstance(value, str):
        if value.upper() == "WGS84":
            return "WGS84"
    elif isinstance(value, Mapping):
        name = value.get("name")
        known = set(value) <= {"name", *_WGS84_AXES}
        named = name is None or (isinstance(name, str) and name.upper() == "WGS84")
        try:
            axes_ok = all(math.isclose(float(value[k]), v, rel_tol=1e-12) for k, v in _WGS84_AXES.items())
        except (KeyError, TypeError, ValueError):
            axes_ok = False
        if known and named and (axes_ok or (set(value) == {"name"} and name is not None)):
            return "WGS84"
    raise ValueError(f"the {GRID_NAME} grid is defined on WGS84 only, got ellipsoid={value!r}")


def _parse_projection(value: Any) -> str:
    if isinstance(value, str) and value.upper() in ("ISEA", "IVEA"):
        return value.upper()
    raise ValueError(f"projection must be 'ISEA' or 'IVEA', got {value!r}")


def _serialized_ellipsoid(value: Any) -> Any:
    """The ellipsoid as attributes hold it (a name or a mapping), as xdggs's grids write it."""
    return value.to_dict() if isinstance(value, Ellipsoid | Sphere) else value


def _as_ids(cell_ids: Any) -> np.ndarray:
    """Cell ids as a numpy array dggs reads: uint64 for integers, ``U`` for strings."""
    arr = np.asarray(cell_ids)
    if arr.dtype.kind in "iu":
        if arr.dtype.kind == "i" and arr.size and arr.min() < 0:
            raise ValueError("integer cell ids must be non-negative")
        return arr.astype(np.uint64, copy=False)
    if arr.dtype.kind in "SUT":  # dggs reads fixed-width and numpy StringDType arrays as they are
        return arr
    if arr.dtype.kind == "O":
        return arr.astype(str)
    raise TypeError(f"cell ids must be integers or strings, got dtype {arr.dtype}")


@dataclass(frozen=True)
class Split26Info(DGGSInfo):
    """Grid information of the dggs Split (2:6) grid for xdggs.

    Parameters
    ----------
    level : int
        The level of the cells, 0 to ``dggs.MAX_LEVEL`` (28). ``resolution`` and, in the CF and zarr
        conventions, ``refinement_level`` are accepted as synonyms by :meth:`from_dict`.
    ellipsoid : str, default "WGS84"
        Always ``"WGS84"``: the grid is equal-area on the WGS84 ellipsoid.
    id_format : {"int", "str"}, default "int"
        The kind of cell ids: uint64 ids (``dggs.str_to_int``) or the string ids.
    stated : mapping, optional
        The optional parameters (``id_format``, ``ellipsoid``) as the attributes stated them, which
        :meth:`to_dict` writes back as they were; set by :meth:`from_dict`. ``None`` (an info built
        directly): :meth:`to_dict` writes ``id_format``. Not part of equality: two infos of the same grid
        are equal however their attributes were spelled.

    Examples
    --------
    >>> Split26Info.from_dict({"grid_name": "dggs_split26", "level": 3}).to_dict()
    {'grid_name': 'dggs_split26', 'level': 3}
    >>> Split26Info(level=3, id_format="str").to_dict()
    {'grid_name': 'dggs_split26', 'level': 3, 'id_format': 'str'}
    """

    level: int
    ellipsoid: Any = "WGS84"
    id_format: str = "int"
    projection: str = "ISEA"
    stated: Mapping[str, Any] | None = field(default=None, compare=False, repr=False, kw_only=True)

    valid_parameters: ClassVar[dict[str, Any]] = {"level": range(dggs.MAX_LEVEL + 1), "id_format": _ID_FORMATS}

    def __post_init__(self) -> None:
        level_ok = isinstance(self.level, int | np.integer) and not isinstance(self.level, bool)
        if not level_ok or self.level not in self.valid_parameters["level"]:
            raise ValueError(f"level must be an integer between 0 and {dggs.MAX_LEVEL}, got {self.level!r}")
        if self.id_format not in _ID_FORMATS:
            raise ValueError(f"id_format must be 'int' or 'str', got {self.id_format!r}")
        object.__setattr__(self, "ellipsoid", _parse_ellipsoid(self.ellipsoid))  # one spelling: equality
        object.__setattr__(self, "projection", _parse_projection(self.projection))
        if self.stated is not None:
            unknown = sorted(set(self.stated) - _OPTIONAL)
            if unknown:
                raise ValueError(f"stated holds id_format and ellipsoid only (besides projection), got {unknown}")
            if self.stated.get("id_format", self.id_format) != self.id_format:
                raise ValueError(f"stated id_format {self.stated['id_format']!r} is not {self.id_format!r}")
            if "ellipsoid" in self.stated:
                _parse_ellipsoid(self.stated["ellipsoid"])
            object.__setattr__(self, "stated", dict(self.stated))

    @classmethod
    def from_dict(cls, mapping: Mapping[str, Any]) -> Split26Info:
        """Build the grid information from attributes (``grid_name`` is ignored, unknown keys raise).

        Raises
        ------
        ValueError
            If a key is unknown, the level is missing or out of range, or the ellipsoid is not WGS84.
        """
        translations = {
            "level": ("level", _parse_level),
            "resolution": ("level", _parse_level),
            "refinement_level": ("level", _parse_level),
            "id_format": ("id_format", str),
            "ellipsoid": ("ellipsoid", _parse_ellipsoid),
            "projection": ("projection", _parse_projection),
        }
        params = translate_parameters(dict(mapping), translations)
        unknown = sorted(set(params) - {"level", "id_format", "ellipsoid", "projection"})
        if unknown:
            raise ValueError(f"unknown parameters for the {GRID_NAME} grid: {unknown}")
        if "level" not in params:
            raise ValueError(f"the {GRID_NAME} grid needs a level")
        stated = {key: mapping[key] for key in _OPTIONAL if key in mapping}
        if "id_format" in stated:
            stated["id_format"] = params["id_format"]
        if "projection" in stated:
            stated["projection"] = params["projection"]
        if "ellipsoid" in stated:
            stated["ellipsoid"] = _serialized_ellipsoid(stated["ellipsoid"])
        return cls(**params, stated=stated)

    def to_dict(self) -> dict[str, Any]:
        """The grid parameters, with the grid name: the attributes :meth:`from_dict` read, as they were.

        ``level`` is always written under that name (``resolution`` and ``refinement_level`` are read as
        synonyms, as xdggs's own grids do); ``id_format`` and ``ellipsoid`` when the attributes stated
        them (:attr:`stated`). An info built directly writes ``id_format`` (WGS84 is implied).
        """
        if self.stated is None:
            named = {"projection": self.projection} if self.projection != "ISEA" else {}
            return {"grid_name": GRID_NAME, "level": self.level, "id_format": self.id_format} | named
        optional = {key: self.stated[key] for key in ("id_format", "ellipsoid", "projection") if key in self.stated}
        return {"grid_name": GRID_NAME, "level": self.level} | optional

    def cell_ids2geographic(self, cell_ids: Any) -> tuple[np.ndarray, np.ndarray]:
        """Cell centres as ``(lon, lat)`` arrays in degrees (xdggs's order; dggs's is ``(lat, lng)``)."""
        ids = _as_ids(cell_ids)
        if ids.size == 0:
            return np.empty(0), np.empty(0)
        lat, lng = dggs.Grid(self.projection).cell_to_latlng(ids)
        return np.asarray(lng, dtype=np.float64), np.asarray(lat, dtype=np.float64)

    def geographic2cell_ids(self, lon: Any, lat: Any) -> np.ndarray:
        """The cells of this level holding the points (degrees), as ids of ``id_format``."""
        lon_ = np.asarray(lon, dtype=np.float64)
        lat_ = np.asarray(lat, dtype=np.float64)
        grid = dggs.Grid(self.projection)
        return np.asarray(grid.latlng_to_cell(lat_, lon_, self.level, as_int=self.id_format == "int"))

    def cell_boundaries(self, cell_ids: Any, backend: str = "shapely", densify: int | None = None) -> Any:
        """Cell boundary polygons (lon, lat), split at the antimeridian into MultiPolygons.

        ``backend="shapely"`` gives an object array of shapely geometries (``dggs.cell_to_polygon``, whose
        default densification keeps polygon areas within 1e-6); ``backend="geoarrow"`` gives a geoarrow
        (multi)polygon array for lonboard, with :data:`GEOARROW_DENSIFY` points per edge by default.

        Raises
        ------
        ValueError
            If ``backend`` is not one of the supported backends.
        """
        if backend not in ("shapely", "geoarrow"):
            raise ValueError(f"invalid backend: {backend!r}")
        ids = _as_ids(cell_ids)
        if backend == "geoarrow" and densify is None:
            densify = GEOARROW_DENSIFY
        if backend == "geoarrow":
            return _to_geoarrow(ids, densify, self.projection)
        if ids.size == 0:
            return np.empty(0, dtype=object)
        return np.asarray(dggs.Grid(self.projection).cell_to_polygon(ids, densify=densify), dtype=object)

    def zoom_to(self, cell_ids: Any, level: int) -> np.ndarray:
        """Parents (``level`` < own level, shape (n,)) or children (shape (n, children per cell)) of the ids.

        Children past ``dggs.cell_to_children``'s limit (50 million cells) raise ``dggs.TooManyCellsError``.

        Raises
        ------
        ValueError
            If ``level`` is outside ``0..MAX_LEVEL``.
        """
        level = _parse_level(level)
        if not 0 <= level <= dggs.MAX_LEVEL:
            raise ValueError(f"level must be an integer between 0 and {dggs.MAX_LEVEL}, got {level!r}")
        ids = _as_ids(cell_ids)
        if level == self.level:
            same: np.ndarray = ids.copy()
            return same
        if level < self.level:
            return np.asarray(dggs.cell_to_parent(ids, level))
        per_cell = 3 ** (level - self.level) * (2 if self.level == 0 else 1)
        if ids.size == 0:
            return np.empty((0, per_cell), dtype=ids.dtype)
        # dggs's max_cells guard (TooManyCellsError past 50 million cells by default) applies
        children = np.asarray(dggs.cell_to_children(ids, level))
        return children.reshape(ids.size, per_cell)


def _to_geoarrow(ids: np.ndarray, densify: int | None, projection: str = "ISEA") -> Any:
    """A geoarrow ``polygon`` (or ``multipolygon``, when any cell crosses the antimeridian) array in EPSG:4326.

    Interleaved coordinates, read by geoarrow-c from the cells' WKB (``dggs.index._shapes.wkb_to_geoarrow``):
    11.7 us a cell against 22.4 us for ``shapely.to_ragged_array`` of the cells' polygons assembled into
    arro3 lists, the same values and types (``benchmarks/bench_handwritten.py``).
    """
    import pyproj
    from arro3.core import Array

    from dggs.index._checks import check_densify
    from dggs.index._convert import cells_in
    from dggs.index._shapes import wkb, wkb_to_geoarrow

    crs = pyproj.CRS.from_epsg(4326).to_json_dict()
    flat, _ = cells_in(ids)
    if projection == "IVEA":  # IVEA's polygons through shapely's WKB
        import pyarrow as pa
        import shapely

        from dggs.index._ivea_shapes import geometries

        geoms = geometries(flat.reshape(-1), None if densify is None else check_densify(densify))
        blobs, types = pa.array(shapely.to_wkb(geoms), pa.binary()), set(shapely.get_type_id(geoms).tolist())
        types = {"MultiPolygon" if t == 6 else "Polygon" for t in types}
    else:
        blobs, _, types = wkb(flat.reshape(-1), None if densify is None else check_densify(densify))
    multi = "MultiPolygon" in types
    array = Array.from_arrow(wkb_to_geoarrow(blobs, multi, interleaved=True, name=""))
    extension = "geoarrow.multipolygon" if multi else "geoarrow.polygon"
    metadata = {"ARROW:extension:name": extension, "ARROW:extension:metadata": json.dumps({"crs": crs})}
    return array.cast(array.field.with_metadata(metadata))


def _cell_id_variable(variables: Mapping[Any, xr.Variable]) -> tuple[Hashable, xr.Variable, Hashable]:
    if len(variables) != 1:
        raise ValueError(f"expected exactly one cell-id variable, got {list(variables)}")
    name, var = next(iter(variables.items()))
    if var.ndim != 1:
        raise ValueError(f"the cell-id variable must be 1-D, got dims {var.dims}")
    return name, var, var.dims[0]


@register_dggs(GRID_NAME)
class Split26Index(DGGSIndex):
    """The xdggs index of a cell-id coordinate of the Split (2:6) grid.

    Built by ``xdggs.decode`` from a 1-D coordinate with the attributes ``grid_name="dggs_split26"`` and
    ``level`` (``id_format`` optional, inferred from the dtype). Decoding checks that the ids are valid
    cells of that level.
    """

    _grid: Split26Info

    def __init__(self, cell_ids: Any, dim: Hashable, name: Hashable, grid_info: Split26Info):
        super().__init__(cell_ids, dim, grid_info)
        self._name = name
        self._index.index.name = name

    @classmethod
    def from_variables(
        cls,
        variables: Mapping[Any, xr.Variable],
        *,
        options: Mapping[str, Any],
    ) -> Split26Index:
        """Build the index from the cell-id variable of ``variables`` (xarray's index protocol).

        Raises
        ------
        ValueError
            If there is not exactly one 1-D cell-id variable, the grid attributes are not those of this
            grid, or an id is not a cell id of their level (plain ValueError, as xdggs's own grids raise).
        """
        name, var, dim = _cell_id_variable(variables)
        attrs = dict(var.attrs) | dict(options)
        data = var.data
        grid_info = Split26Info.from_dict(attrs)
        if "id_format" not in attrs:  # inferred from the dtype, and not written back by to_dict
            inferred = "int" if np.dtype(var.dtype).kind in "iu" else "str"
            grid_info = dataclasses.replace(grid_info, id_format=inferred)
        if isinstance(data, np.ndarray):
            _check_ids(data, grid_info)
        return cls(data, dim, name, grid_info)

    @property
    def grid_info(self) -> Split26Info:
        """The grid parameters (level, id format) of this index."""
        return self._grid

    def _replace(self, new_index: Any) -> Split26Index:
        return type(self)(new_index, self._dim, self._name, self._grid)

    def _repr_inline_(self, max_width: int) -> str:
        return f"Split26Index(level={self._grid.level}, id_format={self._grid.id_format!r})"


def _check_ids(data: np.ndarray, grid: Split26Info) -> None:
    kind = "int" if data.dtype.kind in "iu" else "str"
    if kind != grid.id_format:
        raise ValueError(f"id_format={grid.id_format!r} but the cell ids have dtype {data.dtype}")
    if data.size == 0:
        return
    ids = _as_ids(data)
    valid = np.asarray(dggs.is_valid_cell(ids), dtype=bool)
    if not valid.all():
        bad = ids[~valid][0]
        raise ValueError(f"invalid cell id for the {GRID_NAME} grid: {bad!r}")
    levels = np.asarray(dggs.get_level(ids))
    if (levels != grid.level).any():
        bad = ids[levels != grid.level][0]
        raise ValueError(f"cell {bad!r} is of level {dggs.get_level(bad)}, not {grid.level}")
