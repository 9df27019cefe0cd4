# SPDX-License-Identifier: EPL-2.0
"""The language server as an editor drives it over stdio: diagnostics, completion, clean shutdown.

The small LSP client lives here, not in a conftest, because test modules must not import conftest modules
(pytest may hold several under the one name). Every wait is bounded; a server that does not stop on `exit` is
killed, so a hung JVM never outlives the test.
"""

from __future__ import annotations

import contextlib
import json
import queue
import subprocess
import threading
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import IO, Any

import pytest

from rei import toolchain

Message = dict[str, Any]

#: JVM start plus Xtext's injector on a busy 2-core machine.
START_TIMEOUT_S = 120.0
REPLY_TIMEOUT_S = 60.0


class LspClient:
    """JSON-RPC over the server's stdin/stdout with Content-Length framing; a reader thread queues every
    incoming message and another drains stderr so a chatty server never blocks on a full pipe."""

    def __init__(self, command: list[str], cwd: Path) -> None:
        self.process = subprocess.Popen(
            command, cwd=cwd, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE
        )
        self.messages: queue.Queue[Message | None] = queue.Queue()
        self.stderr_lines: list[str] = []
        self._next_id = 0
        assert self.process.stdout is not None and self.process.stderr is not None
        threading.Thread(target=self._read, args=(self.process.stdout,), daemon=True).start()
        threading.Thread(target=self._drain, args=(self.process.stderr,), daemon=True).start()

    def _read(self, stream: IO[bytes]) -> None:
        try:
            while True:
                headers: dict[str, str] = {}
                while True:
                    line = stream.readline()
                    if not line:
                        return
                    text = line.decode("ascii").strip()
                    if not text:
                        break
                    key, _, value = text.partition(":")
                    headers[key.strip().lower()] = value.strip()
                body = stream.read(int(headers["content-length"]))
                self.messages.put(json.loads(body))
        finally:
            self.messages.put(None)  # end of stream

    def _drain(self, stream: IO[bytes]) -> None:
        for line in stream:
            self.stderr_lines.append(line.decode("utf-8", "replace").rstrip())

    def _send(self, message: Message) -> None:
        assert self.process.stdin is not None
        body = json.dumps({"jsonrpc": "2.0", **message}).encode("utf-8")
        self.process.stdin.write(b"Content-Length: %d\r\n\r\n" % len(body) + body)
        self.process.stdin.flush()

    def notify(self, method: str, params: Any) -> None:
        self._send({"method": method, "params": params})

    def request(self, method: str, params: Any, timeout: float = REPLY_TIMEOUT_S) -> Any:
        """Send a request and return its result; a JSON-RPC error or no answer in time fails the test."""
        self._next_id += 1
        request_id = self._next_id
        self._send({"id": request_id, "method": method, "params": params})
        reply = self.wait_for(lambda m: m.get("id") == request_id and "method" not in m, timeout, method)
        if "error" in reply:
            pytest.fail(f"{method} failed: {reply['error']}")
        return reply.get("result")

    def wait_for(self, predicate: Callable[[Message], bool], timeout: float, what: str) -> Message:
        """The first incoming message matching `predicate`; others are dropped."""
        deadline = time.monotonic() + timeout
        while (left := deadline - time.monotonic()) > 0:
            try:
                message = self.messages.get(timeout=left)
            except queue.Empty:
                break
            if message is None:
                pytest.fail(
                    f"language server closed its output while waiting for {what}; {self.stderr_tail()}"
                )
            if message.get("method") in {"workspace/configuration", "client/registerCapability"}:
                self._send({"id": message["id"], "result": None})  # requests from the server need an answer
            if predicate(message):
                return message
        pytest.fail(f"no {what} within {timeout} s; {self.stderr_tail()}")

    def stderr_tail(self) -> str:
        return "server stderr:\n" + "\n".join(self.stderr_lines[-30:])

    def stop(self, timeout: float = 30.0) -> int:
        """shutdown + exit as an editor does; the exit code, or a test failure if the server must be killed."""
        self.request("shutdown", None, timeout)
        self.notify("exit", None)
        try:
            return self.process.wait(timeout)
        except subprocess.TimeoutExpired:
            self.kill()
            pytest.fail(f"language server still running {timeout} s after exit; {self.stderr_tail()}")

    def kill(self) -> None:
        if self.process.poll() is None:
            self.process.kill()
            self.process.wait(10)


