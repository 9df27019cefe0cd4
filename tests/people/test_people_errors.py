# SPDX-License-Identifier: EPL-2.0
"""A run whose people the model refuses ends with the person's name and place, not a traceback (docs/people.md,
errors at the start of a run)."""

from __future__ import annotations

import shutil
from collections.abc import Callable
from pathlib import Path


def test_a_person_who_cannot_stand_where_it_starts_is_an_error_line_not_a_traceback(
        run_cli, write_rei: Callable[[str, str], Path], repo_root: Path, tmp_path: Path) -> None:
    # the example map at 0.5 m floors: F_6_4 is free, but the block to its right holds the corridor's wall, so its
    # centre is 0.25 m from the walkable area's edge: no room for a person of radius 0.25 (the language checks floors,
    # the model the bodies on them)
    for name in ("two_rooms.yaml", "two_rooms.pgm"):
        shutil.copy(repo_root / "examples" / "maps" / name, tmp_path / name)
    source = write_rei("edge.rei", """
testcase Edge {
  room Office occupancy "two_rooms.yaml" floorSize 0.5 {
    human ann route [F_6_4, F_4_8] speed 1.2
    robot tb3 : Waffle on F_2_6
  }
  mission Go { goto F_3_6 goto F_4_6 }
  monitor { close 0.25 collision 0.01 }
}
""")
    result = run_cli("sim", source, "-o", tmp_path / "out", "--no-router")
    assert result.returncode == 2, result.stderr
    assert "Traceback" not in result.stderr, result.stderr
    assert "error: ann cannot stand at (3.25, 2.25)" in result.stderr, result.stderr


def test_people_of_rooms_generated_on_half_metre_map_floors_can_stand_where_they_start(
        run_cli, repo_root: Path, tmp_path: Path) -> None:
    # rooms 1 and 2 of this command stopped at their start: 'person2 cannot stand at (2.75, 5.25): ... too close to
    # agent', 'person4 cannot stand at (7.25, 4.25): ... too close to geometry boundaries'
    from rei.geometry import Twist2D
    from rei.sim.simulation import Simulation

    rooms = tmp_path / "rooms"
    result = run_cli("gen-rooms", "--map", repo_root / "examples" / "maps" / "two_rooms.yaml", "--floor-size", "0.5",
                     "--density", "dense", "--humans", "6", "--people", "reactive", "--count", "2", "--seed", "4",
                     "-o", rooms)
    assert result.returncode == 0, result.stderr
    for source in sorted(rooms.glob("*.rei")):
        folder = tmp_path / source.stem
        assert run_cli("generate", source, "-o", folder).returncode == 0
        with Simulation(folder, seed=0) as sim:  # the people model places everyone, or raises
            for _ in range(round(sim.physics_rate)):
                sim.step(Twist2D(0.0, 0.0))
            assert sim.crowd is not None and len(sim.crowd.walkers) == 6
