# SPDX-License-Identifier: EPL-2.0
"""`rei sim` as a user runs it: real processes, the router started by the tool, the recorded streams."""

from __future__ import annotations

import itertools
import json
from pathlib import Path

from rei.wamp.recording import read_recording


def test_runs_an_example_through_a_router_it_starts_and_stops(
    run_cli, processes_mentioning, repo_root: Path, tmp_path: Path
) -> None:
    out = tmp_path / "out"
    result = run_cli("sim", repo_root / "examples" / "simple_navigation.rei", "-o", "out", "--no-humans", "--seed", "3",
                     cwd=tmp_path)  # relative, as a user types it
    assert result.returncode == 0, result.stderr
    assert "mission succeeded" in result.stdout
    states = read_recording(out / "streams" / "state.msgpack")
    assert [m["seq"] for m in states] == list(range(len(states)))
    summary = json.loads((out / "sim.json").read_text())
    assert summary["succeeded"] and summary["options"]["seed"] == 3
    # 20 state messages per simulated second, whatever the wall-clock speed
    assert abs(len(states) - 20 * summary["sim_time"]) <= 2
    assert (out / "router" / "crossbar.log").is_file()  # a router really ran for this run ...
    assert processes_mentioning(out / "router") == []  # ... and nothing of it is left


def test_a_failing_mission_exits_one_with_the_reason(run_cli, repo_root: Path, tmp_path: Path) -> None:
    script = tmp_path / "spin.txt"
    script.write_text("3.0 0.0 1.0\n")
    result = run_cli("sim", repo_root / "examples" / "simple_navigation.rei", "-o", tmp_path / "out",
                     "--controller", f"script:{script}", "--no-router")
    assert result.returncode == 1, result.stderr
    assert "FAIL" in result.stdout and "false success" in result.stdout


def test_a_bad_faults_block_is_refused_with_its_position(run_cli, tmp_path: Path) -> None:
    case = tmp_path / "blind.rei"
    case.write_text("testcase T {\n  room R size 3 x 2 {\n    robot r : Waffle on F_0_0\n  }\n"
                    "  mission M { goto F_1_1 goto F_2_1 }\n  faults {\n    laser noise from 2s to 1s\n  }\n}\n")
    result = run_cli("sim", case, "-o", tmp_path / "out")
    assert result.returncode == 1 and not (tmp_path / "out" / "streams").exists()  # as for any invalid case
    assert f"{case}:7:11: error: A laser noise fault needs 'sigma' (metres) [org.rei.dsl.faultParameter]" in result.stderr
    assert f"{case}:7:28: error: 'to' must be after 'from' (2.0 s) [org.rei.dsl.faultTimeOrder]" in result.stderr


def test_bad_arguments_exit_two_before_anything_runs(run_cli, repo_root: Path, tmp_path: Path) -> None:
    example = repo_root / "examples" / "simple_navigation.rei"
    unknown = run_cli("sim", example, "-o", tmp_path / "a", "--controller", "teleport")
    assert unknown.returncode == 2
    assert "teleport" in unknown.stderr and "nav" in unknown.stderr
    fault = run_cli("sim", example, "-o", tmp_path / "b", "--fault", "laser:rate=lots")
    assert fault.returncode == 2 and "laser:rate=lots" in fault.stderr
    order = run_cli("sim", example, "-o", tmp_path / "c", "--fault", "laser:freeze,from=1,to=2;laser:blackout,from=7,to=5")
    assert order.returncode == 2 and not (tmp_path / "c").exists()
    assert "bad fault spec 'laser:blackout,from=7,to=5': 'to' (5 s) must be after 'from' (7 s)" in order.stderr
    animation = run_cli("sim", example, "-o", tmp_path / "d", "--animation", "sideways")
    assert animation.returncode == 2 and "--animation" in animation.stderr and "force" in animation.stderr
    settings = tmp_path / "collector.yaml"
    settings.write_text("rate_hz: 20\nlaser: some\n")
    collector = run_cli("sim", example, "-o", tmp_path / "e", "--collector", settings)
    assert collector.returncode == 2 and f"{settings}:2:8: laser must be full | min | none" in collector.stderr
    missing = run_cli("sim", tmp_path / "nope.rei", "-o", tmp_path / "c")
    assert missing.returncode == 2 and "nope.rei" in missing.stderr


