# SPDX-License-Identifier: EPL-2.0
"""Worlds beyond pybullet's loadSDF limit have their walls and floors merged into bodies of up to 16 boxes
(rei.sim.world_loader). The fixture room loaded merged runs as loaded one body per model: the same drive gives
the same path (to millimetres once pushed against walls: the contact solver meets a compound shape, not boxes), the
same scans, and contacts named after the wall touched, from the same state sample on (or the next)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pybullet as p
import pytest

from rei.artifacts import Category, read_world
from rei.geometry import Twist2D
from rei.sim import world_loader
from rei.sim.simulation import Simulation

# Backwards into the left wall, forwards, then turning across the room into the bottom wall.
DRIVE = [(Twist2D(-0.25, 0.0), 4.0), (Twist2D(0.25, 0.0), 1.5), (Twist2D(0.2, -0.4), 4.0), (Twist2D(0.26, 0.0), 6.0)]


def _run(room: Path) -> tuple[list[tuple], int]:
    samples = []
    with Simulation(room, humans=False) as sim:
        for body, boxes in sim.world.merged.items():  # every box is in its body (pybullet drops extra children)
            low, high = p.getAABB(body, physicsClientId=sim.client)
            assert len(boxes.names) <= world_loader.COMPOUND_LIMIT
            assert (boxes.centres - boxes.half >= np.array(low[:2]) - 1e-9).all()
            assert (boxes.centres + boxes.half <= np.array(high[:2]) + 1e-9).all()
        for cmd, seconds in DRIVE:
            for step in range(round(seconds * sim.physics_rate)):
                sim.step(cmd)
                if step % 12 == 0:  # 20 Hz, the collector's rate
                    state = sim.state()
                    samples.append((state.t, state.robot.pose, state.contacts, state.robot.laser_min))
        return samples, p.getNumBodies(physicsClientId=sim.client)


def _first_contacts(samples: list[tuple]) -> dict[str, int]:
    first: dict[str, int] = {}
    for index, (_, _, contacts, _) in enumerate(samples):
        for _, name in contacts:
            first.setdefault(name, index)
    return first


def test_a_merged_world_runs_as_the_world_of_one_body_per_model(room: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    separate, separate_bodies = _run(room)
    monkeypatch.setattr(world_loader, "MERGE_ABOVE", 0)
    merged, merged_bodies = _run(room)
    fixed = [o for o in read_world(room / "world.json").objects if o.category in (Category.WALL, Category.FLOOR)]
    walls = sum(o.category is Category.WALL for o in fixed)
    chunks = -(-walls // world_loader.COMPOUND_LIMIT) - (-(len(fixed) - walls) // world_loader.COMPOUND_LIMIT)
    assert len(fixed) > 4 and merged_bodies == separate_bodies - len(fixed) + chunks
    first = _first_contacts(separate)
    assert "W_0_0_left" in first and any(name.endswith("_bottom") for name in first), first
    again = _first_contacts(merged)
    assert again.keys() == first.keys()
    assert all(abs(again[name] - first[name]) <= 1 for name in first), (again, first)  # within one sample
    for a, b in zip(merged, separate, strict=True):
        assert a[0] == b[0]
        np.testing.assert_allclose(a[1][:2], b[1][:2], atol=0.02)  # 8 mm apart at most after two pushes
        assert a[3] == pytest.approx(b[3], abs=0.02)
