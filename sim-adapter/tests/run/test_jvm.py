# SPDX-License-Identifier: EPL-2.0
"""Class-data sharing of the short-lived jar runs (rei.run.jvm), with the real monitor jar."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from rei import toolchain
from rei.run.jvm import CDS_ENV, _class_sharing, _keep_archive, cds_archive, run_jar


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


def test_a_rebuilt_jar_replaces_its_archive_and_leaves_other_checkouts_alone(tmp_path: Path,
                                                                               monkeypatch: pytest.MonkeyPatch):
    monkeypatch.setenv(CDS_ENV, str(tmp_path / "cds"))
    java = toolchain.find_java()
    jar, other = tmp_path / "a" / "rei-monitor.jar", tmp_path / "b" / "rei-monitor.jar"  # two checkouts
    for path in (jar, other):
        path.parent.mkdir()
        path.write_bytes(b"jar")

    def dump(path: Path) -> Path:  # what a run with sharing does: dump to a temporary name, keep it on success
        flags, pending = _class_sharing(path, java)
        assert pending is not None and any(flag.startswith("-XX:ArchiveClassesAtExit=") for flag in flags)
        pending[0].write_bytes(b"archive")
        _keep_archive(pending, ok=True)
        return pending[1]

    legacy = tmp_path / "cds" / "rei-monitor-05b804d74e41dc2b.jsa"  # named as before owners were
    first, others = dump(jar), dump(other)
    legacy.write_bytes(b"old")
    assert _class_sharing(jar, java) == ([f"-XX:SharedArchiveFile={first}"], None)
    os.utime(jar, ns=(jar.stat().st_atime_ns, jar.stat().st_mtime_ns + 10**9))  # rebuilt
    second = dump(jar)
    assert second != first
    assert sorted(p.name for p in (tmp_path / "cds").iterdir()) == sorted([second.name, others.name])
