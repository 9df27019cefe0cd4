# SPDX-License-Identifier: EPL-2.0
"""People who see the robot, end to end below the router: a routed person of the language, generated, moved by
the people server's JuPedSim model in lockstep with real pybullet (docs/people.md)."""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from pathlib import Path

import pytest

from rei.geometry import Twist2D
from rei.run import MissionRunOptions, run_mission
from rei.sim.simulation import Simulation
from rei.sim.state import SimState

STILL = Twist2D(0.0, 0.0)


def case(run_cli, write_rei: Callable[[str, str], Path], tmp_path: Path, people: str, robot: str = "F_2_2",
         size: str = "6 x 4", name: str = "people") -> Path:
    source = write_rei(f"{name}.rei", f"""
testcase People {{
  room Lab size {size} {{
    {people}
    robot tb3 : Waffle on {robot}
  }}
  mission Go {{ goto F_3_0 goto F_5_0 }}
  monitor {{ close 0.25 collision 0.01 }}
}}
""")
    out = tmp_path / f"{name}-case"
    result = run_cli("generate", source, "-o", out)
    assert result.returncode == 0, result.stderr
    return out


def still_robot(folder: Path, seconds: float, seed: int = 1) -> list[SimState]:
    """Every state sample (20 Hz) of a run whose robot stands still."""
    states = []
    with Simulation(folder, seed=seed) as sim:
        for k in range(round(seconds * sim.physics_rate)):
            sim.step(STILL)
            if k % 12 == 0:
                states.append(sim.state())
    return states


def place(state: SimState, name: str) -> tuple[float, float]:
    return next(o.pose[:2] for o in state.objects if o.name == name)


def test_a_person_who_sees_the_robot_walks_around_it_to_its_stop(run_cli, write_rei, tmp_path: Path) -> None:
    folder = case(run_cli, write_rei, tmp_path, "human ann route [F_0_2, F_5_2] speed 1.0 avoids")
    states = still_robot(folder, 12.0)
    robot = states[0].robot.pose[:2]
    assert robot == pytest.approx((2.5, 2.5), abs=0.01)
    assert not any(s.contacts for s in states)
    closest = min(math.dist(place(s, "ann"), robot) for s in states)
    assert closest > 0.21 + 0.25  # the footprints' discs never touched
    assert math.dist(place(states[-1], "ann"), (5.5, 2.5)) < 0.2


def test_a_person_walks_into_the_open_side_of_furniture_on_a_polygon(run_cli, write_rei, tmp_path: Path) -> None:
    # a C-shaped desk, 3 x 3 m, open to +x: F_3_2's centre is inside its bounding box, 0.7 m from each of its arms
    write_rei("desks.rei", "catalogue Desks {\n  type CDesk : object polygon (0,0) (3,0) (3,0.8) (0.8,0.8) (0.8,2.2)"
                           " (3,2.2) (3,3) (0,3) height 0.75\n}\n")
    source = write_rei("desk.rei", """import "desks.rei"
testcase Desk {
  room Lab size 7 x 5 {
    object desk : CDesk on F_2_2
    human ann route [F_6_2, F_3_2] speed 1.0 avoids
    robot tb3 : Waffle on F_6_0
  }
  mission Go { goto F_5_0 goto F_6_0 }
}
""")
    folder = tmp_path / "desk-case"
    result = run_cli("generate", source, "-o", folder)
    assert result.returncode == 0, result.stderr
    states = still_robot(folder, 8.0)
    assert math.dist(place(states[-1], "ann"), (3.5, 2.5)) < 0.2  # not held at the bounding box's side, x = 4
    assert not any(s.contacts for s in states)


def test_a_person_who_ignores_the_robot_walks_into_it(run_cli, write_rei, tmp_path: Path) -> None:
    folder = case(run_cli, write_rei, tmp_path, "human ann route [F_0_2, F_5_2] speed 1.0 ignores")
    states = still_robot(folder, 8.0)
    touched = [s for s in states if ("tb3", "ann") in s.contacts]
    assert touched, "the person walked through where the robot stands without touching it"
    assert touched[0].t < 2.5  # at about 2 m from its start at 1 m/s, straight on


def test_a_curious_person_ends_in_front_of_the_robot(run_cli, write_rei, tmp_path: Path) -> None:
    folder = case(run_cli, write_rei, tmp_path, "human cid route [F_0_2, F_5_2] speed 1.0 curious")
    states = still_robot(folder, 6.0)
    x, y = place(states[-1], "cid")
    rx, ry, _, yaw = states[-1].robot.pose
    ahead = (x - rx) * math.cos(yaw) + (y - ry) * math.sin(yaw)
    assert 0 < ahead and math.dist((x, y), (rx, ry)) < 1.0  # within 1 m, in front
    assert not any(s.contacts for s in states)


