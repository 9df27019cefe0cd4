# SPDX-License-Identifier: EPL-2.0
"""A world beyond pybullet's loadSDF limit (its walls merged into compound bodies, its floors on the ground slab)
is as deterministic as a small one: Nav2's depot (1,327 walls), the same seed, twice, gives byte-identical state
and mission streams, including the contacts of a drive backwards into its west wall."""

from __future__ import annotations

import json
from pathlib import Path

from rei.run import MissionRunOptions, run_mission
from rei.sim.world_loader import MERGE_ABOVE
from rei.wamp.recording import read_recording

REPO = Path(__file__).resolve().parents[2]
DEPOT = REPO.parent / "shared" / "data" / "maps" / "depot.yaml"
WEST_WALL = "W_map_1_122"  # beside F_1_8, x 0.05..0.15 m


def test_a_merged_world_run_twice_with_one_seed_gives_byte_identical_streams(run_cli, tmp_path: Path) -> None:
    rei = tmp_path / "wall.rei"
    rei.write_text(f"""testcase IntoTheWall {{
  room Depot occupancy "{DEPOT}" floorSize 1.0 {{
    robot tb3 : Waffle on F_1_8
  }}
  mission Back {{ timeout 6s goto F_1_8 goto F_14_8 }}
}}
""", encoding="utf-8")
    case = tmp_path / "case"
    generated = run_cli("generate", rei, "-o", case)
    assert generated.returncode == 0, generated.stdout + generated.stderr
    assert len(json.loads((case / "world.json").read_text())["objects"]) > MERGE_ABOVE  # merged, not one per model
    script = tmp_path / "backwards.script"
    script.write_text("# backwards from x = 1.5 into the west wall at 0.26 m/s, pushing the last second\n"
                      "6.0 -0.26 0.0\n", encoding="utf-8")
    streams = []
    for attempt in ("a", "b"):
        out = tmp_path / attempt
        options = MissionRunOptions(controller=f"script:{script}", seed=5, fault="laser:1%")
        run_mission(case, out, options, run_id="depot")
        streams.append([(out / "streams" / name).read_bytes() for name in ("state.msgpack", "mission.msgpack")])
    assert streams[0] == streams[1]
    states = read_recording(tmp_path / "a" / "streams" / "state.msgpack")
    assert states[-1]["t"] >= 5.9
    assert ["tb3", WEST_WALL] in [c for m in states for c in (m.get("contacts") or [])]  # it met the wall
