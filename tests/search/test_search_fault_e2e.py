# SPDX-License-Identifier: EPL-2.0
"""`rei search` over a fault on a timeline (#39, "Searchable"), end to end with the real room editor engine,
generator, simulation, monitor jar, evaluator and the reference navigation, in the corridor of
examples/search/blackout.rei, whose person crosses it as the robot arrives (without a fault the robot waits for
them):

* examples/search/blackout.yaml, a lidar blackout: the reference navigation takes a scan without returns for free
  space and drives on;
* examples/search/loss.yaml, the commands lost on their way to the robot: the last one that arrived stays applied,
  so the robot cannot brake.

Each is narrowed to faults that cover the crossing. The search's one evaluation collides with the person;
shrinking finds a shorter fault that still does, and the shrunk case's reproduce line carries it (three
simulations each: the evaluation and a shrinking step for each of its two failures; 23-26 s on the 2-core machine
when idle, 82-89 s at load average 14)."""

from __future__ import annotations

import json
import re
import shutil
from pathlib import Path
from typing import Any

import pytest

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "search"


@pytest.mark.parametrize(("example", "ranges", "narrowed", "fault"), [
    ("blackout", "start: [4, 6], duration: [1, 4]", "start: [5.3, 5.5], duration: [1.2, 3]", "laser blackout"),
    ("loss", "probability: [0.5, 1], start: [4, 6], duration: [1, 4]",
     "probability: [0.9, 1], start: [5.3, 5.5], duration: [1.2, 3]", "commands loss"),
])
def test_a_search_over_a_fault_finds_a_collision_and_shrinks_the_fault(tmp_path: Path, run_cli: Any, example: str,
                                                                      ranges: str, narrowed: str,
                                                                      fault: str) -> None:
    sensor, kind = fault.split()
    shutil.copy(EXAMPLE / "blackout.rei", tmp_path / "blackout.rei")
    spec = (EXAMPLE / f"{example}.yaml").read_text(encoding="utf-8")
    assert ranges in spec
    (tmp_path / "s.yaml").write_text(spec.replace(ranges, narrowed).replace("shrink: {budget: 2}",
                                                                          "shrink: {budget: 1}"), encoding="utf-8")
    out = tmp_path / "out"
    result = run_cli("search", tmp_path / "s.yaml", "-o", out, "--workers", "1", "--budget", "1", timeout=600)
    assert result.returncode == 1, result.stdout + result.stderr  # failures found
    document = json.loads((out / "search.json").read_text(encoding="utf-8"))
    [evaluation] = document["evaluations"]
    params = evaluation["params"]
    assert params["fault.kind"] == kind, params
    # the fault as the fault model writes it: the kind's own values, then its window
    values = "".join(f"{key.removeprefix('fault.')}={round(value, 6)!r},"
                     for key, value in params.items() if key not in ("fault.kind", "fault.start", "fault.duration"))
    found = f"{sensor}:{kind},{values}from={round(params['fault.start'], 3)!r}," \
            f"to={round(params['fault.start'] + params['fault.duration'], 3)!r}"
    assert evaluation["fault"] == found, evaluation
    # the terminal shows each run's fault
    assert f"fault {found};" in result.stdout, result.stdout

    [collision] = [f for f in document["failures"] if f["signature"].startswith("COLLISION/walker/")]
    assert collision["fault"] == found
    assert collision["what"].endswith(f", while {fault} was active"), collision  # the evaluator's evidence
    shrunk = collision["shrunk"]
    # a shorter fault, written as the run's --fault, the same otherwise, that still collides with the person
    assert shrunk["values"]["fault.duration"] < params["fault.duration"], shrunk
    assert {k: v for k, v in shrunk["values"].items() if k != "fault.duration"} == \
        {k: v for k, v in params.items() if k != "fault.duration"}, shrunk
    assert shrunk["fault"] != found and shrunk["kept"] == 1, shrunk
    summary = json.loads((Path(shrunk["run"]) / "summary.json").read_text(encoding="utf-8"))
    assert next(v["status"] for v in summary["verdicts"] if v["requirement"] == "MISSION_SIMPLE") == "fail"
    sim = json.loads((Path(shrunk["run"]) / "sim.json").read_text(encoding="utf-8"))
    assert [(f["sensor"], f["kind"]) for f in sim["faults"]] == [(sensor, kind)], sim["faults"]
    start, end = (float(v) for v in re.fullmatch(rf"{sensor}:{kind},(?:[a-z]+=[0-9.]+,)*from=([0-9.]+),to=([0-9.]+)",
                                                 shrunk["fault"]).groups())
    # its window's events at the first physics steps at or after its edges
    [window] = summary["faults"]
    assert window["fault"] == fault, window
    assert 0 <= window["begin"] - start < 0.01 and 0 <= window["end"] - end < 0.01, (window, start, end)
    # the shrunk case's reproduce line carries that fault to `rei run`
    first = Path(shrunk["case"]).read_text(encoding="utf-8").splitlines()[0]
    assert first.endswith(f"--seed 0 --fault {shrunk['fault']}"), first
    html = (out / "search.html").read_text(encoding="utf-8")
    assert f"fault {found}" in html and f"shrunk to fault {shrunk['fault']}" in html
