# SPDX-License-Identifier: EPL-2.0
"""The high-level requirements of thesis Table 4 (section 5.1.2), judged on one run's signals.

Each requirement gets one Verdict: pass, fail, error or not-applicable, with the evidence that decided it.
The precise semantics are in docs/evaluation.md; in short:

- GEOM_CLOSE_LASER_CORRECT / GEOM_COLLISION_LASER_CORRECT: every geometric episode in CLOSE (or COLLISION)
  must overlap a laser episode in the same zone or be at most ``tolerance`` seconds apart from one, and
  every laser episode must be so matched by a geometric one (else it is a false alarm); episodes that start
  in the last ``tolerance`` seconds of the run are undecided.
- MISSION_SIMPLE: no geometric collision (SIG_GEOM_*_TRANSIT_COLLISION) during the mission, on any leg.
- MISSION_SEQUENCE: every goal got its final state from the robot: TASK_START then exactly one TASK_SUCCESS
  or TASK_FAIL, in goal order, before SIG_MISSION_END; a timeout (the robot gave no feedback) or a "false
  success" (the robot's feedback was wrong, thesis 5.2.1) fails it.
- MISSION_SEQUENCE_CYCLE: as MISSION_SIMPLE, applicable only to back-and-forth missions (g1, g2)*.
- MISSION_WITH_HUMAN_TRAJECTORY: collisions with HUMAN objects < N_COLLISION; applicable with humans only.
- NO_ROBOT_AT_FAULT_COLLISION (REI's own, after Table 4): in no collision with a person was the robot at fault,
  moving towards the person's centre faster than AT_FAULT_SPEED at the collision's first recorded state sample or
  the one before (rei.evaluation.metrics.social); applicable with humans only.

Integrity: a lost or malformed signal, an inconsistent transition, or SIG_MONITOR_DATA_GAP of a stream the
requirement depends on makes it ``error``, and so does a run that did not end with SIG_MISSION_END (or ended
in ERROR) - never ``pass``. A violation that the missing data can not explain away (a collision that was
seen, a false success) still makes it ``fail``.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

from rei.evaluation.context import CaseContext
from rei.evaluation.episodes import Episode, Timeline, build_timeline
from rei.evaluation.faults import FAULT_SIGNAL
from rei.evaluation.metrics.social import AT_FAULT_SPEED, PersonCollision
from rei.evaluation.outcome import Evidence, Status, Verdict
from rei.evaluation.signals import (
    SIG_MISSION_TASK_FAIL,
    SIG_MISSION_TASK_START,
    SIG_MISSION_TASK_SUCCESS,
    Signal,
    Source,
    Transition,
    Zone,
)
from rei.evaluation.trace import Trace

GEOM_CLOSE_LASER_CORRECT = "GEOM_CLOSE_LASER_CORRECT"
GEOM_COLLISION_LASER_CORRECT = "GEOM_COLLISION_LASER_CORRECT"
MISSION_SIMPLE = "MISSION_SIMPLE"
MISSION_SEQUENCE = "MISSION_SEQUENCE"
MISSION_SEQUENCE_CYCLE = "MISSION_SEQUENCE_CYCLE"
MISSION_WITH_HUMAN_TRAJECTORY = "MISSION_WITH_HUMAN_TRAJECTORY"
NO_ROBOT_AT_FAULT_COLLISION = "NO_ROBOT_AT_FAULT_COLLISION"

#: Table 4, in the thesis's order, then REI's own, with their short descriptions (the JUnit test cases'
#: documentation).
REQUIREMENTS: dict[str, str] = {
    GEOM_CLOSE_LASER_CORRECT: "The robot correctly measures the close event",
    GEOM_COLLISION_LASER_CORRECT: "The robot correctly measures the collision event",
    MISSION_SIMPLE: "The robot moves to the neighboring floor without collision",
    MISSION_SEQUENCE: "The robot feeds back information about all goals",
    MISSION_SEQUENCE_CYCLE: "The robot never collides in a mission where it moves back and forth",
    MISSION_WITH_HUMAN_TRAJECTORY: "The robot avoids collision with a human following a trajectory",
    NO_ROBOT_AT_FAULT_COLLISION: "The robot never drives into a person",
}

#: TASK_FAIL reasons (rei.mission.executor) that mean the robot's feedback was missing or wrong.
_NO_FEEDBACK_REASONS = ("timeout", "false success", "no result")  # the last: a bag's goal (rei.bags.mission)
#: Distance within which two goals are the same place when their tolerance is unknown (mission.xml default).
_DEFAULT_GOAL_TOLERANCE = 0.25
#: How far (s) a collision signal's time may be from the first recorded state sample of the same collision: the
#: monitor's signal carries the time of the state message that made it (to its clock's millisecond), so half a
#: sample at the default 20 Hz is generous.
_SAME_SAMPLE = 0.025


def judge(trace: Trace, context: CaseContext) -> tuple[Verdict, ...]:
    """All Table 4 verdicts, in REQUIREMENTS order."""
    timeline = build_timeline(trace.signals, trace.transitions)
    collisions = _collisions(trace.signals, trace.transitions)
    return (
        _laser(GEOM_CLOSE_LASER_CORRECT, Zone.CLOSE, trace, timeline, context),
        _laser(GEOM_COLLISION_LASER_CORRECT, Zone.COLLISION, trace, timeline, context),
        _mission_simple(trace, timeline, context, collisions),
        _mission_sequence(trace, timeline, context),
        _mission_cycle(trace, timeline, context, collisions),
        _human_trajectory(trace, timeline, context, collisions),
        _robot_at_fault(trace, timeline, context, collisions),
    )


# -- integrity ---------------------------------------------------------------------------------------------

def _problems(trace: Trace, timeline: Timeline, streams: tuple[str, ...], sources: tuple[Source, ...]
              ) -> list[Evidence]:
    """Why the signals can not be trusted to be complete for a requirement that reads the monitor's input
    ``streams`` (state, mission) and the zones of ``sources``."""
    found = [*trace.stream_problems, *timeline.inconsistent(*sources)]
    for stream in streams:
        found.extend(
            Evidence(f"the monitor lost {s.distance:g} {stream} message(s) before this time", s.t, s.signal,
                     s.object)
            for s in trace.data_gaps(stream)
        )
    return found


def _decide(requirement: str, *, violations: list[Evidence], problems: list[Evidence],
            trace: Trace, fail_message: str, pass_message: str, pass_evidence: list[Evidence],
            violations_stand: bool, doubtful: list[Evidence] | None = None) -> Verdict:
    """The common rule: proven violations fail; otherwise missing data or an incomplete run is an error.

    ``violations_stand``: the violations remain violations whatever data is missing (a collision that was
    seen); else missing data turns them into an error. ``doubtful``: violations that only count when the
    data is complete and the mission was observed to its end (a goal without feedback).
    """
    doubtful = doubtful or []
    if violations and (violations_stand or not problems):
        return Verdict(requirement, Status.FAIL, fail_message, (*violations, *doubtful, *problems))
    if problems:
        return Verdict(requirement, Status.ERROR,
                       f"cannot judge: {len(problems)} problem(s) with the observed data, first: "
                       f"{problems[0].text}", (*problems, *violations, *doubtful))
    incomplete = trace.incomplete()
    if incomplete is not None:
        return Verdict(requirement, Status.ERROR, f"cannot judge: {incomplete.text}",
                       (incomplete, *doubtful, *pass_evidence))
    if doubtful:
        return Verdict(requirement, Status.FAIL, fail_message, tuple(doubtful))
    return Verdict(requirement, Status.PASS, pass_message, tuple(pass_evidence))


# -- laser correctness -------------------------------------------------------------------------------------

def _laser(requirement: str, level: Zone, trace: Trace, timeline: Timeline, context: CaseContext) -> Verdict:
    settings = context.settings
    if not settings.laser:
        return Verdict(requirement, Status.NOT_APPLICABLE, "the run published no laser data")
    tol, end = settings.tolerance, trace.end_time
    zone = level.name
    entry = "SIG_GEOM_FAR_TRANSIT_CLOSE" if level == Zone.CLOSE else "SIG_GEOM_CLOSE_TRANSIT_COLLISION"
    laser_entry = entry.replace("GEOM", "LASER")
    geometry, laser = timeline.of(Source.GEOM, level), timeline.of(Source.LASER, level)
    confirmed: list[Evidence] = []
    notes: list[Evidence] = []
    violations: list[Evidence] = []
    for g in geometry:
        match = next((sensed for sensed in laser if _overlap(g, sensed, tol, end)), None)
        span = _span(g, end)
        if match is not None:
            confirmed.append(Evidence(
                f"geometry {zone} with {g.object} {span}; the laser reached {zone} at t={match.start:.3f} "
                f"(latency {match.start - g.start:+.3f} s)", g.start, entry, g.object))
        elif g.start + tol > end:
            notes.append(Evidence(f"geometry {zone} with {g.object} {span} began in the last {tol:g} s of "
                                  f"the run: undecided, not judged", g.start, entry, g.object))
        else:
            violations.append(Evidence(
                f"missed: geometry {zone} with {g.object} {span}, but the laser did not reach {zone} "
                f"within {tol:g} s of it", g.start, entry, g.object))
    for sensed in laser:
        if any(_overlap(g, sensed, tol, end) for g in geometry):
            continue
        if sensed.start + tol > end:
            notes.append(Evidence(f"laser {zone} {_span(sensed, end)} began in the last {tol:g} s of the "
                                  f"run: undecided, not judged", sensed.start, laser_entry, sensed.object))
        else:
            violations.append(Evidence(
                f"false alarm: the laser reported {zone} {_span(sensed, end)} with no geometric {zone} "
                f"within {tol:g} s", sensed.start, laser_entry, sensed.object))
    misses = sum(e.text.startswith("missed") for e in violations)
    return _decide(
        requirement, violations=violations, trace=trace, violations_stand=False,
        problems=_problems(trace, timeline, ("state",), (Source.GEOM, Source.LASER)),
        fail_message=f"{misses} geometric {zone} episode(s) missed by the laser, "
                     f"{len(violations) - misses} laser false alarm(s)",
        pass_message=f"{len(confirmed)} geometric {zone} episode(s) confirmed by the laser, no false alarm "
                     f"({len(notes)} not judged)",
        pass_evidence=[*confirmed, *notes])


def _overlap(a: Episode, b: Episode, tol: float, end: float) -> bool:
    """The two intervals overlap or are at most ``tol`` seconds apart."""
    return a.start - tol <= b.end_or(end) and b.start - tol <= a.end_or(end)


def _span(episode: Episode, end: float) -> str:
    until = f"{episode.end:.3f}" if episode.end is not None else f"the end of the run ({end:.3f})"
    return f"from t={episode.start:.3f} to {until}"


# -- collisions --------------------------------------------------------------------------------------------

@dataclass(frozen=True, slots=True)
class _Collision:
    signal: Signal
    task: int | None
    faults: tuple[str, ...] = ()  # the fault windows open then ("laser blackout"), from the SIG_FAULT_ signals

    @property
    def during(self) -> str:
        when = f"during task {self.task}" if self.task is not None else "outside any task"
        verb = "was" if len(self.faults) == 1 else "were"
        return when + (f", while {' and '.join(self.faults)} {verb} active" if self.faults else "")

    def evidence(self, what: str = "collision") -> Evidence:
        return self.fact(f"{what} with {self.signal.object} at t={self.signal.t:.3f} {self.during}")

    def fact(self, text: str) -> Evidence:
        """``text`` as evidence at this collision's time, signal, object and task."""
        return Evidence(text, self.signal.t, self.signal.signal, self.signal.object, self.task)


