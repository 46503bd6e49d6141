"""The shapes floor: cell boundaries, and rings to shapely, WKB and GeoArrow (no Python loop per cell).

:func:`boundaries` runs the compiled kernel; :func:`geometries` gives shapely
polygons (all ordinary cells in one ``shapely.polygons`` call), :func:`wkb`
little-endian WKB straight from the boundary arrays, :func:`geoarrow` native
GeoArrow arrays.  :func:`dggs.cell_to_polygon`, :mod:`dggs.arrow`, the
exports and the server all build cells here.

A boundary ring (lat, lng) becomes a lng/lat polygon.  Rings that cross the
antimeridian or touch a pole (a few cells per level) need unwrapping,
closing over the pole and splitting at +-180; they take :func:`ring_to_geometry`
one by one.  Every other ring is already a simple counter-clockwise lng/lat
ring and goes into one vectorized call.
"""

from __future__ import annotations

import math
import sys
from typing import Any

import numpy as np
import shapely
from shapely.geometry import MultiPolygon, Polygon, box
from shapely.geometry.polygon import orient

from dggs.errors import TooManyCellsError

from ._checks import check_densify, check_point_count
from ._densify import EXACT, check_tolerance, edge_points
from ._kernel import points as kp

_POLE_TOL = 1e-9  # degrees
_WKB_POLYGON = 3


def boundaries(ids: np.ndarray, densify: int, lnglat: bool = False, max_points: int | None = None) -> np.ndarray:
    """(N, 3 (densify + 1), 2) (lat, lng) points of valid ids, or closed (lng, lat) rings one point longer.

    Raises
    ------
    TooManyCellsError
        More points than ``max_points`` (default :data:`dggs.index._checks.MAX_POINTS`), checked before allocating.
    """
    check_point_count(ids.shape[0], 3 * (densify + 1) + int(lnglat), max_points)
    out = np.empty((ids.shape[0], 3 * (densify + 1) + int(lnglat), 2))
    kp.boundaries(ids.shape[0] * (densify + 1), ids, densify, out, lnglat)
    return out


def special_rings(coords: np.ndarray) -> np.ndarray:
    """Rows of closed (lng, lat) rings (N, M, 2) that may cross the antimeridian or touch a pole.

    A step of more than 90 degrees of longitude between consecutive points
    (across +-180, or past a pole between two points), or a point within a
    degree of a pole: the few cells that take the exact per-cell path.
    """
    steps = np.abs(np.diff(coords[..., 0], axis=1))
    special: np.ndarray = (steps > 90.0).any(axis=1) | (np.abs(coords[..., 1]) > 89.0).any(axis=1)
    return special


def rings_to_geometries(coords: np.ndarray, ids: np.ndarray, densify: int) -> np.ndarray:
    """Object array of shapely geometries of the cells ``ids`` from their closed (lng, lat) rings (N, M, 2).

    Ordinary rings go into one ``shapely.polygons`` call; the special ones
    are recomputed by the kernel with their exact pole and antimeridian
    points (:func:`dggs.index.kp.special_ring`) and built one by one.
    """
    n = coords.shape[0]
    out = np.empty(n, dtype=object)
    if n == 0:
        return out
    special = special_rings(coords)
    if special.any():
        plain = ~special
        out[plain] = shapely.polygons(coords[plain])
        buf = np.empty((3 * (densify + 1) + kp.SPECIAL_EXTRA, 2))
        for i in np.flatnonzero(special):
            m = kp.special_ring(ids[i], densify, buf)
            out[i] = ring_to_geometry(buf[:m, 0], buf[:m, 1])
    else:
        out[:] = shapely.polygons(coords)
    return out


