# SPDX-License-Identifier: EPL-2.0
"""The people server as a child process: started with ``.venv-people``'s Python, spoken to over a pipe.

JuPedSim runs in a program of its own (``pedestrians/jupedsim_server.py``, docs/people.md#licence-where-jupedsim-runs), never in
REI's process. Each request is one length-prefixed msgpack map on its standard input, each reply one on its
standard output; a reply that does not come within its time limit, or a server that dies, is a
:class:`PeopleError` with the end of the server's error output, never a hang.
"""

from __future__ import annotations

import contextlib
import os
import select
import struct
import subprocess
import tempfile
import time
from pathlib import Path
from typing import Any

import msgpack

from rei.lifetime import die_with_parent
from rei.toolchain import ToolchainError, find_repo_root

#: Environment variable naming the people server's Python; wins over the repository's .venv-people.
PYTHON_ENV = "REI_PEOPLE_PYTHON"
PROTOCOL = 2
INIT_TIMEOUT = 60.0
STEP_TIMEOUT = 10.0
_STDERR_TAIL = 4000


class PeopleError(RuntimeError):
    """The people could not be started or moved; the message says which person and why, or what the server did."""


#: Where an installed wheel keeps the people server's script (scripts/build-wheel.sh copies
#: ``pedestrians/jupedsim_server.py`` in): a Ray worker node runs reactive people without a checkout. Absent in a
#: checkout, whose ``pedestrians/`` holds it.
PACKAGED_SERVER = Path(__file__).resolve().parents[2] / "pedestrians" / "jupedsim_server.py"
#: What the people server's Python must import (scripts/setup-people.sh installs them into .venv-people).
NEEDS = ("jupedsim", "shapely", "msgpack")
JUPEDSIM_HINT = ("install JuPedSim into a Python of its own (python -m venv V && V/bin/pip install numpy shapely "
                 "deprecated msgpack && V/bin/pip install --no-deps jupedsim==1.4.2, as scripts/setup-people.sh "
                 f"does) and set {PYTHON_ENV} to V/bin/python")


def server_command() -> list[str]:
    """The people server's command line: ``$REI_PEOPLE_PYTHON`` or ``<repo>/.venv-people/bin/python``, and the
    server script an installed wheel carries (``PACKAGED_SERVER``, unless ``REI_HOME`` names a checkout) or the
    checkout's."""
    root = None
    if os.environ.get("REI_HOME") or not PACKAGED_SERVER.is_file():
        try:
            root = find_repo_root()
        except ToolchainError as error:
            raise PeopleError(f"cannot find the people server: {error}") from None
    script = PACKAGED_SERVER if root is None else root / "pedestrians" / "jupedsim_server.py"
    if os.environ.get(PYTHON_ENV):
        python = Path(os.environ[PYTHON_ENV])
    elif root is not None:
        python = root / ".venv-people" / "bin" / "python"
    else:  # a wheel's REI: no checkout to hold .venv-people
        raise PeopleError(f"reactive people need JuPedSim, and ${PYTHON_ENV} names no Python that has it; "
                          f"{JUPEDSIM_HINT}")
    if not (python.is_file() and os.access(python, os.X_OK)):
        raise PeopleError(f"reactive people need JuPedSim, installed by scripts/setup-people.sh into .venv-people "
                          f"(no {python}); run it, or `./rei ...`, which runs it")
    return [str(python), str(script)]


def people_problem(timeout: float = 60.0) -> str | None:
    """What this machine lacks to move people who see the robot (None: nothing): the people server, its Python,
    or JuPedSim and the rest of what the server imports there. Asked of a Ray node (rei.campaign.nodes)."""
    try:
        command = server_command()
    except PeopleError as error:
        return str(error)
    python, script = command
    if not Path(script).is_file():
        return f"the people server {script} is missing; reinstall REI"
    try:
        done = subprocess.run([python, "-c", f"import {', '.join(NEEDS)}"], capture_output=True, text=True,
                              timeout=timeout, check=False)
    except (OSError, subprocess.TimeoutExpired) as error:
        return f"reactive people need JuPedSim: {python} cannot be run ({error}); {JUPEDSIM_HINT}"
    if done.returncode != 0:
        cause = (done.stderr.strip().splitlines() or ["no output"])[-1]
        return f"reactive people need JuPedSim: {python} cannot import it ({cause}); {JUPEDSIM_HINT}"
    return None


