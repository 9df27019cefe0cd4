# SPDX-License-Identifier: EPL-2.0
"""Reader for ``mission.xml``: the start pose and the ordered navigation goals (thesis 2.1.2, 5.2.1)."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from rei.artifacts._xml import read_root
from rei.artifacts.errors import ArtifactError
from rei.geometry import Pose2D

if TYPE_CHECKING:
    from rei.sim.faults import Fault


@dataclass(frozen=True, slots=True)
class GoalSpec:
    """A navigation task: reach ``pose`` within ``tolerance`` metres before ``timeout`` seconds."""

    index: int
    floor: str | None
    pose: Pose2D
    tolerance: float
    timeout: float


@dataclass(frozen=True, slots=True)
class MissionSpec:
    path: Path
    name: str
    testcase: str
    environment: str
    robot: str
    frame: str
    start_floor: str | None
    start: Pose2D
    goals: tuple[GoalSpec, ...]
    faults: tuple[Fault, ...] = ()  # the test case's fault schedule (<faults>), in the order written


def read_mission(path: Path | str) -> MissionSpec:
    """Parse ``mission.xml``; goals come back in execution order (their ``index`` attributes 0, 1, 2, ...)."""
    path = Path(path)
    root = read_root(path, "mission")
    start = root.find("start")
    if start is None:
        raise ArtifactError(path, "<start> is missing")
    goals = tuple(_goal(path, i, g) for i, g in enumerate(root.findall("goal")))
    if not goals:
        raise ArtifactError(path, "the mission has no <goal>")
    for i, goal in enumerate(goals):
        if goal.index != i:
            raise ArtifactError(
                path, f"goal #{i}: index must be {i} (goals in execution order), got {goal.index}"
            )
    frame = root.get("frame", "world")
    if frame != "world":
        raise ArtifactError(path, f"<mission frame>: only 'world' is supported, got {frame!r}")
    return MissionSpec(
        path=path,
        name=_attr(path, "<mission>", root, "name"),
        testcase=_attr(path, "<mission>", root, "testcase"),
        environment=_attr(path, "<mission>", root, "environment"),
        robot=_attr(path, "<mission>", root, "robot"),
        frame=frame,
        start_floor=start.get("floor"),
        start=_pose(path, "<start>", start),
        goals=goals,
        faults=_faults(path, root),
    )


def _faults(path: Path, root: ET.Element) -> tuple[Fault, ...]:
    """``<faults><fault sensor="laser" kind="blackout" from="5" to="7"/>...</faults>``: the attributes besides
    sensor and kind are the keys of a ``--fault`` spec (rei.sim.faults.spec), read by the same code."""
    elements = [f for block in root.findall("faults") for f in block]
    if not elements:
        return ()
    from rei.sim.faults import fault_from_fields  # the simulator's model; read only when a case has faults

    faults = []
    for i, element in enumerate(elements):
        where = f"fault #{i}"
        if element.tag != "fault":
            raise ArtifactError(path, f"<faults> holds <fault> elements only, got <{element.tag}>")
        fields = dict(element.attrib)
        sensor, kind = fields.pop("sensor", ""), fields.pop("kind", "")
        try:
            faults.append(fault_from_fields(sensor, kind, fields))
        except ValueError as error:
            raise ArtifactError(path, f"{where}: {error}") from None
    return tuple(faults)


def _goal(path: Path, i: int, goal: ET.Element) -> GoalSpec:
    where = f"goal #{i}"
    tolerance = _number(path, where, goal, "tolerance")
    timeout = _number(path, where, goal, "timeout")
    if tolerance <= 0 or timeout <= 0:
        raise ArtifactError(path, f"{where}: tolerance and timeout must be > 0, got {tolerance}, {timeout}")
    index_text = _attr(path, where, goal, "index")
    try:
        index = int(index_text)
    except ValueError:
        raise ArtifactError(path, f"{where}: index must be an integer, got {index_text!r}") from None
    return GoalSpec(
        index=index,
        floor=goal.get("floor"),
        pose=_pose(path, where, goal),
        tolerance=tolerance,
        timeout=timeout,
    )


def _pose(path: Path, where: str, element: ET.Element) -> Pose2D:
    return Pose2D(
        _number(path, where, element, "x"),
        _number(path, where, element, "y"),
        _number(path, where, element, "yaw"),
    )


def _attr(path: Path, where: str, element: ET.Element, name: str) -> str:
    value = element.get(name)
    if not value:
        raise ArtifactError(path, f"{where}: attribute {name!r} is missing")
    return value


def _number(path: Path, where: str, element: ET.Element, name: str) -> float:
    text = _attr(path, where, element, name)
    try:
        value = float(text)
    except ValueError:
        raise ArtifactError(path, f"{where}: attribute {name!r} must be a number, got {text!r}") from None
    if not math.isfinite(value):
        raise ArtifactError(path, f"{where}: attribute {name!r} must be finite, got {text!r}")
    return value
