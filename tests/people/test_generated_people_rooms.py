# SPDX-License-Identifier: EPL-2.0
"""Generated rooms with people who see the robot (`rei gen-rooms --people reactive`), through the real generator,
people server and pybullet: the pedestrian model takes every person where it stands and every way between its stops
(it refuses a stop off the walkable area, two stops with no way between them, a person who cannot stand where it
starts), and the people walk; a campaign of such rooms runs to the end."""

from __future__ import annotations

import csv
import math
from pathlib import Path

import pytest

from rei.geometry import Twist2D
from rei.rooms import generate_room, render
from rei.sim.simulation import Simulation

STILL = Twist2D(0.0, 0.0)


@pytest.mark.parametrize(("size", "humans", "behaviour", "seed"), [("small", 2, "avoids", 1),
                                                                   ("medium", 3, "mixed", 2),
                                                                   ("large", 4, "mixed", 3)])
def test_the_people_of_a_generated_room_walk_their_routes(run_cli, tmp_path: Path, size: str, humans: int,
                                                          behaviour: str, seed: int) -> None:
    room = generate_room(size, None, humans, seed, reactive=behaviour)
    source = tmp_path / f"{room.stem}.rei"
    source.write_text(render(room), encoding="utf-8")
    folder = tmp_path / "case"
    result = run_cli("generate", source, "-o", folder)
    assert result.returncode == 0, result.stderr
    first = {p.name: room.centre(p.stops[0][0]) for p in room.people}
    farthest = dict.fromkeys(first, 0.0)
    # the model computes every leg between consecutive stops when it starts, and refuses a person it cannot place or
    # a leg it cannot route: the room starts, or this raises
    with Simulation(folder, seed=1) as sim:
        assert sim.crowd is not None
        for k in range(round(30.0 * sim.physics_rate)):
            sim.step(STILL)
            if k % 12 == 0:
                for thing in sim.state().objects:
                    if thing.name in farthest:
                        farthest[thing.name] = max(farthest[thing.name], math.dist(thing.pose[:2], first[thing.name]))
    # every person set off (by 5 s) and walked away from its first stop, round the others who may hold it up
    assert all(distance > 1.0 for distance in farthest.values()), farthest


def test_a_campaign_of_generated_rooms_with_people_runs(run_cli, tmp_path: Path) -> None:
    spec = tmp_path / "people.yaml"
    spec.write_text("name: people\ntimeout: 300\ngroups:\n  - name: reactive\n    rooms: {size: small, density: "
                    "sparse, humans: 2, people: reactive, behaviour: mixed, count: 1, seed: 4}\n", encoding="utf-8")
    out = tmp_path / "out"
    result = run_cli("campaign", spec, "-o", out, "--workers", "1", "--no-service", timeout=600)
    assert result.returncode == 0, result.stdout + result.stderr
    [row] = list(csv.DictReader((out / "runs.csv").open(encoding="utf-8")))
    assert row["status"] == "COMPLETED", row
    assert row["case"] == "small_sparse_p2-mixed_s4_01", row
    text = next((out / "rooms").glob("*.rei")).read_text(encoding="utf-8")
    assert text.count(" route [") == 2 and "trajectory" not in text
