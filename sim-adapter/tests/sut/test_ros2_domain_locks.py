# SPDX-License-Identifier: EPL-2.0
"""The private folders REI keeps locks and sockets in (rei.private_dirs): the ROS 2 domain locks' folder
(rei.sut.ros2.environment) and the background service's, checked before use, the same for all of the user's processes,
and no lock file followed elsewhere."""

from __future__ import annotations

import os
import stat
import tempfile
from pathlib import Path

import pytest

from rei import private_dirs
from rei.private_dirs import UnsafeFolderError, private_dir
from rei.sut.ros2 import environment
from rei.sut.ros2.environment import DomainLease


def mode(path: Path) -> int:
    return stat.S_IMODE(os.lstat(path).st_mode)


def test_a_missing_folder_is_made_0700_with_its_parents(tmp_path: Path) -> None:
    folder = private_dir(tmp_path / "a" / "b")
    assert folder.is_dir() and mode(folder) == 0o700 and os.lstat(folder).st_uid == os.getuid()


@pytest.mark.parametrize("bits", [0o770, 0o707, 0o777, 0o1777])
def test_a_folder_others_can_write_in_is_refused_and_left_as_it_is(tmp_path: Path, bits: int) -> None:
    folder = tmp_path / "shared"
    folder.mkdir()
    os.chmod(folder, bits)
    with pytest.raises(UnsafeFolderError, match=f"{folder}: mode {bits:04o} lets group or others write"):
        private_dir(folder)
    with pytest.raises(UnsafeFolderError, match="lets group or others write"):
        DomainLease.claim(folder=folder)
    assert mode(folder) == bits and list(folder.iterdir()) == []  # nothing created in it


def test_a_folder_of_the_users_own_that_others_could_only_read_is_closed(tmp_path: Path) -> None:
    """Earlier versions made /tmp/rei-UID 0755: nobody else could put anything in it, so it is kept, made 0700."""
    folder = tmp_path / "old"
    folder.mkdir()
    os.chmod(folder, 0o755)
    assert private_dir(folder) == folder and mode(folder) == 0o700


def test_a_symbolic_link_in_place_of_the_folder_is_refused(tmp_path: Path) -> None:
    target = tmp_path / "elsewhere"
    target.mkdir(mode=0o700)
    link = tmp_path / "link"
    link.symlink_to(target)
    with pytest.raises(UnsafeFolderError, match=f"{link}: a symbolic link \\(to {target}\\)"):
        private_dir(link)
    with pytest.raises(UnsafeFolderError, match="a symbolic link"):
        DomainLease.claim(folder=link)
    assert list(target.iterdir()) == []


def test_a_folder_of_another_user_is_refused(tmp_path: Path) -> None:
    if os.getuid() == 0:  # root can give a folder away; another user's folder is what an attacker plants
        folder = tmp_path / "theirs"
        folder.mkdir(mode=0o700)
        os.chown(folder, 65534, 65534)
        owner = 65534
    else:  # any user: the root folder is root's
        folder, owner = Path("/"), 0
    with pytest.raises(UnsafeFolderError, match=f"owned by uid {owner}, not by this user \\(uid {os.getuid()}\\)"):
        private_dir(folder)


def test_a_planted_symbolic_link_lock_file_is_not_followed(tmp_path: Path) -> None:
    """A lock file that is a link to another file: refused, and the other file keeps its contents."""
    folder = private_dir(tmp_path / "locks")
    victim = tmp_path / "precious.txt"
    victim.write_text("the user's work\n")
    (folder / "domain-7.lock").symlink_to(victim)
    with pytest.raises(UnsafeFolderError, match=f"{folder / 'domain-7.lock'}: a symbolic link, not a lock file"):
        DomainLease.claim(7, folder=folder)
    assert victim.read_text() == "the user's work\n"


def test_the_lock_file_names_its_holder_without_being_truncated(tmp_path: Path) -> None:
    folder = private_dir(tmp_path / "locks")
    lock = folder / "domain-9.lock"
    lock.write_text("123456789\n")  # a longer earlier holder
    with DomainLease.claim(9, folder=folder):
        assert lock.read_text().split() == [str(os.getpid())]


def test_the_lock_folder_is_named_from_the_uid_alone(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """All of one user's processes share the locks, whatever their TMPDIR or XDG_RUNTIME_DIR (a Ray worker started
    from another environment, a CI job)."""
    assert private_dirs.RUNTIME_PARENT == Path("/tmp")  # not tempfile.gettempdir(), which follows TMPDIR
    monkeypatch.setattr(private_dirs, "RUNTIME_PARENT", tmp_path)
    expected = tmp_path / f"rei-{os.getuid()}" / "ros2-domains"
    for runtime, temporary in ((None, None), (str(tmp_path / "xdg"), str(tmp_path / "tmpdir"))):
        for name, value in (("XDG_RUNTIME_DIR", runtime), ("TMPDIR", temporary)):
            if value is None:
                monkeypatch.delenv(name, raising=False)
            else:
                Path(value).mkdir(exist_ok=True)
                monkeypatch.setenv(name, value)
        monkeypatch.setattr(tempfile, "tempdir", None)  # tempfile caches TMPDIR: read it again
        assert environment.lock_dir() == expected
    assert mode(expected.parent) == 0o700 and mode(expected) == 0o700


def test_a_runtime_folder_someone_else_made_first_stops_the_claim(tmp_path: Path,
                                                                   monkeypatch: pytest.MonkeyPatch) -> None:
    """/tmp/rei-UID made by another user (here: made world-writable) before this user's first run."""
    monkeypatch.setattr(private_dirs, "RUNTIME_PARENT", tmp_path)
    planted = tmp_path / f"rei-{os.getuid()}"
    planted.mkdir()
    os.chmod(planted, 0o777)
    with pytest.raises(UnsafeFolderError, match=f"{planted}: mode 0777"):
        DomainLease.claim()
    assert list(planted.iterdir()) == []


def test_the_background_services_folder_is_checked_by_the_same_helper_before_its_socket_is_used(
        tmp_path: Path) -> None:
    """The service's folder holds its control socket: one that others can write in may hold theirs."""
    from rei.service.client import ServiceError, connect

    folder = tmp_path / "service"
    folder.mkdir()
    os.chmod(folder, 0o777)
    with pytest.raises(ServiceError, match=f"the background service's folder: {folder}: mode 0777"):
        connect(log=lambda line: None, folder=folder)
    assert list(folder.iterdir()) == []  # nothing started, nothing connected to
