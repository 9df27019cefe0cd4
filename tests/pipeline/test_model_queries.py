# SPDX-License-Identifier: EPL-2.0
"""Queries over the runtime model (`--queries`) named by patterns (`--patterns`): the four requirements of
examples/patterns each fire on the case that triggers them, at a time the recorded run explains (the robot was
still, a human was next to it, its odometry was off, its navigation aborted twice), and none fires on the simple
navigation example. Real processes: the simulator, the monitor jar, and for `rei run` the router and the live
monitor."""

from __future__ import annotations

import math
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from rei.wamp.recording import read_recording

PATTERNS = Path(__file__).resolve().parents[2] / "examples" / "patterns"
CASES = PATTERNS / "cases"
OWN = ("SIG_ROBOT_STILL_IN_TASK", "SIG_HUMAN_NEXT_TO_ROBOT_ON_F_3_2", "SIG_ODOMETRY_DRIFT",
       "SIG_NAVIGATION_ABORTED_TWICE")
LINE = re.compile(r"^\s*\d+\s+(\S+)\s+(SIG_\S+)\s+(\S+)\s+(\S*)\s+\S+\s*$")


def replay(run_cli, out: Path) -> list[tuple[float, str, str]]:
    """The run's signals of the example requirements: (t, signal, object)."""
    result = run_cli("monitor", "--replay", out, "--queries", PATTERNS, "--patterns", PATTERNS)
    assert result.returncode == 0, result.stderr
    rows = [LINE.match(line) for line in result.stdout.splitlines()]
    return [(float(m[1]), m[2], m[4]) for m in rows if m is not None and m[2] in OWN]


def simulate(run_cli, case: Path, script: Path, out: Path) -> list[dict]:
    result = run_cli("sim", case, "-o", out, "--no-router", "--controller", f"script:{script}")
    assert result.returncode == 0, result.stderr
    return read_recording(out / "streams" / "state.msgpack")


def floor_of(x: float, y: float) -> tuple[int, int]:
    return math.floor(x), math.floor(y)


def test_standing_still_five_seconds_in_a_task(run_cli, tmp_path: Path) -> None:
    states = simulate(run_cli, CASES / "standstill.rei", CASES / "standstill.script", tmp_path / "out")
    ((t, signal, _),) = replay(run_cli, tmp_path / "out")
    assert signal == "SIG_ROBOT_STILL_IN_TASK"
    missions = read_recording(tmp_path / "out" / "streams" / "mission.msgpack")
    started = min(m["t"] for m in missions if m["event"] == "TASK_START")
    ended = min(m["t"] for m in missions if m["event"] in ("TASK_SUCCESS", "TASK_FAIL"))
    assert started <= t - 5 and t < ended
    still = [m for m in states if t - 5 <= m["t"] <= t]
    assert len(still) >= 100 and all(max(map(abs, m["robot"]["twist"])) < 0.01 for m in still)
    before = [m for m in states if t - 5.2 <= m["t"] < t - 5]
    assert any(max(map(abs, m["robot"]["twist"])) >= 0.01 for m in before)  # it had just stopped: the first moment


def test_the_robot_on_f_3_2_with_a_human_on_a_neighbouring_floor(run_cli, tmp_path: Path) -> None:
    states = simulate(run_cli, CASES / "next_to_human.rei", CASES / "next_to_human.script", tmp_path / "out")
    signals = replay(run_cli, tmp_path / "out")  # the robot also waits there longer than 5 s
    ((t, _, human),) = [s for s in signals if s[1] == "SIG_HUMAN_NEXT_TO_ROBOT_ON_F_3_2"]
    assert human == "walker"
    at = min(states, key=lambda m: abs(m["t"] - t))
    robot = floor_of(*at["robot"]["pose"][:2])
    walker = floor_of(*next(o["pose"][:2] for o in at["objects"] if o["name"] == "walker"))
    assert robot == (3, 2) and abs(walker[0] - 3) + abs(walker[1] - 2) == 1, (robot, walker)


def test_odometry_drifting_more_than_0_3_m(run_cli, tmp_path: Path) -> None:
    scenario = PATTERNS.parent / "thesis_7_2"  # pushing the box makes the wheels slip
    states = simulate(run_cli, scenario / "translation.rei", scenario / "translation.script", tmp_path / "out")
    ((t, signal, _),) = replay(run_cli, tmp_path / "out")
    assert signal == "SIG_ODOMETRY_DRIFT"

    def drift(m: dict) -> float:
        (x, y, _, _), (ox, oy, _) = m["robot"]["pose"], m["robot"]["odom"]
        return math.hypot(x - ox, y - oy)

    index = next(i for i, m in enumerate(states) if m["t"] == pytest.approx(t, abs=1e-6))
    assert drift(states[index]) > 0.3 >= drift(states[index - 1])


