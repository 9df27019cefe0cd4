# SPDX-License-Identifier: EPL-2.0
"""The VS Code extension in a real VS Code workbench: code-server 4.100.3 (VS Code 1.100.3 served to a browser)
with the packaged .vsix installed, driven by Debian's chromium through Playwright like a person would: open a
test case from the Explorer, read the Problems panel and the status bar, type in the editor, run a command from
the command palette, hover with the mouse.

Why: the extension's node tests (editors/vscode/test/) drive the language server and the generator without VS
Code; only a workbench runs extension.ts, client.ts, commands.ts and settings.ts against VS Code's own API, with
the .vsix as a user installs it. VS Code's own builds cannot be downloaded here, code-server comes from the npm
registry: scripts/setup-code-server.sh installs it (run-tests' stage 1), scripts/build-vscode.sh makes the .vsix
(stage 3). Nothing is built or downloaded here, and nothing is skipped: a missing piece fails with its hint.

One code-server serves the whole module (starting it and the language server's JVM is most of the time); its
profile, settings and XDG folders live in a temporary folder, nothing under $HOME. The tests run in file order:
the last one stops code-server and checks that no language server outlives it.
"""

from __future__ import annotations

import json
import os
import secrets
import shutil
import signal
import socket
import subprocess
import tempfile
import time
import urllib.request
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import pytest
from playwright.sync_api import Browser, BrowserContext, Page

from rei import toolchain

REPO_ROOT = Path(__file__).resolve().parents[2]
EXTENSION = REPO_ROOT / "editors" / "vscode"
#: Where scripts/setup-code-server.sh installs (the same variable moves both).
CODE_SERVER_DIR = Path(os.environ.get("REI_CODE_SERVER_DIR") or EXTENSION / ".code-server")
CODE_SERVER = CODE_SERVER_DIR / "node_modules" / ".bin" / "code-server"
#: The test case with one typo; `goto F_4_0` is the floor the hover test points at.
EXAMPLE = REPO_ROOT / "examples" / "simple_navigation.rei"
TYPO = ("    object table1 : Table on F_2_1", "    object table1 : Tabel on F_2_1")
ARTIFACTS = ["animation.json", "mission.xml", "monitor.json", "world.json", "world.sdf"]
#: Screenshots left for people after each test (target/ is build output, git-ignored).
SHOTS = REPO_ROOT / "target" / "vscode-workbench"
#: Bounded waits in the page (ms). Generous: on a busy 2-core machine the language server's JVM alone may take
#: tens of seconds to start.
PAGE_TIMEOUT_MS = 90_000
PROCESS_TIMEOUT_S = 120.0
#: Settings of a quiet, predictable workbench: no welcome page, trust prompt, telemetry or update checks; no
#: auto-save, so that "Generate artifacts" has to save a modified file itself; every opened file in a tab of its
#: own (no preview tab that the next file replaces); no port forwarding of the language server's sockets; no git
#: (the workspace is no repository).
USER_SETTINGS = {
    "workbench.startupEditor": "none",
    "workbench.tips.enabled": False,
    "workbench.editor.enablePreview": False,
    "security.workspace.trust.enabled": False,
    "telemetry.telemetryLevel": "off",
    "extensions.autoCheckUpdates": False,
    "extensions.autoUpdate": False,
    "update.mode": "none",
    "files.autoSave": "off",
    "remote.autoForwardPorts": False,
    "git.enabled": False,
}
#: The workbench state the tests read: the status bar's problem counts, the Problems panel's rows (their
#: accessible labels, which spell out severity, message and position) and the editor's error squiggles.
STATE_JS = """() => ({
  status: document.querySelector("[id='status.problems'] a")?.getAttribute('aria-label') ?? null,
  statusText: document.querySelector("[id='status.problems']")?.innerText ?? null,
  rows: [...document.querySelectorAll('.markers-panel .monaco-list-row')].map(r => r.getAttribute('aria-label')),
  squiggles: document.querySelectorAll('.part.editor .monaco-editor .squiggly-error').length,
})"""
#: Centre of `word` in the first visible editor line that contains `line` (null until rendered): where a person
#: would point the mouse.
WORD_CENTRE_JS = """([line, word]) => {
  for (const view of document.querySelectorAll('.part.editor .monaco-editor .view-line')) {
    if (!view.textContent.replace(/\\u00a0/g, ' ').includes(line)) continue;
    const walker = document.createTreeWalker(view, NodeFilter.SHOW_TEXT);
    for (let node = walker.nextNode(); node; node = walker.nextNode()) {
      const at = node.textContent.indexOf(word);
      if (at < 0) continue;
      const range = document.createRange();
      range.setStart(node, at);
      range.setEnd(node, at + word.length);
      const box = range.getBoundingClientRect();
      return {x: box.x + box.width / 2, y: box.y + box.height / 2};
    }
  }
  return null;
}"""