@contextlib.contextmanager
def started(command: list[str], cwd: Path) -> Iterator[LspClient]:
    """A started (not yet initialized) language server, killed on leaving whatever happened."""
    client = LspClient(command, cwd)
    try:
        yield client
    finally:
        client.kill()
        for stream in (client.process.stdin, client.process.stdout, client.process.stderr):
            if stream is not None:
                stream.close()


@pytest.fixture
def language_server(language_server_jar: Path, java: toolchain.Java, tmp_path: Path) -> Iterator[LspClient]:
    """A started (not yet initialized) language server with a workspace folder in `tmp_path`; killed after
    the test whatever happened."""
    with started(toolchain.jar_command(language_server_jar, [], java), tmp_path) as client:
        yield client


BROKEN_LINE = 3  # 1-based: the object stands on a floor the 3 x 2 grid does not have
TEXT = """\
testcase Editing {
  room Lab size 3 x 2 {
    object table1 : Table on F_7_7
    robot tb3 : Waffle on F_0_0
  }
  mission Go { goto F_2_1 goto F_0_1 }
}
"""
FLOORS = {f"F_{x}_{y}" for x in range(3) for y in range(2)}


def labels(result: Any) -> list[str]:
    items = result["items"] if isinstance(result, dict) else result
    return [item["label"] for item in items]


def published_errors(client: LspClient, name: str) -> list[Message]:
    """The errors of the first non-empty diagnostics the server publishes for the file called `name`."""
    published = client.wait_for(
        lambda m: (
            m.get("method") == "textDocument/publishDiagnostics"
            and m["params"]["uri"].endswith("/" + name)
            and m["params"]["diagnostics"]
        ),
        START_TIMEOUT_S,
        f"diagnostics for {name}",
    )
    return [d for d in published["params"]["diagnostics"] if d.get("severity") == 1]


def test_diagnostics_completion_and_clean_exit(language_server: LspClient, tmp_path: Path) -> None:
    path = tmp_path / "editing.rei"
    path.write_text(TEXT, encoding="utf-8")
    uri = path.as_uri()

    result = language_server.request(
        "initialize",
        {"processId": None, "rootUri": tmp_path.as_uri(), "capabilities": {}},
        timeout=START_TIMEOUT_S,
    )
    assert "completionProvider" in result["capabilities"]
    language_server.notify("initialized", {})
    language_server.notify(
        "textDocument/didOpen",
        {"textDocument": {"uri": uri, "languageId": "rei", "version": 1, "text": TEXT}},
    )

    errors = published_errors(language_server, "editing.rei")
    assert [d["range"]["start"]["line"] for d in errors] == [BROKEN_LINE - 1], errors
    assert "F_7_7" in errors[0]["message"]

    line = TEXT.splitlines()[BROKEN_LINE - 1]
    after_on = line.index(" on ") + len(" on ")
    completion = language_server.request(
        "textDocument/completion",
        {"textDocument": {"uri": uri}, "position": {"line": BROKEN_LINE - 1, "character": after_on}},
    )
    offered = {label.rsplit(".", 1)[-1] for label in labels(completion)}
    assert offered >= FLOORS, f"floors missing from completion: {sorted(FLOORS - offered)}"
    assert "table1" not in offered and "tb3" not in offered, "only floors stand after 'on'"

    assert language_server.stop() == 0


