# SPDX-License-Identifier: EPL-2.0
"""Short-lived runs of REI's jars: generation per test case, monitor replay per run (campaigns, re-evaluation).

Why these flags: every JVM of a campaign is short-lived (2-5 s), so most of its CPU goes into starting up and
into the optimising JIT compiler, whose work never pays back. Measured on the 2-core machine with a 665-state
replay: default flags 5.4 s CPU; ``-XX:TieredStopAtLevel=1`` (client compiler only) 3.0 s; plus
``-XX:+UseSerialGC`` (no parallel GC threads competing with the other runs) 2.7 s. Generation: 2.3 -> 1.5 s.

A warm JVM (``JarServer``, the jar's ``--serve SOCKET``, org.rei.warmjvm) runs many commands in one JVM: classes
loaded, code compiled and rule bases built once. ``run_jar(..., server=SOCKET)`` sends the command there instead
of starting a JVM, and falls back to its own JVM when the server is gone.

Class-data sharing on top: the first run of a jar dumps the classes it loaded into an archive
(``-XX:ArchiveClassesAtExit``, once, ~1.4 s extra), later runs map it instead of loading and verifying the classes
again (``benchmarks/replay_jvm.py``). Archives are kept per jar build and Java in ``$REI_CDS_DIR`` (default
``~/.cache/rei/cds``; ``off`` disables them); a rebuilt jar gets a new one.
"""

from __future__ import annotations

import contextlib
import hashlib
import os
import re
import shutil
import socket
import subprocess
import tempfile
import threading
import time
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import IO, Self

from rei import toolchain
from rei.processes import close_and_reap

FAST_START_FLAGS: tuple[str, ...] = ("-XX:TieredStopAtLevel=1", "-XX:+UseSerialGC")
CDS_ENV = "REI_CDS_DIR"


@dataclass(frozen=True, slots=True)
class JvmResult:
    code: int
    wall: float
    cpu: float  # user + system seconds of the JVM (served: of the command's thread in the warm JVM)
    log_tail: str
    served: bool = False  # ran in a warm JVM (JarServer), not in one of its own


#: The words of a warm JVM's protocol (contract/vocabulary.json, "warm_jvm"; org.rei.warmjvm.CommandServer).
REQUEST_WORDS = ("arg", "log", "run")
ANSWER_WORD = "exit"
#: Seconds a warm JVM may take to start listening.
SERVER_START_TIMEOUT = 60.0


class JarServerError(RuntimeError):
    """A warm JVM did not start; the message has its log's tail."""


class JarServer:
    """One of REI's jars serving many commands in one JVM until ``stop()`` (or until this process ends: the JVM
    exits when its standard input closes). Its socket lives in a new private folder (0700), or in ``folder`` (the
    caller's, private, not removed at ``stop()``)."""

    def __init__(self, role: str, log: Path, folder: Path | None = None) -> None:
        self.role, self.log = role, log
        self._given = folder
        self._folder: Path | None = None
        self._process: subprocess.Popen[bytes] | None = None
        self._log_file: IO[bytes] | None = None
        self._dump: tuple[Path, Path] | None = None
        self.cpu = 0.0  # user + system seconds of the JVM, once stopped

    @property
    def socket(self) -> Path:
        if self._folder is None:
            raise RuntimeError("the server is not started")
        return self._folder / "jvm.sock"

    def start(self) -> Self:
        java = toolchain.find_java()
        jar = toolchain.find_jar(self.role)
        sharing, self._dump = _class_sharing(jar, java)
        # 0700: whoever connects runs commands
        self._folder = self._given or Path(tempfile.mkdtemp(prefix=f"rei-{self.role}-"))
        self.log.parent.mkdir(parents=True, exist_ok=True)
        self.log.write_bytes(b"")
        # appending: the JVM's standard error and the copy of its standard output share the file
        self._log_file = open(self.log, "ab")  # noqa: SIM115 - kept open while the JVM runs
        self._process = subprocess.Popen(
            [str(java.executable), *FAST_START_FLAGS, *sharing, "-jar", str(jar), "--serve", str(self.socket)],
            stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=self._log_file)
        assert self._process.stdout is not None
        ready = _read_line(self._process.stdout, SERVER_START_TIMEOUT)
        if ready != b"ready\n":
            self.stop()
            raise JarServerError(f"the warm {self.role} JVM did not start: {tail(self.log, 8)}")
        # whatever the JVM still prints goes to its log: an unread pipe would block it once full
        threading.Thread(target=_copy, args=(self._process.stdout, self._log_file), name=f"{self.role}-jvm-out",
                         daemon=True).start()
        return self

    def alive(self) -> bool:
        return self._process is not None and self._process.poll() is None

    def stop(self, timeout: float = 10.0) -> None:
        """Closes the JVM's standard input (it finishes and exits), kills it after ``timeout``."""
        process = self._process
        if process is None:
            return
        self._process = None
        self.cpu = close_and_reap(process, timeout) or self.cpu  # alive() may have reaped a JVM that died by itself
        if self._dump is not None:
            _keep_archive(self._dump, ok=process.returncode == 0)
        if self._log_file is not None:
            if process.stdout is not None:
                process.stdout.close()
            self._log_file.close()
        if self._folder is not None and self._given is None:
            shutil.rmtree(self._folder, ignore_errors=True)

    def __enter__(self) -> Self:
        return self.start()

    def __exit__(self, *exc: object) -> None:
        self.stop()


