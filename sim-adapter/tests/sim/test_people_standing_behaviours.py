# SPDX-License-Identifier: EPL-2.0
"""A person who stands at its place (a one-stop route, or the last stop of a route walked once) and comes to look at
the robot, or steps into its way, goes back to its place afterwards (docs/people.md, behaviours: "then goes on with
its route"): it stood in front of the robot for good, 0.7 m ahead of a robot that stood still, in its way when it
drove on."""

from __future__ import annotations

import math

from rei.artifacts.animation import Behaviour, PersonSpec, RouteStop
from rei.sim.people.walkers import BLOCK_TIME, LINGER, RobotView, Walker

DT = 0.05


def standing(behaviour: Behaviour, place: tuple[float, float]) -> Walker:
    spec = PersonSpec("p", behaviour, 1.0, 0.0, False, (RouteStop("F", place[0], place[1], 0.0),))
    return Walker(spec, 0.25, [], lambda a, b: [a, b])


def walk(w: Walker, seconds: float, robot: RobotView, at: tuple[float, float]) -> list[tuple[float, float]]:
    """Moves the person straight towards the first point it is given, as far as its speed allows in a step."""
    places = []
    for k in range(round(seconds / DT)):
        speed, points = w.target(k * DT, at, robot)
        tx, ty = points[0][:2]
        d = math.dist(at, (tx, ty))
        step = min(d, speed * DT)
        if d > 0:
            at = (at[0] + (tx - at[0]) * step / d, at[1] + (ty - at[1]) * step / d)
        places.append(at)
    return places


def test_a_standing_curious_person_looks_at_the_robot_then_goes_back_to_its_place() -> None:
    robot = RobotView(x=0.0, y=0.0, yaw=0.0, vx=0.0, vy=0.0, front=0.15, radius=0.21)  # faces +x
    home = (2.0, 2.0)
    places = walk(standing(Behaviour.CURIOUS, home), LINGER + 10.0, robot, home)
    front = (0.15 + 0.3 + 0.25, 0.0)
    assert sum(math.dist(q, front) < 0.05 for q in places) * DT >= LINGER - 0.5  # it came to look
    assert math.dist(places[-1], home) <= 0.15  # and went back (before: 0.7 m in front of the robot)


def test_a_standing_blocking_person_goes_back_to_its_place_after_its_stand() -> None:
    robot = RobotView(x=0.0, y=0.0, yaw=0.0, vx=0.0, vy=0.0, front=0.15, radius=0.21)
    home = (3.0, -1.5)
    places = walk(standing(Behaviour.BLOCKS, home), BLOCK_TIME + 8.0, robot, home)
    way = (0.15 + 0.6 + 0.25, 0.0)
    assert sum(math.dist(q, way) < 0.05 for q in places) * DT >= BLOCK_TIME - 4.0
    assert math.dist(places[-1], home) <= 0.15


def test_a_standing_scared_person_keeps_away() -> None:
    # a scared person who backed away stays away: back at its place it would be near the robot again
    robot = RobotView(x=0.0, y=0.0, yaw=0.0, vx=0.0, vy=0.0, front=0.15, radius=0.21)
    home = (1.0, 0.0)
    places = walk(standing(Behaviour.SCARED, home), 10.0, robot, home)
    assert math.dist(places[-1], (0.0, 0.0)) >= 1.5


def test_a_loop_of_one_place_without_a_wait_stands_and_counts_no_arrival_every_step() -> None:
    # route [F_4_0, F_4_0] loop: every step was an arrival (2416 in a 30 s run, sim.json growing 80 a second)
    spec = PersonSpec("p", Behaviour.AVOIDS, 1.0, 0.0, True, (RouteStop("F", 1.0, 1.0, 0.0),
                                                               RouteStop("F", 1.0, 1.0, 0.0)))
    w = Walker(spec, 0.25, [[(1.0, 1.0), (1.0, 1.0)], [(1.0, 1.0), (1.0, 1.0)]], lambda a, b: [a, b])
    far = RobotView(x=9.0, y=9.0, yaw=0.0, vx=0.0, vy=0.0, front=0.15, radius=0.21)
    places = walk(w, 10.0, far, (1.0, 1.0))
    assert places[-1] == (1.0, 1.0)
    assert len(w.arrivals) <= 2
