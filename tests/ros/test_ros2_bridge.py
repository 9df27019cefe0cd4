# SPDX-License-Identifier: EPL-2.0
"""The ROS 2 bridge (docs/ros.md) on real DDS, with a navigation stack speaking ROS 2's wire conventions in its own
process (examples/sut/ros2: no ROS 2 distribution installs here, so no rclcpp node could be the stack)."""

from __future__ import annotations

import json
from pathlib import Path

EXAMPLE = "examples/simple_navigation.rei"
NODES = "examples/sut/ros2"


def _summary(out: Path) -> dict:
    return json.loads((out / "summary.json").read_text())


def test_the_reference_navigation_on_dds_completes_the_simple_navigation_example_through_the_action(
    run_cli, repo_root: Path, tmp_path: Path, processes_mentioning
) -> None:
    out = tmp_path / "out"
    result = run_cli("run", repo_root / EXAMPLE, "-o", out, "--sut",
                     f"ros2:python3 {repo_root / NODES / 'reference_nav_node.py'} {out}", "--sut-map", timeout=400)
    assert result.returncode == 0, result.stdout + result.stderr + (out / "sut.log").read_text()
    summary = _summary(out)
    assert summary["status"] == "COMPLETED"
    assert summary["tasks"]["succeeded"] == summary["tasks"]["goals"] == 2
    assert {v["status"] for v in summary["verdicts"]} <= {"pass", "not-applicable"}
    bridge_log = (out / "sut.log").read_text()
    assert f"discovery tag rei-{summary['run_id']}" in bridge_log, bridge_log  # the run's own DDS discovery
    assert "map 140x100 cells" in (out / "ros" / "stack.log").read_text()  # the stack planned on REI's /map
    assert processes_mentioning(out) == []


def test_a_ros2_stack_that_dies_ends_the_run_in_error_with_its_log(run_cli, repo_root: Path, tmp_path: Path,
                                                                  processes_mentioning) -> None:
    out = tmp_path / "out"
    result = run_cli("run", repo_root / EXAMPLE, "-o", out, "--sut",
                     f"ros2:python3 -c \"import sys; print('nav2 crashed', flush=True); sys.exit(4)\" {out}",
                     timeout=300)
    assert result.returncode == 2, result.stdout + result.stderr
    error = _summary(out)["error"]
    assert "the ROS 2 navigation stack exited with code 4" in error and "nav2 crashed" in error
    assert processes_mentioning(out) == []
