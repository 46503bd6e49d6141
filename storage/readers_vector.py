"""Read GeoPackage, Shapefile, FlatGeobuf and GeoParquet through pyogrio (GDAL).

pyogrio (the optional extra ``dggs[vector]``) streams a layer as Arrow record
batches (:func:`pyogrio.raw.open_arrow`), geometries as WKB; each batch of
features becomes a :class:`~dggs.storage.readers.RawBatch` the way GeoJSON
features do: points as they are, polygons as the cells whose centre they
hold (:mod:`dggs.storage.readers_geojson`).  Coordinates in another CRS than
WGS84 are transformed with pyproj first.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from pathlib import Path
from typing import Any

from dggs.errors import DggsValueError, StorageError

from .crs import make_transformer
from .readers import RawBatch
from .readers_geojson import geojson_batches

__all__ = ["VECTOR_SUFFIXES", "pyogrio_module", "layer_fields", "feature_count", "first_features", "vector_batches"]

#: File name endings read through pyogrio.
VECTOR_SUFFIXES = (".gpkg", ".shp", ".fgb", ".parquet", ".geoparquet")


def pyogrio_module() -> Any:
    """Import pyogrio, or say how to install it.

    Raises
    ------
    StorageError
        If pyogrio is not installed (the message says how to install it).
    """
    try:
        import pyogrio
    except ImportError:
        raise StorageError(
            "reading GeoPackage, Shapefile, FlatGeobuf or GeoParquet needs pyogrio: "
            "pip install 'dggs[vector]'"
        ) from None
    return pyogrio


def _errors() -> tuple[type[BaseException], ...]:
    pyogrio = pyogrio_module()
    return (pyogrio.errors.DataSourceError, pyogrio.errors.DataLayerError, pyogrio.errors.FieldError)


def _layer(layer: str | int | None) -> str:
    """A layer for a message: ``layer 'roads'``, or ``its first layer`` when none was chosen."""
    return "its first layer" if layer is None else f"layer {layer!r}"


def layer_fields(path: str | Path, layer: str | int | None) -> tuple[list[str], Any]:
    """Return the attribute field names of a layer and its CRS (or None).

    Raises
    ------
    DggsValueError
        If the file cannot be read or has no such layer.
    """
    if _is_parquet(path):
        primary, crs, names = _geoparquet(path)
        return [n for n in names if n != primary], crs
    pyogrio = pyogrio_module()
    try:
        info = pyogrio.read_info(path, layer=layer)
    except _errors() as exc:
        raise DggsValueError(f"{path}: cannot read {_layer(layer)}: {exc}") from exc
    return [str(f) for f in info["fields"]], info.get("crs")


def _is_parquet(path: str | Path) -> bool:
    return Path(path).suffix.lower() in (".parquet", ".geoparquet")


def feature_count(path: str | Path, layer: str | int | None) -> int | None:
    """The number of features of a layer, for a progress bar's total (None where the driver would have to count).

    GeoParquet's row count is in its footer; other formats ask GDAL, which knows it (GeoPackage, FlatGeobuf,
    Shapefile) or answers -1.
    """
    if _is_parquet(path):
        import pyarrow.parquet as pq

        return int(pq.ParquetFile(path).metadata.num_rows)
    try:
        count = int(pyogrio_module().read_info(path, layer=layer, force_feature_count=False)["features"])
    except Exception:  # noqa: BLE001 - only a bar's total: the ingest itself reports a broken file
        return None
    return count if count >= 0 else None


def _geoparquet(path: str | Path) -> tuple[str, Any, list[str]]:
    """GeoParquet's primary geometry column, its CRS (PROJJSON; None: WGS84) and the column names."""
    import json

    import pyarrow as pa
    import pyarrow.parquet as pq

    try:
        schema = pq.read_schema(path)
    except (pa.ArrowInvalid, OSError) as exc:
        raise DggsValueError(f"{path} is not a Parquet file: {exc}") from exc
    geo = json.loads((schema.metadata or {}).get(b"geo", b"null") or b"null")
    if not isinstance(geo, dict) or geo.get("primary_column") not in schema.names:
        raise DggsValueError(f"{path} is not GeoParquet (no 'geo' metadata naming its geometry column)")
    primary = geo["primary_column"]
    column = (geo.get("columns") or {}).get(primary) or {}
    if column.get("encoding", "WKB").upper() != "WKB":
        raise DggsValueError(f"{path}: geometry encoding {column.get('encoding')!r} is not read; WKB is")
    crs = column.get("crs")
    return primary, (json.dumps(crs) if crs is not None else None), list(schema.names)


