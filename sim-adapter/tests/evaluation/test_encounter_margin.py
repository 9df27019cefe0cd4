# SPDX-License-Identifier: EPL-2.0
"""rei.evaluation.metrics.encounter against margins derived by hand and against a brute-force oracle.

The analytic cases: the robot's rectangle (half sizes HX along its heading, HY across) drives straight at speed
``u`` and passes a point O at ``tp``; a human (a circle of radius r) walks straight across its lane at O at speed
``w`` and is at O at ``c``. With ``s = t - tp``, ``sigma = tau - c`` and ``R = r + threshold``, the pair (t, tau)
conflicts when the circle's centre is nearer than R to the rectangle::

    (u|s| - HX)+^2 + (w|sigma| - HY)+^2 < R^2

(``(.)+`` the positive part): a rounded rectangle in the (s, sigma) plane. ``t - tau = s - sigma - (c - tp)``,
and ``s - sigma`` takes every value in (-M, M) on it, where M, the largest ``s + |sigma|``, is reached with both
parts positive: ``max p/u + q/w`` on ``p^2 + q^2 <= R^2`` is ``R sqrt(1/u^2 + 1/w^2)``, so::

    M = HX/u + HY/w + R sqrt(1/u^2 + 1/w^2)        margin = max(0, |c - tp| - M)

The metric samples that set (the robot's records every DT; the schedule at those times, and every STEP before and
after them), so it can only be as small as this infimum and at most DT + STEP above it.
"""

from __future__ import annotations

import math
import shutil
from pathlib import Path

import numpy as np
import pytest

from rei.artifacts import AnimatedObject, AnimationSpec, Category, ControlPoint
from rei.evaluation.metrics.compute import measure, measure_encounters
from rei.evaluation.metrics.encounter import STEP, Encounter, encounters
from rei.spline import Trajectory
from rei.wamp.recording import RecordingWriter, stream_path

ROBOT = (0.281, 0.306)  # the Waffle's footprint
HX, HY = ROBOT[0] / 2, ROBOT[1] / 2
RADIUS = 0.25  # the catalogue's Human: a cylinder of 0.5 m
THRESHOLD = 0.01  # monitor.json's collision threshold
DT = 0.05  # the robot's sample step (the simulator's 20 Hz state)
TOL = DT + STEP + 1e-9
EPS = 1e-9
HUMAN = (np.array([0.0, 0.0, 0.0, 2 * RADIUS, 2 * RADIUS]), True)  # a footprint row as in world.json


def nearest(spec: AnimationSpec, footprints: dict[str, tuple[np.ndarray, bool]], t: np.ndarray, pose: np.ndarray,
            threshold: float = THRESHOLD) -> Encounter | None:
    """The encounter of least margin over the humans, as compute.py takes encounter_margin_humans."""
    return min(encounters(spec, footprints, t, pose, ROBOT, threshold), key=lambda e: e.margin, default=None)


def least(spec: AnimationSpec, footprints: dict[str, tuple[np.ndarray, bool]], t: np.ndarray, pose: np.ndarray,
          threshold: float = THRESHOLD) -> float | None:
    found = nearest(spec, footprints, t, pose, threshold)
    return found.margin if found is not None else None


def extent(u: float, w: float, threshold: float = THRESHOLD) -> float:
    """M of the module docstring: how far apart in time the two passages may be and still conflict."""
    return HX / u + HY / w + (RADIUS + threshold) * math.hypot(1 / u, 1 / w)


def analytic(delay: float, u: float, w: float, threshold: float = THRESHOLD) -> float:
    return max(0.0, abs(delay) - extent(u, w, threshold))


def animation(*objects: AnimatedObject) -> AnimationSpec:
    return AnimationSpec(Path("animation.json"), objects)


def walker(name: str, points: list[tuple[float, float, float]], loop: bool = False,
           category: Category = Category.HUMAN) -> AnimatedObject:
    return AnimatedObject(name, category, loop, tuple(ControlPoint(t, x, y, None) for t, x, y in points))


