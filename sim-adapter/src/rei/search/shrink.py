# SPDX-License-Identifier: EPL-2.0
"""Shrinking a failure, as property-based testing shrinks a counterexample: greedily, one step at a time, keeping
each step that still fails the same way: the same event (kind, element, place: rei.search.failures), violating at
least the requirements it did.

Steps, in order: remove each object, human, crowd and group the failure does not name (a crowd's person names its
crowd), then the extra pieces of furniture (the last first), then move each parameter back to the base case's
value, but a crowd's or a group's count (first of them) towards its fewest people (as many as the failure's
person needs; then halfway), a crowd's rate towards its slowest, and a fault on a timeline towards a shorter
duration, then a later start (rei.search.space.SHRINK_STEPS of the way to the spec's range's end, boldest first). Each step is one candidate (validated and checked like any other) and, when valid, one
simulation; ``budget`` caps the simulations per failure. The shrunk case is written to
``OUT/shrunk/<id>.rei`` with its runs in ``OUT/shrunk/runs/<id>-<step>/``, ``<id>`` the failure's (``failure_id``):
named by what failed, not by its rank, which a resumed search with a larger budget may change.
"""

from __future__ import annotations

import hashlib
import json
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from rei.campaign.results import make_result, write_result
from rei.search.candidates import VALID, Candidate, CandidateMaker
from rei.search.failures import Failure, failures_of
from rei.search.pool import Pool
from rei.search.space import Space

#: The number of extra pieces of furniture (rei.search.space).
EXTRA_COUNT = "furniture.count"
#: What makes a run: the .rei text, the seed and the laser fault (the last two are not in the text, only in the
#: header ``CandidateMaker.write`` adds, so two candidates with one text but another seed are two cases).
Case = tuple[str | None, int, str | None]


def failure_id(signature: str) -> str:
    """A distinct failure's name in file names, the same in every invocation: its signature's parts joined by ``-``
    (other characters than letters, digits, ``_`` and ``.`` as ``_``) and 6 hex digits of the signature's hash, which
    keep apart two signatures that read alike (``COLLISION/walker/F_2_1``: ``COLLISION-walker-F_2_1-4a4421``)."""
    readable = "-".join(re.sub(r"[^A-Za-z0-9_.]", "_", part) for part in signature.split("/"))
    return f"{readable[:80]}-{hashlib.sha256(signature.encode('utf-8')).hexdigest()[:6]}"


def case_of(candidate: Candidate) -> Case:
    return candidate.text, candidate.edit.seed, candidate.edit.fault


@dataclass(frozen=True, slots=True)
class Shrunk:
    case: str | None
    values: dict[str, Any]
    removed: list[str]
    steps: int  # simulations spent
    kept: int  # reductions kept (each still fails the same way)
    run: str | None
    fault: str | None = None  # the shrunk case's --fault (its reproduce line has it too)

    def to_dict(self) -> dict[str, Any]:
        return {"case": self.case, "values": self.values, "removed": self.removed, "steps": self.steps,
                "kept": self.kept, "run": self.run, "fault": self.fault}


def shrink(failure: Failure, values: Mapping[str, Any], space: Space, maker: CandidateMaker, pool: Pool,
           task_of: Callable[[str, Candidate, Path, Path], Any], out: Path, failure_name: str, budget: int,
           log: Callable[[str], None] = print, seen: dict[Case, tuple[list[Failure], str]] | None = None,
           run: str | None = None) -> Shrunk:
    """The smallest case found within ``budget`` simulations that still fails as ``failure`` does; ``run``: the
    run that showed the failure (the shrunk case's run while no reduction is kept). ``seen``: the failures
    (events, run folder) of cases simulated while shrinking other failures, by case (``case_of``); a case is
    not simulated twice. ``failure_name``: the failure's name in file names (``failure_id``)."""
    seen = {} if seen is None else seen
    current = dict(values)
    removed: list[str] = []
    steps = kept = 0
    current_run = run
    folder = out / "shrunk"

    def fails(trial_values: dict[str, Any], trial_removed: list[str]) -> tuple[bool, str | None, Case | None]:
        """Whether the case still fails the same way, the run that shows it, and the case."""
        nonlocal steps
        key = f"{failure_name}-{steps + 1}"
        candidate = maker.make(f"shrink-{key}", space.edit(trial_values, trial_removed))
        if candidate.status != VALID or candidate.text is None:
            return False, None, None
        case = case_of(candidate)
        if case == current_case:
            return True, current_run, case
        if case in seen:
            events, known_run = seen[case]
            same = any(event.shows(failure) for event in events)
            return same, known_run if same else None, case
        case_dir, problem = maker.generate(candidate)
        if problem is not None:  # nothing was simulated: said, and not counted as a simulation
            log(f"  shrink {failure.signature}: a step not simulated: {problem}")
            return False, None, None
        steps += 1
        run_dir = folder / "runs" / key
        task = task_of(f"shrink-{key}", candidate, case_dir, run_dir)
        outcome = pool.submit(task).result()
        result = make_result(task, outcome)
        write_result(task, result)
        if result.status != "COMPLETED":
            log(f"  shrink {failure.signature} step {steps}: ended in ERROR, not kept: {result.error}")
            return False, None, None
        summary = json.loads((run_dir / "summary.json").read_text(encoding="utf-8"))
        found = failures_of(summary, run_dir, case_dir, space.floor_at)
        seen[case] = (found, str(run_dir))
        same = any(event.shows(failure) for event in found)
        log(f"  shrink {failure.signature} step {steps}: {'still fails' if same else 'passes or fails otherwise'}")
        return same, str(run_dir) if same else None, case

    def keep(attempt: dict[str, Any], attempt_removed: list[str]) -> bool:
        """Tries a smaller case; keeps it when it still fails (a step that leaves the case as it was is kept
        without counting: a value that has no effect, such as a removed piece's type)."""
        nonlocal current, removed, kept, current_run, current_case
        ok, run, case = fails(attempt, attempt_removed)
        if not ok:
            return False
        if case != current_case:
            kept, current_run, current_case = kept + 1, run, case
        current, removed = attempt, attempt_removed
        return True

    current_case = case_of(maker.make(f"shrink-{failure_name}-0", space.edit(current, removed)))
    # removals first, as property-based shrinkers delete before they simplify: the biggest reduction per step
    for element in space.removable():
        if steps >= budget:
            break
        if not space.owns(element, failure.element):  # a crowd's person fails with its crowd
            keep(current, [*removed, element])
    while int(current.get(EXTRA_COUNT) or 0) > 0 and steps < budget:  # extra furniture, the last piece first
        if not keep({**current, EXTRA_COUNT: int(current[EXTRA_COUNT]) - 1}, removed):
            break
    # the crowds' and groups' counts first: fewer people is the largest reduction of what is left
    for name in space.shrink_order(list(current)):
        # towards the base case's value; a crowd's or a group's count towards fewer people, a crowd's rate slower
        for value in space.smaller(name, current[name], failure.element):
            if value == current[name]:
                continue
            if steps >= budget or keep({**current, name: value}, removed):
                break
    final = maker.make(f"shrunk-{failure_name}", space.edit(current, removed))
    path: Path | None = folder / f"{failure_name}.rei"
    if final.status == VALID:
        path.parent.mkdir(parents=True, exist_ok=True)
        maker.write(final, path)
    else:  # every kept step was valid, and so was the start: only a changed engine gets here
        path = None
    return Shrunk(None if path is None else str(path), dict(current), removed, steps, kept, current_run,
                  final.edit.fault)
