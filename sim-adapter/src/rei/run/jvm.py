# SPDX-License-Identifier: EPL-2.0
"""Short-lived runs of REI's jars: generation per test case, monitor replay per run (campaigns, re-evaluation).

Why these flags: every JVM of a campaign is short-lived (2-5 s), so most of its CPU goes into starting up and
into the optimising JIT compiler, whose work never pays back. Measured on the 2-core machine with a 665-state
replay: default flags 5.4 s CPU; ``-XX:TieredStopAtLevel=1`` (client compiler only) 3.0 s; plus
``-XX:+UseSerialGC`` (no parallel GC threads competing with the other runs) 2.7 s. Generation: 2.3 -> 1.5 s.

Class-data sharing on top: the first run of a jar dumps the classes it loaded into an archive
(``-XX:ArchiveClassesAtExit``, once, ~1.4 s extra), later runs map it instead of loading and verifying the classes
again (``benchmarks/replay_jvm.py``). Archives are kept per jar build and Java in ``$REI_CDS_DIR`` (default
``~/.cache/rei/cds``; ``off`` disables them); a rebuilt jar gets a new one.
"""

from __future__ import annotations

import hashlib
import os
import subprocess
import time
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from rei import toolchain

FAST_START_FLAGS: tuple[str, ...] = ("-XX:TieredStopAtLevel=1", "-XX:+UseSerialGC")
CDS_ENV = "REI_CDS_DIR"


@dataclass(frozen=True, slots=True)
class JvmResult:
    code: int
    wall: float
    cpu: float  # user + system seconds of the JVM
    log_tail: str


def run_jar(role: str, args: Sequence[str], log: Path, timeout: float | None = None) -> JvmResult:
    """Run one of REI's jars to completion with the fast-start flags, its output into ``log``."""
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
    """Where the class-data-sharing archive of this build of ``jar`` under ``java`` is (or would be); None: off."""
    setting = os.environ.get(CDS_ENV, "")
    if setting == "off":
        return None
    folder = Path(setting) if setting else Path.home() / ".cache" / "rei" / "cds"
    stat = jar.stat()
    build = f"{jar.resolve()}|{stat.st_size}|{stat.st_mtime_ns}|{java.executable}|{java.version}"
    return folder / f"{jar.stem}-{hashlib.sha256(build.encode()).hexdigest()[:16]}.jsa"


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


