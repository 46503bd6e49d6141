"""The hand-written geometry and input code against the libraries made for it (issue 20, item 6).

Each table times dggs's own code and the library doing the same job on the same
input, and says whether the library's result is identical (byte for byte, or
value for value where the result is not bytes).  Medians of interleaved rounds
after a warm-up (``_common.interleaved``), wall time per call.

1. WKB of 100,000 level-10 cells (random ones plus cells along the antimeridian
   and at both poles): ``dggs.index._shapes.wkb`` (numpy records for the
   ordinary cells) against ``shapely.to_wkb`` of the cells' polygons; then the
   encoders alone on the ordinary cells' rings (both sides share the boundary
   kernel and the exact pole and antimeridian cells, which take most of the time).
2. GeoArrow of the same cells: the shapely ragged arrays assembled into pyarrow
   lists by hand, against geoarrow-c's ``as_geoarrow`` kernel reading the WKB (what
   dggs does now); and the same for the xdggs backend (interleaved coordinates,
   arro3 arrays).
3. The export's Polygon-to-MultiPolygon WKB rewrite (``dggs.arrow._as_multipolygons``)
   against shapely and geoarrow-pyarrow doing it.
4. Antimeridian splitting and pole closure of those cells' exact rings:
   ``ring_to_geometry`` against the ``antimeridian`` package's ``fix_polygon``.
5. A GeoJSON file of points with properties (about 50 MB): ``load_geojson`` plus
   ``geojson_batches`` against the same batches through pyogrio
   (``readers_vector.vector_batches``); and the parse alone with json, orjson and
   pyogrio's ``read_arrow``.
6. A 10,000-feature server page from cached geometry text: ``feature_collection``
   (strings joined) against ``json.dumps`` of the document and orjson with
   ``orjson.Fragment``; and ``dggs.cells_to_geojson`` against
   ``shapely.orient_polygons`` + ``mapping`` and ``shapely.to_geojson`` + ``json.loads``.

Run::

    .venv/bin/python benchmarks/bench_handwritten.py            # the sizes above
    .venv/bin/python benchmarks/bench_handwritten.py --quick    # a smoke test

Prints one Markdown section.
"""

from __future__ import annotations

import argparse
import json
import sys
import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import Any

sys.path.insert(0, str(Path(__file__).resolve().parent))

import numpy as np  # noqa: E402

import _common as c  # noqa: E402
from _common import fmt_ns, loadavg  # noqa: E402

Case = tuple[str, Callable[[], Any]]


def level10_cells(n: int) -> np.ndarray:
    """About ``n`` distinct level-10 int ids: random points, 1% along the antimeridian, 0.2% at the poles."""
    import dggs

    lat, lng = c.points(n)
    rng = np.random.default_rng(c.SEED + 1)
    k, p = n // 100, n // 500
    lat[:k] = rng.uniform(-89.99, 89.99, k)
    lng[:k] = rng.choice([-179.9999, 179.9999], k)
    lat[k : k + p] = rng.choice([-89.999, 89.999], p)
    ids: np.ndarray = np.unique(dggs.latlng_to_cell(lat, lng, 10, as_int=True))
    return ids


def _table(title: str, cases: list[Case], same: dict[str, str], rounds: int, unit: str, units: int) -> dict[str, Any]:
    times = c.interleaved({name: (fn, units) for name, fn in cases}, rounds, 120.0)
    return {"title": title, "times": times, "same": same, "unit": unit}


