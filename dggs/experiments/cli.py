"""``dggs experiments``: rerun the thesis's experiments."""

from __future__ import annotations

import click


@click.group()
def experiments() -> None:
    """Rerun the thesis's experiments (chapters 4-6) and print their tables."""
