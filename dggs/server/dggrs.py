"""The DGGRS this server offers, ``DGGS-Split26-ISEA`` and ``DGGS-Split26-IVEA``: descriptions and definitions.

Both are the Split (2:6) hierarchy with the same ids; they differ in the map from
each icosahedron face to the globe (:class:`dggs.Grid`): Snyder's ISEA or the
vertex-oriented great circle projection IVEA (docs/grid.md).  A store's data are
served under the DGGRS its points were binned with (``CellStore.projection``).

OGC API - DGGS Part 1 (§7, requirement ``/req/core/dggrs-description``) asks for a
description at ``.../dggs/{dggrsId}`` (schema ``openapi/schemas/dggs-core/dggrs.yaml``)
with a link (rel ``[ogc-rel:dggrs-definition]``) to a definition of the grid and its
zone identifiers (Annex B, ``core/schemas/dggrs-definition/dggrs-definition-proposed.yaml``:
``dggh``, ``zirs``, ``subZoneOrder``).  The definition is served at
``.../dggs/{dggrsId}/definition`` and embedded in the description too, with the
cell area of every level.

Examples
--------
>>> definition()["dggh"]["definition"]["basePolyhedron"]
'icosahedron'
>>> levels()[7]["zones"], round(levels()[7]["areaKm2"])
(87480, 5831)
>>> projection_of("DGGS-Split26-IVEA"), dggrs_of("ISEA")
('IVEA', 'DGGS-Split26-ISEA')
"""

from __future__ import annotations

from typing import Any

import dggs
from dggs.geometry.authalic import WGS84
from dggs.geometry.icosahedron import ISEA

__all__ = ["DGGRS_ID", "DGGRS_IDS", "REL", "CRS84", "definition", "description", "levels", "item", "zone_count",
           "projection_of", "dggrs_of"]

#: The id of the ISEA DGGRS (``{dggrsId}`` in the paths), the default one.
DGGRS_ID = "DGGS-Split26-ISEA"
#: Every DGGRS served, with the projection of its grid (:class:`dggs.Grid`).
DGGRS_IDS = {DGGRS_ID: "ISEA", "DGGS-Split26-IVEA": "IVEA"}


def projection_of(dggrs_id: str) -> str:
    """The projection (``"ISEA"`` or ``"IVEA"``) of a served DGGRS id (KeyError for another)."""
    return DGGRS_IDS[dggrs_id]


def dggrs_of(projection: str) -> str:
    """The DGGRS id of a projection."""
    return f"DGGS-Split26-{projection}"

#: OGC link relation types, ``[ogc-rel:x]`` in the standard.
REL = "http://www.opengis.net/def/rel/ogc/1.0/"

#: The CRS of all coordinates (longitude, latitude on WGS84).
CRS84 = "http://www.opengis.net/def/crs/OGC/1.3/CRS84"

#: Default ``zone-depth`` of zone data (``defaultDepth``), clamped to the stored level.
DEFAULT_DEPTH = 3

_TITLE = "Split (2:6) equal-area triangles on the ISEA icosahedron (dggs)"

_DESCRIPTION = (
    "Equal-area triangular zones: the 20 faces of an icosahedron in the standard ISEA orientation, "
    "each split into 6 congruent 30-60-90 triangles at level 1 (Split (2:6)), then every triangle into 3 "
    "similar ones per level (aperture 3), mapped to the globe by Snyder's equal-area polyhedral projection "
    "on the WGS84 authalic sphere (Split (2:6): thesis 'Equal Area Spherical Subdivision', University of "
    "Calgary, section 6.1.7). Every zone of a level has exactly the same area on the WGS84 ellipsoid."
)


def zone_count(level: int) -> int:
    """Number of zones at ``level``: 20, then 120 * 3**(level - 1).

    Examples
    --------
    >>> [zone_count(level) for level in range(4)]
    [20, 120, 360, 1080]
    """
    return 20 if level == 0 else 120 * 3 ** (level - 1)


def levels() -> list[dict[str, Any]]:
    """Zone count and area of every level 0..MAX_LEVEL (the ellipsoid's area over the count)."""
    return [
        {
            "level": level,
            "zones": zone_count(level),
            "areaMetersSquare": float(dggs.cell_area(level)),
            "areaKm2": float(dggs.cell_area(level, "km^2")),
        }
        for level in range(dggs.MAX_LEVEL + 1)
    ]