def test_a_server_whose_editor_went_away_without_exit_ends_by_itself(
    language_server: LspClient, tmp_path: Path
) -> None:
    """An editor that crashes closes the server's stdin without shutdown/exit: the server must not live on."""
    language_server.request(
        "initialize",
        {"processId": None, "rootUri": tmp_path.as_uri(), "capabilities": {}},
        timeout=START_TIMEOUT_S,
    )
    language_server.notify("initialized", {})
    assert language_server.process.stdin is not None
    language_server.process.stdin.close()
    try:
        # Xtext's launcher looks at its input every 10 s
        assert language_server.process.wait(30) == 0
    except subprocess.TimeoutExpired:
        pytest.fail(f"language server still running 30 s after its stdin closed; {language_server.stderr_tail()}")


@pytest.mark.parametrize("folders_capability", [False, True], ids=["plain", "workspaceFolders-capable"])
def test_a_client_sending_only_workspace_folders_gets_them_as_the_root(
    language_server: LspClient, tmp_path: Path, folders_capability: bool
) -> None:
    """No rootUri and no rootPath: Xtext alone fails `initialize` unless the client also declares the
    workspaceFolders capability. The folder is the root: a file in it that the client never opens is checked too
    (the initial build's diagnostics come before those of the opened file's build)."""
    (tmp_path / "editing.rei").write_text(TEXT, encoding="utf-8")
    (tmp_path / "unopened.rei").write_text(TEXT, encoding="utf-8")
    capabilities = {"workspace": {"workspaceFolders": True}} if folders_capability else {}
    result = language_server.request(
        "initialize",
        {
            "processId": None,
            "workspaceFolders": [{"uri": tmp_path.as_uri(), "name": "lab"}],
            "capabilities": capabilities,
        },
        timeout=START_TIMEOUT_S,
    )
    assert "completionProvider" in result["capabilities"]
    language_server.notify("initialized", {})
    opened = {"uri": (tmp_path / "editing.rei").as_uri(), "languageId": "rei", "version": 1, "text": TEXT}
    language_server.notify("textDocument/didOpen", {"textDocument": opened})
    for name in ("unopened.rei", "editing.rei"):
        errors = published_errors(language_server, name)
        assert [d["range"]["start"]["line"] for d in errors] == [BROKEN_LINE - 1], (name, errors)
    assert language_server.stop() == 0


CATALOGUE_TEXT = """\
catalogue Lab {
  type Sofa : object box 1.1 x 0.8 x 0.8 mass 40
}
"""
IMPORTING_BROKEN_LINE = 6  # 1-based; the lines above use the imported catalogue's Sofa
IMPORTING_TEXT = """\
import "catalogues/lab.rei"

testcase Imported {
  room Lab size 3 x 2 {
    object sofa : Sofa on F_1_0
    object table1 : Table on F_7_7
    robot tb3 : Waffle on F_0_0
  }
  mission Go { goto F_2_1 goto F_0_1 }
}
"""


@pytest.mark.parametrize("folders_capability", [False, True], ids=["plain", "workspaceFolders-capable"])
def test_without_any_root_a_file_anywhere_is_checked_with_its_imports_and_no_temporary_root_remains(
    language_server_jar: Path, java: toolchain.Java, tmp_path: Path, folders_capability: bool
) -> None:
    """No root at all, as VS Code sends (declaring workspaceFolders) for a file opened without a folder. The server
    makes an empty root of its own in the JVM's temporary directory (here one the test watches), checks the file
    where it is, its catalogue import resolved beside it, and deletes that root on exit."""
    jvm_tmp = tmp_path / "jvm-tmp"
    jvm_tmp.mkdir()
    files = tmp_path / "anywhere"
    (files / "catalogues").mkdir(parents=True)
    (files / "catalogues" / "lab.rei").write_text(CATALOGUE_TEXT, encoding="utf-8")
    path = files / "imported.rei"
    path.write_text(IMPORTING_TEXT, encoding="utf-8")
    command = toolchain.jar_command(language_server_jar, [], java)
    command[1:1] = [f"-Djava.io.tmpdir={jvm_tmp}"]

    with started(command, tmp_path) as server:
        result = server.request(
            "initialize",
            {
                "processId": None,
                "rootPath": None,
                "rootUri": None,
                "workspaceFolders": None,
                "capabilities": {"workspace": {"workspaceFolders": True}} if folders_capability else {},
            },
            timeout=START_TIMEOUT_S,
        )
        assert "completionProvider" in result["capabilities"]
        roots = list(jvm_tmp.glob("rei-language-server-*"))
        assert len(roots) == 1 and roots[0].is_dir() and not any(roots[0].iterdir()), roots
        server.notify("initialized", {})
        opened = {"uri": path.as_uri(), "languageId": "rei", "version": 1, "text": IMPORTING_TEXT}
        server.notify("textDocument/didOpen", {"textDocument": opened})
        errors = published_errors(server, "imported.rei")
        assert [d["range"]["start"]["line"] for d in errors] == [IMPORTING_BROKEN_LINE - 1], errors
        assert "F_7_7" in errors[0]["message"]
        assert server.stop() == 0
    assert not list(jvm_tmp.glob("rei-language-server-*")), "the server left its temporary root behind"


