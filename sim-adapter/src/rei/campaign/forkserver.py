# SPDX-License-Identifier: EPL-2.0
"""Campaign workers forked from a process that has imported their modules already.

Why: a fresh ``python -m rei.campaign.worker`` spends ~0.4 s of CPU starting its interpreter and importing numpy,
pybullet, the simulation, the evaluator and the report before its run's first step (8.7 s for the 23 runs of the
thesis campaign, 7 % of its CPU). A fork of a process that has done so costs milliseconds, and keeps what a
process per run is for: a run that crashes or hangs takes nothing else with it, and memory never accumulates.

The server (``rei.campaign.forkserver.main``, started by ``ForkServer``) runs no threads of its own: a fork copies
only the forking thread, and a lock another thread held would stay locked in the child (numpy's OpenBLAS pool
re-creates itself after a fork). It is a child of the campaign and exits when its standard input ends, so it
never outlives the campaign, stopping the workers it still has. One request per connection on a Unix socket in a
private folder (0700), in JSON lines:

    client: {"run_dir": PATH, "env": {NAME: VALUE, ...}}
    server: {"pid": PID}                         the worker runs, in a session of its own, its output in
                                                 RUN_DIR/worker.log (as a spawned one)
    server: {"status": STATUS, "cpu": SECONDS}   it ended: os.wait4's status, its and its children's CPU

A client that hangs up does not stop the worker: the campaign stops workers by signalling their process group.
"""

from __future__ import annotations

import importlib
import json
import os
import selectors
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
from collections.abc import Mapping
from pathlib import Path
from typing import Any, NoReturn, Self

from rei.forks import Lines, answer, flush_all, reset_signals, run_as_interpreter, stop_all
from rei.processes import close_and_reap
from rei.run.jvm import tail

#: Imported once, before the first fork: what every worker needs (rei.campaign.worker's replay path).
PRELOAD = ("rei.campaign.worker", "rei.run.mission_run", "rei.run.reevaluate", "rei.evaluation", "rei.report",
           "rei.sut.registry", "pybullet")
WORKER_LOG = "worker.log"
#: Seconds the server may take to import PRELOAD and listen.
START_TIMEOUT = 60.0
#: Seconds a client waits for its fork's pid (the server answers at once unless it is stuck).
FORK_TIMEOUT = 30.0
#: Seconds the server waits for a request's line once connected (its client sends it at once).
REQUEST_TIMEOUT = 2.0
_TICK = 0.05
# not ``-m rei.campaign.forkserver``: the package imports this module first, which runpy warns about
_MAIN = "import sys; from rei.campaign.forkserver import main; sys.exit(main())"


class ForkServerError(RuntimeError):
    """The fork server did not start or does not answer; the message says why."""


class ForkServer:
    """The campaign's side: starts the server, forks workers through it (``fork``), stops it (``stop``)."""

    def __init__(self, log: Path) -> None:
        self.log = log
        self._folder: Path | None = None
        self._process: subprocess.Popen[bytes] | None = None
        self.cpu = 0.0  # of the server and every worker it reaped, once stopped

    @property
    def pid(self) -> int:
        if self._process is None:
            raise RuntimeError("the fork server is not started")
        return self._process.pid

    @property
    def socket(self) -> Path:
        if self._folder is None:
            raise RuntimeError("the fork server is not started")
        return self._folder / "fork.sock"

    def launch(self) -> Self:
        """Starts the server without waiting for it: it imports while the caller does something else."""
        self._folder = Path(tempfile.mkdtemp(prefix="rei-forks-"))  # 0700: whoever connects runs workers
        self.log.parent.mkdir(parents=True, exist_ok=True)
        with open(self.log, "wb") as log:
            # a session of its own: Ctrl-C reaches the campaign, which stops the workers and then the server
            self._process = subprocess.Popen([sys.executable, "-c", _MAIN, str(self.socket)],
                                             stdin=subprocess.PIPE, stdout=log, stderr=subprocess.STDOUT,
                                             start_new_session=True)
        return self

    def start(self) -> Self:
        """Launches the server unless it was, and waits until it accepts requests."""
        if self._process is None:
            self.launch()
        assert self._process is not None
        deadline = time.monotonic() + START_TIMEOUT
        while not self.socket.exists():
            if self._process.poll() is not None or time.monotonic() > deadline:
                self.stop()
                raise ForkServerError(f"the fork server did not start: {tail(self.log, 8)}")
            time.sleep(_TICK)
        return self

    def fork(self, run_dir: Path, env: Mapping[str, str] | None = None) -> ForkedWorker:
        """A worker for ``run_dir``, running once this returns."""
        connection = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        lines = Lines(connection)
        try:
            connection.settimeout(FORK_TIMEOUT)
            connection.connect(str(self.socket))
            connection.sendall(json.dumps({"run_dir": str(run_dir), "env": dict(env or {})}).encode() + b"\n")
            answer = json.loads(lines.read(FORK_TIMEOUT) or b"null")
        except (OSError, ValueError) as error:
            connection.close()
            raise ForkServerError(f"the fork server does not answer: {error}") from None
        if not isinstance(answer, dict) or not isinstance(answer.get("pid"), int):
            connection.close()
            raise ForkServerError(f"the fork server could not start the worker: {answer}")
        return ForkedWorker(answer["pid"], lines, run_dir)

    def stop(self, timeout: float = 10.0) -> None:
        """Closes the server's standard input (it stops its workers and exits), kills it after ``timeout``."""
        process, self._process = self._process, None
        if process is not None:  # start's poll() may have reaped a server that died at once
            self.cpu += close_and_reap(process, timeout)
        if self._folder is not None:
            shutil.rmtree(self._folder, ignore_errors=True)
            self._folder = None

    def __enter__(self) -> Self:
        return self.start()

    def __exit__(self, *exc: object) -> None:
        self.stop()


