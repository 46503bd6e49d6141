"""Apache Spark SQL and DataFrame functions over Arrow batches: ``dggs.spark.register(spark)``.

Optional extra: ``pip install 'dggs[spark]'`` (pyspark >= 4.1, Java 17).
Every function is a Spark *Arrow UDF* (``pyspark.sql.functions.arrow_udf``):
Spark hands the Python worker whole Arrow record batches (10,000 rows by
default, ``spark.sql.execution.arrow.maxRecordsPerBatch``), no pandas step,
and dggs's compiled kernel runs once per batch::

    from pyspark.sql import SparkSession
    import dggs.spark

    spark = SparkSession.builder.master("local[2]").config(map=dggs.spark.session_config()).getOrCreate()
    dggs.spark.register(spark)
    spark.sql("SELECT dggs_cell_to_parent(dggs_latlng_to_cell(lat, lng, 12), 6) AS p, count(*) "
              "FROM points GROUP BY p")

    from dggs.spark import latlng_to_cell
    df.withColumn("cell", latlng_to_cell("lat", "lng", 12))

Cell ids are ``bigint`` (every id is a positive int64 whose order is the
string order) or ``string`` (``'C401'``); every function taking ids takes
either, and the ``_str`` functions give string ids.  The functions and their
types are listed in :data:`FUNCTIONS` (and ``docs/scale.md``).

NULL in any argument gives NULL.  A bad value raises, in the Python worker,
the :class:`dggs.DggsValueError` subclass naming the function, the row of the
batch, its values and the partition; Spark reports it on the driver as a
``PythonException`` holding that text, which :func:`spark_errors` turns back
into the typed error.  With ``on_invalid="null"`` bad rows give NULL.

Workers compile nothing: the grid is the compiled C core (``dggs._core``) of the installed package, so a
worker's first call costs what every other does, and Spark's reused Python workers
(``spark.python.worker.reuse``, on by default) import dggs once each.
"""

from __future__ import annotations

import contextlib
import functools
import os
import re
import sys
from collections.abc import Iterator
from typing import Any

from dggs import errors
from dggs._spark_udfs import FUNCTIONS, ON_INVALID, batch_function
from dggs.errors import DggsValueError
from dggs.index._checks import is_choice

try:  # the optional extra
    import pyspark
    from pyspark.errors import PythonException
    from pyspark.sql import Column
    from pyspark.sql import functions as F
except ImportError as exc:  # pragma: no cover - exercised only without the extra
    raise ImportError("dggs.spark needs the 'spark' extra: pip install 'dggs[spark]'") from exc

if not hasattr(F, "arrow_udf"):  # pragma: no cover - pyspark < 4.1
    raise ImportError(f"dggs.spark needs pyspark >= 4.1 for Arrow UDFs (this is {pyspark.__version__})")

__all__ = [
    "FUNCTIONS", "register", "local_session", "session_config", "spark_errors", "rollup", "write_geoparquet",
    "latlng_to_cell", "latlng_to_cell_str", "cell_to_parent", "cell_to_parent_str", "cell_to_children",
    "cell_to_latlng", "cell_to_boundary_wkb", "grid_disk", "grid_path_cells", "cells_to_polygons_wkb",
    "polygon_to_cells", "cell_area", "get_level",
    "is_valid_cell", "str_to_int", "int_to_str",
]

@functools.cache
def _udf(name: str, on_invalid: str) -> Any:
    """The Arrow UDF of SQL function ``name`` (built once per process)."""
    fn = batch_function(name, on_invalid)
    fn.__annotations__ = {}  # no type hints: Spark takes it as a scalar Arrow UDF (SQL_SCALAR_ARROW_UDF)
    arrow_udf: Any = F.arrow_udf
    return arrow_udf(fn, FUNCTIONS[name][1])


def _check_on_invalid(on_invalid: str) -> str:
    if not is_choice(on_invalid, ON_INVALID):
        raise DggsValueError(f"on_invalid={on_invalid!r} is not one of {ON_INVALID}")
    return on_invalid


def register(spark: Any, on_invalid: str = "raise") -> Any:
    """Add the ``dggs_*`` SQL functions of :data:`FUNCTIONS` to a SparkSession and return it.

    Parameters
    ----------
    spark : pyspark.sql.SparkSession
    on_invalid : {"raise", "null"}, default "raise"
        A bad value raises (naming the function, the row and its values) or gives NULL.

    Returns
    -------
    pyspark.sql.SparkSession
        ``spark``, with the functions registered (calling again replaces them).

    Raises
    ------
    DggsValueError
        If ``on_invalid`` is not ``"raise"`` or ``"null"``.

    Examples
    --------
    >>> from pyspark.sql import SparkSession  # doctest: +SKIP
    >>> spark = register(SparkSession.builder.master("local[1]").getOrCreate())  # doctest: +SKIP
    >>> spark.sql("SELECT dggs_latlng_to_cell_str(51.05, -114.07, 9) AS c").first().c  # doctest: +SKIP
    'F200021102'
    """
    on_invalid = _check_on_invalid(on_invalid)
    for name in FUNCTIONS:
        spark.udf.register(name, _udf(name, on_invalid))
    return spark


