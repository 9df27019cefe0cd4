# SPDX-License-Identifier: EPL-2.0
"""Rooms from occupancy maps end to end (issue 31), with real processes: the generator, pybullet, the router, the
monitor and the evaluator.

- Nav2's depot (604 x 307 cells, 1,327 wall rectangles): the reference navigation crosses it between two goals
  25 m apart, and the recorded streams replay through the monitor to the very signals it gave live;
- a scripted drive backwards into the depot's west wall: FAR->CLOSE and CLOSE->COLLISION with that W_map_ wall
  at the state samples where the footprint geometry (rei.geometry, the monitor's definition) says so;
- a synthetic 30 x 50 m building at 0.03 m (1.7 million cells, test-support/maps/synthetic_building.py, drawn
  into the test's folder): it validates, generates, and a short mission in it is simulated and monitored.
"""

from __future__ import annotations

import csv
import json
import math
from pathlib import Path

import numpy as np
import pytest
import synthetic_building  # test-support/maps, on the path by pytest.ini

from rei.geometry import footprint_gaps
from rei.maps import box_of, floor_blocks, load_map, merge_rectangles, obstacle_mask
from rei.wamp.recording import read_recording

REPO = Path(__file__).resolve().parents[2]
DEPOT = REPO.parent / "shared" / "data" / "maps" / "depot.yaml"
RUN_TIMEOUT_S = 420.0
SAMPLE = 0.05  # s between state samples (the collector's 20 Hz)
# The depot's west wall beside F_1_8: cells 1..2 of columns, rows 122..186 (x 0.05..0.15 m, y 6.1..9.35 m).
WEST_WALL = "W_map_1_122"


def _case(text: str, folder: Path, name: str) -> Path:
    path = folder / f"{name}.rei"
    path.write_text(text, encoding="utf-8")
    return path


def _events(path: Path) -> list[tuple[float, str, str, str]]:
    return [(float(r["t"]), r["signal"], r["subject"], r["object"]) for r in csv.DictReader(path.open())]


def _floor_centre(world: dict, name: str) -> tuple[float, float]:
    floor = next(o for o in world["objects"] if o["name"] == name)
    return floor["pose"][0], floor["pose"][1]


def test_the_reference_navigation_crosses_the_depot_and_replays_to_the_same_signals(
        run_cli, tmp_path: Path) -> None:
    case = _case(f"""testcase AcrossTheDepot {{
  room Depot occupancy "{DEPOT}" floorSize 1.0 {{
    robot tb3 : Waffle on F_2_8
  }}
  mission Across {{ timeout 240s goto F_2_8 goto F_27_8 }}
  monitor {{ close 0.25 collision 0.01 }}
}}
""", tmp_path, "across")
    out = tmp_path / "out"
    run = run_cli("run", case, "-o", out, timeout=RUN_TIMEOUT_S)
    assert run.returncode == 0, run.stdout + run.stderr
    world = json.loads((out / "case" / "world.json").read_text())
    walls = [o for o in world["objects"] if o["name"].startswith("W_map_")]
    assert len(walls) == 1327 and world["map"]["width"] == 604
    start, goal = _floor_centre(world, "F_2_8"), _floor_centre(world, "F_27_8")
    assert math.dist(start, goal) >= 20.0
    summary = json.loads((out / "summary.json").read_text())
    assert summary["metrics"]["success"] is True, summary["metrics"]
    assert summary["metrics"]["path_length"] >= 20.0
    states = read_recording(out / "streams" / "state.msgpack")
    assert math.dist(states[-1]["robot"]["pose"][:2], goal) < 0.3
    assert abs(states[-1]["robot"]["pose"][2]) < 0.05  # on the ground all the way: nothing fell
    live = _events(out / "events.csv")
    assert live[0][1] == "SIG_MISSION_BEGIN" and live[-1][1] == "SIG_MISSION_END"
    judged = run_cli("evaluate", out, timeout=RUN_TIMEOUT_S)
    assert judged.returncode == 0, judged.stdout + judged.stderr
    assert _events(out / "events-live.csv") == live
    assert _events(out / "events.csv") == live  # the replay of the recorded streams gives the same signals


def _wall_gaps(states: list[dict], world: dict, wall: str) -> np.ndarray:
    """The robot footprint's gap to ``wall`` at every state sample (rei.geometry: the monitor's definition)."""
    obj = next(o for o in world["objects"] if o["name"] == wall)
    box = np.array([[obj["pose"][0], obj["pose"][1], obj["pose"][3], obj["size"][0], obj["size"][1]]])
    poses = np.array([[m["robot"]["pose"][0], m["robot"]["pose"][1], m["robot"]["pose"][3]] for m in states])
    size = world["robot"]["size"]
    return footprint_gaps(poses, (size[0], size[1]), box, np.array([False]))[:, 0]


