"""The server's hand-written parts against the libraries made for them (issue 20, item 6).

1. HTTP media-type negotiation: ``dggs.server.params.negotiate`` (a loop over the Accept header's entries)
   against python-mimeparse's ``best_match`` and werkzeug's ``MIMEAccept.best_match``, each wrapped to give
   what ``negotiate`` gives (a format name, or the 406 when nothing offered is acceptable), over a tight loop
   of ``--n`` negotiations of realistic Accept headers (browsers, fetch, curl, none, the binary encodings,
   q-weighted lists), for the two sets of formats the server offers most (``/``: json, html; zone lists:
   json, geojson, uint64).  Every header is negotiated both ways and the answers compared.
2. OGC documents: the landing page, a collection, the DGGRS list and a zone information document built as
   dicts and serialised with ``json.dumps`` (what the server does: starlette's JSONResponse) against the
   same documents as pydantic v2 models (written here from the standard's schemas: landingPage,
   collectionDesc, rDGGRSList, zone-info) built from the same values and serialised with
   ``model_dump_json``; the extra cost per document against a whole request (bench_serve.py's p50).

Medians of ``--rounds`` interleaved rounds, microseconds per call, one thread.

Run::

    .venv/bin/python benchmarks/bench_handwritten_server.py            # 100,000 negotiations a case
    .venv/bin/python benchmarks/bench_handwritten_server.py --n 10000 --rounds 3   # quicker
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import tempfile
import time
import warnings
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from dggs.server.errors import NotAcceptable
from dggs.server.params import MEDIA_TYPES, negotiate

#: Accept headers as clients send them.
HEADERS = {
    "Chrome": "text/html,application/xhtml+xml,application/xml;q=0.9,image/avif,image/webp,image/apng,*/*;q=0.8,"
              "application/signed-exchange;v=b3;q=0.7",
    "Firefox": "text/html,application/xhtml+xml,application/xml;q=0.9,*/*;q=0.8",
    "fetch/curl": "*/*",
    "JSON client": "application/json",
    "GeoJSON client": "application/geo+json, application/json;q=0.8",
    "binary, weighted": "application/json;q=0.5, application/x-binary;q=0.9",
    "none": "",
}
#: Documents built per case and round.
REPS = 2000
FORMATS = {"/": ("json", "html"), "zones": ("json", "geojson", "uint64")}


class _Request:
    """What ``negotiate`` reads of a request: its headers."""

    def __init__(self, accept: str) -> None:
        self.headers = {"accept": accept} if accept else {}


def _by_type(formats: tuple[str, ...]) -> tuple[list[str], dict[str, str]]:
    offered = [MEDIA_TYPES[f][0] for f in formats]
    return offered, {MEDIA_TYPES[f][0]: f for f in formats}


def mimeparse_negotiate(accept: str, formats: tuple[str, ...]) -> str:
    """python-mimeparse's best_match, giving a format name or raising the 406 as ``negotiate`` does."""
    import mimeparse

    offered, back = _by_type(formats)
    if not accept.strip():
        return formats[0]
    best = mimeparse.best_match(offered, accept)
    if not best:
        raise NotAcceptable(f"Accept {accept!r}")
    return back[best]


def werkzeug_negotiate(accept: str, formats: tuple[str, ...]) -> str:
    """werkzeug's MIMEAccept.best_match, giving a format name or raising the 406 as ``negotiate`` does."""
    from werkzeug.datastructures import MIMEAccept
    from werkzeug.http import parse_accept_header

    offered, back = _by_type(formats)
    if not accept.strip():
        return formats[0]
    best = parse_accept_header(accept, MIMEAccept).best_match(offered)
    if best is None:
        raise NotAcceptable(f"Accept {accept!r}")
    return back[best]


def _answer(fn: Callable[[], str]) -> str:
    try:
        return fn()
    except NotAcceptable:
        return "406"


