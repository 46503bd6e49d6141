"""``dggs bin-raster``: a raster into a cell store or a folder of GeoParquet files (docs/raster.md).

A thin click layer over :meth:`dggs.storage.CellStore.ingest_raster` and
:func:`dggs.raster.raster_to_cells`; library errors (:class:`dggs.DggsError`)
become one line and exit code 1 in the root group.  ``dggs.raster`` (numba,
pandas) is imported when the command runs, not when ``dggs`` starts.
"""

from __future__ import annotations

import contextlib
import os

import click

__all__ = ["bin_raster", "CLI_MODES"]

#: :data:`dggs.raster.MODES`, spelt out so that the command line starts without loading the raster modules.
CLI_MODES = ("center", "mean", "sum", "min", "max", "count", "mode", "fractions")


@click.command("bin-raster")
@click.argument("raster", metavar="FILE")
@click.option("--level", type=int, required=True, help="Level of the cells.")
@click.option("--mode", type=click.Choice(CLI_MODES), default="mean", show_default=True,
              help="How pixels make a cell's value (docs/raster.md).")
@click.option("--band", "bands", type=int, multiple=True, help="Band to bin (1-based, repeatable) [default: all].")
@click.option("--nodata", type=float, default=None, help="Value of pixels without data [default: the raster's].")
@click.option("--db", type=click.Path(dir_okay=False), default=None, help="Cell store to write (created if missing).")
@click.option("--parquet", type=click.Path(file_okay=False), default=None,
              help="Folder of GeoParquet files to write, one per level-1 parent cell (parent=C4/...).")
@click.option("--density", is_flag=True, help='For --mode sum: the values are per m², not per pixel.')
@click.option("--block-size", type=click.IntRange(min=1), default=512, show_default=True,
              help="Pixels a block side (with --db, a block is a transaction).")
@click.option("--replace", is_flag=True, help="With --db: forget what an earlier ingest of FILE stored first.")
@click.option("--progress/--no-progress", default=None, help="Progress bar of the blocks [default: on a terminal].")
@click.option("--dataset", default=None, metavar="NAME",
              help="With --db: the store's named dataset to write (made if new) [default: its default dataset].")
def bin_raster(raster: str, level: int, mode: str, bands: tuple[int, ...], nodata: float | None, db: str | None,
               parquet: str | None, density: bool, block_size: int, replace: bool, progress: bool | None,
               dataset: str | None) -> None:
    """Bin the pixels of raster FILE into equal-area cells, into a store or GeoParquet files.

    FILE is any raster GDAL reads (GeoTIFF, COG, NetCDF, ...), in any CRS.
    With --db, each block of pixels is committed in one transaction and
    running the same command again resumes after the blocks stored (or does
    nothing if it finished); the cells' rows appear when the last block is in.
    With --parquet, the folder appears whole, one GeoParquet file per level-1
    cell.

    \b
    Examples:
      dggs bin-raster dem.tif --level 9 --mode mean --db dem.db
      dggs bin-raster landcover.tif --level 9 --mode fractions --parquet cover/
    """  # noqa: D301 - \b stops click re-wrapping the examples: a raw docstring would print it
    if (db is None) == (parquet is None):
        raise click.UsageError("give one output: --db STORE or --parquet FOLDER")
    if replace and db is None:
        raise click.UsageError("--replace goes with --db")
    if dataset is not None and db is None:
        raise click.UsageError("--dataset goes with --db")
    band = list(bands) or None
    if db is not None:
        from dggs.raster import open_checked
        from dggs.storage import CellStore

        # checked before the store is created (as ``dggs bin`` does): arguments that can only fail leave no
        # empty store behind; a new store whose ingest fails later (a pixel of +-inf) is removed again
        open_checked(raster, level, mode, band, nodata, None, block_size)
        new = not os.path.exists(db)
        try:  # a dataset this command made is taken back, with its partial blocks, if the ingest fails (CellStore)
            with CellStore(db, dataset=dataset) as store:
                result = store.ingest_raster(raster, level, mode=mode, band=band, nodata=nodata, density=density,
                                             block_size=block_size, replace=replace, progress=progress)
        except BaseException:
            if new:
                for tail in ("", "-wal", "-shm", "-journal"):
                    with contextlib.suppress(OSError):
                        os.remove(db + tail)
            raise
        where = db if dataset is None else f"{db} dataset {dataset}"
        click.echo(f"{result.summary()} -> {where} (level {level})")
        return
    from dggs.raster import raster_to_cells
    from dggs.raster.parquet import write_partitioned

    table = raster_to_cells(raster, level, mode=mode, band=band, nodata=nodata, density=density,
                            block_size=block_size, progress=progress)
    counts = write_partitioned(table, str(parquet))
    click.echo(f"{raster}: wrote {len(table):,} cells in {len(counts):,} GeoParquet file(s) under {parquet}")
