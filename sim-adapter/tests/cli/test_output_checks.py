# SPDX-License-Identifier: EPL-2.0
"""A run refuses an output folder it cannot write to, or a disk without room, before anything starts."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from rei.cli._case import prepare_output
from rei.cli.errors import CommandError


def test_an_unwritable_folder_is_refused(tmp_path: Path) -> None:
    locked = tmp_path / "locked"
    locked.mkdir()
    locked.chmod(0o500)
    try:
        if os.access(locked, os.W_OK):  # root ignores permission bits: use a path under a regular file instead
            target = tmp_path / "file"
            target.write_text("")
            out = target / "out"
        else:
            out = locked / "out"
        with pytest.raises(CommandError, match="cannot write to"):
            prepare_output(out)
    finally:
        locked.chmod(0o700)


def test_a_disk_without_room_is_refused(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("REI_MIN_FREE_MB", str(10**12))  # more than any disk has
    with pytest.raises(CommandError, match=r"MB free on the disk of .* needs at least"):
        prepare_output(tmp_path / "out")


def test_a_writable_folder_with_room_is_accepted(tmp_path: Path) -> None:
    prepare_output(tmp_path / "a" / "b")
    assert (tmp_path / "a" / "b").is_dir() and not list((tmp_path / "a" / "b").iterdir())