class ForkedWorker:
    """A worker the fork server started: its pid (and process group) and, once it ended, its status and CPU."""

    def __init__(self, pid: int, lines: Lines, run_dir: Path) -> None:
        self.pid = pid
        self._lines, self._run_dir = lines, run_dir
        self._ended: tuple[int, float] | None = None

    def poll(self, timeout: float = 0.0) -> tuple[int, float] | None:
        """``(wait status, CPU seconds)`` once the worker ended, else None after ``timeout`` seconds."""
        if self._ended is not None:
            return self._ended
        line = self._lines.read(timeout)
        if line is None:
            return None
        try:
            ended = json.loads(line)
            self._ended = (int(ended["status"]), float(ended["cpu"]))
        except (ValueError, TypeError, KeyError):  # b"": the server went before its answer
            self._ended = self._lost()
        self._lines.close()
        return self._ended

    def _lost(self) -> tuple[int, float]:
        """The server went before the worker: stop what is left of it and say so in its log."""
        try:
            os.killpg(self.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        with open(self._run_dir / WORKER_LOG, "a", encoding="utf-8") as log:
            log.write("campaign: the fork server ended before this worker; the worker was killed\n")
        return signal.SIGKILL, 0.0  # a wait status: killed by SIGKILL


def serve(path: Path) -> int:
    """The server's loop (module docstring); returns once its standard input ends."""
    for module in PRELOAD:
        importlib.import_module(module)
    listener = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    listener.bind(str(path) + ".new")
    listener.listen(16)
    os.rename(str(path) + ".new", path)  # the client waits for the name: it appears once it accepts
    running: dict[int, socket.socket] = {}
    try:
        _loop(listener, running)
    finally:  # whatever ended the loop, the workers do not outlive the server
        listener.close()
        stop_all(running, lambda: _reap(running), tick=_TICK)
    return 0


def _loop(listener: socket.socket, running: dict[int, socket.socket]) -> None:
    with selectors.DefaultSelector() as selector:
        selector.register(listener, selectors.EVENT_READ)
        selector.register(sys.stdin.fileno(), selectors.EVENT_READ)
        serving = True
        while serving:
            for key, _ in selector.select(_TICK):
                if key.fileobj is listener:
                    connection, _ = listener.accept()
                    try:
                        _start(connection, running, keep=(listener, selector))
                    except Exception as error:  # noqa: BLE001 - one failed fork (no memory, no fds) is that run's
                        answer(connection, {"error": f"cannot fork: {error}"})
                        connection.close()
                elif not os.read(sys.stdin.fileno(), 4096):
                    serving = False
            _reap(running)


def _start(connection: socket.socket, running: dict[int, socket.socket], keep: tuple[Any, ...]) -> None:
    try:
        connection.settimeout(REQUEST_TIMEOUT)
        request = json.loads(connection.makefile("rb").readline())
        run_dir, env = Path(request["run_dir"]), {str(k): str(v) for k, v in dict(request.get("env", {})).items()}
    except (OSError, ValueError, TypeError, KeyError) as error:
        answer(connection, {"error": f"bad request: {error}"})
        connection.close()
        return
    flush_all()
    pid = os.fork()
    if pid == 0:
        for inherited in (*keep, *running.values(), connection):
            inherited.close()
        _become_worker(run_dir, env)  # never returns
    running[pid] = connection
    answer(connection, {"pid": pid})


def _become_worker(run_dir: Path, env: Mapping[str, str]) -> NoReturn:
    """In the forked child: what ``subprocess.Popen(worker_command, start_new_session=True, ...)`` would set up,
    then the worker itself; exits the process as its interpreter would (``rei.forks.run_as_interpreter``)."""

    def worker() -> int:
        os.setsid()
        reset_signals()
        run_dir.mkdir(parents=True, exist_ok=True)
        log = os.open(run_dir / WORKER_LOG, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644)
        null = os.open(os.devnull, os.O_RDONLY)
        os.dup2(null, 0)
        os.dup2(log, 1)
        os.dup2(log, 2)
        os.close(log)
        os.close(null)
        os.chdir(run_dir)
        os.environ.update(env)
        from rei.campaign.worker import main

        return main([str(run_dir)])

    run_as_interpreter(worker)


def _reap(running: dict[int, socket.socket]) -> None:
    while running:
        try:
            pid, status, usage = os.wait4(-1, os.WNOHANG)
        except ChildProcessError:  # none left to wait for (cannot happen while one runs)
            running.clear()
            return
        if not pid:
            return
        connection = running.pop(pid, None)
        if connection is not None:
            answer(connection, {"status": status, "cpu": round(usage.ru_utime + usage.ru_stime, 3)})
            connection.close()


def main(argv: list[str] | None = None) -> int:
    args = sys.argv[1:] if argv is None else argv
    if len(args) != 1:
        print("usage: python -m rei.campaign.forkserver SOCKET", file=sys.stderr)
        return 2
    return serve(Path(args[0]))


if __name__ == "__main__":
    sys.exit(main())
