# SPDX-License-Identifier: EPL-2.0
"""The ROS 2 bridge (docs/ros.md) on real DDS, with two navigation stacks as ROS 2 nodes in their own processes:
a node written on ros2-client (Rust, on RustDDS: a ROS 2 implementation independent of the Cyclone DDS the bridge
uses, with ros2-client's own action server; examples/sut/ros2/rust_nav_node, built by scripts/setup-ros2-node.sh
in run-tests' stage 1), and REI's reference navigation on Cyclone DDS (examples/sut/ros2/reference_nav_node.py).
No ROS 2 distribution installs here, so no rclcpp node is the stack."""

from __future__ import annotations

import json
import os
import re
import subprocess
import threading
import time
from pathlib import Path

import pytest

EXAMPLE = "examples/simple_navigation.rei"
NODES = "examples/sut/ros2"
DOMAIN_LINE = re.compile(r"rei ros2-bridge: ROS domain (\d+) \(the run's own\)")


@pytest.fixture(scope="module")
def rust_node(repo_root: Path) -> Path:
    """The ros2-client node's binary, up to date (scripts/setup-ros2-node.sh: nothing to do after stage 1)."""
    done = subprocess.run(["bash", str(repo_root / "scripts" / "setup-ros2-node.sh")], check=False,
                          capture_output=True, text=True, timeout=1200)
    assert done.returncode == 0, done.stderr
    binary = Path(done.stdout.strip().splitlines()[-1])
    assert binary.is_file(), done.stdout + done.stderr
    return binary


def _summary(out: Path) -> dict:
    return json.loads((out / "summary.json").read_text())


def _text(path: Path) -> str:
    return path.read_text() if path.is_file() else ""


def _domain(out: Path) -> int:
    match = DOMAIN_LINE.search((out / "sut.log").read_text())
    assert match, (out / "sut.log").read_text()
    return int(match.group(1))


def _assert_completed(result, out: Path) -> dict:  # type: ignore[no-untyped-def]
    assert result.returncode == 0, result.stdout + result.stderr + (out / "sut.log").read_text()
    summary = _summary(out)
    assert summary["status"] == "COMPLETED"
    assert summary["tasks"]["succeeded"] == summary["tasks"]["goals"] == 2
    assert {v["status"] for v in summary["verdicts"]} <= {"pass", "not-applicable"}
    return summary


def _stack_gone(out: Path) -> None:
    """The node the bridge started, and its process group, no longer exist."""
    match = re.search(r"pid (\d+)", (out / "ros" / "stack.log").read_text())
    assert match, (out / "ros" / "stack.log").read_text()
    with pytest.raises(ProcessLookupError):
        os.killpg(int(match.group(1)), 0)


def test_a_ros2_client_node_on_rustdds_completes_the_simple_navigation_example_through_the_action(
    run_cli, repo_root: Path, tmp_path: Path, rust_node: Path, processes_mentioning
) -> None:
    """Unmodified ros2-client and RustDDS: discovery with the bridge's Cyclone participant, every topic's CDR, the
    action's services in rmw_cyclonedds's mapping, and ros2-client's AsyncActionServer, which publishes a goal's
    final status only after the client asked for the result: without REI's get_result, no goal would end."""
    out = tmp_path / "out"
    result = run_cli("run", repo_root / EXAMPLE, "-o", out, "--sut", f"ros2:{rust_node} {out}", "--sut-map",
                     timeout=400)
    _assert_completed(result, out)
    stack_log = (out / "ros" / "stack.log").read_text()
    assert f"on ROS domain {_domain(out)}" in stack_log  # the node got the run's domain from ROS_DOMAIN_ID
    assert "map 140x100 cells" in stack_log  # REI's transient-local /map reached a late RustDDS reader
    assert stack_log.count("goal ended: Succeeded") == 2, stack_log  # result sent: REI asked for it
    assert processes_mentioning(out) == []
    _stack_gone(out)