def test_a_drive_into_a_map_wall_is_close_then_a_collision_when_the_geometry_says(
        run_cli, tmp_path: Path) -> None:
    case = _case(f"""testcase IntoTheWall {{
  room Depot occupancy "{DEPOT}" floorSize 1.0 {{
    robot tb3 : Waffle on F_1_8
  }}
  mission Back {{ goto F_1_8 within 60s goto F_1_8 }}
  monitor {{ close 0.25 collision 0.01 }}
}}
""", tmp_path, "wall")
    script = tmp_path / "backwards.script"
    script.write_text("# backwards at 0.2 m/s from x = 1.5 into the west wall (x = 0.15), then stand\n"
                      "8.0 -0.2 0.0\n1.0 0.0 0.0\n", encoding="utf-8")
    out = tmp_path / "out"
    sim = run_cli("sim", case, "-o", out, "--no-router", "--controller", f"script:{script}", timeout=RUN_TIMEOUT_S)
    assert sim.returncode in (0, 1), sim.stdout + sim.stderr  # the goals are judged, not what is tested here
    replay = run_cli("monitor", "--replay", out)
    assert replay.returncode == 0, replay.stderr
    signals = [line.split() for line in replay.stdout.splitlines()]
    geometric = [(float(s[1]), s[2]) for s in signals if len(s) >= 5 and s[2].startswith("SIG_GEOM_")]
    assert {s[4] for s in signals if len(s) >= 5 and s[2].startswith("SIG_GEOM_")} == {WEST_WALL}
    assert [name for _, name in geometric][:2] == ["SIG_GEOM_FAR_TRANSIT_CLOSE", "SIG_GEOM_CLOSE_TRANSIT_COLLISION"]

    world = json.loads((out / "case" / "world.json").read_text())
    thresholds = json.loads((out / "case" / "monitor.json").read_text())["thresholds"]
    states = read_recording(out / "streams" / "state.msgpack")
    gaps = _wall_gaps(states, world, WEST_WALL)
    touching = np.array([[ "tb3", WEST_WALL] in (m.get("contacts") or []) for m in states])
    t = np.array([m["t"] for m in states])
    close_at = t[np.argmax(gaps < thresholds["close"])]
    collision_at = t[np.argmax((gaps < thresholds["collision"]) | touching)]
    assert (gaps < thresholds["collision"]).any() and 4.0 < close_at < collision_at
    assert geometric[0][0] == pytest.approx(close_at, abs=SAMPLE + 1e-9)
    assert geometric[1][0] == pytest.approx(collision_at, abs=SAMPLE + 1e-9)
    assert states[-1]["robot"]["pose"][0] < 0.4 and abs(states[-1]["robot"]["pose"][2]) < 0.05  # at the wall


def _free_block_near(free: np.ndarray, x: float, y: float) -> str:
    """The free 1 m floor block nearest map metres (x, y)."""
    ys, xs = np.nonzero(free)
    k = int(np.argmin(np.hypot(xs + 0.5 - x, ys + 0.5 - y)))
    return f"F_{xs[k]}_{ys[k]}"


def test_a_30_by_50_metre_map_at_3_cm_validates_generates_simulates_and_is_monitored(
        run_cli, tmp_path: Path) -> None:
    yaml = synthetic_building.write(tmp_path / "map")
    occupancy = load_map(yaml)
    assert occupancy.width * occupancy.height > 1_600_000
    rectangles = merge_rectangles(obstacle_mask(occupancy))
    free = floor_blocks(occupancy, 1.0).free
    (x0, y0), (x1, y1) = synthetic_building.CORRIDOR_GOALS
    start, middle = _free_block_near(free, x0, y0), _free_block_near(free, x0, y0 + 10.0)
    case = _case(f"""testcase Building {{
  room Floor3 occupancy "map/{yaml.name}" floorSize 1.0 {{
    object cart : Table on {_free_block_near(free, x1, y1)}
    robot tb3 : Waffle on {start}
  }}
  mission AlongTheCorridor {{ timeout 120s goto {start} goto {middle} }}
  monitor {{ close 0.25 collision 0.01 }}
}}
""", tmp_path, "building")
    valid = run_cli("validate", case)
    assert valid.returncode == 0, valid.stdout + valid.stderr
    out = tmp_path / "out"
    run = run_cli("run", case, "-o", out, timeout=RUN_TIMEOUT_S)
    assert run.returncode == 0, run.stdout + run.stderr
    world = json.loads((out / "case" / "world.json").read_text())
    walls = {o["name"]: o for o in world["objects"] if o["category"] == "WALL"}
    assert len(walls) == len(rectangles) > 2000
    first = rectangles[0]
    assert walls[f"W_map_{first.col}_{first.row}"]["size"][:2] == pytest.approx(list(box_of(first, occupancy)[2:]))
    assert sum(o["category"] == "FLOOR" for o in world["objects"]) == int(free.sum())
    summary = json.loads((out / "summary.json").read_text())
    assert summary["metrics"]["success"] is True, summary["metrics"]
    assert summary["metrics"]["clearance_static_min"] > 0.0  # the monitor's geometry saw the walls, none hit
    events = _events(out / "events.csv")
    assert events[0][1] == "SIG_MISSION_BEGIN" and events[-1][1] == "SIG_MISSION_END"
    assert [e[1] for e in events].count("SIG_MISSION_TASK_SUCCESS") == 2
