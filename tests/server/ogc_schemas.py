"""JSON Schemas (Draft 2020-12) of the server's responses, restating the OGC standard's schemas.

Each schema restates the required properties and their types from a file of the
standard's repository, github.com/opengeospatial/ogcapi-discrete-global-grid-systems
(cited per schema; read at its HEAD of 2026).  The standard's YAML is written for
OpenAPI 3.0 (``nullable``); here a nullable number is ``["number", "null"]``.
The two web-map schemas at the end are this project's own contract.
"""

from __future__ import annotations

from typing import Any

import jsonschema

# openapi/schemas/common-core/link.yaml: href and rel required; type, hreflang, title strings; length int.
LINK: dict[str, Any] = {
    "type": "object",
    "required": ["href", "rel"],
    "properties": {
        "href": {"type": "string"},
        "rel": {"type": "string"},
        "type": {"type": "string"},
        "hreflang": {"type": "string"},
        "title": {"type": "string"},
        "length": {"type": "integer"},
    },
}

# openapi/schemas/common-core/linkTemplate.yaml: uriTemplate and rel required.
LINK_TEMPLATE: dict[str, Any] = {
    "type": "object",
    "required": ["uriTemplate", "rel"],
    "properties": {"uriTemplate": {"type": "string"}, "rel": {"type": "string"}, "type": {"type": "string"}},
}

_LINKS = {"type": "array", "items": LINK}

# openapi/schemas/common-core/landingPage.yaml: links required; title, description, attribution strings.
LANDING_PAGE: dict[str, Any] = {
    "type": "object",
    "required": ["links"],
    "properties": {
        "title": {"type": "string"},
        "description": {"type": "string"},
        "attribution": {"type": "string"},
        "links": _LINKS,
    },
}

# openapi/schemas/common-core/confClasses.yaml: conformsTo, an array of strings, required.
CONFORMANCE: dict[str, Any] = {
    "type": "object",
    "required": ["conformsTo"],
    "properties": {"conformsTo": {"type": "array", "items": {"type": "string"}}},
}

# openapi/schemas/common-geodata/extent.yaml (spatial part): bbox, an array of 4 or 6 numbers per box.
_EXTENT: dict[str, Any] = {
    "type": "object",
    "properties": {
        "spatial": {
            "type": "object",
            "properties": {
                "bbox": {
                    "type": "array",
                    "minItems": 1,
                    "items": {
                        "type": "array",
                        "oneOf": [{"minItems": 4, "maxItems": 4}, {"minItems": 6, "maxItems": 6}],
                        "items": {"type": "number"},
                    },
                },
                "crs": {"type": "string"},
            },
        }
    },
}

# openapi/schemas/common-geodata/collectionDesc.yaml: id and links required; title, description strings;
# extent (extent.yaml); crs an array of strings; storageCrs a string.
COLLECTION: dict[str, Any] = {
    "type": "object",
    "required": ["id", "links"],
    "properties": {
        "id": {"type": "string"},
        "title": {"type": "string"},
        "description": {"type": "string"},
        "links": _LINKS,
        "extent": _EXTENT,
        "crs": {"type": "array", "items": {"type": "string"}},
        "storageCrs": {"type": "string"},
    },
}

# openapi/schemas/common-geodata/collections.yaml: links and collections required;
# numberMatched, numberReturned non-negative integers (numberMatched.yaml, numberReturned.yaml).
COLLECTIONS: dict[str, Any] = {
    "type": "object",
    "required": ["links", "collections"],
    "properties": {
        "links": _LINKS,
        "collections": {"type": "array", "items": COLLECTION},
        "numberMatched": {"type": "integer", "minimum": 0},
        "numberReturned": {"type": "integer", "minimum": 0},
    },
}

# openapi/schemas/dggs-core/dggrs-item.yaml: id, title and links required; uri a string.
DGGRS_ITEM: dict[str, Any] = {
    "type": "object",
    "required": ["id", "title", "links"],
    "properties": {"id": {"type": "string"}, "title": {"type": "string"}, "uri": {"type": "string"}, "links": _LINKS},
}

# openapi/responses/dggs-core/rDGGRSList.yaml: dggrs (array of dggrs-item) required; links.
DGGRS_LIST: dict[str, Any] = {
    "type": "object",
    "required": ["dggrs"],
    "properties": {"links": _LINKS, "dggrs": {"type": "array", "minItems": 1, "items": DGGRS_ITEM}},
}

