"""One progress convention for every long step: a tqdm bar on stderr.

Every function that can take long (ingest, raster binning, polygon fill over
many polygons, :meth:`~dggs.storage.CellStore.export`, ``aggregate`` over a
large store) takes ``progress``, read here the same way everywhere:

* ``None`` (the default): a bar on stderr only when stderr is a terminal, and
  only once the work has run for :data:`AUTO_DELAY` seconds, so that quick calls
  (and calls in a loop) draw nothing, and logs and pipes stay clean;
* ``True``: a bar on stderr at once, terminal or not;
* ``False``: nothing;
* a callable: called with each increment (rows, blocks, polygons, cells), no bar.

The bar has a total (and so an ETA) wherever the length of the work is known.
Steps that are one long call (the final sort of an ingest, an aggregate's SQL, drawing
an export's polygons) keep the bar's clock running (:meth:`Bar.heartbeat`), so the
bar covers the whole call, not only the part that counts rows.

Examples
--------
>>> seen = []
>>> with Bar(seen.append, total=3, unit="rows") as bar:
...     bar.update(2)
...     bar.update(1)
>>> seen
[2, 1]
>>> with Bar(False, total=3) as bar:  # silent
...     bar.update(3)
"""

from __future__ import annotations

import sys
import threading
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

from dggs.errors import DggsValueError

__all__ = ["AUTO_DELAY", "Bar", "Progress", "check_progress", "shows"]

#: Seconds of work before the default (``progress=None``) bar appears on a terminal.
AUTO_DELAY = 2.0

#: What a ``progress`` argument may be.
Progress = bool | Callable[[int], Any] | None


def check_progress(progress: Any, what: str = "a count") -> None:
    """Refuse a ``progress`` that is not ``True``, ``False``, ``None`` or a callable.

    Raises
    ------
    DggsValueError
        Naming the bad value.

    Examples
    --------
    >>> check_progress("yes")
    Traceback (most recent call last):
    ...
    dggs.errors.DggsValueError: progress must be True, False, None or a callable taking a count, not 'yes'
    """
    if not (progress is None or isinstance(progress, bool) or callable(progress)):
        raise DggsValueError(f"progress must be True, False, None or a callable taking {what}, not {progress!r}")


def shows(progress: Any) -> bool:
    """Whether ``progress`` draws a bar: ``True``, or ``None`` with stderr a terminal.

    Examples
    --------
    >>> shows(True), shows(False), shows(print)
    (True, False, False)
    """
    if progress is None:
        try:
            return sys.stderr.isatty()
        except (AttributeError, ValueError):  # replaced or closed stderr
            return False
    return progress is True


class Bar:
    """A progress bar as ``progress`` asks (see the module's docstring); a context manager.

    Parameters
    ----------
    progress : bool, callable or None
        As every long function's ``progress`` argument.
    total : int, optional
        Units of work, when known (gives the bar a percentage and an ETA).
    unit : str
        What is counted: ``"rows"``, ``"blocks"``, ``"polygons"``, ``"steps"``; ``""`` for a clock alone (one
        long call whose work cannot be counted).
    desc : str
        What the work is, shown before the bar.
    initial : int
        Units already done (a resumed ingest).

    Raises
    ------
    DggsValueError
        For a ``progress`` that is none of the above.
    """

    def __init__(self, progress: Any, total: int | None = None, unit: str = "rows", desc: str = "",
                 initial: int = 0) -> None:
        check_progress(progress, f"a {unit.rstrip('s') or 'work'} count")
        self.callback: Callable[[int], Any] | None = progress if callable(progress) else None
        self.tqdm: Any = None
        if shows(progress):
            from tqdm import tqdm

            self.tqdm = tqdm(
                total=total, initial=initial, unit=f" {unit}", unit_scale=unit != "steps", desc=desc,
                file=sys.stderr, delay=AUTO_DELAY if progress is None else 0.0,
                bar_format="{desc}: {elapsed}" if unit == "" else None,  # a clock alone: nothing to count
            )

    def update(self, n: int) -> None:
        """Count ``n`` more units of work."""
        if self.tqdm is not None:
            self.tqdm.update(n)
        if self.callback is not None:
            self.callback(n)

    def stage(self, desc: str) -> None:
        """Name the step now running (e.g. ``"sorting"`` after the rows are read)."""
        if self.tqdm is not None:
            self.tqdm.set_description_str(desc)

    def refresh(self) -> None:
        """Redraw the bar (its elapsed time) without counting anything."""
        bar = self.tqdm
        if bar is None:
            return
        now = time.time()  # tqdm's clock
        # as tqdm.update() does: at most every mininterval, and a delayed bar only once its delay has passed
        if now - bar.last_print_t >= bar.mininterval and now >= bar.start_t + bar.delay:
            bar.refresh()
            bar.last_print_t = now

    @contextmanager
    def heartbeat(self, every: float = 0.5) -> Iterator[None]:
        """Keep the bar's clock running through one long call (an SQL statement, a GEOS call, a write).

        A thread redraws the bar every ``every`` seconds; those calls release the GIL, so it runs meanwhile.
        """
        if self.tqdm is None:
            yield
            return
        stop = threading.Event()

        def beat() -> None:
            while not stop.wait(every):
                self.refresh()

        thread = threading.Thread(target=beat, name="progress-heartbeat", daemon=True)
        thread.start()
        try:
            yield
        finally:
            stop.set()
            thread.join()

    def close(self) -> None:
        """Close the bar (leaving its last state on the terminal)."""
        if self.tqdm is not None:
            self.tqdm.close()
            self.tqdm = None

    def __enter__(self) -> Bar:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