def _parquet_batches(path: str | Path, values: Sequence[str], batch_size: int, skip: int) -> Iterator[tuple[Any, dict]]:
    """(WKB array, properties) of the features after ``skip``, ``batch_size`` at a time."""
    import pyarrow.parquet as pq

    primary, _, _ = _geoparquet(path)
    file = pq.ParquetFile(path)
    seen = 0
    for batch in file.iter_batches(batch_size=batch_size, columns=[primary, *values]):
        n = batch.num_rows
        if seen + n <= skip:
            seen += n
            continue
        if seen < skip:
            batch = batch.slice(skip - seen)
        seen += n
        yield batch.column(0), {name: batch.column(i + 1).to_pylist() for i, name in enumerate(values)}


def _ogr_batches(
    path: str | Path, layer: str | int | None, values: Sequence[str], batch_size: int, skip: int
) -> Iterator[tuple[Any, dict]]:
    """(WKB array, properties) of the features after ``skip``, read by pyogrio."""
    pyogrio_module()
    from pyogrio.raw import open_arrow

    try:
        with open_arrow(
            path, layer=layer, columns=list(values), skip_features=skip, batch_size=batch_size,
            use_pyarrow=True,
        ) as (meta, reader):
            for batch in reader:
                names = batch.schema.names
                geometry = _geometry_column(batch.schema, meta)
                wkb = batch.column(names.index(geometry)) if geometry in names else None
                yield wkb, {name: batch.column(names.index(name)).to_pylist() for name in values}
    except _errors() as exc:
        raise DggsValueError(f"{path}: cannot read {_layer(layer)}: {exc}") from exc


def _features(geoms: Any, values: Sequence[str], props: dict) -> list[dict[str, Any]]:
    """GeoJSON-like features of shapely geometries (None: no geometry) and their properties."""
    import shapely.geometry

    return [
        {
            "type": "Feature",
            "geometry": None if g is None else shapely.geometry.mapping(g),
            "properties": {name: props[name][i] for name in values},
        }
        for i, g in enumerate(geoms)
    ]


def _source(path: str | Path, layer: str | int | None, values: Sequence[str], batch_size: int, skip: int) -> Any:
    if _is_parquet(path):
        return _parquet_batches(path, values, batch_size, skip)
    return _ogr_batches(path, layer, values, batch_size, skip)


def first_features(path: str | Path, layer: str | int | None, n: int) -> list[dict[str, Any]]:
    """The first ``n`` features of a layer (geometries as read, no properties): for a check before ingest.

    Raises
    ------
    DggsValueError
        If the layer cannot be read.
    """
    import shapely

    for wkb, _ in _source(path, layer, [], n, 0):
        count = len(wkb) if wkb is not None else 0
        geoms = shapely.from_wkb(wkb.to_numpy(zero_copy_only=False)) if count else []
        return _features(geoms, [], {})
    return []


def vector_batches(
    path: str | Path,
    layer: str | int | None,
    values: Sequence[str],
    level: int,
    batch_size: int,
    skip: int = 0,
    crs: Any = None,
    projection: str = "ISEA",
) -> Iterator[RawBatch]:
    """Stream a layer's features as batches: points as they are, polygons as cells.

    ``crs`` is the layer's CRS (default: what the file says; WGS84 if it
    says nothing).  Records are features, numbered from 1 in layer order.
    Polygons are filled with the cells of ``dggs.Grid(projection)``.
    """
    import shapely

    transformer = make_transformer(crs)
    done = skip
    for wkb, props in _source(path, layer, values, batch_size, skip):
        n = len(wkb) if wkb is not None else len(next(iter(props.values()), []))
        if not n:
            continue
        geoms = shapely.from_wkb(wkb.to_numpy(zero_copy_only=False)) if wkb is not None else [None] * n
        if transformer is not None:
            geoms = shapely.transform(geoms, lambda xy: _apply(transformer, xy))
        features = _features(geoms, values, props)
        for raw in geojson_batches(features, values, level, n, projection=projection):
            raw.rows = [r + done for r in raw.rows]
            yield raw
        done += n


def _geometry_column(schema: Any, meta: dict) -> str:
    """The name of the WKB geometry column of a batch (GDAL names it by driver)."""
    for f in schema:
        if (f.metadata or {}).get(b"ARROW:extension:name") == b"geoarrow.wkb":
            return str(f.name)
    for name in (meta.get("geometry_name"), "wkb_geometry", "wkb", "geometry"):
        if name and name in schema.names:
            return str(name)
    return ""


def _apply(transformer: Any, xy: Any) -> Any:
    import numpy as np

    x, y = transformer.transform(xy[:, 0], xy[:, 1])
    return np.column_stack([x, y])
