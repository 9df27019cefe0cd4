# SPDX-License-Identifier: EPL-2.0
"""What a finished run scores on the spec's objectives, read from its ``summary.json``.

Every objective is continuous where the run gives a slope (utility, time, the navigation metrics of
rei.evaluation.metrics, a signal's count or first time); a verdict is 0 when it fails and 1 when it holds, so a
search that minimizes it looks for the failure. A value the run does not have (a human clearance in a run
without humans, a signal that never came) scores as far from the worse side as the run allows, never as a finding.
"""

from __future__ import annotations

import csv
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

from rei.search.spec import Objective

#: Score of a value a run does not have, on the side the search moves away from.
ABSENT = 1e6


def present(value: float) -> bool:
    """Whether ``value`` is a run's own, not the score of one it does not have (left out of best values, charts
    and importance, where 10^6 would swamp every real figure)."""
    return abs(value) < ABSENT


def score(objectives: Sequence[Objective], summary: Mapping[str, Any], run_dir: Path) -> list[float]:
    return [_one(o, summary, run_dir) for o in objectives]


def _one(objective: Objective, summary: Mapping[str, Any], run_dir: Path) -> float:
    absent = ABSENT if objective.direction == "minimize" else -ABSENT
    if objective.kind == "utility":
        return float(summary.get("total_utility") or 0.0)
    if objective.kind == "time":
        return float(summary.get("sim_duration") or 0.0)
    if objective.kind == "metric":
        value = (summary.get("metrics") or {}).get(objective.key)
        if value is None:
            return absent
        return float(value)
    if objective.kind == "verdict":
        return 0.0 if failed_requirements(summary, objective.key) else 1.0
    if objective.kind == "signal":
        if objective.of == "count":
            return float((summary.get("counts") or {}).get(objective.key, 0))
        first = first_time(run_dir / "events.csv", objective.key)
        return absent if first is None else first
    raise AssertionError(objective)


def failed_requirements(summary: Mapping[str, Any], requirement: str = "any") -> list[str]:
    return [v["requirement"] for v in summary.get("verdicts") or []
            if v.get("status") == "fail" and requirement in ("any", v["requirement"])]


def first_time(events: Path, signal: str) -> float | None:
    """The time of the first ``signal`` in a run's events.csv (``t,signal,...``), None when it never came."""
    try:
        with open(events, newline="", encoding="utf-8") as f:
            for row in csv.DictReader(f):
                if row.get("signal") == signal:
                    return float(row["t"])
    except (OSError, ValueError, KeyError):
        return None
    return None


def better(objective: Objective, a: float, b: float) -> bool:
    """Whether ``a`` is further towards the search's side than ``b``."""
    return a < b if objective.direction == "minimize" else a > b