def wkb_table(ids: np.ndarray, rounds: int) -> list[dict[str, Any]]:
    import pyarrow as pa
    import shapely

    from dggs.index import _shapes as s

    out = []
    for d in (0, 16):
        def library(d: int = d) -> Any:
            geoms = s.geometries(ids, d)
            return shapely.to_wkb(geoms, byte_order=1, output_dimension=2), shapely.bounds(geoms)

        coords = s.boundaries(ids, d, lnglat=True)
        plain = coords[~s.special_rings(coords)]  # the ordinary cells' closed rings, as wkb() encodes them

        def records(plain: np.ndarray = plain) -> Any:
            block = s._wkb_records(plain)
            offsets = np.arange(plain.shape[0] + 1, dtype=np.int64) * block.shape[1]
            return s._binary_array([(np.arange(plain.shape[0]), offsets, block.reshape(-1))], plain.shape[0])

        def shapely_encoder(plain: np.ndarray = plain) -> Any:
            return shapely.to_wkb(shapely.polygons(plain), byte_order=1, output_dimension=2)

        ours = s.wkb(ids, d)
        lib = library()
        same = ours[0].to_pylist() == list(lib[0]) and np.array_equal(ours[1], lib[1])
        cases = [("dggs: numpy WKB records (index/_shapes.wkb)", lambda d=d: s.wkb(ids, d)),
                 ("shapely.to_wkb of the polygons, shapely.bounds", library),
                 ("the encoder alone, ordinary cells' rings: numpy records", records),
                 ("the encoder alone, ordinary cells' rings: shapely.polygons + to_wkb", shapely_encoder)]
        enc_same = records().equals(pa.array(shapely_encoder(), type=pa.binary()))
        out.append(_table(f"WKB and bounds of {ids.size:,} level-10 cells, densify={d}", cases,
                          {cases[1][0]: "yes" if same else "no", cases[3][0]: "yes" if enc_same else "no"},
                          rounds, "cell", ids.size))
    return out


def old_xdggs(polygons: np.ndarray) -> Any:
    """dggs.xdggs's geoarrow builder before geoarrow-c (kept here to time it): ragged arrays into arro3 lists."""
    import pyproj
    import shapely
    from arro3.core import list_array

    crs = pyproj.CRS.from_epsg(4326).to_json_dict()
    geometry_type, coords, offsets = shapely.to_ragged_array(polygons)
    coords = np.ascontiguousarray(coords, dtype=np.float64)
    if geometry_type == shapely.GeometryType.POLYGON:
        rings, geoms = offsets
        array = list_array(geoms.astype(np.int32), list_array(rings.astype(np.int32), coords))
        extension = "geoarrow.polygon"
    else:
        rings, parts, geoms = offsets
        array = list_array(geoms.astype(np.int32),
                           list_array(parts.astype(np.int32), list_array(rings.astype(np.int32), coords)))
        extension = "geoarrow.multipolygon"
    metadata = {"ARROW:extension:name": extension, "ARROW:extension:metadata": json.dumps({"crs": crs})}
    return array.cast(array.field.with_metadata(metadata))


def geoarrow_table(ids: np.ndarray, rounds: int) -> list[dict[str, Any]]:
    import pyarrow as pa
    import shapely

    import dggs
    from dggs.index import _shapes as s

    if c.try_import("geoarrow.c", "geoarrow-c") is None:
        return []
    from dggs.xdggs import _to_geoarrow

    def old_geoarrow(d: int) -> Any:  # the builder this table's library variant replaced (kept here to time it)
        kind, coords, offsets = shapely.to_ragged_array(s.geometries(ids, d))
        fields = [pa.field("x", pa.float64()), pa.field("y", pa.float64())]
        arr: Any = pa.StructArray.from_arrays([pa.array(coords[:, 0]), pa.array(coords[:, 1])], fields=fields)
        for off in offsets:
            arr = pa.ListArray.from_arrays(pa.array(np.asarray(off, dtype=np.int32)), arr)
        return arr

    out = []
    for d in (0, 16):
        same = s.geoarrow(ids, d)[0].equals(old_geoarrow(d))
        cases = [("hand-assembled pyarrow lists of shapely.to_ragged_array", lambda d=d: old_geoarrow(d)),
                 ("dggs now: geoarrow-c as_geoarrow of dggs's WKB (index/_shapes.geoarrow)",
                  lambda d=d: s.geoarrow(ids, d))]
        out.append(_table(f"GeoArrow (separated x/y) of {ids.size:,} level-10 cells, densify={d}", cases,
                          {cases[1][0]: "yes" if same else "no"}, rounds, "cell", ids.size))
    def former() -> Any:  # cell_boundaries(backend="geoarrow") before: the polygons, then their ragged arrays
        return old_xdggs(np.asarray(dggs.cell_to_polygon(ids, densify=4), dtype=object))

    lib = _to_geoarrow(ids, 4)
    same = lib.type == former().type and pa.array(lib).equals(pa.array(former()))
    cases = [("cell_to_polygon, shapely.to_ragged_array into arro3 lists (xdggs's former builder)", former),
             ("dggs.xdggs now: geoarrow-c as_geoarrow (interleaved) of dggs's WKB", lambda: _to_geoarrow(ids, 4))]
    out.append(_table(f"xdggs's geoarrow backend, {ids.size:,} level-10 cells (densify=4)", cases,
                      {cases[1][0]: "yes" if same else "no"}, rounds, "cell", ids.size))
    return out


