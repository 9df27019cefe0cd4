# SPDX-License-Identifier: EPL-2.0
"""The mission's event log ``OUT/events.csv`` (thesis 6.1.5): time, signal, its utility and the running total.

Each row is written and flushed the moment its signal arrives, so a crash of the evaluator (or of anything
that takes its process down) loses no row it had received: the file is the run's record even when no summary
is ever written. Flushing hands the bytes to the operating system; surviving a crash of the machine itself
(fsync per row) is not attempted.

Columns, exactly: ``t,signal,utility,total,subject,object``. ``t`` has 6 decimals (simulation seconds);
utilities and totals are printed as integers when they are integral, else with full float precision.
"""

from __future__ import annotations

import csv
import os
from pathlib import Path
from types import TracebackType
from typing import Self, TextIO

COLUMNS = ("t", "signal", "utility", "total", "subject", "object")


class EventLog:
    """Appends one CSV row per signal to a new file (the header is written and flushed at once)."""

    def __init__(self, path: str | os.PathLike[str]) -> None:
        self.path = Path(path)
        self.path.parent.mkdir(parents=True, exist_ok=True)
        self._file: TextIO | None = open(self.path, "w", encoding="utf-8", newline="")  # noqa: SIM115
        self._writer = csv.writer(self._file, lineterminator="\n")
        self._writer.writerow(COLUMNS)
        self._file.flush()
        self.rows = 0

    def write(self, t: float, signal: str, utility: float, total: float, subject: str, obj: str) -> None:
        if self._file is None:
            raise ValueError(f"event log {self.path} is closed")
        self._writer.writerow(
            (f"{t:.6f}", signal, format_number(utility), format_number(total), subject, obj))
        self._file.flush()
        self.rows += 1

    def close(self) -> None:
        if self._file is not None:
            self._file.close()
            self._file = None

    def __enter__(self) -> Self:
        return self

    def __exit__(
        self, exc_type: type[BaseException] | None, exc: BaseException | None, tb: TracebackType | None
    ) -> None:
        self.close()


def format_number(value: float) -> str:
    """``-10`` for integral values (the usual case with Table 3), ``0.5`` / ``repr`` precision otherwise."""
    if value.is_integer():
        return str(int(value))
    return repr(value)
