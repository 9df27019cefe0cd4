# SPDX-License-Identifier: EPL-2.0
"""A run's side of the background service: find it (starting or replacing it when needed), take a router over."""

from __future__ import annotations

import json
import os
import socket
import subprocess
import sys
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Self

from rei.lifetime import alive
from rei.private_dirs import private_dir
from rei.service import DIR_ENV, IDLE_SECONDS, LOG_NAME, PID_NAME, SOCKET_NAME, fingerprint, service_dir

#: The longest path of a Unix socket (Linux: 108 bytes with the terminating zero).
MAX_SOCKET_PATH = 107
#: Seconds a run waits for a service it started to answer.
START_TIMEOUT = 30.0


class ServiceError(RuntimeError):
    """The service could not be reached or started; the run goes on without it."""


@dataclass(frozen=True, slots=True)
class Service:
    folder: Path
    pid: int
    fingerprint: str
    monitor: Path | None  # the warm monitor JVM's socket (rei.run.jvm), None while it is being replaced
    cli: Path | None  # the warm generator JVM's socket
    idle: float = IDLE_SECONDS  # it stops after this many seconds without a request

    def take_router(self, owner: int, wait: float) -> dict[str, Any] | None:
        """The spare router's description (``Router.adopt``), now this run's; None when none is ready in time."""
        return request(self.folder, {"op": "router", "owner": owner, "wait": wait}, timeout=wait + 10.0).get("router")


def request(folder: Path, message: dict[str, Any], timeout: float = 10.0) -> dict[str, Any]:
    connection = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    connection.settimeout(timeout)
    try:
        with connection:
            connection.connect(str(folder / SOCKET_NAME))
            connection.sendall(json.dumps(message).encode("utf-8") + b"\n")
            with connection.makefile("rb") as stream:
                line = stream.readline()
    except OSError as error:
        raise ServiceError(f"the background service in {folder} does not answer: {error}") from error
    if not line:
        raise ServiceError(f"the background service in {folder} closed the connection")
    answer = json.loads(line)
    if "error" in answer:
        raise ServiceError(f"the background service: {answer['error']}")
    return answer


def connect(log: Callable[[str], None] = print, folder: Path | None = None) -> Service:
    """The running service, started first when there is none (and replaced when it died, which ``log`` says)."""
    folder = folder or service_dir()
    if len(os.fsencode(folder / SOCKET_NAME)) > MAX_SOCKET_PATH:
        raise ServiceError(f"the service's folder {folder} is too deep for a Unix socket ({MAX_SOCKET_PATH} bytes "
                           f"at most); set {DIR_ENV} to a shorter one")
    try:  # before talking to a socket in it: a folder others can write in may hold their socket
        private_dir(folder)
    except OSError as error:
        raise ServiceError(f"the background service's folder: {error}") from error
    try:
        found = _hello(folder)
        if found.fingerprint == fingerprint():
            return found
        log(f"rei: REI was rebuilt since the background service (pid {found.pid}) started; replacing it")
        request(folder, {"op": "stop"})
        _await_released(folder, found.pid)
    except ServiceError:
        pass
    stale = _stale_pid(folder)
    if stale is not None:
        log(f"rei: the background service (pid {stale}) is gone; starting a new one")
    try:
        _spawn(folder)
    except OSError as error:
        raise ServiceError(f"cannot start the background service in {folder}: {error}") from error
    deadline = time.monotonic() + START_TIMEOUT
    while True:
        try:
            return _hello(folder)
        except ServiceError as error:
            if time.monotonic() > deadline:
                raise ServiceError(f"{error}; see {folder / LOG_NAME}") from None
            time.sleep(0.05)


def running(folder: Path | None = None) -> Service | None:
    """The service if it runs already and is of this build, else None. Never starts one: for commands whose own JVMs
    cost less than a router and two JVMs would (``rei evaluate``, ``rei campaign``)."""
    from rei.service import enabled

    if not enabled():
        return None
    try:
        found = _hello(folder or service_dir())
    except (ServiceError, ValueError, KeyError):
        return None
    return found if found.fingerprint == fingerprint() else None


