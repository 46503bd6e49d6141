"""Distances and lines: great-circle and geodesic distances, the cells along a geodesic.

Distances in metres are geodesic distances on the WGS84 ellipsoid
(``pyproj.Geod``, Karney's algorithm, exact to a few nanometres); distances
in radians are central angles on a sphere (haversine), as h3's
``great_circle_distance(..., unit="rads")``.  The cells along a line follow the
WGS84 geodesic between the two points.
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any

import numpy as np

from dggs.errors import CoordinateError, DggsValueError

from ._checks import check_level, check_projection, is_choice
from ._convert import VALUE, Op, apply_pair, as_float_scalar, coords_in, pair_kind, values_out
from ._convert.coords import _container
from ._convert.frames import polars_out
from ._kernel import points as kp

__all__ = ["great_circle_distance", "cell_centers_distance", "geodesic_to_cells", "DISTANCE_UNITS"]


@lru_cache(maxsize=1)
def _geod() -> Any:
    """Pyproj's WGS84 geodesic solver, made on first use (``import dggs`` stays free of pyproj)."""
    import pyproj

    return pyproj.Geod(ellps="WGS84")


#: Units of the distance functions: metres and kilometres on WGS84, radians on the sphere.
DISTANCE_UNITS = ("m", "km", "rad")


def _check_unit(unit: Any) -> str:
    if not is_choice(unit, DISTANCE_UNITS):
        raise DggsValueError(f"unit {unit!r} must be one of {', '.join(map(repr, DISTANCE_UNITS))}")
    checked: str = unit
    return checked


def _distance(lat1: np.ndarray, lng1: np.ndarray, lat2: np.ndarray, lng2: np.ndarray, unit: str) -> np.ndarray:
    if unit == "rad":
        p1, p2 = np.radians(lat1), np.radians(lat2)
        dlat, dlng = p2 - p1, np.radians(lng2 - lng1)
        h = np.sin(dlat / 2) ** 2 + np.cos(p1) * np.cos(p2) * np.sin(dlng / 2) ** 2
        angle: np.ndarray = 2 * np.arcsin(np.sqrt(np.clip(h, 0.0, 1.0)))
        return angle
    _, _, d = _geod().inv(lng1, lat1, lng2, lat2)
    d = np.asarray(d, dtype=np.float64)
    return d / 1000.0 if unit == "km" else d


def _centres(ids: np.ndarray, projection: str = "ISEA") -> tuple[np.ndarray, np.ndarray]:
    lat, lng = np.empty(ids.shape[0]), np.empty(ids.shape[0])
    if projection == "ISEA":
        kp.centres(ids.shape[0], ids, lat, lng)
    else:  # IVEA's centres (loaded on first use)
        from ._kernel import ivea_points

        ivea_points.centres(ids.shape[0], ids, lat, lng)
    return lat, lng


def _centres_distance(a: np.ndarray, b: np.ndarray, unit: str, projection: str = "ISEA") -> np.ndarray:
    return _distance(*_centres(a, projection), *_centres(b, projection), unit)


_CENTRES_DISTANCE = Op(many=_centres_distance, out=VALUE)


def _check_range(lat: np.ndarray, lng: np.ndarray, what: str) -> None:
    bad = ~(np.isfinite(lat) & np.isfinite(lng) & (np.abs(lat) <= 90.0))
    if bad.any():
        i = int(np.flatnonzero(bad)[0])
        raise CoordinateError(
            f"{what} point ({float(lat[i])!r}, {float(lng[i])!r}) at index {i} is not a finite latitude "
            "in -90..90 and a finite longitude"
        )


