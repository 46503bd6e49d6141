"""The ``dggs`` command line: a thin click layer over the Python API.

Every :class:`dggs.DggsError` becomes a clear message and exit code 1.
"""

from __future__ import annotations

from typing import Any

import click

from dggs.errors import DggsError


class _DggsGroup(click.Group):
    """A click group that turns library errors into clean CLI errors."""

    def invoke(self, ctx: click.Context) -> Any:  # noqa: D102
        try:
            return super().invoke(ctx)
        except DggsError as exc:
            raise click.ClickException(str(exc)) from exc


@click.group(cls=_DggsGroup)
@click.version_option(package_name="dggs")
def main() -> None:
    """dggs: an equal-area triangular discrete global grid (Split 2:6 + Snyder ISEA)."""


def _register() -> None:
    from dggs.cell_cli import cell
    from dggs.experiments.cli import experiments
    from dggs.raster_cli import bin_raster  # click only: the raster package loads when it runs
    from dggs.server.cli import serve  # click only: fastapi is imported when the command runs
    from dggs.storage.cli import register as register_storage

    main.add_command(cell)
    main.add_command(experiments)
    main.add_command(serve)
    main.add_command(bin_raster)
    register_storage(main)  # bin, query, export, plot, info, demo


_register()

if __name__ == "__main__":  # pragma: no cover
    main()
