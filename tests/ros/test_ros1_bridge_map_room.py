# SPDX-License-Identifier: EPL-2.0
"""A room from an occupancy map through the ROS 1 bridge (issue 31): /map is Nav2's tb3_sandbox map itself, cell
for cell, unknown cells included, and REI's reference navigation as a ROS node completes a mission in it. A real
ROS master and rospy nodes, as tests/ros/test_ros1_bridge.py. The expected grid is decoded here from the PGM bytes
with map_server's trinary rule, not by rei.maps, which the bridge publishes from."""

from __future__ import annotations

import json
import re
import shlex
from pathlib import Path

import numpy as np
import yaml

SANDBOX = Path(__file__).resolve().parents[2].parent / "shared" / "data" / "maps" / "tb3_sandbox.yaml"


def _trinary(yaml_path: Path) -> tuple[dict, np.ndarray]:
    """map_server's trinary reading of an 8-bit P5 map: p = (255 - v) / 255 (negate 0), occupied (100) above
    occupied_thresh, free (0) below free_thresh, else unknown (-1); row 0 of the grid is the image's bottom row."""
    header = yaml.safe_load(yaml_path.read_text(encoding="utf-8"))
    assert header.get("negate", 0) == 0 and header.get("mode", "trinary") == "trinary"
    data = (yaml_path.parent / header["image"]).read_bytes()
    fields = re.match(rb"P5(?:\s+|#[^\n]*\n)+(\d+)(?:\s+|#[^\n]*\n)+(\d+)(?:\s+|#[^\n]*\n)+(\d+)\s", data)
    assert fields is not None
    width, height, maxval = (int(v) for v in fields.groups())
    assert maxval == 255
    pixels = np.frombuffer(data, dtype=np.uint8, count=width * height, offset=fields.end()).reshape(height, width)
    p = (255.0 - pixels) / 255.0
    grid = np.where(p > header["occupied_thresh"], 100, np.where(p < header["free_thresh"], 0, -1)).astype(np.int8)
    return header, grid[::-1]


def test_the_ros1_bridge_s_map_of_a_map_room_is_the_original_image_cell_for_cell(
    run_cli, repo_root: Path, tmp_path: Path, processes_mentioning
) -> None:
    case = tmp_path / "sandbox.rei"
    case.write_text(f"""testcase Sandbox {{
  room Arena occupancy {json.dumps(str(SANDBOX))} floorSize 0.5 {{
    robot tb3 : Waffle on F_18_15
  }}
  mission Along {{ timeout 90s goto F_21_16 goto F_18_16 }}
  monitor {{ close 0.25 collision 0.01 }}
}}
""", encoding="utf-8")
    out = tmp_path / "out"
    recorded = tmp_path / "map.npz"
    recorder = shlex.join(["python3", str(repo_root / "tests/ros/programs/map_recorder.py"), str(recorded)])
    node = shlex.join(["python3", str(repo_root / "examples/sut/ros1/reference_nav_node.py"), str(out)])
    result = run_cli("run", case, "-o", out, "--sut",
                     f"ros1:sh -c {shlex.quote(f'{recorder} & exec {node}')}", "--sut-map", timeout=400)
    assert result.returncode == 0, result.stdout + result.stderr + (out / "sut.log").read_text()
    summary = json.loads((out / "summary.json").read_text())
    assert summary["status"] == "COMPLETED" and summary["tasks"]["succeeded"] == summary["tasks"]["goals"] == 2

    header, expected = _trinary(SANDBOX)
    with np.load(recorded) as grid:
        assert (int(grid["width"]), int(grid["height"])) == (expected.shape[1], expected.shape[0]) == (384, 384)
        assert float(grid["resolution"]) == np.float32(header["resolution"])  # the message's float32
        assert grid["origin"].tolist() == header["origin"][:2] and str(grid["frame"]) == "map"
        cells = grid["data"].reshape(expected.shape)
    assert np.array_equal(cells, expected)
    assert {-1, 0, 100} == set(np.unique(cells).tolist())  # mostly unknown around the arena, as the image has it
    assert processes_mentioning(out) == []