def _pole_pairs(lat: np.ndarray, lng: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The ring with every point at a pole given as two: arriving and leaving longitude.

    The kernel's exact rings already give pole points in pairs; a lone pole
    point (a plain boundary's corner) takes its neighbours' longitudes.
    """
    at_pole = np.abs(np.abs(lat) - 90.0) < _POLE_TOL
    if not at_pole.any():
        return lat, lng
    m = len(lat)
    ys: list[float] = []
    xs: list[float] = []
    i = 0
    while i < m:
        if at_pole[i]:
            pole = math.copysign(90.0, lat[i])
            if i + 1 < m and at_pole[i + 1]:
                xs += [float(lng[i]), float(lng[i + 1])]
                i += 2
            else:
                xs += [float(lng[i - 1]), float(lng[(i + 1) % m])]
                i += 1
            ys += [pole, pole]
        else:
            xs.append(float(lng[i]))
            ys.append(float(lat[i]))
            i += 1
    return np.array(ys), np.array(xs)


def ring_to_geometry(lat: np.ndarray, lng: np.ndarray) -> Polygon | MultiPolygon:
    """A lng/lat ring on the sphere (counter-clockwise seen from outside) -> shapely geometry.

    Longitudes are unwrapped so that consecutive points are under 180
    degrees apart, except along a pole (two consecutive points at latitude
    +-90), where the ring runs west at the North Pole and east at the South
    Pole (the cell lies below, resp. above, that side), over the cell's
    angle at the pole.  The result is split at the antimeridian, and every
    exterior is counter-clockwise (RFC 7946).

    Written by hand, and kept: the ``antimeridian`` package's ``fix_polygon`` took 2.1 ms a ring against
    0.65 ms here (830 pole and antimeridian rings among 100,000 level-10 cells), and gave other rings
    (other start points, repeated points, up to 4e-13 degrees apart; benchmarks/bench_handwritten.py).
    """
    ys, xs = _pole_pairs(np.asarray(lat, dtype=float), np.asarray(lng, dtype=float))
    steps = np.diff(np.concatenate([xs, xs[:1]]))
    steps = (steps + 180.0) % 360.0 - 180.0
    along = (np.abs(ys) == 90.0) & (np.roll(ys, -1) == ys)
    if along.any():
        raw = np.roll(xs, -1)[along] - xs[along]
        steps[along] = np.where(ys[along] > 0, -((-raw) % 360.0), raw % 360.0)
    xs = xs[0] + np.concatenate([[0.0], np.cumsum(steps[:-1])])
    winding = float(np.sum(steps))
    if abs(winding) > 180.0:  # the ring goes round a pole: close it over the pole
        pole = 90.0 if ys.mean() > 0 else -90.0
        xs = np.concatenate([xs, [xs[-1], xs[0] + winding, xs[0] + winding]])
        ys = np.concatenate([ys, [pole, pole, ys[0]]])
    poly = Polygon(np.column_stack([xs, ys]))
    if not poly.is_valid:
        poly = shapely.make_valid(poly)
    lo, hi = xs.min(), xs.max()
    if lo >= -180.0 and hi <= 180.0:
        parts = [poly]
    else:
        parts = []
        for k in range(int(math.floor((lo + 180.0) / 360.0)), int(math.floor((hi + 180.0) / 360.0)) + 1):
            window = box(-180.0 + 360.0 * k, -90.0, 180.0 + 360.0 * k, 90.0)
            piece = poly.intersection(window)
            if not piece.is_empty:
                parts.append(shapely.affinity.translate(piece, xoff=-360.0 * k))
    geoms: list[Any] = []
    for p in parts:
        geoms.extend(getattr(p, "geoms", [p]))
    geoms = [orient(g, 1.0) for g in geoms if isinstance(g, Polygon) and g.area > 0]
    return geoms[0] if len(geoms) == 1 else MultiPolygon(geoms)


def densify_groups(
    ids: np.ndarray, densify: int | None, tolerance: Any = EXACT, ivea: bool = False
) -> list[tuple[np.ndarray, int]]:
    """(row indices, densify) per group of rows built alike: one group, or one per count cells need.

    With ``densify=None`` each cell gets the points per edge ``tolerance`` needs
    (:func:`dggs.index._densify.edge_points`): by default, ``"exact"``, those that keep its
    geodesic area within 1e-6 of the cell's.
    """
    if densify is not None:
        return [(np.arange(ids.shape[0]), check_densify(densify))]
    need = edge_points(ids, tolerance, ivea)
    return [(np.flatnonzero(need == n), int(n)) for n in np.unique(need).tolist()]


def special_geometries(ids: np.ndarray, densify: int) -> np.ndarray:
    """Shapely geometries of cells that touch a pole or cross the antimeridian (exact kernel rings)."""
    out = np.empty(ids.shape[0], dtype=object)
    buf = np.empty((3 * (densify + 1) + kp.SPECIAL_EXTRA, 2))
    for i in range(ids.shape[0]):
        m = kp.special_ring(ids[i], densify, buf)
        out[i] = ring_to_geometry(buf[:m, 0], buf[:m, 1])
    return out


def _wkb_records(coords: np.ndarray) -> np.ndarray:
    """(N, L) uint8: the little-endian WKB Polygon of each closed (lng, lat) ring of ``coords`` (N, M, 2).

    Written by hand, and kept (docs/architecture.md, "Written by hand, and why"): on the ordinary rings of
    100,000 level-10 cells these records take 125 ns a cell against 9.3 us for shapely.polygons +
    shapely.to_wkb (1.0 us against 16.5 us at densify=16), the same bytes (benchmarks/bench_handwritten.py).
    """
    n, m = coords.shape[0], coords.shape[1]
    record = np.dtype([("order", "u1"), ("type", "<u4"), ("rings", "<u4"), ("points", "<u4"), ("xy", "<f8", (m, 2))])
    out = np.empty(n, dtype=record)
    out["order"] = 1
    out["type"] = _WKB_POLYGON
    out["rings"] = 1
    out["points"] = m
    out["xy"] = coords
    return out.view(np.uint8).reshape(n, record.itemsize)


def _binary_array(chunks: list[tuple[np.ndarray, np.ndarray, np.ndarray]], n: int) -> Any:
    """A binary array of ``n`` rows from (rows, offsets-from-0, data) chunks, each chunk's rows ascending.

    Each chunk's bytes are copied straight to their rows' places, a run of consecutive rows at a time
    (the ordinary cells are one chunk, split only where a cell at a pole or across the antimeridian
    sits between them): no gather of the whole array afterwards.
    """
    import pyarrow as pa

    lengths = np.zeros(n, dtype=np.int64)
    for rows, offsets, _ in chunks:
        lengths[rows] = np.diff(offsets)
    ends = np.zeros(n + 1, dtype=np.int64)
    np.cumsum(lengths, out=ends[1:])
    data = np.empty(int(ends[-1]), dtype=np.uint8)
    for rows, offsets, blob in chunks:
        if rows.size == 0:
            continue
        breaks = np.flatnonzero(np.diff(rows) != 1) + 1
        for a, b in zip([0, *breaks.tolist()], [*breaks.tolist(), rows.size], strict=True):
            dst = int(ends[rows[a]])
            data[dst : dst + int(offsets[b] - offsets[a])] = blob[int(offsets[a]) : int(offsets[b])]
    arr = pa.LargeBinaryArray.from_buffers(pa.large_binary(), n, [None, pa.py_buffer(ends), pa.py_buffer(data)])
    return arr.cast(pa.binary()) if ends[-1] < 2**31 - 1 else arr


def _checked_groups(
    ids: np.ndarray, densify: int | None, max_points: int | None, tolerance: Any = EXACT
) -> list[tuple[np.ndarray, int]]:
    """:func:`densify_groups`, after checking the points of all groups together against ``max_points``."""
    groups = densify_groups(ids, densify, tolerance)
    if groups:
        widest = max(3 * (d + 1) + 1 for _, d in groups)
        total = sum(rows.shape[0] * (3 * (d + 1) + 1) for rows, d in groups)
        check_point_count(ids.shape[0], widest, max_points) if len(groups) == 1 else check_point_count(1, total, max_points)
    return groups


def wkb(
    ids: np.ndarray, densify: int | None, max_points: int | None = None, tolerance: Any = EXACT
) -> tuple[Any, np.ndarray, set[str]]:
    """WKB of each cell, its (N, 4) bounds and the geometry types present (``tolerance`` as :func:`densify_groups`)."""
    n = ids.shape[0]
    chunks = []
    bounds = np.empty((n, 4))
    types: set[str] = set()
    for rows, d in _checked_groups(ids, densify, max_points, tolerance):
        coords = boundaries(ids[rows], d, lnglat=True)
        special = special_rings(coords)
        plain = rows[~special]
        if plain.size:
            xy = coords[~special] if plain.size < rows.size else coords
            block = _wkb_records(xy)
            offsets = np.arange(plain.size + 1, dtype=np.int64) * block.shape[1]
            chunks.append((plain, offsets, block.reshape(-1)))
            for k in (0, 1):  # one coordinate at a time: 8x faster than reducing (N, M, 2) over axis 1
                bounds[plain, k] = xy[..., k].min(axis=1)
                bounds[plain, k + 2] = xy[..., k].max(axis=1)
            types.add("Polygon")
        if special.any():
            sel = rows[special]
            geoms = special_geometries(ids[sel], d)
            blobs = shapely.to_wkb(geoms, byte_order=1, output_dimension=2)
            lengths = np.fromiter((len(b) for b in blobs), dtype=np.int64, count=blobs.shape[0])
            offsets = np.concatenate([[0], np.cumsum(lengths)])
            chunks.append((sel, offsets, np.frombuffer(b"".join(blobs), dtype=np.uint8)))
            bounds[sel] = shapely.bounds(geoms)
            types.update(g.geom_type for g in geoms)
    return _binary_array(chunks, n), bounds, types


#: Cells a pass of :func:`ragged_geometries` draws at once: its scratch (13 rows a cell, 1.7 MB) stays in cache.
_RAGGED_CHUNK = 8192


def ragged_geometries(ids: np.ndarray, tolerance: Any = EXACT, max_points: int | None = None, ivea: bool = False) -> np.ndarray:
    """Shapely geometries of valid ids, each with the points per edge ``tolerance`` needs, in one ragged build.

    The core counts each cell's points per edge and writes its (lng, lat) ring in one pass (from the count's own
    points at 0, 1 or 3 an edge: :func:`dggs.index._kernel.edge_bound.edge_rings_count`), then lays the rings end
    to end and flags those at a pole or across the antimeridian (``edge_rings_write``), which are replaced by
    their exact geometries one by one.  In chunks; ``max_points`` checked before each chunk's buffer.
    """
    from ._kernel import edge_bound
    from ._kernel import ivea_points as ki

    n = ids.shape[0]
    check_point_count(0, 0, max_points)  # a bad max_points is named before any work
    ids = np.ascontiguousarray(ids, dtype=np.uint64)
    metres, area = check_tolerance(tolerance)
    proj, kernel = (1, ki) if ivea else (0, kp)
    out = np.empty(n, dtype=object)
    scratch = np.empty((min(n, _RAGGED_CHUNK) * edge_bound.EDGE_RING_ROWS, 2))
    total = 0
    for lo in range(0, n, _RAGGED_CHUNK):
        part = ids[lo : lo + _RAGGED_CHUNK]
        m = part.shape[0]
        counts = np.empty(m, dtype=np.int32)
        rows = edge_bound.edge_rings_count(proj, part, metres, area, counts, scratch)
        total += rows
        try:
            check_point_count(1, total, max_points)
        except TooManyCellsError:  # named with the points of every cell, as a check before any work would
            check_point_count(1, int((3 * (edge_points(ids, tolerance, ivea) + 1) + 1).sum()), max_points)
            raise
        offsets, coords, special = np.empty(m + 1, dtype=np.int64), np.empty((rows, 2)), np.empty(m, dtype=np.uint8)
        edge_bound.edge_rings_write(proj, part, counts, scratch, offsets, coords, special)
        out[lo : lo + m] = shapely.from_ragged_array(shapely.GeometryType.POLYGON, coords, (offsets, np.arange(m + 1)))
        for i in np.flatnonzero(special).tolist():
            d = int(counts[i])
            buf = np.empty((3 * (d + 1) + kernel.SPECIAL_EXTRA, 2))
            k = kernel.special_ring(part[i], d, buf)
            out[lo + i] = ring_to_geometry(buf[:k, 0], buf[:k, 1])
    return out


def geometries(ids: np.ndarray, densify: int | None, max_points: int | None = None, tolerance: Any = EXACT) -> np.ndarray:
    """Shapely geometries of valid ids: one group per densify, ordinary rings in one ``shapely.polygons`` call.

    Without ``densify``, :func:`ragged_geometries` (each cell its own count, one build).
    """
    if densify is None:
        return ragged_geometries(ids, tolerance, max_points)
    out = np.empty(ids.shape[0], dtype=object)
    for rows, d in _checked_groups(ids, densify, max_points, tolerance):
        coords = boundaries(ids[rows], d, lnglat=True)
        special = special_rings(coords)
        out[rows[~special]] = shapely.polygons(coords[~special])
        if special.any():
            out[rows[special]] = special_geometries(ids[rows[special]], d)
    return out


#: geoarrow-c's type ids (geoarrow.h: GEOARROW_TYPE_POLYGON, GEOARROW_TYPE_MULTIPOLYGON; interleaved x/y adds 10000).
_GEOARROW_POLYGON, _GEOARROW_MULTIPOLYGON, _GEOARROW_INTERLEAVED = 3, 6, 10_000


def _kernel_options(options: dict[str, object]) -> bytes:
    """geoarrow-c's kernel options: a count, then each key and value as length-prefixed UTF-8 (native int32s)."""
    out = len(options).to_bytes(4, sys.byteorder, signed=True)
    for key, value in options.items():
        for text in (str(key).encode(), str(value).encode()):
            out += len(text).to_bytes(4, sys.byteorder, signed=True) + text
    return out


def wkb_to_geoarrow(blobs: Any, multi: bool, interleaved: bool = False, name: str = "item") -> Any:
    """Native GeoArrow storage (a plain pyarrow list array) of WKB polygons, by geoarrow-c's ``as_geoarrow``.

    ``multi``: multipolygons (one list level more); ``interleaved``: ``fixed_size_list<double>[2]``
    coordinates instead of ``struct<x, y>``; ``name``: the list fields' names.  geoarrow-c is called
    through its C data interface, so pyarrow gets no extension types registered (importing
    geoarrow-pyarrow would register them for the whole process, and change what ``pa.array`` gives
    other code for any field tagged ``geoarrow.*``).
    """
    import pyarrow as pa

    try:
        from geoarrow.c import lib
    except ImportError:  # pragma: no cover - geoarrow-c is a dependency
        raise ImportError("GeoArrow output needs geoarrow-c: pip install geoarrow-c") from None
    if interleaved:
        coord: Any = pa.list_(pa.field("item", pa.float64(), nullable=False), 2)
    else:
        coord = pa.struct([pa.field("x", pa.float64()), pa.field("y", pa.float64())])
    storage = pa.list_(pa.field(name, pa.list_(pa.field(name, coord))))
    if multi:
        storage = pa.list_(pa.field(name, storage))
    if len(blobs) == 0:
        return pa.array([], type=storage)
    kind = (_GEOARROW_MULTIPOLYGON if multi else _GEOARROW_POLYGON) + (_GEOARROW_INTERLEAVED if interleaved else 0)
    kernel = lib.CKernel(b"as_geoarrow")
    schema = lib.SchemaHolder()
    tag = {b"ARROW:extension:name": b"geoarrow.wkb", b"ARROW:extension:metadata": b"{}"}
    pa.field("geometry", blobs.type, metadata=tag)._export_to_c(schema._addr())
    kernel.start(schema, _kernel_options({"type": kind}))
    holder = lib.ArrayHolder()
    blobs._export_to_c(holder._addr())
    out = kernel.push_batch(holder)  # held while pyarrow imports it: a dropped holder releases the array
    return pa.Array._import_from_c(out._addr(), storage)


def geoarrow(
    ids: np.ndarray, densify: int | None, max_points: int | None = None, tolerance: Any = EXACT
) -> tuple[Any, str]:
    """Native GeoArrow polygons (or multipolygons where any cell is split), separated x/y.

    geoarrow-c reads the cells' WKB (:func:`wkb`, :func:`wkb_to_geoarrow`): 6.9 us a cell against
    20.5 us for ``shapely.to_ragged_array`` assembled into pyarrow lists (28 us against 38 us at
    densify=16), the same values and types (``benchmarks/bench_handwritten.py``).
    """
    blobs, _, types = wkb(ids, densify, max_points, tolerance)
    multi = "MultiPolygon" in types
    return wkb_to_geoarrow(blobs, multi), "geoarrow.multipolygon" if multi else "geoarrow.polygon"