class PeopleServer:
    """One server process; :meth:`request` sends a map and returns the reply's map."""

    def __init__(self, command: list[str] | None = None) -> None:
        # its error output in a file, not a pipe: a chatty server must not block on a full pipe
        self._stderr = tempfile.TemporaryFile()  # noqa: SIM115 - closed in close()
        self._process = subprocess.Popen(die_with_parent(command or server_command()), stdin=subprocess.PIPE,
                                         stdout=subprocess.PIPE, stderr=self._stderr, start_new_session=True)
        self._buffer = b""

    def request(self, message: dict[str, Any], timeout: float = STEP_TIMEOUT) -> dict[str, Any]:
        self.send(message)
        return self.receive(message.get("op"), timeout)

    def send(self, message: dict[str, Any]) -> None:
        """Send a request without waiting for its reply (:meth:`receive` reads it)."""
        data = msgpack.packb(message, use_bin_type=True)
        stdin = self._process.stdin
        assert stdin is not None
        try:
            stdin.write(struct.pack(">I", len(data)) + data)
            stdin.flush()
        except (BrokenPipeError, OSError):
            raise self._dead(f"before {message.get('op')!r}") from None

    def receive(self, op: Any, timeout: float = STEP_TIMEOUT) -> dict[str, Any]:
        """The reply to the oldest request sent and not yet received; raises its error."""
        reply = msgpack.unpackb(self._read(timeout, op), raw=False)
        if "error" in reply:
            raise PeopleError(str(reply["error"]))
        return reply

    def discard(self, op: Any) -> None:
        """Read and drop the reply of a request sent (a pending step when the run ends)."""
        with contextlib.suppress(PeopleError):
            self.receive(op, timeout=5.0)

    def _read(self, timeout: float, op: Any) -> bytes:
        deadline = time.monotonic() + timeout
        head = self._exactly(4, deadline, op)
        (size,) = struct.unpack(">I", head)
        return self._exactly(size, deadline, op)

    def _exactly(self, size: int, deadline: float, op: Any) -> bytes:
        stdout = self._process.stdout
        assert stdout is not None
        fd = stdout.fileno()
        while len(self._buffer) < size:
            left = deadline - time.monotonic()
            if left <= 0 or not select.select([fd], [], [], left)[0]:
                tail = self._stderr_tail()
                self.close(kill=True)
                raise PeopleError(f"the people server did not answer {op!r} within its time limit{tail}")
            chunk = os.read(fd, max(65536, size - len(self._buffer)))
            if not chunk:
                raise self._dead(f"during {op!r}")
            self._buffer += chunk
        data, self._buffer = self._buffer[:size], self._buffer[size:]
        return data

    def _dead(self, when: str) -> PeopleError:
        try:
            code: int | str = self._process.wait(timeout=5)
        except subprocess.TimeoutExpired:
            code = "unknown (still running)"
        return PeopleError(f"the people server ended {when} with exit code {code}{self._stderr_tail()}")

    def _stderr_tail(self) -> str:
        if self._stderr.closed:
            return ""
        self._stderr.seek(0)
        text = self._stderr.read().decode("utf-8", "replace").strip()[-_STDERR_TAIL:]
        return f": {text}" if text else ""

    def close(self, *, kill: bool = False) -> None:
        process = self._process
        if process.poll() is None and not kill:
            with contextlib.suppress(PeopleError, OSError, ValueError):
                self.request({"op": "close"}, timeout=2.0)
        if process.poll() is None:
            process.kill()
        with contextlib.suppress(subprocess.TimeoutExpired):
            process.wait(timeout=5)
        for stream in (process.stdin, process.stdout, self._stderr):
            if stream is not None:
                with contextlib.suppress(OSError):
                    stream.close()