class Lane:
    """The robot driving along ``heading`` through O = (1, 2) at speed ``u``, there at ``tp``, recorded every DT
    from 0 to ``end``; humans cross the lane at O, perpendicular to it."""

    ORIGIN = np.array([1.0, 2.0])

    def __init__(self, u: float, tp: float, end: float, heading: float = 0.0) -> None:
        self.u, self.tp, self.heading = u, tp, heading
        self.along = np.array([math.cos(heading), math.sin(heading)])
        self.across = np.array([-math.sin(heading), math.cos(heading)])
        self.t = np.arange(0.0, end + EPS, DT)
        centres = self.ORIGIN + np.outer(u * (self.t - tp), self.along)
        self.pose = np.column_stack((centres, np.full(len(self.t), heading)))

    def crossing(self, name: str, c: float, w: float, half: float = 3.0) -> AnimatedObject:
        """A human walking across the lane at speed ``w``, at O at ``c``: once, from ``half`` metres on one side to
        ``half`` on the other (where it waits before and stays after, out of reach)."""
        start, stop = self.ORIGIN - half * self.across, self.ORIGIN + half * self.across
        return walker(name, [(c - half / w, *start), (c + half / w, *stop)])

    def margin(self, spec: AnimationSpec, threshold: float = THRESHOLD,
               names: tuple[str, ...] | None = None) -> float | None:
        names = names if names is not None else tuple(o.name for o in spec.objects)
        return least(spec, dict.fromkeys(names, HUMAN), self.t, self.pose, threshold)


@pytest.mark.parametrize("heading", [0.0, 0.7, -2.0])
@pytest.mark.parametrize(("u", "w"), [(0.5, 1.0), (0.26, 1.4)])
@pytest.mark.parametrize("delay", [-6.0, -2.5, 1.7, 4.0, 9.0])
def test_a_human_crossing_too_early_or_too_late(delay: float, u: float, w: float, heading: float) -> None:
    lane = Lane(u, tp=10.0, end=20.0, heading=heading)
    expected = analytic(delay, u, w)
    m = lane.margin(animation(lane.crossing("h", lane.tp + delay, w)))
    assert m is not None and expected - EPS <= m <= expected + TOL, (m, expected)


@pytest.mark.parametrize("threshold", [0.01, 0.3])
def test_the_collision_threshold_widens_the_conflict(threshold: float) -> None:
    lane = Lane(0.5, tp=10.0, end=20.0)
    m = lane.margin(animation(lane.crossing("h", 14.0, 1.0)), threshold)
    expected = analytic(4.0, 0.5, 1.0, threshold)
    assert m is not None and expected - EPS <= m <= expected + TOL
    assert abs(analytic(4.0, 0.5, 1.0, 0.3) - analytic(4.0, 0.5, 1.0, 0.01)) > 3 * TOL  # the cases differ


@pytest.mark.parametrize("delay", [0.0, 0.3, -0.5])
def test_a_human_on_time_met_the_robot(delay: float) -> None:
    lane = Lane(0.5, tp=10.0, end=20.0, heading=0.4)
    assert analytic(delay, 0.5, 1.0) == 0  # well inside M (about 1.0 s)
    assert lane.margin(animation(lane.crossing("h", lane.tp + delay, 1.0))) == 0.0


@pytest.mark.parametrize("delay", [15.0, 60.0, 300.0])
def test_a_human_who_sets_off_after_the_run_scores_the_delay(delay: float) -> None:
    """Setting off at ``touch`` the human would just touch the robot; setting off ``delay`` later (after the run
    ended at 20 s), the margin is ``delay``: 300 s too late scores 300, not the same as 60 s too late."""
    lane = Lane(0.5, tp=10.0, end=20.0)
    half, w = 3.0, 1.0
    touch = lane.tp + extent(0.5, w) - half / w
    setoff = touch + delay
    assert setoff > lane.t[-1]
    m = lane.margin(animation(lane.crossing("h", setoff + half / w, w, half)))
    assert m is not None and delay - EPS <= m <= delay + TOL, (m, delay)


