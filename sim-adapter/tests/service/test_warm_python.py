# SPDX-License-Identifier: EPL-2.0
"""rei.service.warm's server and client without a service: a real server (its preload cut to rei.cli) whose
``rei.cli.main`` is replaced by a probe that reports the forked command's process state, compared with what the
requester has; and the client's handling of a server that goes."""

from __future__ import annotations

import json
import os
import signal
import socket
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from pathlib import Path

import pytest

from rei.forks import Lines
from rei.service import warm

#: A pid that no process has (above Linux's most): what a test's command may signal without harm.
_NO_PROCESS = 4_194_305
#: What a Python's standard streams are (an expression).
_STREAMS = "[[s.encoding, s.errors, s.line_buffering, s.write_through] for s in (sys.stdin, sys.stdout, sys.stderr)]"
#: The server as the service starts it, with a probe for ``rei probe``: what the forked command sees, as JSON.
_SERVER = """
import json, os, resource, signal, sys, time
import rei.service.warm as warm
import rei.cli

warm.PRELOAD = ("rei.cli",)
warm.source_fingerprint = lambda root=None: "this-test"  # others may edit REI's modules meanwhile
real = rei.cli.main

def probe(argv):
    if argv[:1] == ["interrupt"]:
        raise KeyboardInterrupt
    if argv[:1] == ["exit-in-a-thread's-time"]:
        import threading
        threading.Thread(target=lambda: (time.sleep(0.5), print("the thread's line", flush=True))).start()
        sys.exit(4)
    if argv[:1] != ["probe"]:
        return real(argv)
    status = open("/proc/self/status").read()
    print(json.dumps({
        "path": sys.path, "cwd": os.getcwd(), "argv": sys.argv, "tzname": list(time.tzname),
        "umask": next(line.split()[1] for line in status.splitlines() if line.startswith("Umask:")),
        "fds": sorted(int(fd) for fd in os.listdir("/proc/self/fd")), "env": dict(os.environ),
        "streams": STREAMS, "nice": os.getpriority(os.PRIO_PROCESS, 0), "cpus": sorted(os.sched_getaffinity(0)),
        "core": resource.getrlimit(resource.RLIMIT_CORE),
        "signals": {s.name: str(signal.getsignal(s)) for s in (signal.SIGHUP, signal.SIGQUIT, signal.SIGINT)}}))
    return int(argv[1]) if argv[1:] else 0

rei.cli.main = probe
signal.signal(signal.SIGQUIT, signal.SIG_IGN)  # as a service started by a command that ignored it
sys.exit(warm.main())
""".replace("STREAMS", _STREAMS)


@pytest.fixture
def server(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Path]:
    """A warm Python serving ``tmp_path/warm.sock``, started in ``tmp_path/home`` (as the service does, in its
    folder) with this test's environment."""
    monkeypatch.setattr(warm, "source_fingerprint", lambda root=None: "this-test")
    home = tmp_path / "home"
    home.mkdir()
    path = tmp_path / warm.SOCKET_NAME
    with open(tmp_path / "warm.log", "wb") as log:
        process = subprocess.Popen([sys.executable, "-c", _SERVER, str(path)], cwd=home, stdin=subprocess.PIPE,
                                   stdout=log, stderr=subprocess.STDOUT)
    deadline = time.monotonic() + 60
    while not path.exists():
        assert process.poll() is None and time.monotonic() < deadline, (tmp_path / "warm.log").read_text()
        time.sleep(0.05)
    yield path
    assert process.stdin is not None
    process.stdin.close()
    process.wait(30)


def _probe(path: Path, cwd: Path, env: dict[str, str], *args: str) -> tuple[dict, int]:
    """``rei probe ARGS`` forked by the server with a pipe for its stdout: what it reported, its wait status."""
    output, status = _command(path, cwd, env, "probe", *args)
    return json.loads(output), status


