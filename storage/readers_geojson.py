"""Read GeoJSON: points as they are, polygons as the cells they cover.

A file is loaded whole (GeoJSON is one JSON document), then cut into
:class:`~dggs.storage.readers.RawBatch` es of features.
"""

from __future__ import annotations

import json
from collections.abc import Iterator, Sequence
from functools import partial
from pathlib import Path
from typing import Any

import numpy as np

import dggs
from dggs.errors import DggsValueError

from .readers import RawBatch

__all__ = ["load_geojson", "geojson_batches", "feature_problem"]


#: How deep each geometry's coordinates nest to reach a position (RFC 7946, sections 3.1.2-3.1.7).
_DEPTH = {"Point": 0, "MultiPoint": 1, "Polygon": 2, "MultiPolygon": 3}


class _Malformed(ValueError):
    """A geometry whose coordinates are not what RFC 7946 says its type holds."""


def _position(value: Any) -> tuple[float, ...]:
    """A position: an array of two or more numbers (RFC 7946, 3.1.1); JSON strings and booleans are not numbers."""
    if not isinstance(value, (list, tuple)):
        raise _Malformed(f"a position must be an array of numbers, not {_shown(value)}")
    if len(value) < 2:
        raise _Malformed(f"a position needs two or more numbers, not {_shown(value)}")
    for number in value:
        if isinstance(number, bool) or not isinstance(number, (int, float)):
            raise _Malformed(f"coordinate {_shown(number)} in {_shown(value)} is not a number")
    try:
        return tuple(float(number) for number in value)
    except OverflowError:
        raise _Malformed(f"a coordinate in {_shown(value)} is too large for a float") from None


def _checked(kind: str, coords: Any) -> list[Any]:
    """The coordinates of a ``kind`` geometry as nested lists of float positions, or _Malformed saying why."""
    depth = _DEPTH[kind]
    if depth == 0:
        return list(_position(coords))

    def walk(value: Any, level: int) -> list[Any]:
        if not isinstance(value, (list, tuple)):
            raise _Malformed(f"{kind} coordinates must be arrays nested {depth} deep, not {_shown(value)}")
        if level == 1:
            return [list(_position(v)) for v in value]
        return [walk(v, level - 1) for v in value]

    out = walk(coords, depth)
    if kind == "MultiPoint" and not out:
        raise _Malformed("MultiPoint has no points")
    return out


def _shown(value: Any) -> str:
    """A short repr for a message (a malformed geometry can be large)."""
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def _json_text(value: Any) -> Any:
    """A nested property (a JSON object or array) as JSON text, as it was in the file; anything else as it is."""
    if isinstance(value, (dict, list, tuple)):
        return json.dumps(value, ensure_ascii=False)
    return value


def _feature_at(props: Sequence[dict[str, Any]], lat: Sequence[Any], lng: Sequence[Any], i: int) -> dict[str, Any]:
    return {"lat": lat[i], "lng": lng[i], **props[i]}


def load_geojson(path: str | Path) -> list[dict[str, Any]]:
    """Read the features of a GeoJSON file (FeatureCollection, Feature or geometry).

    The json module, kept (docs/architecture.md, "Written by hand, and why"): for a 49 MB file of
    260,000 points, this and :func:`geojson_batches` took 7.7 s against 15.1 s through pyogrio
    (:func:`dggs.storage.readers_vector.vector_batches`); orjson parses it in 4.9 s against 6.4 s,
    but reads integers past 64 bits as floats, refuses NaN and Infinity and stops at depth 1024
    with another error, each a change of what a file gives (benchmarks/bench_handwritten.py).

    Raises
    ------
    DggsValueError
        If the file is not GeoJSON.
    """
    try:
        with open(path, encoding="utf-8") as fh:
            data = json.load(fh)
    except (json.JSONDecodeError, UnicodeDecodeError) as exc:
        raise DggsValueError(f"{path} is not valid JSON: {exc}") from exc
    except RecursionError:
        raise DggsValueError(f"{path} is nested too deeply to read as GeoJSON") from None
    kind = data.get("type") if isinstance(data, dict) else None
    if kind == "FeatureCollection" and isinstance(data.get("features"), list):
        features: list[dict[str, Any]] = data["features"]
        return features
    if kind == "Feature":
        return [data]
    if isinstance(kind, str) and "coordinates" in data:
        return [{"type": "Feature", "geometry": data, "properties": {}}]
    raise DggsValueError(f"{path} is not GeoJSON (no FeatureCollection, Feature or geometry)")