# A loop up and down the line x = X through the robot's lane (y = 0), one control point a second: -4 .. 4 .. -2
# and back to -4 (the closing segment lasts a second too, the period is 8 s). Between the points +-2 its knot
# velocities all equal the chords' 2 m/s, so the Catmull-Rom is exactly straight and uniform there: it crosses the
# lane upwards at 2 + 8n s and downwards at 6 + 8n s, at w = 2 m/s.
LOOP_Y = [-4.0, -2.0, 0.0, 2.0, 4.0, 2.0, 0.0, -2.0]
X = 5.0


def test_a_loop_counts_its_next_period_after_the_run() -> None:
    spline = Trajectory(list(range(8)), [(X, y) for y in LOOP_Y], loop=True)
    assert spline.period == 8.0
    for tau, y in ((10.1, 0.2), (9.8, -0.4), (14.2, -0.4), (5.9, 0.2)):  # the premise: uniform around crossings
        assert spline.position(tau) == pytest.approx((X, y), abs=1e-12)
    u, w, tp = 1.0, 2.0, 8.9
    t = np.arange(0.0, 9.5 + EPS, DT)  # the run ends at 9.5 s: the crossing at 10 s is after it, 1.1 s after tp
    pose = np.column_stack((X + u * (t - tp), np.zeros_like(t), np.zeros_like(t)))
    points = [(float(k), X, y) for k, y in enumerate(LOOP_Y)]
    looped = least(animation(walker("h", points, loop=True)), {"h": HUMAN}, t, pose)
    expected = analytic(10.0 - tp, u, w)
    assert looped is not None and expected - EPS <= looped <= expected + TOL
    # walked once, the same human stands at y = -2 from 7 s: only the crossings at 2 and 6 s are left
    once = least(animation(walker("h", points)), {"h": HUMAN}, t, pose)
    expected_once = analytic(6.0 - tp, u, w)
    assert once is not None and expected_once - EPS <= once <= expected_once + TOL
    assert once - looped > 1.5


@pytest.mark.parametrize("loop", [True, False])
def test_a_schedule_that_crossed_the_lane_before_the_run(loop: bool) -> None:
    """The same walk three seconds earlier: it crosses the lane upwards at -1 s (a loop at -1 + 8n s), downwards at
    3 s; the robot, recorded from -0.5 s, passes at 0.2 s. The nearest meeting is the crossing before the run, 1.2 s
    early: the human had to set off later by 1.2 s less M (0.69 s), not earlier by the 2.8 s to the crossing at 3 s
    less M (2.30 s). A loop repeats before its first point as after it, and a walk once that began before the
    run's first sample was walking then too."""
    spline = Trajectory([k - 3.0 for k in range(8)], [(X, y) for y in LOOP_Y], loop)
    for tau, y in ((-0.9, 0.2), (-1.2, -0.4), (2.8, 0.4), (3.2, -0.4)):  # the premise: uniform around crossings
        assert spline.position(tau) == pytest.approx((X, y), abs=1e-12)
    u, w, tp = 1.0, 2.0, 0.2
    t = np.arange(-0.5, 2.0 + EPS, DT)
    pose = np.column_stack((X + u * (t - tp), np.zeros_like(t), np.zeros_like(t)))
    found = nearest(animation(walker("h", [(k - 3.0, X, y) for k, y in enumerate(LOOP_Y)], loop)), {"h": HUMAN},
                    t, pose)
    expected = analytic(-1.0 - tp, u, w)
    assert expected == pytest.approx(0.69, abs=0.01) and analytic(3.0 - tp, u, w) == pytest.approx(2.30, abs=0.01)
    assert found is not None and expected - EPS <= found.margin <= expected + TOL, (found, expected)
    assert found.shift == found.margin  # later: the robot came after the human had crossed