# openapi/schemas/dggs-core/dggrs.yaml: id, title, description, defaultDepth and links required;
# defaultDepth an integer >= 0 or a string; maxRefinementLevel, maxRelativeDepth integers >= 0;
# keywords strings; linkTemplates (linkTemplate.yaml).
DGGRS_DESCRIPTION: dict[str, Any] = {
    "type": "object",
    "required": ["id", "title", "description", "defaultDepth", "links"],
    "properties": {
        "id": {"type": "string"},
        "title": {"type": "string"},
        "description": {"type": "string"},
        "keywords": {"type": "array", "items": {"type": "string"}},
        "uri": {"type": "string"},
        "defaultDepth": {"oneOf": [{"type": "integer", "minimum": 0}, {"type": "string"}]},
        "maxRefinementLevel": {"type": "integer", "minimum": 0},
        "maxRelativeDepth": {"type": "integer", "minimum": 0},
        "links": _LINKS,
        "linkTemplates": {"type": "array", "items": LINK_TEMPLATE},
    },
}

# core/schemas/dggrs-definition/dggrs-definition-proposed.yaml: dggh, zirs and subZoneOrder required;
# dggh.definition requires spatialDimensions and temporalDimensions (integers); basePolyhedron a string,
# refinementRatio an integer; parameters.orientation requires latitude and longitude (numbers);
# zirs requires textZIRS, which requires a description; subZoneOrder requires a description.
DGGRS_DEFINITION: dict[str, Any] = {
    "type": "object",
    "required": ["dggh", "zirs", "subZoneOrder"],
    "properties": {
        "title": {"type": "string"},
        "description": {"type": "string"},
        "dggh": {
            "type": "object",
            "properties": {
                "definition": {
                    "type": "object",
                    "required": ["spatialDimensions", "temporalDimensions"],
                    "properties": {
                        "spatialDimensions": {"type": "integer"},
                        "temporalDimensions": {"type": "integer"},
                        "basePolyhedron": {"type": "string"},
                        "refinementRatio": {"type": "integer"},
                        "zoneTypes": {"type": "array", "items": {"type": "string"}},
                        "constraints": {"type": "object",
                                        "properties": {"cellEqualSized": {"type": "boolean"}}},
                    },
                },
                "parameters": {
                    "type": "object",
                    "properties": {
                        "ellipsoid": {"type": "string"},
                        "orientation": {
                            "type": "object",
                            "required": ["longitude", "latitude"],
                            "properties": {"latitude": {"type": "number"}, "longitude": {"type": "number"},
                                           "azimuth": {"type": "number"}, "description": {"type": "string"}},
                        },
                    },
                },
            },
        },
        "zirs": {
            "type": "object",
            "required": ["textZIRS"],
            "properties": {
                "textZIRS": {"type": "object", "required": ["description"],
                             "properties": {"description": {"type": "string"}, "type": {"type": "string"}}},
                "uint64ZIRS": {"type": "object", "required": ["description"],
                               "properties": {"description": {"type": "string"}}},
            },
        },
        "subZoneOrder": {"type": "object", "required": ["description"],
                         "properties": {"description": {"type": "string"}, "type": {"type": "string"}}},
    },
}

# openapi/schemas/geojson/*.yaml (RFC 7946): a FeatureCollection of Features with a geometry
# (Polygon or MultiPolygon here, coordinates arrays of positions) and properties.
_POSITION = {"type": "array", "minItems": 2, "items": {"type": "number"}}
_RING = {"type": "array", "minItems": 4, "items": _POSITION}
GEOMETRY: dict[str, Any] = {
    "oneOf": [
        {"type": "object", "required": ["type", "coordinates"],
         "properties": {"type": {"const": "Polygon"}, "coordinates": {"type": "array", "items": _RING}}},
        {"type": "object", "required": ["type", "coordinates"],
         "properties": {"type": {"const": "MultiPolygon"},
                        "coordinates": {"type": "array", "items": {"type": "array", "items": _RING}}}},
    ]
}
FEATURE: dict[str, Any] = {
    "type": "object",
    "required": ["type", "geometry", "properties"],
    "properties": {
        "type": {"const": "Feature"},
        "id": {"type": ["string", "integer"]},
        "geometry": GEOMETRY,
        "properties": {"type": ["object", "null"]},
    },
}
FEATURE_COLLECTION: dict[str, Any] = {
    "type": "object",
    "required": ["type", "features"],
    "properties": {"type": {"const": "FeatureCollection"}, "features": {"type": "array", "items": FEATURE}},
}

# openapi/schemas/dggs-core/zone-info.yaml: id and links required; shapeType, crs strings; level an
# integer >= 0; centroid 2-3 numbers; bbox 4-6 numbers; areaMetersSquare a number; geometry GeoJSON;
# statistics: per field an object of minimum, maximum, average, stdDev numbers.
ZONE_INFO: dict[str, Any] = {
    "type": "object",
    "required": ["id", "links"],
    "properties": {
        "id": {"type": "string"},
        "links": _LINKS,
        "shapeType": {"type": "string"},
        "level": {"type": "integer", "minimum": 0},
        "crs": {"type": "string"},
        "centroid": {"type": "array", "minItems": 2, "maxItems": 3, "items": {"type": "number"}},
        "bbox": {"type": "array", "minItems": 4, "maxItems": 6, "items": {"type": "number"}},
        "areaMetersSquare": {"type": "number"},
        "geometry": GEOMETRY,
        "statistics": {
            "type": "object",
            "additionalProperties": {
                "type": "object",
                "properties": {k: {"type": "number"} for k in ("minimum", "maximum", "average", "stdDev")},
            },
        },
    },
}

