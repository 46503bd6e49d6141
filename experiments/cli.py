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
    """Turns library errors into clean CLI errors when run on its own; loads ``snyder`` (chapter 4) when asked."""

    def list_commands(self, ctx: click.Context) -> list[str]:  # noqa: D102
        return sorted({*super().list_commands(ctx), "snyder"})

    def get_command(self, ctx: click.Context, cmd_name: str):  # noqa: D102
        if cmd_name == "snyder" and cmd_name not in self.commands:
            from dggs.experiments.chapter4 import snyder_command

            self.add_command(snyder_command, "snyder")
        return super().get_command(ctx, cmd_name)

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
              help="1:4, 1:9, catmull-clark, 1:3, 1:6, 1:5, 2:6, latlng (chapter 7's equal-area "
                   "lat-lng grid), or dggs (the grid itself).")
@click.option("--levels", type=int, default=None,
              help="Deepest level (default: the thesis's depth for the scheme).")
@click.option("--json", "as_json", is_flag=True, help="Print a JSON list, one object per level.")
@click.option("--densify", type=int, default=64, show_default=True,
              help="Boundary points per edge for --scheme dggs.")
@click.option("--variant", type=click.Choice(["dggs", "thesis"]), default="dggs", show_default=True,
              help="thesis: the thesis's own rule (2:6 placement, Catmull-Clark and 1:5 as the thesis computed "
                   "them); dggs: ours. The same for 1:4, 1:9, 1:3, 1:6.")
def subdivision(scheme: str, levels: int | None, as_json: bool, densify: int, variant: str) -> None:
    """Metrics of Tables 6.1-6.7 for one scheme, level by level (each cell marked against the thesis)."""
    from dggs.experiments.schemes import get_scheme, run_scheme
    from dggs.experiments.tables import format_dggs_row, format_scheme

    if scheme.lower() == "dggs":
        from dggs.experiments.dggs_grid import dggs_grid_metrics

        rows = dggs_grid_metrics(5 if levels is None else levels, densify, _progress())
        text = format_dggs_row(rows, densify)
    else:
        s = get_scheme(scheme, variant)
        rows = run_scheme(s, s.thesis_levels if levels is None else levels, _progress())
        text = format_scheme(s.key, rows, variant)
    if as_json:
        click.echo(json.dumps([r.to_json() for r in rows], indent=1))
    else:
        click.echo(text)


@experiments.command()
@click.option("--quick", is_flag=True, help="Shallower runs (chapter 4 too, if present).")
@click.option("--dggs-levels", type=int, default=5, show_default=True,
              help="Levels for the dggs grid row (0 skips it).")
def tables(quick: bool, dggs_levels: int) -> None:
    """All tables of chapters 4-6 beside the thesis's values; chapter 6 with the thesis's rules and dggs's."""
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
    from dggs.experiments.latlng_grid import spherical_cell_errors
    from dggs.experiments.schemes import run_scheme

    ours = run_all(depth, _progress())
    latlng_levels = 3 if quick else 7
    ours["latlng"] = run_scheme("latlng", latlng_levels, _progress())
    click.echo(format_all_tables(ours, run_all(depth, _progress(), "thesis")))
    click.echo()
    worst = max(float(abs(spherical_cell_errors(2 ** (k + 1), 2 ** (k + 2))).max()) for k in range(latlng_levels + 1))
    click.echo(
        "latlng: chapter 7's equal-area lat-lng grid, sin(lat_k) = -1 + 2k/n, level L = 2^(L+1) bands x "
        f"2^(L+2) meridians.\n  Its spherical cells are exactly equal (max error {worst:.1e} % by Archimedes' "
        "zone formula);\n  the rows above measure its polyhedral approximation (flat quads, polar triangles), "
        "as chapter 6 measures every scheme."
    )
    if dggs_levels:
        from dggs.experiments.dggs_grid import dggs_grid_metrics

        click.echo()
        click.echo(format_dggs_row(dggs_grid_metrics(dggs_levels, 64, _progress()), 64))


@experiments.command()
@click.argument("outdir", type=click.Path(file_okay=False))
@click.option("--chapter", "chapter", type=click.Choice(["3", "4", "5", "6", "all"]), default=None,
              help="Figures of one chapter (default: all; only 6 when --scheme is given).")
@click.option("--scheme", "schemes", multiple=True,
              help="Chapter 6: scheme(s) to draw (default: all seven, plus Figure 6.18).")
@click.option("--levels", type=int, default=None,
              help="Chapter 6: deepest level (default: the thesis's depth; globes capped at 5).")
@click.option("--variant", type=click.Choice(["dggs", "thesis"]), default="thesis", show_default=True,
              help="Chapter 6 rules for 2:6, Catmull-Clark, 1:5: the thesis's (files *_thesis.png) or dggs's"
              " (*_dggs.png); each figure names its rule.")
@click.option("--quick", is_flag=True, help="Coarser samples and chapter 6 to level 3 (a few seconds).")
def figures(outdir: str, chapter: str | None, schemes: tuple[str, ...], levels: int | None, variant: str,
            quick: bool) -> None:
    """Write the thesis's figures as PNG: chapters 3 (3.13-3.14), 4 (4.1-4.5), 5 (5.1-5.22), 6 (6.14-6.28)."""
    from dggs.experiments.figures import CHAPTERS, write_all

    if chapter is None:
        chapter = "6" if schemes else "all"
    chapters = CHAPTERS if chapter == "all" else (chapter,)
    for path in write_all(outdir, chapters, schemes or None, levels, _progress(), variant, quick):
        click.echo(path)


@experiments.command()
@click.option("--level", type=int, default=5, show_default=True, help="Level whose cells' edge ratios are measured.")
@click.option("--samples", type=int, default=120, show_default=True,
              help="Barycentric steps a side of the natural triangle's sample (about samples**2 / 2 points).")
@click.option("--json", "as_json", is_flag=True, help="Print a JSON list, one object per projection.")
def projections(level: int, samples: int, as_json: bool) -> None:
    """Angular distortion of Snyder's ISEA and the vertex-oriented great circle IVEA side by side (thesis §3.1.7)."""
    from dggs.experiments.projections import distortion_table, format_table

    rows = distortion_table(level, samples)
    if as_json:
        click.echo(json.dumps(rows, indent=1))
        return
    click.echo(format_table(rows))
    click.echo("ω: maximum angular deformation 2 asin((a - b) / (a + b)) of the Tissot indicatrix over the sample"
               " (Snyder 1992 gives ISEA's supremum, 17.27°, at the face centre);\nedge ratio: longest over"
               " shortest geodesic corner-to-corner edge of each cell (2 for the planar 30-60-90 cell).")
