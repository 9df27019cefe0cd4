# SPDX-License-Identifier: EPL-2.0
"""Find the Java runtime and the REI jars, and run a jar as a child process.

The language tooling (parser, validation, generators, language server) is Java; the Python side only
delegates to it. Everything that can go wrong before the JVM starts (no Java, an old Java, a checkout that
was never built) is reported here as a `ToolchainError` with a message that says what to do, so the CLI can
print one line instead of a traceback.
"""

from __future__ import annotations

import os
import re
import shutil
import signal
import subprocess
import sys
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

MIN_JAVA_VERSION = 17

#: Jars the Python side starts, by role, relative to the repository root. `./rei` builds the same list.
JARS: Mapping[str, str] = {
    "cli": "generators/org.rei.cli/target/rei-cli.jar",
    "language-server": "bundles/org.rei.dsl.ide/target/rei-language-server.jar",
    "room-editor": "bundles/org.rei.dsl.edit/target/rei-room-editor.jar",  # the edit engine of `rei edit`
    "monitor": "runtime-monitor/target/rei-monitor.jar",
    "sut-kit": "sut-kits/java/target/rei-sut-kit.jar",  # the Java client kit of external SUTs (docs/sut.md)
}

BUILD_HINT = "run ./rei once to build the Java parts"
#: Where an installed wheel keeps the jars it carries (scripts/build-wheel.sh copies them in, by their file names):
#: a Ray worker node or a container runs REI without a checkout. Absent in a checkout, whose Maven builds them.
PACKAGED_JARS = Path(__file__).with_name("jars")

# The Java generator reads a robot's URDF or xacro description through REI's Python reader (xacro and ROS's URDF
# parser are Python packages): every JVM started from here inherits this interpreter, the one REI is installed in.
os.environ.setdefault("REI_PYTHON", sys.executable)

_VERSION_RE = re.compile(r'version "(\d+)(?:\.(\d+))?[^"]*"')
_RELEASE_RE = re.compile(r'^JAVA_VERSION="(\d+)(?:\.(\d+))?[^"]*"', re.MULTILINE)


class ToolchainError(Exception):
    """The environment cannot run the Java parts; the message tells the user how to fix it."""


@dataclass(frozen=True, slots=True)
class Java:
    """A Java launcher that was checked to be recent enough."""

    executable: Path
    version: int


def find_repo_root(start: Path | None = None, env: Mapping[str, str] | None = None) -> Path:
    """The REI checkout whose jars to use: `REI_HOME` when set, else the first parent of `start`
    (default: this module) holding both `pom.xml` and `sim-adapter/` -- true for an editable install."""
    env = os.environ if env is None else env
    home = env.get("REI_HOME")
    if home:
        root = Path(home).expanduser()
        if not _is_repo_root(root):
            raise ToolchainError(
                f"REI_HOME={home} is not an REI checkout (no pom.xml and sim-adapter/ there)"
            )
        return root.resolve()
    origin = (start or Path(__file__)).resolve()
    for candidate in (origin, *origin.parents):
        if _is_repo_root(candidate):
            return candidate
    raise ToolchainError(f"cannot find the REI checkout above {origin}; set REI_HOME to the repository root")


def _is_repo_root(path: Path) -> bool:
    return (path / "pom.xml").is_file() and (path / "sim-adapter").is_dir()


def find_java(env: Mapping[str, str] | None = None) -> Java:
    """The `java` of `JAVA_HOME` when set (as Maven does), else the one on PATH, checked to be >= 17."""
    env = os.environ if env is None else env
    java_home = env.get("JAVA_HOME")
    if java_home:
        executable = Path(java_home) / "bin" / "java"
        if not os.access(executable, os.X_OK):
            raise ToolchainError(f"JAVA_HOME={java_home} has no bin/java; fix JAVA_HOME or unset it")
    else:
        found = shutil.which("java", path=env.get("PATH"))
        if found is None:
            raise ToolchainError(
                f"java not found on PATH; install a Java {MIN_JAVA_VERSION}+ runtime or set JAVA_HOME"
            )
        executable = Path(found)
    version = java_version(executable)
    if version < MIN_JAVA_VERSION:
        raise ToolchainError(
            f"{executable} is Java {version}; REI needs Java {MIN_JAVA_VERSION} or newer (set JAVA_HOME)"
        )
    return Java(executable, version)


def java_version(executable: Path) -> int:
    """The feature version (8, 11, 17, ...) of a Java launcher.

    Reads the JDK's `release` file when there is one, which costs no JVM start; otherwise asks
    `java -version`.
    """
    release = executable.resolve().parent.parent / "release"
    try:
        found = _RELEASE_RE.search(release.read_text(encoding="utf-8", errors="replace"))
    except OSError:
        found = None
    if found is None:
        try:
            completed = subprocess.run(
                [str(executable), "-version"], capture_output=True, text=True, timeout=60, check=False
            )
        except (OSError, subprocess.TimeoutExpired) as error:
            raise ToolchainError(f"cannot run {executable} -version: {error}") from error
        found = _VERSION_RE.search(completed.stderr + completed.stdout)
        if found is None:
            raise ToolchainError(f"cannot read the version of {executable} from `java -version`")
    major, minor = int(found.group(1)), int(found.group(2) or 0)
    return minor if major == 1 else major  # "1.8.0_402" is Java 8


def find_jar(role: str, root: Path | None = None) -> Path:
    """The built jar for `role` (a key of `JARS`), or an error telling the user to build it: the checkout's
    (`root`, else `REI_HOME`'s), else the one an installed wheel carries, else the checkout above this module's."""
    if role not in JARS:
        raise ValueError(f"unknown jar role {role!r}; known: {', '.join(JARS)}")
    if root is None and not os.environ.get("REI_HOME") and PACKAGED_JARS.is_dir():
        packaged = PACKAGED_JARS / Path(JARS[role]).name
        if packaged.is_file():
            return packaged
        carried = ", ".join(sorted(p.name for p in PACKAGED_JARS.glob("*.jar"))) or "none"
        raise ToolchainError(f"this installation of REI carries no {packaged.name} (it has: {carried}); install a "
                             f"wheel built with it (scripts/build-wheel.sh --jars {role}) or set REI_HOME to a "
                             "built checkout")
    root = find_repo_root() if root is None else root
    jar = root / JARS[role]
    if not jar.is_file():
        raise ToolchainError(f"{jar} is missing: {BUILD_HINT}")
    return jar


def jar_command(jar: Path, args: Sequence[str], java: Java | None = None) -> list[str]:
    """The argument vector that runs `jar` with `args`."""
    java = find_java() if java is None else java
    return [str(java.executable), "-jar", str(jar), *args]


def run_jar(jar: Path, args: Sequence[str], java: Java | None = None, cwd: Path | None = None) -> int:
    """Run `jar` with the caller's stdin/stdout/stderr, so its output streams as it comes, and return its
    exit code. Ctrl-C reaches the JVM through the terminal's process group; we wait for it to finish
    rather than leaving an orphan behind, and report 130 as shells do."""
    command = jar_command(jar, args, java)
    try:
        process = subprocess.Popen(command, cwd=cwd)
    except OSError as error:
        raise ToolchainError(f"cannot start {command[0]}: {error}") from error
    try:
        return process.wait()
    except KeyboardInterrupt:
        process.send_signal(signal.SIGINT)
        try:
            process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()
        return 128 + signal.SIGINT