def session_config(python: str | None = None) -> dict[str, str]:
    """Spark settings for dggs's workers: the worker Python, reused between tasks.

    Parameters
    ----------
    python : str, optional
        The Python of the workers; default this interpreter (``sys.executable``).

    Returns
    -------
    dict of str
        ``spark.pyspark.python`` and ``spark.python.worker.reuse``; pass as
        ``SparkSession.builder.config(map=...)``.

    Raises
    ------
    Nothing.

    Examples
    --------
    >>> session_config("/usr/bin/python3")
    {'spark.pyspark.python': '/usr/bin/python3', 'spark.python.worker.reuse': 'true'}
    """
    return {"spark.pyspark.python": python or sys.executable, "spark.python.worker.reuse": "true"}


def local_session(master: str = "local[2]", **conf: str) -> Any:
    """A SparkSession on this machine with :func:`session_config` and the dggs functions registered.

    Spark starts its Python workers with ``$PYSPARK_PYTHON`` (default ``python3``), not the driver's
    interpreter: unless set, it is set to this interpreter (``sys.executable``) first.

    Parameters
    ----------
    master : str, default "local[2]"
    **conf : str
        More Spark settings (dots written as such: ``**{"spark.sql.shuffle.partitions": "8"}``).

    Returns
    -------
    pyspark.sql.SparkSession

    Raises
    ------
    Nothing of dggs's (Spark raises if Java cannot start).

    Examples
    --------
    >>> spark = local_session(**{"spark.ui.enabled": "false"})  # doctest: +SKIP
    >>> spark.sql("SELECT dggs_get_level('C401') AS lv").first().lv  # doctest: +SKIP
    3
    """
    from pyspark.sql import SparkSession

    os.environ.setdefault("PYSPARK_PYTHON", sys.executable)
    settings: dict[str, Any] = {**session_config(), **conf}
    return register(SparkSession.builder.master(master).config(map=settings).getOrCreate())


_ERROR = re.compile(r"\b(?:dggs\.errors\.)?([A-Za-z]+Error): (dggs_\w+: .*)")


@contextlib.contextmanager
def spark_errors() -> Iterator[None]:
    """Re-raise a worker's dggs error, reported by Spark as a ``PythonException``, as its typed error.

    Raises
    ------
    DggsError
        The subclass raised in the worker, with its message (function, row, values, reason).

    Examples
    --------
    >>> with spark_errors():  # doctest: +SKIP
    ...     spark.sql("SELECT dggs_get_level('Q9')").collect()
    Traceback (most recent call last):
    InvalidCellError: dggs_get_level: row 0 of the batch (cell='Q9'): ...
    """
    try:
        yield
    except PythonException as exc:
        found = _ERROR.findall(str(exc))
        cls = getattr(errors, found[-1][0], None) if found else None
        if isinstance(cls, type) and issubclass(cls, errors.DggsError):
            raise cls(found[-1][1]) from exc
        raise


# ---------------------------------------------------------------------------------------------- column functions


def _col(value: Any) -> Any:
    """A column name or Column as a Column; anything else as a literal."""
    if isinstance(value, Column):
        return value
    if isinstance(value, str):
        return F.col(value)
    return F.lit(value)


def _lit(value: Any) -> Any:
    return value if isinstance(value, Column) else F.lit(value)


def _call(name: str, on_invalid: str, *args: Any) -> Any:
    return _udf(name, _check_on_invalid(on_invalid))(*args)


def latlng_to_cell(lat: Any, lng: Any, level: Any, *, on_invalid: str = "raise") -> Any:
    """Column of the int64 id of the cell at ``level`` holding each (lat, lng) (``dggs_latlng_to_cell``).

    ``lat``/``lng`` are column names or Columns, ``level`` an int or a Column.

    Raises
    ------
    DggsValueError
        If ``on_invalid`` is unknown (bad rows raise, when the job runs, :class:`dggs.CoordinateError`
        or :class:`dggs.LevelError` naming the row; see :func:`spark_errors`).

    Examples
    --------
    >>> df.withColumn("cell", latlng_to_cell("lat", "lng", 12))  # doctest: +SKIP
    """
    return _call("dggs_latlng_to_cell", on_invalid, _col(lat), _col(lng), _col(level))


