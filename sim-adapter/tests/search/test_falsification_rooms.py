# SPDX-License-Identifier: EPL-2.0
"""The falsification benchmark's rooms kept as search specs (benchmarks/falsification/): each parses as a search
spec against its base case, and the parameters and objectives benchmarks/falsification.py takes from it read back
the same in the specs it writes."""

from __future__ import annotations

import importlib.util
import shutil
from pathlib import Path

from rei.search.spec import load_search_spec

REPO = Path(__file__).resolve().parents[3]


def _benchmark():  # type: ignore[no-untyped-def]
    spec = importlib.util.spec_from_file_location("falsification", REPO / "benchmarks" / "falsification.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_the_doorways_room_parses_and_the_benchmark_writes_the_same_parameters(tmp_path: Path) -> None:
    own = load_search_spec(REPO / "benchmarks" / "falsification" / "doorways.yaml")
    assert [p.key for p in own.parameters] == ["early.start", "early.speed", "late.start", "late.speed"]
    case, body = _benchmark().ROOMS["doorways"]
    assert case == own.case
    shutil.copy(case, tmp_path / case.name)
    written = tmp_path / "doorways-reference-1.yaml"
    written.write_text(f"name: doorways-reference\ncase: {case.name}\ncontroller: nav\nseed: 1\n{body}",
                       encoding="utf-8")
    spec = load_search_spec(written)
    assert _what(spec.parameters) == _what(own.parameters) and spec.objectives == own.objectives


def _what(parameters: tuple) -> list[tuple]:  # type: ignore[type-arg]
    # what each parameter changes and over which domain; its place in the file differs
    return [(p.target, p.name, p.prop, p.domain) for p in parameters]
