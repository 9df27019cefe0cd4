# SPDX-License-Identifier: EPL-2.0
"""Failures: what went wrong in an evaluation, as events, and the distinct ones over the search.

A user counts what happened, not how many requirements it broke: one collision with a person fails
MISSION_SIMPLE and MISSION_WITH_HUMAN_TRAJECTORY (and GEOM_COLLISION_LASER_CORRECT when the laser missed it), and
is one failure. So a failure is an *event*: what happened (its kind), with whom (the element) and where (the floor
whose centre is nearest to the robot then), with every requirement it violates. The evidence of a failed verdict
says what happened (rei.evaluation.outcome.Evidence): a line whose signal is the entry into a zone (a transition
the patterns declare, rei.evaluation.signals) names the object and the time, and the requirements whose evidence
names the same kind of entry with the same object in one run fail from the same event. Its kind is the zone
entered, ``COLLISION`` or ``CLOSE`` for the footprint geometry, ``LASER_COLLISION`` or ``LASER_CLOSE`` for the
laser (a false alarm), and it is placed where it first happened in the run. A failed verdict whose evidence names
no such entry (goals without correct feedback: a timeout, a false success) is an event of its own kind, the
requirement's name, with the element the first evidence naming one names (``task_0``) at that evidence's time
(else at the first timed evidence's). The signature reads ``COLLISION/walker/F_2_1``; two evaluations fail the same
way when their signatures agree. Distinct failures are ranked by severity: the lowest total utility any of their
evaluations had (utility falls with every collision and failed task: thesis Table 4), then how often they were
found.

Journals written before failures were events hold one record per failed requirement (``requirement``, no ``kind``);
``events_of`` finds such an evaluation's events again from its run folder, as a new run's are found.
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from rei.campaign.spec import SpecError
from rei.evaluation.outcome import Evidence, Status, Verdict
from rei.evaluation.signals import DEFAULT_TRANSITIONS, Source, Transition
from rei.evaluation.verdicts import GEOM_CLOSE_LASER_CORRECT, GEOM_COLLISION_LASER_CORRECT, REQUIREMENTS
from rei.search.reproduce import reproduce


@dataclass(frozen=True, slots=True)
class Failure:
    """One event of one evaluation and the requirements it violates (in Table 4's order)."""

    kind: str  # COLLISION, CLOSE, LASER_COLLISION, LASER_CLOSE, or a requirement's name (no event evidence)
    element: str  # with whom: the object the evidence names ("-": nothing)
    place: str  # the floor the robot was on then ("-": unknown)
    t: float | None
    requirements: tuple[str, ...]
    what: str  # the first evidence's sentence: "collision with walker at t=8.700 during task 0"
    message: str  # each requirement's verdict message: "MISSION_SIMPLE: 1 collision(s), ...; MISSION_WITH_..."

    @property
    def signature(self) -> str:
        return f"{self.kind}/{self.element}/{self.place}"

    def to_dict(self) -> dict[str, Any]:
        return {"signature": self.signature, "kind": self.kind, "element": self.element, "place": self.place,
                "t": self.t, "requirements": list(self.requirements), "what": self.what, "message": self.message}

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> Failure:
        if "kind" not in data:
            raise ValueError(f"a failure recorded per requirement ({data.get('requirement')}), before failures "
                             f"were events: read it through events_of")
        return cls(data["kind"], data["element"], data["place"], data.get("t"), tuple(data["requirements"]),
                   data.get("what", ""), data.get("message", ""))

    def shows(self, other: Failure) -> bool:
        """This event is ``other`` again: the same signature, violating at least the requirements it did (a
        shrunk case must fail the same way)."""
        return self.signature == other.signature and set(other.requirements) <= set(self.requirements)


def event_kind(transition: Transition | None) -> str | None:
    """``COLLISION``/``CLOSE`` for an entry of the footprint geometry, ``LASER_...`` for the laser's, None for
    anything else (a zone left, a mission signal, a data gap)."""
    if transition is None or transition.after <= transition.before:
        return None
    zone = transition.after.name
    return zone if transition.source == Source.GEOM else f"{transition.source}_{zone}"


_LASER = (GEOM_CLOSE_LASER_CORRECT, GEOM_COLLISION_LASER_CORRECT)


@dataclass(slots=True)
class _Event:
    kind: str
    element: str
    t: float | None
    what: str
    messages: dict[str, str] = field(default_factory=dict)

    def seen(self, t: float | None, what: str) -> None:
        if t is not None and (self.t is None or t < self.t):
            self.t, self.what = t, what


def failures_of(summary: Mapping[str, Any], run_dir: Path, case_dir: Path,
                floor_at: Callable[[float, float], str]) -> list[Failure]:
    """The events of a finished run's failed verdicts, each placed where the robot was when it first happened."""
    failed = [v for v in summary.get("verdicts") or [] if v.get("status") == "fail"]
    if not failed:
        return []
    transitions = _transitions(run_dir)
    events: dict[tuple[str, str], _Event] = {}
    # the laser requirements last: of evidence at the same time, the mission requirements' sentence says what
    # happened ("collision with walker at ..."), the laser's what it measured of it
    for verdict in sorted(failed, key=lambda v: str(v.get("requirement")) in _LASER):
        requirement = str(verdict["requirement"])
        message = str(verdict.get("message", ""))
        evidence = verdict.get("evidence") or []
        happened = [(kind, str(e.get("object") or "-"), e.get("t"), str(e.get("text", "")))
                    for e in evidence if (kind := event_kind(transitions.get(str(e.get("signal"))))) is not None]
        if not happened:
            # no event evidence: its own kind, with the element from the first evidence naming one (a verdict may
            # open with a timed line naming nothing) at its time, else at the first timed evidence's
            named = next((e for e in evidence if e.get("object")), {})
            t = named.get("t")
            if t is None:
                t = next((e["t"] for e in evidence if e.get("t") is not None), None)
            happened = [(requirement, str(named.get("object") or "-"), t, message)]
        for kind, element, t, what in happened:
            t = None if t is None else float(t)
            event = events.get((kind, element))
            if event is None:
                event = events[(kind, element)] = _Event(kind, element, t, what)
            event.seen(t, what)
            event.messages.setdefault(requirement, message)
    robot = _robot_track(run_dir, case_dir) if any(e.t is not None for e in events.values()) else None
    found = []
    for event in events.values():
        place = "-"
        if event.t is not None and robot is not None:
            pose = robot.at(event.t)
            if pose is not None:
                place = floor_at(pose[0], pose[1])
        requirements = ordered(event.messages)
        found.append(Failure(event.kind, event.element, place, None if event.t is None else round(event.t, 3),
                             requirements, event.what,
                             "; ".join(f"{r}: {event.messages[r]}" for r in requirements)))
    return sorted(found, key=lambda f: (f.t is None, f.t or 0.0, f.signature))


def ordered(requirements: Iterable[str]) -> tuple[str, ...]:
    """Requirements in Table 4's order, any other after them by name."""
    table = list(REQUIREMENTS)
    return tuple(sorted(set(requirements), key=lambda r: (table.index(r) if r in table else len(table), r)))


def _transitions(run_dir: Path) -> Mapping[str, Transition]:
    """What the run's patterns declare of their signals (utilities.json: the user's own patterns may declare zone
    changes too), over the defaults'."""
    from rei.evaluation.utilities import UtilityError, load_declared_transitions
    from rei.run.patterns import UTILITIES_FILE

    declared = run_dir / UTILITIES_FILE
    if not declared.is_file():
        return DEFAULT_TRANSITIONS
    try:
        return load_declared_transitions(declared)
    except (OSError, UtilityError):
        return DEFAULT_TRANSITIONS


def _robot_track(run_dir: Path, case_dir: Path) -> Any:
    from rei.report.run_data import load_run
    from rei.report.tracks import collect_tracks

    try:
        return collect_tracks(load_run(run_dir, case_dir).states()).robot
    except (OSError, ValueError):
        return None


# -- evaluations recorded before failures were events ---------------------------------------------------------

class OldRecordError(SpecError):
    """An evaluation recorded per requirement whose run folder can not be judged again."""


#: Events found again from run folders, by (run folder, its summary.json's mtime): search.json, the resume and the
#: shrinking all read the same evaluations.
_AGAIN: dict[tuple[str, int], list[dict[str, Any]]] = {}


def events_of(items: Sequence[Mapping[str, Any]], run_dir: Path) -> list[dict[str, Any]]:
    """An evaluation's recorded failures as events (``Failure.to_dict``). A journal written before failures were
    events has one record per failed requirement (``requirement`` and no ``kind``): that evaluation's events are
    found again from its run folder (its summary.json, the robot's track in its streams, the floors of its case's
    world.json), exactly as a new run's; OldRecordError (a SpecError: `rei search` exits 2) when the folder can not
    be read, rather than counting it otherwise."""
    if all("kind" in item for item in items):
        return [dict(item) for item in items]
    summary_path = run_dir / "summary.json"
    try:
        cached = (str(run_dir), summary_path.stat().st_mtime_ns)
        if cached not in _AGAIN:
            summary = json.loads(summary_path.read_text(encoding="utf-8"))
            case_dir = Path(json.loads((run_dir / "task.json").read_text(encoding="utf-8"))["case_dir"])
            floors: dict[str, tuple[float, float]] = {}

            def floor_at(x: float, y: float) -> str:  # the case's floors, read when an event has a place
                if not floors:
                    floors.update(_floors(case_dir))
                return min(floors, key=lambda name: math.dist(floors[name], (x, y)))

            found = failures_of(summary, run_dir, case_dir, floor_at)
            if not found:
                raise ValueError("its summary.json has no failed verdict, the journal has failures")
            _AGAIN[cached] = [f.to_dict() for f in found]
        return [dict(item) for item in _AGAIN[cached]]
    except (OSError, ValueError, KeyError, TypeError) as error:
        raise OldRecordError(
            f"{run_dir}: this evaluation was recorded by an earlier rei search, one failure per requirement; failures "
            f"are events now and are found again from the run folder, which can not be read ({error}): restore "
            f"the run folder, or give a new -o OUT") from None


def _floors(case_dir: Path) -> dict[str, tuple[float, float]]:
    from rei.artifacts.world import read_world

    floors = {f.name: f.center for f in read_world(case_dir / "world.json").floors}
    if not floors:
        raise ValueError(f"{case_dir / 'world.json'} has no floors")
    return floors



# -- distinct failures -----------------------------------------------------------------------------------------

@dataclass(slots=True)
class DistinctFailure:
    """Every evaluation that failed one way; ``first`` is the one the report shows and shrinking starts from;
    ``requirements``: every requirement the event violated in any of them."""

    failure: Failure
    keys: list[str]
    worst_utility: float
    first: str
    requirements: tuple[str, ...] = ()

    @property
    def severity(self) -> float:
        return -self.worst_utility


def distinct(evaluations: Sequence[Mapping[str, Any]]) -> list[DistinctFailure]:
    """The distinct failures of ``evaluations`` (search.json's records, in order, their failures events), most
    severe first."""
    groups: dict[str, DistinctFailure] = {}
    for record in evaluations:
        utility = float(record.get("utility") or 0.0)
        for item in record.get("failures") or []:
            failure = Failure.from_dict(item)
            group = groups.get(failure.signature)
            if group is None:
                groups[failure.signature] = DistinctFailure(failure, [record["key"]], utility, record["key"],
                                                            failure.requirements)
            else:
                group.keys.append(record["key"])
                group.worst_utility = min(group.worst_utility, utility)
                group.requirements = ordered((*group.requirements, *failure.requirements))
    return sorted(groups.values(), key=lambda g: (-g.severity, -len(g.keys), g.failure.signature))


#: The test case of ``verdicts.xml`` when no failure was found.
NO_FAILURE = "no failure found"


def failure_verdicts(groups: Sequence[DistinctFailure], cases: Mapping[str, str], simulated: int = 0,
                     errors: int = 0) -> list[Verdict]:
    """One failing verdict per distinct failure for ``verdicts.xml`` (rei.evaluation.junit), named by its
    signature, its message naming every requirement it violates and ending with the `rei run` line that
    reproduces it (``cases``: signature -> the saved ``.rei``, whose header has the line: rei.search.reproduce);
    its evidence: what happened, each requirement, the first evaluation's verdicts. With none,
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
        requirements = group.requirements or f.requirements
        where = "" if f.place == "-" else f", the robot on {f.place}"
        verdicts.append(Verdict(f.signature, Status.FAIL, (
            f"{f.what}{where}: fails {', '.join(requirements)} (reproduce: {line})"), (
            Evidence(f"{f.what}{where}", t=f.t, object=None if f.element == "-" else f.element),
            *(Evidence(f"fails {r}: {REQUIREMENTS.get(r, r)}") for r in requirements),
            Evidence(f"in {group.first}: {f.message}"),
            Evidence(f"found in {len(group.keys)} evaluation(s): {', '.join(group.keys)}"),
            Evidence(f"reproduce: {line}"))))
    return verdicts
