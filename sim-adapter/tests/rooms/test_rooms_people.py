# SPDX-License-Identifier: EPL-2.0
"""Generated rooms whose humans are people who see the robot (`rei gen-rooms --people reactive`): each person loops
round a route of 2 or 3 stops on free floors, reachable from each other along the free floors and away from the
robot's start and goals; the rooms pass the real validator, are the same for the same seed, keep their layout
whatever the behaviour, and a campaign's (or a search's) `rooms:` settings make the same rooms. Rooms with humans on
lanes are what they were."""

from __future__ import annotations

import re
import subprocess
import sys
from collections import deque
from pathlib import Path

import pytest

from rei import toolchain
from rei.campaign import SpecError, parse_spec
from rei.rooms import (
    BEHAVIOURS,
    MAX_HUMANS,
    ROOM_CLASSES,
    Room,
    generate_map_room,
    generate_room,
    load_site,
    render,
)
from rei.rooms.check import unplannable_legs
from rei.rooms.floors import PEOPLE_LEG, PEOPLE_SPEED, PEOPLE_START, PEOPLE_WAITS
from rei.rooms.generator import GAP

ROOT = Path(__file__).resolve().parents[3]
MAP = ROOT / "examples" / "maps" / "two_rooms.yaml"
SIDES = ((1, 0), (-1, 0), (0, 1), (0, -1))


def _floors(room: Room) -> set[tuple[int, int]]:
    if room.site is not None:
        return set(room.site.free)
    return {(x, y) for x in range(room.width) for y in range(room.height)}


def _along(free: set[tuple[int, int]], a: tuple[int, int]) -> dict[tuple[int, int], int]:
    """Floors from ``a`` along the free floors."""
    seen, queue = {a: 0}, deque([a])
    while queue:
        x, y = queue.popleft()
        for dx, dy in SIDES:
            n = (x + dx, y + dy)
            if n in free and n not in seen:
                seen[n] = seen[(x, y)] + 1
                queue.append(n)
    return seen


def violations(room: Room, humans: int, behaviour: str | None) -> list[str]:
    """The people's rules, checked from the room's geometry rather than the generator's code."""
    problems = []
    furniture = {f.cell: f for f in room.furniture}
    free = _floors(room) - set(furniture)
    if room.walkers or len(room.people) != humans:
        problems.append(f"{len(room.walkers)} humans on lanes, {len(room.people)} people; wanted {humans} people")
    near_start = {room.start, *((room.start[0] + dx, room.start[1] + dy) for dx, dy in SIDES)}
    goals = {g.cell for g in room.goals}
    every = [cell for person in room.people for cell in person.cells()]
    if len(set(every)) != len(every):
        problems.append("two stops on one floor")
    for person in room.people:
        cells = person.cells()
        if not 2 <= len(cells) <= 3:
            problems.append(f"{person.name} has {len(cells)} stops")
        for cell in cells:
            if cell not in free:
                problems.append(f"{person.name} stops on {cell}, which is not a free floor")
            if cell in near_start or cell in goals:
                problems.append(f"{person.name} stops on the start, beside it or on a goal: {cell}")
            if room.site is None:
                for item in room.furniture:
                    if _gap(_rect(item.cell, item.half_extents()), _rect(cell, (0.5, 0.5))) < GAP - 1e-9:
                        problems.append(f"{item.name} reaches into {person.name}'s stop {cell}")
        for a, b in zip(cells, cells[1:] + cells[:1], strict=True):
            apart = _along(free, a).get(b)
            if apart is None:
                problems.append(f"{person.name} cannot walk from {a} to {b} along the free floors")
            elif apart < PEOPLE_LEG:
                problems.append(f"{person.name}'s stops {a} and {b} are {apart} floors apart")
        if not (PEOPLE_SPEED[0] <= person.speed <= PEOPLE_SPEED[1] and 0 <= person.start <= PEOPLE_START
                and all(wait in PEOPLE_WAITS for _, wait in person.stops)):
            problems.append(f"{person.name}: speed {person.speed}, start {person.start}, stops {person.stops}")
        if person.behaviour not in BEHAVIOURS or behaviour not in ("mixed", person.behaviour):
            problems.append(f"{person.name} {person.behaviour}s")
    return problems


