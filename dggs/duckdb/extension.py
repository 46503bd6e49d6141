"""Loading the native dggs DuckDB extension into a Python connection: ``dggs.duckdb.load(con)``.

The extension (``libdggs/duckdb/``, ``make duckdb-extension``) answers the
``dggs_*`` names in C on DuckDB's own threads; docs/duckdb.md.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import duckdb

from dggs.errors import DggsValueError, ExtensionLoadError

__all__ = ["extension_path", "load"]


def extension_path() -> Path | None:
    """The native extension's file, or None if there is none.

    Looked for in order: ``$DGGS_DUCKDB_EXTENSION``, a file shipped beside this module, and
    ``build/duckdb/dggs.duckdb_extension`` of the source tree (``make duckdb-extension``).
    """
    here = Path(__file__).resolve().parent  # dggs/duckdb/ (the source tree's root is two folders up)
    candidates = [here / "dggs.duckdb_extension", here.parents[1] / "build" / "duckdb" / "dggs.duckdb_extension"]
    if os.environ.get("DGGS_DUCKDB_EXTENSION"):
        candidates.insert(0, Path(os.environ["DGGS_DUCKDB_EXTENSION"]))
    for path in candidates:
        if path.is_file():
            return path
    return None


def load(con: Any, path: Any = None) -> bool:
    """Load the native dggs extension into DuckDB connection ``con``; False if no extension file was found.

    The extension is unsigned: the connection must allow it, from its start
    (``duckdb.connect(config={"allow_unsigned_extensions": "true"})``). Its
    functions are stored nowhere: a database whose views use them needs
    ``load`` again after it is reopened. Do not also :func:`register` the
    Python UDFs on the same connection (the names are the same).

    Parameters
    ----------
    con : duckdb.DuckDBPyConnection
        The connection.
    path : str or os.PathLike, optional
        The extension's file; default :func:`extension_path`'s. Only a file: DuckDB would read any other text
        as the name of an installed extension (``"spatial"``) and load that.

    Raises
    ------
    DggsValueError
        ``con`` is not a DuckDB connection, or ``path`` is not a path to an existing file (the message names it).
    ExtensionLoadError
        The connection refuses unsigned extensions, or DuckDB cannot load the file (the message says why);
        a RuntimeError too.

    Examples
    --------
    >>> import duckdb
    >>> con = duckdb.connect(config={"allow_unsigned_extensions": "true"})
    >>> if load(con):
    ...     assert con.sql("SELECT dggs_latlng_to_cell_str(51.05, -114.07, 9)").fetchall() == [("F200021102",)]
    """
    if not isinstance(con, duckdb.DuckDBPyConnection):
        raise DggsValueError(f"dggs.duckdb.load: con must be a DuckDB connection (duckdb.connect()), not {con!r:.100}")
    if path is None:
        found = extension_path()
        if found is None:
            return False
    else:
        if isinstance(path, bytes):
            path = os.fsdecode(path)
        if not isinstance(path, (str, os.PathLike)):
            raise DggsValueError(f"dggs.duckdb.load: path must be a file path (str or os.PathLike), not {path!r:.100}")
        text = os.fsdecode(os.fspath(path))
        if "\x00" in text or not Path(text).is_file():
            raise DggsValueError(f"dggs.duckdb.load: no extension file at {text!r:.300}")
        found = Path(text)
    literal = str(found).replace("'", "''")
    try:
        con.execute(f"LOAD '{literal}'")
    except duckdb.Error as exc:
        hint = ""
        if "allow_unsigned_extensions" in str(exc):
            hint = ' (connect with config={"allow_unsigned_extensions": "true"})'
        raise ExtensionLoadError(f"dggs.duckdb.load: {exc}{hint}") from exc
    return True
