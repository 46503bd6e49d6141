"""The compiled cache (dggs.geometry._cache), with real processes and real files (issue 17, items 7, 12, 13).

Each case runs Python in a fresh process on a temporary copy of the package (laid out as installed, put first
on PYTHONPATH) or on a cache directory of its own.  Read-only directories are made so with chmod, and, when the
tests run as root (whom chmod does not stop), with a read-only bind mount in a private mount namespace.
The expected coordinates come from a process that compiled everything afresh, never from a cache.
"""

from __future__ import annotations

import os
import random
import shutil
import stat
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
CALL = "import dggs; print(repr(dggs.cell_to_latlng('C401')), repr(dggs.cell_to_latlng(['B20', 'T5'])))"
#: dggs.cell_to_latlng('C401') etc. as one freshly compiled process prints them (filled by ``fresh``)
_FRESH: dict[str, str] = {}


def _copy_package(dest: Path) -> Path:
    """The package as a wheel installs it (dggs/, dggs/index, ...), without caches or the web map."""
    skip = shutil.ignore_patterns("__pycache__", "static", "*.nbi", "*.nbc")
    pkg = dest / "site"
    shutil.copytree(ROOT / "dggs", pkg / "dggs", ignore=skip)
    for src, name in (("index", "index"), ("storage", "storage"), ("experiments", "experiments")):
        shutil.copytree(ROOT / src, pkg / "dggs" / name, ignore=skip)
    return pkg


def _env(home: Path, pythonpath: Path | None = None, **extra: str) -> dict[str, str]:
    env = {k: v for k, v in os.environ.items() if not k.startswith(("NUMBA_", "DGGS_", "XDG_")) and k not in ("TMPDIR", "TEMP", "TMP")}
    env["HOME"] = str(home)
    env.pop("PYTHONPATH", None)
    if pythonpath is not None:
        env["PYTHONPATH"] = str(pythonpath)
    env.update(extra)
    return env


#: an editable install's import hook would find the work tree before the copy on PYTHONPATH: drop it
_PRELUDE = "import sys; sys.meta_path[:] = [f for f in sys.meta_path if 'editable' not in getattr(f, '__module__', '')]; "


def _run(code: str, env: dict[str, str], read_only: tuple[Path, ...] = (), cwd: Path | None = None):
    """Run ``code`` in a new interpreter (in HOME: the work tree's dggs/ would shadow the copy); ``read_only``
    directories are read-only for it."""
    cmd = [sys.executable, "-W", "default", "-c", (_PRELUDE if "PYTHONPATH" in env else "") + code]
    chmodded = read_only and os.geteuid() != 0  # root: a read-only bind mount in a private namespace instead
    if read_only and os.geteuid() == 0:
        if shutil.which("unshare") is None:
            pytest.fail("running as root without unshare: cannot make a directory read-only")
        mounts = " && ".join(f"mount --bind '{p}' '{p}' && mount -o remount,ro,bind '{p}' '{p}'" for p in read_only)
        cmd = ["unshare", "-m", "sh", "-c", f'{mounts} && exec "$@"', "sh", *cmd]
    else:
        for top in read_only:
            for path in [top, *top.rglob("*")]:
                if path.is_dir():
                    path.chmod(stat.S_IRUSR | stat.S_IXUSR | stat.S_IRGRP | stat.S_IXGRP | stat.S_IROTH | stat.S_IXOTH)
    try:
        return subprocess.run(cmd, env=env, cwd=cwd or env["HOME"], capture_output=True, text=True, timeout=900)
    finally:  # undo only what was done: as root nothing was chmodded (a restore here made /tmp 0755)
        for top in read_only if chmodded else ():
            for path in [top, *top.rglob("*")]:
                if path.is_dir():
                    path.chmod(stat.S_IRWXU | stat.S_IRGRP | stat.S_IXGRP | stat.S_IROTH | stat.S_IXOTH)


def _ok(proc) -> str:
    assert proc.returncode == 0, proc.stderr[-3000:]
    assert "Traceback" not in proc.stderr, proc.stderr[-3000:]
    return proc.stdout.strip()


def _cache_files(top: Path) -> list[Path]:
    return sorted(p for p in top.rglob("*") if p.suffix in (".nbi", ".nbc"))


@pytest.fixture(scope="module")
def fresh(tmp_path_factory) -> str:
    """The answer of a process that compiled everything (an empty cache of its own)."""
    if "out" not in _FRESH:
        tmp = tmp_path_factory.mktemp("fresh")
        _FRESH["out"] = _ok(_run(CALL, _env(tmp, NUMBA_CACHE_DIR=str(tmp / "cache"))))
    return _FRESH["out"]


@pytest.fixture(scope="module")
def pristine(tmp_path_factory, fresh) -> Path:
    """A complete cache of CALL's kernels, made by one process (NUMBA_CACHE_DIR)."""
    cache = tmp_path_factory.mktemp("pristine") / "cache"
    assert _ok(_run(CALL, _env(cache.parent, NUMBA_CACHE_DIR=str(cache)))) == fresh
    assert _cache_files(cache)
    return cache


# -- item 7: an edit of one kernel source is seen by the cached kernels of every module that inlined it -----