def free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


def process_group(pgid: int) -> list[tuple[int, str]]:
    """(pid, command line) of the live processes of a process group: code-server and everything it started."""
    found = []
    for stat in Path("/proc").glob("[0-9]*/stat"):
        try:
            # The command name in parentheses may hold spaces: the fields after its closing one are fixed.
            fields = stat.read_text().rsplit(")", 1)[1].split()
            if fields[0] != "Z" and int(fields[2]) == pgid:
                cmdline = (stat.parent / "cmdline").read_bytes().replace(b"\0", b" ").decode(errors="replace")
                found.append((int(stat.parent.name), cmdline.strip()))
        except (OSError, IndexError, ValueError):
            continue
    return found


def language_servers(pgid: int) -> list[tuple[int, str]]:
    return [(pid, cmd) for pid, cmd in process_group(pgid) if "rei-language-server.jar" in cmd]


@dataclass
class Workbench:
    """code-server serving `folder`, and a logged-in chromium page showing it."""

    server: subprocess.Popen[bytes]
    folder: Path
    profile: Path
    log: Path
    tmp: Path
    context: BrowserContext
    page: Page
    stopped: bool = False
    left_over: list[tuple[int, str]] = field(default_factory=list)

    def state(self) -> dict[str, Any]:
        return self.page.evaluate(STATE_JS)

    def wait_until(self, what: str, condition: Callable[[dict[str, Any]], bool], timeout_s: float = 60.0,
                   steady_s: float = 1.5) -> dict[str, Any]:
        """Until `condition(state)` has held for `steady_s` (the Problems panel and the status bar are refreshed
        separately, and an edit passes through intermediate states); the last state."""
        deadline = time.monotonic() + timeout_s
        since = None
        while True:
            state = self.state()
            now = time.monotonic()
            if condition(state):
                since = since or now
                if now - since >= steady_s:
                    return state
            else:
                since = None
            if now > deadline:
                pytest.fail(f"{what}: not within {timeout_s} s; the workbench shows {state}", pytrace=False)
            self.page.wait_for_timeout(200)

    def open_from_explorer(self, name: str) -> None:
        """Click the file in the Explorer (the folder is open in it) and wait for its editor."""
        self.page.locator(".explorer-folders-view .monaco-list-row", has_text=name).first.click()
        self.page.wait_for_selector(f".tabs-container .tab.active[aria-label*='{name}']")
        self.page.wait_for_selector(".part.editor .monaco-editor .view-lines")

    def run_command(self, title: str) -> None:
        """Run a command from the command palette (F1), by its title as the palette lists it."""
        self.page.keyboard.press("F1")
        self.page.wait_for_selector(".quick-input-widget input")
        self.page.keyboard.type(title)
        self.page.locator(".quick-input-list .monaco-list-row", has_text=title).first.wait_for()
        self.page.keyboard.press("Enter")

    def hover(self, line: str, word: str, timeout_s: float = 60.0) -> str:
        """Point the mouse at `word` in the editor's `line` until a hover naming it shows; the hover's text."""
        at = self.word_centre(line, word)
        # Only a hover on screen: the workbench keeps a hidden one's last content.
        shown = ("() => [...document.querySelectorAll('.monaco-hover-content')]"
                 ".filter(e => e.checkVisibility()).map(e => e.innerText).join('\\n')")
        deadline = time.monotonic() + timeout_s
        while word not in (text := self.page.evaluate(shown)):
            assert time.monotonic() < deadline, f"no hover naming {word} within {timeout_s} s; shown: {text!r}"
            # Point elsewhere and back: the workbench asks the server again on the next move over the word.
            self.page.mouse.move(at["x"] - 150, at["y"] + 120)
            self.page.mouse.move(at["x"], at["y"], steps=3)
            self.page.wait_for_timeout(1500)
        self.page.mouse.move(at["x"] - 150, at["y"] + 120)
        return text

    def word_centre(self, line: str, word: str) -> dict[str, float]:
        self.page.wait_for_function(f"arg => ({WORD_CENTRE_JS})(arg) !== null", arg=[line, word])
        return self.page.evaluate(WORD_CENTRE_JS, [line, word])

    def stop(self) -> list[tuple[int, str]]:
        """Close the browser, stop code-server as a service manager would (SIGTERM to its main process), and
        return what of its process group was still alive after 20 s (then killed)."""
        if self.stopped:
            return self.left_over
        self.stopped = True
        try:
            self.context.close()
        finally:
            pgid = self.server.pid  # its own session: code-server leads its process group
            self.server.send_signal(signal.SIGTERM)
            deadline = time.monotonic() + 20.0
            while process_group(pgid) and time.monotonic() < deadline:
                time.sleep(0.2)
            self.left_over = process_group(pgid)
            if self.left_over:
                os.killpg(pgid, signal.SIGKILL)
            self.server.wait(timeout=10)
            shutil.rmtree(self.tmp, ignore_errors=True)
        return self.left_over


