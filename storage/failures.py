"""Raw SQLite and operating-system errors as :class:`dggs.StorageError` naming the file and what to do.

:func:`translate` turns the errors SQLite and the operating system raise (a
corrupt file, a full disk, a lock held too long, read-only media) into a
:class:`dggs.StorageError`; :func:`guarded` applies it to a method.
"""

from __future__ import annotations

import functools
import sqlite3
from collections.abc import Callable
from typing import Any, TypeVar

from dggs.errors import DggsError, StorageError

__all__ = ["translate", "guarded"]

F = TypeVar("F", bound=Callable[..., Any])


def translate(exc: BaseException, path: str, timeout: float | None = None) -> DggsError:
    """Return the :class:`StorageError` (or :class:`DggsValueError`) for a raw error.

    Examples
    --------
    >>> print(translate(sqlite3.OperationalError("database or disk is full"), "a.db"))
    a.db: the disk is full; free space and run the same command again (an ingest resumes where it stopped)
    """
    if isinstance(exc, DggsError):
        return exc
    text = str(exc)
    low = text.lower()
    if isinstance(exc, (sqlite3.Error, OSError)):
        if "full" in low or getattr(exc, "errno", None) == 28:
            return StorageError(
                f"{path}: the disk is full; free space and run the same command again "
                "(an ingest resumes where it stopped)"
            )
        if "locked" in low or "busy" in low:
            waited = f" (waited {timeout:g} s)" if timeout is not None else ""
            return StorageError(
                f"{path} is locked by another process{waited}; try again when it has finished, or pass a longer timeout"
            )
        if "readonly" in low or "read-only" in low:
            return StorageError(f"{path} is on read-only media or not writable; open it with readonly=True")
        if "malformed" in low or "not a database" in low or "corrupt" in low:
            return StorageError(
                f"{path} is corrupt ({text}); restore it from a backup, or ingest the inputs again into a new store"
            )
        if isinstance(exc, sqlite3.Error):
            return StorageError(f"{path}: SQLite error: {text}")
        if isinstance(exc, OSError) and exc.filename is not None:
            return StorageError(f"cannot use {exc.filename}: {exc.strerror or text}")
        return StorageError(f"{path}: {exc.strerror or text}" if isinstance(exc, OSError) else text)
    if isinstance(exc, UnicodeDecodeError):  # text in the file that is not UTF-8: damaged
        return StorageError(
            f"{path} is corrupt (stored text is not UTF-8: {exc.reason}); restore it from a backup, "
            "or ingest the inputs again into a new store"
        )
    if isinstance(exc, RecursionError):
        return StorageError(f"{path}: input nested too deeply to process")
    return StorageError(f"{path}: {type(exc).__name__}: {text}")


def guarded(method: F) -> F:
    """Decorate a method of an object with ``path`` (and ``timeout``): raw errors become StorageError."""

    @functools.wraps(method)
    def wrapper(self: Any, *args: Any, **kwargs: Any) -> Any:
        try:
            return method(self, *args, **kwargs)
        except (sqlite3.Error, OSError, RecursionError, UnicodeDecodeError) as exc:
            raise translate(exc, getattr(self, "path", "?"), getattr(self, "timeout", None)) from exc

    return wrapper  # type: ignore[return-value]