_IVEA_TITLE = "Split (2:6) equal-area triangles on the icosahedron, IVEA projection (dggs)"

_IVEA_DESCRIPTION = _DESCRIPTION.replace(
    "mapped to the globe by Snyder's equal-area polyhedral projection",
    "mapped to the globe by the vertex-oriented great circle equal-area projection of van Leeuwen and Strebe "
    "(2006, IVEA)",
) + " The same zone ids as DGGS-Split26-ISEA name zones up to 56 km from those of ISEA."

_IVEA_PROJECTION = (
    "The vertex-oriented great circle equal-area projection of the icosahedron (van Leeuwen and Strebe 2006, "
    f"IVEA) on the authalic sphere of WGS84 (radius {WGS84.authalic_radius:.4f} m): great circles through a "
    "face's vertices map to straight lines; geodetic latitudes are converted to authalic ones."
)


def _titles(dggrs_id: str) -> tuple[str, str]:
    return (_IVEA_TITLE, _IVEA_DESCRIPTION) if projection_of(dggrs_id) == "IVEA" else (_TITLE, _DESCRIPTION)


def definition(dggrs_id: str = DGGRS_ID) -> dict[str, Any]:
    """The DGGRS definition (Annex B schema: ``dggh``, ``zirs``, ``subZoneOrder``) of ``dggrs_id``.

    Examples
    --------
    >>> definition("DGGS-Split26-IVEA")["dggh"]["definition"]["projection"][:40]
    'The vertex-oriented great circle equal-a'
    """
    out = _isea_definition()
    if projection_of(dggrs_id) == "IVEA":
        out["title"], out["description"] = _titles(dggrs_id)
        out["dggh"]["definition"]["projection"] = _IVEA_PROJECTION
        out["links"] = [{"rel": "related", "href": "https://doi.org/10.3138/X687-1574-4325-WM62",
                         "title": "van Leeuwen and Strebe 2006, A 'slice-and-dice' approach to area equivalence "
                                  "in polyhedral map projections"}]
    return out


def _isea_definition() -> dict[str, Any]:
    geodetic_lat = float(WGS84.authalic_to_geodetic_deg(ISEA.lat))
    return {
        "title": _TITLE,
        "description": _DESCRIPTION,
        "links": [
            {"rel": "related", "href": "https://doi.org/10.3138/27H7-8K88-4882-1752",
             "title": "Snyder 1992, An equal-area map projection for polyhedral globes"},
        ],
        "dggh": {
            "definition": {
                "spatialDimensions": 2,
                "temporalDimensions": 0,
                "crs": CRS84,
                "basePolyhedron": "icosahedron",
                "refinementRatio": 3,
                "refinementDescription": (
                    "Level 0: the 20 icosahedron faces. Level 1: each face split into 6 congruent 30-60-90 "
                    "triangles (vertex A, face centre B, edge midpoint C), aperture 6. Every further level splits "
                    "a triangle A(30) B(60) C(90) into 3 similar ones (aperture 3): the bisector of the 60-degree "
                    "angle meets AC at D, E is the midpoint of AB; children 0 = BCD, 1 = BDE, 2 = ADE."
                ),
                "refinementStrategy": ["nestedChildCell"],
                "constraints": {"cellEqualSized": True},
                "zoneTypes": ["triangle"],
                "projection": (
                    "Snyder's equal-area polyhedral projection (1992) on the authalic sphere of WGS84 "
                    f"(radius {WGS84.authalic_radius:.4f} m); geodetic latitudes are converted to authalic ones."
                ),
            },
            "parameters": {
                "ellipsoid": "[EPSG:7030]",
                "orientation": {
                    "description": (
                        "Standard ISEA orientation (PROJ's +proj=isea default): icosahedron vertex 0 at authalic "
                        f"latitude atan(golden ratio) = {ISEA.lat:.12f} degrees ({geodetic_lat:.12f} geodetic), "
                        f"longitude {ISEA.lng} degrees, second vertex due north (azimuth 0); "
                        "both poles on edge midpoints; faces numbered as PROJ's isea (0..19 = letters A..T)."
                    ),
                    "latitude": geodetic_lat,
                    "authalicLatitude": ISEA.lat,
                    "longitude": ISEA.lng,
                    "azimuth": ISEA.azimuth,
                },
            },
        },
        "zirs": {
            "textZIRS": {
                "description": (
                    "A face letter A-T (icosahedron face 0-19), then a digit 0-5 for the level-1 triangle "
                    "(clockwise from the face's reference vertex), then one digit 0-2 per further level; "
                    "level = length - 1, the parent is the id without its last character, e.g. 'C401' is a "
                    f"level-3 zone. Levels 0..{dggs.MAX_LEVEL}."
                ),
                "type": "hierarchicalConcatenation",
            },
            "uint64ZIRS": {
                "description": (
                    "A positive 64-bit integer, most significant bits first: 0 (sign), 1 (marker), 5 bits face "
                    "0-19, 3 bits level-1 code (0 = none, 1-6 = digit 0-5), then 2 bits per level 2.."
                    f"{dggs.MAX_LEVEL} (0 = none, 1-3 = digit 0-2). Numeric order is the text order; "
                    "'C401' = 4996743786567565312."
                ),
            },
        },
        "subZoneOrder": {
            "description": (
                "Sub-zones at any depth are ordered by their text identifiers (depth-first: children in digit "
                "order 0, 1, 2, or 0-5 below a face), which is also the order of the 64-bit identifiers."
            ),
            "type": "hierarchicalConcatenation",
        },
    }


