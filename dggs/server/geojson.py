"""GeoJSON text assembled from cached geometry text (fast: no parse of the geometries again).

Examples
--------
>>> import json
>>> text = feature_collection(["A"], ['{"type":"Point","coordinates":[0,0]}'], [{"n": 1}], {"numberReturned": 1})
>>> json.loads(text)["features"][0]["properties"], json.loads(text)["numberReturned"]
({'n': 1}, 1)
"""

from __future__ import annotations

import json
import math
from collections.abc import Sequence
from typing import Any

__all__ = ["GEOJSON", "feature_collection", "clean"]

#: Media type of GeoJSON (RFC 7946).
GEOJSON = "application/geo+json"


def clean(value: Any) -> Any:
    """A JSON-safe value: NaN and infinities become null (JSON has neither).

    Examples
    --------
    >>> clean(float("nan")), clean(2.5), clean(3)
    (None, 2.5, 3)
    """
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


def feature_collection(
    ids: Sequence[str], geometries: Sequence[str], properties: Sequence[dict[str, Any]], extra: dict[str, Any]
) -> str:
    """A FeatureCollection as text: feature ``id`` = zone id, geometry text as given, then ``extra`` members."""
    dumps = json.dumps
    features = ",".join(
        f'{{"type":"Feature","id":{dumps(i)},"geometry":{g},"properties":{dumps(p, allow_nan=False)}}}'
        for i, g, p in zip(ids, geometries, properties, strict=True)
    )
    tail = "".join(f",{dumps(k)}:{dumps(v, allow_nan=False)}" for k, v in extra.items())
    return f'{{"type":"FeatureCollection","features":[{features}]{tail}}}'