def _command(path: Path, cwd: Path, env: dict[str, str], *args: str) -> tuple[bytes, int]:
    """``rei ARGS`` forked by the server with a pipe for its stdout: its output and wait status."""
    read, write = os.pipe()
    with open(os.devnull, "rb") as null:
        sent = warm._request(path, ["rei", *args], [null.fileno(), write, 2], env, str(cwd))
    os.close(write)
    assert sent is not None
    connection, _ = sent
    with open(read, "rb") as output:
        report = output.read()
    status = warm._status(connection, 30.0)
    connection.close()
    assert status is not None
    return report, status


def test_a_forked_command_has_the_requesters_folder_environment_and_argv(server: Path, tmp_path: Path) -> None:
    work = tmp_path / "work"
    work.mkdir()
    report, status = _probe(server, work, {**os.environ, "REI_PROBE": "1"}, "3")
    assert os.waitstatus_to_exitcode(status) == 3
    assert report["cwd"] == str(work) and report["argv"] == ["rei", "probe", "3"]
    assert report["env"]["REI_PROBE"] == "1" and report["env"][warm.SOCKET_ENV] == str(server)
    # its standard streams and nothing else of the server's (its socket, the connections, its input)
    assert report["fds"][:3] == [0, 1, 2]
    assert len(report["fds"]) <= 4, report["fds"]  # os.listdir's own


def test_a_forked_command_imports_nothing_from_the_users_folder(server: Path, tmp_path: Path) -> None:
    """A console script's sys.path starts with its own folder; the server's ``-c`` put the current folder there,
    which in the fork is the user's: a ``numpy.py`` of theirs would be imported instead of numpy."""
    report, _ = _probe(server, tmp_path, dict(os.environ))
    assert "" not in report["path"] and str(tmp_path) not in report["path"], report["path"]


def test_a_forked_command_has_the_requesters_umask_and_time_zone(server: Path, tmp_path: Path) -> None:
    """Files a run writes get the user's mode, and its local times the user's zone, not the service's."""
    previous = os.umask(0o027)
    try:
        report, _ = _probe(server, tmp_path, {**os.environ, "TZ": "America/New_York"})
    finally:
        os.umask(previous)
    assert report["umask"] == "0027"
    assert report["tzname"] == ["EST", "EDT"]


def _sent_request(fingerprint: str, *, hang_up: bool = False) -> tuple[socket.socket, socket.socket]:
    """A request as ``_request`` sends it, on a socket pair: (the requester's end, the server's end)."""
    ours, theirs = socket.socketpair()
    request = {"argv": ["rei", "run"], "cwd": "/", "env": dict(os.environ), "process": warm._attributes(),
               "fingerprint": fingerprint}
    with open(os.devnull, "rb") as null:
        socket.send_fds(ours, [json.dumps(request).encode() + b"\n"], [null.fileno()] * 3)
    if hang_up:
        ours.close()
    return ours, theirs


def _open_fds() -> set[str]:
    return set(os.listdir("/proc/self/fd"))


def test_a_failed_fork_fails_its_request_alone(monkeypatch: pytest.MonkeyPatch) -> None:
    """No memory or processes left: the request is answered with the error and the server goes on (an exception
    out of its loop would stop every command it runs), leaking none of the passed streams."""
    before = _open_fds()

    def fork() -> int:
        raise BlockingIOError(11, "Resource temporarily unavailable")

    monkeypatch.setattr(os, "fork", fork)
    ours, theirs = _sent_request(warm.source_fingerprint())
    running: dict[int, socket.socket] = {}
    assert warm._start(theirs, running, warm.source_fingerprint(), keep=()) is None
    assert running == {} and theirs.fileno() == -1
    assert "cannot fork" in json.loads(ours.makefile("rb").readline())["error"]
    ours.close()
    assert _open_fds() <= before


