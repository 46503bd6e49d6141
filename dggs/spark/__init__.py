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

from dggs.spark.columns import (
    cell_area,
    cell_to_boundary_wkb,
    cell_to_children,
    cell_to_latlng,
    cell_to_parent,
    cell_to_parent_str,
    cells_to_polygons_wkb,
    get_level,
    grid_disk,
    grid_path_cells,
    int_to_str,
    is_valid_cell,
    latlng_to_cell,
    latlng_to_cell_str,
    polygon_to_cells,
    str_to_int,
)
from dggs.spark.jobs import rollup, write_geoparquet
from dggs.spark.session import FUNCTIONS, local_session, register, session_config, spark_errors

__all__ = [
    "FUNCTIONS", "register", "local_session", "session_config", "spark_errors", "rollup", "write_geoparquet",
    "latlng_to_cell", "latlng_to_cell_str", "cell_to_parent", "cell_to_parent_str", "cell_to_children",
    "cell_to_latlng", "cell_to_boundary_wkb", "grid_disk", "grid_path_cells", "cells_to_polygons_wkb",
    "polygon_to_cells", "cell_area", "get_level",
    "is_valid_cell", "str_to_int", "int_to_str",
]