def _collisions(signals: tuple[Signal, ...], transitions: Mapping[str, Transition], *,
                per_object: bool = False) -> list[_Collision]:
    """Geometric entries into COLLISION, each with the task running then (by the mission signals): the robot's
    (Table 2), or with ``per_object`` each object's, where a second object while the robot already collides counts
    too and an object's repeated entry does not."""
    found: list[_Collision] = []
    task: int | None = None
    colliding: set[str] = set()
    active: list[str] = []  # a collision during a fault is reported with it (docs/faults.md)
    for s in signals:
        if s.signal == SIG_MISSION_TASK_START:
            task = s.task_index
        elif s.signal in (SIG_MISSION_TASK_SUCCESS, SIG_MISSION_TASK_FAIL):
            task = None
        elif (fault := FAULT_SIGNAL.match(s.signal)) is not None:
            name = f"{fault[1].lower()} {fault[2].lower()}"
            if fault[3] == "BEGIN":
                active.append(name)
            elif name in active:
                active.remove(name)
        step = transitions.get(s.signal)
        if step is None or step.per_object != per_object or step.source != Source.GEOM:
            continue
        if step.after == Zone.COLLISION and not (per_object and s.object in colliding):
            colliding.add(s.object)
            found.append(_Collision(s, task, tuple(dict.fromkeys(active))))
        elif step.after < Zone.COLLISION:
            colliding.discard(s.object)
    return found


