# SPDX-License-Identifier: EPL-2.0
"""The service's warm Python: ``rei run`` and its simulation forked from a process that has imported them already.

Why: a warm ``rei run`` spent ~0.8 s of a 2.4 s simulation's run starting two interpreters and importing numpy,
pybullet, the WAMP stack, the evaluator and the report (the command itself, then ``rei sim``) before the
simulation's first step: most of what the run cost beyond its simulation. A fork of a process that has done so
costs milliseconds. Each command still runs in a process of its own, so a run that crashes takes nothing else
with it.

The server (``serve``, started and kept by the service daemon) runs no threads (a fork copies only the forking
thread) and exits when its standard input ends. One request per connection on ``warm.sock`` in the service's
folder (0700), a JSON line with the requester's standard input, output and error attached (SCM_RIGHTS):

    client: {"argv": [ARGV0, ARG...], "cwd": PATH, "env": {...}, "fingerprint": F}   + 3 file descriptors
    server: {"pid": PID}        the command runs: ``rei.cli.main(ARG...)`` in a process group of its own
    server: {"status": S}       it ended: its wait status
    server: {"error": TEXT}     not run (``stale``: the server's code is not the requester's; the server exits
                                and the service starts a fresh one)

A requester that hangs up before its command ended (killed) takes the command with it: SIGTERM to its group.
``delegate`` is the ``rei run`` side (forwarding its signals), ``WarmProcess`` the run's side for ``rei sim``.
"""

from __future__ import annotations

import contextlib
import importlib
import io
import json
import os
import selectors
import shlex
import signal
import socket
import sys
import threading
import time
import traceback
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import IO, Any, NoReturn

from setproctitle import setproctitle

from rei.forks import Lines, answer, flush_all, reset_signals, run_as_interpreter, signal_group, stop_all
from rei.lifetime import stat_fields

#: Imported once, before the first fork: what ``rei run`` and ``rei sim`` import on their way to the first step.
PRELOAD = ("rei.cli", "rei.cli.run", "rei.cli.sim", "rei.run.pipeline", "rei.run.mission_run", "rei.sim",
           "rei.wamp.client", "rei.evaluation", "rei.report", "rei.sut.registry", "rei.service.client", "pybullet")
SOCKET_NAME = "warm.sock"
#: Set in a forked command: where it forks its own children (``rei run``'s simulation).
SOCKET_ENV = "REI_WARM_SOCKET"
#: Seconds a requester waits for its fork's pid (the server answers at once unless it is stuck or importing).
FORK_TIMEOUT = 10.0
#: Seconds the server waits for a request once connected (its client sends it at once).
REQUEST_TIMEOUT = 2.0
#: Seconds between SIGTERM and SIGKILL for a command whose requester went.
ORPHAN_GRACE = 10.0
_TICK = 0.2
_FORWARDED = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP, signal.SIGQUIT)


def source_fingerprint(root: Path | None = None) -> str:
    """What this Python's REI is: its package folder (``root``) and every module's size and modification time. A
    server made from other code (the user edited or updated REI) refuses, so no run uses stale modules. Every
    ``rei run`` computes it twice (its request, its simulation's): os.scandir, ~2 ms for 235 modules (pathlib's
    rglob took 7-23 ms)."""
    import hashlib

    top = str(root or Path(__file__).resolve().parents[1])
    entries, folders = [], [top]
    while folders:
        with os.scandir(folders.pop()) as found:
            for entry in found:
                if entry.is_dir(follow_symlinks=False):
                    if entry.name != "__pycache__":
                        folders.append(entry.path)
                elif entry.name.endswith(".py"):
                    stat = entry.stat()
                    entries.append(f"{entry.path[len(top) + 1:]}|{stat.st_size}|{stat.st_mtime_ns}")
    return hashlib.sha256("\n".join([top, sys.executable, *sorted(entries)]).encode()).hexdigest()[:16]


# -- the requester's side ------------------------------------------------------------------------------------------


