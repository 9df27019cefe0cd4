# SPDX-License-Identifier: EPL-2.0
"""Failures: each failed verdict of an evaluation, and the distinct ones over the search.

A failure is one failed requirement with the element the first evidence naming one names (a human, an object, a
wall) and the floor whose centre is nearest to the robot at that evidence's time (else at the first timed
evidence's); two evaluations fail the same way when these three agree. Distinct failures are ranked by severity: the lowest total utility any of their evaluations had (utility falls with every
collision and failed task: thesis Table 4), then how often they were found.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

from rei.evaluation.outcome import Evidence, Status, Verdict
from rei.evaluation.verdicts import REQUIREMENTS
from rei.search.reproduce import reproduce


@dataclass(frozen=True, slots=True)
class Failure:
    requirement: str
    element: str  # what the first evidence names ("-": nothing)
    place: str  # the floor the robot was on then ("-": unknown)
    t: float | None
    message: str

    @property
    def signature(self) -> str:
        return f"{self.requirement}/{self.element}/{self.place}"

    def to_dict(self) -> dict[str, Any]:
        return {**asdict(self), "signature": self.signature}

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> Failure:
        return cls(data["requirement"], data["element"], data["place"], data.get("t"), data.get("message", ""))


def failures_of(summary: Mapping[str, Any], run_dir: Path, case_dir: Path,
                floor_at: Callable[[float, float], str]) -> list[Failure]:
    """The failed verdicts of a finished run, each placed where the robot was at its first evidence."""
    failed = [v for v in summary.get("verdicts") or [] if v.get("status") == "fail"]
    if not failed:
        return []
    robot = _robot_track(run_dir, case_dir)
    found = []
    for verdict in failed:
        evidence = verdict.get("evidence") or []
        # the element from the first evidence naming one (a verdict may open with a timed line naming nothing, and
        # the same collision would then be grouped apart from its runs whose evidence names the object first)
        named = next((e for e in evidence if e.get("object")), {})
        t = named.get("t")
        if t is None:
            t = next((e["t"] for e in evidence if e.get("t") is not None), None)
        place = "-"
        if t is not None and robot is not None:
            pose = robot.at(float(t))
            if pose is not None:
                place = floor_at(pose[0], pose[1])
        found.append(Failure(verdict["requirement"], str(named.get("object") or "-"), place,
                             None if t is None else round(float(t), 3), str(verdict.get("message", ""))))
    return found


def _robot_track(run_dir: Path, case_dir: Path) -> Any:
    from rei.report.run_data import load_run
    from rei.report.tracks import collect_tracks

    try:
        return collect_tracks(load_run(run_dir, case_dir).states()).robot
    except (OSError, ValueError):
        return None


@dataclass(slots=True)
class DistinctFailure:
    """Every evaluation that failed one way; ``first`` is the one the report shows and shrinking starts from."""

    failure: Failure
    keys: list[str]
    worst_utility: float
    first: str

    @property
    def severity(self) -> float:
        return -self.worst_utility


def distinct(evaluations: Sequence[Mapping[str, Any]]) -> list[DistinctFailure]:
    """The distinct failures of ``evaluations`` (search.json's records, in order), most severe first."""
    groups: dict[str, DistinctFailure] = {}
    for record in evaluations:
        utility = float(record.get("utility") or 0.0)
        for item in record.get("failures") or []:
            failure = Failure.from_dict(item)
            group = groups.get(failure.signature)
            if group is None:
                groups[failure.signature] = DistinctFailure(failure, [record["key"]], utility, record["key"])
            else:
                group.keys.append(record["key"])
                group.worst_utility = min(group.worst_utility, utility)
    return sorted(groups.values(), key=lambda g: (-g.severity, -len(g.keys), g.failure.signature))


#: The test case of ``verdicts.xml`` when no failure was found.
NO_FAILURE = "no failure found"


def failure_verdicts(groups: Sequence[DistinctFailure], cases: Mapping[str, str], simulated: int = 0,
                     errors: int = 0) -> list[Verdict]:
    """One failing verdict per distinct failure for ``verdicts.xml`` (rei.evaluation.junit), named by its
    signature, its message and evidence ending with the `rei run` line that reproduces it (``cases``: signature ->
    the saved ``.rei``, whose header has the line: rei.search.reproduce). With none,
    one verdict saying so over the ``simulated`` evaluations: a pass, or an error when some of them (``errors``)
    or all ended in ERROR, as `rei search` exits 2 then (nothing vouched for)."""
    if not groups:
        judged = simulated - errors
        message = f"no failure found in {simulated} evaluation(s)" + (f", {errors} in ERROR" if errors else "")
        return [Verdict(NO_FAILURE, Status.ERROR if errors or not judged else Status.PASS, message)]
    verdicts = []
    for group in groups:
        f = group.failure
        case = cases.get(f.signature)
        line = "?" if case is None else reproduce(case)
        verdicts.append(Verdict(f.signature, Status.FAIL, f"{f.message} (reproduce: {line})", (
            Evidence(f"{REQUIREMENTS.get(f.requirement, f.requirement)}; the robot on {f.place}", t=f.t,
                     object=None if f.element == "-" else f.element),
            Evidence(f"found in {len(group.keys)} evaluation(s): {', '.join(group.keys)}"),
            Evidence(f"reproduce: {line}"))))
    return verdicts
