# SPDX-License-Identifier: EPL-2.0
"""Fixtures of the live-monitor tests: the monitor jar and the Java that runs it (never skipped: `./rei` builds)."""

from __future__ import annotations

import pytest

from rei import toolchain


@pytest.fixture(scope="session")
def java_exe() -> str:
    try:
        return str(toolchain.find_java().executable)
    except toolchain.ToolchainError as error:
        problem = str(error)
    pytest.fail(problem, pytrace=False)
