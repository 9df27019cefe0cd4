# SPDX-License-Identifier: EPL-2.0
"""The rooms benchmarks/generation.py times are valid and lay out as drawn, so its figures measure real work.

It also covers the explicit floor-graph form at a size where a wrong traversal shows: every floor F_x_y names only
its right and top neighbours, so reaching the left and bottom ones needs references followed both ways.
"""

from __future__ import annotations

import importlib.util
import json
import sys
from collections import Counter
from collections.abc import Callable
from pathlib import Path
from types import ModuleType
from typing import Any

import pytest


@pytest.fixture(scope="module")
def benchmark(repo_root: Path) -> ModuleType:
    path = repo_root / "benchmarks" / "generation.py"
    spec = importlib.util.spec_from_file_location("rei_benchmark_generation", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module  # dataclasses look their module up there
    spec.loader.exec_module(module)
    return module


def test_grid_sizes_have_exactly_the_requested_floors(benchmark: ModuleType) -> None:
    assert [benchmark.grid_for(n) for n in (100, 1_000, 10_000, 7)] == [
        (10, 10),
        (40, 25),
        (100, 100),
        (7, 1),
    ]


def test_hundred_floor_room_generates_with_every_floor_on_its_cell(
    benchmark: ModuleType, run_cli: Callable[..., Any], tmp_path: Path
) -> None:
    source = tmp_path / "room100.rei"
    source.write_text(benchmark.room_text(100), encoding="utf-8")
    result = run_cli("generate", source, "-o", tmp_path / "out", "--quiet")
    assert result.returncode == 0, result.stderr
    world = json.loads((tmp_path / "out" / "world.json").read_text(encoding="utf-8"))
    assert {floor["name"]: floor["cell"] for floor in world["floors"]} == {
        f"F_{x}_{y}": [x, y] for x in range(10) for y in range(10)
    }
    assert Counter(obj["category"] for obj in world["objects"]) == {"FLOOR": 100, "WALL": 40, "STATIC": 4}
    assert world["bounds"] == pytest.approx([0.0, 0.0, 10.0, 10.0])