# openapi/responses/dggs-core/rZonesList.yaml (application/json): zones, an array of strings, required;
# returnedAreaMetersSquare a number; links.  numberMatched/numberReturned as in common-geodata.
ZONE_LIST: dict[str, Any] = {
    "type": "object",
    "required": ["zones"],
    "properties": {
        "zones": {"type": "array", "items": {"type": "string"}},
        "returnedAreaMetersSquare": {"type": "number"},
        "numberMatched": {"type": "integer", "minimum": 0},
        "numberReturned": {"type": "integer", "minimum": 0},
        "links": _LINKS,
    },
}

# core/schemas/dggs-json/schema.yaml: the "schema" member: type "object" and properties required;
# each property's type one of the JSON Schema type names.
_DGGS_JSON_SCHEMA: dict[str, Any] = {
    "type": "object",
    "required": ["type", "properties"],
    "properties": {
        "type": {"enum": ["object"]},
        "properties": {
            "type": "object",
            "additionalProperties": {
                "type": "object",
                "properties": {
                    "title": {"type": "string"},
                    "type": {"enum": ["array", "boolean", "integer", "null", "number", "object", "string"]},
                },
            },
        },
    },
}

# core/schemas/dggs-json/dggs-json.yaml: dggrs (a URI string), zoneId, depths (integers >= 0) and values
# required; schema (schema.yaml); values maps each property to an array of objects with data (numbers or
# null, required), depth (integer) and shape (count and subZones integers, required).
DGGS_JSON: dict[str, Any] = {
    "type": "object",
    "required": ["dggrs", "zoneId", "depths", "values"],
    "properties": {
        "dggrs": {"type": "string", "format": "uri"},
        "zoneId": {"type": "string"},
        "depths": {"type": "array", "items": {"type": "integer", "minimum": 0}},
        "schema": _DGGS_JSON_SCHEMA,
        "values": {
            "type": "object",
            "additionalProperties": {
                "type": "array",
                "items": {
                    "type": "object",
                    "required": ["data"],
                    "properties": {
                        "depth": {"type": "integer"},
                        "shape": {
                            "type": "object",
                            "required": ["count", "subZones"],
                            "properties": {"count": {"type": "integer"}, "subZones": {"type": "integer"}},
                        },
                        "data": {"type": "array", "items": {"type": ["number", "null"]}},
                    },
                },
            },
        },
    },
}

# openapi/schemas/common-core/exception.yaml (RFC 7807): type required; title, detail, instance strings;
# status an integer.  This server always sends all four of type, title, status and detail.
EXCEPTION: dict[str, Any] = {
    "type": "object",
    "required": ["type", "title", "status", "detail"],
    "properties": {
        "type": {"type": "string"},
        "title": {"type": "string"},
        "status": {"type": "integer"},
        "detail": {"type": "string"},
        "instance": {"type": "string"},
    },
}

# This project's web-map contract (dggs/server/mapdata.py): /map/layers.
MAP_LAYERS: dict[str, Any] = {
    "type": "object",
    "required": ["collection", "stored_level", "levels", "columns", "numeric_columns", "bbox", "count", "max_zones"],
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
    },
}

# /map/cells: a FeatureCollection whose features carry exactly these properties.
MAP_CELLS: dict[str, Any] = {
    "allOf": [
        FEATURE_COLLECTION,
        {
            "properties": {
                "features": {
                    "items": {
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
                        }
                    }
                }
            }
        },
    ]
}

SCHEMAS = {
    "landing": LANDING_PAGE,
    "conformance": CONFORMANCE,
    "collections": COLLECTIONS,
    "collection": COLLECTION,
    "dggrs-list": DGGRS_LIST,
    "dggrs": DGGRS_DESCRIPTION,
    "dggrs-definition": DGGRS_DEFINITION,
    "zone-info": ZONE_INFO,
    "zone-list": ZONE_LIST,
    "dggs-json": DGGS_JSON,
    "geojson": FEATURE_COLLECTION,
    "feature": FEATURE,
    "exception": EXCEPTION,
    "map-layers": MAP_LAYERS,
    "map-cells": MAP_CELLS,
}


def validate(document: Any, name: str) -> None:
    """Validate ``document`` against the schema ``name`` (raises jsonschema.ValidationError)."""
    schema = SCHEMAS[name]
    jsonschema.Draft202012Validator.check_schema(schema)
    jsonschema.Draft202012Validator(schema, format_checker=jsonschema.FormatChecker()).validate(document)
