# SPDX-License-Identifier: EPL-2.0
"""The fault windows of a run, read from its signals: each ``SIG_FAULT_<SENSOR>_<KIND>_BEGIN`` opens a window of
that fault, the next ``..._END`` of the same fault closes it (contract/vocabulary.json ``faults``; the default
patterns publish one signal per window edge the simulation sends). A window still open at the end of the run has
no end. summary.json lists them under ``faults`` (only when there are any)."""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

from rei.evaluation.signals import Signal

FAULT_SIGNAL = re.compile(r"^SIG_FAULT_([A-Z0-9]+)_([A-Z0-9]+)_(BEGIN|END)$")


@dataclass(frozen=True, slots=True)
class FaultWindow:
    sensor: str  # laser
    kind: str  # blackout
    begin: float
    end: float | None

    def to_dict(self) -> dict[str, Any]:
        return {"fault": f"{self.sensor} {self.kind}", "begin": self.begin, "end": self.end}


def fault_windows(signals: Iterable[Signal]) -> tuple[FaultWindow, ...]:
    """The windows in the order they began; ``signals`` in stream order. An END without a window open is
    ignored (the window began before the recording did)."""
    windows: list[FaultWindow] = []
    open_at: dict[tuple[str, str], list[int]] = {}
    for s in signals:
        match = FAULT_SIGNAL.match(s.signal)
        if match is None:
            continue
        sensor, kind, edge = match[1].lower(), match[2].lower(), match[3]
        pending = open_at.setdefault((sensor, kind), [])
        if edge == "BEGIN":
            pending.append(len(windows))
            windows.append(FaultWindow(sensor, kind, s.t, None))
        elif pending:
            i = pending.pop(0)
            windows[i] = FaultWindow(sensor, kind, windows[i].begin, s.t)
    return tuple(windows)
