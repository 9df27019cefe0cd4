# SPDX-License-Identifier: EPL-2.0
"""Shared fixtures of the end-to-end tests: the built jars and helpers that run REI as real processes.

These tests never skip: a missing jar or tool is a failure that says how to get it (`./rei` builds everything).
"""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path

import pytest
from playwright.sync_api import Browser, sync_playwright

from rei import toolchain

REPO_ROOT = Path(__file__).resolve().parent.parent
#: Generous: the JVM starts cold and the 2-core CI machine may be busy with other processes.
CLI_TIMEOUT_S = 180.0


@dataclass(frozen=True, slots=True)
class CliResult:
    """Outcome of one `rei` process."""

    args: list[str]
    returncode: int
    stdout: str
    stderr: str


RunCli = Callable[..., CliResult]


def run_bounded(
    argv: list[str], timeout: float, cwd: Path | None = None, env: dict[str, str] | None = None
) -> tuple[int, str, str]:
    """Run `argv` to completion and return (exit code, stdout, stderr); fail the test after `timeout` s.

    The process gets its own session so a timeout kills the whole group: `rei` is a Python process whose
    JVM child would otherwise outlive it.
    """
    process = subprocess.Popen(
        argv,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        stdin=subprocess.DEVNULL,
        text=True,
        cwd=cwd,
        env={**os.environ, **(env or {})},
        start_new_session=True,
    )
    try:
        stdout, stderr = process.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        stdout, stderr = process.communicate()
        pytest.fail(f"{' '.join(argv)} did not finish within {timeout} s; stderr: {stderr[-2000:]!r}")
    return process.returncode, stdout, stderr


def _jar(role: str) -> Path:
    try:
        return toolchain.find_jar(role, REPO_ROOT)
    except toolchain.ToolchainError as error:
        problem = str(error)
    pytest.fail(problem, pytrace=False)  # outside `except`: one line, no chained traceback


@pytest.fixture(scope="session", autouse=True)
def background_service() -> Iterator[Path]:
    """Runs use the background service (rei.service) as a user's do: one per test session in a folder of its own
    (short: a Unix socket's path is limited to 107 bytes), stopped at the end."""
    import shutil
    import tempfile

    from rei.service import DIR_ENV
    from rei.service.client import stop

    folder = Path(tempfile.mkdtemp(prefix="rei-service-"))
    previous = os.environ.get(DIR_ENV)
    os.environ[DIR_ENV] = str(folder)
    yield folder
    stop(folder)
    if previous is None:
        os.environ.pop(DIR_ENV, None)
    else:
        os.environ[DIR_ENV] = previous
    shutil.rmtree(folder, ignore_errors=True)


@pytest.fixture(scope="session")
def repo_root() -> Path:
    """The checkout under test."""
    return REPO_ROOT


@pytest.fixture(scope="session")
def chromium() -> str:
    """Debian's chromium (installed by scripts/setup-browser.sh) for the browser tests, or REI_CHROMIUM."""
    for candidate in (os.environ.get("REI_CHROMIUM"), "chromium", "chromium-browser", "google-chrome"):
        found = shutil.which(candidate) if candidate else None
        if found:
            return found
    pytest.fail("no headless browser: run scripts/setup-browser.sh (apt-get install chromium) or set REI_CHROMIUM",
                pytrace=False)


@pytest.fixture(scope="session")
def browser(chromium: str) -> Iterator[Browser]:
    """Debian's chromium driven by Playwright (its own browser downloads are never used)."""
    with sync_playwright() as playwright:
        launched = playwright.chromium.launch(executable_path=chromium,
                                              args=["--no-sandbox", "--disable-dev-shm-usage"])
        try:
            yield launched
        finally:
            launched.close()


@pytest.fixture(scope="session")
def java() -> toolchain.Java:
    """The checked Java launcher (>= 17)."""
    try:
        return toolchain.find_java()
    except toolchain.ToolchainError as error:
        problem = str(error)
    pytest.fail(problem, pytrace=False)


@pytest.fixture(scope="session")
def cli_jar() -> Path:
    """`rei-cli.jar` (validate, generate)."""
    return _jar("cli")


@pytest.fixture(scope="session")
def language_server_jar() -> Path:
    """`rei-language-server.jar` (LSP over stdio)."""
    return _jar("language-server")


@pytest.fixture(scope="session")
def monitor_jar() -> Path:
    """`rei-monitor.jar`."""
    return _jar("monitor")


@pytest.fixture(scope="session")
def room_editor_jar() -> Path:
    """`rei-room-editor.jar`, the room editor's edit engine (JSON lines over stdio)."""
    return _jar("room-editor")


@pytest.fixture(scope="session")
def sut_kit_jar() -> Path:
    """`rei-sut-kit.jar`, the Java client kit of external SUTs."""
    return _jar("sut-kit")


@pytest.fixture(scope="session")
def rei_script() -> Path:
    """The installed `rei` console script of the environment running the tests."""
    script = Path(sys.executable).parent / "rei"
    if not script.is_file():
        pytest.fail(f"{script} is missing: pip install -e 'sim-adapter[dev]' (./rei does it)", pytrace=False)
    return script


@pytest.fixture(scope="session")
def run_cli(rei_script: Path, cli_jar: Path, java: toolchain.Java) -> RunCli:
    """Run `rei ARGS...` (the console script, so the Python-to-Java hand-over is part of every test) with a
    timeout, capturing its output; `env` adds to the environment. Depends on `cli_jar` so a missing build fails
    with the build hint."""

    def run(*args: str | Path, timeout: float = CLI_TIMEOUT_S, cwd: Path | None = None,
            env: dict[str, str] | None = None) -> CliResult:
        argv = [str(rei_script), *map(str, args)]
        returncode, stdout, stderr = run_bounded(argv, timeout, cwd=cwd,
                                                 env={"REI_HOME": str(REPO_ROOT), **(env or {})})
        return CliResult(argv, returncode, stdout, stderr)

    return run


@pytest.fixture
def write_rei(tmp_path: Path) -> Callable[[str, str], Path]:
    """Write a test case into the test's temporary directory: `write_rei("case.rei", text)`."""

    def write(name: str, text: str) -> Path:
        path = tmp_path / name
        path.write_text(text, encoding="utf-8")
        return path

    return write


def _processes_mentioning(path: Path) -> list[str]:
    """Command lines of live processes that name `path` (children get their run folder on the command line)."""
    found = []
    for cmdline in Path("/proc").glob("[0-9]*/cmdline"):
        try:
            text = cmdline.read_bytes().replace(b"\0", b" ").decode(errors="replace")
        except OSError:
            continue
        if str(path) in text:
            found.append(text)
    return found


@pytest.fixture(scope="session")
def processes_mentioning() -> Callable[[Path], list[str]]:
    """`processes_mentioning(folder)`: what still runs for a run folder; a clean shutdown leaves nothing."""
    return _processes_mentioning
