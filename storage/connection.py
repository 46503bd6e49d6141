"""The store's SQLite connection: opening, transactions, metadata, errors.

:class:`Connection` opens (or creates) a store file, checks that it is a
cell store, and runs transactions.  The errors SQLite and the operating
system raise become :class:`dggs.StorageError` in :mod:`.failures`.

Read-only opens (immutable when no writer has the store open, and on
read-only media) are in :mod:`.readonly`.
"""

from __future__ import annotations

import contextlib
import sqlite3
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import dggs
from dggs.errors import LevelError, LevelMismatchError, StorageError

from .datasets import check_dataset_name, discard_empty_dataset, open_dataset
from .failures import guarded, translate
from .readonly import connect as _connect
from .readonly import connect_immutable, quiet, signature
from .rollup_exact import register as register_exact_sums
from .rollup_memo import Memo
from .rollup_verify import verify
from .schema import check_meta, check_schema, column_types, create_schema, now, upgrade_layout

__all__ = ["Connection", "translate", "guarded", "DEFAULT_LEVEL", "connect_immutable"]

#: Level used by a new store when none is given.
DEFAULT_LEVEL = 12

_SQLITE_MAGIC = b"SQLite format 3\x00"


def _dggs_version() -> str:
    try:
        from importlib.metadata import version

        return version("dggs")
    except Exception:  # noqa: BLE001 - not installed: fall back to the module
        return str(getattr(dggs, "__version__", "unknown"))