def _request(path: Path, argv: Sequence[str], fds: Sequence[int], env: dict[str, str] | None,
             cwd: str | None) -> tuple[Lines, int] | None:
    """Sends the request; the server's answers to come and the command's pid, or None when there is no (fitting)
    server."""
    connection = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    lines = Lines(connection)
    try:
        connection.settimeout(FORK_TIMEOUT)
        connection.connect(str(path))
        request = {"argv": list(argv), "cwd": cwd or os.getcwd(), "env": dict(os.environ if env is None else env),
                   "process": _attributes(), "fingerprint": source_fingerprint()}
        socket.send_fds(connection, [json.dumps(request).encode() + b"\n"], list(fds))
        connection.settimeout(None)  # the answers' timeouts are Lines.read's
        answer = json.loads(lines.read(FORK_TIMEOUT) or b"null")
    except (OSError, ValueError):
        connection.close()
        return None
    if not isinstance(answer, dict) or not isinstance(answer.get("pid"), int):
        connection.close()
        return None
    return lines, answer["pid"]


#: What a child inherits from the process that starts it, besides its streams, folder and environment.
_LIMITS = ("RLIMIT_AS", "RLIMIT_CORE", "RLIMIT_CPU", "RLIMIT_DATA", "RLIMIT_FSIZE", "RLIMIT_MEMLOCK", "RLIMIT_NOFILE",
           "RLIMIT_NPROC", "RLIMIT_STACK")


def _attributes() -> dict[str, Any]:
    """This process's umask, ignored signals, niceness, CPUs and resource limits: what its child would inherit
    (``nohup``, ``nice``, ``taskset``, ``ulimit``), which the forked command takes on instead of the service's."""
    import resource

    return {"umask": _umask(), "ignored": [int(s) for s in _FORWARDED if signal.getsignal(s) == signal.SIG_IGN],
            "nice": os.getpriority(os.PRIO_PROCESS, 0), "cpus": sorted(os.sched_getaffinity(0)),
            "limits": {name: resource.getrlimit(getattr(resource, name)) for name in _LIMITS}}


def _adopt(attributes: dict[str, Any]) -> None:
    """In the child: the requester's attributes (``_attributes``); a limit or priority it may not take (above the
    service's own) stays the service's."""
    import resource

    os.umask(int(attributes["umask"]))
    for signum in _FORWARDED:  # also those the service was started ignoring
        default = signal.default_int_handler if signum == signal.SIGINT else signal.SIG_DFL
        signal.signal(signum, signal.SIG_IGN if signum in attributes["ignored"] else default)
    with contextlib.suppress(OSError):
        os.setpriority(os.PRIO_PROCESS, 0, int(attributes["nice"]))
    with contextlib.suppress(OSError, ValueError):
        os.sched_setaffinity(0, attributes["cpus"])
    for name, (soft, hard) in attributes["limits"].items():
        with contextlib.suppress(OSError, ValueError, AttributeError):
            resource.setrlimit(getattr(resource, name), (soft, hard))


def _umask() -> int:
    """This process's umask, read without setting it (another thread may be creating files)."""
    with contextlib.suppress(OSError, StopIteration, ValueError), open("/proc/self/status", encoding="ascii") as status:
        return int(next(line for line in status if line.startswith("Umask:")).split()[1], 8)
    mask = os.umask(0o077)
    os.umask(mask)
    return mask


def _status(lines: Lines, timeout: float | None) -> int | None:
    """The command's wait status once it ended (-1: the server went first), None if not within ``timeout``."""
    line = lines.read(timeout)
    if line is None:
        return None
    try:
        return int(json.loads(line)["status"])
    except (ValueError, KeyError, TypeError):
        return -1


def _await_gone(pid: int) -> None:
    """Until process ``pid``, not this one's child, has ended (a zombie has)."""
    while (fields := stat_fields(pid)) is not None and fields[0] != "Z":
        time.sleep(_TICK)


