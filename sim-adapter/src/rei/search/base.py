# SPDX-License-Identifier: EPL-2.0
"""The base case of a spec with ``rooms:`` settings: one room generated into ``OUT/base/<stem>.rei`` (what
``rei gen-rooms`` with the same settings writes as its first room), which the search then starts from as from a
given ``case:``. Generation is deterministic, so a resumed search finds the same base again."""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from pathlib import Path

from rei.rooms import render
from rei.rooms.render import ROBOT
from rei.search.spec import SearchSpec

BASE = "base"


def with_base_case(spec: SearchSpec, out: Path, log: Callable[[str], None] = print) -> SearchSpec:
    """``spec`` with its base case: its own ``case``, or the room its ``rooms`` settings generate into ``out``
    (its element names logged: they are what the parameters address)."""
    if spec.rooms is None:
        return spec
    rooms = spec.rooms
    [room] = rooms.generate(1)
    path = out / BASE / f"{room.stem}.rei"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(render(room, 1, path.parent), encoding="utf-8")
    log(f"base case: {path} (generated room; `rei gen-rooms` with these settings writes the same first room)")
    log(f"  objects: {', '.join(f.name for f in room.furniture) or 'none'}; humans: "
        f"{', '.join(w.name for w in room.walkers) or 'none'}; robot: {ROBOT}; goals: 0 to {len(room.goals) - 1}")
    return dataclasses.replace(spec, case=path)