class Connection:
    """An open cell store file: the connection, its transactions and metadata."""

    def __init__(self, path: str, *, create: bool, readonly: bool, timeout: float, check_same_thread: bool = True,
                 dataset: str | None = None) -> None:
        self.path, self.readonly, self.timeout = path, readonly, timeout
        self.dataset = None if dataset is None else check_dataset_name(dataset)  # None: the default dataset
        self.create = create
        self.created_dataset = False  # this connection made the named dataset (close may take it back)
        self.check_same_thread = check_same_thread
        self.projection = "ISEA"  # the grid of the cells: set by CellStore from meta (storage/projection.py)
        self.created = False  # this connection made the file (close(discard_unused=True) may take it back)
        if path != ":memory:":
            file = Path(path)
            self.created = not file.exists() and create and not readonly
            if file.is_dir():
                raise StorageError(f"{path} is a directory, not a cell store file")
            if not file.exists() and (readonly or not create):
                raise StorageError(f"no cell store at {path}")
            try:
                if file.exists() and file.stat().st_size > 0:
                    with open(file, "rb") as fh:
                        if fh.read(16) != _SQLITE_MAGIC:
                            raise StorageError(f"{path} is not a SQLite database")
            except OSError as exc:
                raise translate(exc, path) from exc
        self._db: Any = None
        self.memo = Memo()  # roll-up partials of the current file state (rollup_memo)
        self._open()

    def _open(self) -> None:
        path, readonly, timeout = self.path, self.readonly, self.timeout
        try:
            # the signature before the open: a change between the two is then seen as one
            before = signature(Path(path).resolve()) if readonly and path != ":memory:" else None
            self._conn, self.immutable = _connect(path, readonly, timeout, self.check_same_thread)
            register_exact_sums(self._conn)  # the kept roll-ups' exact REAL sums (rollup_exact)
            self.signature = before
        except (sqlite3.DatabaseError, UnicodeDecodeError, OSError) as exc:
            raise translate(exc, path, timeout) from exc
        except sqlite3.Error as exc:
            raise StorageError(f"cannot open {path}: {exc}") from exc
        try:
            self._setup()
        except (sqlite3.Error, OSError, UnicodeDecodeError) as exc:
            self._conn.close()
            raise translate(exc, path, timeout) from exc
        except BaseException:
            self._conn.close()
            raise
        self._db = None

    def _catch_up(self) -> None:
        """An immutable reader whose store a writer has opened since (or replaced): open it again.

        Raises
        ------
        StorageError
            If the store was deleted: an error naming it, never its old rows.
        """
        if not Path(self.path).exists():
            self._check_fresh()
        self._conn.close()
        self._open()

    @property
    def conn(self) -> sqlite3.Connection:
        """The SQLite connection; an immutable reader catches up first when a writer has appeared.

        Outside a transaction only: within one, the reader keeps its snapshot.
        """
        if self.immutable and not self._conn.in_transaction and self.behind():
            self._catch_up()
        return self._conn

    def stale(self) -> bool:
        """Whether the file changed (written, replaced, truncated, deleted) since this immutable reader opened it.

        Always False for a WAL reader or a writer: SQLite itself keeps those consistent.
        """
        if not self.immutable:
            return False
        try:
            return signature(Path(self.path).resolve()) != self.signature
        except OSError:
            return True

    def behind(self) -> bool:
        """Whether an immutable reader may miss commits: the file changed, or a writer's ``-wal`` is there now.

        :attr:`conn` opens the store again then.
        """
        return self.immutable and (self.stale() or not quiet(Path(self.path).resolve()))

    def _check_fresh(self) -> None:
        if self.stale():
            gone = not Path(self.path).exists()
            raise StorageError(
                f"{self.path} was deleted while open read-only"
                if gone
                else f"{self.path} changed while it was read (written, replaced or truncated); read it again"
            )

    @property
    def db(self) -> Any:
        """A :class:`sqlite_utils.Database` on the connection (imported on first use: it loads pandas)."""
        conn = self.conn  # an immutable reader may open the store again here
        if self._db is None or self._db.conn is not conn:
            import sqlite_utils

            self._db = sqlite_utils.Database(conn)
        return self._db

    def query(self, sql: str, params: Any = ()) -> Iterator[dict[str, Any]]:
        """Run ``sql`` and yield its rows as dicts."""
        cursor = self.conn.execute(sql, params)
        names = [d[0] for d in cursor.description]
        for row in cursor:
            yield dict(zip(names, row, strict=True))

    def _setup(self) -> None:
        conn = self._conn
        conn.execute("PRAGMA foreign_keys = ON")
        if not self.readonly:
            conn.execute("PRAGMA journal_mode = WAL")
            conn.execute("PRAGMA synchronous = NORMAL")
        conn.execute("PRAGMA cache_size = -65536")
        conn.execute("PRAGMA temp_store = MEMORY")
        conn.execute("PRAGMA threads = 2")  # helper thread for the merge's sort
        if not self.readonly:
            # Fewer, larger checkpoints: ingest writes tens of MB per merge.
            conn.execute("PRAGMA wal_autocheckpoint = 16384")
        if not check_schema(conn, self.path):
            if self.readonly:
                raise StorageError(f"{self.path} is an empty database, not a cell store")
            create_schema(conn, _dggs_version())
            check_schema(conn, self.path)  # whoever created it, it must be ours
        elif not self.readonly:
            upgrade_layout(conn)
        if self.dataset is not None:  # a named dataset, made here if new and allowed (storage/datasets.py)
            self.dataset, made = open_dataset(conn, self.dataset, self.path, self.create and not self.readonly,
                                              _dggs_version(), now())
            self.created_dataset = self.created_dataset or made
        check_meta(conn, self.path)

    def close(self, discard_unused: bool = False) -> None:
        """Close the SQLite connection.

        With ``discard_unused`` (a ``with`` block left by an error), a file this connection created and into
        which nothing was ever ingested is removed, with its ``-wal``/``-shm``/``-journal``: a failed first
        ingest leaves no empty store behind, as ``dggs bin`` checks its input before creating one.  So is a
        named dataset it made that holds no row (storage/datasets.py).
        """
        unused = False
        if discard_unused and self.created_dataset:  # made for an ingest that stored no row: taken back
            with contextlib.suppress(sqlite3.Error):
                discard_empty_dataset(self._conn, str(self.dataset))
        if discard_unused and self.created and self._conn.dataset is None:  # type: ignore[attr-defined]
            try:
                unused = not any(self._conn.execute(f"SELECT 1 FROM {t} LIMIT 1").fetchone()
                                 for t in ("sources", "points", "points_pending"))
            except sqlite3.Error:  # a store half made, or no longer readable: left as it is
                unused = False
        self._conn.close()
        if unused:
            for suffix in ("", "-wal", "-shm", "-journal"):
                Path(self.path + suffix).unlink(missing_ok=True)

    @contextlib.contextmanager
    def transaction(self) -> Iterator[None]:
        """``BEGIN IMMEDIATE`` ... ``COMMIT``; roll back on any error (even a failed commit)."""
        conn = self.conn
        conn.execute("BEGIN IMMEDIATE")
        try:
            yield
            conn.execute("COMMIT")
        except BaseException:
            if conn.in_transaction:
                with contextlib.suppress(sqlite3.Error):
                    conn.execute("ROLLBACK")
            raise

    @contextlib.contextmanager
    def snapshot(self) -> Iterator[str]:
        """Read in one snapshot; yield the table to read from.

        That is ``points`` alone when nothing is pending (the common case,
        and a plain clustered scan), else the ``all_points`` view.

        Raises
        ------
        StorageError
            If an immutable reader's file changed since it was opened, or while it was read.
        """
        own = not self.conn.in_transaction  # an immutable reader caught up here (the conn property)
        if own:
            self.conn.execute("BEGIN")
        try:
            pending = self.conn.execute("SELECT 1 FROM points_pending LIMIT 1").fetchone()
            yield "all_points" if pending else "points"
        except sqlite3.DatabaseError:
            if own:
                self._check_fresh()  # a page a writer changed under an immutable read: say so
            raise
        finally:
            if own and self.conn.in_transaction:
                self.conn.execute("COMMIT")
        if own:
            self._check_fresh()  # and unchanged while it was read

    # -- metadata -----------------------------------------------------------

    @property
    def meta(self) -> dict[str, str]:
        """The ``meta`` table as a dict (schema version, level, CRS, ...)."""
        return dict(self.conn.execute("SELECT key, value FROM meta"))

    @property
    def level(self) -> int | None:
        """The stored level, or None before the first ingest.

        Raises
        ------
        StorageError
            If the stored level is not a level (a damaged ``meta`` table).
        """
        row = self.conn.execute("SELECT value FROM meta WHERE key = 'level'").fetchone()
        if row is None:
            return None
        if not (isinstance(row[0], str) and row[0].isdigit() and int(row[0]) <= dggs.MAX_LEVEL):
            check_meta(self.conn, self.path)  # raises, naming the value
        return int(row[0])

    @property
    def columns(self) -> dict[str, str]:
        """The value columns and their SQL types."""
        return column_types(self.conn)

    def touch(self) -> None:
        """Record now as the time of the last change."""
        self.conn.execute("UPDATE meta SET value = ? WHERE key = 'updated'", (now(),))

    def set_level(self, level: int) -> None:
        """Claim ``level`` as the stored level (inside the caller's write transaction).

        The check before an ingest (:meth:`check_level_for_ingest`) reads the
        level outside any transaction, so two writers creating one new store
        can both pass it; the claim is atomic, and the one that commits second
        sees the first one's level here and stops.

        Raises
        ------
        LevelMismatchError
            If another writer has already claimed another level.
        """
        self.conn.execute("INSERT OR IGNORE INTO meta (key, value) VALUES ('level', ?)", (str(level),))
        self.check_level_for_ingest(level)

    def check_level_for_ingest(self, level: int) -> None:
        """Check that rows may be ingested at ``level``.

        Raises
        ------
        LevelError
            If ``level`` is not an int in ``0..MAX_LEVEL``.
        LevelMismatchError
            If the store already holds cells at another level.
        """
        if isinstance(level, bool) or not isinstance(level, int) or not 0 <= level <= dggs.MAX_LEVEL:
            raise LevelError(f"level {level!r} is out of range 0..{dggs.MAX_LEVEL}")
        stored = self.level
        if stored is not None and stored != level:
            raise LevelMismatchError(
                f"{self.path}{'' if self.dataset is None else f' dataset {self.dataset!r}'} stores cells at level {stored}; "
                f"cannot ingest at level {level} "
                f"(use level={stored}, or another dataset: CellStore(path, dataset=NAME))"
            )

    def resolve_level(self, level: int | None) -> int:
        """``level``, else the stored level, else the default level."""
        if level is not None:
            return level
        stored = self.level
        return DEFAULT_LEVEL if stored is None else stored

    def pending_count(self) -> int:
        """How many ingested rows wait in ``points_pending`` to be merged."""
        return int(self.conn.execute("SELECT count(*) FROM points_pending").fetchone()[0])

    def merge_pending(self) -> None:
        """Move pending rows into ``points`` (inside the caller's transaction).

        Raises
        ------
        StorageError
            If a pending row would be stored twice (its key is already in ``points``).
        """
        from .schema import BASE_COLUMNS, quote

        cols = ", ".join(quote(c) for c in (*BASE_COLUMNS, *self.columns))
        try:
            # Ordered by cell alone: the inserts then walk the clustered key nearly in
            # order, and sorting one key costs 20 % less than the whole key (the
            # primary key places rows of one cell whatever order they come in).
            self.conn.execute(f"INSERT INTO points ({cols}) SELECT {cols} FROM points_pending ORDER BY cell")
        except sqlite3.IntegrityError as exc:  # pragma: no cover - would be a bug
            raise StorageError(f"{self.path}: a row would be stored twice ({exc})") from exc
        self.conn.execute("DELETE FROM points_pending")

    def check(self) -> None:
        """Run ``PRAGMA integrity_check``; raise StorageError unless it says ok.

        Raises
        ------
        StorageError
            If the integrity check finds a problem or the file cannot be read.
        """
        try:
            problems = [row[0] for row in self.conn.execute("PRAGMA integrity_check(20)")]
        except sqlite3.Error as exc:
            raise translate(exc, self.path, self.timeout) from exc
        if problems != ["ok"]:
            raise StorageError(
                f"{self.path} is corrupt ({'; '.join(problems[:3])}); restore it from a backup, "
                "or ingest the inputs again into a new store"
            )
        self._check_levels()
        try:
            with self.snapshot():
                verify(self.conn, self.path)
        except sqlite3.Error as exc:
            raise translate(exc, self.path, self.timeout) from exc

    def _check_levels(self) -> None:
        """Raise StorageError unless every stored cell is at ``meta.level`` (ids have level + 1 characters)."""
        try:
            level = self.level
            with self.snapshot() as table:
                row = self.conn.execute(
                    f"SELECT cell FROM {table} WHERE length(cell) != ? LIMIT 1",
                    (-1 if level is None else level + 1,),
                ).fetchone()
        except sqlite3.Error as exc:
            raise translate(exc, self.path, self.timeout) from exc
        if row is not None:
            raise StorageError(
                f"{self.path} is damaged: it holds cell {row[0]!r} (level {len(row[0]) - 1}) "
                f"but its meta.level is {level}; restore it from a backup, "
                "or ingest the inputs again into a new store"
            )
