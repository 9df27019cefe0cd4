# SPDX-License-Identifier: EPL-2.0
"""A map room offered to an external SUT: ``hello`` names the case's map.yaml, and the grid a ROS bridge publishes
on /map is the map's own, cell for cell (rei.sut.rasterize.map_grid); other rooms keep the rasterized rectangles."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from rei.geometry import Pose2D
from rei.maps import load_map
from rei.sut.api import StaticMap
from rei.sut.client import Session
from rei.sut.external import protocol
from rei.sut.rasterize import map_grid

SHARED_MAPS = Path(__file__).resolve().parents[3].parent / "shared" / "data" / "maps"
STATIC = StaticMap((0.0, 0.0, 2.0, 1.0), ((1.0, 0.5, 0.0, 0.4, 0.2),), (0.3, 0.3))
ROBOT = {"name": "tb3", "footprint": [0.3, 0.3], "max_linear": 0.26, "max_angular": 1.82,
         "lidar": {"beams": 360, "range_min": 0.12, "range_max": 3.5, "rate": 10.0}}


def _hello(static_map: StaticMap | None, occupancy: str | None) -> dict:
    return protocol.hello_answer(run_id="r1", clock="lockstep", control_rate=10.0, deadline=10.0,
                                 start=Pose2D(0.5, 0.5, 0.0), robot=ROBOT, goals=1, static_map=static_map,
                                 occupancy=occupancy)


def test_hello_names_the_map_room_s_yaml_only_with_the_static_map() -> None:
    yaml = "depot.yaml"  # relative to the case's folder (REI_CASE_DIR)
    hello = _hello(STATIC, yaml)
    assert hello["map"]["occupancy"] == yaml
    assert Session.from_hello(hello, SHARED_MAPS).occupancy == SHARED_MAPS / "depot.yaml"
    assert Session.from_hello(hello).occupancy == Path("depot.yaml")
    assert "occupancy" not in _hello(STATIC, None)["map"] and Session.from_hello(_hello(STATIC, None)).occupancy is None
    assert _hello(None, yaml)["map"] is None and Session.from_hello(_hello(None, yaml)).occupancy is None


def test_the_bridges_grid_of_a_map_room_is_the_map_s_own_cell_for_cell() -> None:
    for name, values in (("depot", {0, 100}), ("tb3_sandbox", {-1, 0, 100})):
        occupancy = load_map(SHARED_MAPS / f"{name}.yaml")
        grid = map_grid(STATIC, occupancy)
        assert (grid.width, grid.height, grid.resolution) == (occupancy.width, occupancy.height, 0.05)
        assert (grid.x0, grid.y0) == occupancy.origin[:2]
        assert grid.data.dtype == np.int8 and np.array_equal(grid.data.reshape(grid.height, grid.width),
                                                             occupancy.grid)
        assert set(np.unique(grid.data).tolist()) == values  # the sandbox's unknown cells stay unknown


def test_other_rooms_keep_the_rasterized_rectangles() -> None:
    grid = map_grid(STATIC)
    cells = grid.data.reshape(grid.height, grid.width)
    assert (grid.x0, grid.y0, grid.resolution) == (-0.5, -0.5, 0.05)
    assert int((cells == 100).sum()) == 8 * 4 and set(np.unique(cells).tolist()) == {0, 100}


def test_both_bridges_messages_carry_the_map_room_s_grid() -> None:
    from rei.sut.ros1.environment import import_rospy
    from rei.sut.ros2 import messages as ros2
    from rei.sut.ros_conventions import Frames

    import_rospy()  # Debian's ROS 1, installed by scripts/setup-ros1.sh (./run-tests runs it)
    from rei.sut.ros1 import messages as ros1

    occupancy = load_map(SHARED_MAPS / "tb3_sandbox.yaml")
    for message in (ros1.occupancy_grid(STATIC, Frames(), occupancy=occupancy),
                    ros2.occupancy_grid(STATIC, Frames(), occupancy=occupancy)):
        assert (message.info.width, message.info.height) == (384, 384) and message.header.frame_id == "map"
        assert abs(message.info.resolution - 0.05) < 1e-7
        assert (message.info.origin.position.x, message.info.origin.position.y) == (-10.0, -10.0)
        assert np.array_equal(np.asarray(message.data, dtype=np.int8).reshape(384, 384), occupancy.grid)
