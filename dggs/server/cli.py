"""``dggs serve STORE.db``: the OGC API - DGGS and Features server and web map of a cell store.

Imports only click at module level: fastapi and uvicorn (the ``serve`` extra) are
imported when the command runs, so ``import dggs`` and the other commands never
need them.  Errors are one line and exit status 1:

- fastapi or uvicorn missing: ``pip install 'dggs[serve]'``;
- a missing, corrupt or foreign store file (:class:`dggs.StorageError`);
- a port already in use.
"""

from __future__ import annotations

import errno
import socket

import click

__all__ = ["serve"]


def _check_port(host: str, port: int) -> None:
    """Fail early, in one line, if ``host:port`` cannot be bound."""
    family = socket.AF_INET6 if ":" in host else socket.AF_INET
    with socket.socket(family, socket.SOCK_STREAM) as sock:
        sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        try:
            sock.bind((host, port))
        except OSError as exc:
            reason = "the port is in use" if exc.errno == errno.EADDRINUSE else (exc.strerror or str(exc))
            raise click.ClickException(f"cannot listen on {host}:{port}: {reason}") from None


@click.command("serve")
@click.argument("store", type=click.Path(dir_okay=True, path_type=str))
@click.option("--host", default="127.0.0.1", show_default=True,
              help="Address to listen on (0.0.0.0 for every interface: the API has no authentication).")
@click.option("--port", default=8000, show_default=True, type=click.IntRange(1, 65535), help="TCP port.")
@click.option("--max-zones", default=100_000, show_default=True, type=click.IntRange(min=1),
              help="Most zones in one zone listing (413 beyond).")
@click.option("--max-features", default=50_000, show_default=True, type=click.IntRange(min=1),
              help="Most features of /map/cells and sub-zones of zone data (413 beyond).")
@click.option("--refresh", default=2.0, show_default=True, type=click.FloatRange(min=0),
              help="Seconds the map's roll-ups may lag a store being written to (0: none).")
def serve(store: str, host: str, port: int, max_zones: int, max_features: int, refresh: float) -> None:
    """Serve STORE (a cell store) read-only over OGC API - DGGS and Features, with a web map at /.

    \b
    Example:
      dggs serve demo.db --port 8000     # then open http://127.0.0.1:8000/
    """
    try:
        import fastapi  # noqa: F401
        import uvicorn
    except ImportError as exc:
        raise click.ClickException(
            f"dggs serve needs the serve extra ({exc.name} is missing): pip install 'dggs[serve]'"
        ) from None
    from .app import create_app

    app = create_app(store, max_zones=max_zones, max_features=max_features, refresh=refresh)  # StorageError: one line, exit 1
    _check_port(host, port)
    from .vendor import VENDOR_HELP, missing_vendor

    if missing_vendor():
        click.echo(f"warning: {VENDOR_HELP}", err=True)
    shown = f"[{host}]" if ":" in host else host
    click.echo(f"Serving {store} at http://{shown}:{port}/ (API at /api.html; Ctrl+C stops)", err=False)
    uvicorn.run(app, host=host, port=port, log_level="warning")
