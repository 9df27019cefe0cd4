# SPDX-License-Identifier: EPL-2.0
"""The base case of a spec with ``rooms:`` settings: one room generated into ``OUT/base/<stem>.rei`` (what
``rei gen-rooms`` with the same settings writes as its first room), which the search then starts from as from a
given ``case:``. Generation is deterministic, so a resumed search finds the same base again.

A spec with mistakes of its own is checked against its base case too (``with_base_case_problems``), so that a name
the base case does not have is reported with them."""

from __future__ import annotations

import dataclasses
import tempfile
from collections.abc import Callable
from pathlib import Path

from rei.campaign.spec import RoomSettings, SpecError
from rei.rooms import render
from rei.rooms.render import ROBOT
from rei.search.spec import SearchSpec

BASE = "base"


def with_base_case(spec: SearchSpec, out: Path, log: Callable[[str], None] = print) -> SearchSpec:
    """``spec`` with its base case: its own ``case``, or the room its ``rooms`` settings generate into ``out``
    (its element names logged: they are what the parameters address)."""
    if spec.rooms is None:
        return spec
    return dataclasses.replace(spec, case=write_base_case(spec.rooms, out, log))


def write_base_case(rooms: RoomSettings, out: Path, log: Callable[[str], None] = print) -> Path:
    """The first room of ``rooms`` written as ``out/base/<stem>.rei``."""
    [room] = rooms.generate(1)
    path = out / BASE / f"{room.stem}.rei"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(render(room, 1, path.parent), encoding="utf-8")
    log(f"base case: {path} (generated room; `rei gen-rooms` with these settings writes the same first room)")
    log(f"  objects: {', '.join(f.name for f in room.furniture) or 'none'}; humans: "
        f"{', '.join([*(w.name for w in room.walkers), *(p.name for p in room.people)]) or 'none'}; robot: {ROBOT}; "
        f"goals: 0 to {len(room.goals) - 1}")
    return path


def with_base_case_problems(error: SpecError) -> SpecError:
    """``error`` (a search spec's mistakes, rei.search.spec.SearchSpecError) with the mistakes its base case finds
    besides: the elements its parameters name that the base case does not have, and their floors
    (rei.search.space), so that every mistake of the spec is reported at once. The base case is opened in the room
    editor's engine for it (a ``rooms:`` one generated into a temporary folder, not into OUT); when that cannot be
    done (no engine), the spec's own mistakes are all there is to report."""
    from rei.edit import EngineError
    from rei.search.candidates import CandidateMaker
    from rei.search.space import Space
    from rei.toolchain import ToolchainError

    unchecked = getattr(error, "unchecked", None)
    if unchecked is None or not unchecked.parameters:
        return error
    try:
        with tempfile.TemporaryDirectory(prefix="rei-search-base-") as folder:
            case = unchecked.case or write_base_case(unchecked.rooms, Path(folder), log=lambda _: None)
            maker = CandidateMaker(case, Path(folder), log=lambda _: None)
            try:
                Space(unchecked.parameters, maker.diagram, maker.palette, humans=unchecked.humans,
                      text=maker.base_text, validate=maker.validate)
            finally:
                maker.close()
    except SpecError as found:  # the base case's mistakes: a name it does not have, or it is not valid itself
        return type(error).of([*error.problems, *found.problems])
    except (EngineError, ToolchainError, OSError):
        return error
    return error