def test_people_crossing_in_a_corridor_keep_apart(run_cli, write_rei, tmp_path: Path) -> None:
    walkers = "\n    ".join(
        [f"human l{i} route [F_0_{i}, F_9_{i}] speed 1.2 avoids" for i in range(3)]
        + [f"human r{i} route [F_9_{i + 1}, F_0_{i + 1}] speed 1.2 avoids" for i in range(3)])
    folder = case(run_cli, write_rei, tmp_path, walkers, robot="F_5_4", size="10 x 5")
    states = still_robot(folder, 14.0)
    names = [o.name for o in states[0].objects]
    closest = min(math.dist(place(s, a), place(s, b)) for s in states for i, a in enumerate(names)
                  for b in names[i + 1:])
    assert closest > 2 * 0.25 - 0.02  # the bodies' discs (0.25 m) at most grazed
    for name in names:  # everyone got across
        end = place(states[-1], name)
        assert (end[0] > 8.5) if name.startswith("l") else (end[0] < 1.5), (name, end)


def test_the_lidar_sees_a_person_and_the_robot_is_stopped_by_one(run_cli, write_rei, tmp_path: Path) -> None:
    folder = case(run_cli, write_rei, tmp_path, "human bob route [F_4_2] ignores")  # stands 2 m ahead
    with Simulation(folder, seed=1) as sim:
        x, y, _, yaw = sim.state().robot.pose
        bob = next(o for o in sim.state().objects if o.name == "bob")
        assert bob.pose[:2] == pytest.approx((4.5, 2.5)) and bob.twist == (0.0, 0.0, 0.0)
        ranges = sim.observation().scan.ranges  # type: ignore[union-attr]
        seen = 0
        for i in range(360):
            angle = yaw + math.radians(i)
            dx, dy = math.cos(angle), math.sin(angle)
            b = (x - 4.5) * dx + (y - 2.5) * dy
            disc = b * b - ((x - 4.5) ** 2 + (y - 2.5) ** 2 - 0.25**2)
            if disc >= 0 and -b - math.sqrt(disc) > 0:  # the beam meets bob's cylinder ahead
                seen += 1
                assert ranges[i] == pytest.approx(-b - math.sqrt(disc), abs=1e-6), i
        assert seen >= 10
        for _ in range(round(10.0 * sim.physics_rate)):  # drive into him: he stands, the robot is stopped
            sim.step(Twist2D(0.3, 0.0))
        state = sim.state()
        assert ("tb3", "bob") in state.contacts
        assert next(o for o in state.objects if o.name == "bob").pose[:2] == pytest.approx((4.5, 2.5))
        front = state.robot.pose[0] + sim.case.world.robot.size[0] / 2
        assert 4.5 - 0.25 - 0.02 < front < 4.5 - 0.25 + 0.01  # touching his body, not through it


def test_the_people_see_where_the_robot_really_is(run_cli, write_rei, tmp_path: Path) -> None:
    folder = case(run_cli, write_rei, tmp_path, "human ann route [F_5_2, F_0_2] speed 1.0 avoids", robot="F_0_0")
    with Simulation(folder, seed=3) as sim:
        for _ in range(round(8.0 * sim.physics_rate)):
            sim.step(Twist2D(0.3, 0.1))
        assert sim.crowd is not None
        assert sim.crowd.robot_lag < 0.05


def test_same_case_and_seed_record_the_same_streams(run_cli, write_rei, tmp_path: Path) -> None:
    folder = case(run_cli, write_rei, tmp_path,
                  "human ann route [F_0_2, F_5_2 wait 2s] speed 1.0 loop avoids\n"
                  "    human bob route [F_5_3, F_0_3] speed 0.8 ignores", robot="F_0_0")
    streams = []
    for attempt in ("a", "b"):
        out = tmp_path / attempt
        run_mission(folder, out, MissionRunOptions(seed=5), run_id=attempt)
        streams.append([(out / "streams" / name).read_bytes() for name in ("state.msgpack", "mission.msgpack")])
    assert streams[0] == streams[1]


