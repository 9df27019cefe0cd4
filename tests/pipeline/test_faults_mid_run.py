# SPDX-License-Identifier: EPL-2.0
"""Faults during `rei run` (docs/security.md, "Faults mid-run"), with the real processes.

The runs are paced to real time (``--realtime``, the example's mission lasts ~33 s) so that a fault can be
injected while the mission is under way.
"""

from __future__ import annotations

import csv
import json
import os
import signal
import subprocess
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest

from rei.run.reevaluate import read_signals
from rei.service.client import connect
from rei.wamp.recording import read_recording

RUN_TIMEOUT_S = 240.0


@contextmanager
def _realtime_run(rei_script: Path, repo_root: Path, out: Path, *options: str) -> Iterator[subprocess.Popen[str]]:
    process = subprocess.Popen(
        [str(rei_script), "run", str(repo_root / "examples" / "simple_navigation.rei"), "-o", str(out),
         "--realtime", *options], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True,
        env={**os.environ, "REI_HOME": str(repo_root)})
    try:
        yield process
    finally:
        if process.poll() is None:
            # SIGTERM first: `rei run` then stops its children, whose sessions a SIGKILL of its group would miss
            os.killpg(process.pid, signal.SIGTERM)
            try:
                process.wait(timeout=60)
            except subprocess.TimeoutExpired:
                os.killpg(process.pid, signal.SIGKILL)
                process.wait()


def _await_rows(out: Path, rows: int) -> None:
    """Until events.csv has ``rows`` signals: the mission is under way and the monitor is judging it."""
    events = out / "events.csv"
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline:
        if events.is_file() and events.read_text().count("\n") > rows:
            return
        time.sleep(0.2)
    raise AssertionError("the run never got going")


def _pids(marker: bytes, out: Path) -> list[int]:
    """Processes whose command line contains ``marker`` and names the run folder."""
    found = []
    for proc in Path("/proc").glob("[0-9]*"):
        try:
            argv = (proc / "cmdline").read_bytes()
        except OSError:
            continue
        if marker in argv and str(out).encode() in argv:
            found.append(int(proc.name))
    return found


def _signals(out: Path) -> list[dict]:
    return read_recording(out / "streams" / "signal.msgpack")


def _statuses(out: Path) -> dict[str, str]:
    return {v["requirement"]: v["status"] for v in json.loads((out / "summary.json").read_text())["verdicts"]}


@pytest.mark.parametrize("service", [False, True], ids=["own-jvm", "service-jvm"])
def test_a_monitor_killed_mid_run_is_judged_again_from_the_recording_with_identical_signals(
    run_cli, processes_mentioning, rei_script: Path, repo_root: Path, tmp_path: Path, background_service: Path,
    service: bool
) -> None:
    reference = tmp_path / "reference"
    result = run_cli("run", repo_root / "examples" / "simple_navigation.rei", "-o", reference, timeout=RUN_TIMEOUT_S)
    assert result.returncode == 0, result.stdout + result.stderr
    out = tmp_path / "killed"
    with _realtime_run(rei_script, repo_root, out, *(() if service else ("--no-service",))) as process:
        _await_rows(out, 3)
        if service:  # the background service's warm JVM, which runs this run's monitor
            warm = connect(folder=background_service).monitor
            assert warm is not None
            (monitor,) = _pids(b"--serve", warm)
        else:
            (monitor,) = _pids(b"rei-monitor", out)
        os.kill(monitor, signal.SIGKILL)
        stdout, stderr = process.communicate(timeout=RUN_TIMEOUT_S)
    assert process.returncode == 0, stdout + stderr
    died = "ended without an exit code (the warm JVM serving it is gone)" if service else "was killed by SIGKILL"
    assert f"rei: the live monitor {died}" in stdout, stdout
    if service:  # the service replaces its JVM, said in one line of its log; the next run has it
        deadline = time.monotonic() + 60
        while connect(folder=background_service).monitor in (None, warm) and time.monotonic() < deadline:
            time.sleep(0.2)
        assert "the warm monitor JVM ended; starting a new one" in (background_service / "service.log").read_text()
    summary = json.loads((out / "summary.json").read_text())
    assert summary["status"] == "COMPLETED"
    assert any("re-computed from the recorded streams" in p["text"] for p in summary["problems"])
    # identical to the signals a monitor that was never killed published live for the same seed
    assert _signals(out) == _signals(reference) and len(_signals(out)) >= 6
    assert _statuses(out) == _statuses(reference)
    live = [row["signal"] for row in csv.DictReader((out / "events-live.csv").open())]
    final = [row["signal"] for row in csv.DictReader((out / "events.csv").open())]
    assert 3 <= len(live) < len(final) and final[:len(live)] == live
    assert processes_mentioning(out) == []


