# SPDX-License-Identifier: EPL-2.0
"""Fixtures of the room editor's tests: a copy of a test case open in a real edit engine behind a real server, and
a page of Debian's chromium that fails the test when its script throws."""

from __future__ import annotations

import shutil
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
from edit_helpers import SHOTS, Editor
from playwright.sync_api import Browser, Page

from rei import toolchain
from rei.edit import EditEngine, EditServer, EditSession, engine_command

REPO_ROOT = Path(__file__).resolve().parents[2]
PAGE_TIMEOUT_MS = 60_000
VIEWPORT = {"width": 1400, "height": 900}


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


@pytest.fixture
def page(browser: Browser) -> Iterator[Page]:
    SHOTS.mkdir(parents=True, exist_ok=True)
    opened = browser.new_page(viewport=VIEWPORT)  # type: ignore[arg-type]
    opened.set_default_timeout(PAGE_TIMEOUT_MS)
    errors: list[str] = []
    opened.on("pageerror", lambda error: errors.append(str(error)))
    yield opened
    opened.close()
    assert not errors, f"the page threw: {errors}"