def feature_problem(feature: Any) -> tuple[Any, str] | None:
    """(value, reason) if ``feature`` cannot be stored whatever its coordinates, else None.

    Its properties are no JSON object, or its geometry is none of Point,
    MultiPoint, Polygon and MultiPolygon (RFC 7946, section 3.1): a bad row.
    """
    geometry: Any = feature.get("geometry") if isinstance(feature, dict) else None
    prop = (feature.get("properties") or {}) if isinstance(feature, dict) else {}
    if not isinstance(prop, dict):
        return prop, "feature properties are not a JSON object"
    kind = geometry.get("type") if isinstance(geometry, dict) else None
    if kind not in _DEPTH:
        return kind, "geometry is not a Point, MultiPoint, Polygon or MultiPolygon"
    return None


def _add_cells(add: Any, row: int, prop: dict[str, Any], polygon: Any, level: int, bad: dict, at: int,
               grid: Any = None) -> None:
    """One entry per cell whose centre ``polygon`` holds, at its centre; a bad entry if it holds none.

    The cells are ``grid``'s (default ISEA's): the store's grid.
    """
    grid = dggs.Grid() if grid is None else grid
    found = grid.polygon_to_cells(polygon, level)
    if not len(found):
        bad[at] = (None, polygon.geom_type, f"polygon holds no cell centre at level {level}")
        add(row, None, None, "", prop)
        return
    clat, clng = grid.cell_to_latlng(np.asarray(found))
    triples = zip(np.asarray(found).tolist(), np.ravel(clat).tolist(), np.ravel(clng).tolist(), strict=True)
    for part, (cell, y, x) in enumerate(triples):
        add(row, y, x, cell, prop, part)


def geojson_batches(
    features: Sequence[Any],
    values: Sequence[str],
    level: int,
    batch_size: int,
    skip: int = 0,
    projection: str = "ISEA",
) -> Iterator[RawBatch]:
    """Cut GeoJSON features into batches: points as they are, polygons as cells (of ``Grid(projection)``).

    A ``Polygon``/``MultiPolygon`` feature becomes one entry per cell at
    ``level`` whose centre lies inside it (:func:`dggs.polygon_to_cells`),
    each with the feature's properties and the cell centre as coordinates.
    A ``MultiPoint`` gives one entry per point.  Coordinates are checked
    against RFC 7946 first: a geometry whose coordinates are not arrays of
    numbers nested as its type says (strings, booleans, objects, an empty
    MultiPoint, a number too large for a float) is one bad entry, counted as
    rejected.  Nested properties (JSON objects and arrays) are given as JSON text.
    """
    from shapely.errors import ShapelyError
    from shapely.geometry import shape

    grid = dggs.Grid(projection)
    for start in range(skip, len(features), batch_size):
        chunk = features[start : start + batch_size]
        rows: list[int] = []
        lat: list[Any] = []
        lng: list[Any] = []
        cells: list[str] = []
        props: list[dict[str, Any]] = []
        parts: list[int] = []
        bad: dict[int, tuple[str | None, Any, str]] = {}

        # this chunk's lists are bound as defaults: a closure would see whichever lists the loop made last
        def add(
            row: int, y: Any, x: Any, cell: str, prop: dict[str, Any], part: int = 0, *,
            rows: list[int] = rows, parts: list[int] = parts, lat: list[Any] = lat, lng: list[Any] = lng,
            cells: list[str] = cells, props: list[dict[str, Any]] = props,
        ) -> None:
            rows.append(row)
            parts.append(part)
            lat.append(y)
            lng.append(x)
            cells.append(cell)
            props.append(prop)

        for offset, feature in enumerate(chunk):
            row = start + offset + 1
            geometry: Any = feature.get("geometry") if isinstance(feature, dict) else None
            prop = (feature.get("properties") or {}) if isinstance(feature, dict) else {}
            problem = feature_problem(feature)
            if problem is not None:
                bad[len(rows)] = (None, *problem)
                add(row, None, None, "", prop if isinstance(prop, dict) else {})
                continue
            kind: str = geometry["type"]  # one of _DEPTH's
            try:
                coords = _checked(kind, geometry.get("coordinates"))
                if kind == "Point":
                    add(row, coords[1], coords[0], "", prop)
                elif kind == "MultiPoint":
                    for part, (x, y, *_) in enumerate(coords):
                        add(row, y, x, "", prop, part)
                else:
                    _add_cells(add, row, prop, shape({"type": kind, "coordinates": coords}), level, bad, len(rows),
                               grid)
            except _Malformed as exc:
                bad[len(rows)] = (None, kind, f"geometry is malformed: {exc}")
                add(row, None, None, "", prop)
            except (ValueError, ShapelyError) as exc:  # shapely's or the fill's refusal (DggsValueError)
                bad[len(rows)] = (None, kind, f"geometry cannot be filled: {exc}")
                add(row, None, None, "", prop)

        yield RawBatch(
            consumed=len(chunk),
            rows=rows,
            lines=None,
            lat=lat,
            lng=lng,
            values={name: [_json_text(p.get(name)) for p in props] for name in values},
            text=False,
            record=partial(_feature_at, props, lat, lng),
            bad=bad,
            cells=cells,
            parts=parts,
        )
