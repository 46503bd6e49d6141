"""A block's pixels cut into their pieces in cells (part of :mod:`dggs.raster` and ``cells_to_raster``).

Pixels bend most near the poles and near the faces' centres, so a block is
measured in tiles of :data:`TILE` pixels a side, each with the points per
edge its own pixels need (:func:`dggs.raster.grid.points_per_edge`); the
tiles wanting the same number are then cut together, one kernel call over
the smallest window holding them (most blocks: one call), so Python's cost is
a block's, not a tile's.  Pixels wider than the kernel takes are cut into
``s x s`` sub-pixels first, ``s`` the block's (which changes no area).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from dggs.index._pixels import latlng_pieces, pixel_pieces
from dggs.raster.grid import (
    TOLERANCE,
    chord_error,
    edge_grid,
    pixel_degrees,
    points_per_edge,
    split_factor,
    tile_chord_errors,
)
from dggs.raster.plane import plane_block_pieces
from dggs.raster.source import Block, RasterSource

__all__ = ["TILE", "MOST_POINTS", "block_pieces", "pixel_block_pieces", "latlng_grid", "grid_window", "scale"]

#: Pixels a side of the tiles a block's points per edge are chosen for.
TILE = 32
#: Edge points one kernel call draws at most (each costs about 64 bytes of the kernel's arrays and 40 of
#: the grid's): a call is a band's tiles of one ``k``, fewer where ``k`` is large.
MOST_POINTS = 2**19


def scale(s: int) -> Any:
    """The affine transform of a grid cut ``s`` times finer."""
    from affine import Affine

    return Affine.scale(1.0 / s)


def _split(src: RasterSource, transformer: Any, block: Block) -> int:
    rows, cols = block.shape
    return split_factor(pixel_degrees(*edge_grid(transformer, src.transform, block.row, block.col, rows, cols, 1), 1))


def _tile_points(src: RasterSource, transformer: Any, block: Block, s: int) -> np.ndarray:
    """Points per edge of each tile of the block (0 for a tile without valid pixels)."""
    rows, cols = block.shape
    tiles_r, tiles_c = -(-rows // TILE), -(-cols // TILE)
    padded = np.zeros((tiles_r * TILE, tiles_c * TILE), bool)
    padded[:rows, :cols] = block.valid
    has = np.asarray(padded.reshape(tiles_r, TILE, tiles_c, TILE).any(axis=(1, 3)))
    transform = src.transform @ scale(s)
    errors = tile_chord_errors(transformer, transform, block.row * s, block.col * s, rows * s, cols * s, TILE * s)
    ks = np.zeros((tiles_r, tiles_c), np.int64)
    for i, j in zip(*np.nonzero(has), strict=True):
        err = errors[i, j]
        if not np.isfinite(err):  # no smooth sampled edge: the tile measured again, finer
            r, c = block.row * s + i * TILE * s, block.col * s + j * TILE * s
            err = chord_error(transformer, transform, r, c, min(TILE * s, rows * s - i * TILE * s),
                              min(TILE * s, cols * s - j * TILE * s))
        ks[i, j] = points_per_edge(err)
    return ks


def grid_window(src: RasterSource, transformer: Any, block: Block, k: int, s: int) -> tuple[
    tuple[np.ndarray, ...], np.ndarray
]:
    """The window's edge points, ``k`` an edge and ``s x s`` sub-pixels a pixel, and the sub-pixels' validity.

    Sub-pixels with a point the CRS cannot put on the globe are left out.
    """
    rows, cols = block.shape
    grid = edge_grid(transformer, src.transform, block.row, block.col, rows, cols, k, s)
    valid = np.repeat(np.repeat(block.valid, s, axis=0), s, axis=1) if s > 1 else block.valid
    hbad, vbad = np.isnan(grid[0]), np.isnan(grid[2])
    if hbad.any() or vbad.any():
        n_rows, n_cols = valid.shape
        top = hbad[:, :-1].reshape(n_rows + 1, n_cols, k).any(axis=2) | hbad[:, k::k]
        side = vbad[:-1].reshape(n_rows, k, n_cols + 1).any(axis=1) | vbad[k::k]
        valid = valid & ~(top[:-1] | top[1:] | side[:, :-1] | side[:, 1:])
        grid = (np.nan_to_num(grid[0]), np.nan_to_num(grid[1]), np.nan_to_num(grid[2]), np.nan_to_num(grid[3]))
    return grid, valid


def latlng_grid(src: RasterSource, transformer: Any, block: Block) -> tuple[float, float, np.ndarray] | None:
    """``(west, dlng, lat_edges)`` of a block of a lat/lng (WGS84) raster, or None for any other grid.

    A north-up or south-up grid of WGS84 longitudes and latitudes, its columns 360 degrees at most; rows past a
    pole by up to a pixel (ERA5's layout) have their corners put on it, as :func:`dggs.raster.grid.lnglat`
    does; a grid farther past is left to the general cut.

    Examples
    --------
    >>> from types import SimpleNamespace
    >>> from affine import Affine
    >>> src = SimpleNamespace(transform=Affine(0.25, 0, 359.75, 0, -0.25, 90.125))
    >>> west, dlng, lat = latlng_grid(src, None, Block(0, 0, np.zeros((1, 2, 3)), np.ones((2, 3), bool)))
    >>> west, dlng, lat.tolist()
    (359.75, 0.25, [90.0, 89.875, 89.625])
    """
    t = src.transform
    rows, cols = block.shape
    if transformer is not None or t.b != 0.0 or t.d != 0.0 or not t.a > 0.0 or t.e == 0.0 or t.a * cols > 360.0:
        return None
    lat = t.f + t.e * (block.row + np.arange(rows + 1, dtype=np.float64))
    if not np.isfinite(lat).all() or (np.abs(lat) > 90.0 + abs(t.e)).any():
        return None
    lat = np.clip(lat, -90.0, 90.0)
    step = np.diff(lat)
    if not ((step < 0).all() or (step > 0).all()):  # a row wholly past a pole
        return None
    return t.c + t.a * block.col, t.a, lat


def block_pieces(src: RasterSource, transformer: Any, block: Block, level: int) -> tuple[
    np.ndarray, np.ndarray, np.ndarray, bool
]:
    """``(pixel, cell, area, split)``: the block's valid pixels' pieces in cells at ``level``.

    ``pixel`` is row-major in the block; ``area`` in m²; ``split`` whether
    pixels were cut into sub-pixels (their pieces then come in sub-pixel
    order, and a pixel may have several in a cell).  A lat/lng raster's
    blocks are cut cell by cell against the pixel grid
    (:func:`dggs.index._pixels.latlng_pieces`: a cell's pieces together),
    a projected raster's cell by cell in its own plane where the rules of
    :mod:`dggs.raster.plane` hold (a cell's pieces together), any other's
    pixel by pixel along the cells' edges (each pixel's pieces together, in
    pixel order).
    """
    grid = latlng_grid(src, transformer, block)
    if grid is not None:
        try:
            pixel, cell, area = latlng_pieces(*grid, block.valid, level, TOLERANCE)
            return pixel, cell, area, False
        except RuntimeError:  # cells far coarser than the pixels: their edges want too many points; cut pixels
            pass
    elif (found := plane_block_pieces(src, transformer, block, level)) is not None:
        return found
    return pixel_block_pieces(src, transformer, block, level)


def pixel_block_pieces(src: RasterSource, transformer: Any, block: Block, level: int) -> tuple[
    np.ndarray, np.ndarray, np.ndarray, bool
]:
    """:func:`block_pieces` pixel by pixel, for any CRS: each pixel cut along the cells' edges in the face planes.

    Each pixel's pieces together, in pixel order.
    """
    rows, cols = block.shape
    s = _split(src, transformer, block)
    ks = _tile_points(src, transformer, block, s)
    found = []
    for i in range(ks.shape[0]):  # a band of tiles at a time: the kernel's arrays grow with the points it draws
        r0, r1 = i * TILE, min(rows, (i + 1) * TILE)
        for k in np.unique(ks[i][ks[i] > 0]):
            tc = np.nonzero(ks[i] == k)[0]
            step = max(1, MOST_POINTS // (2 * int(k) * (TILE * s) ** 2))  # tiles a call: pole tiles draw hundreds
            for first in range(int(tc.min()), int(tc.max()) + 1, step):
                c0, c1 = first * TILE, min(cols, (first + step) * TILE)
                mine = np.repeat(ks[i] == k, TILE)[c0:c1]
                window = Block(block.row + r0, block.col + c0, block.data, block.valid[r0:r1, c0:c1] & mine)
                if not window.valid.any():
                    continue
                grid, valid = grid_window(src, transformer, window, int(k), s)
                pixel, cell, area, _ = pixel_pieces(*grid, int(k), valid, level)
                sub_r, sub_c = np.divmod(pixel, (c1 - c0) * s)  # (sub-)pixels of the window back to the block's
                found.append(((r0 + sub_r // s) * cols + c0 + sub_c // s, cell, area))
    if not found:
        return np.zeros(0, np.int64), np.zeros(0, np.uint64), np.zeros(0), s > 1
    pixel, cell, area = (np.concatenate([f[i] for f in found]) for i in range(3))
    if s > 1 or (pixel.size > 1 and (pixel[1:] < pixel[:-1]).any()):  # sub-pixels, or a band of several k
        order = np.argsort(pixel, kind="stable")  # each pixel's pieces together
        pixel, cell, area = pixel[order], cell[order], area[order]
    return pixel, cell, area, s > 1
