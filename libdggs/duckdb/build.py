"""Build the dggs DuckDB extension: build/duckdb/dggs.duckdb_extension (``make duckdb-extension``).

1. DuckDB's C API headers (``duckdb.h``, ``duckdb_extension.h``) come from the source distribution of the
   ``duckdb`` package on PyPI, downloaded by pip into ``build/duckdb-sdk/<version>/`` (never committed);
2. the extension's sources (``libdggs/duckdb/*.c``) and the core's (``libdggs/src/*.c``) are compiled into one
   shared library with the machine's C compiler, against the stable C extension API ``v1.2.0``, with the core's
   floating-point flags (the ids are the Python package's, bit for bit);
3. the metadata footer DuckDB reads on ``LOAD`` is appended (:func:`footer`).

Usage: ``python libdggs/duckdb/build.py [--duckdb-version 1.5.6] [--out build/duckdb/dggs.duckdb_extension]``.
"""

from __future__ import annotations

import argparse
import os
import platform
import shutil
import subprocess
import sys
import tarfile
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
HERE = Path(__file__).resolve().parent
#: The stable C extension API the extension is built against: it loads in every DuckDB from 1.2.0 on (v1 API).
C_API = (1, 2, 0)
#: The DuckDB release whose headers are used by default: that of pip's duckdb-cli, which the tests run.
DEFAULT_DUCKDB = "1.5.6"
EXTENSION_VERSION = "0.1.0"
FLAGS = ["-std=c11", "-O2", "-fPIC", "-shared", "-fvisibility=hidden",
         "-ffp-contract=off", "-fno-fast-math", "-fno-finite-math-only"]  # fmt: skip
# The core's own warnings (libdggs/CMakeLists.txt); DuckDB's headers are -isystem, so only our code is checked.
WARNINGS = ["-Wall", "-Wextra", "-Wpedantic", "-Wshadow", "-Wconversion"]


def headers(version: str, sdk: Path) -> Path:
    """The folder holding duckdb.h and duckdb_extension.h of DuckDB ``version``, downloaded by pip if missing."""
    folder = sdk / version
    if (folder / "duckdb_extension.h").is_file() and (folder / "duckdb.h").is_file():
        return folder
    download = sdk / "download"
    download.mkdir(parents=True, exist_ok=True)
    subprocess.run([sys.executable, "-m", "pip", "download", "--quiet", "--no-deps", "--no-binary", "duckdb",
                    "-d", str(download), f"duckdb=={version}"], check=True)  # fmt: skip
    sdist = download / f"duckdb-{version}.tar.gz"
    folder.mkdir(parents=True, exist_ok=True)
    with tarfile.open(sdist) as tar:
        for member in tar.getmembers():
            name = member.name.rsplit("/", 1)[-1]
            if member.name.endswith(f"/src/include/{name}") and name in ("duckdb.h", "duckdb_extension.h"):
                source = tar.extractfile(member)
                assert source is not None
                (folder / name).write_bytes(source.read())
    if not (folder / "duckdb_extension.h").is_file():
        raise SystemExit(f"no duckdb_extension.h in {sdist}")
    return folder


def duckdb_platform() -> str:
    """DuckDB's name of this platform (``PRAGMA platform``): linux_amd64, linux_arm64, osx_arm64, ...

    ``$DUCKDB_PLATFORM`` overrides it: DuckDB 1.2's Linux builds call linux_amd64 ``linux_amd64_gcc4``.
    """
    if os.environ.get("DUCKDB_PLATFORM"):
        return os.environ["DUCKDB_PLATFORM"]
    system = {"Linux": "linux", "Darwin": "osx", "Windows": "windows"}[platform.system()]
    machine = {"x86_64": "amd64", "AMD64": "amd64", "aarch64": "arm64", "arm64": "arm64"}[platform.machine()]
    return f"{system}_{machine}"


def _field(text: str) -> bytes:
    raw = text.encode("ascii")
    if len(raw) > 32:
        raise ValueError(f"metadata field {text!r} is longer than 32 bytes")
    return raw + b"\0" * (32 - len(raw))


