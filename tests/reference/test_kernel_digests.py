"""The C core gives the numba kernel's ids, centres and boundaries bit for bit (issue 31).

``fixtures/kernel_digests.json`` holds the SHA-256 digests written by ``libdggs/tools/freeze_kernel.py --write`` at
the last numba commit: ids of 10,024,708 points (uniform, plus poles, +-180, the icosahedron's vertex latitudes,
its face edges and offsets of 1e-12 and 1e-9 degrees) at every level 0-28, the centres of the first 400,000 points'
cells and their boundaries (densify 0 and 3), on ISEA and on IVEA.  A check recomputes them with the current build.

Refrozen once since (issue 34), when the core began to carry its own sin, cos, atan2, hypot and asin
(libdggs/src/dmath.c) so that its WebAssembly build gives the same ids: ``libdggs/tools/tie_check.py`` compared
the full arrays of the two builds (the old build's arrays reproduce all 233 digests frozen at the numba commit):
4,592 of the 581,433,064 point-levels changed id, every one an exact tie (moved 1e-13 radians toward either
cell's centre, it gets that cell on both builds), and the centres and boundaries of the cells that kept their
ids moved by at most 1.2e-13 degrees (latitude, and longitude as arc). The file's ``note`` says the same.
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
DIGESTS = ROOT / "tests" / "reference" / "fixtures" / "kernel_digests.json"


def _freeze():
    spec = importlib.util.spec_from_file_location("freeze_kernel", ROOT / "libdggs" / "tools" / "freeze_kernel.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_points_are_the_frozen_ones():
    """The inputs themselves: a change of the point generator would make every digest differ for nothing."""
    import hashlib
    import json

    import numpy as np

    lat, lng = _freeze().points()
    assert lat.size == json.loads(DIGESTS.read_text())["points"] >= 10_000_000
    got = hashlib.sha256(np.ascontiguousarray(np.stack([lat, lng])).tobytes()).hexdigest()
    assert got == json.loads(DIGESTS.read_text())["digests"]["points"]


@pytest.mark.slow
def test_ids_centres_and_boundaries_equal_the_frozen_ones(capsys):
    status = _freeze().main(["--check", str(DIGESTS)])
    out = capsys.readouterr().out
    assert status == 0, out
    assert "233 of 233 digests equal" in out
