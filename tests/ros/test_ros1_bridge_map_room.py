# SPDX-License-Identifier: EPL-2.0
"""A room from an occupancy map through the ROS 1 bridge (issue 31): /map is the map itself, cell for cell, and
REI's reference navigation as a ROS node completes the example's mission in it. A real ROS master and rospy
nodes, as tests/ros/test_ros1_bridge.py."""

from __future__ import annotations

import json
import shlex
from pathlib import Path

import numpy as np

from rei.maps import load_map

EXAMPLE = "examples/maps/two_rooms.rei"
MAP = "examples/maps/two_rooms.yaml"


def test_the_ros1_bridge_s_map_of_a_map_room_is_the_original_image_cell_for_cell(
    run_cli, repo_root: Path, tmp_path: Path, processes_mentioning
) -> None:
    out = tmp_path / "out"
    recorded = tmp_path / "map.npz"
    recorder = shlex.join(["python3", str(repo_root / "tests/ros/programs/map_recorder.py"), str(recorded)])
    node = shlex.join(["python3", str(repo_root / "examples/sut/ros1/reference_nav_node.py"), str(out)])
    result = run_cli("run", repo_root / EXAMPLE, "-o", out, "--sut",
                     f"ros1:sh -c {shlex.quote(f'{recorder} & exec {node}')}", "--sut-map", timeout=400)
    assert result.returncode == 0, result.stdout + result.stderr + (out / "sut.log").read_text()
    summary = json.loads((out / "summary.json").read_text())
    assert summary["status"] == "COMPLETED" and summary["tasks"]["succeeded"] == summary["tasks"]["goals"] == 2

    original = load_map(repo_root / MAP)
    with np.load(recorded) as grid:
        assert (int(grid["width"]), int(grid["height"])) == (original.width, original.height) == (200, 120)
        assert float(grid["resolution"]) == np.float32(original.resolution)  # the message's float32
        assert grid["origin"].tolist() == list(original.origin[:2]) and str(grid["frame"]) == "map"
        cells = grid["data"].reshape(original.height, original.width)
    assert np.array_equal(cells, original.grid)
    assert {-1, 0, 100} == set(np.unique(cells).tolist())  # unknown between the rooms, as the image has it
    assert processes_mentioning(out) == []