HOVER_TEXT = """\
testcase Hovering {
  room Lab size 3 x 2 {
    object table1 : Table on F_1_0
    robot tb3 : Waffle on F_0_0
  }
  mission Go { goto F_2_1 }
  monitor { close 0.3 collision 0.02 maxHumanCollisions 2 }
}
"""


def test_hover_tells_where_a_floor_is_what_a_type_measures_and_what_the_thresholds_mean(
    language_server: LspClient, tmp_path: Path
) -> None:
    path = tmp_path / "hovering.rei"
    path.write_text(HOVER_TEXT, encoding="utf-8")
    uri = path.as_uri()
    language_server.request("initialize", {"processId": None, "rootUri": tmp_path.as_uri(), "capabilities": {}},
                            timeout=START_TIMEOUT_S)
    language_server.notify("initialized", {})
    language_server.notify("textDocument/didOpen",
                           {"textDocument": {"uri": uri, "languageId": "rei", "version": 1, "text": HOVER_TEXT}})
    lines = HOVER_TEXT.splitlines()

    def hover(line: int, word: str) -> str:
        character = lines[line].index(word) + 1
        result = language_server.request("textDocument/hover", {"textDocument": {"uri": uri},
                                                                "position": {"line": line, "character": character}},
                                          timeout=START_TIMEOUT_S)
        assert result is not None, f"no hover on {word!r}"
        contents = result["contents"]
        return contents["value"] if isinstance(contents, dict) else str(contents)

    assert "x 2..3 m, y 1..2 m, centre (2.50, 1.50)" in hover(5, "F_2_1")
    table = hover(2, "Table")
    assert "Table" in table and "1.2 x 0.8 x 0.75 m" in table and "20 kg" in table, table
    waffle = hover(3, "Waffle")
    assert "rad/s" in waffle and "lidar" in waffle, waffle
    thresholds = hover(6, "close")
    assert "below `close` 0.3 m" in thresholds and "below `collision` 0.02 m" in thresholds, thresholds
    assert language_server.stop() == 0