def _object_collisions(signals: tuple[Signal, ...], transitions: Mapping[str, Transition]) -> list[_Collision] | None:
    """The per-object collisions; None when the run's rules publish no per-object signal (hand-written rules)."""
    if not any(s.signal in transitions and transitions[s.signal].per_object for s in signals):
        return None
    return _collisions(signals, transitions, per_object=True)


def _no_collision(requirement: str, trace: Trace, timeline: Timeline, collisions: list[_Collision],
                  scope: list[Evidence]) -> Verdict:
    return _decide(
        requirement, violations=[c.evidence() for c in collisions],
        problems=_problems(trace, timeline, ("state",), (Source.GEOM,)), trace=trace, violations_stand=True,
        fail_message=f"{len(collisions)} collision(s), first with {collisions[0].signal.object} at "
                     f"t={collisions[0].signal.t:.3f}" if collisions else "",
        pass_message=f"no collision in {trace.end_time:.1f} s", pass_evidence=scope)


def _mission_simple(trace: Trace, timeline: Timeline, context: CaseContext,
                    collisions: list[_Collision]) -> Verdict:
    if context.mission is not None and not context.mission.goals:
        return Verdict(MISSION_SIMPLE, Status.NOT_APPLICABLE, "the mission has no goals")
    scope = [Evidence(f"legs observed: {_legs(trace)}; geometric COLLISION entries: 0")]
    return _no_collision(MISSION_SIMPLE, trace, timeline, collisions, scope)


