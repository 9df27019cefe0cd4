# SPDX-License-Identifier: EPL-2.0
"""Procedural test rooms (thesis 7.4): ``generate_room(size, density, humans, seed, index)`` draws a valid,
navigable ``Room``; ``render(room)`` writes it as ``.rei`` text; ``write_rooms`` does both for ``rei gen-rooms``.
``generate_map_room`` and ``write_map_rooms`` do the same on a real building's occupancy map (``rei.rooms.on_map``).
Classes and rules: docs/campaigns.md.
"""

from __future__ import annotations

from pathlib import Path

from rei.rooms.classes import DENSITIES, MAX_HUMANS, ROOM_CLASSES, SIZES, RoomClass, room_class
from rei.rooms.generator import GenerationError, generate_room, generate_rooms
from rei.rooms.model import (
    BEHAVIOURS,
    DEFAULT_TYPES,
    FURNITURE,
    MIXED,
    Furniture,
    Goal,
    MapSite,
    Person,
    Room,
    RoomTypes,
    Walker,
)
from rei.rooms.on_map import generate_map_room, generate_map_rooms, load_site
from rei.rooms.render import render


def write_rooms(out: Path, size: str, density: str | None = None, humans: int | None = None, seed: int = 0,
                count: int = 1, types: RoomTypes = DEFAULT_TYPES, reactive: str | None = None) -> list[tuple[Room, Path]]:
    """Generate ``count`` rooms into ``out`` as ``<stem>.rei``; an existing file of the same name is replaced
    (it holds the same room: generation is deterministic). ``reactive``: people who see the robot with this
    behaviour (or ``mixed``) instead of humans on lanes."""
    out.mkdir(parents=True, exist_ok=True)
    written = []
    for room in generate_rooms(size, density, humans, seed, count, types, reactive):
        path = out / f"{room.stem}.rei"
        path.write_text(render(room, count, out), encoding="utf-8")
        written.append((room, path))
    return written


def write_map_rooms(out: Path, site: MapSite, density: str | None = None, humans: int | None = None, seed: int = 0,
                    count: int = 1, types: RoomTypes = DEFAULT_TYPES, check: bool = True,
                    reactive: str | None = None) -> list[tuple[Room, Path]]:
    """``write_rooms`` on an occupancy map (``rei gen-rooms --map``): each file names the map by its path relative
    to ``out``."""
    out.mkdir(parents=True, exist_ok=True)
    written = []
    for room in generate_map_rooms(site, density, humans, seed, count, types, check, reactive):
        path = out / f"{room.stem}.rei"
        path.write_text(render(room, count, out), encoding="utf-8")
        written.append((room, path))
    return written


__all__ = [
    "BEHAVIOURS",
    "DEFAULT_TYPES",
    "DENSITIES",
    "FURNITURE",
    "MAX_HUMANS",
    "MIXED",
    "ROOM_CLASSES",
    "SIZES",
    "Furniture",
    "GenerationError",
    "Goal",
    "MapSite",
    "Person",
    "Room",
    "RoomClass",
    "RoomTypes",
    "Walker",
    "generate_map_room",
    "generate_map_rooms",
    "generate_room",
    "generate_rooms",
    "load_site",
    "render",
    "room_class",
    "write_map_rooms",
    "write_rooms",
]