def run_served(server: Path, args: Sequence[str], log: Path, timeout: float | None = None) -> JvmResult | None:
    """Run one command in the warm JVM listening on ``server``; None when nobody answers there or the JVM ended
    during the command (then run it in a JVM of its own: REI's commands can be run again).

    ``cpu`` is the command thread's CPU time in the server. A timed-out command is cancelled (exit code -1)."""
    started = time.perf_counter()
    try:
        command = ServedCommand("command", server, args, log)
    except ConnectionError:
        return None
    code = command.wait(timeout)
    command.stop()  # cancels a command that is still running
    if code is None:
        return JvmResult(-1, time.perf_counter() - started, 0.0,
                         f"{tail(log, 7)}\ncancelled after {timeout:.0f} s".strip(), served=True)
    if not command.answered:
        return None  # the warm JVM ended during the command: the caller runs it in a JVM of its own
    return JvmResult(code, time.perf_counter() - started, command.cpu, tail(log, 8), served=True)


class ServedCommand:
    """A command running in a warm JVM, supervised like a child process (rei.processes.ManagedProcess): poll,
    wait, stop (which cancels it in the JVM), its exit described and its log's tail.

    Raises ConnectionError at once when nobody serves ``server``."""

    def __init__(self, name: str, server: Path, args: Sequence[str], log: Path) -> None:
        for value in (*args, str(log)):
            if "\n" in value or "\r" in value:
                raise ValueError(f"a line break in {value!r}: not passed to a warm JVM")
        self.name, self.log = name, log
        self.answered = False  # the JVM gave an exit line (else it went away during the command)
        self.cpu = 0.0  # the command thread's CPU seconds in the JVM, once answered
        self._connection = socket.socket(socket.AF_UNIX, socket.SOCK_STREAM)
        try:
            self._connection.connect(str(server))
            self._connection.sendall(_request(args, log))
        except OSError as error:
            self._connection.close()
            raise ConnectionError(f"no warm JVM answers at {server}: {error}") from error
        self._code: int | None = None
        self._cancelled = False
        self._done = threading.Event()
        self._thread = threading.Thread(target=self._await, name=f"{name}-served", daemon=True)
        self._thread.start()

    def _await(self) -> None:
        answer = b""
        try:
            while not answer.endswith(b"\n"):
                chunk = self._connection.recv(64)
                if not chunk:
                    break
                answer += chunk
        except OSError:
            pass
        fields = answer.decode("ascii", errors="replace").split()
        self.answered = len(fields) == 4 and fields[0] == ANSWER_WORD
        if self.answered:
            self.cpu = int(fields[2]) / 1000
        self._code = int(fields[1]) if self.answered else -1
        self._done.set()

    def poll(self) -> int | None:
        return self._code if self._done.is_set() else None

    def wait(self, timeout: float | None) -> int | None:
        self._done.wait(timeout)
        return self.poll()

    def stop(self, grace: float = 10.0) -> int:
        """Cancel the command unless it finished (closing the connection interrupts its thread in the JVM)."""
        if not self._done.is_set():
            self._cancelled = True
            with contextlib.suppress(OSError):
                self._connection.shutdown(socket.SHUT_RDWR)
            self._done.wait(grace)
        self._connection.close()
        return self._code if self._code is not None else -1

    def describe_exit(self) -> str:
        if self._code is None:
            return f"{self.name} is running"
        if self._code == -1:
            return f"{self.name} was cancelled" if self._cancelled else \
                f"{self.name} ended without an exit code (the warm JVM serving it is gone)"
        return f"{self.name} exited with code {self._code}"

    def log_tail(self, lines: int = 20) -> str:
        return tail(self.log, lines)


def _copy(source: IO[bytes], target: IO[bytes]) -> None:
    with contextlib.suppress(OSError, ValueError):  # closed at stop()
        for line in source:
            target.write(line)
            target.flush()


def _request(args: Sequence[str], log: Path) -> bytes:
    arg, log_word, run = REQUEST_WORDS
    return ("".join(f"{arg} {a}\n" for a in args) + f"{log_word} {log}\n{run}\n").encode("utf-8")