@pytest.mark.slow  # fresh processes compiling every kernel into new caches: make test-all
def test_an_edit_of_the_geometry_kernel_reaches_the_cached_index_kernels(tmp_path):
    pkg = _copy_package(tmp_path)
    env = _env(tmp_path, pkg)
    code = "import dggs; print(dggs.__file__); print(repr(dggs.cell_to_latlng('C401')))"
    where, before = _ok(_run(code, env)).splitlines()
    assert where.startswith(str(pkg))
    kernel = pkg / "dggs" / "geometry" / "kernel.py"
    text = kernel.read_text()
    old = "return math.degrees(beta + b1 * s2), math.degrees(math.atan2(py, px))"
    assert text.count(old) == 1
    kernel.write_text(text.replace(old, "return math.degrees(beta + b1 * s2) + 0.5, math.degrees(math.atan2(py, px))"))
    _, after = _ok(_run(code, env)).splitlines()  # index/_kernel/points.py is unchanged: numba's stamp is its own
    lat0, lng0 = eval(before)
    lat1, lng1 = eval(after)
    assert lat1 == pytest.approx(lat0 + 0.5, abs=1e-12) and lng1 == lng0, "the cached kernel ran the old source"


def test_the_cache_directory_is_named_by_the_sources(tmp_path):
    pkg = _copy_package(tmp_path)
    code = "from dggs.geometry import _cache; print(_cache.sources_hash())"
    first = _ok(_run(code, _env(tmp_path, pkg)))
    target = pkg / "dggs" / "index" / "_kernel" / "bits.py"
    target.write_text(target.read_text() + "\n# an edit\n")
    assert _ok(_run(code, _env(tmp_path, pkg))) != first


# -- item 12: read-only installs -------------------------------------------------------------------------------


@pytest.mark.slow  # fresh processes compiling every kernel into new caches: make test-all
def test_read_only_package_and_home_fall_back_to_a_temp_directory_with_one_warning(tmp_path, fresh):
    pkg = _copy_package(tmp_path / "ro")
    (tmp_path / "ro" / "home").mkdir()
    temp = tmp_path / "temp"
    temp.mkdir()
    proc = _run(CALL, _env(tmp_path / "ro" / "home", pkg, TMPDIR=str(temp)), read_only=(tmp_path / "ro",))
    assert _ok(proc) == fresh
    assert proc.stderr.count("CacheWarning") == 1, proc.stderr
    assert _cache_files(temp), "nothing was cached in the temporary directory"
    again = _run(CALL, _env(tmp_path / "ro" / "home", pkg, TMPDIR=str(temp)), read_only=(tmp_path / "ro",))
    assert _ok(again) == fresh


@pytest.mark.slow  # fresh processes compiling every kernel into new caches: make test-all
def test_nothing_writable_at_all_compiles_without_a_cache_and_one_warning(tmp_path, fresh):
    if os.geteuid() != 0:
        pytest.fail("needs a private mount namespace to make the system temp directories read-only")
    pkg = _copy_package(tmp_path / "ro")
    (tmp_path / "ro" / "home").mkdir()
    tops = tuple(Path(p) for p in ("/tmp", "/var/tmp") if Path(p).is_dir())
    modes = [top.stat().st_mode for top in tops]
    proc = _run(CALL, _env(tmp_path / "ro" / "home", pkg), read_only=(tmp_path / "ro", *tops), cwd=tmp_path / "ro")
    assert [top.stat().st_mode for top in tops] == modes, "the machine's temp directories lost their mode"
    assert _ok(proc) == fresh
    assert proc.stderr.count("CacheWarning") == 1, proc.stderr


@pytest.mark.slow  # fresh processes compiling every kernel into new caches: make test-all
def test_a_read_only_install_with_a_writable_home_uses_its_shipped_cache(tmp_path, fresh):
    pkg = _copy_package(tmp_path / "ro")
    assert _ok(_run(CALL, _env(tmp_path, pkg))) == fresh  # the build step: fills the package's own cache
    shipped = {p.name for p in _cache_files(pkg)}
    assert shipped
    home = tmp_path / "home"
    home.mkdir()
    proc = _run(CALL, _env(home, pkg), read_only=(tmp_path / "ro",))
    assert _ok(proc) == fresh
    assert "CacheWarning" not in proc.stderr
    used = {p.name for p in _cache_files(home / ".cache")}
    assert shipped <= used, "the user cache was compiled afresh instead of starting from the shipped one"


# -- item 13: a damaged cache file is dropped and compiled again ---------------------------------------------


def _damage(files: list[Path], how: str) -> None:
    rng = random.Random(17)
    if how == "swap":
        by_size = sorted(files, key=lambda p: p.stat().st_size)
        for a, b in zip(by_size[0::2], by_size[1::2], strict=False):
            da, db = a.read_bytes(), b.read_bytes()
            a.write_bytes(db)
            b.write_bytes(da)
        return
    for path in files:
        size = path.stat().st_size
        if how == "truncate":
            path.write_bytes(path.read_bytes()[: size // 2])
        elif how == "zero":
            path.write_bytes(bytes(size))
        elif how == "random":
            path.write_bytes(rng.randbytes(size))
        elif how == "empty":
            path.write_bytes(b"")


@pytest.mark.slow  # ten fresh processes compiling again: make test-all
@pytest.mark.parametrize("suffix", [".nbi", ".nbc"])
@pytest.mark.parametrize("how", ["truncate", "zero", "random", "swap", "empty"])
def test_a_damaged_cache_file_is_compiled_again(tmp_path, pristine, fresh, suffix, how):
    cache = tmp_path / "cache"
    shutil.copytree(pristine, cache)
    files = [p for p in _cache_files(cache) if p.suffix == suffix]
    assert len(files) >= 2
    _damage(files, how)
    env = _env(tmp_path, NUMBA_CACHE_DIR=str(cache))
    assert _ok(_run(CALL, env)) == fresh
    assert _ok(_run(CALL, env)) == fresh  # and the entries written again are sound
