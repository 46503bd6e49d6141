"""The web map's JSON (/map/layers, /map/cells): this project's own contract, not an OGC resource.

The standard has no schema for these routes (they are not part of OGC API - DGGS), so their members are
stated here, from docs/serve.md's "The web map's JSON".  The GeoJSON around /map/cells' properties is checked
against the standard's own FeatureCollection schema (tests/server/standard.py) when its files are there.
"""

from __future__ import annotations

from typing import Any

import jsonschema

from .standard import conforms

# docs/serve.md: GET /map/layers.
MAP_LAYERS: dict[str, Any] = {
    "type": "object",
    "required": ["collection", "stored_level", "levels", "columns", "numeric_columns", "bbox", "count", "max_zones",
                 "dggrs", "collections"],
    "additionalProperties": False,
    "properties": {
        "collection": {"type": "string"},
        "stored_level": {"type": ["integer", "null"], "minimum": 0},
        "levels": {"type": "array", "items": {"type": "integer", "minimum": 0}},
        "columns": {"type": "object", "additionalProperties": {"enum": ["INTEGER", "REAL", "TEXT"]}},
        "numeric_columns": {"type": "array", "items": {"type": "string"}},
        "bbox": {"type": "array", "minItems": 4, "maxItems": 4, "items": {"type": "number"}},
        "count": {"type": "integer", "minimum": 0},
        "max_zones": {"type": "integer", "minimum": 1},
        "dggrs": {"enum": ["DGGS-Split26-ISEA", "DGGS-Split26-IVEA"]},
        "collections": {"type": "array", "minItems": 1, "items": {"type": "string"}},  # the store's datasets
    },
}

# docs/serve.md: GET /map/cells, a FeatureCollection whose features carry exactly these properties.
MAP_CELLS: dict[str, Any] = {
    "type": "object",
    "required": ["type", "features"],
    "properties": {
        "type": {"const": "FeatureCollection"},
        "features": {
            "type": "array",
            "items": {
                "type": "object",
                "required": ["type", "geometry", "properties"],
                "properties": {
                    "properties": {
                        "type": "object",
                        "required": ["zone_id", "level", "area_km2", "count", "value"],
                        "additionalProperties": False,
                        "properties": {
                            "zone_id": {"type": "string"},
                            "level": {"type": "integer", "minimum": 0},
                            "area_km2": {"type": "number", "exclusiveMinimum": 0},
                            "count": {"type": "integer", "minimum": 1},
                            "value": {"type": ["number", "null"]},
                        },
                    }
                },
            },
        },
    },
}

SCHEMAS = {"map-layers": MAP_LAYERS, "map-cells": MAP_CELLS}


def validate_map(document: Any, name: str) -> None:
    """Validate ``document`` against the map contract ``name`` (and /map/cells against the standard's GeoJSON)."""
    schema = SCHEMAS[name]
    jsonschema.Draft202012Validator.check_schema(schema)
    jsonschema.Draft202012Validator(schema).validate(document)
    if name == "map-cells":
        conforms(document, "geojson")
