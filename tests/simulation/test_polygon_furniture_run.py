# SPDX-License-Identifier: EPL-2.0
"""examples/corner_desk.rei end to end (grammar, generator, pybullet, reference navigation, monitor, metrics): the
robot reaches a goal in the corner desk's open corner, inside its bounding box, and the monitor's CLOSE to the desk
and the static clearance are what an independent shapely computation on the desk's polygon and the recorded poses
gives."""

from __future__ import annotations

import csv
import json
import math
from collections.abc import Callable
from pathlib import Path
from typing import Any

from shapely import affinity
from shapely.geometry import Polygon, box

from rei.wamp.recording import read_recording

REPO = Path(__file__).resolve().parents[2]


def _placed(points: list[list[float]], pose: list[float]) -> Polygon:
    c, s = math.cos(pose[3]), math.sin(pose[3])
    return Polygon([(pose[0] + c * u - s * v, pose[1] + s * u + c * v) for u, v in points])


def test_the_robot_reaches_the_desks_open_corner_as_shapely_measures_it(run_cli: Callable[..., Any],
                                                                       tmp_path: Path) -> None:
    out = tmp_path / "run"
    result = run_cli("run", REPO / "examples" / "corner_desk.rei", "-o", out, timeout=600)
    assert result.returncode == 0, result.stdout + result.stderr
    world = json.loads((out / "case" / "world.json").read_text(encoding="utf-8"))
    objects = {o["name"]: o for o in world["objects"]}
    desk = _placed(objects["desk"]["footprint"]["points"], objects["desk"]["pose"])
    statics = [_placed(o["footprint"]["points"], o["pose"]) if o["shape"] == "POLYGON" else
               affinity.rotate(box(o["pose"][0] - o["size"][0] / 2, o["pose"][1] - o["size"][1] / 2,
                                   o["pose"][0] + o["size"][0] / 2, o["pose"][1] + o["size"][1] / 2),
                               o["pose"][3], use_radians=True)
               for o in world["objects"] if o["category"] in ("WALL", "STATIC")]
    hx, hy = world["robot"]["size"][0] / 2, world["robot"]["size"][1] / 2
    states = read_recording(out / "streams" / "state.msgpack")

    def robot(pose: list[float]) -> Polygon:
        return _placed([[-hx, -hy], [hx, -hy], [hx, hy], [-hx, hy]], pose)

    with open(out / "events.csv", encoding="utf-8") as f:
        events = list(csv.DictReader(f))
    reached = next(float(e["t"]) for e in events if e["signal"] == "SIG_MISSION_TASK_SUCCESS" and e["object"] == "task_0")
    at_goal = next(s["robot"]["pose"] for s in states if s["t"] >= reached)
    (xmin, ymin, xmax, ymax) = desk.bounds
    assert xmin < at_goal[0] < xmax and ymin < at_goal[1] < ymax  # inside the desk's bounding box
    assert not robot(at_goal).intersects(desk)

    signals = [json.loads(line) for line in (out / "signals.jsonl").read_text(encoding="utf-8").splitlines()]
    close = next(s for s in signals if s["signal"] == "SIG_GEOM_FAR_TRANSIT_CLOSE")
    assert close["object"] == "desk"
    pose = next(s["robot"]["pose"] for s in states if s["t"] == close["t"])
    assert abs(close["distance"] - robot(pose).distance(desk)) < 1e-6

    summary = json.loads((out / "summary.json").read_text(encoding="utf-8"))
    metrics = summary.get("metrics", summary)
    least = min(min(robot(s["robot"]["pose"]).distance(o) for o in statics) for s in states)
    assert abs(metrics["clearance_static_min"] - least) < 1e-6