def find_vsix() -> Path:
    packages = sorted((EXTENSION / "dist").glob("*.vsix"), key=lambda p: p.stat().st_mtime)
    if not packages:
        pytest.fail(f"no .vsix in {EXTENSION / 'dist'}: build it with scripts/build-vscode.sh (run-tests' stage 3 "
                    "does)", pytrace=False)
    return packages[-1]


def find_code_server() -> Path:
    if not os.access(CODE_SERVER, os.X_OK):
        pytest.fail(f"{CODE_SERVER} is missing: install code-server with scripts/setup-code-server.sh (run-tests' "
                    "stage 1 does)", pytrace=False)
    return CODE_SERVER


def code_server_env(profile: Path, tmp: Path) -> dict[str, str]:
    """The test's environment with HOME and the XDG folders in the profile, TMPDIR (where VS Code puts its Unix
    sockets) in `tmp`, and without what would make code-server talk to another instance (VS Code's terminal sets
    VSCODE_IPC_HOOK_CLI) or take another password or port."""
    env = {key: value for key, value in os.environ.items()
           if not key.startswith(("VSCODE_", "CODE_SERVER_", "CS_"))
           and key not in ("PASSWORD", "HASHED_PASSWORD", "PORT", "GITHUB_TOKEN")}
    home = profile / "home"
    for key, sub in (("XDG_CONFIG_HOME", ".config"), ("XDG_DATA_HOME", ".local/share"),
                     ("XDG_CACHE_HOME", ".cache"), ("XDG_STATE_HOME", ".local/state")):
        (home / sub).mkdir(parents=True, exist_ok=True)
        env[key] = str(home / sub)
    env["HOME"] = str(home)
    env["TMPDIR"] = str(tmp)
    return env


def make_workspace(folder: Path) -> Path:
    """typo.rei: the example with one misspelt type name; lab.rei: the example as it is."""
    example = EXAMPLE.read_text(encoding="utf-8")
    assert TYPO[0] in example, f"{EXAMPLE} changed: the test's typo needs the line {TYPO[0]!r}"
    folder.mkdir()
    (folder / "typo.rei").write_text(example.replace(*TYPO), encoding="utf-8")
    (folder / "lab.rei").write_text(example, encoding="utf-8")
    return folder


