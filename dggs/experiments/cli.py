"""``dggs experiments``: rerun the thesis's experiments (chapters 4-6).

Examples
--------
>>> from click.testing import CliRunner
>>> r = CliRunner().invoke(experiments, ["subdivision", "--scheme", "1:4", "--levels", "1", "--json"])
>>> r.exit_code
0
"""

from __future__ import annotations

import json
import sys

import click

from dggs.errors import DggsError

__all__ = ["experiments"]


class _ExperimentsGroup(click.Group):
    """Turns library errors into clean CLI errors when run on its own."""

    def invoke(self, ctx: click.Context):  # noqa: D102
        try:
            return super().invoke(ctx)
        except DggsError as exc:
            raise click.ClickException(str(exc)) from exc


def _progress() -> bool:
    return sys.stderr.isatty()


@click.group(cls=_ExperimentsGroup)
def experiments() -> None:
    """Rerun the thesis's experiments (chapters 4-6) and print their tables."""


@experiments.command()
@click.option("--scheme", "scheme", default="2:6", show_default=True,
              help="1:4, 1:9, catmull-clark, 1:3, 1:6, 1:5, 2:6, or dggs (the grid itself).")
@click.option("--levels", type=int, default=None,
              help="Deepest level (default: the thesis's depth for the scheme).")
@click.option("--json", "as_json", is_flag=True, help="Print a JSON list, one object per level.")
@click.option("--densify", type=int, default=64, show_default=True,
              help="Boundary points per edge for --scheme dggs.")
def subdivision(scheme: str, levels: int | None, as_json: bool, densify: int) -> None:
    """Metrics of Tables 6.1-6.7 for one scheme, level by level."""
    from dggs.experiments.schemes import get_scheme, run_scheme
    from dggs.experiments.tables import format_dggs_row, format_scheme

    if scheme.lower() == "dggs":
        from dggs.experiments.dggs_grid import dggs_grid_metrics

        rows = dggs_grid_metrics(5 if levels is None else levels, densify, _progress())
        text = format_dggs_row(rows, densify)
    else:
        s = get_scheme(scheme)
        rows = run_scheme(s, s.thesis_levels if levels is None else levels, _progress())
        text = format_scheme(s.key, rows)
    if as_json:
        click.echo(json.dumps([r.to_json() for r in rows], indent=1))
    else:
        click.echo(text)


@experiments.command()
@click.option("--quick", is_flag=True, help="Shallower runs (chapter 4 too, if present).")
@click.option("--dggs-levels", type=int, default=5, show_default=True,
              help="Levels for the dggs grid row (0 skips it).")
def tables(quick: bool, dggs_levels: int) -> None:
    """All tables of chapters 5-6 (and 4, if available) beside the thesis's values."""
    from dggs.experiments.chapter5 import format_table_5_1
    from dggs.experiments.tables import format_all_tables, format_dggs_row, run_all

    try:
        from dggs.experiments.chapter4 import chapter4_tables  # written by another engineer
    except ImportError:
        chapter4_tables = None
    if chapter4_tables is not None:
        click.echo(chapter4_tables(quick))
        click.echo()
    click.echo(format_table_5_1())
    click.echo()
    depth = (lambda k: min(3, {"1:9": 2, "1:6": 3}.get(k, 3))) if quick else None
    click.echo(format_all_tables(run_all(depth, _progress())))
    if dggs_levels:
        from dggs.experiments.dggs_grid import dggs_grid_available, dggs_grid_metrics

        click.echo()
        if dggs_grid_available():
            click.echo(format_dggs_row(dggs_grid_metrics(dggs_levels, 64, _progress()), 64))
        else:
            click.echo("dggs grid row skipped: dggs.cell_to_boundary is not available yet")


@experiments.command()
@click.argument("outdir", type=click.Path(file_okay=False))
@click.option("--scheme", "schemes", multiple=True,
              help="Scheme(s) to draw (default: all seven).")
@click.option("--levels", type=int, default=None, help="Deepest level (default: thesis depth, capped at 5).")
def figures(outdir: str, schemes: tuple[str, ...], levels: int | None) -> None:
    """Write Figures 6.14-6.28 analogues (area highlighting, error histograms) as PNG."""
    from dggs.experiments.figures import write_figures

    for path in write_figures(outdir, schemes or None, levels, _progress()):
        click.echo(path)


def _register_chapter4() -> None:
    from dggs.experiments.chapter4 import snyder_command

    experiments.add_command(snyder_command, "snyder")


_register_chapter4()