def delegate(argv: Sequence[str], folder: Path) -> int | None:
    """``rei ARGV`` run by the service's warm Python with this process's standard streams, its signals passed on;
    its exit code, or None when the service has no warm Python for this REI (the caller runs the command itself)."""
    for fd in (0, 1, 2):
        try:
            os.fstat(fd)
        except OSError:  # closed (``<&-``): the request's socket would take its number and the run hold it
            return None
    forked: list[int] = []
    pending: list[int] = []

    def forward(signum: int, _frame: object) -> None:
        if not forked:  # Ctrl-C while the request is on its way: passed on once the command runs
            pending.append(signum)
            return
        with contextlib.suppress(ProcessLookupError):
            os.killpg(forked[0], signum)

    def suspend(_signum: int, _frame: object) -> None:  # Ctrl-Z: the run stops with the command, goes on with it
        if forked:
            signal_group(forked[0], signal.SIGSTOP)
        signal.signal(signal.SIGTSTP, signal.SIG_DFL)
        os.kill(os.getpid(), signal.SIGTSTP)  # stopped here until the shell's SIGCONT (fg, bg)
        signal.signal(signal.SIGTSTP, suspend)
        if forked:
            signal_group(forked[0], signal.SIGCONT)

    # one the command ignores (nohup) it leaves to the run, which ignores it too (``_attributes``)
    previous = {signum: signal.signal(signum, suspend if signum == signal.SIGTSTP else forward)
                for signum in (*_FORWARDED, signal.SIGTSTP) if signal.getsignal(signum) != signal.SIG_IGN}
    try:
        sent = _request(folder / SOCKET_NAME, [sys.argv[0], *argv], (0, 1, 2), None, None)
        if sent is not None:
            lines, pid = sent
            forked.append(pid)
            for signum in pending:
                forward(signum, None)
            status = _status(lines, None)
            lines.close()
    finally:
        for signum, handler in previous.items():
            signal.signal(signum, handler)
    if sent is None:
        for signum in pending:  # the command runs here: as if they came now
            signal.raise_signal(signum)
        return None
    if status is None or status < 0:
        # the run goes on without the server (reparented): the command ends with it, its exit code unknown
        print("rei: the service's warm Python ended before the run; its exit code is lost (see the service's log)",
              file=sys.stderr, flush=True)
        _await_gone(pid)
        return 1
    code = os.waitstatus_to_exitcode(status)
    if code < 0:  # killed by a signal: so is the command, as the run by itself would be (a parent sees that, not an
        _die_by(-code)  # exit code: a shell stops a loop of commands only for a SIGINT death)
    return code if code >= 0 else 128 - code


def _die_by(signum: int) -> None:
    """This process ended by signal ``signum`` (without a core dump of its own: the run's was the one)."""
    import resource

    flush_all()
    with contextlib.suppress(OSError, ValueError):
        resource.setrlimit(resource.RLIMIT_CORE, (0, resource.getrlimit(resource.RLIMIT_CORE)[1]))
    with contextlib.suppress(OSError, ValueError):  # SIGKILL's cannot be set
        signal.signal(signum, signal.SIG_DFL)
    with contextlib.suppress(OSError, ValueError):
        signal.pthread_sigmask(signal.SIG_UNBLOCK, [signum])
        os.kill(os.getpid(), signum)


