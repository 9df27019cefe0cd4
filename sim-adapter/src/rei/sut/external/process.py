# SPDX-License-Identifier: EPL-2.0
"""Starting an external SUT (``--sut "COMMAND ..."``) and telling an attached one where to connect.

The connection goes into environment variables and the secret stays in its 0600 file: a command line is
readable by every user of the machine (docs/security.md). The command is split like a shell line but no shell
runs it, so nothing in it is expanded twice. Its PATH starts with the folder of REI's own Python environment, so
``rei nav-sut`` and ``python3 my_nav.py`` find REI and its client kit.
"""

from __future__ import annotations

import os
import shlex
import shutil
import sys
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

from rei.processes import ManagedProcess

LOG_FILE = "sut.log"
ENV_FILE = "sut.env"
#: Seconds a SUT has to exit by itself after ``end`` before it is stopped (SIGTERM, then SIGKILL).
EXIT_GRACE = 2.0


class SutLaunchError(ValueError):
    """The SUT command cannot be started; the message says why."""


@dataclass(frozen=True, slots=True)
class Connection:
    """Where and as whom a SUT joins: the environment variables of docs/sut.md."""

    router_url: str
    realm: str
    run_id: str
    auth_file: Path | None
    rawsocket_url: str | None = None  # the same router over RawSocket: less framing for clients that have it
    case_dir: Path | None = None  # the run's generated case (world.json, a map room's map.yaml)

    def environment(self) -> dict[str, str]:
        env = {"REI_ROUTER_URL": self.router_url, "REI_REALM": self.realm, "REI_RUN_ID": self.run_id}
        if self.auth_file is not None:
            env["REI_AUTH_FILE"] = str(self.auth_file)
        if self.rawsocket_url is not None:
            env["REI_ROUTER_RAWSOCKET_URL"] = self.rawsocket_url
        if self.case_dir is not None:
            env["REI_CASE_DIR"] = str(self.case_dir)
        return env

    def write_env_file(self, path: Path) -> Path:
        """``KEY=value`` lines (shell-quoted) for a SUT the user starts (``--sut-attach``); no secret in it."""
        path.write_text("".join(f"{key}={shlex.quote(value)}\n" for key, value in self.environment().items()),
                        encoding="utf-8")
        return path


#: ``--sut "PREFIX:COMMAND"``: COMMAND speaks a middleware, reached through REI's bridge for it (docs/ros.md).
BRIDGES = {"ros1": ["rei", "ros1-bridge"], "ros2": ["rei", "ros2-bridge"]}


def split_command(command: str) -> list[str]:
    """The argv of ``--sut``; raises SutLaunchError for an empty or unbalanced command."""
    prefix, _, rest = command.partition(":")
    if prefix in BRIDGES:
        command = rest
    try:
        argv = shlex.split(command)
    except ValueError as error:
        raise SutLaunchError(f"--sut {command!r}: {error}") from None
    if not argv:
        raise SutLaunchError("--sut needs a command, e.g. --sut \"python3 my_nav.py\" or \"ros1:roslaunch ...\"")
    return argv


def bridged(command: str, argv: list[str], out_dir: Path) -> list[str]:
    """The argv REI starts for ``--sut`` (``argv``: the command split): the command, or its bridge with the command
    after ``--``."""
    prefix = command.partition(":")[0]
    if prefix not in BRIDGES:
        return argv
    return [*BRIDGES[prefix], "--ros-home", str(out_dir / "ros"), "--", *argv]


def search_path(base: Mapping[str, str]) -> str:
    """``PATH`` with this Python's environment first: what a started SUT (and a bridge's stack) gets, so
    ``python3 my_nav.py`` imports ``rei`` and ``rei nav-sut`` is found."""
    own = str(Path(sys.executable).parent)
    rest = base.get("PATH", os.defpath)
    return own if not rest else f"{own}{os.pathsep}{rest}"


def check_command(command: str, cwd: Path | None = None) -> list[str]:
    """The argv, once its program is known to exist (so a typo fails before any process starts); a relative
    program path is relative to ``cwd`` (default: the current folder)."""
    argv = split_command(command)
    program = argv[0]
    if os.sep in program:
        path = Path(program) if cwd is None else cwd / program
        if not (path.is_file() and os.access(path, os.X_OK)):
            raise SutLaunchError(f"--sut: {path} is not an executable file")
    elif shutil.which(program, path=search_path(os.environ)) is None:
        raise SutLaunchError(f"--sut: program {program!r} not found on PATH{_prefix_hint(program)}")
    return argv


def _prefix_hint(program: str) -> str:
    """For a program that looks like a misspelt bridge prefix ("ros:...", "ROS1:...", "ros1 :..."): which there
    are."""
    prefix = program.partition(":")[0]
    if ":" not in program and program.lower() not in BRIDGES:
        return ""
    known = " or ".join(f"'{name}:COMMAND'" for name in BRIDGES)
    return f" (a ROS stack is run with --sut {known}, no space before the colon; {prefix!r} is no bridge)"


def start(command: str, connection: Connection, out_dir: Path, cwd: Path | None = None) -> ManagedProcess:
    """Start the SUT (or its bridge) in its own process group, in ``cwd``, with its output in ``out_dir/sut.log``."""
    argv = bridged(command, check_command(command, cwd), out_dir)
    env = {**connection.environment(), "PATH": search_path(os.environ), "PYTHONUNBUFFERED": "1"}
    try:
        return ManagedProcess("system under test", argv, out_dir / LOG_FILE, env=env, cwd=cwd)
    except OSError as error:
        raise SutLaunchError(f"--sut: cannot start {argv[0]}: {error.strerror or error}") from None


def stop(process: ManagedProcess) -> int:
    """Give the SUT EXIT_GRACE seconds to leave after ``end``, then stop its process group; its exit code."""
    if process.wait(EXIT_GRACE) is None:
        return process.stop(grace=5.0)
    return process.stop()
