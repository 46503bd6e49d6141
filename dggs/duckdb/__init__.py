"""DuckDB SQL functions: the native extension (``dggs.duckdb.load(con)``) or Python UDFs (``register(con)``).

:func:`load` loads the native DuckDB extension built from the C core
(``make duckdb-extension``, docs/duckdb.md), which answers the same names in
C on DuckDB's own threads, into a Python connection, if its file is found.
The Python UDFs below remain for where it is not (no C compiler, a wheel
without it, a DuckDB older than 1.2) and for what it does not have yet
(dissolve, polygon fill, lines, circles, vertexes).

Optional extra: ``pip install 'dggs[duckdb]'``.  :func:`register` adds
vectorized scalar functions to a DuckDB connection.  DuckDB hands each
function a whole batch of rows (about 2,048) as Arrow arrays and dggs's
compiled kernel runs once per batch, not once per row::

    import duckdb, dggs.duckdb
    con = dggs.duckdb.register(duckdb.connect())
    con.sql("SELECT dggs_cell_to_parent(cell, 6) AS p, sum(pop) FROM 'points.parquet' GROUP BY 1")

Cell ids are ``BIGINT`` (every id is a positive int64, numeric order is the
string order), ``UBIGINT`` (what a numpy/pyarrow ``uint64`` column becomes)
or ``VARCHAR`` (``'C401'``).  A function that returns ids returns the kind it
was given.  Each overloaded name is a temporary SQL macro that dispatches on
the argument's type to a typed Python function named with a suffix
(``_i64``, ``_u64``, ``_str``), which can also be called directly.

NULL in any argument gives NULL.  Invalid ids, coordinates or levels raise a
DuckDB ``InvalidInputException`` whose message names the function and the
bad value, e.g. ``InvalidCellError: dggs_get_level: 'X9' is not a valid cell
id: ...``.  The full list of functions is in ``docs/duckdb.md``; the
hierarchy, grid, region and vertex functions are in ``dggs/duckdb/more.py``.
"""

from dggs.duckdb.extension import extension_path, load  # the native extension
from dggs.duckdb.udfs import FUNCTIONS, register  # the Python UDFs

__all__ = ["register", "load", "extension_path", "FUNCTIONS"]
