# SPDX-License-Identifier: EPL-2.0
"""The outline of a robot read from its URDF or xacro description, for the room editor's diagram.

The edit engine (Java) knows such a robot type only by its description's file, xacro arguments and lidar link; the
outline (the collision shapes projected to the floor: a polygon or a circle) is what REI's Python reader computes,
the same one the generator writes into world.json's ``robot.footprint``. It is read once per description and kept
while the files it was read from are unchanged (the description, its xacro includes, its collision meshes): the
page asks for the state after every edit.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

_Key = tuple[str, tuple[tuple[str, str], ...]]
#: Each file a read depends on, with its modification time and size (-1, -1: gone).
_Stamps = tuple[tuple[Path, int, int], ...]


class RobotOutlines:
    def __init__(self) -> None:
        self._read: dict[_Key, tuple[_Stamps, dict[str, Any]]] = {}

    def of_diagram(self, diagram: dict[str, Any] | None, folder: Path) -> dict[str, Any] | None:
        """The diagram with its robot's footprint carrying ``outline`` (world.json's footprint JSON, or null for a
        box robot and a description that does not read: the validator or ``rei generate`` says why) and its
        description's file relative to ``folder`` (the browser needs no path of this machine)."""
        robot = (diagram or {}).get("robot") or {}
        footprint = robot.get("footprint") or {}
        description = footprint.get("description")
        if diagram is None or not footprint:
            return diagram
        outline = None if not description else self._outline(description)
        if description:
            file = Path(os.path.relpath(description["file"], folder)).as_posix()
            description = {**description, "file": file}
        return {**diagram, "robot": {**robot, "footprint": {**footprint, "description": description,
                                                             "outline": outline}}}

    def _outline(self, description: dict[str, Any]) -> dict[str, Any] | None:
        path = Path(description["file"])
        if not path.is_file():
            return None
        args = tuple((str(k), str(v)) for k, v in (description.get("args") or {}).items())
        key: _Key = (str(path), args)
        known = self._read.get(key)
        # only the top file was stamped: an edited xacro include kept the old outline on the page
        if known is None or known[0] != _stamps(p for p, _, _ in known[0]):
            known = _load(path, dict(args))
            if known is None:  # not kept: which files it would read again is not known until it reads
                self._read.pop(key, None)
                return None
            self._read[key] = known
        return known[1]


def _stamps(paths: Any) -> _Stamps:
    stamps = []
    for path in paths:
        try:
            stat = path.stat()
            stamps.append((path, stat.st_mtime_ns, stat.st_size))
        except OSError:
            stamps.append((path, -1, -1))
    return tuple(stamps)


def _load(path: Path, args: dict[str, str]) -> tuple[_Stamps, dict[str, Any]] | None:
    # xacro and the URDF parser: imported only for such a robot
    from rei.robots import DescriptionError, load_description

    try:
        # no lidar link: the outline does not depend on it, and a misnamed one (the validator's error) still draws
        robot = load_description(path, args)
    except DescriptionError:
        return None
    return _stamps(robot.sources), robot.footprint.to_json()
