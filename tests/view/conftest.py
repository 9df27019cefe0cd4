# SPDX-License-Identifier: EPL-2.0
"""Fixtures of the live view's browser tests: a router and a view server (the browser is tests/conftest.py's).

Playwright's own browser downloads are never used (`executable_path` points at the system's chromium, which
scripts/setup-browser.sh installs). These tests never skip: a missing browser fails with the set-up hint.
"""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from rei.wamp import Router


@pytest.fixture(scope="module")
def router() -> Iterator[Router]:
    with Router(auth=False) as running:
        yield running