def _time(cases: dict[str, Callable[[], Any]], rounds: int) -> dict[str, float]:
    """Median seconds of one call of each case, the cases in turn in every round (after a warm-up)."""
    times: dict[str, list[float]] = {k: [] for k in cases}
    for fn in cases.values():
        fn()
    for _ in range(rounds):
        for key, fn in cases.items():
            t = time.perf_counter()
            fn()
            times[key].append(time.perf_counter() - t)
    return {k: statistics.median(v) for k, v in times.items()}


def negotiation(n: int, rounds: int) -> list[str]:
    """Table 1: µs per negotiation, per header and set of formats, and whether the answers agree."""
    libs: dict[str, Callable[[str, tuple[str, ...]], str]] = {}
    for name, fn in (("python-mimeparse", mimeparse_negotiate), ("werkzeug", werkzeug_negotiate)):
        try:
            fn("*/*", ("json",))
            libs[name] = fn
        except ImportError:
            print(f"note: {name} is not installed; its column is left out", file=sys.stderr)
    out = ["| formats | Accept | hand-written µs | " + " | ".join(f"{k} µs" for k in libs)
           + " | answers (hand / " + " / ".join(libs) + ") |",
           "|---|---|---:|" + "---:|" * len(libs) + "---|"]
    totals: dict[str, list[float]] = {"hand-written": [], **{k: [] for k in libs}}
    for route, formats in FORMATS.items():
        for label, accept in HEADERS.items():
            request = _Request(accept)
            cases: dict[str, Callable[[], Any]] = {
                "hand-written": lambda r=request, f=formats: [_answer(lambda: negotiate(r, None, f)) for _ in range(n)]}
            for name, fn in libs.items():
                cases[name] = lambda a=accept, f=formats, g=fn: [_answer(lambda: g(a, f)) for _ in range(n)]
            answers = {"hand-written": _answer(lambda r=request, f=formats: negotiate(r, None, f)),
                       **{k: _answer(lambda g=g, a=accept, f=formats: g(a, f)) for k, g in libs.items()}}
            med = _time(cases, rounds)
            for k, v in med.items():
                totals[k].append(v / n)
            out.append(f"| {route} | {label} | {med['hand-written'] / n * 1e6:.2f} | "
                       + " | ".join(f"{med[k] / n * 1e6:.2f}" for k in libs)
                       + " | " + " / ".join(answers.values()) + " |")
    out.append("| **all** | mean of the rows | " + " | ".join(
        f"**{statistics.mean(v) * 1e6:.2f}**" for v in totals.values()) + " | |")
    return out


# -- 2. OGC documents as pydantic models ------------------------------------------------------------


def _models() -> dict[str, Any]:
    """Pydantic v2 models of the four documents, from the standard's schemas (optional members as None)."""
    from pydantic import BaseModel, ConfigDict

    class Link(BaseModel):  # common-core/link.yaml
        href: str
        rel: str
        type: str | None = None
        title: str | None = None

    class Landing(BaseModel):  # common-core/landingPage.yaml
        title: str | None = None
        description: str | None = None
        links: list[Link]

    class Spatial(BaseModel):
        bbox: list[list[float]]
        crs: str | None = None

    class Extent(BaseModel):
        spatial: Spatial | None = None

    class Collection(BaseModel):  # common-geodata/collectionDesc.yaml
        model_config = ConfigDict(extra="allow")
        id: str
        title: str | None = None
        description: str | None = None
        extent: Extent | None = None
        crs: list[str] | None = None
        storageCrs: str | None = None
        links: list[Link]

    class DggrsItem(BaseModel):  # dggs-core/dggrs-item.yaml
        id: str
        title: str
        uri: str | None = None
        links: list[Link]

    class DggrsList(BaseModel):  # rDGGRSList.yaml
        links: list[Link] | None = None
        dggrs: list[DggrsItem]

    class Geometry(BaseModel):
        type: str
        coordinates: list[Any]

    class Stats(BaseModel):
        minimum: float | None = None
        maximum: float | None = None
        average: float | None = None
        stdDev: float | None = None

    class ZoneInfo(BaseModel):  # dggs-core/zone-info.yaml (and this server's members)
        id: str
        level: int
        shapeType: str
        crs: str
        centroid: list[float]
        bbox: list[float]
        areaMetersSquare: float
        uint64Id: str
        parent: str | None
        children: list[str]
        neighbors: list[str]
        geometry: Geometry
        links: list[Link]
        dataCount: int | None = None
        statistics: dict[str, Stats] | None = None

    return {"landing page": Landing, "collection": Collection, "DGGRS list": DggrsList, "zone information": ZoneInfo}


