"""Per-cell statistics of raster pieces: partials per block, combined across blocks (part of :mod:`dggs.raster`).

A block's pieces (pixel, cell, area) and its pixels' values give per-cell
partials that add across blocks: the covered area, the weighted sums, the
minimum and maximum, the pixel count, and the area of each class.  A cell
on a block's edge gets partials from each block it meets; :func:`combine`
adds them up once at the end.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

__all__ = ["Partials", "block_partials", "combine", "SLIVER", "shared"]

#: A pixel meets a cell when the area they share is more than this fraction of the smaller of the two.
#: Less is the rounding of the cut, not area: a pixel that touches a cell only at a point or along an
#: edge (the top row of a global raster round a cell with a corner at the pole) gets a piece of about
#: 1e-20 m² from the kernel, 1e-28 of the pixel; the weights themselves are good to about 1e-9 at best.
SLIVER = 1e-9


@dataclass
class Partials:
    """Per-cell partials of one block (or, combined, of the raster), cells sorted."""

    cells: np.ndarray
    covered: np.ndarray  # m² of valid pixels in the cell
    sums: np.ndarray  # (bands, cells): sum of area x value (mean, density sums) or of share x value (count sums)
    low: np.ndarray  # (bands, cells)
    high: np.ndarray  # (bands, cells)
    count: np.ndarray  # valid pixels touching the cell
    classes: dict[str, np.ndarray] = field(default_factory=dict)  # long form: cell, value, area


def shared(pixel: np.ndarray, cell: np.ndarray, area: np.ndarray, total: np.ndarray, cell_m2: float) -> np.ndarray:
    """Which pieces are shared area (more than :data:`SLIVER` of the smaller of their pixel and cell).

    ``total`` is each pixel's whole area (all its pieces), ``cell_m2`` the area of a cell of the level.
    Every statistic is over these pieces only (docs/raster.md, "The modes"): the minimum, maximum and
    count of a cell take only the pixels with positive shared area, as exactextract does.

    Examples
    --------
    >>> shared(np.array([0, 0]), np.array([5, 6]), np.array([1e6, 3e-20]), np.array([1e6]), 5e9).tolist()
    [True, False]
    """
    keep: np.ndarray = area > SLIVER * np.minimum(total[pixel], cell_m2)
    return keep


def _groups(cell: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``np.unique(cell, return_inverse=True)``, in one pass where ``cell`` is sorted already.

    The lat/lng cut hands a block's pieces over cell by cell in id order (depth first through the hierarchy), so
    the sort ``np.unique`` does (most of a block's Python time where cells are the pixels' size) is not needed.

    Examples
    --------
    >>> [a.tolist() for a in _groups(np.array([3, 3, 5, 9, 9], np.uint64))]
    [[3, 5, 9], [0, 0, 1, 2, 2]]
    >>> [a.tolist() for a in _groups(np.array([9, 3, 9], np.uint64))]
    [[3, 9], [1, 0, 1]]
    """
    if cell.size < 2 or not (cell[1:] >= cell[:-1]).all():
        cells, inv = np.unique(cell, return_inverse=True)
        return cells, inv.reshape(-1)
    new = np.empty(cell.size, bool)
    new[0] = True
    np.not_equal(cell[1:], cell[:-1], out=new[1:])
    inv = np.cumsum(new) - 1
    return cell[new], inv


def block_partials(
    pixel: np.ndarray, cell: np.ndarray, area: np.ndarray, total: np.ndarray, values: np.ndarray, mode: str,
    density: bool, split: bool = False,
) -> Partials:
    """Partials of one block: ``values`` (bands, pixels) of the block's pixels, ``total`` each pixel's area.

    With ``split``, pixels were cut into sub-pixels, and a pixel may have several pieces in a cell.
    """
    cells, inv = _groups(cell)
    n = cells.shape[0]
    bands = values.shape[0]
    picked = values[:, pixel].astype(np.float64)
    covered = np.bincount(inv, weights=area, minlength=n)
    if mode == "sum" and not density:  # counts: each pixel's value shared by the area of its pieces
        weight = area / total[pixel]
    else:
        weight = area
    sums = np.vstack([np.bincount(inv, weights=weight * picked[b], minlength=n) for b in range(bands)])
    low = np.full((bands, n), np.inf)
    high = np.full((bands, n), -np.inf)
    if mode in ("min", "max"):
        for b in range(bands):
            np.minimum.at(low[b], inv, picked[b])
            np.maximum.at(high[b], inv, picked[b])
    if split:  # a pixel cut into sub-pixels counts once
        pairs = np.sort(pixel.astype(np.int64) * n + inv)
        pairs = pairs[np.concatenate([[True], pairs[1:] != pairs[:-1]])]
        count = np.bincount(pairs % n, minlength=n)
    else:  # one piece a pixel and cell
        count = np.bincount(inv, minlength=n)
    out = Partials(cells, covered, sums, low, high, count)
    if mode in ("mode", "fractions"):
        out.classes = {"cell": cell, "value": values[0, pixel], "area": area}
    return out


def combine(parts: list[Partials], bands: int) -> Partials:
    """The partials of all blocks added up, per cell."""
    if not parts:
        empty = np.empty((bands, 0))
        return Partials(np.empty(0, np.uint64), np.empty(0), empty, empty, empty, np.empty(0, np.int64),
                        {"cell": np.empty(0, np.uint64), "value": np.empty(0), "area": np.empty(0)})
    if len(parts) == 1:
        one = parts[0]
        return one
    allc = np.concatenate([p.cells for p in parts])
    cells, inv = np.unique(allc, return_inverse=True)
    n = cells.shape[0]
    covered = np.bincount(inv, weights=np.concatenate([p.covered for p in parts]), minlength=n)
    stacked = np.concatenate([p.sums for p in parts], axis=1)
    sums = np.vstack([np.bincount(inv, weights=stacked[b], minlength=n) for b in range(bands)])
    low = np.full((bands, n), np.inf)
    high = np.full((bands, n), -np.inf)
    lows = np.concatenate([p.low for p in parts], axis=1)
    highs = np.concatenate([p.high for p in parts], axis=1)
    for b in range(bands):
        np.minimum.at(low[b], inv, lows[b])
        np.maximum.at(high[b], inv, highs[b])
    count = np.bincount(inv, weights=np.concatenate([p.count for p in parts]), minlength=n).astype(np.int64)
    classes = {}
    if parts[0].classes:
        classes = {k: np.concatenate([p.classes[k] for p in parts]) for k in ("cell", "value", "area")}
    return Partials(cells, covered, sums, low, high, count, classes)