def test_no_fork_for_a_requester_that_stopped_waiting(monkeypatch: pytest.MonkeyPatch) -> None:
    """It runs the command itself after FORK_TIMEOUT: a fork now would be a second run into its folder."""
    before = _open_fds()

    def fork() -> int:
        raise AssertionError("forked for a requester that went")

    monkeypatch.setattr(os, "fork", fork)
    _, theirs = _sent_request(warm.source_fingerprint(), hang_up=True)
    assert warm._start(theirs, {}, warm.source_fingerprint(), keep=()) is None
    assert theirs.fileno() == -1 and _open_fds() <= before


def test_poll_does_not_wait_for_another_threads_wait() -> None:
    """As Popen's: the pipeline may poll the simulation while another thread waits for it."""
    ours, theirs = socket.socketpair()
    process = warm.WarmProcess(Lines(ours), _NO_PROCESS, None, None)
    waiter = threading.Thread(target=process.wait, args=(3.0,))
    waiter.start()
    time.sleep(0.2)
    started = time.monotonic()
    assert process.poll() is None
    assert time.monotonic() - started < 1.0
    theirs.sendall(json.dumps({"status": 3 << 8}).encode() + b"\n")
    waiter.join()
    assert process.poll() == 3 and process.wait() == 3
    theirs.close()


def test_a_command_whose_server_went_is_ended_as_reported() -> None:
    """Its status is lost with the server: it is reported killed, so it must be."""
    command = subprocess.Popen(["sleep", "60"], start_new_session=True)
    ours, theirs = socket.socketpair()
    process = warm.WarmProcess(Lines(ours), command.pid, None, None)
    theirs.close()
    assert process.wait(5.0) == -signal.SIGKILL
    assert command.wait(5) == -signal.SIGKILL


def test_a_delegated_command_whose_server_went_returns_once_the_command_has_ended(
        tmp_path: Path, capfd: pytest.CaptureFixture[str]) -> None:
    """The run goes on without the server (it writes to the command's streams): the command returns after it."""
    command = subprocess.Popen(["sleep", "1.5"], start_new_session=True)
    listener = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    listener.bind(str(tmp_path / warm.SOCKET_NAME))
    listener.listen(1)

    def serve_once() -> None:  # forks nothing: answers with the pid of the command above, then goes
        connection, _ = listener.accept()
        _, fds, _, _ = socket.recv_fds(connection, 1 << 20, 3)
        for fd in fds:
            os.close(fd)
        connection.sendall(json.dumps({"pid": command.pid}).encode() + b"\n")
        connection.close()

    server = threading.Thread(target=serve_once)
    server.start()
    started = time.monotonic()
    try:
        assert warm.delegate(["run", "x.rei"], tmp_path) == 1
    finally:
        server.join()
        listener.close()
    assert time.monotonic() - started > 1.0 and command.poll() == 0
    assert "exit code is lost" in capfd.readouterr().err


def test_a_forked_command_ends_as_the_interpreter_would(server: Path, tmp_path: Path) -> None:
    """An uncaught Ctrl-C: killed by SIGINT (a shell's 130, as Python does); sys.exit: non-daemon threads first."""
    _, status = _command(server, tmp_path, dict(os.environ), "interrupt")
    assert os.WIFSIGNALED(status) and os.WTERMSIG(status) == signal.SIGINT
    output, status = _command(server, tmp_path, dict(os.environ), "exit-in-a-thread's-time")
    assert os.waitstatus_to_exitcode(status) == 4 and output == b"the thread's line\n"


def test_a_requester_with_other_interpreter_settings_runs_its_command_itself(server: Path, tmp_path: Path) -> None:
    """PYTHONPATH and the like are read at an interpreter's start: a fork would have the service's."""
    with open(os.devnull, "rb") as null:
        fds = [null.fileno()] * 3
        assert warm._request(server, ["rei", "probe"], fds, {**os.environ, "PYTHONPATH": str(tmp_path)},
                             str(tmp_path)) is None
        assert warm._request(server, ["rei", "probe"], fds, {**os.environ, "PYTHONHASHSEED": "7"},
                             str(tmp_path)) is None
    report, _ = _probe(server, tmp_path, dict(os.environ))  # the server goes on
    assert report["cwd"] == str(tmp_path)


