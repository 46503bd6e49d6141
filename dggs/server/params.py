"""Parsing and checking request parameters; every failure is a :class:`BadRequest` naming the value.

Examples
--------
>>> parse_bbox("170,-10,-170,10")
(170.0, -10.0, -170.0, 10.0)
>>> parse_depths("1-3"), parse_depths("0,2"), parse_depths(None, default=2)
([1, 2, 3], [0, 2], [2])
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field, replace
from typing import Any

import dggs

from .errors import BadRequest, NotAcceptable, NotFound

__all__ = ["Context", "parse_bbox", "parse_zone", "parse_depths", "check_level", "negotiate", "base_url",
           "MEDIA_TYPES"]


@dataclass
class Context:
    """What every handler needs: the store and the limits."""

    reader: Any  # StoreReader: the default dataset's (the root paths), or the collection's (check_collection)
    max_zones: int  # zones in a zone listing
    max_features: int  # features (or sub-zone values) in /map/cells and zone data
    readers: dict[str, Any] = field(default_factory=dict)  # every collection's StoreReader, by collection id


def base_url(request: Any) -> str:
    """The server's base URL without a trailing slash (for absolute links)."""
    return str(request.base_url).rstrip("/")


def parse_bbox(raw: str | None, name: str = "bbox") -> tuple[float, float, float, float] | None:
    """``w,s,e,n`` in degrees (CRS84); ``w > e`` crosses the antimeridian.

    Raises
    ------
    BadRequest
        Unless there are 4 finite numbers with -180 <= w, e <= 180, -90 <= s < n <= 90, w != e.
    """
    if raw is None:
        return None
    parts = raw.split(",")
    try:
        values = [float(p) for p in parts]
    except ValueError:
        raise BadRequest(f"{name} {raw!r} must be 4 comma-separated numbers w,s,e,n (degrees)") from None
    if len(values) != 4 or not all(math.isfinite(v) for v in values):
        raise BadRequest(f"{name} {raw!r} must be 4 comma-separated finite numbers w,s,e,n (degrees)")
    w, s, e, n = values
    if not (-180 <= w <= 180 and -180 <= e <= 180):
        raise BadRequest(f"{name} {raw!r}: longitudes must lie in -180..180")
    if not (-90 <= s <= 90 and -90 <= n <= 90):
        raise BadRequest(f"{name} {raw!r}: latitudes must lie in -90..90")
    if s >= n:
        raise BadRequest(f"{name} {raw!r}: south {s:g} must be less than north {n:g}")
    if w == e:
        raise BadRequest(f"{name} {raw!r}: west and east are equal (an empty box)")
    return (w, s, e, n)


def parse_zone(raw: str) -> str:
    """A zone id (text form, e.g. ``C401``), checked.

    Raises
    ------
    BadRequest
        If it is not a valid zone id of this DGGRS.
    """
    if not dggs.is_valid_cell(raw):
        raise BadRequest(
            f"zoneId {raw!r} is not a zone of this DGGRS: a face letter A-T, a digit 0-5, "
            f"then digits 0-2, at most {dggs.MAX_LEVEL + 1} characters (e.g. 'C401')"
        )
    return raw


_DEPTH = re.compile(r"^\d{1,2}$")


def parse_depths(raw: str | None, default: int = 0) -> list[int]:
    """The ``zone-depth`` forms of /req/data-custom-depths/zone-depth: ``d``, ``lo-hi`` or ``a,b,c``.

    Raises
    ------
    BadRequest
        For anything else (negative, empty, reversed range).
    """
    if raw is None:
        return [default]
    text = raw.strip()
    bad = BadRequest(
        f"zone-depth {raw!r} must be a depth (e.g. 2), a range low-high (e.g. 1-3) or a list (e.g. 0,2), "
        "of whole numbers >= 0"
    )
    if "-" in text:
        lo, _, hi = text.partition("-")
        if not (_DEPTH.match(lo) and _DEPTH.match(hi)) or int(lo) > int(hi):
            raise bad
        return list(range(int(lo), int(hi) + 1))
    parts = text.split(",")
    if not all(_DEPTH.match(p) for p in parts):
        raise bad
    return sorted({int(p) for p in parts})


def check_level(name: str, level: int, stored: int | None) -> int:
    """A level in 0..MAX_LEVEL and no finer than the stored level (/per/core/beyond-max-refinement).

    Raises
    ------
    BadRequest
        If ``level`` is outside ``0..MAX_LEVEL`` or finer than the stored level.
    """
    if not 0 <= level <= dggs.MAX_LEVEL:
        raise BadRequest(f"{name} {level} is out of range 0..{dggs.MAX_LEVEL}")
    if stored is not None and level > stored:
        raise BadRequest(
            f"{name} {level} is finer than the stored level {stored} (maxRefinementLevel); use 0..{stored}"
        )
    return level