def test_navigation_aborted_twice_in_one_task(run_cli, tmp_path: Path) -> None:
    out = tmp_path / "out"
    generated = run_cli("generate", CASES / "standstill.rei", "-o", out / "case")
    assert generated.returncode == 0, generated.stderr
    subprocess.run([sys.executable, str(CASES / "aborted_twice.py"), str(out)], check=True, timeout=60)
    # task 0 aborts at 3 s and again at 6 s; task 1 aborts once (the robot also stands still, 5 s into task 0)
    assert [s for s in replay(run_cli, out) if s[1] == "SIG_NAVIGATION_ABORTED_TWICE"] == [
        (6.0, "SIG_NAVIGATION_ABORTED_TWICE", "")]


def test_none_fires_on_the_simple_navigation_example_and_the_run_keeps_its_queries(
    run_cli, processes_mentioning, repo_root: Path, tmp_path: Path
) -> None:
    out = tmp_path / "out"
    result = run_cli("run", repo_root / "examples" / "simple_navigation.rei", "-o", out, "--queries", PATTERNS,
                     "--patterns", PATTERNS, timeout=300)
    assert result.returncode == 0, result.stdout + result.stderr
    events = (out / "events.csv").read_text()
    assert "SIG_MISSION_END" in events and not any(signal in events for signal in OWN)
    assert (out / "queries" / "requirements.drl").read_text() == (PATTERNS / "requirements.drl").read_text()
    assert processes_mentioning(out) == []
    # the model as facts leaves the default signals alone: the same lines, byte for byte, as a replay without them
    plain = tmp_path / "plain"
    shutil.copytree(out / "streams", plain / "streams")
    with_queries = run_cli("monitor", "--replay", out, "--case", out / "case")
    without = run_cli("monitor", "--replay", plain, "--case", out / "case")
    assert with_queries.returncode == without.returncode == 0, with_queries.stderr + without.stderr
    assert with_queries.stdout == without.stdout and "SIG_MISSION_END" in without.stdout
    again = run_cli("evaluate", out, timeout=300)  # the replay loads the kept queries: the patterns still compile
    assert again.returncode == 0, again.stdout + again.stderr


def test_a_malformed_query_stops_rei_run_with_file_and_line_before_anything_starts(
    run_cli, repo_root: Path, tmp_path: Path
) -> None:
    queries = tmp_path / "queries"
    queries.mkdir()
    (queries / "broken.drl").write_text("package rei;\n\nquery broken(String subject)\n"
                                        "    RobotDescription( subject := name )\nend\n")
    out = tmp_path / "out"
    result = run_cli("run", repo_root / "examples" / "simple_navigation.rei", "-o", out, "--queries", queries)
    assert result.returncode == 2
    assert f"{queries / 'broken.drl'}:4:" in result.stderr and "RobotDescription" in result.stderr, result.stderr
    assert not out.exists()


def test_a_generated_rooms_default_signals_are_the_same_with_the_model_queries_loaded(
    run_cli, tmp_path: Path
) -> None:
    """As a campaign judges its rooms: simulate one (furniture and a walking human), replay it with and without
    the example queries and patterns; the default signals agree byte for byte."""
    rooms = tmp_path / "rooms"
    made = run_cli("gen-rooms", "--size", "small", "--humans", "1", "--seed", "4", "--count", "1", "-o", rooms,
                   "--no-check")
    assert made.returncode == 0, made.stderr
    (room,) = rooms.glob("*.rei")
    out = tmp_path / "out"
    sim = run_cli("sim", room, "-o", out, "--no-router", timeout=300)
    assert sim.returncode in (0, 1), sim.stderr  # a failed task is a verdict, not a broken run
    plain = run_cli("monitor", "--replay", out)
    loaded = run_cli("monitor", "--replay", out, "--queries", PATTERNS, "--patterns", PATTERNS)
    assert plain.returncode == loaded.returncode == 0, plain.stderr + loaded.stderr
    own = [line for line in loaded.stdout.splitlines() if any(signal in line for signal in OWN)]
    defaults = [line for line in loaded.stdout.splitlines() if line not in own]
    expected = plain.stdout.splitlines()
    assert len(expected) > 10 and any("SIG_GEOM_" in line for line in expected)
    # the example signals take sequence numbers of their own: compare the default signals without them
    assert [line.split(None, 1)[1] for line in defaults] == [line.split(None, 1)[1] for line in expected]
