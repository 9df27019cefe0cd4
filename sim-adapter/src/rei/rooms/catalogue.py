# SPDX-License-Identifier: EPL-2.0
"""Furnishing generated rooms from a user catalogue (``rei gen-rooms --catalogue FILE``).

The catalogue is read by the language's own front end (``rei-cli types``), so it is validated exactly as a test
case that imports it would be, with file:line:column messages; its object types become the furniture (equally
frequent) and its robot type, when it declares one, the robot.
"""

from __future__ import annotations

import json
import subprocess
from pathlib import Path

from rei import toolchain
from rei.rooms.model import WAFFLE, RoomTypes


class CatalogueError(ValueError):
    """The catalogue can not furnish a room; the message says why (the validator's messages included)."""


def room_types(catalogue: Path, robot: str | None = None) -> RoomTypes:
    """The furniture (``object`` types) and robot of ``catalogue``; ``robot`` picks one of its robot types
    (default: its only one, else the default catalogue's Waffle)."""
    described = _describe(catalogue)
    types = described.get("types", [])
    furniture = {t["name"]: (float(t["size"][0]), float(t["size"][1])) for t in types if t["category"] == "STATIC"}
    robots = {t["name"]: (float(t["size"][0]), float(t["size"][1])) for t in types if t["category"] == "ROBOT"}
    if not furniture:
        raise CatalogueError(f"{catalogue}: declares no furniture ('type NAME : object ...') to place in rooms")
    if robot is None and len(robots) > 1:
        raise CatalogueError(f"{catalogue}: declares robot types {', '.join(robots)}: choose one with --robot")
    if robot is None:
        name, size = next(iter(robots.items())) if robots else WAFFLE
    elif robot in robots:
        name, size = robot, robots[robot]
    elif robot == WAFFLE[0]:
        name, size = WAFFLE
    else:
        raise CatalogueError(f"--robot {robot}: {catalogue} declares no such robot type "
                             f"(robot types: {', '.join([*robots, WAFFLE[0]])})")
    try:
        return RoomTypes(furniture, dict.fromkeys(furniture, 1), name, size, catalogue)
    except ValueError as error:
        raise CatalogueError(f"{catalogue}: {error}") from None


def _describe(catalogue: Path) -> dict:
    if not catalogue.is_file():
        raise CatalogueError(f"cannot read catalogue {catalogue}: no such file")
    command = toolchain.jar_command(toolchain.find_jar("cli"), ["types", str(catalogue)])
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=300, check=False)
    except (OSError, subprocess.TimeoutExpired) as error:
        raise CatalogueError(f"cannot read catalogue {catalogue}: {error}") from None
    if done.returncode != 0:
        raise CatalogueError(f"catalogue {catalogue} can not be used:\n{done.stderr.strip()}" if done.stderr.strip()
                             else f"cannot read catalogue {catalogue} (exit {done.returncode})")
    return json.loads(done.stdout)
