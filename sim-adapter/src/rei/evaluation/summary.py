# SPDX-License-Identifier: EPL-2.0
"""``OUT/summary.json``: the run in one document - who, how long, how well (utility), what happened (signal
counts, tasks), which requirements held (verdicts with evidence) and whether the run itself completed.

Format ``rei-summary/1``; keys in the order below. ``status`` is the run's (COMPLETED or ERROR, with
``error``); the robot's performance is in ``total_utility``, ``tasks``, ``verdicts`` and ``metrics`` (the
navigation metrics of docs/metrics.md: every name of rei.evaluation.metrics.METRICS and ``task_times``, None
where one does not apply; all None with ``metrics_error`` saying why when the recording could not be measured).
"""

from __future__ import annotations

import json
import os
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from rei.evaluation.outcome import Evidence, Status, Verdict

FORMAT = "rei-summary/1"


@dataclass(frozen=True, slots=True)
class TaskRecord:
    index: int
    outcome: str  # SUCCESS, FAIL, or RUNNING (started, no final state)
    started: float | None
    ended: float | None
    reason: str | None

    def to_dict(self) -> dict[str, Any]:
        return {"index": self.index, "outcome": self.outcome, "started": self.started, "ended": self.ended,
                "reason": self.reason}


@dataclass(frozen=True, slots=True)
class Summary:
    mission: str | None
    testcase: str | None
    run_id: str
    status: str
    error: str | None
    sim_duration: float
    wall_time: float
    total_utility: float
    signals: int
    counts: Mapping[str, int]
    unknown_signals: Mapping[str, int]
    goals: int | None
    tasks: tuple[TaskRecord, ...]
    verdicts: tuple[Verdict, ...]
    problems: tuple[Evidence, ...] = ()
    utility_source: str = "defaults"
    files: Mapping[str, str] = field(default_factory=dict)
    metrics: Mapping[str, Any] = field(default_factory=dict)
    metrics_error: str | None = None
    faults: tuple[Any, ...] = ()  # rei.evaluation.faults.FaultWindow: the run's fault windows, from its signals

    @property
    def tasks_started(self) -> int:
        return len(self.tasks)

    @property
    def exit_code(self) -> int:
        """0: every verdict passes (or does not apply); 1: a verdict fails; 2: the run ended in ERROR, or no verdict
        fails but one is an error (nothing proven wrong, nothing vouched for: a CI job must not go green on it)."""
        if self.status != "COMPLETED":
            return 2
        if any(v.status == Status.FAIL for v in self.verdicts):
            return 1
        return 2 if any(v.status == Status.ERROR for v in self.verdicts) else 0

    @property
    def tasks_succeeded(self) -> int:
        return sum(t.outcome == "SUCCESS" for t in self.tasks)

    @property
    def tasks_failed(self) -> int:
        return sum(t.outcome == "FAIL" for t in self.tasks)

    def verdict(self, requirement: str) -> Verdict:
        return next(v for v in self.verdicts if v.requirement == requirement)

    def to_dict(self) -> dict[str, Any]:
        return {
            "format": FORMAT,
            "mission": self.mission,
            "testcase": self.testcase,
            "run_id": self.run_id,
            "status": self.status,
            "error": self.error,
            "sim_duration": self.sim_duration,
            "wall_time": self.wall_time,
            "total_utility": self.total_utility,
            "utilities": self.utility_source,
            "signals": self.signals,
            "counts": dict(sorted(self.counts.items())),
            "unknown_signals": dict(sorted(self.unknown_signals.items())),
            "tasks": {"goals": self.goals, "started": self.tasks_started, "succeeded": self.tasks_succeeded,
                      "failed": self.tasks_failed, "list": [t.to_dict() for t in self.tasks]},
            "verdicts": [v.to_dict() for v in self.verdicts],
            "verdict_counts": {str(s): sum(v.status == s for v in self.verdicts) for s in Status},
            "metrics": dict(self.metrics),
            "metrics_error": self.metrics_error,
            "problems": [p.to_dict() for p in self.problems],
            "files": dict(self.files),
            # only when a fault had a window: runs without faults keep the summary they always had
            **({"faults": [f.to_dict() for f in self.faults]} if self.faults else {}),
        }

    def write(self, path: str | os.PathLike[str]) -> Path:
        """Write atomically (temporary file, then rename): a reader never sees half a summary."""
        path = Path(path)
        tmp = path.with_name(path.name + ".tmp")
        tmp.write_text(json.dumps(self.to_dict(), indent=2, allow_nan=False) + "\n", encoding="utf-8")
        os.replace(tmp, path)
        return path