def test_a_human_waits_at_the_first_point_before_setting_off() -> None:
    """A walk once that sets off after the run, from the middle of the robot's lane: during the run the human
    stood there, so it met the robot. (Earlier schedule times than the run's first sample add nothing to a walk
    that begins after it: the human stands at the same first point there, further in time from every sample.)"""
    lane = Lane(0.5, tp=10.0, end=20.0)
    away = walker("h", [(25.0, *lane.ORIGIN), (30.0, *(lane.ORIGIN + 5 * lane.across))])
    found = nearest(animation(away), {"h": HUMAN}, lane.t, lane.pose)
    assert found is not None and found.margin == 0.0 and found.shift == 0.0


@pytest.mark.parametrize("arrival", [15.0, 40.0, 3.0])
def test_a_human_whose_last_point_is_where_the_robot_stopped(arrival: float) -> None:
    """The robot drives to P = (3, 0), stands there from 6 s, the run ends at 8 s; a human walks up to P from the
    side at 1 m/s and stays. Arriving after the run, the margin is the time from the run's end until the circle
    reaches the footprint (within HY + R of P); standing there before the robot came, it met the robot."""
    t = np.arange(0.0, 8.0 + EPS, DT)
    pose = np.column_stack((np.minimum(0.5 * t, 3.0), np.zeros_like(t), np.zeros_like(t)))
    spec = animation(walker("h", [(arrival - 3.0, 3.0, -3.0), (arrival, 3.0, 0.0)]))
    m = least(spec, {"h": HUMAN}, t, pose)
    reaches = arrival - (HY + RADIUS + THRESHOLD)  # the first time the circle is that close
    expected = max(0.0, reaches - t[-1])
    assert m is not None and expected - EPS <= m <= expected + STEP + EPS, (m, expected)
    if arrival < 6.0:
        assert m == 0.0


def test_a_person_standing_for_minutes_beside_a_robot_held_for_minutes() -> None:
    """A robot held for 300 s (20 Hz) beside a person who waits there 300 s before setting off (and one who arrived
    there 300 s before the run and stays): 6001 samples against 6001 schedule times within reach, 36 million
    pairs if each were measured; a standing person is one place over an interval of schedule times. 0.5 m beside
    the robot's side the circle is 0.097 m off its footprint, no conflict; the first setting off towards the robot
    at 0.2 m/s from 310 s conflicts once within HY + R of it, (0.5 - HY - R) / 0.2 s later: it had to set off that
    much earlier than 310 s, 10 s after the run's end."""
    t = np.arange(0.0, 300.0 + EPS, DT)
    pose = np.zeros((len(t), 3))
    beside = (0.0, 0.5)
    closer = walker("closer", [(310.0, *beside), (312.0, 0.0, 0.1)])
    stays = walker("stays", [(-300.0, 0.0, 8.0), (-290.0, *beside)])
    found = encounters(animation(closer, stays), {"closer": HUMAN, "stays": HUMAN}, t, pose, ROBOT, THRESHOLD)
    expected = 310.0 + (0.5 - (HY + RADIUS + THRESHOLD)) / 0.2 - t[-1]
    assert [e.human for e in found] == ["closer"]
    assert found[0].shift == -found[0].margin and expected - EPS <= found[0].margin <= expected + STEP + EPS


def test_nobody_near_the_robots_path_has_no_margin() -> None:
    lane = Lane(0.5, tp=10.0, end=20.0)
    # a human walking a parallel lane 1 m to the side: 1 - HY - R = 0.59 m from the footprint at best
    side = lane.ORIGIN + lane.across
    parallel = walker("side", [(0.0, *(side - 5 * lane.along)), (20.0, *(side + 5 * lane.along))])
    assert lane.margin(animation(parallel)) is None
    # a cart on time through the lane is no human; a human the recording did not publish is left out
    cart = lane.crossing("cart", lane.tp, 1.0)
    cart = AnimatedObject(cart.name, Category.DYNAMIC, cart.loop, cart.points)
    assert lane.margin(animation(parallel, cart)) is None
    assert lane.margin(animation(parallel, lane.crossing("hidden", lane.tp, 1.0)), names=("side",)) is None
    # no robot samples
    assert least(animation(parallel), {"side": HUMAN}, np.empty(0), np.empty((0, 3))) is None