def link(href: str, rel: str, kind: str = "application/json", title: str | None = None) -> dict[str, Any]:
    """One OGC API link object (``href``, ``rel``, ``type``, optional ``title``)."""
    link = {"href": href, "rel": rel, "type": kind}
    if title:
        link["title"] = title
    return link


def item(base: str, prefix: str, dggrs_id: str = DGGRS_ID) -> dict[str, Any]:
    """The short entry of the DGGRS list (``openapi/schemas/dggs-core/dggrs-item.yaml``)."""
    href = f"{base}{prefix}/dggs/{dggrs_id}"
    return {
        "id": dggrs_id,
        "title": _titles(dggrs_id)[0],
        "links": [
            link(href, "self"),
            link(f"{href}/definition", REL + "dggrs-definition", title="DGGRS definition"),
        ],
    }


def description(base: str, prefix: str, stored_level: int | None, collection: str | None,
                dggrs_id: str = DGGRS_ID, serves_data: bool = True) -> dict[str, Any]:
    """The DGGRS description (``openapi/schemas/dggs-core/dggrs.yaml``, /req/core/dggrs-description).

    ``maxRefinementLevel`` is the stored level (/rec/core/max-refinement):
    zone data and zone queries go no finer.  Without ``serves_data`` (the DGGRS
    the store's data were not binned with) there are no zone data or zone query links.
    """
    href = f"{base}{prefix}/dggs/{dggrs_id}"
    title, text = _titles(dggrs_id)
    links = [
        link(href, "self"),
        link(f"{href}/definition", REL + "dggrs-definition", title="DGGRS definition"),
        link(f"{base}/", REL + "dataset", title="Landing page"),
    ]
    if serves_data:
        links.insert(2, link(f"{href}/zones", REL + "dggrs-zone-query", title="Zones holding data"))
    if collection is not None:
        links.append(link(f"{base}/collections/{collection}", REL + "geodata", title=collection))
    keywords = ["IVEA", "van Leeuwen", "Strebe"] if projection_of(dggrs_id) == "IVEA" else ["ISEA", "Snyder"]
    out: dict[str, Any] = {
        "id": dggrs_id,
        "title": title,
        "description": text,
        "keywords": ["DGGS", "equal-area", "triangle", "icosahedron", "Split 2:6", *keywords],
        "crs": CRS84,
        "defaultDepth": DEFAULT_DEPTH,
        "links": links,
        "linkTemplates": [
            {"uriTemplate": f"{href}/zones/{{zoneId}}", "rel": REL + "dggrs-zone-info",
             "type": "application/json", "variables": {"zoneId": {"type": "string"}}},
        ] + ([{"uriTemplate": f"{href}/zones/{{zoneId}}/data", "rel": REL + "dggrs-zone-data",
               "type": "application/json", "variables": {"zoneId": {"type": "string"}}}] if serves_data else []),
        "definition": definition(dggrs_id),
        "levels": levels(),
    }
    if stored_level is not None and serves_data:
        out["maxRefinementLevel"] = stored_level
        out["maxRelativeDepth"] = stored_level
    return out
