"""`dggs serve` as a real process on 127.0.0.1 for the server tests: a free port, and the server started on it."""

from __future__ import annotations

import contextlib
import socket
import subprocess
import sys
import time
import urllib.request
from collections.abc import Iterator
from pathlib import Path


def free_port() -> int:
    """A TCP port of 127.0.0.1 free now (the OS's choice)."""
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return int(sock.getsockname()[1])


@contextlib.contextmanager
def serving(store: Path, *args: str) -> Iterator[str]:
    """``dggs serve store [args]`` as a process on a free port of 127.0.0.1: yields its base URL once it answers."""
    exe = Path(sys.executable).parent / "dggs"
    assert exe.exists(), f"the dggs script is not installed next to {sys.executable}"
    port = free_port()
    proc = subprocess.Popen([str(exe), "serve", str(store), "--port", str(port), *args],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    base = f"http://127.0.0.1:{port}"
    try:
        deadline = time.monotonic() + 60
        while True:
            try:
                with urllib.request.urlopen(base + "/conformance", timeout=5):
                    break
            except OSError as exc:
                if proc.poll() is not None or time.monotonic() > deadline:
                    raise AssertionError(f"dggs serve did not answer: {proc.stderr.read() if proc.stderr else ''}") from exc
                time.sleep(0.2)
        yield base
    finally:
        proc.terminate()
        proc.communicate(timeout=30)
