# SPDX-License-Identifier: EPL-2.0
"""Fixtures of the WAMP tests: the real Crossbar router (installed on demand) and the generated artifacts."""

from __future__ import annotations

import json
import subprocess
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from rei.wamp import Router

REPO = Path(__file__).resolve().parents[3]
FIXTURE = Path(__file__).resolve().parents[1] / "fixtures" / "room6x4"


@pytest.fixture(scope="session")
def crossbar() -> Path:
    """The pinned crossbar of <repo>/.venv-router; the set-up script installs it when missing (no skipping)."""
    subprocess.run([str(REPO / "scripts" / "setup-router.sh")], check=True, capture_output=True, timeout=900)
    path = REPO / ".venv-router" / "bin" / "crossbar"
    assert path.is_file()
    return path


@pytest.fixture(scope="session")
def router(crossbar: Path) -> Iterator[Router]:
    """One router for the session (start-up costs ~2.5 s); tests use distinct run ids."""
    with Router(crossbar=crossbar, auth=False) as running:
        yield running


@pytest.fixture(scope="session")
def world() -> dict[str, Any]:
    return json.loads((FIXTURE / "world.json").read_text())


@pytest.fixture(scope="session")
def monitor() -> dict[str, Any]:
    return json.loads((FIXTURE / "monitor.json").read_text())