def test_a_person_on_a_route_is_hovered_outlined_and_checked(
    language_server: LspClient, tmp_path: Path, repo_root: Path
) -> None:
    """A human who walks a route (docs/language.md, people who see the robot): its hover says where it goes and
    how it behaves, the outline lists it as it lists a human on rails, and its file is clean."""
    text = (repo_root / "examples" / "people" / "reactive_crossing.rei").read_text(encoding="utf-8")
    path = tmp_path / "reactive_crossing.rei"
    path.write_text(text, encoding="utf-8")
    uri = path.as_uri()
    language_server.request("initialize", {"processId": None, "rootUri": tmp_path.as_uri(), "capabilities": {}},
                            timeout=START_TIMEOUT_S)
    language_server.notify("initialized", {})
    language_server.notify("textDocument/didOpen",
                           {"textDocument": {"uri": uri, "languageId": "rei", "version": 1, "text": text}})
    published = language_server.wait_for(
        lambda m: m.get("method") == "textDocument/publishDiagnostics" and m["params"]["uri"] == uri,
        START_TIMEOUT_S, f"diagnostics for {path.name}")
    assert published["params"]["diagnostics"] == []
    line = next(i for i, s in enumerate(text.splitlines()) if "human ann" in s)
    result = language_server.request("textDocument/hover", {
        "textDocument": {"uri": uri},
        "position": {"line": line, "character": text.splitlines()[line].index("ann") + 1}}, timeout=START_TIMEOUT_S)
    hover = result["contents"]["value"] if isinstance(result["contents"], dict) else str(result["contents"])
    assert hover.startswith("**Human ann**, walking a route at 1.1 m/s in a loop; avoids:"), hover
    assert "- F_3_0, waits 2 s: x 3..4 m, y 0..1 m, centre (3.50, 0.50)" in hover, hover
    symbols = language_server.request("textDocument/documentSymbol", {"textDocument": {"uri": uri}},
                                      timeout=START_TIMEOUT_S)

    def names(items: list[Message]) -> list[str]:
        return [n for s in items for n in [s["name"].rsplit(".", 1)[-1], *names(s.get("children") or [])]]

    assert {"ann", "bob", "tb3", "table1"} <= set(names(symbols)), names(symbols)
    assert language_server.stop() == 0


def test_a_crowd_and_a_group_are_hovered_outlined_and_checked(
    language_server: LspClient, tmp_path: Path, repo_root: Path
) -> None:
    """A crowd and a group (docs/language.md, crowds and groups), in the example as written: its file is clean, the
    crowd's hover says who its people are, how fast and when they set off and between which floors, the group's
    who leads, and the outline lists both as it lists everything named in the room."""
    text = (repo_root / "examples" / "people" / "crowds.rei").read_text(encoding="utf-8")
    path = tmp_path / "crowds.rei"
    path.write_text(text, encoding="utf-8")
    uri = path.as_uri()
    language_server.request("initialize", {"processId": None, "rootUri": tmp_path.as_uri(), "capabilities": {}},
                            timeout=START_TIMEOUT_S)
    language_server.notify("initialized", {})
    language_server.notify("textDocument/didOpen",
                           {"textDocument": {"uri": uri, "languageId": "rei", "version": 1, "text": text}})
    published = language_server.wait_for(
        lambda m: m.get("method") == "textDocument/publishDiagnostics" and m["params"]["uri"] == uri,
        START_TIMEOUT_S, f"diagnostics for {path.name}")
    assert published["params"]["diagnostics"] == []
    lines = text.splitlines()

    def hover(statement: str, word: str) -> str:
        line = next(i for i, s in enumerate(lines) if statement in s)
        result = language_server.request("textDocument/hover", {
            "textDocument": {"uri": uri},
            "position": {"line": line, "character": lines[line].index(word) + 1}}, timeout=START_TIMEOUT_S)
        assert result is not None, f"no hover on {word!r}"
        return result["contents"]["value"] if isinstance(result["contents"], dict) else str(result["contents"])

    crowd = hover("crowd shoppers", "shoppers")
    assert crowd.startswith("**Crowd shoppers**, 12 people (shoppers_1 to shoppers_12) walking at 1-1.4 m/s, "
                            "setting off 1 a second from 0 s, back and forth; avoids:"), crowd
    assert "\n- from F_0_2, F_0_3, F_0_4, F_0_5, F_1_2, F_1_3, F_1_4, F_1_5\n- to F_12_2, " in crowd, crowd
    group = hover("group family", "family")
    assert group.startswith("**Group family**, 3 people (family_1 leads, family_2 and family_3 keep near it), "
                            "walking a route at 1-1.2 m/s in a loop; avoids:"), group
    assert "- F_5_6, waits 2 s: x 5..6 m, y 6..7 m" in group, group
    symbols = language_server.request("textDocument/documentSymbol", {"textDocument": {"uri": uri}},
                                      timeout=START_TIMEOUT_S)

    def names(items: list[Message]) -> list[str]:
        return [n for s in items for n in [s["name"].rsplit(".", 1)[-1], *names(s.get("children") or [])]]

    assert {"shoppers", "family", "tb3", "table1"} <= set(names(symbols)), names(symbols)
    assert language_server.stop() == 0


