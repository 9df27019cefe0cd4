# SPDX-License-Identifier: EPL-2.0
"""Shrinking a failure, as property-based testing shrinks a counterexample: greedily, one step at a time, keeping
each step that still fails the same way (same requirement, same element, same place).

Steps, in order: remove each object and human the failure does not name, then move each parameter back to the
base case's value. Each step is one candidate (validated and checked like any other) and, when valid, one
simulation; ``budget`` caps the simulations per failure. The shrunk case is written to
``OUT/shrunk/shrunk-<n>.rei`` with its run in ``OUT/shrunk/runs/<n>-<step>/``.
"""

from __future__ import annotations

import json
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from rei.campaign.results import make_result, write_result
from rei.search.candidates import VALID, Candidate, CandidateMaker
from rei.search.failures import Failure, failures_of
from rei.search.pool import Pool
from rei.search.space import Space

#: Evaluates a candidate: its run's folder and case folder give the failures it shows (None: not simulated).
Check = Callable[[Candidate, str], "list[Failure] | None"]


@dataclass(frozen=True, slots=True)
class Shrunk:
    case: str | None
    values: dict[str, Any]
    removed: list[str]
    steps: int  # simulations spent
    kept: int  # steps that kept the failure
    run: str | None

    def to_dict(self) -> dict[str, Any]:
        return {"case": self.case, "values": self.values, "removed": self.removed, "steps": self.steps,
                "kept": self.kept, "run": self.run}


def shrink(failure: Failure, values: Mapping[str, Any], space: Space, maker: CandidateMaker, pool: Pool,
           task_of: Callable[[str, Candidate, Path, Path], Any], out: Path, index: int, budget: int,
           log: Callable[[str], None] = print, seen: dict[str, tuple[list[str], str]] | None = None) -> Shrunk:
    """The smallest case found within ``budget`` simulations that still fails as ``failure`` does. ``seen``:
    the failures (signatures, run folder) of cases simulated while shrinking other failures, by their text; a
    case is not simulated twice."""
    seen = {} if seen is None else seen
    base = space.base_values()
    current = dict(values)
    removed: list[str] = []
    steps = kept = 0
    last_run: str | None = None
    folder = out / "shrunk"

    def fails(trial_values: dict[str, Any], trial_removed: list[str]) -> tuple[bool, str | None]:
        nonlocal steps
        key = f"{index}-{steps + 1}"
        candidate = maker.make(f"shrink-{key}", space.edit(trial_values, trial_removed))
        if candidate.status != VALID or candidate.text is None:
            return False, None
        if candidate.text in seen:
            signatures, known_run = seen[candidate.text]
            return failure.signature in signatures, known_run if failure.signature in signatures else None
        steps += 1
        case_dir, problem = maker.generate(candidate)
        if problem is not None:
            return False, None
        run_dir = folder / "runs" / key
        task = task_of(f"shrink-{key}", candidate, case_dir, run_dir)
        outcome = pool.submit(task).result()
        result = make_result(task, outcome)
        write_result(task, result)
        if result.status != "COMPLETED":
            return False, None
        summary = json.loads((run_dir / "summary.json").read_text(encoding="utf-8"))
        found = failures_of(summary, run_dir, case_dir, space.floor_at)
        seen[candidate.text] = ([f.signature for f in found], str(run_dir))
        same = any(f.signature == failure.signature for f in found)
        log(f"  shrink {index} step {steps}: {'still fails' if same else 'passes or fails otherwise'}")
        return same, str(run_dir) if same else None

    # removals first, as property-based shrinkers delete before they simplify: the biggest reduction per step
    for element in space.removable():
        if steps >= budget:
            break
        if element == failure.element:
            continue
        ok, run = fails(current, [*removed, element])
        if ok:
            removed, kept, last_run = [*removed, element], kept + 1, run
    for name in [k for k in current if current[k] != base.get(k)]:
        if steps >= budget:
            break
        attempt = {**current, name: base.get(name)}
        ok, run = fails(attempt, removed)
        if ok:
            current, kept, last_run = attempt, kept + 1, run
    final = maker.make(f"shrunk-{index}", space.edit(current, removed))
    path: Path | None = folder / f"shrunk-{index}.rei"
    if final.status == VALID and path is not None:
        path.parent.mkdir(parents=True, exist_ok=True)
        maker.write(final, path)
    else:  # every kept step was valid, and so was the start: only a changed engine gets here
        path = None
    return Shrunk(None if path is None else str(path), dict(current), removed, steps, kept, last_run)