def _mission_cycle(trace: Trace, timeline: Timeline, context: CaseContext,
                   collisions: list[_Collision]) -> Verdict:
    if not context.settings.mission:
        return Verdict(MISSION_SEQUENCE_CYCLE, Status.NOT_APPLICABLE, _NO_MISSION)
    path = _path(trace, context)
    if path is None:
        return Verdict(MISSION_SEQUENCE_CYCLE, Status.ERROR,
                       "cannot judge: the goals' positions are unknown (no mission_info, no mission events)")
    cycle = _back_and_forth(path)
    description = " -> ".join(f"({x:.2f}, {y:.2f})" for x, y, _ in path)
    if not cycle:
        return Verdict(MISSION_SEQUENCE_CYCLE, Status.NOT_APPLICABLE,
                       f"the mission is not a back-and-forth cycle (g1, g2)*: {description}",
                       (Evidence(f"path: {description}"),))
    scope = [Evidence(f"back-and-forth path: {description}")]
    return _no_collision(MISSION_SEQUENCE_CYCLE, trace, timeline, collisions, scope)


def _human_trajectory(trace: Trace, timeline: Timeline, context: CaseContext,
                      collisions: list[_Collision]) -> Verdict:
    requirement = MISSION_WITH_HUMAN_TRAJECTORY
    if not context.humans:
        return Verdict(requirement, Status.NOT_APPLICABLE, "no human in the simulation")
    n = context.n_collision
    if n is None:
        return Verdict(requirement, Status.ERROR, f"cannot judge: {context.n_collision_problem}")
    hits = _human_collisions(trace, context, collisions)
    humans = ", ".join(sorted(context.humans))
    return _decide(
        requirement, violations=[c.evidence("human collision") for c in hits] if len(hits) >= n else [],
        problems=_problems(trace, timeline, ("state",), (Source.GEOM,)), trace=trace, violations_stand=True,
        fail_message=f"{len(hits)} collision(s) with humans, not fewer than N_COLLISION = {n}",
        pass_message=f"{len(hits)} collision(s) with humans ({humans}), fewer than N_COLLISION = {n}",
        pass_evidence=[c.evidence("human collision") for c in hits]
        or [Evidence(f"no collision with {humans}; N_COLLISION = {n}")])


