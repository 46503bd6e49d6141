"""The JS package (js/) against this Python package, under node's own test runner.

`make wasm` builds the C core as WebAssembly (installing clang, lld, wasi-libc and node from Debian where missing),
js/tools/write_fixtures.py writes what this package answers into a temporary folder, and `node --test` runs
js/test/dggs.test.mjs against it: equal ids (on an edge, one of the cells meeting there), centres and boundaries
within 1e-12 degrees, on both projections at every level; and js/test/docs.test.mjs runs the code blocks of
docs/js.md and js/README.md. `make test-js` runs the same from the shell.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def run(cmd: list[str], **kw: object) -> subprocess.CompletedProcess[str]:
    return subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, timeout=900, **kw)  # type: ignore[call-overload]


def test_js_package_matches_python(tmp_path: Path) -> None:
    built = run(["make", "--no-print-directory", "wasm"])
    assert built.returncode == 0, built.stdout + built.stderr
    wrote = run([sys.executable, "js/tools/write_fixtures.py", str(tmp_path)])
    assert wrote.returncode == 0, wrote.stdout + wrote.stderr
    tests = ["js/test/dggs.test.mjs", "js/test/docs.test.mjs"]
    tested = run(["node", "--test", *tests], env={**os.environ, "DGGS_JS_FIXTURES": str(tmp_path)})
    assert tested.returncode == 0, tested.stdout[-20000:] + tested.stderr[-5000:]
    assert "# fail 0" in tested.stdout


def test_js_package_refuses_corrupt_values_with_its_error() -> None:
    """The adversarial suite's corrupt ids, levels, radii, coordinates and options fed to every verb of the JS
    package (js/test/adversarial.test.mjs): an answer or a DggsError, never a TypeError or a trap (issue 32)."""
    built = run(["make", "--no-print-directory", "wasm"])
    assert built.returncode == 0, built.stdout + built.stderr
    tested = run(["node", "--test", "js/test/adversarial.test.mjs"])
    assert tested.returncode == 0, tested.stdout[-20000:] + tested.stderr[-5000:]
    assert "# fail 0" in tested.stdout