def test_a_router_restarted_mid_run_is_survived_and_the_lost_data_turns_verdicts_into_errors(
    run_cli, processes_mentioning, rei_script: Path, repo_root: Path, tmp_path: Path
) -> None:
    out = tmp_path / "out"
    # --no-service: the run's own router, whose exit code the run knows (a router adopted from the background
    # service, taken when a spare one happens to be ready, is reported as "unknown to this run")
    with _realtime_run(rei_script, repo_root, out, "--no-service") as process:
        _await_rows(out, 3)
        # the node controller (crossbar retitles its processes, so its pid file names it); its worker shares its group
        router = json.loads((out / "router" / ".crossbar" / "node.pid").read_text())["pid"]
        # Frozen first, then killed: the messages sent to it meanwhile are certainly lost in its socket buffers.
        os.killpg(router, signal.SIGSTOP)
        time.sleep(1.0)
        os.killpg(router, signal.SIGKILL)
        stdout, stderr = process.communicate(timeout=RUN_TIMEOUT_S)
    assert "rei: the router exited with code -9" in stdout, stdout + stderr
    summary = json.loads((out / "summary.json").read_text())
    context = f"{stdout}\n{json.dumps(summary, indent=1)}\n{(out / 'monitor.log').read_text()}"
    assert summary["status"] == "COMPLETED", context
    assert any("restarted on the same ports" in p["text"] for p in summary["problems"]), context
    # the components reconnected: the mission was followed to its end and judged
    signals = _signals(out)
    assert signals[-1]["signal"] == "SIG_MISSION_END", context
    gaps = [s for s in signals if s["signal"] == "SIG_MONITOR_DATA_GAP"]
    assert gaps and gaps[0]["object"] == "state" and gaps[0]["distance"] >= 1, context
    statuses = _statuses(out)
    # only the verdicts that read the stream with the gap turn into errors: the mission stream lost nothing
    reads_state = ("GEOM_CLOSE_LASER_CORRECT", "GEOM_COLLISION_LASER_CORRECT", "MISSION_SIMPLE",
                   "MISSION_WITH_HUMAN_TRAJECTORY", "NO_ROBOT_AT_FAULT_COLLISION")
    assert {statuses[r] for r in reads_state} == {"error"}, context
    mission_gap = any(g["object"] == "mission" for g in gaps)
    assert statuses["MISSION_SEQUENCE"] == ("error" if mission_gap else "pass"), context
    assert process.returncode == 2, context + stderr
    # nothing lost: the event log holds every signal the monitor emitted, in order
    emitted = read_signals(out / "signals.jsonl")
    logged = list(csv.DictReader((out / "events.csv").open()))
    assert [s["seq"] for s in emitted] == list(range(len(emitted))), context
    assert [r["signal"] for r in logged] == [s["signal"] for s in emitted], context
    assert signals == emitted, context  # the copy the report reads, too
    assert processes_mentioning(out) == []

    # the simulation recorded every message: judged again from the recording, nothing is missing
    again = run_cli("evaluate", out, timeout=RUN_TIMEOUT_S)
    assert again.returncode == 0, again.stdout + again.stderr
    assert "SIG_MONITOR_DATA_GAP" not in {s["signal"] for s in _signals(out)}
    assert set(_statuses(out).values()) <= {"pass", "not-applicable"}
    assert (out / "events-live.csv").is_file()


def test_a_rei_run_killed_outright_leaves_no_process_behind(
    processes_mentioning, rei_script: Path, repo_root: Path, tmp_path: Path
) -> None:
    """SIGKILL runs no clean-up code: the children must go by themselves (rei.lifetime)."""
    out = tmp_path / "out"
    with _realtime_run(rei_script, repo_root, out) as process:
        _await_rows(out, 2)
        router = json.loads((out / "router" / ".crossbar" / "node.pid").read_text())["pid"]
        assert processes_mentioning(out) and _running(router)
        process.kill()  # the rei process only, not its group: its children are in sessions of their own anyway
        process.wait(timeout=10)
        deadline = time.monotonic() + 30
        while (processes_mentioning(out) or _running(router)) and time.monotonic() < deadline:
            time.sleep(0.2)
    assert processes_mentioning(out) == [], "the monitor or the simulation outlived rei run"
    assert not _running(router), "the router outlived rei run"


def _running(pid: int) -> bool:
    """Alive and not a zombie (an orphan's zombie waits for init to reap it)."""
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except (OSError, IndexError):
        return False
    return state != "Z"
