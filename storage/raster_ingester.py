"""The :class:`RasterIngester`: a raster binned into one store, a block a transaction.

:class:`~dggs.storage.CellStore` owns one and delegates ``ingest_raster`` to
it; the work is :func:`dggs.storage.raster_ingest.ingest_raster`'s.  The
docstring is the public method's (``CellStore`` shows it), example included.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from .connection import Connection, guarded

if TYPE_CHECKING:  # pragma: no cover
    from .raster_ingest import RasterIngestResult

__all__ = ["RasterIngester"]


class RasterIngester:
    """``ingest_raster`` into one open store (:class:`~dggs.storage.connection.Connection`; extra ``raster``)."""

    def __init__(self, store: Connection) -> None:
        self._store = store
        self.path, self.timeout = store.path, store.timeout  # named by the errors of guarded

    @guarded
    def ingest_raster(
        self,
        source: Any,
        level: int | None = None,
        *,
        mode: str = "mean",
        band: int | list[int] | None = None,
        nodata: Any = None,
        window: Any = None,
        density: bool = False,
        block_size: int = 512,
        replace: bool = False,
        progress: bool | Callable[[int], Any] | None = None,
    ) -> RasterIngestResult:
        """Bin a raster into the store's cells as :func:`dggs.raster.raster_to_cells` does, resumably.

        The raster is read and cut a block at a time; each block's per-cell
        partials are committed with the source's progress in one transaction,
        so a run killed at any moment resumes after its last whole block.
        When every block is in, one row per cell (at the cell's centre, ``row``
        numbering the cells in id order) goes into the store with the value
        columns ``raster_to_cells`` gives (``value``, ``band_<n>`` or
        ``class_<v>``, and ``coverage``; a class label that is not an
        identifier is spelt ``class_m1_5`` for -1.5), exactly its numbers,
        in one transaction that also keeps the kept roll-ups current.  The
        raster is identified by its content: ingesting it again resumes, or
        does nothing if it was ingested completely (``sources`` counts its
        blocks in ``rows_done``).

        Parameters
        ----------
        source : str, path or xarray.DataArray
            A raster GDAL reads, or a DataArray with a CRS (as ``raster_to_cells``).
        level : int, optional
            The store's level (default: the store's, or 12 for a new store).
        mode, band, nodata, window, density, block_size
            As :func:`dggs.raster.raster_to_cells` (a block is also the unit of a transaction).
        replace : bool
            Forget what an earlier ingest of this raster (or of an older version of the file) stored first.
        progress : bool or callable, optional
            A bar of the blocks on stderr: ``None`` (default) on a terminal once the work has run 2 s,
            ``True`` always, ``False`` never; a callable is given the blocks committed.

        Returns
        -------
        RasterIngestResult
            ``rows_read`` blocks read by this run, ``rows_inserted`` cells stored, ``blocks`` in all.

        Raises
        ------
        RasterError, LevelError, DggsValueError
            As :func:`dggs.raster.raster_to_cells`, before anything is stored.
        LevelMismatchError
            The store holds another level.
        DggsValueError
            A store binned on IVEA (rasters are binned on ISEA only).
        StorageError
            A read-only store, a file changed since (without ``replace``), the same raster ingested
            before with other settings, or another process ingesting it at the same time.

        Examples
        --------
        >>> import numpy as np, xarray as xr, rioxarray
        >>> from dggs.storage import CellStore
        >>> grid = xr.DataArray(np.arange(4.0).reshape(2, 2), dims=("y", "x"),
        ...                     coords={"y": [1.5, 0.5], "x": [0.5, 1.5]}).rio.write_crs("EPSG:4326")
        >>> with CellStore() as store:
        ...     result = store.ingest_raster(grid, 6)
        ...     result.rows_inserted == store.count(), store.columns
        (True, {'value': 'REAL', 'coverage': 'REAL'})
        """
        from .raster_ingest import ingest_raster

        if self._store.projection != "ISEA":
            from dggs.errors import DggsValueError

            raise DggsValueError(f"rasters are binned on ISEA only; {self._store.path} is binned on "
                                 f"{self._store.projection} (ingest into a store created with projection='ISEA')")
        return ingest_raster(
            self._store, source, level, mode=mode, band=band, nodata=nodata, window=window, density=density,
            block_size=block_size, replace=replace, progress=progress,
        )
