# SPDX-License-Identifier: EPL-2.0
"""Where a reactive person heads: its route, waits and start, its way round the robot and its behaviours.

Pure logic, no model: the person is moved straight to where it heads, as far as its speed allows in a step."""

from __future__ import annotations

import itertools
import math

import pytest

from rei.artifacts.animation import Behaviour, PersonSpec, RouteStop
from rei.sim.people.walkers import (
    BLOCK_TIME,
    CLEARANCE,
    LINGER,
    NOTICE,
    SCARED_CLEARANCE,
    Queue,
    RobotView,
    Walker,
)

DT = 0.05
FAR = RobotView(x=100.0, y=100.0, yaw=0.0, vx=0.0, vy=0.0, front=0.15, radius=0.21)


def person(behaviour: Behaviour = Behaviour.AVOIDS, *, stops: tuple[tuple[float, float, float], ...] = (
        (0.0, 0.0, 0.0), (4.0, 0.0, 0.0)), loop: bool = False, start: float = 0.0, speed: float = 1.0) -> PersonSpec:
    return PersonSpec("p", behaviour, speed, start, loop, tuple(RouteStop(f"F{i}", x, y, w)
                                                               for i, (x, y, w) in enumerate(stops)))


def straight(a: tuple[float, float], b: tuple[float, float]) -> list[tuple[float, float]]:
    return [a, b]


def walker(spec: PersonSpec) -> Walker:
    stops = [(s.x, s.y) for s in spec.route]
    pairs = list(itertools.pairwise(stops))
    if spec.loop and len(stops) > 1:
        pairs.append((stops[-1], stops[0]))
    return Walker(spec, 0.25, [[a, b] for a, b in pairs], straight)


def walk(w: Walker, seconds: float, robot: RobotView = FAR, at: tuple[float, float] = (0.0, 0.0),
         t0: float = 0.0) -> tuple[tuple[float, float], list[tuple[float, float]]]:
    """Moves the person towards the first point it is given (the model would); its places every step."""
    places = []
    for k in range(round(seconds / DT)):
        speed, points = w.target(t0 + k * DT, at, robot)
        tx, ty = points[0]
        d = math.dist(at, (tx, ty))
        step = min(d, speed * DT)
        if d > 0:
            at = (at[0] + (tx - at[0]) * step / d, at[1] + (ty - at[1]) * step / d)
        places.append(at)
    return at, places


def test_walks_its_route_and_stays_at_the_last_stop() -> None:
    at, _ = walk(walker(person()), 6.0)
    assert math.dist(at, (4.0, 0.0)) <= 0.15


def test_waits_until_its_start_then_at_each_stop() -> None:
    w = walker(person(stops=((0.0, 0.0, 0.0), (2.0, 0.0, 3.0), (4.0, 0.0, 0.0)), start=2.0))
    _, places = walk(w, 10.0)
    moved = [round(k * DT, 2) for k in range(1, len(places)) if places[k] != places[k - 1]]
    assert moved[0] == pytest.approx(2.0)  # stands until its start
    # reaches the middle stop (within 0.15 m) after 1.85 m at 1 m/s, then stands 3 s
    still = [k * DT for k in range(1, len(places)) if places[k] == places[k - 1] and k * DT > 2.1]
    assert still[0] == pytest.approx(2.0 + 1.9, abs=0.06) and still[0] + 2.9 < moved[-1]
    assert math.dist(places[-1], (4.0, 0.0)) <= 0.15


def test_a_loop_comes_back_to_its_first_stop() -> None:
    w = walker(person(loop=True))
    _, places = walk(w, 8.0)
    assert min(math.dist(q, (0.0, 0.0)) for q in places[100:]) <= 0.15  # back at the start after 4 m and 4 m