def _rect(cell: tuple[int, int], half: tuple[float, float]) -> tuple[float, float, float, float]:
    return (cell[0] + 0.5 - half[0], cell[1] + 0.5 - half[1], cell[0] + 0.5 + half[0], cell[1] + 0.5 + half[1])


def _gap(a: tuple[float, ...], b: tuple[float, ...]) -> float:
    dx, dy = max(b[0] - a[2], a[0] - b[2]), max(b[1] - a[3], a[1] - b[3])
    return max(dx, dy) if dx < 0 or dy < 0 else (dx**2 + dy**2) ** 0.5


@pytest.mark.parametrize("size", list(ROOM_CLASSES))
def test_people_keep_the_rules_over_many_seeds(size: str) -> None:
    for humans in range(1, MAX_HUMANS[size] + 1):
        for behaviour in ("avoids", "mixed"):
            for seed in range(40):
                room = generate_room(size, None, humans, seed, reactive=behaviour)
                assert not violations(room, humans, behaviour), (room.stem, violations(room, humans, behaviour))
                assert len(room.furniture) == ROOM_CLASSES[size].objects(room.density)


def test_the_behaviour_changes_only_the_behaviour_and_mixed_draws_each() -> None:
    rooms = {b: generate_room("medium", "dense", 3, 5, reactive=b) for b in (*BEHAVIOURS, "mixed")}
    def layout(room: Room) -> str:
        return re.sub(r" (avoids|ignores|curious|scared|blocks)\n", "\n", render(room).split("\n", 2)[2])
    assert len({layout(room) for room in rooms.values()}) == 1
    assert [p.behaviour for p in rooms["scared"].people] == ["scared"] * 3
    drawn = {p.behaviour for seed in range(20) for p in generate_room("large", None, 4, seed, reactive="mixed").people}
    assert drawn == set(BEHAVIOURS)


def test_the_same_seed_writes_the_same_people_and_lanes_stay_as_they_were() -> None:
    room = generate_room("medium", None, 2, 7, 2, reactive="curious")
    assert render(room) == render(generate_room("medium", None, 2, 7, 2, reactive="curious"))
    assert room.stem == "medium_sparse_p2-curious_s7_02"
    assert generate_room("medium", None, 2, 7, 2, reactive="avoids").stem == "medium_sparse_p2_s7_02"
    text = render(room)
    assert "--humans 2 --seed 7 --people reactive --behaviour curious` (room 2)" in text
    lines = [line for line in text.splitlines() if line.startswith("    human ")]
    assert len(lines) == 2 and all(re.fullmatch(
        r"    human person\d route \[F_\d_\d( wait \ds)?(, F_\d_\d( wait \ds)?){1,2}\] speed [01](\.\d)?( start \ds)? "
        r"loop curious", line) for line in lines), lines
    # humans on lanes draw from their own sequence: the same room as before people existed
    rails = generate_room("medium", None, 2, 7, 2)
    assert not rails.people and len(rails.walkers) == 2 and rails.stem == "medium_sparse_h2_s7_02"
    assert "trajectory" in render(rails) and "route" not in render(rails)


def test_the_reference_planner_finds_every_leg_beside_people() -> None:
    for seed in range(10):
        room = generate_room("large", None, 4, seed, reactive="mixed")
        assert unplannable_legs(room) == [], room.stem


def test_people_on_a_building_s_map() -> None:
    site = load_site(MAP, 0.5)
    room = generate_map_room(site, "sparse", 2, seed=3, reactive="mixed")
    assert not violations(room, 2, "mixed")
    assert room.stem == "two_rooms_sparse_p2-mixed_s3_01"
    assert render(room) == render(generate_map_room(load_site(MAP, 0.5), "sparse", 2, seed=3, reactive="mixed"))