def write_config(profile: Path, port: int, password: str) -> Path:
    """code-server's config: password authentication with the password in this file (0600) rather than on a
    command line that `ps` shows; bound to the loopback interface only; plain HTTP (no certificate to trust)."""
    config = profile / "config.yaml"
    config.touch(mode=0o600)
    config.write_text(f"bind-addr: 127.0.0.1:{port}\nauth: password\npassword: {password}\ncert: false\n"
                      "disable-telemetry: true\ndisable-update-check: true\ndisable-workspace-trust: true\n"
                      "disable-getting-started-override: true\n", encoding="utf-8")
    user = profile / "user-data" / "User"
    user.mkdir(parents=True)
    (user / "settings.json").write_text(json.dumps(USER_SETTINGS, indent=2), encoding="utf-8")
    return config


def wait_until_healthy(server: subprocess.Popen[bytes], base: str, log: Path, timeout_s: float = 60.0) -> None:
    deadline = time.monotonic() + timeout_s
    while True:
        if server.poll() is not None:
            pytest.fail(f"code-server exited with {server.returncode}: {log.read_text()[-2000:]}", pytrace=False)
        try:
            with urllib.request.urlopen(f"{base}/healthz", timeout=2) as response:
                if response.status == 200:
                    return
        except OSError:
            pass
        if time.monotonic() > deadline:
            pytest.fail(f"code-server did not answer {base}/healthz within {timeout_s} s: {log.read_text()[-2000:]}",
                        pytrace=False)
        time.sleep(0.3)


@pytest.fixture(scope="module")
def workbench(tmp_path_factory: pytest.TempPathFactory, browser: Browser) -> Iterator[Workbench]:
    """The session's one Playwright browser (tests/conftest.py), in a context of its own: a second Playwright
    started in the same process would refuse to run inside the first one's event loop."""
    vsix = find_vsix()
    code_server = find_code_server()
    profile = tmp_path_factory.mktemp("vscode")
    folder = make_workspace(profile / "workspace")
    port = free_port()
    password = secrets.token_urlsafe(24)
    config = write_config(profile, port, password)
    dirs = ["--config", str(config), "--user-data-dir", str(profile / "user-data"),
            "--extensions-dir", str(profile / "extensions")]
    log = profile / "code-server.log"
    # Short (a Unix socket's path is limited to 107 bytes), so not under pytest's temporary folders.
    tmp = Path(tempfile.mkdtemp(prefix="rei-vscode-"))
    env = code_server_env(profile, tmp)
    server = None
    context = None
    try:
        installed = subprocess.run([str(code_server), *dirs, "--install-extension", str(vsix)], env=env,
                                   capture_output=True, text=True, timeout=PROCESS_TIMEOUT_S,
                                   stdin=subprocess.DEVNULL, check=False)
        assert installed.returncode == 0 and "successfully installed" in installed.stdout, \
            f"installing {vsix}: {installed.stdout[-1000:]} {installed.stderr[-2000:]}"
        with log.open("wb") as out:
            # A session of its own, so that the whole tree (the extension host, the language server's JVM) can be
            # found and, should a graceful stop fail, killed by its process group.
            server = subprocess.Popen([str(code_server), *dirs, str(folder)], env=env, stdout=out,
                                      stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL, start_new_session=True)
        base = f"http://127.0.0.1:{port}"
        wait_until_healthy(server, base, log)
        context = browser.new_context(viewport={"width": 1280, "height": 800})
        page = context.new_page()
        page.set_default_timeout(PAGE_TIMEOUT_MS)
        page.goto(f"{base}/?folder={folder}")
        page.fill("input[name=password]", password)  # code-server's login page
        page.keyboard.press("Enter")
        page.wait_for_selector(".monaco-workbench .explorer-folders-view")
        bench = Workbench(server, folder, profile, log, tmp, context, page)
    except BaseException:
        if context is not None:
            context.close()
        if server is not None:
            os.killpg(server.pid, signal.SIGKILL)
            server.wait()
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    try:
        yield bench
    finally:
        stopped_by_a_test = bench.stopped
        left_over = bench.stop()
    if not stopped_by_a_test:
        assert not left_over, f"still running 20 s after code-server was told to stop (killed): {left_over}"


