"""The timed tables of bench_kernel.py, run inside one worker process (one thread or default).

Each ``table_*`` function builds its cases (dggs and the peers at the nearest
cell size), runs them round-robin (``_common.interleaved``) and returns a
table: ``{"title", "unit", "rows": [{op, impl, ref, wall, cpu, units}]}``.
``ref`` names the row a peer row is compared with (its time per unit over
that row's, so >= 1x means dggs is at least as fast).  A function of the new
API that is not there yet is skipped with a note (see ``_common.note``).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from _common import interleaved, note, points, sampled

#: Our levels and the peers' resolutions closest in mean cell area (km^2):
#: dggs 10 ~216 / h3 5 ~253; dggs 15 ~0.89 / h3 8 ~0.74; dggs 17 ~0.099 / h3 9 ~0.105.
H3_RES = {10: 5, 15: 8, 17: 9}
EARTH_KM2 = 510_065_621.7  # the WGS84 ellipsoid's area; dggs cells split it equally
DGGS_INT = "dggs (int ids)"
DGGS_STR = "dggs (string ids)"


def dggs_area_km2(level: int) -> float:
    """Mean (= exact) cell area of a dggs level: 20 faces, 6 level-1 cells, then 3 children each."""
    return EARTH_KM2 / 20 if level == 0 else EARTH_KM2 / (120 * 3 ** (level - 1))


def healpy_nside(area_km2: float) -> int:
    """The power-of-two nside whose pixel area is closest to ``area_km2`` (in log)."""
    return min((2**p for p in range(0, 30)),
               key=lambda ns: abs(math.log(EARTH_KM2 / (12 * ns * ns) / area_km2)))


def a5_res(a5, area_km2: float) -> int:
    best, best_d = 0, float("inf")
    for res in range(0, 31):
        try:
            d = abs(math.log(a5.cell_area(res) / 1e6 / area_km2))
        except Exception:
            break
        if d < best_d:
            best, best_d = res, d
    return best


def count_cells(res: Any) -> int:
    """Cells in a result: uint64 arrays without the 0 padding, string arrays without '', arrow lists flattened."""
    if isinstance(res, np.ndarray):
        if res.dtype == np.uint64 or res.dtype.kind in "iu":
            return int(np.count_nonzero(res))
        if res.dtype.kind == "U":
            return int(np.count_nonzero(res != ""))
        if res.dtype == object:
            return int(sum(count_cells(np.asarray(x)) if not isinstance(x, str) else 1 for x in res.ravel()))
        return int(res.size)
    if isinstance(res, (list, tuple)):
        return sum(count_cells(np.asarray(x)) for x in res)
    try:  # an arrow array (h3ronpy): flatten a list array
        import pyarrow as pa

        a = pa.array(res)
        while pa.types.is_list(a.type) or pa.types.is_large_list(a.type):
            a = a.flatten()
        return len(a) - a.null_count
    except Exception:
        return len(res)


class Kernel:
    """The dggs calls, int ids where the new API is there, string ids otherwise (with a note)."""

    def __init__(self) -> None:
        import dggs

        from _common import has_int_api

        self.d = dggs
        self.has_int = has_int_api()
        if not self.has_int:
            note("dggs has no `as_int=True` yet (the 64-bit id API): the int-id rows are skipped and the "
                 "operations that need ids run on string ids instead, labelled as such.")
        self.kinds = ["int", "str"] if self.has_int else ["str"]
        self.primary = self.kinds[0]
        self.label = {"int": DGGS_INT, "str": DGGS_STR}

    def cells(self, lat, lng, level: int, kind: str):
        if kind == "int":
            return self.d.latlng_to_cell(lat, lng, level, as_int=True)
        return self.d.latlng_to_cell(lat, lng, level)

    def polyfill(self, poly, level: int, kind: str):
        if kind == "int":
            return self.d.polygon_to_cells(poly, level, as_int=True)
        return self.d.polygon_to_cells(poly, level)


def _rows(secs: dict, ref: dict[Any, str]) -> list[dict[str, Any]]:
    return [dict(op=op, impl=impl, ref=ref.get((op, impl)), **v) for (op, impl), v in secs.items()]


# --------------------------------------------------------------------------- point to cell


def table_point_to_cell(k: Kernel, mods: dict[str, Any], n: int, loop_n: int, repeat: int,
                        budget: float) -> dict[str, Any]:
    lat, lng = points(n)
    theta, phi = np.radians(90.0 - lat), np.radians(lng)  # healpy's angles, made outside the timing
    lat_l, lng_l = lat[:loop_n].tolist(), lng[:loop_n].tolist()
    pts = list(zip(lng_l, lat_l, strict=True))  # A5 takes (lng, lat)
    cases: dict[tuple[str, str], tuple] = {}
    ref: dict[tuple[str, str], str] = {}
    prim = k.label[k.primary]
    h3, hv, hp, a5 = mods.get("h3"), mods.get("h3ronpy.vector"), mods.get("healpy"), mods.get("a5")
    for lv in (10, 17):
        r = H3_RES[lv]
        area = dggs_area_km2(lv)
        op = f"level {lv} ({area:.3g} km²)"
        for kind in k.kinds:
            cases[(op, k.label[kind])] = (lambda lv=lv, kind=kind: k.cells(lat, lng, lv, kind), n,
                                          sampled(lambda a, b, lv=lv, kind=kind: k.cells(a, b, lv, kind), lat, lng))
        if hv is not None:
            cases[(op, f"h3ronpy `coordinates_to_cells`, res {r}")] = (lambda r=r: hv.coordinates_to_cells(lat, lng, r), n)
        if hp is not None:
            ns = healpy_nside(area)
            cases[(op, f"healpy `ang2pix(nest=True)`, nside {ns} ({EARTH_KM2 / (12 * ns * ns):.3g} km²)")] = (
                lambda ns=ns: hp.ang2pix(ns, theta, phi, nest=True), n)
        if h3 is not None:
            from h3.api import basic_int as h3i

            cases[(op, f"h3-py string API loop, res {r}")] = (
                lambda r=r: [h3.latlng_to_cell(a, b, r) for a, b in zip(lat_l, lng_l, strict=True)], loop_n)
            cases[(op, f"h3-py int API loop, res {r}")] = (
                lambda r=r: [h3i.latlng_to_cell(a, b, r) for a, b in zip(lat_l, lng_l, strict=True)], loop_n)
        if a5 is not None:
            ar = a5_res(a5, area)
            cases[(op, f"A5 (pya5) loop, res {ar} ({a5.cell_area(ar) / 1e6:.3g} km²)")] = (
                lambda ar=ar: [a5.lonlat_to_cell(p, ar) for p in pts], loop_n)
    for key in cases:
        if key[1] != prim:
            ref[key] = prim
    secs = interleaved(cases, repeat, budget)
    return {"title": f"Point to cell, {n:,} random points uniform on the sphere (Python loops on the first "
                     f"{loop_n:,}); dggs level 10 vs h3 res 5, level 17 vs h3 res 9, healpy and A5 at the closest area",
            "unit": "point", "rows": _rows(secs, ref)}


def table_levels(k: Kernel, n: int, repeat: int, budget: float) -> dict[str, Any]:
    """dggs point to cell alone: time per point against the level and the number of points."""
    lat, lng = points(n)
    small = max(n // 10, 1)
    levels = [lv for lv in (5, 10, 17, 28) if lv <= int(getattr(k.d, "MAX_LEVEL", 28))]
    cases: dict[tuple[str, str], tuple[Callable[[], Any], Any]] = {}
    for lv in levels:
        for m in (n, small):
            cases[(f"level {lv}", f"{k.label[k.primary]}, {m:,} points")] = (
                lambda lv=lv, m=m: k.cells(lat[:m], lng[:m], lv, k.primary), m)
    secs = interleaved(cases, repeat, budget)
    return {"title": "dggs point to cell alone: cost per point against the level and the number of points "
                     "(no peer; flat columns mean cost linear in points, a slow rise with the level is the "
                     "per-level descent)", "unit": "point", "rows": _rows(secs, {})}


# --------------------------------------------------------------------------- cell operations


def table_cell_ops(k: Kernel, mods: dict[str, Any], n: int, repeat: int, budget: float) -> dict[str, Any]:
    d = k.d
    lat, lng = points(n)
    ids = {kind: k.cells(lat, lng, 17, kind) for kind in k.kinds}
    cases: dict[tuple[str, str], tuple[Callable[[], Any], Any]] = {}
    ref: dict[tuple[str, str], str] = {}
    prim = k.label[k.primary]
    # The string rows only for the light operations (k=5 disks of 100k string ids would take ~1 GB).
    light = ("centre", "boundary", "parent", "children", "disk k=1")
    ops = {
        "centre": (lambda c: d.cell_to_latlng(c), n),
        "boundary": (lambda c: d.cell_to_boundary(c), n),
        "parent": (lambda c: d.cell_to_parent(c, 16), n),
        "children": (lambda c: d.cell_to_children(c, 18), count_cells),
        "disk k=1": (lambda c: d.grid_disk(c, 1), count_cells),
        "disk k=5": (lambda c: d.grid_disk(c, 5), count_cells),
        "polygon densify=0": (lambda c: d.cell_to_polygon(c, densify=0), n),
        "polygon default densify": (lambda c: d.cell_to_polygon(c), n),
    }
    for kind in k.kinds:
        c = ids[kind]
        for op, (f, units) in ops.items():
            if kind == k.primary or op in light:
                cases[(op, k.label[kind])] = (lambda f=f, c=c: f(c), units, sampled(f, c))
    h3ronpy, hv = mods.get("h3ronpy"), mods.get("h3ronpy.vector")
    if h3ronpy is not None and hv is not None:
        import shapely

        arr = hv.coordinates_to_cells(lat, lng, 9)  # an arrow uint64 array, as h3ronpy users hold them
        peer = {
            "centre": ("h3ronpy `cells_to_coordinates`", lambda: hv.cells_to_coordinates(arr), n),
            "boundary": ("h3ronpy `cells_to_wkb_polygons`", lambda: hv.cells_to_wkb_polygons(arr), n),
            "parent": ("h3ronpy `change_resolution(arr, 8)`", lambda: h3ronpy.change_resolution(arr, 8), n),
            "children": ("h3ronpy `change_resolution(arr, 10)`", lambda: h3ronpy.change_resolution(arr, 10), count_cells),
            "disk k=1": ("h3ronpy `grid_disk(arr, 1)`", lambda: h3ronpy.grid_disk(arr, 1), count_cells),
            "disk k=5": ("h3ronpy `grid_disk(arr, 5)`", lambda: h3ronpy.grid_disk(arr, 5), count_cells),
            "polygon densify=0": ("h3ronpy WKB + `shapely.from_wkb`",
                                  lambda: shapely.from_wkb(hv.cells_to_wkb_polygons(arr)), n),
        }
        for op, (impl, fn, units) in peer.items():
            cases[(op, impl)] = (fn, units)
            ref[(op, impl)] = prim
        # the target for the default densify: within 3x of h3ronpy's polygons
        ref[("polygon default densify", "h3ronpy WKB + `shapely.from_wkb`")] = prim
        cases[("polygon default densify", "h3ronpy WKB + `shapely.from_wkb`")] = peer["polygon densify=0"][1:]
    secs = interleaved(cases, repeat, budget)
    return {"title": f"Cell operations on {n:,} cells (dggs level 17 ~0.099 km² vs h3 res 9 ~0.105 km²); "
                     "parent one level up, children one level down",
            "unit": "cell", "rows": _rows(secs, ref)}


# --------------------------------------------------------------------------- regions


def geodesic_circle(lat: float, lng: float, radius_km: float, n: int = 360):
    """A shapely polygon (lng, lat) approximating a geodesic circle on WGS84."""
    import pyproj
    import shapely

    az = np.linspace(0.0, 360.0, n, endpoint=False)
    lons, lats, _ = pyproj.Geod(ellps="WGS84").fwd(np.full(n, lng), np.full(n, lat), az, np.full(n, radius_km * 1e3))
    return shapely.Polygon(np.column_stack([lons, lats]))


def table_compact(k: Kernel, mods: dict[str, Any], target_cells: int, repeat: int, budget: float) -> dict[str, Any]:
    """compact / uncompact ~``target_cells`` level-15 cells: a circle's level-10 cells uncompacted to 15."""
    d = k.d
    radius = math.sqrt(target_cells * dggs_area_km2(15) / math.pi)
    circle = geodesic_circle(45.0, 10.0, radius)
    cases: dict[tuple[str, str], tuple[Callable[[], Any], Any]] = {}
    ref: dict[tuple[str, str], str] = {}
    prim = k.label[k.primary]
    sizes: dict[str, Any] = {"radius_km": radius}
    try:
        fine = d.uncompact_cells(k.polyfill(circle, 10, k.primary), 15)
        packed = d.compact_cells(fine)
        sizes["dggs"] = (len(fine), len(packed))
        cases[("compact", prim)] = (lambda: d.compact_cells(fine), len(fine))
        cases[("uncompact", prim)] = (lambda: d.uncompact_cells(packed, 15), len)
    except Exception as exc:
        note(f"dggs compact / uncompact setup failed ({type(exc).__name__}: {str(exc)[:200]}); skipped.")
    h3ronpy, hv = mods.get("h3ronpy"), mods.get("h3ronpy.vector")
    if h3ronpy is not None and hv is not None:
        fine_h = h3ronpy.uncompact(hv.geometry_to_cells(circle, 5), 8)
        packed_h = h3ronpy.compact(fine_h)
        sizes["h3"] = (len(fine_h), len(packed_h))
        cases[("compact", "h3ronpy `compact`")] = (lambda: h3ronpy.compact(fine_h), len(fine_h))
        cases[("uncompact", "h3ronpy `uncompact(arr, 8)`")] = (lambda: h3ronpy.uncompact(packed_h, 8), len)
        ref[("compact", "h3ronpy `compact`")] = prim
        ref[("uncompact", "h3ronpy `uncompact(arr, 8)`")] = prim
    secs = interleaved(cases, repeat, budget)
    desc = "; ".join(f"{who}: {a:,} fine cells, {b:,} compacted" for who, (a, b) in
                     ((w, sizes[w]) for w in ("dggs", "h3") if w in sizes))
    return {"title": f"Compact and uncompact (dggs level 15 ~0.89 km² vs h3 res 8 ~0.74 km²): the cells of a "
                     f"{radius:.0f} km circle at 45N 10E, dggs level 10 / h3 res 5, uncompacted to level 15 / res 8 "
                     f"({desc}); compact per input cell, uncompact per output cell",
            "unit": "cell", "rows": _rows(secs, ref)}


