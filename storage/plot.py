"""Draw cells on an equal-area (Mollweide) world map, coloured by value.

Needs matplotlib (the ``plot`` extra); it is imported only when a map is
drawn.  Uses matplotlib's object API (no pyplot), so it is safe in servers
and tests.
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from typing import Any

import numpy as np

import dggs
from dggs.errors import DggsError

__all__ = ["plot_cells"]

#: The map projection: Mollweide, equal-area like the grid itself.
PROJECTION = "+proj=moll +lon_0=0 +datum=WGS84 +units=m +no_defs"

def _import_matplotlib() -> Any:
    try:
        import matplotlib  # noqa: F401
    except ImportError as exc:
        raise DggsError(
            "drawing maps needs matplotlib: pip install 'dggs[plot]'"
        ) from exc
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    return Figure, FigureCanvasAgg

def land_rings() -> list[np.ndarray] | None:
    """The land's outer rings (lng/lat) from the web map's Natural Earth countries, or None where they are absent.

    The file is world-atlas's ``countries-50m.json`` (TopoJSON, its ``land`` layer), which ``make static`` or a
    built wheel puts in ``dggs/server/static/vendor``; GDAL reads TopoJSON, through pyogrio (the ``vector``
    extra). Without either, maps are drawn without land (and say so under the map).
    """
    from pathlib import Path

    file = Path(dggs.__file__).parent / "server" / "static" / "vendor" / "world-atlas" / "countries-50m.json"
    if not file.is_file():
        return None
    try:
        import pyogrio
    except ImportError:
        return None
    try:
        geometries = pyogrio.read_dataframe(file, layer="land", read_geometry=True).geometry
    except Exception:  # noqa: BLE001 - a basemap only: a broken file leaves the map without land
        return None
    return [piece for g in geometries for ring in _rings(g) for piece in _split_at_antimeridian(ring)]


def _split_at_antimeridian(ring: np.ndarray) -> list[np.ndarray]:
    """A lng/lat ring that crosses 180 degrees as the rings of its parts on either side (one ring if none).

    TopoJSON rings run across the antimeridian (179.9 to -179.9); drawn as they are, their edges streak across
    the whole map. The ring is unwrapped to continuous longitudes and cut by the map's -180..180 window,
    shifted a turn either way. A ring around a pole (Antarctica: it does not close in unwrapped longitude) is
    left as it is.
    """
    if np.all(np.abs(np.diff(ring[:, 0])) <= 180):
        return [ring]
    lng = np.degrees(np.unwrap(np.radians(ring[:, 0])))
    if abs(lng[-1] - lng[0]) > 1e-9:
        return [ring]
    import shapely
    from shapely.geometry import Polygon, box

    shape = shapely.make_valid(Polygon(np.column_stack([lng, ring[:, 1]])))
    window = box(-180, -90, 180, 90)
    pieces = []
    for shift in (-360.0, 0.0, 360.0):
        cut = shapely.intersection(shapely.transform(shape, lambda xy, d=shift: xy + (d, 0.0)), window)
        pieces += [np.asarray(p.exterior.coords) for p in shapely.get_parts(cut)
                   if p.geom_type == "Polygon" and p.area > 0]
    return pieces


def _rings(geometry: Any) -> list[np.ndarray]:
    polys = getattr(geometry, "geoms", [geometry])
    return [np.asarray(p.exterior.coords) for p in polys]

def plot_cells(
    cells: Sequence[str],
    values: Sequence[float],
    path: str | os.PathLike[str],
    *,
    title: str = "",
    label: str = "",
    log: bool | None = None,
    cmap: str = "viridis",
    points: tuple[Sequence[float], Sequence[float]] | None = None,
    dpi: int = 150,
    projection: str = "ISEA",
    land: bool | None = None,
) -> bool:
    """Draw ``cells`` coloured by ``values`` on a Mollweide world map, save as PNG.

    Parameters
    ----------
    cells : sequence of str
        Cell ids (any levels).
    values : sequence of float
        One value per cell (None/NaN cells are drawn grey).
    path : str or Path
        PNG file to write.
    title, label : str
        Map title and colour-bar label.
    log : bool, optional
        Logarithmic colour scale; default: when positive values span more
        than three orders of magnitude.
    cmap : str
        A matplotlib colormap name.
    points : (lat, lng) arrays, optional
        Points to draw as faint dots under the cells (e.g. the raw data).
    dpi : int, default 150
        Resolution of the PNG.
    projection : {"ISEA", "IVEA"}, default "ISEA"
        The grid the cells are drawn on (a store's ``projection``).
    land : bool, optional
        Draw the land (Natural Earth 1:50m, :func:`land_rings`) under the cells: ``None`` (default) where it is
        installed, ``False`` never, ``True`` or fail.

    Returns
    -------
    bool
        Whether land was drawn (the footer says so too).

    Raises
    ------
    DggsError
        If matplotlib is missing, or ``land=True`` and the land is not installed.

    Examples
    --------
    >>> import os, tempfile
    >>> out = os.path.join(tempfile.mkdtemp(), "map.png")
    >>> plot_cells(["A0", "B3"], [1.0, 10.0], out, title="two cells", land=False)
    False
    >>> os.path.getsize(out) > 0
    True
    """
    Figure, FigureCanvasAgg = _import_matplotlib()
    from matplotlib.collections import PolyCollection
    from matplotlib.colors import LogNorm, Normalize
    from pyproj import Transformer

    to_map = Transformer.from_crs("EPSG:4326", PROJECTION, always_xy=True)
    cells = [str(c) for c in cells]
    vals = np.array([np.nan if v is None else float(v) for v in values], dtype=float)
    polys: list[np.ndarray] = []
    poly_vals: list[float] = []
    if cells:
        levels = {len(c) - 1 for c in cells}
        densify = 8 if min(levels) < 4 else 2
        geoms = dggs.Grid(projection).cell_to_polygon(np.asarray(cells), densify=densify)
        for geometry, value in zip(np.atleast_1d(geoms), vals, strict=True):
            for ring in _rings(geometry):
                x, y = to_map.transform(ring[:, 0], ring[:, 1])
                polys.append(np.column_stack([x, y]))
                poly_vals.append(value)
    pv = np.asarray(poly_vals, dtype=float)
    finite = pv[np.isfinite(pv)]
    positive = finite[finite > 0]
    if log is None:  # skewed, (nearly) all positive values read better on a log scale
        log = (
            len(positive) > 1
            and len(positive) >= 0.95 * len(finite)
            and positive.max() / positive.min() > 1e3
        )
    if len(finite) == 0:
        norm = Normalize(0, 1)
    elif log:  # from the 2nd percentile up: a few tiny outliers would wash out the rest
        norm = LogNorm(max(float(np.percentile(positive, 2)), 1e-12), positive.max(), clip=True)
    else:
        norm = Normalize(finite.min(), finite.max() if finite.max() > finite.min() else finite.min() + 1)

    fig = Figure(figsize=(12, 6.6), dpi=dpi)
    FigureCanvasAgg(fig)
    ax = fig.add_axes((0.02, 0.15, 0.96, 0.77))
    ax.set_aspect("equal")
    ax.axis("off")

    # Globe outline, ocean and graticule.
    t = np.linspace(-90, 90, 181)
    ox, oy = to_map.transform(np.r_[np.full_like(t, -180), np.full_like(t, 180)[::-1]], np.r_[t, t[::-1]])
    ax.fill(ox, oy, color="#eef3f8", zorder=0)
    ax.plot(ox, oy, color="#8090a0", lw=0.8, zorder=3)
    for lon in range(-150, 181, 30):
        gx, gy = to_map.transform(np.full_like(t, lon), t)
        ax.plot(gx, gy, color="#c8d2dc", lw=0.4, zorder=1)
    s = np.linspace(-180, 180, 361)
    for lat in range(-60, 61, 30):
        gx, gy = to_map.transform(s, np.full_like(s, lat))
        ax.plot(gx, gy, color="#c8d2dc", lw=0.4, zorder=1)

    rings = land_rings() if land is not False else None
    if land and rings is None:
        raise DggsError("land=True, but the land outlines are not installed: they need pyogrio ('dggs[vector]') "
                        "and the web map's world-atlas files (make static)")
    for ring in rings or ():
        lx, ly = to_map.transform(ring[:, 0], ring[:, 1])
        ax.fill(lx, ly, facecolor="#dcd8cc", edgecolor="#9a9484", lw=0.3, zorder=0.5)

    if points is not None and len(points[0]):
        px, py = to_map.transform(np.asarray(points[1], dtype=float), np.asarray(points[0], dtype=float))
        ax.scatter(px, py, s=0.2, color="#6b7785", alpha=0.35, linewidths=0, zorder=1.5)

    if polys:
        import matplotlib

        colours = matplotlib.colormaps[cmap].with_extremes(bad="#b0b0b0")
        collection = PolyCollection(polys, cmap=colours, norm=norm, edgecolors="face", linewidths=0.15, zorder=2)
        shown = np.where(np.isfinite(pv), pv, np.nan)
        if log:  # zero and below: the bottom colour
            shown = np.where(shown > 0, shown, float(norm.vmin or 0.0))
        collection.set_array(np.ma.masked_invalid(shown))
        ax.add_collection(collection)
        cax = fig.add_axes((0.3, 0.105, 0.4, 0.025))
        bar = fig.colorbar(collection, cax=cax, orientation="horizontal")
        bar.set_label(label + (" (log scale)" if log else ""))
    pad = 2.0e5
    ax.set_xlim(min(ox) - pad, max(ox) + pad)
    ax.set_ylim(min(oy) - pad, max(oy) + pad)
    if title:
        fig.suptitle(title, fontsize=13, y=0.97)
    if cells:
        level = min(len(c) - 1 for c in cells)
        area = float(dggs.cell_area(level, unit="km^2"))
        fig.text(
            0.5,
            0.015,
            f"{len(cells):,} cells, level {level} (each {area:,.0f} km\u00b2, equal area); Mollweide projection; "
            + ("land: Natural Earth 1:50m" if rings else "no land drawn (needs dggs[vector] and make static)"),
            ha="center",
            fontsize=8,
            color="#506070",
        )
    from .atomic import atomic_path

    with atomic_path(path, suffix=".png") as tmp:
        fig.savefig(tmp, dpi=dpi, format="png")
    return bool(rings)
