"""A GeoParquet 1.1.0 referee for the tests: every MUST of the specification that a file can break.

Written from the specification's text (format-specs/geoparquet.md, tag v1.1.0); section names are
cited as "§...".  The ``geo`` metadata is checked against ``fixtures/geoparquet-1.1.0.schema.json``
(written from the same text); what a JSON schema cannot say is checked here, reading the file with
readers that are not dggs: DuckDB's ``parquet_schema`` and ``parquet_kv_metadata`` for the Parquet
schema (repetition, physical types) and the key/value metadata, pyarrow and shapely for the rows.

:func:`violations` returns one message per broken rule (empty: the file meets them all).
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
import shapely

SCHEMA = json.loads((Path(__file__).parent / "fixtures" / "geoparquet-1.1.0.schema.json").read_text())
_KINDS = {1: "Point", 2: "LineString", 3: "Polygon", 4: "MultiPoint", 5: "MultiLineString", 6: "MultiPolygon",
          7: "GeometryCollection"}


def _root_nodes(path: Path) -> dict[str, dict[str, Any]]:
    """The root fields of the Parquet schema as DuckDB reads them: repetition, physical type, children."""
    import duckdb

    rows = duckdb.connect().execute(
        "SELECT name, repetition_type, num_children, type FROM parquet_schema(?)", [str(path)]).fetchall()
    nodes: dict[str, dict[str, Any]] = {}
    i = 1  # rows are the schema tree depth first; row 0 is the root 'schema' group
    while i < len(rows):
        name, rep, kids, kind = rows[i]
        children = []
        j = i + 1
        for _ in range(kids or 0):  # the bbox group's children are leaves (checked below)
            children.append({"name": rows[j][0], "repetition": rows[j][1], "type": rows[j][3], "group": bool(rows[j][2])})
            j += 1
        nodes[name] = {"repetition": rep, "type": kind, "group": kids is not None and kids > 0, "children": children}
        i = j if not any(c["group"] for c in children) else len(rows)  # nested groups: stop (none expected)
    return nodes


def _geo(path: Path) -> tuple[dict | None, list[str]]:
    import duckdb

    rows = duckdb.connect().execute(
        "SELECT value FROM parquet_kv_metadata(?) WHERE key = 'geo'", [str(path)]).fetchall()
    if len(rows) != 1:
        return None, ["§Metadata: a GeoParquet file MUST include a 'geo' key in the Parquet metadata"]
    try:
        return json.loads(rows[0][0].decode("utf-8")), []
    except (UnicodeDecodeError, ValueError) as exc:
        return None, [f"§Metadata: 'geo' MUST be a JSON-encoded UTF-8 string ({exc})"]


def _in_lng(x: np.ndarray, lo: np.ndarray, hi: np.ndarray, tol: float) -> np.ndarray:
    """x within [lo, hi], or within [lo, 180] or [-180, hi] where lo > hi (RFC 7946 §5.2)."""
    plain = (x >= lo - tol) & (x <= hi + tol)
    wrapped = (x >= lo - tol) | (x <= hi + tol)
    inside: np.ndarray = np.where(lo <= hi, plain, wrapped)
    return inside


def violations(path: str | Path, tol: float = 1e-9) -> list[str]:
    """Every GeoParquet 1.1.0 rule the file at ``path`` breaks, one message each."""
    import jsonschema
    import pyarrow.parquet as pq

    path = Path(path)
    geo, out = _geo(path)
    if geo is None:
        return out
    out += [f"§Metadata (schema): {e.message} at {list(e.absolute_path)}"
            for e in jsonschema.Draft202012Validator(SCHEMA).iter_errors(geo)]
    if out:
        return out
    if geo["primary_column"] not in geo["columns"]:
        out.append(f"§File metadata: primary_column {geo['primary_column']!r} is not one of the columns")
    nodes = _root_nodes(path)
    table = pq.read_table(path)
    for name, col in geo["columns"].items():
        node = nodes.get(name)
        if node is None:  # §Nesting: geometry columns MUST be at the root of the schema
            out.append(f"§Nesting: geometry column {name!r} is not at the root of the Parquet schema")
            continue
        if node["repetition"] not in ("REQUIRED", "OPTIONAL"):
            out.append(f"§Repetition: geometry column {name!r} is {node['repetition']}, not required or optional")
        if col["encoding"] == "WKB" and (node["group"] or node["type"] != "BYTE_ARRAY"):
            out.append(f"§WKB: column {name!r} MUST be stored as BYTE_ARRAY, not {node['type']}")
        geoms = shapely.from_wkb(table.column(name).to_numpy(zero_copy_only=False))
        present = ~shapely.is_missing(geoms)
        out += _types(name, col, table.column(name).to_pylist(), present)
        if col.get("orientation") == "counterclockwise":
            out += _orientation(name, geoms[present])
        if "covering" in col:
            out += _covering(name, col, node, nodes, table, geoms, present, tol)
        if "bbox" in col and present.any():
            out += _file_bbox(name, col["bbox"], geoms[present], tol)
    return out


def _types(name: str, col: dict, blobs: list, present: np.ndarray) -> list[str]:
    """§geometry_types: 'It is expected that this field is strictly correct'."""
    if not col["geometry_types"]:
        return []
    found = set()
    for blob in blobs:
        if blob is not None:
            code = int.from_bytes(blob[1:5], "little" if blob[0] == 1 else "big")
            found.add(_KINDS[code % 1000] + (" Z" if code // 1000 in (1, 3) else ""))
    if found != set(col["geometry_types"]):
        return [f"§geometry_types: column {name!r} declares {sorted(col['geometry_types'])}, holds {sorted(found)}"]
    return []


def _orientation(name: str, geoms: np.ndarray) -> list[str]:
    """§orientation: exterior rings counterclockwise, interior rings clockwise."""
    polys = shapely.get_parts(geoms)
    shells = shapely.get_exterior_ring(polys)
    bad = int((~shapely.is_ccw(shells)).sum())
    holes = [shapely.get_interior_ring(p, i) for p in polys for i in range(shapely.get_num_interior_rings(p))]
    bad += int(shapely.is_ccw(np.array(holes, dtype=object)).sum()) if holes else 0
    return [f"§orientation: {bad} ring(s) of {name!r} wound against 'counterclockwise'"] if bad else []


def _covering(name: str, col: dict, geom_node: dict, nodes: dict, table: Any, geoms: np.ndarray,
              present: np.ndarray, tol: float) -> list[str]:
    """§covering and §Bounding Box Columns."""
    paths = col["covering"]["bbox"]
    groups = {p[0] for p in paths.values()}
    if len(groups) != 1:
        return [f"§bbox covering encoding: all values MUST use the same column name, not {sorted(groups)}"]
    (bbox,) = groups
    node = nodes.get(bbox)
    if node is None or not node["group"]:
        return [f"§Bounding Box Columns: {bbox!r} MUST be a group field at the root of the schema"]
    out = []
    names = [c["name"] for c in node["children"]]
    if names not in (["xmin", "ymin", "xmax", "ymax"], ["xmin", "ymin", "zmin", "xmax", "ymax", "zmax"]):
        out.append(f"§Bounding Box Columns: the fields of {bbox!r} are {names}, not xmin, ymin, [zmin,] xmax, ymax, [zmax]")
    kinds = {c["type"] for c in node["children"]}
    if len(kinds) != 1 or not kinds <= {"FLOAT", "DOUBLE"}:
        out.append(f"§Bounding Box Columns: the fields MUST all be FLOAT or all DOUBLE, not {sorted(map(str, kinds))}")
    if node["repetition"] != geom_node["repetition"]:
        out.append(f"§Bounding Box Columns: the repetition of {bbox!r} ({node['repetition']}) MUST match "
                   f"the geometry column's ({geom_node['repetition']})")
    boxes = table.column(bbox).combine_chunks()
    has_box = ~np.asarray(boxes.is_null().to_numpy(zero_copy_only=False))
    if not np.array_equal(has_box, present):
        out.append("§Bounding Box Columns: a row MUST contain a bounding box iff it contains a geometry")
        return out
    b = {k: boxes.field(k).to_numpy(zero_copy_only=False).astype(float) for k in ("xmin", "ymin", "xmax", "ymax")}
    xy, row = shapely.get_coordinates(geoms, return_index=True)
    inside = _in_lng(xy[:, 0], b["xmin"][row], b["xmax"][row], tol)
    inside &= (xy[:, 1] >= b["ymin"][row] - tol) & (xy[:, 1] <= b["ymax"][row] + tol)
    if not inside.all():
        rows = np.unique(row[~inside])
        out.append(f"§Bounding Box Columns: {rows.size} row(s) have points outside their bbox (RFC 7946 §5), e.g. row {rows[0]}")
    return out


def _file_bbox(name: str, bbox: list, geoms: np.ndarray, tol: float) -> list[str]:
    """§bbox: the file's bbox (RFC 7946 §5) holds every coordinate of the column."""
    xy = shapely.get_coordinates(geoms)
    x0, y0, x1, y1 = bbox[:2] + bbox[-2:] if len(bbox) == 4 else (bbox[0], bbox[1], bbox[3], bbox[4])
    inside = _in_lng(xy[:, 0], np.full(len(xy), x0), np.full(len(xy), x1), tol)
    inside &= (xy[:, 1] >= y0 - tol) & (xy[:, 1] <= y1 + tol)
    return [] if inside.all() else [f"§bbox: the bbox {bbox} of {name!r} leaves out {int((~inside).sum())} point(s)"]