def documents(n_rounds: int) -> tuple[list[str], float]:
    """Table 2: µs per document, dict + json.dumps against the pydantic model + model_dump_json."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        from fastapi.testclient import TestClient

    from dggs.server.app import create_app
    from dggs.storage import CellStore

    rng = np.random.default_rng(7)
    tmp = Path(tempfile.mkdtemp()) / "bench.db"
    lat, lng = np.degrees(np.arcsin(rng.uniform(-1, 1, 20_000))), rng.uniform(-180, 180, 20_000)
    with CellStore(tmp) as store:
        store.ingest_points(lat, lng, 7, {"pop": rng.integers(0, 1000, 20_000)})
    urls = {"landing page": "/?f=json", "collection": "/collections/bench", "DGGRS list": "/dggs",
            "zone information": "/dggs/DGGS-Split26-ISEA/zones/C401"}
    models = _models()
    out = ["| document | dict + json.dumps µs | pydantic build + model_dump_json µs | extra µs | "
           "whole request in process (TestClient) µs |", "|---|---:|---:|---:|---:|"]
    worst = 0.0
    with TestClient(create_app(tmp)) as client:
        for name, url in urls.items():
            doc = client.get(url).json()
            model = models[name]
            assert json.loads(model.model_validate(doc).model_dump_json(exclude_none=True)) == doc, name

            def as_dict(d: dict[str, Any] = doc) -> None:
                for _ in range(REPS):
                    json.dumps(json.loads(json.dumps(d)))  # a fresh dict of the same values, then its JSON

            def as_model(d: dict[str, Any] = doc, m: Any = model) -> None:
                for _ in range(REPS):
                    m.model_validate(json.loads(json.dumps(d))).model_dump_json(exclude_none=True)

            def copy_only(d: dict[str, Any] = doc) -> None:
                for _ in range(REPS):
                    json.loads(json.dumps(d))

            def request(u: str = url) -> None:
                for _ in range(50):
                    client.get(u)

            med = _time({"dict": as_dict, "model": as_model, "copy": copy_only, "request": request}, n_rounds)
            base = med["copy"] / REPS  # the fresh copy of the values, common to both ways
            d, m = (med["dict"] / REPS - base) * 1e6, (med["model"] / REPS - base) * 1e6
            worst = max(worst, m - d)
            out.append(f"| {name} | {d:.1f} | {m:.1f} | {m - d:.1f} | {med['request'] / 50 * 1e6:.0f} |")
    tmp.unlink()
    return out, worst


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--n", type=int, default=100_000, help="negotiations per case and round")
    ap.add_argument("--rounds", type=int, default=5)
    args = ap.parse_args()
    print(f"## Media-type negotiation: {args.n:,} negotiations a case, median of {args.rounds} rounds\n")
    print("\n".join(negotiation(args.n, args.rounds)))
    print("\n## OGC documents: dicts against pydantic models\n")
    table, worst = documents(args.rounds)
    print("\n".join(table))
    print(f"\nLargest extra cost of the pydantic models: {worst:.1f} µs a document, "
          f"{worst / 57_000 * 100:.3f} % of bench_serve.py's p50 request (57 ms).")


if __name__ == "__main__":
    main()
