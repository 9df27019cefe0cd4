# SPDX-License-Identifier: EPL-2.0
"""A `rei search` stopped in the middle of an evaluation resumes where it stopped, with the real processes (room
editor engine, generator, fork server, simulation, monitor jar, evaluator): the search is sent SIGTERM (a
supervisor's stop: it writes the outputs of what finished and exits 143) or SIGKILL (nothing of it runs any
more) once one evaluation has finished and the next is running; the same command then runs the budget to its
end. No evaluation is lost or named twice, the one that was cut is asked again (its point), and the finished
ones are not simulated again (their run folders are left as they were)."""

from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import time
from pathlib import Path
from typing import Any

import pytest

REPO_ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = REPO_ROOT / "examples" / "search"
TIMEOUT = 300.0
BUDGET = 3
SPEC = f"""\
case: crossing.rei
seed: 4
budget: {BUDGET}
timeout: 120
parameters:
  - {{human: walker, start: [5, 11], speed: [0.6, 1.5]}}
objectives:
  - {{metric: clearance_humans_min}}
shrink: {{budget: 0}}
"""


def _runs(out: Path) -> tuple[dict[str, int], list[str]]:
    """The finished runs (key -> mtime of result.json, written once the search has read the run) and the
    started ones without a result."""
    finished, running = {}, []
    for task in (out / "runs").glob("*/task.json"):
        result = task.parent / "result.json"
        if result.is_file():
            finished[task.parent.name] = result.stat().st_mtime_ns
        else:
            running.append(task.parent.name)
    return finished, running


def _stop_mid_run(argv: list[str], out: Path, log: Path, signum: int) -> int:
    """Starts `rei search`, sends it ``signum`` once an evaluation has finished and another has been running for
    a second; its exit code."""
    with open(log, "wb") as output:
        process = subprocess.Popen(argv, stdout=output, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL,
                                   start_new_session=True, env={**os.environ, "REI_HOME": str(REPO_ROOT)})
    try:
        deadline = time.monotonic() + TIMEOUT
        seen: dict[str, float] = {}
        while True:
            assert process.poll() is None, f"the search ended before it was stopped: {log.read_text()[-3000:]}"
            assert time.monotonic() < deadline, f"no run finished with another running: {log.read_text()[-3000:]}"
            finished, running = _runs(out) if (out / "runs").is_dir() else ({}, [])
            now = time.monotonic()
            for key in running:
                seen.setdefault(key, now)
            if finished and any(now - seen[key] >= 1.0 for key in running):
                break
            time.sleep(0.1)
        process.send_signal(signum)
        return process.wait(timeout=120)
    finally:
        if process.poll() is None:
            process.kill()
            process.wait()


@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGKILL], ids=["sigterm", "sigkill"])
def test_a_search_stopped_mid_run_resumes_without_losing_or_repeating_an_evaluation(
        signum: int, tmp_path: Path, rei_script: Path, run_cli: Any,
        processes_mentioning: Any) -> None:
    shutil.copy(EXAMPLE / "crossing.rei", tmp_path / "crossing.rei")
    spec = tmp_path / "crossing.yaml"
    spec.write_text(SPEC, encoding="utf-8")
    out = tmp_path / "out"
    args = ["search", str(spec), "-o", str(out), "--workers", "1", "--no-shrink"]
    code = _stop_mid_run([str(rei_script), *args], out, tmp_path / "first.log", signum)
    first = (tmp_path / "first.log").read_text(encoding="utf-8")
    if signum == signal.SIGTERM:
        assert code == 128 + signal.SIGTERM, first
        assert "search interrupted: finished evaluations are kept" in first
        assert json.loads((out / "search.json").read_text(encoding="utf-8"))["counts"]["interrupted"] >= 1
    else:
        assert code == -signal.SIGKILL
        # nothing of the killed search may go on working in its folder: the fork server stops its workers when
        # the search's end of its pipe closes, the JVMs die with their parent
        deadline = time.monotonic() + 60
        while processes_mentioning(out) and time.monotonic() < deadline:
            time.sleep(0.5)
        assert not processes_mentioning(out), processes_mentioning(out)
    finished, cut = _runs(out)
    assert 1 <= len(finished) < BUDGET and cut, (finished, cut)

    resumed = run_cli(*args, timeout=TIMEOUT)
    assert resumed.returncode in (0, 1), resumed.stdout + resumed.stderr
    assert f"{len(finished)} finished already, {BUDGET - len(finished)} to run" in resumed.stdout, resumed.stdout
    document = json.loads((out / "search.json").read_text(encoding="utf-8"))
    records = document["evaluations"]
    keys = [r["key"] for r in records]
    assert len(keys) == len(set(keys)), keys
    simulated = [r for r in records if r["status"] in ("COMPLETED", "ERROR")]
    assert document["counts"]["simulated"] == len(simulated) == BUDGET
    assert all(r["status"] == "COMPLETED" for r in simulated), simulated
    now, left = _runs(out)
    assert set(now) == {r["key"] for r in simulated}, (now, simulated)  # each simulated one has its run
    for key, mtime in finished.items():
        assert now.get(key) == mtime, f"{key} was simulated again"
    # the cut evaluation (and the next one, made ready beside it but not started): recorded as interrupted, its
    # folder left unfinished, its point asked again and run
    interrupted = [r for r in records if r["status"] == "interrupted"]
    assert set(cut) == set(left) and set(cut) <= {r["key"] for r in interrupted}, (interrupted, cut, left)
    again = [r["params"] for r in simulated if r["key"] not in finished]
    for record in interrupted:
        assert record["params"] in again, (record, again)
