# SPDX-License-Identifier: EPL-2.0
"""`rei run` forked from the background service's warm Python (rei.service.warm) with its simulation: the command
itself only passes its streams and signals on, gives the run's exit code and results, Ctrl-C reaches the run, and a
warm Python made from other code refuses (the command then runs itself). Real service, router, monitor JVM and
simulation."""

from __future__ import annotations

import json
import os
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

import pytest

from rei.service import DIR_ENV
from rei.service import client as service_client
from rei.service.warm import SOCKET_NAME

RUN_TIMEOUT_S = 240.0


@pytest.fixture
def warm_service(tmp_path_factory: pytest.TempPathFactory, run_cli: Any, repo_root: Path,
                 monkeypatch: pytest.MonkeyPatch) -> Any:
    """A service of this test's own whose warm Python is up (its first run started it)."""
    import shutil
    import tempfile

    folder = Path(tempfile.mkdtemp(prefix="rei-warm-"))
    monkeypatch.setenv(DIR_ENV, str(folder))
    first = tmp_path_factory.mktemp("first") / "out"
    result = run_cli("run", repo_root / "examples" / "simple_navigation.rei", "-o", first, timeout=RUN_TIMEOUT_S)
    assert result.returncode == 0, result.stdout + result.stderr
    deadline = time.monotonic() + 120
    while not (folder / SOCKET_NAME).exists():
        assert time.monotonic() < deadline, (folder / "warm.log").read_text() if (folder / "warm.log").exists() else ""
        time.sleep(0.2)
    yield folder, first
    service_client.stop(folder)
    shutil.rmtree(folder, ignore_errors=True)


def _rei(repo_root: Path, *args: Any) -> subprocess.Popen[str]:
    """`rei ARGS` as run_cli runs it, but left running."""
    return subprocess.Popen([str(Path(sys.executable).parent / "rei"), *map(str, args)], cwd=repo_root,
                            env={**os.environ, "REI_HOME": str(repo_root)}, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)


def _children(pid: int) -> list[int]:
    found: list[int] = []
    for task in Path(f"/proc/{pid}/task").iterdir():
        found += [int(child) for child in (task / "children").read_text().split()]
    return found


def _warm_pid(folder: Path) -> int:
    for entry in Path("/proc").glob("[0-9]*"):
        try:
            command = (entry / "cmdline").read_bytes().split(b"\0")
        except OSError:
            continue
        if str(folder / SOCKET_NAME).encode() in command:
            return int(entry.name)
    raise AssertionError(f"no warm Python serves {folder / SOCKET_NAME}")


def _await_stepping(out: Path, process: subprocess.Popen[str]) -> None:
    deadline = time.monotonic() + RUN_TIMEOUT_S
    while not (out / "streams" / "state.msgpack").exists():
        assert process.poll() is None, process.communicate()
        assert time.monotonic() < deadline
        time.sleep(0.05)


def _verdicts(out: Path) -> list[tuple[str, str]]:
    return [(v["requirement"], v["status"]) for v in json.loads((out / "summary.json").read_text())["verdicts"]]


def test_a_warm_run_and_its_simulation_are_forked_and_give_the_runs_results(warm_service: Any, repo_root: Path,
                                                                            tmp_path: Path) -> None:
    folder, first = warm_service
    warm = _warm_pid(folder)
    out = tmp_path / "out"
    process = _rei(repo_root, "run", repo_root / "examples" / "simple_navigation.rei", "-o", out)
    _await_stepping(out, process)
    # the command started nothing itself: the run and its simulation are the warm Python's, each in its own group
    assert _children(process.pid) == []
    forked = _children(warm)
    assert len(forked) == 2, forked
    assert all(os.getpgid(pid) == pid for pid in forked)
    # each shows its own command line, as it would have run by itself: ps and a check for leftovers find them
    titles = sorted(Path(f"/proc/{pid}/cmdline").read_bytes().decode() for pid in forked)
    assert [title.split()[1] for title in titles] == ["run", "sim"], titles
    assert all(str(out) in title and str(folder) not in title for title in titles), titles
    stdout, stderr = process.communicate(timeout=RUN_TIMEOUT_S)
    assert process.returncode == 0, stdout + stderr
    assert "total utility +69" in stdout and "report: " in stdout  # its output reached the command's stdout
    assert _verdicts(out) == _verdicts(first)
    assert (out / "streams" / "state.msgpack").read_bytes() == (first / "streams" / "state.msgpack").read_bytes()
    # a user error's message and exit code are those of the command run by itself
    answers = []
    for options in ((), ("--no-service",)):
        missing = _rei(repo_root, "run", tmp_path / "missing.rei", "-o", tmp_path / "m", *options)
        answers.append((missing.communicate(timeout=RUN_TIMEOUT_S), missing.returncode))
    assert answers[0] == answers[1] and answers[0][1] == 2 and "missing.rei" in answers[0][0][1], answers


