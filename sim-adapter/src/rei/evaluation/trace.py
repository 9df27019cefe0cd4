# SPDX-License-Identifier: EPL-2.0
"""Everything the evaluator observed during one run, frozen at ``finish()``: the input of the verdicts.

Keeping it a plain value (no locks, no files) lets every verdict be tested with a hand-written trace.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from rei.evaluation.outcome import Evidence
from rei.evaluation.signals import (
    DEFAULT_TRANSITIONS,
    SIG_MISSION_BEGIN,
    SIG_MISSION_END,
    SIG_MONITOR_DATA_GAP,
    Signal,
    Transition,
)

if TYPE_CHECKING:
    from rei.evaluation.metrics.social import PersonCollision


@dataclass(frozen=True, slots=True)
class Trace:
    """Signals in arrival order and what else the run told us.

    ``end_time``: the end of observation (the simulated duration, at least the last signal's time).
    ``completed``: the run's status was COMPLETED (False: it ended in ERROR, ``error_reason`` says why).
    ``task_reasons``: TASK_FAIL reasons by task index, from the mission topic (signals carry none).
    ``task_goals``: goal positions ``(x, y)`` by task index, from the mission topic's TASK_START events.
    ``stream_problems``: losses in the signal stream itself (seq gaps, malformed messages), as evidence.
    ``person_collisions``: the collisions with people measured in the recorded state, with the robot's approach
    speed at each one's first sample (rei.evaluation.metrics); None when the state was not measured.
    """

    signals: tuple[Signal, ...]
    end_time: float
    completed: bool = True
    error_reason: str | None = None
    task_reasons: Mapping[int, str] = field(default_factory=dict)
    task_goals: Mapping[int, tuple[float, float]] = field(default_factory=dict)
    stream_problems: tuple[Evidence, ...] = ()
    #: False for a run that recorded no mission (an imported bag): it is complete without SIG_MISSION_END.
    mission_recorded: bool = True
    #: The zone change each signal stands for, as its pattern declares it (rei.evaluation.utilities).
    transitions: Mapping[str, Transition] = field(default_factory=lambda: DEFAULT_TRANSITIONS)
    person_collisions: tuple[PersonCollision, ...] | None = None

    @property
    def began(self) -> bool:
        return any(s.signal == SIG_MISSION_BEGIN for s in self.signals)

    @property
    def ended(self) -> bool:
        """SIG_MISSION_END was received: the mission ran to its end and the monitor followed it there."""
        return any(s.signal == SIG_MISSION_END for s in self.signals)

    def data_gaps(self, stream: str) -> list[Signal]:
        """The monitor's SIG_MONITOR_DATA_GAP for input stream ``state`` or ``mission``."""
        return [s for s in self.signals if s.signal == SIG_MONITOR_DATA_GAP and s.object == stream]

    def incomplete(self) -> Evidence | None:
        """Why the run can not vouch for a requirement over the whole mission, or None."""
        if not self.completed:
            reason = self.error_reason or "no reason given"
            return Evidence(f"the run ended in ERROR: {reason}", self.end_time)
        if not self.ended and self.mission_recorded:
            return Evidence("the run ended without SIG_MISSION_END: the mission was not observed to its end",
                            self.end_time)
        return None
