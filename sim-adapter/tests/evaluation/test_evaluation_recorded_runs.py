# SPDX-License-Identifier: EPL-2.0
"""End to end on real data: `rei sim` records a run (generated from the example), the monitor jar replays it
into signals, and the evaluator judges them offline.

The monitor prints one line per signal, ``seq t signal subject object distance`` (docs/monitor.md); it has no
machine-readable output option in the built jar, so the lines are parsed here. Two runs: the reference
navigation of simple_navigation (every applicable requirement holds) and a scripted robot that turns towards
the table and rams it (MISSION_SIMPLE fails with the collision's time and table1 as evidence).
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest

from rei import toolchain
from rei.artifacts import read_mission
from rei.evaluation import DEFAULT_UTILITIES, Evaluator, Status, Summary, replay
from rei.mission import mission_info
from rei.wamp import read_recording

REPO = Path(__file__).resolve().parents[3]
EXAMPLE = REPO / "examples" / "simple_navigation.rei"
#: Turn towards the table, then drive straight into it (docs: scripted controller, `duration v w`).
RAM_TABLE = "2.0 0.0 0.2318\n12.0 0.26 0.0\n"
TIMEOUT_S = 300.0


@dataclass(frozen=True, slots=True)
class Evaluated:
    signals: list[dict[str, Any]]
    summary: Summary
    out: Path


def _run(argv: list[str], cwd: Path | None = None) -> str:
    """Run to completion (the whole process group is killed on a timeout) and return stdout."""
    process = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, stdin=subprocess.DEVNULL,
                               text=True, cwd=cwd, env={**os.environ, "REI_HOME": str(REPO)},
                               start_new_session=True)
    try:
        stdout, stderr = process.communicate(timeout=TIMEOUT_S)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        process.communicate()
        pytest.fail(f"{' '.join(argv)} did not finish within {TIMEOUT_S} s")
    assert process.returncode in (0, 1), f"{' '.join(argv)} exited {process.returncode}: {stderr[-2000:]}"
    return stdout


def parse_monitor_lines(text: str) -> list[dict[str, Any]]:
    """The monitor's replay output as signal messages (``seq t signal subject object distance`` per line)."""
    signals = []
    for line in text.splitlines():
        seq, t, name, subject, obj, distance = line.split()
        signals.append({"seq": int(seq), "t": float(t), "signal": name, "subject": subject, "object": obj,
                        "distance": float(distance)})
    return signals


def _simulate_and_evaluate(tmp: Path, *sim_args: str) -> Evaluated:
    rei = Path(sys.executable).parent / "rei"
    assert rei.is_file(), f"{rei} is missing: pip install -e 'sim-adapter[dev]' (./rei does it)"
    try:
        java, jar = toolchain.find_java(), toolchain.find_jar("monitor", REPO)
    except toolchain.ToolchainError as error:
        pytest.fail(str(error), pytrace=False)
    run = tmp / "run"
    _run([str(rei), "sim", str(EXAMPLE), "-o", str(run), "--no-router", *sim_args])
    stdout = _run([str(java.executable), "-jar", str(jar), "--replay", str(run), "--case", str(run / "case")])
    signals = parse_monitor_lines(stdout)
    case = run / "case"
    evaluator = Evaluator(tmp / "evaluation", mission_info=mission_info(read_mission(case / "mission.xml")),
                          monitor_config=json.loads((case / "monitor.json").read_text()),
                          world=json.loads((case / "world.json").read_text()))
    sim = json.loads((run / "sim.json").read_text())
    summary = replay(signals, evaluator, missions=read_recording(run / "streams" / "mission.msgpack"),
                     sim_duration=sim["sim_time"], wall_time=sim["wall_time"], run_id=sim["run_id"])
    return Evaluated(signals, summary, tmp / "evaluation")


@pytest.fixture(scope="module")
def nominal_run(tmp_path_factory: pytest.TempPathFactory) -> Evaluated:
    return _simulate_and_evaluate(tmp_path_factory.mktemp("nominal"))


@pytest.fixture(scope="module")
def ramming_run(tmp_path_factory: pytest.TempPathFactory) -> Evaluated:
    tmp = tmp_path_factory.mktemp("ram")
    script = tmp / "ram.txt"
    script.write_text(RAM_TABLE)
    return _simulate_and_evaluate(tmp, "--controller", f"script:{script}")


def test_simple_navigation_meets_every_applicable_requirement(nominal_run: Evaluated) -> None:
    statuses = {v.requirement: v.status for v in nominal_run.summary.verdicts}
    assert statuses == {
        "GEOM_CLOSE_LASER_CORRECT": Status.PASS, "GEOM_COLLISION_LASER_CORRECT": Status.PASS,
        "MISSION_SIMPLE": Status.PASS, "MISSION_SEQUENCE": Status.PASS,
        "MISSION_SEQUENCE_CYCLE": Status.NOT_APPLICABLE,  # F_0_0 -> F_4_0 -> F_5_3 is no back-and-forth
        "MISSION_WITH_HUMAN_TRAJECTORY": Status.PASS,
        "NO_ROBOT_AT_FAULT_COLLISION": Status.PASS,  # no collision with the walker: nobody at fault
    }, [v.to_dict() for v in nominal_run.summary.verdicts]
    summary = nominal_run.summary
    assert (summary.status, summary.tasks_succeeded, summary.tasks_failed, summary.goals) == (
        "COMPLETED", 2, 0, 2)


def test_total_utility_is_the_sum_of_the_table_over_the_signals_seen(nominal_run: Evaluated) -> None:
    names = [s["signal"] for s in nominal_run.signals]
    assert names[0] == "SIG_MISSION_BEGIN" and names[-1] == "SIG_MISSION_END"
    assert nominal_run.summary.total_utility == sum(DEFAULT_UTILITIES[name] for name in names)
    rows = (nominal_run.out / "events.csv").read_text().splitlines()
    assert len(rows) == 1 + len(names)
    assert rows[-1].split(",")[3] == str(int(nominal_run.summary.total_utility))
    written = json.loads((nominal_run.out / "summary.json").read_text())
    assert written["total_utility"] == nominal_run.summary.total_utility


def test_ramming_the_table_fails_mission_simple_with_the_collision_as_evidence(
        ramming_run: Evaluated) -> None:
    collisions = [s for s in ramming_run.signals if s["signal"] == "SIG_GEOM_CLOSE_TRANSIT_COLLISION"]
    assert collisions and collisions[0]["object"] == "table1"
    verdict = ramming_run.summary.verdict("MISSION_SIMPLE")
    assert verdict.status == Status.FAIL
    first = verdict.evidence[0]
    assert (first.t, first.object, first.signal, first.task) == (
        collisions[0]["t"], "table1", "SIG_GEOM_CLOSE_TRANSIT_COLLISION", 0)
    first_t = collisions[0]["t"]
    assert verdict.message == f"{len(collisions)} collision(s), first with table1 at t={first_t:.3f}"
    # the table is no human, and the laser did see the approach and the collision
    assert ramming_run.summary.verdict("MISSION_WITH_HUMAN_TRAJECTORY").status == Status.PASS
    assert ramming_run.summary.verdict("GEOM_COLLISION_LASER_CORRECT").status == Status.PASS
    # the script claims success far from the goals: false successes
    assert ramming_run.summary.verdict("MISSION_SEQUENCE").status == Status.FAIL
