# SPDX-License-Identifier: EPL-2.0
"""The room editor's robot outline (rei.edit.outlines) is read again when a file of the description changes: an
edited xacro include, not only the description itself."""

from __future__ import annotations

import os
from pathlib import Path

from rei.edit.outlines import RobotOutlines


def _write(path: Path, text: str, mtime: int) -> None:
    path.write_text(text, encoding="utf-8")
    os.utime(path, ns=(mtime, mtime))  # distinct times, whatever the file system's clock resolution


def test_an_edited_include_changes_the_outline_shown(tmp_path: Path) -> None:
    top = tmp_path / "bot.xacro"
    _write(top, '<robot name="bot" xmlns:xacro="http://ros.org/wiki/xacro"><xacro:include filename="body.xacro"/>'
                '<link name="base_footprint"><collision><origin xyz="0 0 0.1"/>'
                '<geometry><cylinder radius="${radius}" length="0.2"/></geometry></collision></link></robot>',
           10**18)
    body = tmp_path / "body.xacro"
    diagram = {"robot": {"footprint": {"name": "Bot", "description": {"file": str(top), "args": {}, "lidar": None}}}}
    outlines = RobotOutlines()
    for i, radius in enumerate((0.2, 0.25, 0.3)):
        _write(body, '<robot xmlns:xacro="http://ros.org/wiki/xacro">'
                     f'<xacro:property name="radius" value="{radius}"/></robot>', 10**18 + i * 10**9)
        shown = outlines.of_diagram(diagram, tmp_path)
        assert shown is not None
        assert shown["robot"]["footprint"]["outline"] == {"type": "circle", "x": 0.0, "y": 0.0, "radius": radius}
    # a description that stops reading: no outline, and back when it reads again
    _write(body, "<robot", 10**18 + 5 * 10**9)
    assert outlines.of_diagram(diagram, tmp_path)["robot"]["footprint"]["outline"] is None  # type: ignore[index]
    _write(body, '<robot xmlns:xacro="http://ros.org/wiki/xacro"><xacro:property name="radius" value="0.4"/></robot>',
           10**18 + 6 * 10**9)
    assert outlines.of_diagram(diagram, tmp_path)["robot"]["footprint"]["outline"]["radius"] == 0.4  # type: ignore[index]