def great_circle_distance(lat1: Any, lng1: Any, lat2: Any, lng2: Any, unit: str = "m") -> Any:
    """Distance between points (geodetic WGS84 degrees), element-wise.

    ``unit="m"`` or ``"km"``: the geodesic distance on the WGS84 ellipsoid
    (``pyproj.Geod.inv``, exact to nanometres; the shortest path on the
    ellipsoid, which the great circle is on a sphere).  ``unit="rad"``: the
    central angle on a sphere (haversine of the given latitudes), as in h3.

    Parameters
    ----------
    lat1, lng1, lat2, lng2 : float or array_like
        Degrees; shapes broadcast as in numpy.
    unit : {"m", "km", "rad"}

    Returns
    -------
    float or ndarray

    Raises
    ------
    CoordinateError
        A latitude outside -90..90, a non-finite or non-numeric value, or shapes that do not broadcast.
    DggsValueError
        An unknown ``unit``.

    Examples
    --------
    >>> round(great_circle_distance(51.05, -114.07, 49.28, -123.12, "km"), 3)
    675.421
    >>> round(great_circle_distance(0, 0, 0, 90, "rad"), 6)
    1.570796
    """
    _check_unit(unit)
    a1, o1, k1 = coords_in(lat1, lng1)
    a2, o2, k2 = coords_in(lat2, lng2)
    try:
        shape = np.broadcast_shapes(k1.shape, k2.shape)
    except ValueError:
        raise CoordinateError(
            f"first points of shape {k1.shape} do not broadcast with second points of shape {k2.shape}"
        ) from None
    _check_range(a1, o1, "first")
    _check_range(a2, o2, "second")
    a1, o1, a2, o2 = (np.broadcast_to(x.reshape(k.shape), shape).reshape(-1) for x, k in ((a1, k1), (o1, k1), (a2, k2), (o2, k2)))
    return values_out(_distance(a1, o1, a2, o2, unit), pair_kind(k1, k2, shape))


def cell_centers_distance(a: Any, b: Any, unit: str = "m", *, projection: str = "ISEA") -> Any:
    """Distance between the centres of cells ``a`` and ``b`` (element-wise, shapes broadcast).

    The centres are :func:`dggs.cell_to_latlng`'s; the distance is
    :func:`great_circle_distance`'s (geodesic on WGS84 for ``"m"`` and ``"km"``).
    Cells of different levels are allowed.  ``projection`` (``"ISEA"`` or ``"IVEA"``, which
    ``dggs.Grid(projection).cell_centers_distance`` passes) picks the grid whose centres are measured.

    Raises
    ------
    InvalidCellError
        A malformed id.
    DggsValueError
        An unknown ``unit``, or shapes that do not broadcast.

    Examples
    --------
    >>> round(cell_centers_distance("C401", "C402", "km"), 1)
    869.6
    >>> [round(d, 1) for d in cell_centers_distance(["C401", "C402"], "C401")]
    [0.0, 869565.6]
    """
    return apply_pair(_CENTRES_DISTANCE, a, b, _check_unit(unit), check_projection(projection))


# --------------------------------------------------------------------------
# Cells along a geodesic
# --------------------------------------------------------------------------

