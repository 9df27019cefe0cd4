# SPDX-License-Identifier: EPL-2.0
"""The record of one finished run (``OUT/runs/<key>/result.json``) and what resuming a campaign reads back.

A run is finished once its ``result.json`` exists, whether it COMPLETED or ended in ERROR (a crash, a timeout):
both are results of the campaign. A run stopped by an interruption gets no ``result.json`` and runs again on
resume. ``result.json`` is written last and atomically, so a campaign killed at any moment leaves no half
result behind.
"""

from __future__ import annotations

import json
import os
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

from rei.campaign.plan import TASK_FILE, RunTask, write_task
from rei.campaign.supervise import Outcome

RESULT_FILE = "result.json"
FORMAT = "rei-campaign-run/1"


@dataclass(frozen=True, slots=True)
class RunResult:
    key: str
    group: str
    case: str
    variant: str
    repetition: int
    seed: int
    humans: bool
    fault: str | None
    status: str  # COMPLETED or ERROR
    error: str | None
    wall_time: float  # of the worker process, seconds
    cpu_time: float  # of the worker and its children, plus its replay's thread in the warm monitor JVM (that JVM's
    # compiler and collector threads are in the campaign's total only); seconds
    host: str
    sim_duration: float | None = None
    total_utility: float | None = None
    mission_succeeded: bool | None = None
    tasks_started: int = 0
    tasks_succeeded: int = 0
    tasks_failed: int = 0
    counts: dict[str, int] = field(default_factory=dict)
    verdicts: dict[str, str] = field(default_factory=dict)
    timing: dict[str, Any] = field(default_factory=dict)
    metrics: dict[str, Any] = field(default_factory=dict)  # summary.json's navigation metrics (docs/metrics.md)
    attempt: int = 1  # which try gave this result (a Ray task lost with its node is tried again: rei.campaign.backends)

    def to_dict(self) -> dict[str, Any]:
        return {"format": FORMAT, **asdict(self)}

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> RunResult:
        return cls(**{k: v for k, v in data.items() if k != "format"})


def make_result(task: RunTask, outcome: Outcome) -> RunResult:
    """Combine how the worker ended with what the run wrote (summary.json, timing.json)."""
    run_dir = Path(task.run_dir)
    summary = _json(run_dir / "summary.json")
    error = outcome.error
    if error is None and summary is None:
        error = "crashed: the worker ended without writing summary.json"
    timing = _json(run_dir / "timing.json") or {}
    monitor = timing.get("monitor") or {}
    served = float(monitor.get("cpu", 0.0)) if monitor.get("served") else 0.0  # spent in the warm monitor JVM
    base: dict[str, Any] = {
        "key": task.key, "group": task.group, "case": task.case, "variant": task.variant,
        "repetition": task.repetition, "seed": task.seed, "humans": task.humans, "fault": task.fault,
        "wall_time": round(outcome.wall, 3), "cpu_time": round(outcome.cpu + served, 3), "host": outcome.host,
        "timing": timing, "attempt": outcome.attempt}
    if error is not None or summary is None:
        return RunResult(status="ERROR", error=error, **base)
    tasks = summary.get("tasks") or {}
    goals = tasks.get("goals")
    return RunResult(
        status=summary.get("status", "ERROR"), error=summary.get("error"), **base,
        sim_duration=summary.get("sim_duration"), total_utility=summary.get("total_utility"),
        mission_succeeded=goals is not None and tasks.get("succeeded") == goals,
        tasks_started=int(tasks.get("started") or 0), tasks_succeeded=int(tasks.get("succeeded") or 0),
        tasks_failed=int(tasks.get("failed") or 0), counts=dict(summary.get("counts") or {}),
        verdicts={v["requirement"]: v["status"] for v in summary.get("verdicts") or []},
        metrics=dict(summary.get("metrics") or {}))


def write_result(task: RunTask, result: RunResult) -> Path:
    """``result.json`` of the run. A run none of whose files arrived (a Ray task lost on each try, or with no node
    left to take it) has no folder yet: it gets one with its task.json, so it is recorded (runs.csv) as a run that
    ended in ERROR is, and --retry-errors redoes it."""
    path = Path(task.run_dir) / RESULT_FILE
    if not (path.parent / TASK_FILE).exists():
        write_task(task, path.parent)
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(json.dumps(result.to_dict(), indent=2) + "\n", encoding="utf-8")
    os.replace(tmp, path)
    return path


def finished_result(task: RunTask) -> RunResult | None:
    """The result of an earlier attempt at exactly this task (same task.json), or None."""
    run_dir = Path(task.run_dir)
    data, recorded = _json(run_dir / RESULT_FILE), _json(run_dir / TASK_FILE)
    if isinstance(recorded, dict) and "case_stamp" not in recorded:  # recorded before tasks carried it
        recorded["case_stamp"] = task.case_stamp
    if data is None or recorded != task.to_dict():
        return None
    try:
        return RunResult.from_dict(data)
    except TypeError:
        return None


def _json(path: Path) -> Any:
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