VEPL_TEXT = """\
queryEvent closeFound as robotClose found
queryEvent thesisFar() as findFarObject found
atomicEvent taskStarted as mission TASK_START
complexEvent closeDuringTask() { as taskStarted -> closeFound }
signal SIG_CLOSE_IN_TASK utility -2 transition geometry FAR -> CLOSE
rule closeInTask on closeDuringTask emits SIG_CLOSE_IN_TASK
rule farAgain on thesisFar emits SIG_CLOSE_IN_TASK
"""


def test_the_same_server_hovers_vepl_events_and_signals_with_their_definitions(
    language_server: LspClient, tmp_path: Path
) -> None:
    path = tmp_path / "patterns.vepl"
    path.write_text(VEPL_TEXT, encoding="utf-8")
    uri = path.as_uri()
    language_server.request("initialize", {"processId": None, "rootUri": tmp_path.as_uri(), "capabilities": {}},
                            timeout=START_TIMEOUT_S)
    language_server.notify("initialized", {})
    language_server.notify("textDocument/didOpen",
                           {"textDocument": {"uri": uri, "languageId": "vepl", "version": 1, "text": VEPL_TEXT}})
    lines = VEPL_TEXT.splitlines()

    def hover(line: int, word: str, occurrence: int = 0) -> str:
        start = -1
        for _ in range(occurrence + 1):
            start = lines[line].index(word, start + 1)
        result = language_server.request("textDocument/hover", {"textDocument": {"uri": uri},
                                                                "position": {"line": line, "character": start + 1}},
                                          timeout=START_TIMEOUT_S)
        assert result is not None, f"no hover on {word!r}"
        contents = result["contents"]
        return contents["value"] if isinstance(contents, dict) else str(contents)

    # on a use of an event, its declaration as written
    used = hover(3, "closeFound")
    assert "Query event closeFound" in used and "`robotClose` appears" in used, used
    assert "queryEvent closeFound as robotClose found" in used, used
    assert "the mission topic's `TASK_START` event" in hover(3, "taskStarted")
    assert "{ as taskStarted -> closeFound }" in hover(5, "closeDuringTask")
    assert "the thesis's name of REI's `robotFar`" in hover(6, "thesisFar")
    signal = hover(5, "SIG_CLOSE_IN_TASK")
    assert "utility -2.0" in signal and "robot's zone by geometry goes from FAR to CLOSE" in signal, signal
    assert language_server.stop() == 0


UNKNOWN_QUERY_LINE = 2  # 1-based: a query neither the defaults nor the user declares
OUTSIDE_TEXT = """\
queryEvent closeFound as robotClose found
queryEvent nearFound as robotNear found
queryEvent another as \n"""


