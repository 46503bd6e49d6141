"""The binary encodings of OGC API - DGGS Part 1: zone lists as 64-bit integers, zone data as DGGS-UBJSON.

- *Zone list - 64-bit integer* (requirements class ``zone-uint64``, /req/zone-uint64/content, checked against
  the requirement's text in OGC 21-038r1, core/requirements/requirements_class_zone_list_binary_64bit.adoc at
  commit 539f23e, part by part):

  1. "Every 200 response ... for zone query with the media type ``application/x-binary`` SHALL be ... a first
     64-bit integer count defining the number of zones returned, followed by one 64-bit integer for each
     zone": the count is of the zones in this response (after ``limit``/``offset``), then exactly that many
     ids, nothing else (no header, no padding); clause 17's media-type table names ``application/x-binary``,
     and the ``f`` value is ``uint64``, as the standard's ``f-zoneQueries`` parameter lists it.
  2. "The 64-bit integer identifiers SHALL be the ones defined by the DGGRS": the DGGRS definition's
     ``uint64ZIRS`` (docs/grid.md's bit layout), the ``uint64Id`` of zone information (``dggs.str_to_int``).
  3. "The endianness of the returned count and zones integers SHALL be little endian": ``<u8`` for both;
     the overview calls them unsigned.
  4. "If the DGGRS does not define a 64-bit integer identifier, a 406": not applicable, this one does (every
     id of levels 0-28, the levels a store can hold).
- *DGGS-UBJSON* (requirements class ``data-ubjson``, /req/data-ubjson/content): media type
  ``application/ubjson`` (``f=ubjson``): the DGGS-JSON document of zone data (/req/data-json/content) in
  Universal Binary JSON, encoded by the ``py-ubjson`` library (floats as float64, so nothing is rounded).

Examples
--------
>>> import numpy as np
>>> body = uint64_zone_list(["A", "C401"])
>>> n, *ids = np.frombuffer(body, dtype="<u8").tolist()
>>> n, dggs.int_to_str(ids)
(2, ['A', 'C401'])
>>> import ubjson
>>> ubjson.loadb(dggs_ubjson({"zoneId": "C4", "data": [1, None, 2.5]})) == {"zoneId": "C4", "data": [1, None, 2.5]}
True
"""

from __future__ import annotations

import importlib.util
from typing import Any

import numpy as np

import dggs

__all__ = ["UINT64", "UBJSON", "HAS_UBJSON", "uint64_zone_list", "dggs_ubjson"]

#: Media type of the 64-bit integer zone list (/req/zone-uint64/content).
UINT64 = "application/x-binary"
#: Media type of DGGS-UBJSON zone data (/req/data-ubjson/content).
UBJSON = "application/ubjson"
#: Whether ``py-ubjson`` (the ``serve`` extra) is installed: DGGS-UBJSON is offered only then.
HAS_UBJSON = importlib.util.find_spec("ubjson") is not None


def uint64_zone_list(zones: list[str]) -> bytes:
    """The zone list ``zones`` (text ids) as /req/zone-uint64/content has it.

    A little-endian uint64 count, then the zones' uint64 ids, little-endian, in the given order (parts 1-3 of
    /req/zone-uint64/content; see the module docstring).
    """
    ids = dggs.str_to_int(np.asarray(zones, dtype=str)) if zones else np.empty(0, dtype=np.uint64)
    head = np.array([len(zones)], dtype="<u8")
    return head.tobytes() + np.asarray(ids).astype("<u8").tobytes()


def dggs_ubjson(document: dict[str, Any]) -> bytes:
    """The DGGS-JSON ``document`` in UBJSON (/req/data-ubjson/content), by the ``py-ubjson`` library.

    Raises
    ------
    ImportError
        If ``py-ubjson`` (the ``serve`` extra) is not installed.
    """
    import ubjson

    return bytes(ubjson.dumpb(document))
