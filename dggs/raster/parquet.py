"""A table of cells as a folder of GeoParquet files, one per coarse parent cell (``dggs bin-raster --parquet``).

Hive-style partitions, ``OUT/parent=C4/part-0.parquet``: the cells under each
level-1 cell (a sixth of a face) in one GeoParquet 1.1 file of
:func:`dggs.arrow.cells_to_table` (WKB geometry, ``bbox`` covering), so a
reader that filters on ``parent`` opens only the files it needs.  The folder
appears whole or not at all: it is written under a temporary name beside
``OUT`` and renamed; a folder of partitions already there is replaced.
"""

from __future__ import annotations

import contextlib
import os
import shutil
import tempfile
from pathlib import Path
from typing import Any

import numpy as np

from dggs.errors import StorageError

__all__ = ["write_partitioned", "PARTITION_LEVEL"]

#: The level of the cells the files are partitioned by.
PARTITION_LEVEL = 1


def write_partitioned(frame: Any, out: str | os.PathLike[str], densify: int | None = 16) -> dict[str, int]:
    """Write a ``raster_to_cells`` table (with ``cell_id``) as GeoParquet partitions; return cells per partition.

    Raises
    ------
    StorageError
        ``out`` is a file, or a folder holding anything but ``parent=*`` partitions, or cannot be written.

    Examples
    --------
    >>> import numpy as np, pandas as pd, tempfile, os, dggs
    >>> ids = dggs.latlng_to_cell(np.array([10.0, -40.0]), np.array([20.0, 100.0]), 5, as_int=True)
    >>> folder = os.path.join(tempfile.mkdtemp(), "cells")
    >>> write_partitioned(pd.DataFrame({"cell_id": ids, "value": [1.0, 2.0]}), folder)
    {'C2': 1, 'R3': 1}
    >>> sorted(os.listdir(folder))
    ['parent=C2', 'parent=R3']
    """
    import pyarrow.parquet as pq

    from dggs.arrow import cells_to_table
    from dggs.index.hierarchy import cell_to_parent, get_level
    from dggs.index.ids import int_to_str

    target = Path(out)
    _check_target(target)
    ids = frame["cell_id"].to_numpy().astype(np.uint64)
    level = int(get_level(ids[0])) if ids.size else PARTITION_LEVEL
    keys = np.asarray(cell_to_parent(ids, min(PARTITION_LEVEL, level))) if ids.size else np.empty(0, np.uint64)
    props = frame.drop(columns=[c for c in ("cell_id", "cell") if c in frame.columns])
    counts: dict[str, int] = {}
    tmp = _temporary(target)
    try:
        for key in np.unique(keys):
            rows = np.flatnonzero(keys == key)
            name = str(int_to_str(key))
            folder = Path(tmp) / f"parent={name}"
            folder.mkdir()
            table = cells_to_table(ids[rows], props.iloc[rows].reset_index(drop=True), densify=densify)
            pq.write_table(table, folder / "part-0.parquet", compression="zstd")
            counts[name] = int(rows.size)
        _swap(tmp, target)
    except OSError as exc:
        raise StorageError(f"cannot write {out}: {exc.strerror or exc}; nothing was written") from exc
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return counts


def _ours(folder: Path) -> bool:
    """Whether a folder holds only partitions (``parent=*`` folders)."""
    return all(entry.is_dir() and entry.name.startswith("parent=") for entry in folder.iterdir())


def _check_target(target: Path) -> None:
    if target.exists() and not target.is_dir():
        raise StorageError(f"cannot write {target}: it is a file; give a folder for the partitions")
    if target.is_dir() and not _ours(target):
        raise StorageError(f"cannot write {target}: it holds files other than parent=* partitions; "
                           "give a new or empty folder")


def _temporary(target: Path) -> str:
    """A fresh hidden folder beside ``target``, named as :mod:`dggs.storage.atomic` names its temporary files."""
    from dggs.storage.atomic import remove_stale

    parent = target.parent if str(target.parent) else Path(".")
    parent.mkdir(parents=True, exist_ok=True)
    remove_stale(target)  # a killed writer's folder
    return tempfile.mkdtemp(prefix=f".{target.name}.{os.getpid()}-", suffix=".tmp", dir=parent)


def _swap(tmp: str, target: Path) -> None:
    """Rename ``tmp`` to ``target``; an old folder of partitions goes aside first, then away."""
    old = None
    if target.exists():
        _check_target(target)  # still ours: it may have changed while the files were written
        old = tempfile.mkdtemp(prefix=f".{target.name}.{os.getpid()}-", suffix=".tmp", dir=target.parent)
        os.rmdir(old)
        os.rename(target, old)
    os.rename(tmp, target)
    if old is not None:
        with contextlib.suppress(OSError):
            shutil.rmtree(old)
