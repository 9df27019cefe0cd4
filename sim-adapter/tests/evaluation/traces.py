# SPDX-License-Identifier: EPL-2.0
"""Hand-written signal traces: a builder that numbers the messages like the monitor does."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any

from rei.evaluation.context import CaseContext, VerdictSettings
from rei.evaluation.mission_info import MissionInfo
from rei.evaluation.outcome import Verdict
from rei.evaluation.signals import Signal
from rei.evaluation.trace import Trace
from rei.evaluation.verdicts import judge

#: world.json objects: one table, one wall, one human.
WORLD: dict[str, Any] = {"objects": [
    {"name": "table1", "category": "STATIC"}, {"name": "W_0_0_bottom", "category": "WALL"},
    {"name": "walker", "category": "HUMAN"}, {"name": "F_0_0", "category": "FLOOR"},
]}
MONITOR: dict[str, Any] = {"testcase": "Case", "requirements": {"maxHumanCollisions": 1}}
#: Two goals, from a start that differs from both: not a cycle.
MISSION: dict[str, Any] = {"name": "M", "testcase": "Case", "start": {"x": 0.5, "y": 0.5, "yaw": 0.0},
                           "goals": [{"index": 0, "x": 4.5, "y": 0.5, "yaw": 0.0, "tolerance": 0.25},
                                     {"index": 1, "x": 5.5, "y": 3.5, "yaw": 0.0, "tolerance": 0.25}]}


class TraceBuilder:
    """``b.at(t, "GEOM_FAR_TRANSIT_CLOSE", "table1")`` appends ``SIG_GEOM_FAR_TRANSIT_CLOSE``; seq counts."""

    def __init__(self) -> None:
        self.messages: list[dict[str, Any]] = []

    def at(self, t: float, name: str, obj: str = "x", distance: float = 0.0) -> TraceBuilder:
        signal = name if name.startswith("SIG_") else f"SIG_{name}"
        self.messages.append({"seq": len(self.messages), "t": float(t), "signal": signal, "subject": "tb3",
                              "object": obj, "distance": float(distance)})
        return self

    def begin(self, t: float = 0.0) -> TraceBuilder:
        return self.at(t, "MISSION_BEGIN", "mission").at(t, "MISSION_TASK_START", "task_0")

    def task(self, t: float, index: int, outcome: str = "SUCCESS", start_next: bool = True) -> TraceBuilder:
        """Task ``index`` ends with ``outcome``; the next task starts at the same time."""
        self.at(t, f"MISSION_TASK_{outcome}", f"task_{index}")
        return self.at(t, "MISSION_TASK_START", f"task_{index + 1}") if start_next else self

    def end(self, t: float, last_task: int = 1, outcome: str = "SUCCESS") -> TraceBuilder:
        return self.task(t, last_task, outcome, start_next=False).at(t, "MISSION_END", "mission")

    def geom(self, t: float, step: str, obj: str = "table1") -> TraceBuilder:
        return self.at(t, f"GEOM_{step}", obj)

    def laser(self, t: float, step: str) -> TraceBuilder:
        return self.at(t, f"LASER_{step}", "laser")


def nominal(*, collision_with: str | None = None, close: bool = True) -> TraceBuilder:
    """A two-goal mission: a confirmed CLOSE episode with table1 in task 0, optionally a collision in
    task 1."""
    b = TraceBuilder().begin()
    if close:
        b.geom(5.0, "FAR_TRANSIT_CLOSE").laser(5.1, "FAR_TRANSIT_CLOSE")
        b.geom(7.0, "CLOSE_TRANSIT_FAR").laser(7.1, "CLOSE_TRANSIT_FAR")
    b.task(10.0, 0)
    if collision_with is not None:
        b.geom(12.0, "FAR_TRANSIT_CLOSE", collision_with)
        b.geom(12.5, "CLOSE_TRANSIT_COLLISION", collision_with)
        b.laser(12.1, "FAR_TRANSIT_CLOSE").laser(12.9, "CLOSE_TRANSIT_COLLISION")
        b.geom(14.0, "COLLISION_TRANSIT_CLOSE", collision_with).laser(14.1, "COLLISION_TRANSIT_CLOSE")
        b.geom(15.0, "CLOSE_TRANSIT_FAR", collision_with).laser(15.1, "CLOSE_TRANSIT_FAR")
    return b.end(20.0)


def judge_trace(messages: Iterable[Mapping[str, Any]], *, mission: Mapping[str, Any] | None = MISSION,
                world: Mapping[str, Any] | None = WORLD, monitor: Mapping[str, Any] | None = MONITOR,
                settings: VerdictSettings | None = None, end_time: float | None = None,
                **trace: Any) -> dict[str, Verdict]:
    """The verdicts of a trace by requirement."""
    signals = tuple(Signal.from_message(m) for m in messages)
    end = end_time if end_time is not None else (signals[-1].t if signals else 0.0)
    info = MissionInfo.from_message(mission) if mission is not None else None
    context = CaseContext.from_configs(info, monitor, world, settings)
    return {v.requirement: v for v in judge(Trace(signals, end, **trace), context)}
