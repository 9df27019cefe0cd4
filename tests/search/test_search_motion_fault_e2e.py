# SPDX-License-Identifier: EPL-2.0
"""`rei search` over a motion fault (#39, "Searchable"), end to end with the real room editor engine, generator,
simulation, monitor jar, evaluator and the reference navigation: examples/search/loss.yaml, the commands lost on
their way to the robot while a person crosses its corridor (the last command that arrived stays applied, so the
robot cannot brake), narrowed to losses that cover the crossing. The search's one evaluation collides with the
person; shrinking finds shorter losses that still do (two simulations)."""

from __future__ import annotations

import json
import re
import shutil
from pathlib import Path
from typing import Any

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "search"


def test_a_search_over_command_loss_finds_a_collision_and_shrinks_the_loss(tmp_path: Path, run_cli: Any) -> None:
    shutil.copy(EXAMPLE / "blackout.rei", tmp_path / "blackout.rei")
    spec = (EXAMPLE / "loss.yaml").read_text(encoding="utf-8")
    narrowed = spec.replace("probability: [0.5, 1], start: [4, 6], duration: [1, 4]",
                            "probability: [0.9, 1], start: [5.3, 5.5], duration: [1.2, 3]")
    assert narrowed != spec
    (tmp_path / "loss.yaml").write_text(narrowed.replace("shrink: {budget: 2}", "shrink: {budget: 1}"),
                                        encoding="utf-8")
    out = tmp_path / "out"
    result = run_cli("search", tmp_path / "loss.yaml", "-o", out, "--workers", "1", "--budget", "1", timeout=600)
    assert result.returncode == 1, result.stdout + result.stderr  # failures found
    document = json.loads((out / "search.json").read_text(encoding="utf-8"))
    [evaluation] = document["evaluations"]
    params = evaluation["params"]
    assert params["fault.kind"] == "loss", params
    start, end = params["fault.start"], params["fault.start"] + params["fault.duration"]
    found = f"commands:loss,probability={round(params['fault.probability'], 6)!r}," \
            f"from={round(start, 3)!r},to={round(end, 3)!r}"
    assert evaluation["fault"] == found, evaluation
    assert f"fault {found};" in result.stdout, result.stdout

    [collision] = [f for f in document["failures"] if f["signature"].startswith("COLLISION/walker/")]
    assert collision["fault"] == found
    assert collision["what"].endswith(", while commands loss was active"), collision  # the evaluator's evidence
    shrunk = collision["shrunk"]
    # shorter losses, written as the run's --fault, with the same probability, that still collide with the person
    assert shrunk["values"]["fault.duration"] < params["fault.duration"], shrunk
    assert shrunk["values"]["fault.probability"] == params["fault.probability"]
    assert shrunk["fault"] != found and shrunk["kept"] == 1, shrunk
    summary = json.loads((Path(shrunk["run"]) / "summary.json").read_text(encoding="utf-8"))
    assert next(v["status"] for v in summary["verdicts"] if v["requirement"] == "MISSION_SIMPLE") == "fail"
    sim = json.loads((Path(shrunk["run"]) / "sim.json").read_text(encoding="utf-8"))
    assert [(f["sensor"], f["kind"]) for f in sim["faults"]] == [("commands", "loss")], sim["faults"]
    start, end = (float(v) for v in re.fullmatch(r"commands:loss,probability=[0-9.]+,from=([0-9.]+),to=([0-9.]+)",
                                                 shrunk["fault"]).groups())
    [window] = summary["faults"]
    assert window["fault"] == "commands loss", window
    assert 0 <= window["begin"] - start < 0.01 and 0 <= window["end"] - end < 0.01, (window, start, end)
    # the shrunk case's reproduce line carries that fault to `rei run`
    first = Path(shrunk["case"]).read_text(encoding="utf-8").splitlines()[0]
    assert first.endswith(f"--seed 0 --fault {shrunk['fault']}"), first
