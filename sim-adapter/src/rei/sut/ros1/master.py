# SPDX-License-Identifier: EPL-2.0
"""A private ROS master for one run: rosmaster and rosout on a free loopback port, stopped with the run.

Why not ``roscore``: roslaunch starts its children in sessions of their own, so stopping roscore's process group
leaves them running; rosmaster and rosout started directly are two children REI supervises like any other
(``rei.processes``), and they start in ~0.3 s instead of ~1 s.
"""

from __future__ import annotations

import socket
import time
import xmlrpc.client
from pathlib import Path
from types import TracebackType
from typing import Self

from rei.processes import ManagedProcess
from rei.sut.ros1.environment import SETUP_HINT, RosUnavailableError, ros_environment

ROSMASTER = Path("/usr/bin/rosmaster")
ROSOUT = Path("/usr/lib/rosout/rosout")
START_TIMEOUT = 30.0


def master_online(uri: str, *, rosout: bool = False) -> bool:
    """Whether the master at ``uri`` answers (and, with ``rosout``, /rosout has registered)."""
    try:
        code, _, state = xmlrpc.client.ServerProxy(uri).getSystemState("/rei")
    except (OSError, xmlrpc.client.Error):
        return False
    return code == 1 and (not rosout or any(topic == "/rosout_agg" for topic, _ in state[0]))


class RosMaster:
    """``with RosMaster(home) as master: master.uri``; logs in ``home/log``."""

    def __init__(self, home: Path) -> None:
        self.home = home
        self.uri = ""
        self._processes: list[ManagedProcess] = []

    def start(self) -> RosMaster:
        for program in (ROSMASTER, ROSOUT):
            if not program.is_file():
                raise RosUnavailableError(f"{program} is missing: {SETUP_HINT}")
        (self.home / "log").mkdir(parents=True, exist_ok=True)
        port = _free_port()
        self.uri = f"http://127.0.0.1:{port}"
        env = ros_environment(self.uri, self.home)
        self._processes.append(ManagedProcess("rosmaster", [str(ROSMASTER), "--core", "-p", str(port), "-w", "3"],
                                              self.home / "log" / "rosmaster.out", env=env))
        deadline = time.monotonic() + START_TIMEOUT
        while not master_online(self.uri):
            self._check(deadline)
        self._processes.append(ManagedProcess("rosout", [str(ROSOUT), "__name:=rosout"],
                                              self.home / "log" / "rosout.out", env=env))
        while not master_online(self.uri, rosout=True):
            self._check(deadline)
        return self

    def stop(self) -> None:
        for process in reversed(self._processes):
            process.stop(grace=5.0)
        self._processes.clear()

    def __enter__(self) -> Self:
        return self.start()

    def __exit__(self, exc_type: type[BaseException] | None, exc: BaseException | None,
                 tb: TracebackType | None) -> None:
        self.stop()

    def _check(self, deadline: float) -> None:
        for process in self._processes:
            if process.poll() is not None:
                self.stop()
                raise RosUnavailableError(f"the ROS {process.describe_exit()}: {process.log_tail(5)}")
        if time.monotonic() > deadline:
            self.stop()
            raise RosUnavailableError(f"the ROS master at {self.uri} did not answer within {START_TIMEOUT:g} s")
        time.sleep(0.02)


def _free_port() -> int:
    with socket.socket(socket.AF_INET, socket.SOCK_STREAM) as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])
