# SPDX-License-Identifier: EPL-2.0
"""An external SUT in a room from an occupancy map, over the real router (`rei sim --sut ... --sut-map`): hello's
static map is still rectangles (docs/sut.md), and they are the map's walls (world.json's W_map_ walls, the map's
merged obstacle cells) with the furniture; `map.occupancy` names the run's copy of the map."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import msgpack

from rei.maps import box_of, load_map, merge_rectangles, obstacle_mask

PROGRAMS = Path(__file__).resolve().parent / "programs"
EXAMPLE = "examples/maps/two_rooms.rei"
#: contract_sut.py's plan: a hello, zero commands, and both goals given up at once (the run ends quickly).
PLAN = {"hello_call": {"name": "map-room"}, "command": [{"tick": 0, "v": 0.0, "w": 0.0}],
        "status": {str(goal): {"goal_id": goal, "status": "ABORTED", "text": "only here for hello"} for goal in (0, 1)},
        "cancelled": {"goal_id": 0, "status": "CANCELLED"}}


def _box(values: list[float]) -> tuple[float, ...]:
    return tuple(round(v, 6) for v in values)


def test_hello_offers_the_map_s_walls_as_rectangles_and_names_the_map(run_cli, repo_root: Path,
                                                                      tmp_path: Path) -> None:
    out = tmp_path / "out"
    out.mkdir()
    (tmp_path / "plan.json").write_text(json.dumps(PLAN))
    sut = f"{sys.executable} {PROGRAMS / 'contract_sut.py'} {tmp_path / 'plan.json'} {out}"
    result = run_cli("sim", repo_root / EXAMPLE, "-o", out, "--progress", "none", "--no-humans", "--sut", sut,
                     "--sut-map", timeout=180)
    assert result.returncode == 1, result.stdout + result.stderr  # both goals given up: the run itself is fine
    (name, hello), *_ = msgpack.unpackb((out / "contract.msgpack").read_bytes())
    assert name == "hello"
    static = hello["map"]
    assert static["occupancy"] == "map.yaml"  # relative to REI_CASE_DIR, the run's case folder
    assert static["bounds"] == [0.0, 0.0, 10.0, 6.0]
    offered = {_box(box) for box in static["obstacles"]}
    world = json.loads((out / "case" / "world.json").read_text())
    walls = [o for o in world["objects"] if o["category"] == "WALL"]
    occupancy = load_map(repo_root / "examples" / "maps" / "two_rooms.yaml")
    rectangles = merge_rectangles(obstacle_mask(occupancy))
    assert len(walls) == len(rectangles) == 10
    for rect in rectangles:  # every merged rectangle of the map's obstacle cells, as the SUT receives it
        x, y, sx, sy = box_of(rect, occupancy)
        assert _box([x, y, 0.0, sx, sy]) in offered, (rect, sorted(offered))
    furniture = [o for o in world["objects"] if o["category"] == "STATIC"]
    assert len(offered) == len(walls) + len(furniture)