def multipolygon_table(ids: np.ndarray, rounds: int) -> list[dict[str, Any]]:
    import pyarrow as pa
    import shapely

    from dggs.arrow import _as_multipolygons
    from dggs.index import _shapes as s

    ga = c.try_import("geoarrow.pyarrow", "geoarrow-pyarrow")
    blobs = s.wkb(ids, 16)[0]

    def with_geoarrow() -> Any:
        return ga.as_wkb(ga.as_geoarrow(ga.wkb().wrap_array(blobs), type=ga.multipolygon())).storage

    def with_shapely() -> Any:
        g = shapely.from_wkb(blobs.to_numpy(zero_copy_only=False))
        single = np.flatnonzero(shapely.get_type_id(g) == shapely.GeometryType.POLYGON)
        g[single] = shapely.multipolygons(g[single], indices=np.arange(single.size))
        return pa.array(shapely.to_wkb(g, byte_order=1, output_dimension=2), type=blobs.type)

    ours = _as_multipolygons(blobs)
    cases: list[Case] = [("dggs.arrow._as_multipolygons (a 9-byte header before each Polygon's WKB)",
                          lambda: _as_multipolygons(blobs)),
                         ("shapely: from_wkb, multipolygons, to_wkb", with_shapely)]
    same = {cases[1][0]: "yes" if with_shapely().equals(ours) else "no"}
    if ga is not None:
        cases.append(("geoarrow-pyarrow: as_geoarrow(multipolygon), as_wkb", with_geoarrow))
        same[cases[-1][0]] = "yes" if with_geoarrow().cast(ours.type).equals(ours) else "no"
    return [_table(f"WKB Polygons as one-part MultiPolygons (GeoPackage/FlatGeobuf export), {ids.size:,} cells, "
                   "densify=16", cases, same, rounds, "cell", ids.size)]


def antimeridian_table(ids: np.ndarray, rounds: int) -> list[dict[str, Any]]:
    import shapely
    from shapely.geometry import Polygon

    from dggs.index import _shapes as s
    from dggs.index._kernel import points as kp

    am = c.try_import("antimeridian")
    if am is None:
        return []
    d = 4
    special = ids[s.special_rings(s.boundaries(ids, d, lnglat=True))]
    buf = np.empty((3 * (d + 1) + kp.SPECIAL_EXTRA, 2))
    rings = []
    for i in special:
        m = kp.special_ring(i, d, buf)
        rings.append(buf[:m].copy())

    def ours() -> list[Any]:
        return [s.ring_to_geometry(r[:, 0], r[:, 1]) for r in rings]

    def library() -> list[Any]:
        return [am.fix_polygon(Polygon(r[:, ::-1]), great_circle=False) for r in rings]

    a, b = ours(), library()
    exact = sum(bool(x.equals_exact(y, 0.0)) for x, y in zip(a, b, strict=True))
    far = max(float(shapely.hausdorff_distance(x, y)) for x, y in zip(a, b, strict=True))
    same = f"no: {exact} of {len(a)} identical, the rest within {far:.1g} degrees (other start points, repeated points)"
    cases = [("dggs: ring_to_geometry (exact pole points, split at +-180)", ours),
             ("antimeridian.fix_polygon(great_circle=False)", library)]
    return [_table(f"Antimeridian and pole cells among the {ids.size:,} (densify={d}): {len(rings)} rings", cases,
                   {cases[1][0]: same}, rounds, "ring", len(rings))]


def geojson_file(path: Path, n: int) -> None:
    lat, lng = c.points(n)
    rng = np.random.default_rng(c.SEED)
    pop = rng.integers(0, 10**6, n).tolist()
    with open(path, "w") as fh:
        fh.write('{"type": "FeatureCollection", "features": [')
        for i, (y, x, p) in enumerate(zip(lat.tolist(), lng.tolist(), pop, strict=True)):
            feature = {"type": "Feature", "geometry": {"type": "Point", "coordinates": [x, y]},
                       "properties": {"pop": p, "name": f"place {i}", "score": p / 7}}
            fh.write(("," if i else "") + json.dumps(feature))
        fh.write("]}")


