"""``progress=True`` on the ingest methods: a tqdm bar of the rows read."""

from __future__ import annotations

import sys
from typing import Any

__all__ = ["RowsBar"]


class RowsBar:
    """``progress=True``: a tqdm bar of the rows read, on stderr (closed when the ingest ends)."""

    def __init__(self) -> None:
        self.bar: Any = None

    def __call__(self, rows: int) -> None:
        """Advance the bar by ``rows`` (opening it on the first batch)."""
        if self.bar is None:
            from tqdm import tqdm

            self.bar = tqdm(unit=" rows", unit_scale=True, desc="binning", file=sys.stderr)
        self.bar.update(rows)

    def close(self) -> None:
        """Close the bar, if it was opened."""
        if self.bar is not None:
            self.bar.close()
