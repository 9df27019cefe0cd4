# SPDX-License-Identifier: EPL-2.0
"""What REI's two fork servers share (``rei.campaign.forkserver``: campaign workers; ``rei.service.warm``: ``rei run``
and its simulation): a child forked from a server that has imported its modules, set up and ended as a freshly
started interpreter would be; the server's side of its children. Standard library only: both import this module,
it imports neither."""

from __future__ import annotations

import atexit
import contextlib
import ctypes
import json
import os
import select
import signal
import socket
import sys
import threading
import time
import traceback
from collections.abc import Callable
from typing import Any, NoReturn


def flush_all() -> None:
    """Python's and C's output buffers (pybullet prints with printf): a fork would copy what they hold into the
    child, and ``os._exit`` would drop what the child wrote."""
    for stream in (sys.stdout, sys.stderr):
        with contextlib.suppress(OSError, ValueError):  # a reader gone: the other buffers are still flushed
            stream.flush()
    ctypes.CDLL(None).fflush(None)


def reset_signals() -> None:
    """In the child, the signals as a new interpreter has them: the server's SIGTERM and SIGCHLD handling gone,
    Ctrl-C a KeyboardInterrupt, SIGPIPE and SIGXFSZ ignored (writes raise instead)."""
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    signal.signal(signal.SIGCHLD, signal.SIG_DFL)
    signal.signal(signal.SIGINT, signal.default_int_handler)
    signal.signal(signal.SIGPIPE, signal.SIG_IGN)
    signal.signal(signal.SIGXFSZ, signal.SIG_IGN)


def run_as_interpreter(body: Callable[[], int]) -> NoReturn:
    """In the child: ``body()`` (its set-up, then the command), and the process's exit as the interpreter's own
    would be whatever ended it: SystemExit's code, a traceback for an exception, killed by SIGINT for an uncaught
    Ctrl-C (a shell's 130), non-daemon threads joined, exit functions run, buffers flushed. Never returns: this
    process must not go back into the server's loop."""
    code, interrupted = 1, False
    try:
        code = body()
    except SystemExit as stop:
        if stop.code is None or isinstance(stop.code, int):
            code = stop.code or 0
        else:
            print(stop.code, file=sys.stderr)
            code = 1
    except KeyboardInterrupt:
        traceback.print_exc()
        interrupted = True
    except BaseException:  # noqa: BLE001 - its stderr gets it, its parent sees the code
        traceback.print_exc()
        code = 1
    finally:
        for thread in threading.enumerate():
            if thread is not threading.main_thread() and not thread.daemon:
                with contextlib.suppress(KeyboardInterrupt):
                    thread.join()
        with contextlib.suppress(BaseException):
            atexit._run_exitfuncs()
        with contextlib.suppress(BaseException):
            flush_all()
        if interrupted:
            signal.signal(signal.SIGINT, signal.SIG_DFL)
            os.kill(os.getpid(), signal.SIGINT)
        os._exit(code)


def signal_group(pid: int, sig: int) -> None:
    """``sig`` to process group ``pid``, if it is still there."""
    with contextlib.suppress(ProcessLookupError, PermissionError):
        os.killpg(pid, sig)


def answer(connection: socket.socket, message: dict[str, Any]) -> None:
    """A JSON line to a requester; none gone is an error (its command is stopped or goes on, as the server says)."""
    with contextlib.suppress(OSError):
        connection.setblocking(True)
        connection.sendall(json.dumps(message).encode() + b"\n")


class Lines:
    """A requester's side: the server's answers, a JSON line each, from its socket, each within a timeout. Whole
    lines only: two answers may come in one read (a command that ended at once: its pid and its status), and a
    socket file's buffer is undefined after a timeout."""

    def __init__(self, connection: socket.socket) -> None:
        self._connection, self._buffer = connection, b""
        connection.setblocking(True)  # the timeouts are the poll's
        self._poll = select.poll()  # not select(): a process with many files open has descriptors past FD_SETSIZE
        self._poll.register(connection, select.POLLIN)

    def read(self, timeout: float | None) -> bytes | None:
        """The next line; b"" once the other side closed; None when none came within ``timeout`` seconds (None:
        no limit)."""
        deadline = None if timeout is None else time.monotonic() + timeout
        while b"\n" not in self._buffer:
            wait = None if deadline is None else max(deadline - time.monotonic(), 0.0) * 1000
            if not self._poll.poll(wait):
                return None
            try:
                chunk = self._connection.recv(4096)
            except OSError:
                chunk = b""
            if not chunk:
                return b""
            self._buffer += chunk
        line, self._buffer = self._buffer.split(b"\n", 1)
        return line + b"\n"

    def close(self) -> None:
        self._connection.close()


def stop_all(running: dict[int, Any], reap: Callable[[], None], grace: float = 3.0, tick: float = 0.05) -> None:
    """The server's children's groups stopped: SIGTERM, SIGKILL after ``grace`` seconds; ``reap`` takes the ended
    ones out of ``running``."""
    for pid in running:
        signal_group(pid, signal.SIGTERM)
    deadline = time.monotonic() + grace
    while running and time.monotonic() < deadline:
        reap()
        time.sleep(tick)
    for pid in running:
        signal_group(pid, signal.SIGKILL)
    while running:
        reap()
        time.sleep(tick)


__all__ = ["Lines", "answer", "flush_all", "reset_signals", "run_as_interpreter", "signal_group", "stop_all"]