@pytest.fixture(autouse=True)
def screenshot(workbench: Workbench, request: pytest.FixtureRequest) -> Iterator[None]:
    """What the workbench showed at the end of each test, for whoever reads a failure."""
    yield
    if not workbench.stopped:
        SHOTS.mkdir(parents=True, exist_ok=True)
        workbench.page.screenshot(path=str(SHOTS / f"{request.node.name}.png"))


def markers(state: dict[str, Any]) -> list[str]:
    """The Problems panel's marker rows; the rows of files say 'N problems in file NAME of folder ...'."""
    return [row for row in state["rows"] if row and " problems in file " not in row]


def test_a_typo_is_one_error_on_its_line(workbench: Workbench) -> None:
    page = workbench.page
    started = time.monotonic()
    workbench.open_from_explorer("typo.rei")
    page.wait_for_selector(".part.editor .monaco-editor .squiggly-error", state="attached")
    first_diagnostic = time.monotonic() - started
    print(f"first diagnostic {first_diagnostic:.1f} s after opening typo.rei (extension activation and the "
          "language server's start included)")

    page.keyboard.press("Control+Shift+M")  # View: Problems
    page.wait_for_selector(".markers-panel")
    state = workbench.wait_until("one error in the Problems panel", lambda s: len(markers(s)) == 1)
    (marker,) = markers(state)
    assert marker.startswith("Error: ") and "'Tabel'" in marker and "at line 5 and character 21" in marker, marker
    assert state["status"] == "Errors: 1", state
    assert state["statusText"].split() == ["1", "0"], state  # 1 error, 0 warnings
    assert state["squiggles"] >= 1


def test_typing_the_fix_clears_the_problems(workbench: Workbench) -> None:
    page = workbench.page
    workbench.open_from_explorer("typo.rei")
    workbench.wait_until("the typo's error", lambda s: s["status"] == "Errors: 1", steady_s=0)
    # Select the misspelt word as a person does (double-click) and type over it.
    at = workbench.word_centre(": Tabel on", "Tabel")
    page.mouse.dblclick(at["x"], at["y"])
    page.keyboard.type("Table")
    page.keyboard.press("Escape")  # the completion list that typing opened
    page.wait_for_function(f"arg => ({WORD_CENTRE_JS})(arg) !== null", arg=[TYPO[0].strip(), "Table"])
    if not page.locator(".markers-panel").is_visible():
        page.keyboard.press("Control+Shift+M")
    state = workbench.wait_until("no problems after the fix",
                                 lambda s: s["status"] == "No Problems" and not s["rows"] and not s["squiggles"])
    assert state["statusText"].split() == ["0", "0"], state
    assert "No problems have been detected" in page.locator(".markers-panel").inner_text()
    # Only the editor changed: the file on disk still has the typo (no auto-save).
    assert TYPO[1] in (workbench.folder / "typo.rei").read_text(encoding="utf-8")


def default_generate_folder(file: Path, workspace: Path) -> Path:
    """Where the extension's declared default of `rei.generate.outputDirectory` points for `file`."""
    manifest = json.loads((EXTENSION / "package.json").read_text(encoding="utf-8"))
    template = manifest["contributes"]["configuration"]["properties"]["rei.generate.outputDirectory"]["default"]
    for name, value in (("workspaceFolder", str(workspace)), ("fileDirname", str(file.parent)),
                        ("fileBasenameNoExtension", file.stem), ("fileBasename", file.name)):
        template = template.replace("${" + name + "}", value)
    return file.parent / template


