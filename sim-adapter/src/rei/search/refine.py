# SPDX-License-Identifier: EPL-2.0
"""Encounter-guided refinement: a near miss says how far to move the person who nearly met the robot.

The encounter margin (rei.evaluation.metrics.encounter) is the time a person's scheduled walk is off a meeting with
the robot, and its sign says which way: set off ``shift`` seconds later (earlier when negative) and the person is at
the conflict when the robot was. When the person's ``start`` is a parameter of the search, that is a step along the
objective's own slope that no sampler can take: TPE and CMA-ES only see values, not directions, and a meeting is a
window of a second or two in a range of minutes. So after an evaluation that did not fail in a new way, the search
enqueues its point with that person's start moved by the shift (Optuna's ``enqueue_trial``, so it is in the journal
and a resumed search neither loses nor repeats it). The robot reacts to people, so the meeting may move: the
refined point is refined again, up to ``DEPTH`` steps. The person chosen is the nearest one whose start is searched
and who has not yet been met in a failure, so the budget goes to meetings not found yet.
"""

from __future__ import annotations

from collections.abc import Collection, Mapping
from pathlib import Path
from typing import Any

from optuna.distributions import BaseDistribution, FloatDistribution

from rei.evaluation.metrics.compute import MetricsError, measure_encounters
from rei.evaluation.metrics.encounter import Encounter
from rei.search.spec import SearchSpec

#: The objective whose slope a refinement follows.
OBJECTIVE = "encounter_margin_humans"
#: Refinements of refinements at most: the robot's reaction moves the meeting by less each time.
DEPTH = 3
#: Shifts below this (s) are left to the sampler: the schedule is sampled at 0.05 s, a state at 0.05 s.
LEAST_SHIFT = 0.05
#: The user attribute of an enqueued refinement: its depth.
ATTR = "refinement"


def enabled(spec: SearchSpec) -> bool:
    """Refining follows the encounter margin down: on when it is an objective minimized and the sampler learns from
    points it did not draw (TPE and NSGA-II; CMA-ES would update its mean and step size from them as if it had
    drawn them; the random and quasi-random baselines' draws must stay their own)."""
    return spec.refine and spec.sampler in ("tpe", "nsga2") and any(
        o.kind == "metric" and o.key == OBJECTIVE and o.direction == "minimize" for o in spec.objectives)


def encounters(run_dir: Path, case_dir: Path) -> list[Encounter]:
    """Every human's encounter in a finished run; [] when it cannot be measured. Only the encounters are measured
    again, on the search loop's thread: not the other metrics the worker measured."""
    try:
        return list(measure_encounters(run_dir, case_dir))
    except MetricsError:
        return []


def refined(params: Mapping[str, Any], distributions: Mapping[str, BaseDistribution],
            found: list[Encounter], met: Collection[str]) -> tuple[dict[str, Any], Encounter] | None:
    """``params`` with the start of the nearest person not in ``met`` (else the nearest) moved by its shift, within
    its range; None when no searched start can move."""
    movable = [e for e in found if isinstance(distributions.get(f"{e.human}.start"), FloatDistribution)
               and abs(e.shift) >= LEAST_SHIFT]
    for encounter in sorted(movable, key=lambda e: (e.human in met, e.margin)):
        key = f"{encounter.human}.start"
        domain = distributions[key]
        assert isinstance(domain, FloatDistribution)
        start = min(max(float(params[key]) + encounter.shift, domain.low), domain.high)
        if abs(start - float(params[key])) >= LEAST_SHIFT:
            return {**params, key: start}, encounter
    return None
