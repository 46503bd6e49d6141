"""``dggs cell``: cell-id queries from the command line."""

from __future__ import annotations

import click


@click.group()
def cell() -> None:
    """Look up cells: from a point, info about an id, boundaries."""
