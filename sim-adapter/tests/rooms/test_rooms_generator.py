# SPDX-License-Identifier: EPL-2.0
"""The room generator: deterministic per seed, every rule of its module doc holds, the catalogue agrees."""

from __future__ import annotations

import itertools
import re
import xml.etree.ElementTree as ET
from collections import deque
from pathlib import Path

import pytest

from rei.rooms import FURNITURE, MAX_HUMANS, ROOM_CLASSES, Room, generate_room, generate_rooms, render
from rei.rooms.check import unplannable_legs
from rei.rooms.generator import GAP, WALL_CLEARANCE

CATALOGUE = (Path(__file__).resolve().parents[3] / "metamodels" / "src" / "main" / "resources" / "org" / "rei"
             / "catalogue" / "default.catalogue")


def settings() -> list[tuple[str, str, int]]:
    return [(size, density, humans) for size in ROOM_CLASSES for density in ("dense", "sparse")
            for humans in range(MAX_HUMANS[size] + 1)]


def test_same_seed_same_room_and_index_does_not_depend_on_count() -> None:
    for size, density, humans in settings():
        first = [render(r) for r in generate_rooms(size, density, humans, seed=42, count=3)]
        assert first == [render(r) for r in generate_rooms(size, density, humans, seed=42, count=3)]
        assert render(generate_room(size, density, humans, 42, 3)) == first[2]
        assert len(set(first)) == 3, "three rooms of one seed must differ"


def test_different_seeds_give_different_rooms() -> None:
    texts = {render(generate_room("small", seed=seed)) for seed in range(50)}
    assert len(texts) == 50


def test_the_text_is_pinned_for_one_seed() -> None:
    """A change of the generator changes every campaign's rooms: it must be deliberate (update this pin)."""
    text = render(generate_room("small", "dense", 0, seed=1, index=1))
    assert text.count("    object ") == 10
    assert "testcase SmallDense_1_1 {" in text and "room Room size 7 x 5 {" in text
    assert re.search(r"robot tb3 : Waffle on F_0_\d\n", text)
    assert re.search(r"goto F_6_\d within \d+s\n    goto F_\d_\d within \d+s\n  }", text)


@pytest.mark.parametrize(("size", "density", "humans"), settings())
def test_rules_hold_over_many_seeds(size: str, density: str, humans: int) -> None:
    for seed in range(150):
        room = generate_room(size, density, humans, seed)
        problems = rule_violations(room)
        assert not problems, f"{room.stem}: {problems}"
        assert len(room.furniture) == ROOM_CLASSES[size].objects(density)
        assert len(room.walkers) == humans and len(room.goals) == ROOM_CLASSES[size].goals


@pytest.mark.parametrize("size", list(ROOM_CLASSES))
def test_the_reference_planner_finds_every_leg(size: str) -> None:
    for density, seed in itertools.product(("dense", "sparse"), range(25 if size == "large" else 60)):
        room = generate_room(size, density, None, seed)
        assert unplannable_legs(room) == [], room.stem


def test_bad_settings_are_refused_with_the_reason() -> None:
    with pytest.raises(ValueError, match="size must be one of small, medium, large"):
        generate_room("huge")
    with pytest.raises(ValueError, match="density must be one of dense, sparse"):
        generate_room("small", "crowded")
    with pytest.raises(ValueError, match="a small room holds 0 to 2 humans"):
        generate_room("small", humans=3)


def test_catalogue_footprints_match_the_default_catalogue() -> None:
    root = ET.parse(CATALOGUE).getroot()
    sizes = {t.get("name"): (float(t.get("sizeX")), float(t.get("sizeY"))) for t in root.iter("ownedTypes")
             if t.get("category") == "STATIC"}
    assert sizes == FURNITURE


def rule_violations(room: Room) -> list[str]:
    """Every rule of rei.rooms.generator, checked from the room's geometry rather than the generator's code."""
    problems = []
    cells = {(x, y) for x in range(room.width) for y in range(room.height)}
    blocked = {f.cell for f in room.furniture}
    robot = {room.start, *(g.cell for g in room.goals)}
    lanes = {c for w in room.walkers for c in w.cells()}
    if len(blocked) != len(room.furniture):
        problems.append("two pieces on one floor")
    if robot & blocked or lanes & blocked:
        problems.append("furniture on the start, a goal or a lane")
    if len(robot) != 1 + len(room.goals):
        problems.append("start and goals are not distinct")
    rects = {f.cell: _rect(f.cell, f.half_extents()) for f in room.furniture}
    inner = (WALL_CLEARANCE, WALL_CLEARANCE, room.width - WALL_CLEARANCE, room.height - WALL_CLEARANCE)
    for cell, r in rects.items():
        if not (r[0] >= inner[0] - 1e-9 and r[1] >= inner[1] - 1e-9 and r[2] <= inner[2] + 1e-9
                and r[3] <= inner[3] + 1e-9):
            problems.append(f"furniture on {cell} reaches into a wall")
        for other, q in rects.items():
            if other != cell and _gap(r, q) < GAP - 1e-9:
                problems.append(f"furniture on {cell} and {other} closer than {GAP} m")
        for c in robot | lanes:
            if _gap(r, _rect(c, (0.5, 0.5))) < GAP - 1e-9:
                problems.append(f"furniture on {cell} reaches into reserved floor {c}")
    free = cells - blocked
    seen = _reachable(room.start, free)
    if seen != free:
        problems.append(f"floors cut off: {sorted(free - seen)}")
    for c in robot:
        around = [(c[0] + dx, c[1] + dy) for dx, dy in ((1, 0), (-1, 0), (0, 1), (0, -1))]
        if sum(n in free for n in around) < 2:
            problems.append(f"{c} has fewer than two free neighbours")
    near_start = {room.start, *((room.start[0] + dx, room.start[1] + dy) for dx, dy in ((1, 0), (-1, 0), (0, 1), (0, -1)))}
    if lanes & (near_start | {g.cell for g in room.goals}):
        problems.append("a human walks over the start, its neighbours or a goal")
    if sum(len(w.cells()) for w in room.walkers) != len(lanes):
        problems.append("two humans share floors")
    if room.start[0] != 0 or room.goals[0].cell[0] != room.width - 1:
        problems.append("the robot does not start on one side and go to the other")
    return problems


def _rect(cell: tuple[int, int], half: tuple[float, float]) -> tuple[float, float, float, float]:
    cx, cy = cell[0] + 0.5, cell[1] + 0.5
    return (cx - half[0], cy - half[1], cx + half[0], cy + half[1])


def _gap(a: tuple[float, ...], b: tuple[float, ...]) -> float:
    """Distance between two axis-aligned rectangles (negative depth when they overlap)."""
    dx = max(b[0] - a[2], a[0] - b[2])
    dy = max(b[1] - a[3], a[1] - b[3])
    return max(dx, dy) if dx < 0 or dy < 0 else (dx**2 + dy**2) ** 0.5


def _reachable(origin: tuple[int, int], free: set[tuple[int, int]]) -> set[tuple[int, int]]:
    seen, queue = {origin}, deque([origin])
    while queue:
        x, y = queue.popleft()
        for n in ((x + 1, y), (x - 1, y), (x, y + 1), (x, y - 1)):
            if n in free and n not in seen:
                seen.add(n)
                queue.append(n)
    return seen
