"""The binary encodings of OGC API - DGGS Part 1: zone lists as 64-bit integers, zone data as DGGS-UBJSON.

- *Zone list - 64-bit integer* (requirements class ``zone-uint64``, /req/zone-uint64/content): media type
  ``application/x-binary`` (``f=uint64``, the value the standard's ``f`` parameter of zone queries lists):
  the number of zones as a little-endian unsigned 64-bit integer, then each zone's 64-bit integer id,
  little-endian, in the order of the JSON list.  This DGGRS's integer ids are the ``uint64Id`` of zone
  information (``dggs.str_to_int``).
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

    A little-endian uint64 count, then the zones' uint64 ids, little-endian, in the given order.
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