def footer(platform_name: str, api_version: str, extension_version: str, abi: str = "C_STRUCT") -> bytes:
    """The 534 bytes DuckDB expects at the end of a loadable extension.

    It is a WebAssembly custom section (so a Wasm build stays valid): the section id 0, its length 531 as
    LEB128 (0x93 0x04), the name's length 16 and the name ``duckdb_signature``, the payload's length 512 as
    LEB128 (0x80 0x04); then eight 32-byte NUL-padded fields written last first (8, 7, 6 unused; 5 the ABI
    type; 4 the extension's version; 3 the DuckDB version, for the C_STRUCT ABI the C API version the
    extension needs; 2 the platform; 1 the magic "4"), then 256 bytes for a signature (zeros: unsigned, so
    DuckDB loads it only with ``allow_unsigned_extensions``, the CLI's ``-unsigned``).
    """
    head = bytes([0, 0x93, 0x04, 16]) + b"duckdb_signature" + bytes([0x80, 0x04])
    fields = ["4", platform_name, api_version, extension_version, abi, "", "", ""]
    body = b"".join(_field(f) for f in reversed(fields))
    out = head + body + b"\0" * 256
    assert len(out) == 2 + 1 + 1 + 16 + 2 + 512 and len(out) - 3 == 531
    return out


SANITIZE = ["-fsanitize=address,undefined", "-fno-sanitize-recover=all", "-fno-omit-frame-pointer", "-g"]


def build(version: str, out: Path, cc: str, sanitize: bool = False, werror: bool = False) -> Path:
    include = headers(version, ROOT / "build" / "duckdb-sdk")
    out.parent.mkdir(parents=True, exist_ok=True)
    library = Path(tempfile.mkdtemp(prefix="dggs-duckdb-")) / "dggs.so"  # not left beside the output (a wheel's dggs/)
    sources = sorted(str(p) for p in (ROOT / "libdggs" / "src").glob("*.c")) + sorted(str(p) for p in HERE.glob("*.c"))
    major, minor, patch = C_API
    defines = ["-DDUCKDB_EXTENSION_NAME=dggs", f"-DDUCKDB_EXTENSION_API_VERSION_MAJOR={major}",
               f"-DDUCKDB_EXTENSION_API_VERSION_MINOR={minor}", f"-DDUCKDB_EXTENSION_API_VERSION_PATCH={patch}"]  # fmt: skip
    if platform.machine() in ("i386", "i686", "x86"):
        defines += ["-msse2", "-mfpmath=sse"]
    includes = [f"-isystem{include}", f"-I{ROOT / 'libdggs' / 'include'}", f"-I{ROOT / 'libdggs' / 'src'}"]
    flags = FLAGS + WARNINGS + (["-Werror"] if werror else []) + (SANITIZE if sanitize else [])
    subprocess.run([cc, *flags, *defines, *includes, *sources, "-o", str(library), "-lm"], check=True)
    tmp = out.with_suffix(".tmp")
    shutil.copyfile(library, tmp)
    with open(tmp, "ab") as f:
        f.write(footer(duckdb_platform(), "v{}.{}.{}".format(*C_API), EXTENSION_VERSION))
    tmp.replace(out)
    shutil.rmtree(library.parent, ignore_errors=True)
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--duckdb-version", default=os.environ.get("DUCKDB_VERSION", DEFAULT_DUCKDB))
    parser.add_argument("--out", type=Path, default=ROOT / "build" / "duckdb" / "dggs.duckdb_extension")
    parser.add_argument("--cc", default=os.environ.get("CC", "cc"))
    parser.add_argument("--sanitize", action="store_true",
                        help="AddressSanitizer and UBSan (run the CLI binary with LD_PRELOAD of the compiler's libasan)")
    parser.add_argument("--werror", action="store_true", help="fail on any warning (make's builds and CI)")
    args = parser.parse_args()
    print(build(args.duckdb_version, args.out, args.cc, args.sanitize, args.werror))


if __name__ == "__main__":
    main()
