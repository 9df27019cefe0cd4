# SPDX-License-Identifier: EPL-2.0
"""Helpers of the room editor's page tests: the page driven with Playwright's mouse as a user drives it, and the
wait until an edit the page sent has come back drawn."""

from __future__ import annotations

import time

from edit_helpers import Editor
from playwright.sync_api import Locator, Page


def open_page(page: Page, editor: Editor) -> None:
    page.goto(editor.server.url)
    page.locator('[data-kind="robot"]').wait_for()


def element(page: Page, kind: str, name: str) -> Locator:
    return page.locator(f'[data-kind="{kind}"][data-name="{name}"]').first


def centre(locator: Locator) -> tuple[float, float]:
    box = locator.bounding_box()
    assert box is not None, f"{locator} is not drawn"
    return box["x"] + box["width"] / 2, box["y"] + box["height"] / 2


def click_floor(page: Page, name: str) -> None:
    x, y = centre(element(page, "floor", name))
    page.mouse.click(x, y)


def settled(editor: Editor, page: Page, version: int, timeout: float = 60.0) -> int:
    """Waits until an operation the page sent landed (the session moved past ``version``) and the page drew the
    state that came back."""
    deadline = time.monotonic() + timeout
    while (now := int(editor.session.status()["version"])) <= version:
        if time.monotonic() > deadline:
            raise AssertionError(f"no change reached the editor within {timeout} s")
        time.sleep(0.05)
    page.wait_for_function("v => (window.reiEdit?.state?.version ?? 0) >= v", arg=now)
    return now


def drag(page: Page, source: Locator, target: Locator) -> None:
    (x0, y0), (x1, y1) = centre(source), centre(target)
    page.mouse.move(x0, y0)
    page.mouse.down()
    page.mouse.move((x0 + x1) / 2, (y0 + y1) / 2, steps=5)
    page.mouse.move(x1, y1, steps=5)
    page.mouse.up()