def test_a_forked_commands_standard_streams_are_an_interpreters(server: Path, tmp_path: Path) -> None:
    """Encoding, errors, buffering (PYTHONUNBUFFERED, PYTHONIOENCODING) as a Python started with the same
    environment and the same files makes them."""
    report, _ = _probe(server, tmp_path, dict(os.environ))
    fresh = subprocess.run([sys.executable, "-c", f"import json, sys; print(json.dumps({_STREAMS}))"],
                           stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, check=True)
    assert report["streams"] == json.loads(fresh.stdout)


def test_the_fingerprint_changes_with_a_module_and_only_with_one(tmp_path: Path) -> None:
    package = tmp_path / "rei"
    (package / "sub" / "__pycache__").mkdir(parents=True)
    (package / "a.py").write_text("A = 1\n")
    module = package / "sub" / "b.py"
    module.write_text("B = 1\n")
    first = warm.source_fingerprint(package)
    (package / "sub" / "__pycache__" / "b.cpython-311.pyc").write_bytes(b"compiled")
    (package / "data.json").write_text("{}")
    assert warm.source_fingerprint(package) == first
    os.utime(module, ns=(module.stat().st_atime_ns, module.stat().st_mtime_ns + 1))  # edited, same size
    second = warm.source_fingerprint(package)
    assert second != first
    (package / "sub" / "c.py").write_text("")
    assert warm.source_fingerprint(package) not in (first, second)
    assert warm.source_fingerprint() == warm.source_fingerprint(Path(warm.__file__).resolve().parents[1])


def _answering(tmp_path: Path, *lines: dict) -> threading.Thread:
    """A server on ``tmp_path/warm.sock`` that answers one request with ``lines``, in one write, and goes."""
    listener = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    listener.bind(str(tmp_path / warm.SOCKET_NAME))
    listener.listen(1)

    def answer() -> None:
        with listener:
            connection, _ = listener.accept()
            with connection:
                _, fds, _, _ = socket.recv_fds(connection, 1 << 20, 3)
                for fd in fds:
                    os.close(fd)
                connection.sendall(b"".join(json.dumps(line).encode() + b"\n" for line in lines))
                connection.recv(1)  # until the requester hangs up

    thread = threading.Thread(target=answer)
    thread.start()
    return thread


def test_a_command_that_ended_at_once_is_not_run_again(tmp_path: Path) -> None:
    """Its pid and its status in one read: the pid is taken, the status kept for later (the requester took the two
    lines for a bad answer and ran the command a second time itself)."""
    server = _answering(tmp_path, {"pid": 4242}, {"status": 2 << 8})
    sent = warm._request(tmp_path / warm.SOCKET_NAME, ["rei", "run"], [0, 1, 2], dict(os.environ), str(tmp_path))
    assert sent is not None and sent[1] == 4242
    process = warm.WarmProcess(*sent, None, None)
    assert process.wait(5.0) == 2
    server.join()


def test_a_forked_command_takes_on_what_a_child_of_the_requester_would_inherit(server: Path, tmp_path: Path) -> None:
    """nohup, nice, taskset, ulimit -c: the requester's, not the service's (whose SIGQUIT is ignored here)."""
    script = f"""
import json, os, resource, signal, sys
sys.path.insert(0, {str(Path(__file__).parent)!r})
import test_warm_python as t
from rei.service import warm
warm.source_fingerprint = lambda root=None: "this-test"
signal.signal(signal.SIGHUP, signal.SIG_IGN)
os.nice(3)
os.sched_setaffinity(0, {{0}})
resource.setrlimit(resource.RLIMIT_CORE, (0, resource.getrlimit(resource.RLIMIT_CORE)[1]))
print(json.dumps(t._probe(__import__("pathlib").Path({str(server)!r}), __import__("pathlib").Path("/"),
                          dict(os.environ))[0]))
"""
    report = json.loads(subprocess.run([sys.executable, "-c", script], stdout=subprocess.PIPE, check=True).stdout)
    assert report["signals"] == {"SIGHUP": str(signal.SIG_IGN), "SIGQUIT": str(signal.SIG_DFL),
                                 "SIGINT": str(signal.default_int_handler)}
    assert report["nice"] == os.getpriority(os.PRIO_PROCESS, 0) + 3
    assert report["cpus"] == [0] and report["core"][0] == 0


