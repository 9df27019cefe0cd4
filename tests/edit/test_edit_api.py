# SPDX-License-Identifier: EPL-2.0
"""The room editor's HTTP API against a real edit engine: who may call it, what a save writes, what a change on
disk does, and that a broken engine or a bad request never ends the editor (docs/room-editor.md)."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import time
import urllib.request
from pathlib import Path
from urllib.parse import parse_qs, urlsplit

from edit_helpers import Editor, write_as_another_program

from rei.edit import TOKEN_HEADER

CASE = "examples/simple_navigation.rei"
MOVE = {"op": "moveObject", "name": "table1", "floor": "F_3_3"}


def test_api_needs_the_token_and_the_editors_own_origin(open_editor) -> None:
    editor: Editor = open_editor(CASE)
    port = editor.server.port
    assert editor.call("GET", "/api/state", headers={})[0] == 403
    assert editor.call("GET", "/api/state", headers={TOKEN_HEADER: "guess"})[0] == 403
    good = {TOKEN_HEADER: editor.server.token}
    status, answer = editor.call("POST", "/api/apply", {"operations": [MOVE]},
                                 headers={**good, "Origin": "http://evil.example"})
    assert status == 403 and "origin" in answer["error"]
    assert editor.call("GET", "/api/state", headers={**good, "Origin": f"http://127.0.0.1:{port + 1}"})[0] == 403
    assert editor.call("GET", "/api/state", headers={**good, "Host": f"rebound.example:{port}"})[0] == 403
    assert editor.session.state()["canUndo"] is False, "a refused request changed the model"
    assert editor.call("GET", "/api/state", headers={**good, "Origin": f"http://127.0.0.1:{port}"})[0] == 200
    assert editor.server.url.startswith(f"http://127.0.0.1:{port}/edit.html?token=")
    # Static files carry no secret; nothing outside the built page is served.
    assert editor.call("GET", "/api/../../../etc/passwd", headers={})[0] in (403, 404)
    status, _ = editor.call("GET", "/..%2F..%2Fpyproject.toml", headers={})
    assert status == 404


def test_state_shows_the_room_and_a_move_is_saved_as_a_one_line_change(open_editor, run_cli) -> None:
    editor: Editor = open_editor(CASE)
    before = editor.case.read_text(encoding="utf-8")
    state = editor.ok("GET", "/api/state")
    assert state["text"] == before and state["dirty"] is False
    diagram = state["diagram"]
    assert diagram["room"]["form"] == "grid" and len(diagram["room"]["floors"]) == 24
    assert {o["name"] for o in diagram["objects"]} == {"table1", "shelf1"}
    assert diagram["robot"]["name"] == "tb3"
    assert [g["floor"] for g in diagram["mission"]["goals"]] == ["F_4_0", "F_5_3"]
    assert diagram["monitor"] == {"close": 0.25, "collision": 0.01, "maxHumanCollisions": 1}
    assert {"Table", "Shelf", "Waffle"} <= {t["name"] for t in state["palette"]}

    moved = editor.apply(MOVE)
    assert moved["dirty"] is True and moved["canUndo"] is True and moved["version"] > state["version"]
    assert editor.case.read_text(encoding="utf-8") == before, "an edit wrote the file before Save"
    saved = editor.ok("POST", "/api/save", {})
    assert saved["dirty"] is False
    after = editor.case.read_text(encoding="utf-8")
    assert after == before.replace("object table1 : Table on F_2_1", "object table1 : Table on F_3_3")
    assert run_cli("validate", editor.case).returncode == 0

    assert editor.ok("POST", "/api/undo", {})["dirty"] is True
    assert editor.ok("POST", "/api/redo", {})["dirty"] is False
    status, answer = editor.call("POST", "/api/redo", {})
    assert status == 409 and "redo" in answer["error"]


def test_refused_operations_and_bad_requests_change_nothing(open_editor) -> None:
    editor: Editor = open_editor(CASE)
    version = editor.ok("GET", "/api/status")["version"]
    status, answer = editor.call("POST", "/api/apply", {"operations": [{**MOVE, "floor": "F_9_9"}]})
    assert status == 422 and "F_9_9" in answer["error"]
    status, answer = editor.call("POST", "/api/apply", {"operations": [{"op": "teleport", "name": "table1"}]})
    assert status == 422 and "teleport" in answer["error"]
    assert editor.call("POST", "/api/apply", raw=b"{not json")[0] == 400
    assert editor.call("POST", "/api/apply", {"operations": []})[0] == 400
    assert editor.call("POST", "/api/apply", ["a list"])[0] == 400
    assert editor.call("POST", "/api/nothing", {})[0] == 404
    status = editor.ok("GET", "/api/status")
    assert status["version"] == version and status["canUndo"] is False
    assert editor.apply(MOVE)["canUndo"] is True, "the editor stopped working after bad requests"


def test_an_internal_failure_of_the_engine_is_shown_as_such_not_as_a_refusal(open_editor) -> None:
    editor: Editor = open_editor(CASE)
    # a yaw the grammar cannot write: the engine's read-back check fails inside it (the edit is not refused)
    status, answer = editor.call("POST", "/api/apply", {"operations": [
        {"op": "rotateObject", "name": "table1", "yawDegrees": 1e300}]})
    assert status == 500 and answer["kind"] == "internal", answer
    assert answer["error"].startswith("Internal failure of the room editor, not a fault of your edit"), answer
    assert "does not read back" in answer["error"], answer
    status, answer = editor.call("POST", "/api/apply", {"operations": [{**MOVE, "floor": "F_9_9"}]})
    assert status == 422 and "kind" not in answer and "Internal" not in answer["error"], answer
    assert editor.apply(MOVE)["canUndo"] is True


def test_a_change_on_disk_is_followed_without_unsaved_edits_and_asked_about_with_them(open_editor) -> None:
    editor: Editor = open_editor(CASE)
    text = editor.case.read_text(encoding="utf-8")
    write_as_another_program(editor.case, text.replace("close 0.25", "close 0.3"))
    state = editor.ok("GET", "/api/state")
    assert state["diagram"]["monitor"]["close"] == 0.3 and state["dirty"] is False
    assert state["diskChanged"] is False and "changed on disk" in state["notice"]

    edited = editor.apply(MOVE)["text"]
    theirs = text.replace("close 0.25", "close 0.4")
    write_as_another_program(editor.case, theirs)
    status = editor.ok("GET", "/api/status")
    assert status["diskChanged"] is True and status["dirty"] is True
    code, answer = editor.call("POST", "/api/save", {})
    assert code == 409 and "changed on disk" in answer["error"]
    assert editor.case.read_text(encoding="utf-8") == theirs, "a save overwrote the other version unasked"

    kept = editor.ok("POST", "/api/keep", {})
    assert kept["diskChanged"] is False and kept["dirty"] is True and kept["text"] == edited
    editor.ok("POST", "/api/save", {})
    assert editor.case.read_text(encoding="utf-8") == edited

    write_as_another_program(editor.case, theirs)
    editor.apply({**MOVE, "floor": "F_3_2"})
    assert editor.ok("GET", "/api/status")["diskChanged"] is True
    reloaded = editor.ok("POST", "/api/reload", {})
    assert reloaded["text"] == theirs and reloaded["dirty"] is False and reloaded["canUndo"] is False


def test_a_killed_or_hung_engine_is_replaced_and_keeps_the_edits(open_editor) -> None:
    editor: Editor = open_editor(CASE, timeout=20)
    edited = editor.apply(MOVE)["text"]
    _signal_engine(editor, signal.SIGKILL)
    state = editor.ok("GET", "/api/state")  # answered from what the server holds
    moved = editor.apply({"op": "rotateObject", "name": "table1", "yawDegrees": 90})
    assert "object table1 : Table on F_3_3 yaw 90" in moved["text"]
    assert moved["text"].replace(" yaw 90", "") == edited
    assert "started again" in moved["notice"] and editor.ok("GET", "/api/state")["notice"] is None
    assert state["dirty"] is True

    _signal_engine(editor, signal.SIGSTOP)  # hangs
    started = time.monotonic()
    status, answer = editor.call("POST", "/api/apply", {"operations": [{**MOVE, "floor": "F_3_2"}]})
    assert status == 500 and "did not answer" in answer["error"]
    assert time.monotonic() - started < 60
    again = editor.apply({**MOVE, "floor": "F_3_2"})
    assert "object table1 : Table on F_3_2 yaw 90" in again["text"]


def _start_rei_edit(rei_script: Path, tmp_path: Path) -> tuple[Path, subprocess.Popen[str], str]:
    """`rei edit` on a copy of CASE, once it printed its URL: the copy, the process and that line."""
    case = tmp_path / "case.rei"
    case.write_text((Path(__file__).parents[2] / CASE).read_text(encoding="utf-8"), encoding="utf-8")
    process = subprocess.Popen([str(rei_script), "edit", str(case)], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True)
    assert process.stdout is not None
    line = process.stdout.readline()
    if not line.startswith("edit: http://127.0.0.1:"):
        process.kill()
        process.wait()
    assert line.startswith("edit: http://127.0.0.1:"), line
    return case, process, line


def test_rei_edit_keeps_unsaved_edits_when_stopped(rei_script: Path, tmp_path: Path) -> None:
    case, process, line = _start_rei_edit(rei_script, tmp_path)
    try:
        url = urlsplit(line.split()[1])
        request = urllib.request.Request(
            f"http://{url.netloc}/api/apply", method="POST", data=json.dumps({"operations": [MOVE]}).encode(),
            headers={TOKEN_HEADER: parse_qs(url.query)["token"][0], "Content-Type": "application/json"})
        with urllib.request.urlopen(request, timeout=120) as answer:
            assert json.loads(answer.read())["dirty"] is True
        process.send_signal(signal.SIGINT)
        out, err = process.communicate(timeout=60)
    finally:
        if process.poll() is None:
            process.kill()
            process.wait()
    assert process.returncode == 0, err
    rescue = tmp_path / "case.rei.unsaved"
    assert f"they are in {rescue}" in out
    assert "on F_3_3" in rescue.read_text(encoding="utf-8")
    assert "on F_2_1" in case.read_text(encoding="utf-8"), "stopping the editor saved unasked"


def test_rei_edit_stops_on_a_ctrl_c_that_lands_on_another_thread(rei_script: Path, tmp_path: Path) -> None:
    """The kernel hands a process's signal to any of its threads; one that lands on a server thread must stop
    the editor too (a main thread blocked in a wait without timeout never saw it: the editor ran on)."""
    _, process, _ = _start_rei_edit(rei_script, tmp_path)
    try:
        others = [int(tid) for tid in os.listdir(f"/proc/{process.pid}/task") if int(tid) != process.pid]
        assert others, "rei edit runs no thread besides its main one"
        _thread_kill(process.pid, others[0], signal.SIGINT)
        _, err = process.communicate(timeout=30)
    finally:
        if process.poll() is None:
            process.kill()
            process.wait()
    assert process.returncode == 0, err


def _thread_kill(pid: int, tid: int, sig: signal.Signals) -> None:
    """tgkill(2): ``sig`` to thread ``tid`` of process ``pid`` only (os.kill lets the kernel choose the thread)."""
    import ctypes

    libc = ctypes.CDLL(None, use_errno=True)
    sys_tgkill = 234  # x86_64
    if libc.syscall(sys_tgkill, pid, tid, int(sig)) != 0:
        raise OSError(ctypes.get_errno(), f"tgkill({pid}, {tid}, {sig.name})")


def _signal_engine(editor: Editor, sig: signal.Signals) -> None:
    pid = editor.engine.pid
    assert pid is not None
    os.kill(pid, sig)
    if sig == signal.SIGKILL:
        deadline = time.monotonic() + 10
        while editor.engine.alive and time.monotonic() < deadline:
            time.sleep(0.05)
