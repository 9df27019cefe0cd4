# SPDX-License-Identifier: EPL-2.0
"""Fixtures of the room editor's tests: a copy of a test case open in a real edit engine behind a real server."""

from __future__ import annotations

import shutil
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
from edit_helpers import Editor

from rei import toolchain
from rei.edit import EditEngine, EditServer, EditSession, engine_command

REPO_ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture
def open_editor(tmp_path: Path, room_editor_jar: Path, java: toolchain.Java) -> Iterator[Callable[..., Editor]]:
    """``open_editor("examples/simple_navigation.rei")``: a copy of the file in tmp_path, open in an editor
    served on loopback (``copy=False``: the file itself, for tests that do not save); ``timeout`` bounds each engine
    request."""
    opened: list[Editor] = []

    def open_(source: str | Path, *, timeout: float = 120.0, copy: bool = True) -> Editor:
        source = REPO_ROOT / source
        case = tmp_path / source.name if copy else source
        if copy:
            shutil.copyfile(source, case)
        engine = EditEngine(engine_command(room_editor_jar, java.executable), timeout=timeout)
        session = EditSession(case, engine)
        server = EditServer(session).start()
        editor = Editor(case, session, server, engine)
        opened.append(editor)
        return editor

    yield open_
    for editor in opened:
        editor.server.stop()
        editor.session.close()