def test_a_ros2_node_that_never_answers_a_goal_ends_the_run_in_error_naming_the_request(
    run_cli, repo_root: Path, tmp_path: Path, rust_node: Path, processes_mentioning
) -> None:
    out = tmp_path / "out"
    result = run_cli("run", repo_root / EXAMPLE, "-o", out, "--sut", f"ros2:{rust_node} --never-answer {out}",
                     "--sut-map", timeout=300)
    assert result.returncode == 2, result.stdout + result.stderr
    error = _summary(out)["error"]
    assert ("the navigate_to_pose action server (matched on ROS domain" in error
            and "did not answer goal 0's send_goal request within 10 s" in error), error
    assert "never answering goals" in (out / "ros" / "stack.log").read_text()
    assert f"last lines of {out / 'ros' / 'stack.log'}:" in error and "never answering goals" in error, error
    assert processes_mentioning(out) == []
    _stack_gone(out)


def test_two_ros2_runs_at_once_get_domains_of_their_own_and_both_complete(
    run_cli, repo_root: Path, tmp_path: Path, rust_node: Path, processes_mentioning
) -> None:
    """Both runs start together and are paced at wall-clock speed (~30 s of mission each), so both bridges hold
    their domains at once for most of that time, whatever the machine's load does to their start-up (b started once
    a's node had a goal, and on a loaded machine a ended before b's bridge was up). On one domain the two bridges'
    clocks, goals and commands would reach both nodes (each bridge matches every action server it discovers); on
    their own domains both runs pass."""
    a, b = tmp_path / "a", tmp_path / "b"
    results: dict[Path, object] = {}

    def run(out: Path) -> None:
        results[out] = run_cli("run", repo_root / EXAMPLE, "-o", out, "--sut", f"ros2:{rust_node} {out}",
                               "--sut-map", "--realtime", timeout=400)

    def wait_for(condition, thread: threading.Thread, log: Path) -> None:  # type: ignore[no-untyped-def]
        deadline = time.monotonic() + 120
        while not condition():
            assert thread.is_alive() and time.monotonic() < deadline, _text(log)
            time.sleep(0.1)

    first = threading.Thread(target=run, args=(a,))
    second = threading.Thread(target=run, args=(b,))
    first.start()
    second.start()
    for out, thread in ((a, first), (b, second)):
        wait_for(lambda out=out: "goal" in _text(out / "ros" / "stack.log"), thread, out / "sut.log")
    assert not (a / "summary.json").exists() and not (b / "summary.json").exists()  # both nodes have goals now
    for thread in (first, second):
        thread.join()
    for out in (a, b):
        _assert_completed(results[out], out)
    assert _domain(a) != _domain(b)
    assert processes_mentioning(a) == [] and processes_mentioning(b) == []


def test_the_reference_navigation_on_dds_completes_the_simple_navigation_example_through_the_action(
    run_cli, repo_root: Path, tmp_path: Path, processes_mentioning
) -> None:
    out = tmp_path / "out"
    result = run_cli("run", repo_root / EXAMPLE, "-o", out, "--sut",
                     f"ros2:python3 {repo_root / NODES / 'reference_nav_node.py'} {out}", "--sut-map", timeout=400)
    _assert_completed(result, out)
    _domain(out)  # the run's own domain
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


def test_a_ros2_stack_without_the_action_server_is_named_in_the_join_timeout_s_error(
        run_cli, repo_root: Path, tmp_path: Path, processes_mentioning) -> None:
    """A stack that is not matched (no /clock subscription, no NavigateToPose server): REI's join timeout ended the
    run with "no command for tick 0" before the bridge's own 60 s wait said what was missing; now the bridge's note
    of it is in the error's last lines."""
    out = tmp_path / "out"
    result = run_cli("run", repo_root / EXAMPLE, "-o", out, "--sut-join-timeout", "12", "--sut",
                     f"ros2:python3 -c \"import time; time.sleep(60)\" {out}", timeout=300)
    assert result.returncode == 2, result.stdout + result.stderr
    error = _summary(out)["error"]
    assert "no command for tick 0" in error and "the stack is not matched after 5 s" in error, error
    assert "a /clock subscription (rt/clock)" in error
    assert processes_mentioning(out) == []


def test_a_holonomic_robot_strafes_on_cmd_vel_s_linear_y(strafes, repo_root: Path) -> None:
    """The strafe example through the bridge: the reference node plays the sideways-only script."""
    strafes(lambda script, out: f"ros2:python3 {repo_root / NODES / 'reference_nav_node.py'} --script {script} {out}")