def geodesic_to_cells(
    lat1: Any, lng1: Any, lat2: Any, lng2: Any, level: int, as_int: bool = False, max_cells: int | None = None,
    *, projection: str = "ISEA",
) -> Any:
    """The cells along the WGS84 geodesic from one point to another, in order (h3's ``grid_path_cells``).

    The one-segment case of :func:`dggs.line_to_cells`: the geodesic
    (``pyproj.Geod``) is traced by the compiled tracer, which samples it every
    half short edge and bisects wherever two consecutive cells are not edge
    neighbours; a line that passes within 0.1 mm of a corner is joined around
    that corner the shorter way.  Hence the first cell holds the start point, the last
    the end point, every cell meets the geodesic, and consecutive cells share
    an edge.  A cell can appear twice if the geodesic leaves and re-enters it
    (curved edges), never twice in a row.

    Parameters
    ----------
    lat1, lng1, lat2, lng2 : float
        Start and end point, geodetic WGS84 degrees.
    level : int
        Level of the cells.
    as_int : bool
        Return uint64 ids instead of strings.
    max_cells : int, optional
        Refuse lines longer than this many cells (an upper estimate from the
        length, 3 cells per short edge plus 24, checked before any sampling;
        default :data:`dggs.index.hierarchy.MAX_CELLS`).
    projection : {"ISEA", "IVEA"}
        The grid whose cells are found (``dggs.Grid(projection).geodesic_to_cells`` passes it; docs/grid.md).

    Returns
    -------
    ndarray of str or uint64
        For containers of end points (broadcast against each other, as :func:`dggs.latlng_to_cell`),
        one such array per line, in the coordinates' kind of container (a list of arrays for lists,
        an object array for numpy, a Series of arrays, a pyarrow list array).

    Raises
    ------
    CoordinateError
        A latitude outside -90..90 or a non-finite or non-numeric coordinate.
    LevelError
        A bad level.
    DggsValueError
        ``max_cells`` is not None or a non-negative integer.
    TooManyCellsError
        The line could have more than ``max_cells`` cells (the upfront estimate, or the cells found).

    Examples
    --------
    >>> cells = geodesic_to_cells(51.05, -114.07, 49.28, -123.12, 9)
    >>> str(cells[0]), str(cells[-1]), len(cells)
    ('F200021102', 'F201011110', 44)
    >>> import dggs
    >>> bool(dggs.are_neighbor_cells(cells[:-1], cells[1:]).all())
    True
    """
    level = check_level(level)
    projection = check_projection(projection)
    if any(_container(v) is not None for v in (lat1, lng1, lat2, lng2)):
        return _geodesics(lat1, lng1, lat2, lng2, level, as_int, max_cells, projection)
    lat1, lng1, lat2, lng2 = (
        as_float_scalar(v, n) for v, n in ((lat1, "latitude"), (lng1, "longitude"), (lat2, "latitude"), (lng2, "longitude"))
    )
    _check_range(np.array([lat1, lat2]), np.array([lng1, lng2]), "a")
    from .paths import line_to_cells  # the compiled tracer of polylines (paths imports nothing of this module)

    return line_to_cells(np.array([[lat1, lng1], [lat2, lng2]]), level, as_int, max_cells, projection=projection)


def _geodesics(
    lat1: Any, lng1: Any, lat2: Any, lng2: Any, level: int, as_int: bool, max_cells: int | None, projection: str
) -> Any:
    """:func:`geodesic_to_cells` of each line of containers of end points, in the first container's kind."""
    a_lat, a_lng, ka = coords_in(lat1, lng1)
    b_lat, b_lng, kb = coords_in(lat2, lng2)
    sa, sb = ka.shape, kb.shape
    try:
        shape = np.broadcast_shapes(sa, sb)
    except ValueError:
        raise CoordinateError(f"start points of shape {sa} do not match end points of shape {sb}") from None
    a_lat, a_lng, b_lat, b_lng = (
        np.broadcast_to(v.reshape(s), shape).reshape(-1) for v, s in ((a_lat, sa), (a_lng, sa), (b_lat, sb), (b_lng, sb))
    )
    lines = np.empty(a_lat.size, dtype=object)
    for i in range(a_lat.size):
        try:
            lines[i] = geodesic_to_cells(
                float(a_lat[i]), float(a_lng[i]), float(b_lat[i]), float(b_lng[i]), level, as_int, max_cells,
                projection=projection,
            )
        except DggsValueError as e:
            raise type(e)(f"{e} (line at index {i})" if a_lat.size > 1 else str(e)) from None
    kind = pair_kind(ka, kb, shape)
    if kind.container in ("arrow", "polars"):
        import pyarrow as pa

        arr = pa.array([line.tolist() for line in lines])
        if kind.container == "polars":
            return polars_out(arr, kind.name)
        return pa.chunked_array([arr], type=arr.type) if kind.chunked else arr
    return values_out(lines, kind)
