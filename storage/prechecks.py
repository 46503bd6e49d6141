"""Check an input before a store is touched: CSV, GeoJSON and vector files.

The ingest functions of :mod:`.inputs` run :func:`check_csv`,
:func:`check_geojson` and :func:`check_vector` before a source is
registered.  ``dggs bin`` runs them (:func:`check_bin_input`) before it
creates the store, so input that can only fail (a missing column, broken
JSON, an unknown layer or CRS, a bad level, a first batch holding a feature
that is no point or polygon) leaves no empty store file behind.
"""

from __future__ import annotations

import codecs
import os
from collections.abc import Iterable, Mapping, Sequence
from pathlib import Path
from typing import Any

import dggs
from dggs.errors import DggsValueError, LevelError, StorageError

from . import readers, readers_csv, readers_geojson, readers_vector
from .crs import make_transformer
from .errors import BadRowError
from .schema import BASE_COLUMNS, check_column_name

__all__ = ["source_file", "default_values", "check_csv", "check_geojson", "check_vector", "check_bin_input"]

Values = Sequence[str] | Mapping[str, Any] | None


def source_file(path: str | os.PathLike[str]) -> Path:
    """``path`` as a :class:`~pathlib.Path`, if it is a file.

    Raises
    ------
    StorageError
        If ``path`` does not exist (or is no file).
    """
    file = Path(path)
    if not file.is_file():
        raise StorageError(f"no such file: {path}")
    return file


def default_values(path: Any, keys: Iterable[Any]) -> list[str]:
    """Every property name except the built-in columns; refuse names differing only in case.

    Raises
    ------
    DggsValueError
        If two names differ only in case (SQLite column names ignore case).
    """
    seen: dict[str, str] = {}
    for key in keys:
        if isinstance(key, str) and key.lower() not in BASE_COLUMNS:
            if key.lower() in seen and seen[key.lower()] != key:
                raise DggsValueError(
                    f"{path}: properties {seen[key.lower()]!r} and {key!r} differ only in case "
                    "(SQLite column names ignore case); pass values= to choose"
                )
            seen.setdefault(key.lower(), key)
    return list(seen.values())


def value_spec(values: Values) -> tuple[list[str], dict[str, Any]]:
    """Split ``values`` into names (validated, distinct ignoring case) and declared types.

    Raises
    ------
    DggsValueError
        If a name or type is not valid, or two names are the same column to SQLite
        (names ignore case).
    """
    if values is None:
        return [], {}
    if isinstance(values, str):
        values = [values]
    names = [check_column_name(n) for n in values]
    seen: dict[str, str] = {}
    for n in names:
        if n.lower() in seen:
            raise DggsValueError(
                f"value columns {seen[n.lower()]!r} and {n!r} are the same column to SQLite "
                "(names ignore case); keep one"
            )
        seen[n.lower()] = n
    declared = {k: v for k, v in values.items() if v is not None} if isinstance(values, Mapping) else {}
    return names, declared  # a None type in a dict: guess it, as for a list


def check_csv(
    path: str | os.PathLike[str], lat: str, lng: str, values: Values, delimiter: str = ",", encoding: str = "utf-8"
) -> tuple[Path, list[str], dict[str, Any]]:
    """Check a CSV input without a store: encoding, delimiter, header; return the file and value spec.

    Raises
    ------
    DggsValueError
        If ``encoding`` is unknown or ``delimiter`` is not one plain character, or a column is missing.
    StorageError
        If ``path`` does not exist.
    """
    file = source_file(path)
    try:
        codecs.lookup(encoding)
    except (LookupError, TypeError):
        raise DggsValueError(f"unknown text encoding {encoding!r} (e.g. utf-8, latin-1, cp1252)") from None
    if not isinstance(delimiter, str) or len(delimiter) != 1 or delimiter in '"\r\n':
        raise DggsValueError(f"delimiter must be one character (not a quote or newline), not {delimiter!r}")
    names, declared = value_spec(values)
    header = readers_csv.csv_header(file, delimiter, encoding)
    readers.check_columns(file, header, [lat, lng, *names])
    return file, names, declared


