"""The experiments are research code beside the library (issue 13): ``import dggs`` and the geometry kernel
load none of them, and the ``dggs experiments`` CLI group still works (registered from dggs.cli, loaded lazily)."""

from __future__ import annotations

import subprocess
import sys

from click.testing import CliRunner


def test_import_dggs_loads_no_experiments():
    code = (
        "import dggs, dggs.geometry, dggs.geometry.snyder, sys; "
        "bad = [m for m in sys.modules if 'experiments' in m]; assert not bad, bad"
    )
    subprocess.run([sys.executable, "-c", code], check=True)


def test_the_experiments_live_outside_the_dggs_folder():
    from pathlib import Path

    import dggs
    import dggs.experiments

    core = Path(dggs.__file__).resolve().parent
    here = Path(dggs.experiments.__file__).resolve().parent
    assert here.name == "experiments" and core not in here.parents


def test_cli_group_is_registered():
    from dggs.cli import main

    res = CliRunner().invoke(main, ["experiments", "--help"])
    assert res.exit_code == 0 and "subdivision" in res.output


def test_the_cli_loads_chapter_4_only_when_its_command_runs():
    code = (
        "import dggs.cli, sys; assert 'dggs.experiments.chapter4' not in sys.modules; "
        "from dggs.experiments.cli import experiments; import click; "
        "ctx = click.Context(experiments); assert experiments.get_command(ctx, 'snyder').name == 'snyder'; "
        "assert 'dggs.experiments.chapter4' in sys.modules"
    )
    subprocess.run([sys.executable, "-c", code], check=True)
