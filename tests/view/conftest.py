# SPDX-License-Identifier: EPL-2.0
"""Fixtures of the live view's browser tests: Debian's chromium driven by Playwright, a router, a view server.

Playwright's own browser downloads are never used (`executable_path` points at the system's chromium, which
scripts/setup-browser.sh installs). These tests never skip: a missing browser fails with the set-up hint.
"""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from playwright.sync_api import Browser, sync_playwright

from rei.wamp import Router


@pytest.fixture(scope="session")
def browser(chromium: str) -> Iterator[Browser]:
    with sync_playwright() as playwright:
        launched = playwright.chromium.launch(executable_path=chromium,
                                              args=["--no-sandbox", "--disable-dev-shm-usage"])
        try:
            yield launched
        finally:
            launched.close()


@pytest.fixture(scope="module")
def router() -> Iterator[Router]:
    with Router(auth=False) as running:
        yield running