def test_a_person_who_sees_the_robot_heads_beside_it_on_the_right_then_on() -> None:
    robot = RobotView(x=2.0, y=0.0, yaw=math.pi, vx=0.0, vy=0.0, front=0.15, radius=0.21)
    _speed, points = walker(person()).target(0.0, (0.0, 0.0), robot)
    clear = 0.21 + 0.25 + CLEARANCE + 0.1
    assert points == [pytest.approx((2.0, -clear)), pytest.approx((2.0, clear))]  # right first, then left
    at, places = walk(walker(person()), 6.0, robot)
    assert min(math.dist(q, (2.0, 0.0)) for q in places) >= 0.21 + 0.25
    assert math.dist(at, (4.0, 0.0)) <= 0.15


def test_a_robot_left_of_the_way_is_passed_on_the_right_and_a_scared_person_passes_wider() -> None:
    robot = RobotView(x=2.0, y=0.2, yaw=0.0, vx=0.0, vy=0.0, front=0.15, radius=0.21)
    _, points = walker(person()).target(0.0, (0.0, 0.0), robot)
    assert points[0][1] < 0 < points[1][1]
    _, scared = walker(person(Behaviour.SCARED)).target(0.0, (0.0, 0.0), robot)
    assert scared[0][1] == pytest.approx(0.2 - (0.21 + 0.25 + SCARED_CLEARANCE + 0.1))


def test_a_person_who_ignores_the_robot_heads_straight_through_it() -> None:
    robot = RobotView(x=2.0, y=0.0, yaw=0.0, vx=0.0, vy=0.0, front=0.15, radius=0.21)
    assert walker(person(Behaviour.IGNORES)).target(0.0, (0.0, 0.0), robot) == (1.0, [(4.0, 0.0)])


def test_a_robot_out_of_notice_changes_nothing() -> None:
    robot = RobotView(x=NOTICE + 0.5, y=0.0, yaw=0.0, vx=0.0, vy=0.0, front=0.15, radius=0.21)
    w = walker(person(stops=((0.0, 0.0, 0.0), (9.0, 0.0, 0.0))))
    assert w.target(0.0, (0.0, 0.0), robot) == (1.0, [(9.0, 0.0)])


def test_a_curious_person_stands_in_front_of_the_robot_for_a_while_then_goes_on() -> None:
    robot = RobotView(x=2.0, y=1.0, yaw=-math.pi / 2, vx=0.0, vy=0.0, front=0.15, radius=0.21)  # faces -y
    w = walker(person(Behaviour.CURIOUS))
    at, places = walk(w, LINGER + 3.0, robot)
    front = (2.0, 1.0 - 0.15 - 0.3 - 0.25)
    standing = [q for q in places if math.dist(q, front) < 0.05]
    assert len(standing) * DT >= LINGER - 0.5
    at, _ = walk(w, 8.0, robot, at, t0=LINGER + 3.0)
    assert math.dist(at, (4.0, 0.0)) <= 0.15  # once: it does not come back


def test_a_blocking_person_stands_in_the_robots_way_for_a_while() -> None:
    robot = RobotView(x=3.0, y=1.0, yaw=math.pi, vx=0.0, vy=0.0, front=0.15, radius=0.21)  # faces -x
    w = walker(person(Behaviour.BLOCKS))
    _, places = walk(w, BLOCK_TIME + 6.0, robot)
    way = (3.0 - 0.15 - 0.6 - 0.25, 1.0)
    assert sum(math.dist(q, way) < 0.05 for q in places) * DT >= BLOCK_TIME - 4.0
    assert math.dist(places[-1], (4.0, 0.0)) <= 0.15


def test_a_scared_person_backs_away_from_a_near_robot() -> None:
    robot = RobotView(x=0.5, y=0.0, yaw=math.pi, vx=-0.3, vy=0.0, front=0.15, radius=0.21)
    speed, points = walker(person(Behaviour.SCARED)).target(0.0, (0.0, 0.0), robot)
    assert points[0][0] < -1.0 and speed > 1.0


