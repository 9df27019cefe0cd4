# SPDX-License-Identifier: EPL-2.0
"""The motion's faults from the test case's faults block to the run: the language reads them, the generator writes
them to mission.xml, the simulator reads them back with the ``--fault`` reader and sends their window edges as
mission events; bad ones are refused with their position (a case) or the spec (``--fault``), exit 2 before
anything runs."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from pathlib import Path

from rei.wamp.recording import read_recording

CASE = """testcase T {
  room R size 6 x 4 {
    robot r : Waffle on F_0_0
  }
  mission M { goto F_3_0 within 4s goto F_4_0 within 4s }
  faults {
    commands latency delay 0.2s from 1s to 2s
    commands loss probability 0.5 from 2s to 3s
    drive slip fraction 0.5 from 3s to 4s
    drive stuck wheel right from 4s to 4.5s
    odometry drift scale 1.1 bias 3 from 0.5s to 5s
    odometry jump dx 0.2 from 5s to 5.5s
    pose kidnap dx 0.3 dy 0.2 dyaw 45 from 6s
  }
}
"""


def test_a_faults_block_of_motion_faults_is_generated_run_and_sent_as_events(run_cli, tmp_path: Path) -> None:
    case = tmp_path / "moved.rei"
    case.write_text(CASE)
    generated = run_cli("generate", case, "-o", tmp_path / "gen")
    assert generated.returncode == 0, generated.stderr
    faults = [dict(f.attrib) for f in ET.parse(tmp_path / "gen" / "mission.xml").getroot().iter("fault")]
    assert faults == [
        {"sensor": "commands", "kind": "latency", "from": "1.0", "to": "2.0", "delay": "0.2"},
        {"sensor": "commands", "kind": "loss", "from": "2.0", "to": "3.0", "probability": "0.5"},
        {"sensor": "drive", "kind": "slip", "from": "3.0", "to": "4.0", "fraction": "0.5"},
        {"sensor": "drive", "kind": "stuck", "from": "4.0", "to": "4.5", "wheel": "right"},
        {"sensor": "odometry", "kind": "drift", "from": "0.5", "to": "5.0", "scale": "1.1", "bias": "3.0"},
        {"sensor": "odometry", "kind": "jump", "from": "5.0", "to": "5.5", "dx": "0.2"},
        {"sensor": "pose", "kind": "kidnap", "from": "6.0", "dx": "0.3", "dy": "0.2", "dyaw": "45.0"},
    ]
    sim = run_cli("sim", tmp_path / "gen", "-o", tmp_path / "out", "--no-router", "--no-humans", "--seed", "2")
    assert sim.returncode in (0, 1), sim.stderr
    events = [(m["t"], m["event"]) for m in read_recording(tmp_path / "out" / "streams" / "mission.msgpack")
              if m["event"].startswith("FAULT_")]
    assert events == [
        (0.5, "FAULT_ODOMETRY_DRIFT_BEGIN"), (1.0, "FAULT_COMMANDS_LATENCY_BEGIN"),
        (2.0, "FAULT_COMMANDS_LATENCY_END"), (2.0, "FAULT_COMMANDS_LOSS_BEGIN"), (3.0, "FAULT_COMMANDS_LOSS_END"),
        (3.0, "FAULT_DRIVE_SLIP_BEGIN"), (4.0, "FAULT_DRIVE_SLIP_END"), (4.0, "FAULT_DRIVE_STUCK_BEGIN"),
        (4.5, "FAULT_DRIVE_STUCK_END"), (5.0, "FAULT_ODOMETRY_DRIFT_END"), (5.0, "FAULT_ODOMETRY_JUMP_BEGIN"),
        (5.5, "FAULT_ODOMETRY_JUMP_END"), (6.0, "FAULT_POSE_KIDNAP_BEGIN")]
    summary = json.loads((tmp_path / "out" / "sim.json").read_text())
    assert [(f["sensor"], f["kind"]) for f in summary["faults"]] == [(f["sensor"], f["kind"]) for f in faults]


def test_bad_motion_faults_are_refused_with_their_position(run_cli, tmp_path: Path) -> None:
    case = tmp_path / "bad.rei"
    case.write_text(CASE.replace("drive slip fraction 0.5", "drive slip fraction 2").replace(
        "commands loss probability 0.5", "commands loss"))
    result = run_cli("sim", case, "-o", tmp_path / "out")
    assert result.returncode == 1 and not (tmp_path / "out" / "streams").exists()
    assert f"{case}:8:14: error: A commands loss fault needs 'probability' [org.rei.dsl.faultParameter]" in result.stderr
    assert (f"{case}:9:25: error: The fraction of the commanded motion the robot makes: expected more than 0 and at "
            "most 1 [org.rei.dsl.outOfRange]") in result.stderr


def test_a_latency_off_the_control_periods_exits_two_before_anything_runs(run_cli, repo_root: Path,
                                                                           tmp_path: Path) -> None:
    result = run_cli("sim", repo_root / "examples" / "simple_navigation.rei", "-o", tmp_path / "out",
                     "--fault", "commands:latency,delay=0.15,from=2")
    assert result.returncode == 2 and not (tmp_path / "out").exists()
    assert "a command latency of 0.15 s is not a whole number of control periods at 10 Hz" in result.stderr
    kind = run_cli("sim", repo_root / "examples" / "simple_navigation.rei", "-o", tmp_path / "out",
                   "--fault", "drive:skid,fraction=0.5")
    assert kind.returncode == 2 and "unknown drive fault 'skid': known kinds slip, stuck" in kind.stderr


def test_a_case_s_latency_off_the_control_periods_is_refused_before_the_run(run_cli, tmp_path: Path) -> None:
    case = tmp_path / "late.rei"
    case.write_text(CASE.replace("delay 0.2s", "delay 0.15s"))
    result = run_cli("sim", case, "-o", tmp_path / "out", "--no-router")
    assert result.returncode == 2 and not (tmp_path / "out" / "streams").exists()
    assert ("mission.xml: faults: a command latency of 0.15 s is not a whole number of control periods at 10 Hz "
            "(periods of 0.1 s)") in result.stderr


def test_rei_run_refuses_a_case_s_latency_off_the_control_periods_before_its_monitor_starts(
        run_cli, tmp_path: Path) -> None:
    case = tmp_path / "late.rei"
    case.write_text(CASE.replace("delay 0.2s", "delay 0.15s"))
    out = tmp_path / "out"
    result = run_cli("run", case, "-o", out, timeout=300)
    # before: the run started, its simulation exited with 2 and every verdict was an ERROR of the run
    assert result.returncode == 2, result.stdout + result.stderr
    assert ("mission.xml: faults: a command latency of 0.15 s is not a whole number of control periods at 10 Hz "
            "(periods of 0.1 s)") in result.stderr
    assert not (out / "monitor.log").exists() and not (out / "summary.json").exists()
    assert not (out / "streams").exists()


def test_rei_run_refuses_a_stuck_wheel_of_a_holonomic_robot_before_its_monitor_starts(
        run_cli, repo_root: Path, tmp_path: Path) -> None:
    omni = repo_root / "bundles" / "org.rei.dsl" / "src" / "test" / "resources" / "catalogues" / "omni.rei"
    case = tmp_path / "omni.rei"
    case.write_text(f'import "{omni}"\n' + CASE.split("  faults {")[0].replace("r : Waffle", "r : Omni") + "}\n")
    out = tmp_path / "out"
    result = run_cli("run", case, "-o", out, "--fault", "drive:stuck,wheel=left,from=1", timeout=300)
    assert result.returncode == 2, result.stdout + result.stderr
    assert "robot: r is holonomic, and a stuck wheel is a fault of a differential drive" in result.stderr
    assert not (out / "monitor.log").exists() and not (out / "summary.json").exists()
