"""Rasters on equal-area cells: a synthetic elevation and land-cover raster over Europe, binned and drawn.

Writes two GeoTIFFs in EPSG:3035 (Lambert azimuthal equal-area, Europe), 10 km pixels:

* ``europe_elevation.tif``: metres above sea level, float32, a smooth relief (an Alpine arc, uplands,
  a lowland plain) with noise, the sea as nodata;
* ``europe_landcover.tif``: uint8 classes derived from it (1 water, 2 cropland, 3 forest, 4 grassland,
  5 rock and ice), noisy at the class edges as real land cover is;

then bins them into level-8 cells (1,944 km² each) with ``dggs.raster.raster_to_cells`` and draws each
raster beside its cells (mean elevation; the land-cover mode and the forest share) into PNGs.

Run from the repository: ``python examples/raster_example.py`` writes the rasters into examples/data/ and
the figures into docs/ (docs/raster.md shows them); ``--data DIR --figures DIR`` writes elsewhere.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
import rasterio
from rasterio.transform import from_origin

import dggs
from dggs.raster import raster_to_cells

ROOT = Path(__file__).resolve().parents[1]
CRS = "EPSG:3035"
PIXEL = 10_000.0  # metres
ROWS, COLS = 120, 160
TRANSFORM = from_origin(3_400_000.0, 3_300_000.0, PIXEL, PIXEL)  # from the Massif Central to the Vistula
NODATA = -9999.0
CLASSES = {1: "water", 2: "cropland", 3: "forest", 4: "grassland", 5: "rock and ice"}
COLOURS = {1: "#3b7dd8", 2: "#f2d16b", 3: "#2f7d32", 4: "#9ccc65", 5: "#e0e0e0"}


def _smooth_noise(rng: np.random.Generator, scale: float, modes: int = 40) -> np.ndarray:
    """A random field of wavelength about ``scale`` pixels: a sum of random plane waves."""
    rows, cols = np.mgrid[0:ROWS, 0:COLS].astype(np.float64)
    field = np.zeros((ROWS, COLS))
    for _ in range(modes):
        angle, phase = rng.uniform(0, 2 * np.pi, 2)
        k = 2 * np.pi / (scale * rng.uniform(0.7, 1.4))
        field += np.cos(k * (np.cos(angle) * cols + np.sin(angle) * rows) + phase)
    return field / np.sqrt(modes / 2)


def elevation(seed: int = 19) -> np.ndarray:
    """Metres above sea level, NaN at sea: a plain in the north, uplands, an Alpine arc in the south."""
    rng = np.random.default_rng(seed)
    rows, cols = np.mgrid[0:ROWS, 0:COLS].astype(np.float64)
    bend = 96 - 26 * np.exp(-(((cols - 10) / 30.0) ** 2)) + 4 * _smooth_noise(rng, 25)  # the arc bends north-west
    along = np.exp(-(((cols - 75) / 60.0) ** 4))
    alps = along * np.exp(-(((rows - bend) / 9.0) ** 2)) * (1 + 0.25 * _smooth_noise(rng, 5))
    uplands = (0.5 + 0.5 * np.tanh((rows - 52 + 8 * _smooth_noise(rng, 20)) / 8.0)) * (1 + 0.5 * _smooth_noise(rng, 12))
    relief = 60 + 2500 * np.clip(alps, 0, None) + 480 * np.clip(uplands, 0, None) + 50 * _smooth_noise(rng, 14)
    relief += 12 * rng.standard_normal((ROWS, COLS))
    coast = rows - (26 - 0.28 * cols) + 5 * _smooth_noise(rng, 30)  # the North Sea in the north-west
    return np.where(coast < 0, np.nan, np.maximum(relief, 1.0))


def landcover(height: np.ndarray, seed: int = 20) -> np.ndarray:
    """Classes from the elevation, with noise at their edges."""
    rng = np.random.default_rng(seed)
    h = np.nan_to_num(height, nan=-1.0) + 150 * _smooth_noise(rng, 6) + 40 * rng.standard_normal(height.shape)
    out = np.full(height.shape, 2, dtype=np.uint8)
    out[(h > 350) | (_smooth_noise(rng, 10) > 1.3)] = 3
    out[h > 1700] = 4
    out[h > 2500] = 5
    out[(_smooth_noise(rng, 7) > 2.3) & (h < 700)] = 1  # lakes
    out[np.isnan(height)] = 1
    return out


def write(path: Path, data: np.ndarray, nodata: float | None) -> Path:
    with rasterio.open(path, "w", driver="GTiff", height=ROWS, width=COLS, count=1, dtype=data.dtype, crs=CRS,
                       transform=TRANSFORM, nodata=nodata, compress="deflate") as dst:
        dst.write(data[None])
    return path


def _cells(ax, cells: np.ndarray, colours, **kwargs) -> None:
    """Draw cells (int ids) in EPSG:3035 metres."""
    import matplotlib.collections as mc
    from pyproj import Transformer

    to = Transformer.from_crs("EPSG:4326", CRS, always_xy=True)
    shapes = []
    for polygon in dggs.cell_to_polygon(cells, densify=8):
        lng, lat = np.asarray(polygon.exterior.coords).T
        x, y = to.transform(lng, lat)
        shapes.append(np.column_stack([x, y]) / 1000.0)
    ax.add_collection(mc.PolyCollection(shapes, facecolors=colours, edgecolors="white", linewidths=0.15, **kwargs))


def _frame(ax, title: str) -> None:
    left, top = TRANSFORM.c / 1000.0, TRANSFORM.f / 1000.0
    ax.set_xlim(left, left + COLS * PIXEL / 1000.0)
    ax.set_ylim(top - ROWS * PIXEL / 1000.0, top)
    ax.set_aspect("equal")
    ax.set_title(title, fontsize=10)
    ax.set_xlabel("EPSG:3035 easting (km)", fontsize=8)
    ax.tick_params(labelsize=7)


def figures(elevation_tif: Path, landcover_tif: Path, out: Path, level: int = 8) -> list[Path]:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import ListedColormap, Normalize

    extent = (TRANSFORM.c / 1000.0, (TRANSFORM.c + COLS * PIXEL) / 1000.0,
              (TRANSFORM.f - ROWS * PIXEL) / 1000.0, TRANSFORM.f / 1000.0)
    with rasterio.open(elevation_tif) as src:
        height = src.read(1, masked=True)
    with rasterio.open(landcover_tif) as src:
        cover = src.read(1)
    written = []

    mean = raster_to_cells(elevation_tif, level, mode="mean")
    norm, cmap = Normalize(-900, 3400), plt.get_cmap("terrain")  # from green at sea level
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.6), constrained_layout=True)
    a.imshow(height, extent=extent, cmap=cmap, norm=norm, interpolation="nearest")
    _frame(a, f"elevation raster: {ROWS} x {COLS} pixels of 10 km")
    _cells(b, mean["cell_id"].to_numpy().astype(np.uint64), cmap(norm(mean["value"].to_numpy())),
           alpha=None)
    _frame(b, f'mode="mean": {len(mean):,} level-{level} cells of {dggs.cell_area(level, "km^2"):,.0f} km²')
    fig.colorbar(plt.cm.ScalarMappable(norm=norm, cmap=cmap), ax=(a, b), shrink=0.8, label="metres")
    written.append(out / "raster-mean.png")
    fig.savefig(written[-1], dpi=90)
    plt.close(fig)

    mode = raster_to_cells(landcover_tif, level, mode="mode")
    shares = raster_to_cells(landcover_tif, level, mode="fractions")
    classes = ListedColormap([COLOURS[k] for k in sorted(COLOURS)])
    fig, (a, b, c) = plt.subplots(1, 3, figsize=(15, 4.4), constrained_layout=True)
    a.imshow(cover, extent=extent, cmap=classes, vmin=0.5, vmax=5.5, interpolation="nearest")
    _frame(a, "land-cover raster (5 classes)")
    _cells(b, mode["cell_id"].to_numpy().astype(np.uint64), [COLOURS[int(v)] for v in mode["value"]])
    _frame(b, 'mode="mode": the class covering most of each cell')
    forest, greens = shares["class_3"].to_numpy(), plt.get_cmap("Greens")
    _cells(c, shares["cell_id"].to_numpy().astype(np.uint64), greens(forest))
    _frame(c, 'mode="fractions": share of forest (class_3)')
    fig.colorbar(plt.cm.ScalarMappable(norm=Normalize(0, 1), cmap=greens), ax=c, shrink=0.8, label="forest share")
    handles = [plt.Rectangle((0, 0), 1, 1, color=COLOURS[k]) for k in sorted(COLOURS)]
    a.legend(handles, [CLASSES[k] for k in sorted(CLASSES)], fontsize=7, loc="lower left")
    written.append(out / "raster-classes.png")
    fig.savefig(written[-1], dpi=80)
    plt.close(fig)
    return written


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--data", type=Path, default=ROOT / "examples" / "data", help="where the rasters go")
    parser.add_argument("--figures", type=Path, default=ROOT / "docs", help="where the PNGs go")
    args = parser.parse_args()
    height = elevation()
    elevation_tif = write(args.data / "europe_elevation.tif", np.nan_to_num(height, nan=NODATA).astype(np.float32),
                          NODATA)
    landcover_tif = write(args.data / "europe_landcover.tif", landcover(height), None)
    print(f"wrote {elevation_tif} and {landcover_tif}")
    for path in figures(elevation_tif, landcover_tif, args.figures):
        print(f"wrote {path}")


if __name__ == "__main__":
    main()
