# SPDX-License-Identifier: EPL-2.0
"""The fault windows of a run, read from its signals: each ``SIG_FAULT_<SENSOR>_<KIND>_BEGIN`` opens a window of
that fault, the next ``..._END`` of the same fault closes it (contract/vocabulary.json ``faults``; the default
patterns publish one signal per window edge the simulation sends). A window still open at the end of the run has
no end. summary.json lists them under ``faults`` (only when there are any).

Two windows of one fault kind may be open at once (two blackouts, one inside the other). The signals do not say
which fault an END is of, so the run's schedule (sim.json's ``faults``) does: an END closes the open window whose
fault, active when it began, is due to end nearest to the END's time; without a schedule, the window that began
first."""

from __future__ import annotations

import json
import math
import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from rei.evaluation.signals import Signal

if TYPE_CHECKING:
    from rei.sim.faults import Fault

FAULT_SIGNAL = re.compile(r"^SIG_FAULT_([A-Z0-9]+)_([A-Z0-9]+)_(BEGIN|END)$")


@dataclass(frozen=True, slots=True)
class FaultWindow:
    sensor: str  # laser
    kind: str  # blackout
    begin: float
    end: float | None

    def to_dict(self) -> dict[str, Any]:
        return {"fault": f"{self.sensor} {self.kind}", "begin": self.begin, "end": self.end}


def fault_windows(signals: Iterable[Signal], schedule: Sequence[Fault] = ()) -> tuple[FaultWindow, ...]:
    """The windows in the order they began; ``signals`` in stream order, ``schedule`` the run's faults (pairs the
    edges of overlapping windows of one kind). An END without a window open is ignored (the window began before
    the recording did)."""
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
            i = pending.pop(_closed_by(pending, windows, s.t, schedule) if len(pending) > 1 else 0)
            windows[i] = FaultWindow(sensor, kind, windows[i].begin, s.t)
    return tuple(windows)


def _closed_by(pending: list[int], windows: list[FaultWindow], t: float, schedule: Sequence[Fault]) -> int:
    """The position in ``pending`` of the window an END at ``t`` closes: the one whose fault (of its kind, active
    when it began) ends nearest to ``t``; the first of those as near (without a schedule, the first)."""
    best, gap = 0, math.inf
    for position, i in enumerate(pending):
        window = windows[i]
        ends = [f.timing.next_edge(window.begin) for f in schedule
                if f.sensor == window.sensor and f.kind == window.kind and f.timing.active(window.begin)]
        nearest = min((abs(end - t) for end in ends), default=math.inf)
        if nearest < gap:
            best, gap = position, nearest
    return best


def run_schedule(run_dir: Path) -> tuple[Fault, ...]:
    """The faults the run's simulation ran with (its sim.json's ``faults``); none when it wrote none or they
    cannot be read (the windows are then paired in the order they began)."""
    try:
        listed = json.loads((run_dir / "sim.json").read_text(encoding="utf-8")).get("faults") or ()
        if not listed:
            return ()
        from rei.sim.faults import fault_from_fields  # the simulator's model: only for a run with faults

        return tuple(fault_from_fields(str(f["sensor"]), str(f["kind"]),
                                       {k: str(v) for k, v in f.items() if k not in ("sensor", "kind", "description")})
                     for f in listed)
    except (OSError, ValueError, TypeError, KeyError, AttributeError):
        return ()