def test_generated_people_rooms_pass_the_validator(tmp_path: Path) -> None:
    files = []
    for size in ROOM_CLASSES:
        for behaviour in ("avoids", "mixed"):
            for seed in range(30):
                room = generate_room(size, None, MAX_HUMANS[size], seed, reactive=behaviour)
                files.append(tmp_path / f"{room.stem}.rei")
                files[-1].write_text(render(room), encoding="utf-8")
    site = load_site(MAP, 0.5)
    for seed in range(5):
        room = generate_map_room(site, "dense", 3, seed, reactive="mixed")
        files.append(tmp_path / f"{room.stem}.rei")
        files[-1].write_text(render(room, folder=tmp_path), encoding="utf-8")
    assert len(set(files)) == len(files) == 185
    for file in files:
        text = file.read_text(encoding="utf-8")
        humans = int(re.search(r"--humans (\d)", text)[1])  # type: ignore[index]
        assert "trajectory" not in text and len(re.findall(r"\n    human person\d route \[", text)) == humans >= 2, file
    # a person whose stop is on furniture proves the validator judges the people of every file
    broken = tmp_path / "zz_broken.rei"
    room = generate_room("small", None, 2, 1, reactive="avoids")
    item = room.furniture[0]
    broken.write_text(re.sub(r"(human person1 route \[F_\d_\d[^,]*, )F_\d_\d", rf"\g<1>F_{item.cell[0]}_{item.cell[1]}",
                             render(room)), encoding="utf-8")
    java, jar = toolchain.find_java(), toolchain.find_jar("cli")
    done = subprocess.run([str(java.executable), "-XX:TieredStopAtLevel=1", "-jar", str(jar), "validate",
                           *map(str, files), str(broken), "--quiet"],
                          capture_output=True, text=True, timeout=300, check=False)
    output = done.stdout + done.stderr
    reported = {line.split(":", 1)[0] for line in output.splitlines() if ": error:" in line}
    assert reported == {str(broken)}, output[-3000:]
    assert done.returncode == 1


def test_gen_rooms_people_reactive(tmp_path: Path) -> None:
    def generate(out: Path, *options: str) -> subprocess.CompletedProcess[str]:
        return subprocess.run([sys.executable, "-m", "rei.cli", "gen-rooms", "--size", "medium", "--humans", "2",
                               "--count", "2", "--seed", "4", *options, "-o", str(out)],
                              capture_output=True, text=True, timeout=120, check=False)

    done = generate(tmp_path / "a", "--people", "reactive")
    assert done.returncode == 0, done.stderr
    assert done.stdout.count("9 objects, 2 people on routes, 2 goals") == 2, done.stdout
    written = {p.name: p.read_text(encoding="utf-8") for p in (tmp_path / "a").glob("*.rei")}
    assert sorted(written) == ["medium_sparse_p2_s4_01.rei", "medium_sparse_p2_s4_02.rei"]
    assert all(text.count(" route [") == 2 and " avoids\n" in text for text in written.values())
    assert generate(tmp_path / "b", "--people", "reactive").returncode == 0
    assert {p.name: p.read_text(encoding="utf-8") for p in (tmp_path / "b").glob("*.rei")} == written
    mixed = generate(tmp_path / "c", "--people", "reactive", "--behaviour", "mixed")
    assert mixed.returncode == 0 and sorted(p.name for p in (tmp_path / "c").glob("*.rei")) == [
        "medium_sparse_p2-mixed_s4_01.rei", "medium_sparse_p2-mixed_s4_02.rei"]
    lone = generate(tmp_path / "d", "--behaviour", "blocks")
    assert lone.returncode == 2
    assert "--behaviour is the behaviour of people who see the robot: give --people reactive too" in lone.stderr


def test_a_campaign_s_rooms_take_people_and_their_behaviour() -> None:
    base = ROOT / "examples"
    parsed = parse_spec({"groups": [{"name": "g", "rooms": {"size": "small", "humans": 2, "people": "reactive",
                                                             "behaviour": "mixed", "seed": 3}}]}, base=base)
    settings = parsed.groups[0].rooms
    assert settings is not None and settings.reactive == "mixed"
    assert [r.stem for r in settings.generate(1)] == ["small_dense_p2-mixed_s3_01"]
    for rooms, message in [
        ({"size": "small", "behaviour": "curious"}, ("'behaviour' is the behaviour of people who see the robot: give "
                                                    "'people: reactive' too")),
        ({"size": "small", "people": "reactive", "behaviour": "angry"}, ("'behaviour' must be one of avoids, ignores, "
                                                                        "curious, scared, blocks, mixed, got 'angry'")),
        ({"size": "small", "people": "ghosts"}, "'people' must be one of rails, reactive, got 'ghosts'"),
    ]:
        with pytest.raises(SpecError, match=re.escape(message)):
            parse_spec({"groups": [{"name": "g", "rooms": rooms}]}, base=base)