def test_a_run_of_a_generated_folder_is_replayed_without_naming_the_case_again(
    run_cli, repo_root: Path, tmp_path: Path
) -> None:
    generated = run_cli("generate", repo_root / "examples" / "simple_navigation.rei", "-o", tmp_path / "gen")
    assert generated.returncode == 0, generated.stderr
    collector = tmp_path / "collector.yaml"
    collector.write_text("rate_hz: 10\nlaser: none\nodometry: false\n")
    sim = run_cli("sim", tmp_path / "gen", "-o", tmp_path / "out", "--no-router", "--animation", "force",
                  "--collector", collector)
    assert sim.returncode == 0, sim.stderr
    assert not (tmp_path / "out" / "case").exists()  # the case stayed where it was generated ...
    summary = json.loads((tmp_path / "out" / "sim.json").read_text())
    assert summary["case"] == str((tmp_path / "gen").resolve())
    # the human walked, pushed by forces through the contact solver instead of given velocities
    assert summary["options"]["animation"] == "force"
    states = read_recording(tmp_path / "out" / "streams" / "state.msgpack")
    walker = [o["pose"][0] for m in states for o in m["objects"] if o["name"] == "walker"]
    assert len(walker) > 100 and max(walker) - min(walker) > 2.0, (min(walker), max(walker))
    # the collector's settings came from the file: 10 states per simulated second, no laser, no odometry
    assert abs(len(states) - 10 * summary["sim_time"]) <= 2
    assert not any("laser_min" in m["robot"] or "odom" in m["robot"] for m in states)
    replay = run_cli("monitor", "--replay", tmp_path / "out")  # ... and sim.json says where
    assert replay.returncode == 0, replay.stderr
    assert "SIG_MISSION_END" in replay.stdout


def test_the_user_catalogue_example_runs_with_its_own_robot_and_furniture(
    run_cli, repo_root: Path, tmp_path: Path
) -> None:
    out = tmp_path / "out"
    result = run_cli("sim", repo_root / "examples" / "own_types.rei", "-o", out, "--no-router", "--laser", "full")
    assert result.returncode == 0, result.stderr
    assert "mission succeeded" in result.stdout
    world = json.loads((out / "case" / "world.json").read_text())
    robot = world["robot"]
    assert (robot["type"], robot["size"], robot["lidar"]["rate"]) == ("Burger", [0.138, 0.178, 0.192], 5.0)
    assert {o["type"] for o in world["objects"] if o["category"] == "STATIC"} == {"Sofa", "Pillar", "Plant", "Table"}
    # the Burger's lidar scans 5 times a second: a new scan every 4th state at 20 Hz
    states = read_recording(out / "streams" / "state.msgpack")
    scans = [m["robot"]["laser_ranges"] for m in states[:41] if "laser_ranges" in m["robot"]]
    changes = sum(a != b for a, b in itertools.pairwise(scans))
    assert 9 <= changes <= 10, changes


def test_the_collector_publishes_only_the_objects_its_settings_name(run_cli, repo_root: Path, tmp_path: Path) -> None:
    example = repo_root / "examples" / "simple_navigation.rei"
    settings = tmp_path / "collector.yaml"
    settings.write_text("objects: [DYNAMIC]\n")  # the example's only moving object is the human walker
    out = tmp_path / "out"
    sim = run_cli("sim", example, "-o", out, "--no-router", "--collector", settings)
    assert sim.returncode == 0, sim.stderr
    states = read_recording(out / "streams" / "state.msgpack")
    assert len(states) > 100 and not any(o["type"] == "HUMAN" for m in states for o in m["objects"])
    assert states[0]["full"] is True and states[0]["objects"] == []  # no human, and statics are in world.json only
    replay = run_cli("monitor", "--replay", out)
    assert replay.returncode == 0, replay.stderr
    settings.write_text("objects: [walkr]\n")
    typo = run_cli("sim", example, "-o", tmp_path / "typo", "--no-router", "--collector", settings)
    assert typo.returncode == 2
    assert f"{settings}: collector objects: 'walkr' is neither a moving object of the case (walker)" in typo.stderr
    assert not (tmp_path / "typo" / "streams").exists()
