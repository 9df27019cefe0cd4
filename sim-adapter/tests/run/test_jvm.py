# SPDX-License-Identifier: EPL-2.0
"""Class-data sharing of the short-lived jar runs (rei.run.jvm), with the real monitor jar."""

from __future__ import annotations

from pathlib import Path

import pytest

from rei import toolchain
from rei.run.jvm import CDS_ENV, cds_archive, run_jar


def test_the_first_run_dumps_the_archive_and_later_runs_use_it(tmp_path: Path, monkeypatch: pytest.MonkeyPatch):
    monkeypatch.setenv(CDS_ENV, str(tmp_path / "cds"))
    archive = cds_archive(toolchain.find_jar("monitor"), toolchain.find_java())
    assert archive is not None and not archive.exists()
    first = run_jar("monitor", ["--compile-only"], tmp_path / "first.log")
    assert first.code == 0, first.log_tail
    assert archive.is_file() and [p.name for p in archive.parent.iterdir()] == [archive.name]
    assert "warning" not in (tmp_path / "first.log").read_text()  # the dump's per-class warnings are off
    second = run_jar("monitor", ["--compile-only"], tmp_path / "second.log")
    assert second.code == 0, second.log_tail
    assert "warning" not in (tmp_path / "second.log").read_text()  # the archive matches this jar and Java


def test_a_failed_run_leaves_no_archive_and_off_means_off(tmp_path: Path, monkeypatch: pytest.MonkeyPatch):
    monkeypatch.setenv(CDS_ENV, str(tmp_path / "cds"))
    failed = run_jar("monitor", ["--no-such-option"], tmp_path / "failed.log")
    assert failed.code == 2
    assert list((tmp_path / "cds").iterdir()) == []
    monkeypatch.setenv(CDS_ENV, "off")
    assert cds_archive(toolchain.find_jar("monitor"), toolchain.find_java()) is None
