# SPDX-License-Identifier: EPL-2.0
"""`rei run` end to end: router, monitor jar, simulation and evaluator as real processes, judged verdicts."""

from __future__ import annotations

import csv
import json
import os
import signal
import subprocess
import sys
import time
import xml.etree.ElementTree as ET
from pathlib import Path

from rei.evaluation.verdicts import REQUIREMENTS
from rei.wamp.recording import read_recording

RAM_THE_TABLE = "2.0 0.0 0.2318\n12.0 0.26 0.0\n"  # from F_0_0, turn 26.6 deg towards table1, drive on


def verdicts(out: Path) -> dict[str, dict]:
    return {v["requirement"]: v for v in json.loads((out / "summary.json").read_text())["verdicts"]}


def test_the_example_passes_and_its_signals_replay_identically(
    run_cli, processes_mentioning, repo_root: Path, tmp_path: Path
) -> None:
    out = tmp_path / "out"
    # a relative output folder, as in the README's command: the router and children run elsewhere
    result = run_cli("run", repo_root / "examples" / "simple_navigation.rei", "-o", "out", timeout=300, cwd=tmp_path)
    assert result.returncode == 0, result.stdout + result.stderr
    summary = json.loads((out / "summary.json").read_text())
    assert summary["status"] == "COMPLETED"
    assert {v["status"] for v in summary["verdicts"]} <= {"pass", "not-applicable"}
    suite = ET.parse(out / "verdicts.xml").getroot()
    cases = list(suite.iter("testcase"))
    assert len(cases) == len(REQUIREMENTS) and all(case.get("name") for case in cases)  # one per requirement
    rows = list(csv.DictReader((out / "events.csv").open()))
    assert [r["signal"] for r in rows][:2] == ["SIG_MISSION_BEGIN", "SIG_MISSION_TASK_START"]
    assert rows[-1]["signal"] == "SIG_MISSION_END"
    assert float(rows[-1]["total"]) == sum(float(r["utility"]) for r in rows)
    assert (out / "report.html").stat().st_size > 1000 and (out / "run.mcap").stat().st_size > 1000
    # The signals the monitor published live are exactly those a replay of the recorded streams produces.
    live = [(m["signal"], round(m["t"], 6), m["subject"], m["object"]) for m in
            read_recording(out / "streams" / "signal.msgpack")]
    replay = run_cli("monitor", "--replay", out)
    assert replay.returncode == 0, replay.stderr
    replayed = [(f[2], round(float(f[1]), 6), f[3], f[4]) for f in (line.split() for line in replay.stdout.splitlines())
                if len(f) == 6 and f[2].startswith("SIG_")]
    assert live == replayed and len(live) >= 6
    assert processes_mentioning(out) == []


def test_driving_into_the_table_fails_mission_simple_with_the_collision_as_evidence(
    run_cli, repo_root: Path, tmp_path: Path
) -> None:
    script = tmp_path / "ram.txt"
    script.write_text(RAM_THE_TABLE)
    out = tmp_path / "out"
    result = run_cli("run", repo_root / "examples" / "simple_navigation.rei", "-o", out, "--no-humans",
                     "--controller", f"script:{script}", timeout=300)
    assert result.returncode == 1, result.stdout + result.stderr
    simple = verdicts(out)["MISSION_SIMPLE"]
    assert simple["status"] == "fail"
    evidence = simple["evidence"][0]
    assert evidence["object"] == "table1"
    assert 6.0 < evidence["t"] < 9.0  # the turn takes 2 s, then ~1.3 m at 0.26 m/s to the table's edge
    assert "FAIL" in result.stdout and "MISSION_SIMPLE" in result.stdout


def test_a_noisy_laser_fails_the_laser_verdicts_but_not_the_geometric_ones(
    run_cli, repo_root: Path, tmp_path: Path
) -> None:
    out = tmp_path / "out"
    result = run_cli("run", repo_root / "examples" / "simple_navigation.rei", "-o", out, "--no-humans",
                     "--fault", "laser:10%", timeout=400)
    assert result.returncode == 1, result.stdout + result.stderr
    judged = verdicts(out)
    assert judged["GEOM_CLOSE_LASER_CORRECT"]["status"] == "fail"
    assert "false alarm" in judged["GEOM_CLOSE_LASER_CORRECT"]["message"]
    assert judged["MISSION_SIMPLE"]["status"] == "pass"


def test_killing_the_simulation_is_an_error_that_keeps_every_signal_and_leaves_no_process(
    processes_mentioning, repo_root: Path, tmp_path: Path, rei_script: Path, cli_jar: Path
) -> None:
    out = tmp_path / "out"
    process = subprocess.Popen(
        [str(rei_script), "run", str(repo_root / "examples" / "simple_navigation.rei"), "-o", str(out),
         "--realtime"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True,
        env={**os.environ, "REI_HOME": str(repo_root)})
    try:
        events = out / "events.csv"
        deadline = time.monotonic() + 120
        while time.monotonic() < deadline and not (events.is_file() and events.read_text().count("\n") >= 3):
            time.sleep(0.2)
        assert events.is_file(), "the run never got going"
        simulation = [p for p in Path("/proc").glob("[0-9]*") if _is_simulation_of(p, out)]
        assert len(simulation) == 1
        os.kill(int(simulation[0].name), signal.SIGKILL)
        stdout, stderr = process.communicate(timeout=120)
    finally:
        if process.poll() is None:
            os.killpg(process.pid, signal.SIGKILL)
    assert process.returncode == 2, stdout + stderr
    summary = json.loads((out / "summary.json").read_text())
    assert summary["status"] == "ERROR" and "SIGKILL" in summary["error"]
    received = [m["signal"] for m in read_recording(out / "streams" / "signal.msgpack")]
    logged = [row["signal"] for row in csv.DictReader(events.open())]
    assert logged == received and len(logged) >= 2
    assert {v["status"] for v in summary["verdicts"]} <= {"error", "not-applicable", "fail"}
    assert processes_mentioning(out) == []


def _is_simulation_of(proc: Path, out: Path) -> bool:
    """The run's simulation writes its errors to OUT/simulation.log, whether started as `python -m rei.cli sim` or
    forked from the service's warm Python (whose command line it keeps)."""
    try:
        return os.readlink(proc / "fd" / "2") == str(out / "simulation.log")
    except OSError:
        return False


