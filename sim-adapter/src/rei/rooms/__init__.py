# SPDX-License-Identifier: EPL-2.0
"""Procedural test rooms (thesis 7.4): ``generate_room(size, density, humans, seed, index)`` draws a valid,
navigable ``Room``; ``render(room)`` writes it as ``.rei`` text; ``write_rooms`` does both for ``rei gen-rooms``.
Classes and rules: docs/campaigns.md.
"""

from __future__ import annotations

from pathlib import Path

from rei.rooms.classes import DENSITIES, MAX_HUMANS, ROOM_CLASSES, SIZES, RoomClass, room_class
from rei.rooms.generator import GenerationError, generate_room, generate_rooms
from rei.rooms.model import DEFAULT_TYPES, FURNITURE, Furniture, Goal, Room, RoomTypes, Walker
from rei.rooms.render import render


def write_rooms(out: Path, size: str, density: str | None = None, humans: int | None = None, seed: int = 0,
                count: int = 1, types: RoomTypes = DEFAULT_TYPES) -> list[tuple[Room, Path]]:
    """Generate ``count`` rooms into ``out`` as ``<stem>.rei``; an existing file of the same name is replaced
    (it holds the same room: generation is deterministic)."""
    out.mkdir(parents=True, exist_ok=True)
    written = []
    for room in generate_rooms(size, density, humans, seed, count, types):
        path = out / f"{room.stem}.rei"
        path.write_text(render(room, count, out), encoding="utf-8")
        written.append((room, path))
    return written


__all__ = [
    "DEFAULT_TYPES",
    "DENSITIES",
    "FURNITURE",
    "MAX_HUMANS",
    "ROOM_CLASSES",
    "SIZES",
    "Furniture",
    "GenerationError",
    "Goal",
    "Room",
    "RoomClass",
    "RoomTypes",
    "Walker",
    "generate_room",
    "generate_rooms",
    "render",
    "room_class",
    "write_rooms",
]