class WarmProcess:
    """What ``subprocess.Popen`` gives ``rei.processes.ManagedProcess``, for a ``rei`` command forked by the warm
    Python: ``pid`` (also its process group), ``stdin``/``stdout`` pipes (text, line-buffered), ``poll``, ``wait``
    and ``returncode`` (negative: killed by that signal)."""

    def __init__(self, lines: Lines, pid: int, stdin: IO[str] | None, stdout: IO[str] | None) -> None:
        self.pid, self.stdin, self.stdout = pid, stdin, stdout
        self._lines = lines
        self.returncode: int | None = None
        self._lock = threading.Lock()

    @classmethod
    def start(cls, argv: Sequence[str], *, stdin_pipe: bool, stdout: IO[Any] | None, stderr: IO[Any],
              env: dict[str, str], cwd: Path | None) -> WarmProcess | None:
        """``rei ARGV`` forked (None: no warm Python here, or not for this code); ``stdout`` None: a pipe."""
        path = os.environ.get(SOCKET_ENV)
        if not path:
            return None
        ours: list[tuple[str, int]] = []  # our ends of the pipes
        theirs: list[int] = []  # what the child gets and we close once it has them
        if stdin_pipe:
            read, write = os.pipe()
            theirs.append(read)
            ours.append(("w", write))
        else:
            theirs.append(os.open(os.devnull, os.O_RDONLY))
        child_out = stdout.fileno() if stdout is not None else None
        if child_out is None:
            read, write = os.pipe()
            theirs.append(write)
            ours.append(("r", read))
        sent = None
        try:
            fds = [theirs[0], child_out if child_out is not None else theirs[1], stderr.fileno()]
            sent = _request(Path(path), ["rei", *argv], fds, env, str(cwd) if cwd else None)
        finally:
            for fd in theirs:
                os.close(fd)
            if sent is None:  # also when interrupted (Ctrl-C as the run starts)
                for _, fd in ours:
                    os.close(fd)
        if sent is None:
            return None
        # as Popen(text=True) makes them: the locale's encoding, which the child's streams have too
        pipes = {mode: open(fd, mode, buffering=1) for mode, fd in ours}  # noqa: SIM115 - the caller closes them
        return cls(sent[0], sent[1], pipes.get("w"), pipes.get("r"))

    def poll(self) -> int | None:
        """As Popen's: never blocks, also not while another thread waits (then: None, or the code it got)."""
        if not self._lock.acquire(blocking=False):
            return self.returncode
        try:
            return self._ended(0.0)
        finally:
            self._lock.release()

    def wait(self, timeout: float | None = None) -> int | None:
        with self._lock:
            return self._ended(timeout)

    def _ended(self, timeout: float | None) -> int | None:
        if self.returncode is None:
            status = _status(self._lines, timeout)
            if status is None:  # not ended within ``timeout``
                return None
            if status < 0:  # the server went first: the command's status is lost, so it is ended for sure
                with contextlib.suppress(ProcessLookupError, PermissionError):
                    os.killpg(self.pid, signal.SIGKILL)
                self.returncode = -signal.SIGKILL
            else:
                self.returncode = os.waitstatus_to_exitcode(status)
            self._lines.close()
        return self.returncode


# -- the server's side ---------------------------------------------------------------------------------------------


def serve(path: Path) -> int:
    """The server's loop (module docstring); returns once its standard input ends or a stale request came."""
    fingerprint = source_fingerprint()  # before the imports: a module edited meanwhile makes this server stale
    for module in PRELOAD:
        importlib.import_module(module)
    listener = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    with contextlib.suppress(FileNotFoundError):
        os.unlink(str(path) + ".new")
    listener.bind(str(path) + ".new")
    listener.listen(16)
    os.rename(str(path) + ".new", path)  # requesters find the name once it accepts
    name = os.stat(path)
    running: dict[int, socket.socket] = {}
    orphans: dict[int, float] = {}  # pid -> when its requester went
    # a command's end wakes the loop at once (its requester, `rei run` waiting for its simulation or the user for
    # the run, waited up to a tick for it): SIGCHLD writes to this socket
    wake, waker = socket.socketpair()
    wake.setblocking(False)
    waker.setblocking(False)
    signal.set_wakeup_fd(waker.fileno(), warn_on_full_buffer=False)
    signal.signal(signal.SIGCHLD, lambda _signum, _frame: None)
    try:
        with selectors.DefaultSelector() as selector:
            selector.register(listener, selectors.EVENT_READ)
            selector.register(sys.stdin.fileno(), selectors.EVENT_READ)
            selector.register(wake, selectors.EVENT_READ)
            serving = True
            while serving:
                for key, _ in selector.select(_TICK):
                    if key.fileobj is listener:
                        try:
                            connection, _ = listener.accept()
                        except OSError:  # out of file descriptors: the commands running go on, this waits
                            traceback.print_exc()
                            time.sleep(_TICK)
                            continue
                        try:
                            serving = _start(connection, running, fingerprint,
                                             keep=(listener, selector, wake, waker)) != "stale"
                        except Exception:  # noqa: BLE001 - one request's failure is its own: the others' go on
                            traceback.print_exc()
                            connection.close()
                    elif key.fileobj is wake:
                        with contextlib.suppress(BlockingIOError):
                            wake.recv(4096)
                    elif not os.read(sys.stdin.fileno(), 4096):
                        serving = False
                _reap(running, orphans)
                _watch_requesters(running, orphans)
        # the service stops (or this code is stale): no more forks (a requester then runs its command itself; a
        # new server's name replaces this one's), but the commands running are users' runs: they go on
        listener.close()
        with contextlib.suppress(OSError):
            if os.path.samestat(os.stat(path), name):  # stale: the service starts a new server when it is gone
                os.unlink(path)
        while running:
            _reap(running, orphans)
            _watch_requesters(running, orphans)
            time.sleep(_TICK)
    finally:
        listener.close()
        stop_all(running, lambda: _reap(running, {}))  # only after an error: the loop above waits for them
    return 0