def test_the_least_margin_over_the_humans() -> None:
    lane = Lane(0.5, tp=10.0, end=20.0, heading=1.2)
    spec = animation(lane.crossing("late", lane.tp + 6.0, 1.0), lane.crossing("early", lane.tp - 3.0, 1.2),
                     walker("far", [(0.0, 50.0, 50.0), (5.0, 60.0, 50.0)]))
    expected = analytic(-3.0, 0.5, 1.2)
    m = lane.margin(spec)
    assert m is not None and expected - EPS <= m <= expected + TOL


# -- against a brute-force oracle ---------------------------------------------------------------------------------


def oracle(trajectory: Trajectory, t: np.ndarray, pose: np.ndarray, threshold: float) -> tuple[float, float] | None:
    """The least |t_k - tau| by brute force, and its tau: every robot sample against the schedule every 0.01 s from
    the run's start (so at the metric's times too, which it can only be below) and at the samples' own times, from
    two periods before the run to two periods after it (a loop), or from 5 s
    before the earlier of the run's and the schedule's starts to 5 s after the later of their ends (once), with the
    circle's distance to the rectangle computed here."""
    if trajectory.loop:
        low, high = t[0] - 2 * trajectory.period, t[-1] + 2 * trajectory.period
    else:
        low, high = min(t[0], trajectory.start) - 5.0, max(t[-1], trajectory.end) + 5.0
    taus = np.union1d(t[0] + 0.01 * np.arange(math.floor((low - t[0]) / 0.01), math.ceil((high - t[0]) / 0.01)), t)
    places = np.array([trajectory.position(float(tau)) for tau in taus])
    # a place outside the robot's box of positions widened by 1 m is over 1 m from all of them: no conflict
    inside = ((places >= pose[:, :2].min(axis=0) - 1.0) & (places <= pose[:, :2].max(axis=0) + 1.0)).all(axis=1)
    taus, places = taus[inside], places[inside]
    dx = places[None, :, 0] - pose[:, None, 0]
    dy = places[None, :, 1] - pose[:, None, 1]
    cos, sin = np.cos(pose[:, 2])[:, None], np.sin(pose[:, 2])[:, None]
    along, across = np.abs(cos * dx + sin * dy), np.abs(-sin * dx + cos * dy)  # the centre in the robot's frame
    distance = np.hypot(np.maximum(along - HX, 0.0), np.maximum(across - HY, 0.0))
    conflict = distance < RADIUS + threshold
    if not conflict.any():
        return None
    k, j = np.nonzero(conflict)
    best = np.argmin(np.abs(t[k] - taus[j]))
    return float(abs(t[k[best]] - taus[j[best]])), float(taus[j[best]])


