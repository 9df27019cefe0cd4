# SPDX-License-Identifier: EPL-2.0
"""The ROS 1 bridge (docs/ros.md) with a real ROS master and rospy nodes as the system under test."""

from __future__ import annotations

import json
from pathlib import Path

EXAMPLE = "examples/simple_navigation.rei"
NODES = "examples/sut/ros1"


def _summary(out: Path) -> dict:
    return json.loads((out / "summary.json").read_text())


def _verdicts(out: Path) -> dict[str, dict]:
    return {v["requirement"]: v for v in _summary(out)["verdicts"]}


def test_the_reference_navigation_as_a_ros_node_completes_the_simple_navigation_example(
    run_cli, repo_root: Path, tmp_path: Path, processes_mentioning
) -> None:
    out = tmp_path / "out"
    result = run_cli("run", repo_root / EXAMPLE, "-o", out, "--sut",
                     f"ros1:python3 {repo_root / NODES / 'reference_nav_node.py'} {out}", "--sut-map", timeout=400)
    assert result.returncode == 0, result.stdout + result.stderr + (out / "sut.log").read_text()
    summary = _summary(out)
    assert summary["status"] == "COMPLETED"
    assert summary["tasks"]["succeeded"] == summary["tasks"]["goals"] == 2
    assert {v["status"] for v in summary["verdicts"]} <= {"pass", "not-applicable"}
    assert (out / "ros" / "stack.log").is_file() and (out / "ros" / "log" / "rosmaster.out").is_file()
    assert processes_mentioning(out) == []  # the node, the master and rosout are gone
    assert processes_mentioning(out / "ros") == []


def test_the_ramming_script_as_a_ros_node_fails_mission_simple_with_the_in_process_evidence(
    run_cli, repo_root: Path, tmp_path: Path, processes_mentioning
) -> None:
    out = tmp_path / "out"
    result = run_cli("run", repo_root / EXAMPLE, "-o", out, "--no-humans", "--sut",
                     f"ros1:python3 {repo_root / NODES / 'ram_node.py'} {out}", timeout=400)
    assert result.returncode == 1, result.stdout + result.stderr + (out / "sut.log").read_text()
    simple = _verdicts(out)["MISSION_SIMPLE"]
    assert simple["status"] == "fail"
    evidence = simple["evidence"][0]
    # as tests/pipeline/test_rei_run.py's in-process script: a 2 s turn towards table1, then ~1.3 m to its edge
    assert evidence["object"] == "table1" and 6.0 < evidence["t"] < 9.0
    assert processes_mentioning(out) == []


def test_a_stack_that_dies_ends_the_run_in_error_with_its_log(run_cli, repo_root: Path, tmp_path: Path,
                                                             processes_mentioning) -> None:
    out = tmp_path / "out"
    result = run_cli("run", repo_root / EXAMPLE, "-o", out, "--sut",
                     f"ros1:python3 -c \"import sys; print('planner crashed', flush=True); sys.exit(4)\" {out}",
                     timeout=300)
    assert result.returncode == 2, result.stdout + result.stderr
    error = _summary(out)["error"]
    assert "the ROS navigation stack exited with code 4" in error and "planner crashed" in error
    assert processes_mentioning(out) == []


def test_a_holonomic_robot_strafes_on_cmd_vel_s_linear_y(strafes, repo_root: Path) -> None:
    """The strafe example through the bridge: the ramming node plays its sideways-only script."""
    strafes(lambda script, out: f"ros1:python3 {repo_root / NODES / 'ram_node.py'} _script:={script} {out}")


def test_a_stack_without_the_move_base_server_is_named_in_the_join_timeout_s_error(
        run_cli, repo_root: Path, tmp_path: Path, processes_mentioning) -> None:
    """A stack serving no move_base action: REI's join timeout (60 s by default, as the bridge's own wait for the
    server, and counted from earlier) ended the run with "no command for tick 0" and a sut.log that said only that
    the stack was started; now the bridge's note of what it waits for is in the error's last lines."""
    out = tmp_path / "out"
    result = run_cli("run", repo_root / EXAMPLE, "-o", out, "--sut-join-timeout", "12", "--sut",
                     f"ros1:python3 -c \"import time; time.sleep(60)\" {out}", timeout=300)
    assert result.returncode == 2, result.stdout + result.stderr
    error = _summary(out)["error"]
    assert "no command for tick 0" in error and "no move_base action server after 5 s" in error, error
    assert "move_base_msgs/MoveBaseAction" in error
    assert processes_mentioning(out) == []