def _start(connection: socket.socket, running: dict[int, socket.socket], fingerprint: str,
           keep: tuple[Any, ...]) -> str | None:
    fds: list[int] = []
    try:
        connection.settimeout(REQUEST_TIMEOUT)
        message, fds, _, _ = socket.recv_fds(connection, 1 << 20, 3)
        while not message.endswith(b"\n"):
            chunk = connection.recv(1 << 20)
            if not chunk:
                raise ValueError("the request ended early")
            message += chunk
        request = json.loads(message)
        if not isinstance(request, dict):
            raise TypeError("not a JSON object")
        if request.get("fingerprint") != fingerprint:  # first: other code's request may have other fields
            _close_all(fds)
            answer(connection, {"error": "stale"})
            connection.close()
            return "stale"
        argv = [str(arg) for arg in request["argv"]]
        env = {str(k): str(v) for k, v in dict(request["env"]).items()}
        cwd = str(request["cwd"])
        attributes = dict(request["process"])
        if len(fds) != 3:
            raise ValueError(f"expected 3 file descriptors, got {len(fds)}")
    except (OSError, ValueError, TypeError, KeyError) as error:
        _close_all(fds)
        answer(connection, {"error": f"bad request: {error}"})
        connection.close()
        return None
    if (differ := _interpreter_settings(env) ^ _interpreter_settings(os.environ)):
        # read once, at the interpreter's start (PYTHONPATH, PYTHONHASHSEED, PYTHONWARNINGS, ...): a fork would
        # run with the service's; the requester runs the command itself
        _close_all(fds)
        answer(connection, {"error": f"other interpreter settings: {', '.join(sorted({k for k, _ in differ}))}"})
        connection.close()
        return None
    if _hung_up(connection):  # its requester stopped waiting (FORK_TIMEOUT) and runs the command itself
        _close_all(fds)
        connection.close()
        return None
    try:
        flush_all()
        pid = os.fork()
    except OSError as error:  # no memory or processes left: this request fails, the commands running go on
        _close_all(fds)
        answer(connection, {"error": f"cannot fork: {error}"})
        connection.close()
        return None
    if pid == 0:
        try:
            signal.set_wakeup_fd(-1)  # the server's, closed here: nothing may write to its number once reused
            for inherited in (*keep, *running.values(), connection):
                inherited.close()
            _become(argv, env, cwd, fds, attributes)  # never returns
        finally:
            os._exit(1)  # never back into the server's loop
    _close_all(fds)
    with contextlib.suppress(OSError):  # also here: a signal to the group right after the answer reaches it
        os.setpgid(pid, pid)
    running[pid] = connection
    answer(connection, {"pid": pid})
    return None


def _interpreter_settings(env: Mapping[str, str]) -> set[tuple[str, str]]:
    """What an interpreter reads from its environment once, as it starts: its PYTHON* settings and its locale."""
    return {(name, value) for name, value in env.items()
            if name.startswith("PYTHON") or name in ("LANG", "LC_ALL", "LC_CTYPE")}


def _hung_up(connection: socket.socket) -> bool:
    """Whether the other side has closed the connection (it sends nothing after its request)."""
    try:
        connection.setblocking(False)
        return connection.recv(1, socket.MSG_PEEK) == b""
    except (BlockingIOError, InterruptedError):
        return False
    except OSError:
        return True