def run_scripted(run_cli, write_rei, tmp_path: Path, people: str, script: str, name: str) -> dict:
    """`rei run` (router, monitor, evaluator) with the robot on F_2_2 driven by ``script``; summary.json."""
    source = write_rei(f"{name}.rei", f"""
testcase Fault {{
  room Lab size 6 x 4 {{
    {people}
    robot tb3 : Waffle on F_2_2
  }}
  mission Hold {{ goto F_2_2 within 12s goto F_2_2 within 1s }}
  monitor {{ close 0.25 collision 0.01 maxHumanCollisions 1 }}
}}
""")
    timeline = tmp_path / f"{name}.script"
    timeline.write_text(script, encoding="utf-8")
    out = tmp_path / name
    result = run_cli("run", source, "-o", out, "--controller", f"script:{timeline}", timeout=240)
    assert result.returncode in (0, 1), result.stdout + result.stderr
    return json.loads((out / "summary.json").read_text(encoding="utf-8"))


def verdict(summary: dict, requirement: str) -> str:
    return next(v["status"] for v in summary["verdicts"] if v["requirement"] == requirement)


def test_who_was_at_fault(run_cli, write_rei, tmp_path: Path) -> None:
    # a person who ignores the standing robot walks into it: the person's fault
    walked_in = run_scripted(run_cli, write_rei, tmp_path, "human ann route [F_0_2, F_5_2] speed 1.0 ignores",
                             "12.0 0.0 0.0\n", "walked-in")
    assert walked_in["metrics"]["collisions_person_at_fault"] >= 1
    assert walked_in["metrics"]["collisions_robot_at_fault"] == 0
    assert verdict(walked_in, "NO_ROBOT_AT_FAULT_COLLISION") == "pass"
    # the same person who sees it walks around it: no collision at all
    around = run_scripted(run_cli, write_rei, tmp_path, "human ann route [F_0_2, F_5_2] speed 1.0 avoids",
                          "12.0 0.0 0.0\n", "around")
    assert around["metrics"]["collisions_person_at_fault"] == 0
    assert around["metrics"]["collisions_robot_at_fault"] == 0
    # the robot driven into a person who stands (and does not see it coming): the robot's fault
    rammed = run_scripted(run_cli, write_rei, tmp_path, "human bob route [F_4_2] ignores",
                          "12.0 0.3 0.0\n", "rammed")
    assert rammed["metrics"]["collisions_robot_at_fault"] >= 1
    assert verdict(rammed, "NO_ROBOT_AT_FAULT_COLLISION") == "fail"


def test_what_the_robot_cost_the_people(run_cli, write_rei, tmp_path: Path) -> None:
    from rei.sim.people.cost import people_cost

    def cost(robot: str, name: str) -> dict:
        folder = case(run_cli, write_rei, tmp_path, "human ann route [F_0_2, F_5_2] speed 1.0", robot=robot,
                      name=name)
        with Simulation(folder, seed=1) as sim:
            for _ in range(round(9.0 * sim.physics_rate)):
                sim.step(STILL)
            assert sim.crowd is not None
            return people_cost(sim.crowd, sim.t)["ann"]

    away = cost("F_2_0", "away")  # not in her way: she walks as she would without it
    assert (away["delay"], away["detour"], away["censored"]) == (0.0, 0.0, False)
    assert away["arrivals"] == away["arrivals_without_robot"] and len(away["arrivals"]) == 1
    blocking = cost("F_2_2", "blocking")  # standing on her straight line: she walks round it
    assert blocking["detour"] > 0.1 and blocking["delay"] > 0.1 and not blocking["censored"]
    assert blocking["walked"] == pytest.approx(blocking["walked_without_robot"] + blocking["detour"], abs=0.01)


def test_no_way_through_a_gap_narrower_than_a_body(run_cli, tmp_path: Path) -> None:
    # a generated room where a curious person's way on from the robot ran through the 0.15 m between a table and a
    # chair: it stood in front of the gap from 24 s on; routed where a body fits, it walks round
    rooms = tmp_path / "rooms"
    result = run_cli("gen-rooms", "--size", "medium", "--humans", "3", "--people", "reactive", "--behaviour", "mixed",
                     "--seed", "2", "--count", "1", "-o", rooms)
    assert result.returncode == 0, result.stderr
    (source,) = rooms.glob("*.rei")
    folder = tmp_path / "case"
    assert run_cli("generate", source, "-o", folder).returncode == 0
    run_mission(folder, tmp_path / "run", MissionRunOptions(seed=0), run_id="gap")
    from rei.wamp.recording import read_recording

    track = [(m["t"], next(o["pose"][:2] for o in m["objects"] if o["name"] == "person3"))
             for m in read_recording(tmp_path / "run" / "streams" / "state.msgpack")]
    later = [xy for t, xy in track if 24.0 <= t <= 40.0]
    assert max(math.dist(later[0], xy) for xy in later) > 1.0
