# SPDX-License-Identifier: EPL-2.0
"""Runs that crash, hang or are interrupted end as they should, and only they; no process is left behind."""

from __future__ import annotations

import os
import sys
import threading
import time
from dataclasses import replace
from pathlib import Path

from rei.campaign.backends import LocalBackend
from rei.campaign.plan import RunTask
from rei.campaign.results import finished_result, make_result, write_result
from rei.campaign.supervise import Outcome, supervise


def task(tmp_path: Path, key: str, timeout: float = 30.0) -> RunTask:
    return RunTask(key=key, group="g", case="c", variant="v", repetition=0, seed=0, humans=True, fault=None,
                   controller="nav", mode="replay", timeout=timeout, report=False, case_dir=str(tmp_path / "case"),
                   run_dir=str(tmp_path / "runs" / key))


def python(code: str) -> list[str]:
    return [sys.executable, "-c", code]


WRITES_SUMMARY = ("import json; json.dump({'status': 'COMPLETED', 'total_utility': 7, 'sim_duration': 3.0, "
                  "'tasks': {'goals': 2, 'started': 2, 'succeeded': 2, 'failed': 0}, 'counts': {'SIG_MISSION_END': 1}, "
                  "'verdicts': [{'requirement': 'MISSION_SIMPLE', 'status': 'pass'}]}, open('summary.json', 'w'))")


def test_a_crash_a_hang_and_a_good_run_each_get_their_result(tmp_path: Path) -> None:
    commands = {"good": python(WRITES_SUMMARY), "crash": python("import os; print('boom'); os.kill(os.getpid(), 9)"),
                "fails": python("raise SystemExit('no such controller')"),
                "hang": python("import subprocess, sys, time; subprocess.Popen([sys.executable, '-c', "
                               "'import time; time.sleep(60)']); open('child', 'w').write('x'); time.sleep(60)")}
    tasks = [task(tmp_path, key, timeout=2.0 if key == "hang" else 30.0) for key in commands]
    outcomes: dict[str, Outcome] = {}
    started = time.perf_counter()
    LocalBackend(2, command=lambda t: commands[t.key]).run(tasks, lambda t, o: outcomes.__setitem__(t.key, o),
                                                           threading.Event())
    assert time.perf_counter() - started < 15
    results = {t.key: make_result(t, outcomes[t.key]) for t in tasks}
    assert (results["good"].status, results["good"].total_utility, results["good"].mission_succeeded) == ("COMPLETED", 7, True)
    assert results["good"].verdicts == {"MISSION_SIMPLE": "pass"}
    assert results["crash"].status == "ERROR" and "killed by SIGKILL: boom" in results["crash"].error
    assert results["fails"].status == "ERROR" and "exited with 1: no such controller" in results["fails"].error
    assert results["hang"].status == "ERROR" and results["hang"].error.startswith("timeout: stopped after 2 s")
    assert (Path(tasks[3].run_dir) / "child").is_file()
    assert not _processes_running("time.sleep(60)"), "the hung run's child must be stopped with it"


def test_a_stopped_run_is_interrupted_not_failed(tmp_path: Path) -> None:
    stop = threading.Event()
    threading.Timer(0.5, stop.set).start()
    outcome = supervise(task(tmp_path, "slow"), stop, python("import time; time.sleep(30)"))
    assert outcome.interrupted and not outcome.timed_out and outcome.wall < 10


def test_only_an_identical_finished_task_counts_as_finished(tmp_path: Path) -> None:
    t = task(tmp_path, "good")
    outcome = supervise(t, None, python(WRITES_SUMMARY))
    write_result(t, make_result(t, outcome))
    assert finished_result(t) is not None
    assert finished_result(replace(t, fault="laser:1%")) is None, "a changed variant must run again"


def _processes_running(needle: str) -> bool:
    mine = []
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            cmd = Path(f"/proc/{pid}/cmdline").read_bytes().replace(b"\0", b" ").decode()
            stat = Path(f"/proc/{pid}/stat").read_text()
        except OSError:
            continue
        if needle in cmd and stat.split(") ", 1)[1].split()[0] != "Z":
            mine.append(pid)
    return bool(mine)


def test_the_workers_get_the_backends_environment(tmp_path: Path) -> None:
    # what `rei campaign --no-service` relies on: REI_SERVICE=off reaches the runs (mode: pipeline runs `rei run`)
    seen = python("import os; open('seen', 'w').write(os.environ.get('REI_SERVICE', '-') + ' ' "
                  "+ os.environ.get('REI_MONITOR_SERVER', '-'))\n" + WRITES_SUMMARY)
    tasks = [task(tmp_path, "one")]
    outcomes: dict[str, Outcome] = {}
    LocalBackend(1, command=lambda t: seen, worker_env={"REI_SERVICE": "off"},
                 monitor_server=tmp_path / "jvm.sock").run(tasks, lambda t, o: outcomes.__setitem__(t.key, o),
                                                           threading.Event())
    assert make_result(tasks[0], outcomes["one"]).status == "COMPLETED"
    assert (Path(tasks[0].run_dir) / "seen").read_text() == f"off {tmp_path / 'jvm.sock'}"