def _human_collisions(trace: Trace, context: CaseContext, collisions: list[_Collision]) -> list[_Collision]:
    """The collisions with humans: per object (a human who bumps a robot already touching a wall counts), or the
    robot-level ones when the run's rules publish no per-object signal."""
    per_object = _object_collisions(trace.signals, trace.transitions)
    return [c for c in (per_object if per_object is not None else collisions) if c.signal.object in context.humans]


def _robot_at_fault(trace: Trace, timeline: Timeline, context: CaseContext,
                    collisions: list[_Collision]) -> Verdict:
    """The collisions with humans the signals show (as MISSION_WITH_HUMAN_TRAJECTORY counts them), each judged by
    the recorded state at its first sample and the one before: the robot is at fault when it moved towards the
    person's centre faster than AT_FAULT_SPEED, else the person walked into a robot that stood or moved away."""
    requirement = NO_ROBOT_AT_FAULT_COLLISION
    if not context.humans:
        return Verdict(requirement, Status.NOT_APPLICABLE, "no human in the simulation")
    at_fault: list[tuple[_Collision, PersonCollision]] = []
    judged: list[Evidence] = []
    unjudged: list[Evidence] = []
    for hit in _human_collisions(trace, context, collisions):
        person, t = hit.signal.object, hit.signal.t
        measured = _measured(hit, trace.person_collisions)
        if measured is None or math.isnan(measured.approach):
            why = ("the recorded state was not measured (summary.json's metrics_error says why)"
                   if trace.person_collisions is None else
                   "no collision with them begins in the recorded state then" if measured is None else
                   "the robot's velocity was not recorded then")
            unjudged.append(hit.fact(f"collision with {person} at t={t:.3f} {hit.during}: cannot tell who was at "
                                     f"fault, {why}"))
        elif measured.robot_at_fault:
            at_fault.append((hit, measured))
        else:
            judged.append(hit.fact(f"person at fault: {person} walked into the robot at t={t:.3f} {hit.during}; "
                                   f"the robot moved towards them at {measured.approach:+.2f} m/s (stood or moved "
                                   f"away: at most {AT_FAULT_SPEED:g} m/s)"))
    violations = [hit.fact(f"robot at fault: it drove into {hit.signal.object} at {m.approach:.2f} m/s towards "
                           f"their centre (more than {AT_FAULT_SPEED:g} m/s) at t={hit.signal.t:.3f} {hit.during}")
                  for hit, m in at_fault]
    humans = ", ".join(sorted(context.humans))
    count = len(judged) + len(at_fault) + len(unjudged)
    first = at_fault[0] if at_fault else None
    return _decide(
        requirement, violations=violations, trace=trace, violations_stand=True,
        problems=[*_problems(trace, timeline, ("state",), (Source.GEOM,)), *unjudged],
        fail_message=f"{len(at_fault)} collision(s) with people with the robot at fault, first with "
                     f"{first[0].signal.object} at t={first[0].signal.t:.3f} ({first[1].approach:.2f} m/s "
                     f"towards them)" if first else "",
        pass_message=(f"{count} collision(s) with people ({humans}), none with the robot at fault" if count
                      else f"no collision with people ({humans})"),
        pass_evidence=judged or [Evidence(f"no collision with {humans}")])


def _measured(hit: _Collision, measured: tuple[PersonCollision, ...] | None) -> PersonCollision | None:
    """The collision the recorded state shows for the signalled one: the same person, beginning within
    _SAME_SAMPLE seconds of the signal (the nearest)."""
    near = [m for m in measured or () if m.person == hit.signal.object and abs(m.t - hit.signal.t) <= _SAME_SAMPLE]
    return min(near, key=lambda m: abs(m.t - hit.signal.t), default=None)


def _legs(trace: Trace) -> str:
    started = [s.task_index for s in trace.signals if s.signal == SIG_MISSION_TASK_START]
    return ", ".join(f"task {i}" for i in started) or "none"


def _path(trace: Trace, context: CaseContext) -> list[tuple[float, float, float]] | None:
    """Start (when known) and goals as ``(x, y, tolerance)``: mission_info, else the mission events."""
    if context.mission is not None and context.mission.goals:
        goals = [(g.x, g.y, g.tolerance or _DEFAULT_GOAL_TOLERANCE) for g in context.mission.goals]
        start = context.mission.start
    elif trace.task_goals:
        goals = [(*trace.task_goals[i], _DEFAULT_GOAL_TOLERANCE) for i in sorted(trace.task_goals)]
        start = None
    else:
        return None
    return ([(start[0], start[1], goals[0][2])] if start is not None else []) + goals