def test_a_vepl_file_outside_the_repository_knows_the_default_queries(
    language_server: LspClient, tmp_path: Path
) -> None:
    """A user's workspace has no queries/ folder above it: the server still knows the queries the monitor always
    loads (packaged in the jar), as it checks them and offers them."""
    assert not any((d / "queries").is_dir() for d in (tmp_path, *tmp_path.parents)), "queries/ above tmp_path"
    path = tmp_path / "mine.vepl"
    path.write_text(OUTSIDE_TEXT, encoding="utf-8")
    uri = path.as_uri()
    language_server.request("initialize", {"processId": None, "rootUri": tmp_path.as_uri(), "capabilities": {}},
                            timeout=START_TIMEOUT_S)
    language_server.notify("initialized", {})
    language_server.notify("textDocument/didOpen",
                           {"textDocument": {"uri": uri, "languageId": "vepl", "version": 1, "text": OUTSIDE_TEXT}})

    published = language_server.wait_for(
        lambda m: (
            m.get("method") == "textDocument/publishDiagnostics"
            and m["params"]["uri"].endswith("/mine.vepl")
            and m["params"]["diagnostics"]
        ),
        START_TIMEOUT_S,
        "diagnostics for mine.vepl",
    )
    unknown = [d for d in published["params"]["diagnostics"] if d.get("code") == "org.rei.vepl.unknownQuery"]
    assert [d["range"]["start"]["line"] for d in unknown] == [UNKNOWN_QUERY_LINE - 1], published
    assert "'robotNear'" in unknown[0]["message"] and "robotClose" in unknown[0]["message"], unknown

    last = OUTSIDE_TEXT.splitlines()[-1]
    completion = language_server.request(
        "textDocument/completion",
        {"textDocument": {"uri": uri}, "position": {"line": 2, "character": last.index(" as ") + len(" as ")}},
    )
    assert "robotClose" in labels(completion)
    assert language_server.stop() == 0


#: Far deeper than VEPL's limit of 100 levels; the parser would recurse once per bracket.
DEEP = 3_000
DEEP_HEAD = "/* ((((( */ complexEvent c() { as "
#: Each a file on line 2 (0-based 1) nested too deep, and the 0-based column of the token refused: the complex
#: event's brace is level 1, so the 100th '(' is one level too many; the 201st operator is one too many, since a
#: chain of operators is one level of the model per operator.
TOO_DEEP = {
    "deep.vepl": (DEEP_HEAD + "(" * DEEP + "a" + ")" * DEEP + " }\n", len(DEEP_HEAD) + 99),
    "unbalanced.vepl": ("complexEvent c() { as " + "(" * DEEP + "\n", len("complexEvent c() { as ") + 99),
    "chain.vepl": ("complexEvent c() { as a" + " -> a" * 20_000 + " }\n", len("complexEvent c() { as a") + 200 * 5 + 1),
}
#: Diagnostics of a too-deep file, measured from its didOpen once the server has checked a first file.
DEEP_DIAGNOSTICS_S = 2.0


def vepl_diagnostics(client: LspClient, uri: str, timeout: float) -> list[Message]:
    published = client.wait_for(
        lambda m: m.get("method") == "textDocument/publishDiagnostics" and m["params"]["uri"] == uri,
        timeout,
        f"diagnostics for {uri}",
    )
    return published["params"]["diagnostics"]


def test_a_vepl_file_nested_too_deep_gets_its_diagnostic_at_once_and_the_server_keeps_checking(
    language_server: LspClient, tmp_path: Path
) -> None:
    """3,000 levels of brackets, balanced or not, and a chain of 20,000 operators: one error on the first bracket or
    operator beyond the limit within 2 s, then the next file opened is checked as always (the parser, or scoping,
    used to overflow its stack, and the server then checked nothing more)."""
    warm = tmp_path / "warm.vepl"  # the server checks it while starting: the VEPL checker is loaded after that
    warm.write_text(OUTSIDE_TEXT, encoding="utf-8")
    language_server.request("initialize", {"processId": None, "rootUri": tmp_path.as_uri(), "capabilities": {}},
                            timeout=START_TIMEOUT_S)
    language_server.notify("initialized", {})
    assert vepl_diagnostics(language_server, warm.as_uri(), START_TIMEOUT_S), "no diagnostics for warm.vepl"

    for name, (text, column) in TOO_DEEP.items():
        uri = (tmp_path / name).as_uri()
        started = time.monotonic()
        language_server.notify("textDocument/didOpen", {"textDocument": {
            "uri": uri, "languageId": "vepl", "version": 1, "text": "queryEvent a as robotFar found\n" + text}})
        diagnostics = vepl_diagnostics(language_server, uri, START_TIMEOUT_S)
        took = time.monotonic() - started
        print(f"{name}: diagnostics {took:.3f} s after didOpen")
        assert took < DEEP_DIAGNOSTICS_S, f"{name}: diagnostics after {took:.2f} s"
        assert [(d["code"], d["range"]["start"], d["range"]["end"]["line"]) for d in diagnostics] == [
            ("org.rei.vepl.tooDeep", {"line": 1, "character": column}, 1)], diagnostics
        assert "the file is not parsed" in diagnostics[0]["message"]

    path = tmp_path / "next.vepl"
    language_server.notify("textDocument/didOpen", {"textDocument": {
        "uri": path.as_uri(), "languageId": "vepl", "version": 1, "text": OUTSIDE_TEXT}})
    unknown = [d for d in vepl_diagnostics(language_server, path.as_uri(), REPLY_TIMEOUT_S)
               if d.get("code") == "org.rei.vepl.unknownQuery"]
    assert [d["range"]["start"]["line"] for d in unknown] == [UNKNOWN_QUERY_LINE - 1], unknown
    assert language_server.stop() == 0