def test_generate_artifacts_from_the_command_palette(workbench: Workbench, java: toolchain.Java, cli_jar: Path,
                                                     tmp_path: Path) -> None:
    page = workbench.page
    source = workbench.folder / "lab.rei"
    workbench.open_from_explorer("lab.rei")
    # An unsaved edit: the command must save the file before the generator reads it.
    page.locator(".part.editor .monaco-editor .view-lines").first.click()
    page.keyboard.press("Control+End")
    page.keyboard.type("// saved by Generate artifacts\n")
    page.wait_for_selector(".tabs-container .tab.active.dirty")

    workbench.run_command("REI: Generate artifacts")
    expected = default_generate_folder(source, workbench.folder)
    toast = page.locator(".notifications-toasts .notification-toast", has_text="REI: wrote")
    toast.first.wait_for()
    assert f"REI: wrote 5 files to {expected}" in toast.first.inner_text()
    assert source.read_text(encoding="utf-8").endswith("// saved by Generate artifacts\n"), \
        "the command generated from the file on disk without saving the editor's edit first"
    page.wait_for_selector(".tabs-container .tab.active:not(.dirty)", timeout=10_000)

    reference = tmp_path / "reference"
    cli = subprocess.run([str(java.executable), "-jar", str(cli_jar), "generate", str(source), "-o", str(reference)],
                         capture_output=True, text=True, timeout=PROCESS_TIMEOUT_S, stdin=subprocess.DEVNULL,
                         check=False)
    assert cli.returncode == 0, cli.stderr
    assert sorted(p.name for p in expected.iterdir()) == ARTIFACTS
    assert sorted(p.name for p in reference.iterdir()) == ARTIFACTS
    for name in ARTIFACTS:
        assert (expected / name).read_bytes() == (reference / name).read_bytes(), f"{name} differs from rei-cli's"


def test_hover_over_a_floor_describes_it(workbench: Workbench) -> None:
    workbench.open_from_explorer("lab.rei")
    text = workbench.hover("goto F_4_0", "F_4_0")
    assert "Floor F_4_0" in text, text


def test_restarting_twice_in_a_row_leaves_one_new_language_server(workbench: Workbench) -> None:
    """REI: Restart language server, twice: the second comes while the first is still stopping or starting its
    server (an impatient person, or a change of rei.java.home during a restart). Exactly one server afterwards,
    a new process, and it answers."""
    (old,) = language_servers(workbench.server.pid)
    workbench.run_command("REI: Restart language server")
    workbench.run_command("REI: Restart language server")
    deadline = time.monotonic() + 60.0
    since = None
    started: set[int] = set()  # the restarts run one after the other: two new servers, the first one stopped
    while True:
        running = language_servers(workbench.server.pid)
        started.update(pid for pid, _ in running if pid != old[0])
        settled = len(running) == 1 and running != [old] and len(started) >= 2
        now = time.monotonic()
        since = (since or now) if settled else None
        if since is not None and now - since > 3.0:
            break
        assert now < deadline, (f"language servers 60 s after two restarts: {running} (before: {old}; "
                                f"new ones seen: {sorted(started)})")
        time.sleep(0.3)
    workbench.open_from_explorer("lab.rei")
    assert "Floor F_5_3" in workbench.hover("goto F_5_3", "F_5_3")
    assert language_servers(workbench.server.pid) == running


def test_stopping_code_server_ends_the_language_server(workbench: Workbench) -> None:
    running = language_servers(workbench.server.pid)
    assert len(running) == 1, f"expected the one language server of the workbench, found {running}"
    assert str(workbench.profile / "extensions") in running[0][1]  # the .vsix's own jar
    started = time.monotonic()
    left_over = workbench.stop()
    assert not left_over, f"still running 20 s after code-server was told to stop (killed): {left_over}"
    print(f"code-server and its processes ended {time.monotonic() - started:.1f} s after SIGTERM")
