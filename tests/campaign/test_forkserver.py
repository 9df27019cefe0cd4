# SPDX-License-Identifier: EPL-2.0
"""The campaign's fork server (rei.campaign.forkserver) with the real worker, simulation and monitor jar: a forked
run records the same streams as a run in a new process; a hung worker is stopped by its process group and the
server forks the next; a server that dies or is stopped takes its workers with it."""

from __future__ import annotations

import dataclasses
import json
import os
import signal
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from rei.campaign.forkserver import ForkServer
from rei.campaign.plan import RunTask
from rei.campaign.supervise import supervise, worker_command

REPO_ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = REPO_ROOT / "examples" / "simple_navigation.rei"


@pytest.fixture(scope="module")
def case_dir(tmp_path_factory: pytest.TempPathFactory, run_cli: Any) -> Path:
    case = tmp_path_factory.mktemp("case") / "simple_navigation"
    result = run_cli("generate", EXAMPLE, "-o", case)
    assert result.returncode == 0, result.stdout + result.stderr
    return case


@pytest.fixture
def forks(tmp_path: Path) -> Iterator[ForkServer]:
    with ForkServer(tmp_path / "forkserver.log") as server:
        yield server


def task(case_dir: Path, run_dir: Path, **changes: Any) -> RunTask:
    script = run_dir.parent / "short.txt"
    script.write_text("1.0 0.1 0.0\n", encoding="utf-8")  # a controller that gives up at once: a short run
    base = RunTask(key="example__simple_navigation__short__r0", group="example", case="simple_navigation",
                   variant="short", repetition=0, seed=0, humans=True, fault=None, controller=f"script:{script}",
                   mode="replay", timeout=120.0, report=False, case_dir=str(case_dir), run_dir=str(run_dir))
    return dataclasses.replace(base, **changes)


def gone(pid: int) -> bool:
    try:
        os.killpg(pid, 0)
    except ProcessLookupError:
        return True
    return False


def await_gone(pid: int, message: str) -> None:
    """Until no process is left in the group ``pid`` leads (what it started goes with it, within seconds)."""
    deadline = time.monotonic() + 10
    while not gone(pid):
        assert time.monotonic() < deadline, message
        time.sleep(0.05)


def test_a_forked_run_records_the_same_streams_as_one_in_a_new_process(tmp_path: Path, case_dir: Path,
                                                                        forks: ForkServer) -> None:
    forked = supervise(task(case_dir, tmp_path / "forked"), forks=forks)
    spawned = supervise(task(case_dir, tmp_path / "spawned"),
                        command=worker_command(tmp_path / "spawned"))
    assert (forked.exit_code, spawned.exit_code) == (0, 0), forked.log_tail + spawned.log_tail
    streams = sorted(p.relative_to(tmp_path / "forked") for p in (tmp_path / "forked" / "streams").rglob("*")
                     if p.is_file())
    assert streams, "the forked run recorded nothing"
    for stream in streams:
        assert (tmp_path / "forked" / stream).read_bytes() == (tmp_path / "spawned" / stream).read_bytes(), stream
    assert (tmp_path / "forked" / "events.csv").read_bytes() == (tmp_path / "spawned" / "events.csv").read_bytes()
    summaries = [json.loads((tmp_path / run / "summary.json").read_text()) for run in ("forked", "spawned")]
    for summary in summaries:
        summary.pop("wall_time")  # the only field that differs (verdicts.xml holds it too)
    assert summaries[0] == summaries[1]
    assert forked.cpu > 0  # the forked worker's CPU reaches the campaign through the server


def test_a_hung_worker_is_stopped_by_its_group_and_the_server_forks_the_next(tmp_path: Path, case_dir: Path,
                                                                              forks: ForkServer) -> None:
    # the reference navigation drives for several seconds: one second is a run that hangs
    hung = supervise(task(case_dir, tmp_path / "hung", controller="nav", timeout=1.0), forks=forks)
    assert hung.timed_out and hung.error == "timeout: stopped after 1 s"
    assert hung.exit_code == 128 + signal.SIGTERM  # it unwound (rei.lifetime.sigterm_unwinds), as a new process does
    following = supervise(task(case_dir, tmp_path / "next"), forks=forks)
    assert following.exit_code == 0 and (tmp_path / "next" / "summary.json").is_file(), following.log_tail


def test_a_server_that_dies_takes_its_workers_with_it(tmp_path: Path, case_dir: Path, forks: ForkServer) -> None:
    run_dir = tmp_path / "orphan"
    run_dir.mkdir()
    (run_dir / "task.json").write_text(json.dumps(task(case_dir, run_dir, controller="nav").to_dict()), encoding="utf-8")
    worker = forks.fork(run_dir)
    os.kill(forks.pid, signal.SIGKILL)
    ended = worker.poll(10.0)
    assert ended is not None and os.waitstatus_to_exitcode(ended[0]) == -signal.SIGKILL
    assert "the fork server ended before this worker" in (run_dir / "worker.log").read_text(encoding="utf-8")
    await_gone(worker.pid, "the worker outlived the fork server")


def test_a_stopped_server_stops_its_workers(tmp_path: Path, case_dir: Path, forks: ForkServer) -> None:
    run_dir = tmp_path / "stopped"
    run_dir.mkdir()
    (run_dir / "task.json").write_text(json.dumps(task(case_dir, run_dir, controller="nav").to_dict()), encoding="utf-8")
    worker = forks.fork(run_dir)
    time.sleep(0.5)
    forks.stop()  # as when the campaign ends or is interrupted
    ended = worker.poll(10.0)
    assert ended is not None and os.waitstatus_to_exitcode(ended[0]) == 128 + signal.SIGTERM
    await_gone(worker.pid, "the worker's group outlived the stopped server")