def _become(argv: list[str], env: dict[str, str], cwd: str, fds: list[int], attributes: dict[str, Any]) -> NoReturn:
    """In the forked child: the requester's streams, folder and environment, then ``rei.cli.main``; exits the
    process as the interpreter would (``rei.forks.run_as_interpreter``)."""

    def command() -> int:
        os.setpgid(0, 0)  # a group of its own: the requester's signals and its hang-up reach all it started
        # its own command line, not the server's: what ps, top and a check for what a run left behind look for
        setproctitle(shlex.join(argv))
        reset_signals()
        for target, fd in enumerate(fds):
            os.dup2(fd, target)
        _close_all([fd for fd in fds if fd > 2])
        sys.stdin = sys.__stdin__ = _standard_stream(0)
        sys.stdout = sys.__stdout__ = _standard_stream(1)
        sys.stderr = sys.__stderr__ = _standard_stream(2)
        os.chdir(cwd)
        _adopt(attributes)  # the user's file modes, nohup, nice, ulimit: not the service's
        os.environ.clear()
        os.environ.update(env)
        os.environ[SOCKET_ENV] = os.environ.get(SOCKET_ENV) or _server_socket
        time.tzset()  # the time module read TZ when the server imported it
        sys.argv = argv
        from rei.cli import main

        return main(argv[1:])

    run_as_interpreter(command)


def _standard_stream(fd: int) -> io.TextIOWrapper:
    """Standard stream ``fd`` as the interpreter makes it at its start (CPython's create_stdio): the server's
    encoding and errors (the same locale and PYTHON* settings as the requester's), line-buffered on a terminal (stderr
    always), written through with PYTHONUNBUFFERED, no newline translation."""
    buffered = not _unbuffered
    raw = io.FileIO(fd, "r" if fd == 0 else "w", closefd=False)
    raw.name = ("<stdin>", "<stdout>", "<stderr>")[fd]
    binary = raw if fd and not buffered else (io.BufferedReader(raw) if fd == 0 else io.BufferedWriter(raw))
    encoding, errors = _stdio[fd]
    return io.TextIOWrapper(binary, encoding, errors, newline="\n",
                            line_buffering=buffered and (fd == 2 or raw.isatty()), write_through=not buffered)


_server_socket = ""
#: The server's standard streams' encoding and errors, as its interpreter chose them.
_stdio = [("utf-8", "strict"), ("utf-8", "strict"), ("utf-8", "backslashreplace")]
_unbuffered = False


def _reap(running: dict[int, socket.socket], orphans: dict[int, float]) -> None:
    while running:
        try:
            pid, status = os.waitpid(-1, os.WNOHANG)
        except ChildProcessError:
            running.clear()
            return
        if not pid:
            return
        orphans.pop(pid, None)
        connection = running.pop(pid, None)
        if connection is not None:
            answer(connection, {"status": status})
            connection.close()


def _watch_requesters(running: dict[int, socket.socket], orphans: dict[int, float]) -> None:
    """A requester that hung up (killed) takes its command with it: SIGTERM, SIGKILL after ORPHAN_GRACE."""
    now = time.monotonic()
    for pid, connection in running.items():
        if pid in orphans:
            if now - orphans[pid] > ORPHAN_GRACE:
                signal_group(pid, signal.SIGKILL)
            continue
        if _hung_up(connection):
            orphans[pid] = now
            signal_group(pid, signal.SIGTERM)


def _close_all(fds: Sequence[int]) -> None:
    for fd in fds:
        with contextlib.suppress(OSError):
            os.close(fd)


def main(argv: list[str] | None = None) -> int:
    global _server_socket, _stdio, _unbuffered
    args = sys.argv[1:] if argv is None else argv
    if len(args) != 1:
        print("usage: python -c 'from rei.service.warm import main; main()' SOCKET", file=sys.stderr)
        return 2
    _server_socket = args[0]
    _stdio = [(stream.encoding, stream.errors or "strict") for stream in (sys.stdin, sys.stdout, sys.stderr)]
    _unbuffered = sys.stdout.write_through  # PYTHONUNBUFFERED, -u: not in sys.flags
    # ``python -c`` put the current folder first on sys.path, which in a fork is the user's: a module of theirs
    # would shadow a library the command imports later (a console script's first entry is its own folder)
    while "" in sys.path:
        sys.path.remove("")
    return serve(Path(args[0]))


__all__ = ["SOCKET_ENV", "SOCKET_NAME", "WarmProcess", "delegate", "main", "serve", "source_fingerprint"]