def test_a_follower_keeps_its_place_abreast_of_its_leader_or_on_its_trail_and_arrives_with_it() -> None:
    from rei.sim.people.walkers import Follower

    leader = walker(person())
    spacing = 2 * 0.25 + 0.1
    state: dict = {"trail": None}

    def place():
        return (0.0, 0.0), 0.0, state["trail"]

    first, second, third = (Follower(person(), 0.25, k, leader, place) for k in (1, 2, 3))
    assert first.target(0.0, (0.0, -1.0), FAR) == (0.0, [(0.0, -1.0)])  # the leader has not set off: stands
    state["trail"] = lambda back: (-back, 0.0)  # it came along the x axis
    assert first.target(0.0, (0.0, spacing), FAR)[0] == 0.0  # in its place: stands
    # abreast on the left, else in file on the trail; the second on the right; the third behind on the left; each
    # place with the pace that gets there: twice the walk a metre or more off, standing when there
    assert first.target(0.0, (0.0, 0.0), FAR)[1] == [pytest.approx((0.0, spacing, 1.6)),
                                                     pytest.approx((-spacing, 0.0, 1.6))]
    assert second.target(0.0, (0.0, 0.0), FAR)[1] == [pytest.approx((0.0, -spacing, 1.6)),
                                                      pytest.approx((-2 * spacing, 0.0, 2.0))]
    assert third.target(0.0, (0.0, 0.0), FAR)[1] == [pytest.approx((-spacing, spacing / 2, 1.0 + math.hypot(
        spacing, spacing / 2))), pytest.approx((-3 * spacing, 0.0, 2.0))]
    assert first.target(0.0, (-spacing, 0.0), FAR)[1][1][2] == 0.0
    walk(leader, 6.0)
    assert first.arrivals == leader.arrivals == [pytest.approx(3.85, abs=0.06)]


def test_a_queue_lets_one_pass_every_so_often_and_the_others_line_up_behind_in_the_order_they_came() -> None:
    """Three people set off 0.5 s apart along the x axis to a queue at x = 4 (one every 3 s) and on to x = 8; each is
    moved straight to where it heads, as the model would, without the model's keeping apart."""
    queue = Queue((4.0, 0.0), every=3.0, spacing=0.75)
    walkers = []
    for i in range(3):
        spec = PersonSpec(f"p{i}", Behaviour.AVOIDS, 1.0, 0.5 * i, False, (
            RouteStop("F0", 0.0, 0.0, 0.0), RouteStop("F1", 4.0, 0.0, 0.0, queue=3.0), RouteStop("F2", 8.0, 0.0, 0.0)))
        walkers.append(Walker(spec, 0.25, [[(0.0, 0.0), (4.0, 0.0)], [(4.0, 0.0), (8.0, 0.0)]], straight,
                              queues={1: queue}))
    places = [(0.0, 0.0)] * 3
    lined_up = None
    for k in range(round(16.0 / DT)):
        t = k * DT
        for i, w in enumerate(walkers):
            speed, points = w.target(t, places[i], FAR)
            (tx, ty), at = points[0], places[i]
            d = math.dist(at, (tx, ty))
            if d > 0:
                step = min(d, speed * DT)
                places[i] = (at[0] + (tx - at[0]) * step / d, at[1] + (ty - at[1]) * step / d)
        if lined_up is None and len(queue.passed) == 1 and t > queue.passed[0][0] + 1.5:
            lined_up = list(places)
    assert [name for _, name in queue.passed] == ["p0", "p1", "p2"]  # in the order they came
    times = [time for time, _ in queue.passed]
    assert times[0] == pytest.approx(3.75, abs=0.06)  # p0 reached the floor (within 0.3 m) after 3.7 m
    assert [b - a for a, b in itertools.pairwise(times)] == pytest.approx([3.0, 3.0], abs=DT)
    # while p0 walks on, p1 stands on the floor and p2 one spacing behind it, back along the way they came
    assert lined_up is not None
    assert math.dist(lined_up[1], (4.0, 0.0)) <= 0.15 and math.dist(lined_up[2], (3.25, 0.0)) <= 0.15
    assert all(math.dist(at, (8.0, 0.0)) <= 0.15 for at in places)  # and all got on to their last stop
    assert [w.arrivals[0] for w in walkers] == times  # passing the queue is reaching its stop