def reader_table(n: int, rounds: int) -> list[dict[str, Any]]:
    from dggs.storage import readers_geojson as rg
    from dggs.storage import readers_vector as rv

    orjson = c.try_import("orjson")
    pyogrio = c.try_import("pyogrio")
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "points.geojson"
        geojson_file(path, n)
        mb = path.stat().st_size / 1e6
        values = ["pop", "name"]

        def ours() -> list[Any]:
            return [(b.lat, b.lng, b.values) for b in rg.geojson_batches(rg.load_geojson(path), values, 10, 50_000)]

        def library() -> list[Any]:
            return [(b.lat, b.lng, b.values) for b in rv.vector_batches(path, None, values, 10, 50_000)]

        same = "yes" if ours() == library() else "no"
        cases: list[Case] = [("dggs: json.load + geojson_batches", ours),
                             ("pyogrio (GDAL) through readers_vector.vector_batches", library),
                             ("the parse alone: json.load", lambda: rg.load_geojson(path))]
        samesets = {cases[1][0]: same}
        if orjson is not None:
            cases.append(("the parse alone: orjson.loads", lambda: orjson.loads(path.read_bytes())["features"]))
            samesets[cases[-1][0]] = "yes" if orjson.loads(path.read_bytes())["features"] == rg.load_geojson(path) else "no"
        if pyogrio is not None:
            cases.append(("the parse alone: pyogrio.read_arrow", lambda: pyogrio.read_arrow(path)))
        return [_table(f"A GeoJSON file of {n:,} points with properties ({mb:.0f} MB)", cases, samesets, rounds,
                       "file", 1)]


def page_table(n: int, rounds: int) -> list[dict[str, Any]]:
    import shapely
    from shapely.geometry import MultiPolygon, Polygon, mapping

    import dggs
    from dggs.server.geojson import clean, feature_collection

    orjson = c.try_import("orjson")
    ids = level10_cells(n)[:n]
    zones = [str(z) for z in dggs.int_to_str(ids)]
    texts = [str(t) for t in shapely.to_geojson(np.asarray(dggs.cell_to_polygon(ids, densify=4), dtype=object))]
    props = [{"count": i, "mean": clean(i / 3), "name": f"zone {z}"} for i, z in enumerate(zones)]
    extra = {"numberReturned": n, "links": [{"href": "/next", "rel": "next"}]}

    def with_json() -> str:
        feats = [{"type": "Feature", "id": i, "geometry": json.loads(g), "properties": p}
                 for i, g, p in zip(zones, texts, props, strict=True)]
        return json.dumps({"type": "FeatureCollection", "features": feats, **extra}, allow_nan=False)

    def joined() -> str:  # the strings-joined feature_collection that orjson replaced (kept here to time it)
        dumps = json.dumps
        features = ",".join(
            f'{{"type":"Feature","id":{dumps(i)},"geometry":{g},"properties":{dumps(p, allow_nan=False)}}}'
            for i, g, p in zip(zones, texts, props, strict=True))
        tail = "".join(f",{dumps(k)}:{dumps(v, allow_nan=False)}" for k, v in extra.items())
        return f'{{"type":"FeatureCollection","features":[{features}]{tail}}}'

    ref = json.loads(joined())
    cases: list[Case] = [("strings joined around json.dumps of each feature's properties", joined),
                         ("json.dumps of the document (geometry text parsed)", with_json)]
    same = {cases[1][0]: "yes" if json.loads(with_json()) == ref else "no"}
    if orjson is not None:
        def with_orjson() -> bytes:
            feats = [{"type": "Feature", "id": i, "geometry": orjson.Fragment(g), "properties": p}
                     for i, g, p in zip(zones, texts, props, strict=True)]
            out: bytes = orjson.dumps({"type": "FeatureCollection", "features": feats, **extra})
            return out

        cases.append(("orjson.dumps, geometry text as orjson.Fragment", with_orjson))
        same[cases[-1][0]] = "yes" if json.loads(with_orjson()) == ref else "no"
    cases.append(("dggs: feature_collection as it is now", lambda: feature_collection(zones, texts, props, extra)))
    same[cases[-1][0]] = "yes" if json.loads(feature_collection(zones, texts, props, extra)) == ref else "no"
    out = [_table(f"A server page of {n:,} features from cached geometry text", cases, same, rounds, "page", 1)]

    polys = np.asarray(dggs.cell_to_polygon(ids, densify=16), dtype=object)

    def orient(g: Any) -> Any:  # the orient loop that shapely.orient_polygons replaced (kept here to time it)
        if isinstance(g, Polygon):
            return shapely.geometry.polygon.orient(g, 1.0)
        return MultiPolygon([shapely.geometry.polygon.orient(p, 1.0) for p in g.geoms])

    oriented = shapely.orient_polygons(polys, exterior_cw=False)
    ref2 = [mapping(orient(g)) for g in polys]
    now = [f["geometry"] for f in dggs.cells_to_geojson(ids, densify=16)["features"]]
    cases = [("orientation: shapely.geometry.polygon.orient one polygon at a time", lambda: [orient(g) for g in polys]),
             ("orientation: shapely.orient_polygons, one call", lambda: shapely.orient_polygons(polys, exterior_cw=False)),
             ("to dicts: shapely mapping of each oriented polygon", lambda: [mapping(g) for g in oriented]),
             ("to dicts: shapely.to_geojson + json.loads", lambda: [json.loads(t) for t in shapely.to_geojson(oriented)]),
             ("dggs.cells_to_geojson as it is now (whole features)", lambda: dggs.cells_to_geojson(ids, densify=16))]
    same = {cases[1][0]: "yes" if [mapping(g) for g in oriented] == ref2 else "no",
            cases[3][0]: "yes" if [json.loads(t) for t in shapely.to_geojson(oriented)] == json.loads(json.dumps(ref2))
            else "no (float text)",
            cases[4][0]: "yes" if now == ref2 else "no"}
    out.append(_table(f"cells_to_geojson of {n:,} level-10 cells (densify=16)", cases, same, rounds, "cell", n))
    return out