def test_random_walks_against_the_brute_force_oracle() -> None:
    """Curved robot drives (an arc at a random turn rate) against random Catmull-Rom schedules around them, which
    may begin before the run, during it or after it."""
    rng = np.random.default_rng(20261126)
    seen = {"none": 0, "zero": 0, "positive": 0, "before the run": 0}
    for _ in range(60):
        t = np.arange(0.0, 10.0 + EPS, DT)
        speed, turn = rng.uniform(0.2, 0.6), rng.uniform(-0.3, 0.3)
        yaw = rng.uniform(-math.pi, math.pi) + turn * t
        step = speed * DT * np.column_stack((np.cos(yaw), np.sin(yaw)))
        xy = np.vstack(([0.0, 0.0], np.cumsum(step, axis=0)[:-1]))
        pose = np.column_stack((xy, yaw))
        n = int(rng.integers(2, 6))
        times = np.cumsum(rng.uniform(1.0, 6.0, n)) + rng.uniform(-8.0, 8.0)
        points = xy[rng.integers(0, len(t), n)] + rng.normal(0.0, 1.0, (n, 2))
        loop = bool(rng.integers(0, 2))
        threshold = float(rng.choice([0.01, 0.1]))
        human = walker("h", [(float(s), float(x), float(y)) for s, (x, y) in zip(times, points, strict=True)], loop)
        m = least(animation(human), {"h": HUMAN}, t, pose, threshold)
        found = oracle(Trajectory(list(times), [tuple(p) for p in points], loop), t, pose, threshold)
        if found is None:
            assert m is None
            seen["none"] += 1
            continue
        expected, tau = found
        assert m is not None and expected - EPS <= m <= expected + TOL, (m, expected)
        seen["zero" if expected == 0 else "positive"] += 1
        seen["before the run"] += int(tau < t[0] - TOL)
    assert min(seen.values()) >= 3, seen  # every kind of outcome is exercised


# -- from a run folder ----------------------------------------------------------------------------------------------

FIXTURE = Path(__file__).resolve().parents[1] / "fixtures" / "room6x4"  # its human h1 loops around (2.5, 2.3)


def run_folder(tmp_path: Path, begin: float) -> Path:
    """The fixture's case and a 14 s recording: the robot stands at (1.5, 2.3) until 2 s, where h1 passes it at
    the start of its loop, then drives along y = 1, about 0.9 m from anywhere h1 walks; the mission begins at ``begin``."""
    run = tmp_path / f"run-{begin}"
    shutil.copytree(FIXTURE, run / "case")
    with RecordingWriter(stream_path(run, "state")) as writer:
        for k in range(281):
            t = round(k * DT, 6)
            x, y = (1.5, 2.3) if t < 2.0 else (1.0 + 0.25 * (t - 2.0), 1.0)
            writer.write({"t": t, "robot": {"pose": [x, y, 0.0, 0.0], "twist": [0.25, 0.0, 0.0], "odom": [x, y]},
                          "objects": [{"name": "h1", "pose": [0.0, 0.0, 0.85, 0.0]}], "contacts": []})
    with RecordingWriter(stream_path(run, "mission")) as writer:
        writer.write({"t": begin, "event": "BEGIN"})
        writer.write({"t": 14.0, "event": "END"})
    return run


def test_a_run_folders_encounters_alone_are_measured_in_the_missions_window(tmp_path: Path) -> None:
    """measure_encounters (the search's refinement) reads and cuts the run as measure does: the meeting before the
    mission's BEGIN is out of the window."""
    whole, cut = run_folder(tmp_path, 0.0), run_folder(tmp_path, 2.0)
    met = (Encounter("h1", 0.0),)
    assert measure_encounters(whole) == measure(whole).encounters == met
    assert measure(whole).metrics["encounter_margin_humans"] == 0.0
    assert measure_encounters(cut) == measure(cut).encounters == ()
    assert measure(cut).metrics["encounter_margin_humans"] is None


@pytest.mark.parametrize("damage", ["missing", "not JSON"])
def test_an_unreadable_animation_is_a_note_not_a_silent_empty_margin(tmp_path: Path, damage: str) -> None:
    run = run_folder(tmp_path, 0.0)
    animation = run / "case" / "animation.json"
    if damage == "missing":
        animation.unlink()
    else:
        animation.write_text("{", encoding="utf-8")
    measured = measure(run)
    assert measured.metrics["encounter_margin_humans"] is None and measured.encounters == ()
    assert len(measured.notes) == 1 and measured.notes[0].startswith(str(animation))
    assert "encounter_margin_humans has no value" in measured.notes[0]
    assert ("missing" if damage == "missing" else "not valid JSON") in measured.notes[0]
    assert measure_encounters(run) == ()