def test_a_floor_size_typed_on_the_way_to_another_is_a_diagnostic_on_the_number_and_the_server_lives_on(
    language_server: LspClient, tmp_path: Path, repo_root: Path
) -> None:
    """examples/maps/two_rooms.rei (10 x 6 m of 0.05 m cells) while its user retypes `floorSize 0.5` as `0.05`:
    on the way it reads `0.0000001`, which would cut the map into 6 * 10^15 blocks. That is one error on the number
    (the block count once overflowed an int and the server's check died with it), then the text goes on being
    checked, and the server ends cleanly."""
    for name in ("two_rooms.yaml", "two_rooms.pgm"):
        (tmp_path / name).write_bytes((repo_root / "examples" / "maps" / name).read_bytes())
    source = (repo_root / "examples" / "maps" / "two_rooms.rei").read_text(encoding="utf-8")
    path = tmp_path / "two_rooms.rei"
    path.write_text(source, encoding="utf-8")
    uri = path.as_uri()
    language_server.request("initialize", {"processId": None, "rootUri": tmp_path.as_uri(), "capabilities": {}},
                            timeout=START_TIMEOUT_S)
    language_server.notify("initialized", {})
    language_server.notify("textDocument/didOpen",
                           {"textDocument": {"uri": uri, "languageId": "rei", "version": 1, "text": source}})

    def published(version: int, floor_size: str, wanted: Callable[[list[Message]], bool]) -> list[Message]:
        if version > 1:
            language_server.notify("textDocument/didChange", {
                "textDocument": {"uri": uri, "version": version},
                "contentChanges": [{"text": source.replace("floorSize 0.5", f"floorSize {floor_size}")}]})
        message = language_server.wait_for(
            lambda m: (m.get("method") == "textDocument/publishDiagnostics" and m["params"]["uri"] == uri
                       and wanted(m["params"]["diagnostics"])),
            START_TIMEOUT_S, f"diagnostics of two_rooms.rei with floorSize {floor_size}")
        return message["params"]["diagnostics"]

    def too_large(diagnostics: list[Message]) -> list[Message]:
        return [d for d in diagnostics if d.get("code") == "org.rei.dsl.roomTooLarge"]

    assert published(1, "0.5", lambda d: not d) == []
    line = source.splitlines().index('  room Office occupancy "two_rooms.yaml" floorSize 0.5 {')
    typing = published(2, "0.0000001", too_large)
    assert [(d["range"]["start"], d["severity"]) for d in typing] == [
        ({"line": line, "character": len('  room Office occupancy "two_rooms.yaml" floorSize ')}, 1)], typing
    assert typing[0]["message"].startswith("floorSize 0.0000001 m cuts the map two_rooms.yaml (200 x 120 cells of "
                                           "0.05 m) into 100000000 x 60000000 blocks"), typing
    assert not too_large(published(3, "0.05", lambda d: not too_large(d)))
    assert published(4, "0.5", lambda d: not d) == []
    assert language_server.stop() == 0