#: The media types of each ``f`` value; a route offers some of them (its ``formats``), the first the default.
#: ``uint64`` is /req/zone-uint64/content's zone list and ``ubjson`` /req/data-ubjson/content's DGGS-UBJSON;
#: ``openapi`` is ``/api``'s own type (3.0, /req/oas30/oas-impl-1), which also answers ``application/json``.
MEDIA_TYPES = {
    "json": ("application/json",),
    "geojson": ("application/geo+json",),
    "html": ("text/html",),
    "uint64": ("application/x-binary",),
    "ubjson": ("application/ubjson",),
    "openapi": ("application/vnd.oai.openapi+json", "application/json"),
    "text": ("text/plain",),
    "xml": ("application/xml", "text/xml"),
}


# Written by hand on purpose (issue 20, item 6): benchmarks/bench_handwritten_server.py times 100,000
# negotiations of each of 14 realistic Accept headers (Chrome, Firefox, */*, JSON, GeoJSON and binary clients,
# none) for the root's and the zone lists' formats: 8.3-8.6 µs a negotiation here on average (two runs),
# python-mimeparse's best_match 33-38 µs (about 4x) and werkzeug's MIMEAccept.best_match 74-96 µs (9-12x),
# each wrapped to give the same answer.  Neither library is as fast, and python-mimeparse also answers differently: among equal weights it
# takes the *last* offered type, so */* (curl, fetch) would get HTML at / and the binary zone list at /zones.
def negotiate(request: Any, f: str | None, formats: tuple[str, ...] = ("json", "geojson")) -> str:
    """Pick one of ``formats``: ``f`` if given, else the best match of the Accept header.

    The ``f`` parameter overrides the header.  In the header, ``q`` weights are honoured (``q=0`` refuses a
    type), ``*/*`` and ``type/*`` stand for the first of ``formats`` of that type, and among equal weights the
    header's first entry wins.  No Accept header (or an empty one) gives ``formats[0]``.

    Raises
    ------
    BadRequest
        For an ``f`` that is not one of ``formats``.
    NotAcceptable
        When the Accept header names only media types not offered (OGC API - Common /req/core/http: 406).
    """
    if f is not None:
        if f not in formats:
            raise BadRequest(f"f {f!r} is not a format of this resource; use one of {', '.join(formats)}")
        return f
    accept = request.headers.get("accept", "")
    if not accept.strip():
        return formats[0]
    best, best_q = None, 0.0
    for part in accept.split(","):
        media, *options = [p.strip() for p in part.split(";")]
        media = media.lower()
        q = 1.0
        for option in options:
            if option.replace(" ", "").lower().startswith("q="):
                try:
                    q = float(option.split("=", 1)[1])
                except ValueError:
                    q = 0.0
        if q <= best_q:
            continue
        for fmt in formats:
            types = MEDIA_TYPES[fmt]
            if media in types or media == "*/*" or (media.endswith("/*") and types[0].startswith(media[:-1])):
                best, best_q = fmt, q
                break
    if best is None:
        offered = ", ".join(MEDIA_TYPES[f][0] for f in formats)
        raise NotAcceptable(f"Accept {accept!r} names no media type offered here ({offered})")
    return best


def check_collection(ctx: Context, collection: str | None) -> Context:
    """The context of ``collection`` (its dataset's reader); ``ctx`` itself for None (the root paths).

    Each dataset of the store is a collection (storage/datasets.py); the default one keeps the file's stem.

    Raises
    ------
    NotFound
        If ``collection`` is not a collection this server serves, naming the ones it does.
    """
    if collection is None:
        return ctx
    readers = ctx.readers or {ctx.reader.collection_id: ctx.reader}
    if collection not in readers:
        raise NotFound(f"no collection {collection!r}; this server has {', '.join(map(repr, readers))}")
    return replace(ctx, reader=readers[collection])


def check_dggrs(dggrs_id: str) -> str:
    """The projection of ``dggrs_id`` (``"ISEA"`` or ``"IVEA"``); 404 unless it is a DGGRS served.

    Raises
    ------
    NotFound
        If ``dggrs_id`` is not a DGGRS this server offers.
    """
    from .dggrs import DGGRS_IDS

    if dggrs_id not in DGGRS_IDS:
        raise NotFound(f"no DGGRS {dggrs_id!r}; this server offers {', '.join(map(repr, DGGRS_IDS))}")
    return DGGRS_IDS[dggrs_id]


def check_data_dggrs(ctx: Context, dggrs_id: str) -> str:
    """``dggrs_id``'s projection if the store's data were binned with it; 404 naming the right DGGRS if not.

    The same zone id names another place on the other projection, so data binned on one are never
    served under the other (they would be misplaced by up to 56 km).

    Raises
    ------
    NotFound
        If ``dggrs_id`` is not served, or is not the DGGRS of the store's data.
    """
    from .dggrs import dggrs_of

    projection = check_dggrs(dggrs_id)
    if projection != ctx.reader.projection:
        raise NotFound(f"no data under DGGRS {dggrs_id!r}: the store {ctx.reader.path.name} was binned on "
                       f"{ctx.reader.projection}; its data are served under {dggrs_of(ctx.reader.projection)!r}")
    return projection