def test_a_command_with_a_standard_stream_closed_runs_itself(tmp_path: Path) -> None:
    """``rei run <&-``: the request's socket would be its standard input, passed to the run, which would then hold
    the requester's end (its death unnoticed) and read the server's answers."""
    listener = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    listener.bind(str(tmp_path / warm.SOCKET_NAME))
    listener.listen(1)
    listener.setblocking(False)
    script = f"import os; os.close(0); from pathlib import Path; from rei.service import warm; " \
             f"print(warm.delegate(['run', 'x.rei'], Path({str(tmp_path)!r})))"
    done = subprocess.run([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True, timeout=60, check=True)
    assert done.stdout == "None\n"
    with pytest.raises(BlockingIOError):  # it did not even ask
        listener.accept()
    listener.close()


_DELEGATE = "import sys; from pathlib import Path; from rei.service import warm; sys.exit(warm.delegate(['run'], Path(sys.argv[1])))"


def test_a_command_whose_run_was_killed_by_a_signal_is_killed_by_it(tmp_path: Path) -> None:
    """As the run by itself: its parent sees the signal, not an exit code (bash stops a loop only for that)."""
    server = _answering(tmp_path, {"pid": _NO_PROCESS}, {"status": signal.SIGKILL})
    done = subprocess.run([sys.executable, "-c", _DELEGATE, str(tmp_path)], timeout=60, check=False)
    server.join()
    assert done.returncode == -signal.SIGKILL


def _state(pid: int) -> str:
    return Path(f"/proc/{pid}/stat").read_text().rpartition(")")[2].split()[0]


def _await_state(pid: int, state: str) -> None:
    deadline = time.monotonic() + 10
    while _state(pid) != state:
        assert time.monotonic() < deadline, (pid, _state(pid), state)
        time.sleep(0.02)


def test_ctrl_z_stops_the_run_with_the_command_and_fg_goes_on_with_both(tmp_path: Path) -> None:
    run = subprocess.Popen(["sleep", "60"], start_new_session=True)
    listener = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
    listener.bind(str(tmp_path / warm.SOCKET_NAME))
    listener.listen(1)
    # a process group of its own in the test's session, as a shell's job is: in an orphaned group (the test's own
    # under a CI runner without a terminal) the kernel discards a stop signal whose action is the default
    command = subprocess.Popen([sys.executable, "-c", _DELEGATE, str(tmp_path)], process_group=0)
    try:
        connection, _ = listener.accept()
        _, fds, _, _ = socket.recv_fds(connection, 1 << 20, 3)
        for fd in fds:
            os.close(fd)
        connection.sendall(json.dumps({"pid": run.pid}).encode() + b"\n")
        time.sleep(0.5)  # the command waits for the run's end
        command.send_signal(signal.SIGTSTP)
        _await_state(command.pid, "T")
        _await_state(run.pid, "T")
        command.send_signal(signal.SIGCONT)
        _await_state(run.pid, "S")
    finally:
        run.kill()
        command.kill()
        run.wait()
        command.wait()
        listener.close()


def test_an_interrupted_start_leaks_no_pipe(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    def interrupted(*_args: object) -> None:
        raise KeyboardInterrupt

    monkeypatch.setattr(warm, "_request", interrupted)
    monkeypatch.setenv(warm.SOCKET_ENV, str(tmp_path / warm.SOCKET_NAME))
    with open(os.devnull, "w") as log:
        before = _open_fds()
        with pytest.raises(KeyboardInterrupt):
            warm.WarmProcess.start(["sim"], stdin_pipe=True, stdout=None, stderr=log, env={}, cwd=None)
        assert _open_fds() <= before