def _back_and_forth(path: list[tuple[float, float, float]]) -> bool:
    """(g1, g2)*: at least three points, each the same place as the one two before, the first two apart."""
    if len(path) < 3 or _same(path[0], path[1]):
        return False
    return all(_same(path[i], path[i - 2]) for i in range(2, len(path)))


def _same(a: tuple[float, float, float], b: tuple[float, float, float]) -> bool:
    return math.hypot(a[0] - b[0], a[1] - b[1]) <= max(a[2], b[2])


# -- mission sequence --------------------------------------------------------------------------------------

_NO_MISSION = "the run recorded no mission (an imported run without goals)"


def _mission_sequence(trace: Trace, timeline: Timeline, context: CaseContext) -> Verdict:
    requirement = MISSION_SEQUENCE
    if not context.settings.mission:
        return Verdict(requirement, Status.NOT_APPLICABLE, _NO_MISSION)
    starts: dict[int, list[float]] = {}
    finals: dict[int, list[Signal]] = {}
    facts: list[Evidence] = []
    expected, running = 0, None
    for s in trace.signals:
        index = s.task_index
        if s.signal == SIG_MISSION_TASK_START and index is not None:
            if running is not None:
                facts.append(Evidence(f"task {index} started while task {running} had no final state",
                                      s.t, s.signal, s.object, index))
            elif index != expected:
                facts.append(Evidence(f"task {index} started, expected task {expected} (goal order)",
                                      s.t, s.signal, s.object, index))
            starts.setdefault(index, []).append(s.t)
            running, expected = index, index + 1
        elif s.signal in (SIG_MISSION_TASK_SUCCESS, SIG_MISSION_TASK_FAIL) and index is not None:
            finals.setdefault(index, []).append(s)
            if running == index:
                running = None
    notes: list[Evidence] = []
    if context.mission is not None:
        count = len(context.mission.goals)
        if count == 0:
            return Verdict(requirement, Status.NOT_APPLICABLE, "the mission has no goals")
    else:
        count = max([*starts, *finals], default=-1) + 1
        notes.append(Evidence(f"mission information unavailable: judged on the {count} task(s) seen"))
    doubtful: list[Evidence] = []
    fed_back: list[Evidence] = []
    for index in range(count):
        if index not in starts:
            doubtful.append(Evidence(f"task {index} never started: no final state for goal {index}",
                                     task=index))
        elif index not in finals:
            began = starts[index][0]
            doubtful.append(Evidence(f"task {index} started at t={began:.3f} but has no final state", began,
                                     SIG_MISSION_TASK_START, f"task_{index}", index))
        elif len(finals[index]) > 1:
            facts.append(Evidence(f"task {index} has {len(finals[index])} final states", finals[index][1].t,
                                  finals[index][1].signal, f"task_{index}", index))
        else:
            final = finals[index][0]
            reason = trace.task_reasons.get(index)
            outcome = final.signal.removeprefix("SIG_MISSION_")
            detail = f" ({reason})" if reason else ""
            evidence = Evidence(f"task {index}: {outcome} at t={final.t:.3f}{detail}", final.t, final.signal,
                                final.object, index)
            if final.signal == SIG_MISSION_TASK_FAIL and reason and reason.startswith(_NO_FEEDBACK_REASONS):
                facts.append(Evidence(f"task {index}: no correct feedback from the robot: {outcome} at "
                                      f"t={final.t:.3f} ({reason})", final.t, final.signal, final.object,
                                      index))
            else:
                fed_back.append(evidence)
    for index in sorted(set(finals) - set(range(count))):
        facts.append(Evidence(f"task {index} is not a goal of the mission ({count} goals)",
                              finals[index][0].t, finals[index][0].signal, f"task_{index}", index))
    return _decide(
        requirement, violations=facts, problems=_problems(trace, timeline, ("mission",), ()), trace=trace,
        violations_stand=True, doubtful=doubtful,
        fail_message=f"{len(facts) + len(doubtful)} goal(s) without correct feedback"
                     f" (first: {(facts + doubtful)[0].text})" if facts or doubtful else "",
        pass_message=f"all {count} goal(s) got their final state in order",
        pass_evidence=[*fed_back, *notes])
