# SPDX-License-Identifier: EPL-2.0
"""`rei gen-rooms --map`: the rooms it writes on real maps pass the real validator (rei-cli.jar) with the map
named relative to them, and one of them, generated and simulated with real pybullet, is completed by the
reference navigation without touching anything."""

from __future__ import annotations

from pathlib import Path

from rei.run import MissionRunOptions, run_mission
from rei.wamp.recording import read_recording

SHARED_MAPS = Path(__file__).resolve().parents[2].parent / "shared" / "data" / "maps"


def test_rooms_on_real_maps_validate_and_one_is_driven_through(run_cli, repo_root: Path, tmp_path: Path) -> None:
    rooms = tmp_path / "rooms"
    written = run_cli("gen-rooms", "--map", repo_root / "examples" / "maps" / "two_rooms.yaml", "--floor-size", "0.5",
                      "--count", "3", "--seed", "7", "-o", rooms)
    assert written.returncode == 0, written.stdout + written.stderr
    depot = run_cli("gen-rooms", "--map", SHARED_MAPS / "depot.yaml", "--density", "dense", "--humans", "2",
                    "--count", "2", "-o", rooms / "depot")
    assert depot.returncode == 0, depot.stdout + depot.stderr
    files = sorted(rooms.rglob("*.rei"))
    assert len(files) == 5
    validated = run_cli("validate", *files)
    assert validated.returncode == 0, validated.stdout + validated.stderr

    case = tmp_path / "case"
    generated = run_cli("generate", rooms / "two_rooms_sparse_h1_s7_03.rei", "-o", case)
    assert generated.returncode == 0, generated.stderr
    result = run_mission(case, tmp_path / "run", MissionRunOptions(humans=False), run_id="gen")
    assert result.succeeded, [(t.index, t.reason) for t in result.tasks]
    states = read_recording(tmp_path / "run" / "streams" / "state.msgpack")
    assert not any(m.get("contacts") for m in states)