def _read_line(stream: IO[bytes], timeout: float) -> bytes:
    """One line of a child's output, or b"" when none comes within ``timeout`` seconds (or it ended)."""
    import selectors

    with selectors.DefaultSelector() as selector:
        selector.register(stream, selectors.EVENT_READ)
        if not selector.select(timeout):
            return b""
    return stream.readline()


def run_jar(role: str, args: Sequence[str], log: Path, timeout: float | None = None,
            server: Path | None = None) -> JvmResult:
    """Run one of REI's jars to completion with the fast-start flags, its output into ``log``: in the warm JVM
    listening on ``server`` when given and answering, else in a JVM of its own."""
    if server is not None:
        served = run_served(server, args, log, timeout)
        if served is not None:
            return served
    java = toolchain.find_java()
    jar = toolchain.find_jar(role)
    sharing, dump = _class_sharing(jar, java)
    command = [str(java.executable), *FAST_START_FLAGS, *sharing, "-jar", str(jar), *args]
    started = time.perf_counter()
    with open(log, "wb") as out:
        process = subprocess.Popen(command, stdout=out, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL)
        deadline = None if timeout is None else started + timeout
        while True:
            pid, status, usage = os.wait4(process.pid, os.WNOHANG)
            if pid:
                break
            if deadline is not None and time.perf_counter() > deadline:
                process.kill()
                pid, status, usage = os.wait4(process.pid, 0)
                break
            time.sleep(0.02)
    process.returncode = os.waitstatus_to_exitcode(status)
    if dump is not None:
        _keep_archive(dump, ok=process.returncode == 0)
    return JvmResult(process.returncode, time.perf_counter() - started, usage.ru_utime + usage.ru_stime,
                     tail(log, 8))


def cds_archive(jar: Path, java: toolchain.Java) -> Path | None:
    """Where the class-data-sharing archive of this build of ``jar`` under ``java`` is (or would be); None: off.

    Named ``<jar>-<owner>-<build>.jsa``: the owner is the jar's path and the Java it runs under, the build its size,
    time and Java's version. A new build's archive replaces its owner's older ones (``_keep_archive``), so
    rebuilding REI does not pile up archives of jars that are gone (each is 10-30 MB)."""
    setting = os.environ.get(CDS_ENV, "")
    if setting == "off":
        return None
    folder = Path(setting) if setting else Path.home() / ".cache" / "rei" / "cds"
    stat = jar.stat()
    owner = _digest(f"{jar.resolve()}|{java.executable}")
    build = _digest(f"{stat.st_size}|{stat.st_mtime_ns}|{java.version}")
    return folder / f"{jar.stem}-{owner}-{build}.jsa"


def _digest(text: str) -> str:
    return hashlib.sha256(text.encode()).hexdigest()[:8]


def _stale_archives(archive: Path) -> list[Path]:
    """The same owner's archives of other builds, and archives named as before owners were (``<jar>-<16 hex>``),
    which nothing uses any more."""
    stem, owner, _ = archive.stem.rsplit("-", 2)
    stale = [p for p in archive.parent.glob(f"{stem}-{owner}-*.jsa") if p != archive]
    return stale + [p for p in archive.parent.glob(f"{stem}-*.jsa") if _OLD_NAME.fullmatch(p.name[len(stem) + 1:])]


_OLD_NAME = re.compile(r"[0-9a-f]{16}\.jsa")


def _class_sharing(jar: Path, java: toolchain.Java) -> tuple[list[str], tuple[Path, Path] | None]:
    """JVM flags that use the jar's archive, or dump it when there is none yet (then: where to, and its name)."""
    archive = cds_archive(jar, java)
    if archive is None:
        return [], None
    if archive.is_file():
        return [f"-XX:SharedArchiveFile={archive}"], None
    try:
        archive.parent.mkdir(parents=True, exist_ok=True)
    except OSError:
        return [], None  # no writable cache: run without sharing
    # another run may dump at the same time: each writes its own file, the last rename wins (same content)
    pending = archive.with_name(f".{archive.name}.{os.getpid()}.tmp")
    # quiet: the dump warns of every class it cannot archive (old bytecode, excluded super classes)
    return [f"-XX:ArchiveClassesAtExit={pending}", "-Xlog:cds=off", "-Xlog:cds+dynamic=off"], (pending, archive)


def _keep_archive(dump: tuple[Path, Path], *, ok: bool) -> None:
    pending, archive = dump
    try:
        if ok and pending.is_file():
            os.replace(pending, archive)
            for stale in _stale_archives(archive):  # a running JVM keeps its mapping of an unlinked archive
                stale.unlink(missing_ok=True)
        else:
            pending.unlink(missing_ok=True)  # a failed run's classes are not worth keeping
    except OSError:
        pass  # the archive is an optimisation: without it the next run dumps again


def tail(path: Path, lines: int) -> str:
    try:
        text = path.read_text(encoding="utf-8", errors="replace")
    except OSError:
        return ""
    return "\n".join(text.rstrip().splitlines()[-lines:])


