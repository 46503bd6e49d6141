"""Where a global 1-degree raster's cells lose exactness (issue 32 item 2): a diagnosis, not a fix.

Bins a global lat/lng raster of ones (1 degree) at level 5 and takes each cell's covered fraction before
``coverage`` caps it at 1 (``Partials.covered`` over the cell's area), then sorts the cells by where their
pixels are: pixels crossing an icosahedron edge, pixels crossing a sector median (the arcs from a face's
centre to its vertices and edge midpoints, where Snyder's projection kinks), cells round an icosahedron
vertex, the polar rows.  Run ``python -m dggs.experiments.raster_weights_diagnosis`` (needs the raster extra).

Findings on the kernel of 8997da8 (unchanged since), 9,720 cells:

- 7,617 cells are more than 1e-8 from 1 (2,590 below, 5,027 above: ``coverage`` caps those), 60 more than
  1e-6, the worst 0.99999664 (O21222);
- 59 of the 60 worst contain pixels crossing a sector median, none a pixel crossing a face edge; the worst
  eight are the cells at face centres (``...222``, where the six sector rays meet), 24 of the 60 lie within
  two steps of a face centre's cell;
- cells with no pixel crossing any kink are still off by about 2e-8 (median): the pixel's whole area is
  extrapolated to ~1e-9, but each piece only to ``TOLERANCE`` (1e-5 of its pixel), and a cell's coverage is
  a sum of pieces, so ~1e-9 is a bound on pixels, not on cells.

So the inexactness is the pieces of pixels cut across the sector medians (the kernel draws the crossing
as an edge point but the piece areas on either side carry the chord error), worst where the medians meet.

Root cause (found after; issue 32 item 2): neither kink was it.  With one ``k`` for the whole raster and
the pieces left as the kernel cuts them, every cell is covered to 4e-14: chord polygons sharing their edges
tile the plane, kinks included.  Two things broke the tiling: (1) tiles of 32 pixels drawn with different
``k`` (26 to 102 here) draw their shared edges with different chords, and (2) each pixel's pieces were
scaled to its Richardson-extrapolated area, moving area between the cells a pixel meets in proportion to
the pieces, not to where its edges' chords cut (the face centres: pixels with strongly bent edges).  The
fix (``dggs_raster_pieces_arcs``, the kernel's ``arcs``) adds each pair of chords' parabolic segment to the piece of
the cell it lies in: a shared edge then gives and takes the same area in the same cell; worst cell 1.5e-7.
"""

from __future__ import annotations

import tempfile
from pathlib import Path
from typing import Any

import numpy as np

__all__ = ["coverage_fractions", "kink_cells", "main"]


def coverage_fractions(level: int = 5) -> tuple[np.ndarray, np.ndarray]:
    """(cells, covered fraction uncapped) of a global 1-degree raster of ones binned at ``level``."""
    import rasterio
    from rasterio.transform import from_origin

    from dggs.index.measure import cell_area
    from dggs.raster import block_results, combine, open_checked

    path = Path(tempfile.mkdtemp()) / "ones.tif"
    with rasterio.open(path, "w", driver="GTiff", height=180, width=360, count=1, dtype="float64", crs="EPSG:4326",
                       transform=from_origin(-180, 90, 1, 1)) as dst:
        dst.write(np.ones((1, 180, 360)))
    _, src = open_checked(str(path), level, "mean", None, None, None, 512)
    parts = [p for p in block_results(src, level, "mean", False, 512) if p is not None]
    total = combine(parts, 1)
    return total.cells, total.covered / float(cell_area(level, unit="m^2"))


def _arc(a: np.ndarray, b: np.ndarray, n: int = 4000) -> np.ndarray:
    w = np.arccos(np.clip(a @ b, -1, 1))
    t = np.linspace(0, 1, n)[:, None]
    out: np.ndarray = (np.sin((1 - t) * w) * a + np.sin(t * w) * b) / np.sin(w)
    return out


def _geodetic(xyz: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    from dggs.geometry.authalic import WGS84
    from dggs.geometry.icosahedron import xyz_to_latlng

    out = [xyz_to_latlng(p) for p in xyz]
    beta, lng = np.degrees([o[0] for o in out]), np.degrees([o[1] for o in out])
    return np.array([WGS84.authalic_to_geodetic_deg(b) for b in beta]), lng


def kink_cells(level: int = 5) -> dict[str, set[int]]:
    """Cells sharing a 1-degree pixel with a face edge, with a sector median; cells round a face centre."""
    from dggs.geometry.icosahedron import ISEA
    from dggs.index.grid import grid_disk
    from dggs.index.points import latlng_to_cell

    vertices, faces = np.asarray(ISEA.geometry.vertices), np.asarray(ISEA.geometry.face_vertices)
    edges, medians, centres = [], [], []
    for f in range(20):
        c = vertices[faces[f]].sum(axis=0)
        c /= np.linalg.norm(c)
        centres.append(c)
        for k in range(3):
            a, b = vertices[faces[f, k]], vertices[faces[f, (k + 1) % 3]]
            edges.append(_arc(a, b))
            medians += [_arc(c, a), _arc(c, (a + b) / np.linalg.norm(a + b))]

    def through_pixels(arcs: list[np.ndarray]) -> set[int]:
        lat, lng = _geodetic(np.concatenate(arcs))
        rows = np.clip(np.floor(90 - lat), 0, 179).astype(int)
        cols = np.clip(np.floor(lng + 180), 0, 359).astype(int)
        pix = np.unique(rows * 360 + cols)
        fr = (np.arange(10) + 0.5) / 10
        r, c = pix // 360, pix % 360
        plat = (90 - r[:, None, None] - fr[None, :, None] + 0 * fr[None, None, :]).ravel()
        plng = (-180 + c[:, None, None] + fr[None, None, :] + 0 * fr[None, :, None]).ravel()
        return set(np.asarray(latlng_to_cell(plat, plng, level, as_int=True)).tolist())

    clat, clng = _geodetic(np.array(centres))
    centre = np.asarray(latlng_to_cell(clat, clng, level, as_int=True), dtype=np.uint64)
    disk = set(np.asarray(grid_disk(centre, 2)).ravel().tolist()) - {0}
    return {"face edge pixel": through_pixels(edges), "sector median pixel": through_pixels(medians),
            "within 2 of a face centre": disk}


def main() -> dict[str, Any]:
    """Print and return the counts of the module doc."""
    from dggs.index.ids import int_to_str

    cells, frac = coverage_fractions()
    err = np.abs(frac - 1)
    groups = kink_cells()
    report: dict[str, Any] = {"cells": int(cells.size), "over 1e-8": int((err > 1e-8).sum()),
                              "below 1 - 1e-8": int((frac < 1 - 1e-8).sum()), "over 1e-6": int((err > 1e-6).sum())}
    big = err > 1e-6
    for name, members in groups.items():
        inside = np.isin(cells, np.fromiter(members, np.uint64))
        report[f"over 1e-6 with a {name}"] = int((big & inside).sum())
    worst = np.argsort(err)[::-1][:8]
    report["worst"] = [(str(int_to_str(int(c))), float(f)) for c, f in zip(cells[worst], frac[worst], strict=True)]
    for k, v in report.items():
        print(f"{k}: {v}")
    return report


if __name__ == "__main__":
    main()
