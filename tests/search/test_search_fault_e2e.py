# SPDX-License-Identifier: EPL-2.0
"""`rei search` over a lidar blackout's start and duration (#39, "Searchable"), end to end with the real room
editor engine, generator, simulation, monitor jar, evaluator and the reference navigation, which takes a scan
without returns for free space and drives on: examples/search/blackout.yaml, whose person crosses the corridor as
the robot arrives (without a fault the robot waits for them), narrowed to blackouts that cover the crossing. The
search's one evaluation collides with the person; shrinking finds a shorter blackout that still does, and the shrunk
case's reproduce line runs it (three simulations: 23 s on the 2-core machine)."""

from __future__ import annotations

import json
import re
import shutil
from pathlib import Path
from typing import Any

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "search"


def test_a_search_over_a_blackout_finds_a_collision_and_shrinks_the_blackout(tmp_path: Path, run_cli: Any) -> None:
    shutil.copy(EXAMPLE / "blackout.rei", tmp_path / "blackout.rei")
    spec = (EXAMPLE / "blackout.yaml").read_text(encoding="utf-8")
    narrowed = spec.replace("start: [4, 6], duration: [1, 4]", "start: [5.3, 5.5], duration: [1.2, 3]")
    assert narrowed != spec
    (tmp_path / "blackout.yaml").write_text(narrowed.replace("shrink: {budget: 2}", "shrink: {budget: 1}"),
                                            encoding="utf-8")
    out = tmp_path / "out"
    result = run_cli("search", tmp_path / "blackout.yaml", "-o", out, "--workers", "1", "--budget", "1",
                     timeout=600)
    assert result.returncode == 1, result.stdout + result.stderr  # failures found
    document = json.loads((out / "search.json").read_text(encoding="utf-8"))
    [evaluation] = document["evaluations"]
    params = evaluation["params"]
    assert params["fault.kind"] == "blackout", params
    found = f"laser:blackout,from={round(params['fault.start'], 3)!r}," \
            f"to={round(params['fault.start'] + params['fault.duration'], 3)!r}"
    assert evaluation["fault"] == found, evaluation
    # the terminal shows each run's fault
    assert f"fault {found};" in result.stdout, result.stdout

    [collision] = [f for f in document["failures"] if f["signature"].startswith("COLLISION/walker/")]
    assert collision["fault"] == found
    assert collision["what"].endswith(", while laser blackout was active"), collision  # the evaluator's evidence
    shrunk = collision["shrunk"]
    # a shorter blackout, written as the run's --fault, that still collides with the person
    assert shrunk["values"]["fault.duration"] < params["fault.duration"], shrunk
    assert shrunk["values"]["fault.start"] == params["fault.start"]
    assert shrunk["fault"] != found and shrunk["kept"] == 1, shrunk
    summary = json.loads((Path(shrunk["run"]) / "summary.json").read_text(encoding="utf-8"))
    assert next(v["status"] for v in summary["verdicts"] if v["requirement"] == "MISSION_SIMPLE") == "fail"
    sim = json.loads((Path(shrunk["run"]) / "sim.json").read_text(encoding="utf-8"))
    assert [f["kind"] for f in sim["faults"]] == ["blackout"], sim["faults"]
    start, end = (float(v) for v in re.fullmatch(r"laser:blackout,from=([0-9.]+),to=([0-9.]+)",
                                                 shrunk["fault"]).groups())
    # its window's events at the first physics steps at or after its edges
    [window] = summary["faults"]
    assert window["fault"] == "laser blackout", window
    assert 0 <= window["begin"] - start < 0.01 and 0 <= window["end"] - end < 0.01, (window, start, end)
    # the shrunk case's reproduce line carries that fault to `rei run`
    first = Path(shrunk["case"]).read_text(encoding="utf-8").splitlines()[0]
    assert first.endswith(f"--seed 0 --fault {shrunk['fault']}"), first
    html = (out / "search.html").read_text(encoding="utf-8")
    assert f"fault {found}" in html and f"shrunk to fault {shrunk['fault']}" in html