def latlng_to_cell_str(lat: Any, lng: Any, level: Any, *, on_invalid: str = "raise") -> Any:
    """As :func:`latlng_to_cell`, giving string ids (``dggs_latlng_to_cell_str``)."""
    return _call("dggs_latlng_to_cell_str", on_invalid, _col(lat), _col(lng), _col(level))


def cell_to_parent(cell: Any, level: Any, *, on_invalid: str = "raise") -> Any:
    """Column of each cell's ancestor at ``level`` as an int64 id (``dggs_cell_to_parent``)."""
    return _call("dggs_cell_to_parent", on_invalid, _col(cell), _col(level))


def cell_to_parent_str(cell: Any, level: Any, *, on_invalid: str = "raise") -> Any:
    """As :func:`cell_to_parent`, giving string ids (``dggs_cell_to_parent_str``)."""
    return _call("dggs_cell_to_parent_str", on_invalid, _col(cell), _col(level))


def cell_to_children(cell: Any, level: Any, *, on_invalid: str = "raise") -> Any:
    """Column of arrays of each cell's descendants at ``level`` (``dggs_cell_to_children``)."""
    return _call("dggs_cell_to_children", on_invalid, _col(cell), _col(level))


def cell_to_latlng(cell: Any, *, on_invalid: str = "raise") -> Any:
    """Column of structs ``(lat, lng)``, each cell's centre (``dggs_cell_to_latlng``)."""
    return _call("dggs_cell_to_latlng", on_invalid, _col(cell))


def cell_to_boundary_wkb(cell: Any, *, on_invalid: str = "raise") -> Any:
    """Column of WKB (Multi)Polygons in lng/lat, each cell's boundary (``dggs_cell_to_boundary_wkb``)."""
    return _call("dggs_cell_to_boundary_wkb", on_invalid, _col(cell))


def grid_disk(cell: Any, k: Any, *, on_invalid: str = "raise") -> Any:
    """Column of arrays of the cells within ``k`` edge steps, sorted (``dggs_grid_disk``)."""
    return _call("dggs_grid_disk", on_invalid, _col(cell), _col(k))


def grid_path_cells(a: Any, b: Any, *, on_invalid: str = "raise") -> Any:
    """Column of arrays: a shortest path of edge neighbours from ``a`` to ``b``, both included (``dggs_grid_path_cells``)."""
    return _call("dggs_grid_path_cells", on_invalid, _col(a), _col(b))


def cells_to_polygons_wkb(cells: Any, *, on_invalid: str = "raise") -> Any:
    """Column of WKB outlines of each row's array of cells (``dggs_cells_to_polygons_wkb``; e.g. of ``collect_list``)."""
    return _call("dggs_cells_to_polygons_wkb", on_invalid, _col(cells))


def polygon_to_cells(wkb: Any, level: Any, mode: Any = "center", *, on_invalid: str = "raise") -> Any:
    """Column of arrays of the cells filling each WKB polygon (``dggs_polygon_to_cells``).

    ``wkb`` is a column name or Column (or WKB bytes), ``mode`` one of
    ``"center"``, ``"contains"``, ``"overlaps"`` (a literal) or a Column.
    """
    return _call("dggs_polygon_to_cells", on_invalid, _col(wkb), _col(level), _lit(mode))


def cell_area(cell: Any, *, on_invalid: str = "raise") -> Any:
    """Column of each cell's area in m² on WGS84 (``dggs_cell_area``)."""
    return _call("dggs_cell_area", on_invalid, _col(cell))


def get_level(cell: Any, *, on_invalid: str = "raise") -> Any:
    """Column of each cell's level (``dggs_get_level``)."""
    return _call("dggs_get_level", on_invalid, _col(cell))


def is_valid_cell(cell: Any) -> Any:
    """Column of booleans: is each id a well-formed cell (never raises; ``dggs_is_valid_cell``)."""
    return _call("dggs_is_valid_cell", "raise", _col(cell))


def str_to_int(cell: Any, *, on_invalid: str = "raise") -> Any:
    """Column of int64 ids (``dggs_str_to_int``)."""
    return _call("dggs_str_to_int", on_invalid, _col(cell))


def int_to_str(cell: Any, *, on_invalid: str = "raise") -> Any:
    """Column of string ids (``dggs_int_to_str``)."""
    return _call("dggs_int_to_str", on_invalid, _col(cell))


from dggs._spark_jobs import rollup, write_geoparquet  # noqa: E402  (they use the column functions above)
