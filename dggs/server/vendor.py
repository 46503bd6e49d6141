"""The web map's MapLibre GL JS files: whether they are installed, and how to get them.

They are an npm dependency (``dggs/server/package.json``) that ``make static`` copies into
``static/vendor`` (git-ignored) and that building a wheel copies in (:mod:`dggs.server._build`); a wheel
built where npm was missing lacks them, and the page would then wait for them forever.  ``dggs serve`` warns at start-up and ``/`` answers a page that says so.
"""

from __future__ import annotations

import os
from pathlib import Path

__all__ = ["STATIC_FOLDER", "VENDOR", "VENDOR_HELP", "missing_vendor"]

#: The web map's files (served at ``/static`` and ``/``).
STATIC_FOLDER = Path(__file__).parent / "static"
#: The MapLibre GL JS files the web map imports (copied into ``static/vendor`` by ``make static``).
VENDOR = ("vendor/maplibre-gl/maplibre-gl.mjs", "vendor/maplibre-gl/maplibre-gl.css")
#: How to get them (docs/serve.md, "The web map's MapLibre files").
VENDOR_HELP = (
    "the web map's MapLibre GL JS files are not installed (static/vendor/maplibre-gl): "
    "the API works, the map at / does not; in a clone of the repository run `make static` (needs npm), "
    "or pass create_app(static=...) a folder that has them (docs/serve.md)"
)


def missing_vendor(folder: str | os.PathLike[str] | None = None) -> list[str]:
    """The MapLibre files missing from the web map's folder (``STATIC_FOLDER`` by default): empty when it is complete.

    A wheel built without ``make static`` lacks them, and the page would then wait for them forever.

    Examples
    --------
    >>> missing_vendor("/nonexistent")
    ['vendor/maplibre-gl/maplibre-gl.mjs', 'vendor/maplibre-gl/maplibre-gl.css']
    """
    base = Path(folder) if folder is not None else STATIC_FOLDER
    return [name for name in VENDOR if not (base / name).is_file()]