def running_monitor(folder: Path | None = None) -> Path | None:
    """The warm monitor JVM's socket of a service that runs already and is current, else None."""
    found = running(folder)
    return found.monitor if found is not None else None


class Lease:
    """Keeps a service from stopping for idleness while a long job (a campaign) uses its JVMs without asking it
    anything: says hello four times per idle period until the ``with`` block ends. A hello that fails is tried
    again while the service's process lives. Should the service go away or be replaced by another (its JVMs' sockets
    are then gone), the job's commands fall back to JVMs of their own (rei.run.jvm.run_jar) and ``log`` says so."""

    def __init__(self, service: Service, log: Callable[[str], None] = print) -> None:
        self.service, self.every, self.log = service, max(0.1, service.idle / 4), log
        self._done = threading.Event()
        self._thread = threading.Thread(target=self._renew, name="rei-service-lease", daemon=True)

    def __enter__(self) -> Self:
        self._thread.start()
        return self

    def __exit__(self, *exc: object) -> None:
        self._done.set()
        self._thread.join()

    def _renew(self) -> None:
        while not self._done.wait(self.every):
            try:
                answer = request(self.service.folder, {"op": "hello"}, timeout=5.0)
            except (ServiceError, ValueError) as error:  # busy, or a reply cut short: again, unless it is gone
                if alive(self.service.pid):
                    continue
                self.log(f"rei: the background service (pid {self.service.pid}) is gone ({error}); commands start "
                         "JVMs of their own from now on")
                return
            if answer.get("pid") != self.service.pid:
                self.log(f"rei: the background service (pid {self.service.pid}) was replaced; commands start JVMs "
                         "of their own from now on")
                return


def stop(folder: Path | None = None) -> bool:
    """Stop the service and what it keeps, and wait until it has exited; False when none was running."""
    folder = folder or service_dir()
    try:
        pid = int(request(folder, {"op": "status"})["pid"])
        request(folder, {"op": "stop"})
    except ServiceError:
        return False
    _wait_until(lambda: not alive(pid))
    return True


def _hello(folder: Path) -> Service:
    answer = request(folder, {"op": "hello"}, timeout=5.0)
    return Service(folder, int(answer["pid"]), str(answer.get("fingerprint")),
                   *(Path(answer[r]) if answer.get(r) else None for r in ("monitor", "cli")),
                   idle=float(answer.get("idle", IDLE_SECONDS)))


def _await_released(folder: Path, pid: int) -> None:
    """Until a stopping service has given its folder up (it may stay a while for runs that hold its routers)."""
    _wait_until(lambda: not (folder / SOCKET_NAME).exists() or not alive(pid))


def _wait_until(done: Callable[[], bool], timeout: float = 20.0) -> None:
    deadline = time.monotonic() + timeout
    while not done() and time.monotonic() < deadline:
        time.sleep(0.05)


def _stale_pid(folder: Path) -> int | None:
    """The pid a dead service left in its pid file (a service that was killed runs no clean-up)."""
    try:
        pid = int((folder / PID_NAME).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    return None if alive(pid) else pid


def _spawn(folder: Path) -> None:
    """Start the service detached from this run (own session): it outlives the run, not the machine."""
    private_dir(folder)
    with open(folder / LOG_NAME, "ab") as log:
        subprocess.Popen([sys.executable, "-m", "rei.service"], stdin=subprocess.DEVNULL, stdout=log,
                         stderr=subprocess.STDOUT, start_new_session=True, cwd=folder,
                         env={**os.environ, "REI_SERVICE_DIR": str(folder)})


__all__ = ["Lease", "Service", "ServiceError", "connect", "request", "running", "running_monitor", "stop"]