def check_geojson(
    path: str | os.PathLike[str], values: Values, crs: Any, batch_size: int
) -> tuple[Path, list[Any], list[str], dict[str, Any]]:
    """Load and check a GeoJSON input without a store; return the file, its features and the value spec.

    Without ``values``, the value columns are the properties seen in the first ``batch_size`` features.

    Raises
    ------
    DggsValueError
        If ``crs`` is set (GeoJSON is WGS84 by definition), the file is not GeoJSON, or two
        property names differ only in case.
    StorageError
        If ``path`` does not exist.
    """
    file = source_file(path)
    if crs is not None:
        raise DggsValueError("GeoJSON is WGS84 lng/lat by definition (RFC 7946): crs cannot be set")
    features = readers_geojson.load_geojson(file)
    if values is None:  # the properties seen in the first batch
        props = (f.get("properties") if isinstance(f, dict) else None for f in features[:batch_size])
        values = default_values(path, (key for p in props if isinstance(p, dict) for key in p))
    names, declared = value_spec(values)
    return file, features, names, declared


def check_vector(
    path: str | os.PathLike[str], layer: str | int | None, values: Values, crs: Any
) -> tuple[Path, list[str], dict[str, Any], Any]:
    """Check a vector layer without a store: readable, its fields, the CRS; return file, value spec and CRS.

    Raises
    ------
    DggsValueError
        If the layer cannot be read, a value column is not one of its fields, or the CRS is unknown.
    StorageError
        If ``path`` does not exist, or pyogrio is not installed.
    """
    file = source_file(path)
    fields, file_crs = readers_vector.layer_fields(file, layer)
    if values is None:
        values = default_values(path, fields)
    names, declared = value_spec(values)
    readers.check_columns(file, fields, names)
    crs = crs if crs is not None else file_crs
    make_transformer(crs)  # an unknown CRS fails here
    return file, names, declared, crs


def _first_bad_feature(path: Any, features: Sequence[Any]) -> None:
    """Raise the :class:`BadRowError` ``on_error="fail"`` gives for the first feature no geometry of its can store."""
    for i, feature in enumerate(features):
        problem = readers_geojson.feature_problem(feature)
        if problem is not None:
            raise BadRowError(str(path), i + 1, None, None, problem[0], problem[1], hint="nothing was stored")


def check_bin_input(
    kind: str,
    path: str,
    *,
    new_store: bool,
    lat: str,
    lng: str,
    values: Values,
    crs: Any,
    encoding: str,
    layer: str | None,
    level: int | None,
    batch_size: int,
    on_error: str,
) -> None:
    """Check the input of ``dggs bin`` before the store is opened (``kind`` as :func:`readers.sniff_kind`).

    A new store is created only for input that may be stored: with
    ``on_error="fail"`` a first batch holding a feature with no Point,
    MultiPoint, Polygon or MultiPolygon geometry (or properties that are no
    object) is refused here, as the ingest would refuse it before storing
    a row.  A GeoJSON file is loaded for this only when the store is new.

    Raises
    ------
    DggsError
        What the ingest would raise: :class:`LevelError`, :class:`BadRowError`,
        :class:`DggsValueError` or :class:`StorageError`.
    """
    if level is not None and not 0 <= level <= dggs.MAX_LEVEL:
        raise LevelError(f"level {level!r} is out of range 0..{dggs.MAX_LEVEL}")
    fail_first = new_store and on_error == "fail"
    if kind == "csv":
        check_csv(path, lat, lng, values, encoding=encoding)
    elif kind == "vector":
        check_vector(path, layer, values or None, crs)
        if fail_first:
            _first_bad_feature(path, readers_vector.first_features(path, layer, batch_size))
    elif new_store:
        _, features, _, _ = check_geojson(path, values or None, None, batch_size)
        if fail_first:
            _first_bad_feature(path, features[:batch_size])