def render(tables: list[dict[str, Any]], load: list[list[float]], code: dict[str, Any]) -> str:
    lines = ["### Written by hand or by a library (bench_handwritten.py)\n",
             f"Wall time per unit, medians of interleaved rounds; default threads. {c.describe_code(code)}; "
             f"1-minute load average {load[0][0]:.2f} at the start, {load[1][0]:.2f} at the end.\n"]
    for t in tables:
        lines.append(f"#### {t['title']}\n\n| code | wall per {t['unit']} | vs the first row | identical result |\n"
                     "|---|---:|---:|---|")
        first = next(iter(t["times"].values()), None)
        for name, v in t["times"].items():
            per = v["wall"] / v["units"] if v.get("units") else None
            ratio = v["wall"] / first["wall"] if first and first["wall"] else None
            lines.append(f"| {name} | {fmt_ns(per)} | {c.fmt_ratio(ratio)} | {t['same'].get(name, '-')} |")
        lines.append("")
    lines.append(c.notes_section())
    return "\n".join(lines) + "\n"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="small sizes, 1 round (a smoke test)")
    ap.add_argument("--only", default="", help="comma-separated tables: wkb,geoarrow,multipolygon,antimeridian,reader,page")
    args = ap.parse_args()
    cells, features, page, rounds = (5_000, 20_000, 1_000, 1) if args.quick else (100_000, 260_000, 10_000, 5)
    only = set(filter(None, args.only.split(",")))
    code, load0 = c.code_state(), loadavg()
    ids = level10_cells(cells)
    parts: list[tuple[str, Callable[[], list[dict[str, Any]]]]] = [
        ("wkb", lambda: wkb_table(ids, rounds)),
        ("geoarrow", lambda: geoarrow_table(ids, rounds)),
        ("multipolygon", lambda: multipolygon_table(ids, rounds)),
        ("antimeridian", lambda: antimeridian_table(ids, rounds)),
        ("reader", lambda: reader_table(features, rounds)),
        ("page", lambda: page_table(page, rounds)),
    ]
    tables: list[dict[str, Any]] = []
    for name, run in parts:
        if not only or name in only:
            tables += run()
    print(render(tables, [load0, loadavg()], code))


if __name__ == "__main__":
    main()