def test_ctrl_c_reaches_a_warm_run_which_ends_as_interrupted_and_leaves_nothing(
        warm_service: Any, repo_root: Path, tmp_path: Path, processes_mentioning: Any) -> None:
    folder, _ = warm_service
    warm = _warm_pid(folder)
    out = tmp_path / "out"
    process = _rei(repo_root, "run", repo_root / "examples" / "simple_navigation.rei", "-o", out)
    _await_stepping(out, process)
    process.send_signal(signal.SIGINT)
    stdout, stderr = process.communicate(timeout=RUN_TIMEOUT_S)
    assert process.returncode == 2, stdout + stderr
    assert "ended in ERROR: interrupted" in stdout, stdout + stderr
    assert json.loads((out / "summary.json").read_text())["status"] == "ERROR"
    deadline = time.monotonic() + 30
    while _children(warm):
        assert time.monotonic() < deadline, _children(warm)
        time.sleep(0.1)
    assert processes_mentioning(out) == []


def _warm_pids(folder: Path) -> set[int]:
    found = set()
    for entry in Path("/proc").glob("[0-9]*"):
        try:
            command = (entry / "cmdline").read_bytes().split(b"\0")
            zombie = "Z" in (entry / "stat").read_text().split(")")[1][:3]
        except OSError:
            continue
        if str(folder / SOCKET_NAME).encode() in command and not zombie:
            found.add(int(entry.name))
    return found


def test_a_warm_python_of_other_code_refuses_and_is_replaced_at_once_while_its_run_goes_on(
        warm_service: Any, repo_root: Path, tmp_path: Path) -> None:
    """The user edited or updated REI: the warm Python's modules are not theirs (the command runs itself). It
    stays for the run it forked, which ends as usual, and the service starts a new one meanwhile."""
    folder, first = warm_service
    warm = _warm_pid(folder)
    out = tmp_path / "out"
    process = _rei(repo_root, "run", repo_root / "examples" / "simple_navigation.rei", "-o", out)
    _await_stepping(out, process)
    with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as connection:
        connection.settimeout(30)
        connection.connect(str(folder / SOCKET_NAME))
        request = {"argv": ["rei", "run", "x.rei"], "cwd": "/", "env": {}, "fingerprint": "not-this-code"}
        socket.send_fds(connection, [json.dumps(request).encode() + b"\n"], [0, 1, 2])
        assert json.loads(connection.makefile("rb").readline()) == {"error": "stale"}
    deadline = time.monotonic() + 30
    while len(pids := _warm_pids(folder)) < 2:  # the new one starts while the run goes on in the old one
        assert process.poll() is None and time.monotonic() < deadline, (pids, process.poll())
        time.sleep(0.1)
    assert warm in pids
    stdout, stderr = process.communicate(timeout=RUN_TIMEOUT_S)
    assert process.returncode == 0, stdout + stderr
    assert _verdicts(out) == _verdicts(first)
    deadline = time.monotonic() + 120
    while warm in _warm_pids(folder) or not (folder / SOCKET_NAME).exists():  # the old one ends, the new serves
        assert time.monotonic() < deadline
        time.sleep(0.2)
