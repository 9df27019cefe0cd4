# SPDX-License-Identifier: EPL-2.0
"""Folders only the user can enter, checked before REI puts locks, sockets or secrets in them.

A folder in a place every user can write (``/tmp``) may have been made first by someone else, or be a symbolic link
to somewhere else: ``mkdir(exist_ok=True)`` would accept either, and whoever owns it could then plant files (a
symbolic link where a lock file is expected) or hold every lock. So an existing folder is looked at with ``lstat``
and refused unless it is a real folder, the user's own, that neither group nor others can write. One of the user's
own that others could only read or enter (as earlier versions of REI made ``/tmp/rei-UID``: 0755) is closed to
0700: nobody else can have put anything in it. ``/tmp`` has the sticky bit, so once checked, nobody else can rename
or remove the folder.
"""

from __future__ import annotations

import os
import stat
from pathlib import Path

#: Where a user's runtime folder lives: ``/tmp`` itself, not ``$TMPDIR``.
RUNTIME_PARENT = Path("/tmp")


class UnsafeFolderError(OSError):
    """A folder REI would keep private files in that someone else could enter, write or redirect."""


def private_dir(path: Path) -> Path:
    """``path``, created with mode 0700 if it is missing (its parents as the umask makes them), else checked.

    Raises ``UnsafeFolderError`` naming the folder and what is wrong when it is a symbolic link or not a folder,
    belongs to another user, or lets group or others write; read or search permission for them is taken away."""
    path.parent.mkdir(parents=True, exist_ok=True)
    try:
        os.mkdir(path, 0o700)
    except FileExistsError:
        pass
    else:
        os.chmod(path, 0o700)  # a stricter umask would leave the user without access; never wider than 0700
    info = os.lstat(path)
    if stat.S_ISLNK(info.st_mode):
        raise UnsafeFolderError(f"{path}: a symbolic link (to {os.readlink(path)}), not a folder of the user's own: "
                                f"REI refuses to keep private files there; remove it")
    if not stat.S_ISDIR(info.st_mode):
        raise UnsafeFolderError(f"{path}: not a folder; REI needs a private folder there: remove it")
    if info.st_uid != os.getuid():
        raise UnsafeFolderError(f"{path}: owned by uid {info.st_uid}, not by this user (uid {os.getuid()}): another "
                                f"user made it first, and REI refuses to keep private files there; ask them or an "
                                f"administrator to remove it")
    mode = stat.S_IMODE(info.st_mode)
    if mode & 0o022:
        raise UnsafeFolderError(f"{path}: mode {mode:04o} lets group or others write in it; REI keeps private files "
                                f"there and needs 0700 (check what others may have put there, then chmod 700 {path})")
    if mode & 0o077:
        os.chmod(path, mode & 0o700)  # checked a real folder of the user's own just above; lstat is not followed
    return path


def user_runtime_dir() -> Path:
    """The user's private runtime folder, ``/tmp/rei-UID``, checked (``private_dir``).

    Named from the uid alone, not from ``$TMPDIR`` or ``$XDG_RUNTIME_DIR``: every process of the user finds the same
    folder, a Ray worker or a CI job started with another environment too, so locks in it are shared by all of them.
    """
    return private_dir(RUNTIME_PARENT / f"rei-{os.getuid()}")
