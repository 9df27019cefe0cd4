# SPDX-License-Identifier: EPL-2.0
"""Who was at fault in a collision with a person (docs/metrics.md "People"), in the real simulation and judged
by the monitor: a scripted robot driving at 0.26 m/s into a person who stands in its lane, and a person walking
into a robot that stands. In pybullet the impact has already stopped the driving robot by the first state sample
in COLLISION, so the judgement must not read that sample alone. `rei evaluate` replays each run through the
monitor: NO_ROBOT_AT_FAULT_COLLISION fails the first with the person's name, the time of the monitor's collision
signal and the speed, and passes the second, while MISSION_WITH_HUMAN_TRAJECTORY fails both."""

from __future__ import annotations

import json

import pytest

CASES = {
    # the person stands on F_2_0 (centre 2.5, 0.5) in the lane of the robot, which starts on F_0_0 facing +x
    "ram": ("""testcase RamPerson {
  room Lane size 5 x 3 {
    human stander trajectory [F_2_0 @ 0s, F_2_0 @ 60s] once
    robot tb3 : Waffle on F_0_0
  }
  mission Go { goto F_4_0 within 60s goto F_4_1 }
}
""", "12.0 0.26 0.0\n"),
    # the person walks from F_4_0 to F_0_0 at 0.5 m/s through the robot standing on F_1_0
    "walk": ("""testcase WalkInto {
  room Lane size 5 x 3 {
    human walker trajectory [F_4_0 @ 0s, F_0_0 @ 8s] once
    robot tb3 : Waffle on F_1_0
  }
  mission Go { goto F_1_2 within 60s goto F_0_2 }
}
""", "12.0 0.0 0.0\n"),
}


@pytest.fixture(scope="module")
def judged(run_cli, tmp_path_factory: pytest.TempPathFactory) -> dict[str, dict]:
    folder = tmp_path_factory.mktemp("social")
    out = {}
    for name, (case, script) in CASES.items():
        (folder / f"{name}.rei").write_text(case, encoding="utf-8")
        (folder / f"{name}.script").write_text(script, encoding="utf-8")
        generated = run_cli("generate", folder / f"{name}.rei", "-o", folder / f"{name}-case")
        assert generated.returncode == 0, generated.stderr
        sim = run_cli("sim", folder / f"{name}-case", "-o", folder / name, "--no-router",
                      "--controller", f"script:{folder / f'{name}.script'}")
        assert sim.returncode in (0, 1), sim.stderr
        evaluated = run_cli("evaluate", folder / name)
        assert evaluated.returncode == 1, evaluated.stdout + evaluated.stderr  # the collision fails verdicts
        out[name] = json.loads((folder / name / "summary.json").read_text())
    return out


def _verdict(summary: dict, requirement: str) -> dict:
    return next(v for v in summary["verdicts"] if v["requirement"] == requirement)


def test_a_robot_driving_into_a_standing_person_is_at_fault(judged: dict[str, dict]) -> None:
    summary = judged["ram"]
    metrics = summary["metrics"]
    assert (metrics["collisions_robot_at_fault"], metrics["collisions_person_at_fault"]) == (1, 0), metrics
    assert metrics["ttc_humans_min"] == 0.0 and metrics["intimate_time"] > 0
    verdict = _verdict(summary, "NO_ROBOT_AT_FAULT_COLLISION")
    assert verdict["status"] == "fail", verdict
    (evidence,) = verdict["evidence"]
    assert evidence["object"] == "stander" and evidence["signal"] == "SIG_OBJECT_COLLISION_BEGIN"
    # the speed it drove in with, not what the impact left of it
    assert "at 0.26 m/s towards their centre" in evidence["text"], evidence
    assert _verdict(summary, "MISSION_WITH_HUMAN_TRAJECTORY")["status"] == "fail"


def test_a_person_walking_into_a_standing_robot_is_at_fault(judged: dict[str, dict]) -> None:
    summary = judged["walk"]
    metrics = summary["metrics"]
    assert (metrics["collisions_robot_at_fault"], metrics["collisions_person_at_fault"]) == (0, 1), metrics
    verdict = _verdict(summary, "NO_ROBOT_AT_FAULT_COLLISION")
    assert verdict["status"] == "pass", verdict
    assert verdict["evidence"][0]["text"].startswith("person at fault: walker walked into the robot")
    assert _verdict(summary, "MISSION_WITH_HUMAN_TRAJECTORY")["status"] == "fail"
    # the walker walks straight: no heading change
    assert metrics["path_irregularity_humans"] < 0.05
