# SPDX-License-Identifier: EPL-2.0
"""Fixtures of the simulation tests."""

from __future__ import annotations

from pathlib import Path

import pytest


@pytest.fixture(scope="session")
def case(run_cli, repo_root: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """examples/simple_navigation.rei generated once (a run reads its case and writes elsewhere)."""
    out = tmp_path_factory.mktemp("simple_navigation")
    result = run_cli("generate", repo_root / "examples" / "simple_navigation.rei", "-o", out)
    assert result.returncode == 0, result.stderr
    return out