def table_polyfill(k: Kernel, mods: dict[str, Any], box_deg: float, circle_km: float, repeat: int,
                   budget: float) -> dict[str, Any]:
    import shapely

    box = shapely.box(0.0, 40.0 - box_deg / 2, box_deg, 40.0 + box_deg / 2)
    circle = geodesic_circle(45.0, 10.0, circle_km)
    regions = {f"{box_deg:g}x{box_deg:g} degree box at 40N, level 10 / res 5": (box, 10),
               f"{circle_km:g} km circle at 45N 10E, level 15 / res 8": (circle, 15)}
    cases: dict[tuple[str, str], tuple[Callable[[], Any], Any]] = {}
    ref: dict[tuple[str, str], str] = {}
    prim = k.label[k.primary]
    hv = mods.get("h3ronpy.vector")
    for op, (poly, lv) in regions.items():
        cases[(op, prim)] = (lambda poly=poly, lv=lv: k.polyfill(poly, lv, k.primary), len)
        if hv is not None:
            impl = "h3ronpy `geometry_to_cells` (centroid containment)"
            cases[(op, impl)] = (lambda poly=poly, lv=lv: hv.geometry_to_cells(poly, H3_RES[lv]), len)
            ref[(op, impl)] = prim
    countries = natural_earth_countries()
    if countries is not None:  # real shapes: 177 countries, thousands of vertices, islands and holes
        import pyarrow as pa

        op = f"the {len(countries)} Natural Earth countries, level 10 / res 5"
        cases[(op, prim)] = (lambda: [k.polyfill(g, 10, k.primary) for g in countries], lambda r: sum(map(len, r)))
        if hv is not None:
            impl = "h3ronpy `wkb_to_cells` (centroid containment)"
            wkb = pa.array(shapely.to_wkb(countries))
            cases[(op, impl)] = (lambda: hv.wkb_to_cells(wkb, H3_RES[10]), lambda r: sum(len(x) for x in r.to_pylist()))
            ref[(op, impl)] = prim
    secs = interleaved(cases, repeat, budget)
    return {"title": "Polygon to cells (per output cell)", "unit": "output cell", "rows": _rows(secs, ref)}


