"""``dggs cell``: cell-id queries from the command line."""

from __future__ import annotations

import json

import click


@click.group()
def cell() -> None:
    """Look up cells: from a point, info about an id, boundaries."""


@cell.command("from-latlng", context_settings={"ignore_unknown_options": True})
@click.argument("lat", type=float)
@click.argument("lng", type=float)
@click.option("--level", "-l", type=int, required=True, help="Subdivision level (0..MAX_LEVEL).")
def from_latlng(lat: float, lng: float, level: int) -> None:
    """Print the id of the cell at LEVEL holding the point LAT LNG (WGS84 degrees).

    Example: dggs cell from-latlng 51.05 -114.07 --level 9
    """
    import dggs

    click.echo(dggs.latlng_to_cell(lat, lng, level))


@cell.command("info")
@click.argument("cell_id")
@click.option("--json", "as_json", is_flag=True, help="Print JSON instead of text.")
def info(cell_id: str, as_json: bool) -> None:
    """Print level, face, centre, area, parent, children and neighbours of CELL_ID."""
    import dggs

    level = dggs.get_level(cell_id)
    lat, lng = dggs.cell_to_latlng(cell_id)
    data = {
        "cell": cell_id,
        "level": level,
        "face": dggs.get_face(cell_id),
        "centre": {"lat": lat, "lng": lng},
        "area_km2": dggs.cell_area(cell_id, "km^2"),
        "parent": dggs.cell_to_parent(cell_id) if level > 0 else None,
        "children": dggs.cell_to_children(cell_id) if level < dggs.MAX_LEVEL else [],
        "neighbors": dggs.edge_neighbors(cell_id),
    }
    if as_json:
        click.echo(json.dumps(data, indent=2))
        return
    for key, value in data.items():
        if key == "centre":
            value = f"{lat:.8f}, {lng:.8f}"
        elif isinstance(value, list):
            value = " ".join(value)
        click.echo(f"{key:>10}: {value}")


@cell.command("boundary")
@click.argument("cell_id")
@click.option("--densify", type=int, default=None, help="Points added along each curved edge.")
@click.option("--geojson", "as_geojson", is_flag=True, help="Print a GeoJSON Feature (lng, lat).")
def boundary(cell_id: str, densify: int | None, as_geojson: bool) -> None:
    """Print the corners of CELL_ID as lat lng lines (or a GeoJSON Feature)."""
    import dggs

    if as_geojson:
        fc = dggs.cells_to_geojson([cell_id], densify=densify)
        click.echo(json.dumps(fc["features"][0]))
        return
    for lat, lng in dggs.cell_to_boundary(cell_id, densify=densify or 0):
        click.echo(f"{lat:.10f} {lng:.10f}")


@cell.command("levels")
@click.option("--max-level", type=int, default=20, show_default=True)
def levels(max_level: int) -> None:
    """Print the level table: cell count, area and edge lengths."""
    import dggs

    table = dggs.level_table(max_level)  # a bad level fails before anything is printed
    click.echo(f"{'level':>5} {'cells':>26} {'area':>16} {'short edge':>12}")
    for row in table:
        click.echo(
            f"{row['level']:>5} {row['cells']:>26,} {_area(row['area_m2']):>16} {_length(row['short_edge_m']):>12}"
        )


def _area(m2: float) -> str:
    if m2 >= 1e6:
        return f"{m2 / 1e6:,.3f} km^2"
    if m2 >= 1e-2:
        return f"{m2:,.4f} m^2"
    return f"{m2 * 1e4:.4f} cm^2"


def _length(m: float) -> str:
    if m >= 1e3:
        return f"{m / 1e3:,.3f} km"
    if m >= 1:
        return f"{m:.3f} m"
    return f"{m * 100:.3f} cm"
