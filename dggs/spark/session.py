"""A SparkSession with dggs's SQL functions: registering the Arrow UDFs, the session's settings, typed errors back.

The package face is :mod:`dggs.spark`; the column functions are in :mod:`dggs.spark.columns`.
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
from dggs.errors import DggsValueError
from dggs.index._checks import is_choice
from dggs.spark.udfs import FUNCTIONS, ON_INVALID, batch_function

try:  # the optional extra
    import pyspark
    from pyspark.errors import PythonException
    from pyspark.sql import functions as F
except ImportError as exc:  # pragma: no cover - exercised only without the extra
    raise ImportError("dggs.spark needs the 'spark' extra: pip install 'dggs[spark]'") from exc

if not hasattr(F, "arrow_udf"):  # pragma: no cover - pyspark < 4.1
    raise ImportError(f"dggs.spark needs pyspark >= 4.1 for Arrow UDFs (this is {pyspark.__version__})")

__all__ = ["FUNCTIONS", "arrow_udf_of", "check_on_invalid", "local_session", "register", "session_config", "spark_errors"]

@functools.cache
def arrow_udf_of(name: str, on_invalid: str) -> Any:
    """The Arrow UDF of SQL function ``name`` (built once per process)."""
    fn = batch_function(name, on_invalid)
    fn.__annotations__ = {}  # no type hints: Spark takes it as a scalar Arrow UDF (SQL_SCALAR_ARROW_UDF)
    arrow_udf: Any = F.arrow_udf
    return arrow_udf(fn, FUNCTIONS[name][1])


def check_on_invalid(on_invalid: str) -> str:
    """``on_invalid`` if it is ``"raise"`` or ``"null"``; else :class:`dggs.DggsValueError` naming it."""
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
    on_invalid = check_on_invalid(on_invalid)
    for name in FUNCTIONS:
        spark.udf.register(name, arrow_udf_of(name, on_invalid))
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