def natural_earth_countries() -> Any:
    """Natural Earth's 1:110m countries as shapely geometries, from the copy the pyogrio package ships (or None)."""
    try:
        import pyogrio
    except ImportError:
        return None
    from pathlib import Path

    path = Path(pyogrio.__file__).parent / "tests" / "fixtures" / "naturalearth_lowres" / "naturalearth_lowres.shp"
    if not path.is_file():
        return None
    return pyogrio.read_dataframe(path).geometry.values


# --------------------------------------------------------------------------- single calls


def table_single(k: Kernel, mods: dict[str, Any], n: int, repeat: int, budget: float) -> dict[str, Any]:
    """One call at a time in a Python loop over ``n`` different points / cells: ns per call."""
    d = k.d
    lat, lng = points(n, seed=7)
    pts = list(zip(lat.tolist(), lng.tolist(), strict=True))
    cases: dict[tuple[str, str], tuple[Callable[[], Any], Any]] = {}
    ref: dict[tuple[str, str], str] = {}
    h3 = mods.get("h3")
    if h3 is not None:
        from h3.api import basic_int as h3i

        peers = {"str": ("h3-py string API", h3), "int": ("h3-py int API", h3i)}
    else:
        peers = {}
    for kind in ("str", "int"):
        mine = k.label[kind] + " one call"
        if kind in k.kinds:
            cells = k.cells(lat, lng, 17, kind).tolist()  # Python str / int, what a loop has
            kw = {"as_int": True} if kind == "int" else {}
            loops = {  # each a function of (points, cells): one call per item
                "latlng_to_cell": lambda p, c, kw=kw: [d.latlng_to_cell(a, b, 17, **kw) for a, b in p],
                "cell_to_latlng": lambda p, c: [d.cell_to_latlng(x) for x in c],
                "cell_to_parent": lambda p, c: [d.cell_to_parent(x, 16) for x in c],
                "grid_disk(c, 1)": lambda p, c: [d.grid_disk(x, 1) for x in c],
            }
            for op, f in loops.items():
                cases[(op, mine)] = (lambda f=f, c=cells: f(pts, c), n, sampled(f, pts, cells))
        if kind in peers:
            name, api = peers[kind]
            hc = [api.latlng_to_cell(a, b, 9) for a, b in pts]
            g = {"latlng_to_cell": lambda api=api: [api.latlng_to_cell(a, b, 9) for a, b in pts],
                 "cell_to_latlng": lambda api=api, hc=hc: [api.cell_to_latlng(c) for c in hc],
                 "cell_to_parent": lambda api=api, hc=hc: [api.cell_to_parent(c, 8) for c in hc],
                 "grid_disk(c, 1)": lambda api=api, hc=hc: [api.grid_disk(c, 1) for c in hc]}
            for op, fn in g.items():
                cases[(op, name)] = (fn, n)
                ref[(op, name)] = mine
    secs = interleaved(cases, repeat, budget)
    return {"title": f"One call at a time: a Python loop of {n:,} calls on different points / cells "
                     "(dggs level 17 vs h3 res 9; each h3-py API against the dggs ids of the same kind)",
            "unit": "call", "rows": _rows(secs, ref)}


def run_all_tables(mods: dict[str, Any], sizes: dict[str, Any], repeat: int, budget: float) -> dict[str, Any]:
    k = Kernel()
    out = {"int_api": k.has_int, "tables": {}}
    steps = {
        "point_to_cell": lambda: table_point_to_cell(k, mods, sizes["points"], sizes["loop_points"], repeat, budget),
        "levels": lambda: table_levels(k, sizes["points"], repeat, budget),
        "cell_ops": lambda: table_cell_ops(k, mods, sizes["cells"], repeat, budget),
        "compact": lambda: table_compact(k, mods, sizes["compact_cells"], repeat, budget),
        "polyfill": lambda: table_polyfill(k, mods, sizes["box_deg"], sizes["circle_km"], repeat, budget),
        "single": lambda: table_single(k, mods, sizes["single_calls"], repeat, budget),
    }
    for name, step in steps.items():
        try:
            out["tables"][name] = step()
        except Exception as exc:  # never lose the other tables to one failure
            note(f"table {name} failed ({type(exc).__name__}: {str(exc)[:300]}); skipped.")
    return out
