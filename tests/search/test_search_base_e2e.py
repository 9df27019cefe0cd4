# SPDX-License-Identifier: EPL-2.0
"""`rei search`'s base cases beyond a plain `.rei` file, with the real room generator, room editor engine,
simulation, monitor jar and evaluator. From generated-room settings (``rooms:`` instead of ``case:``): the base case
is written into the search's folder before anything runs, the parameters are checked against it (a name it does
not have is refused at the parameter, with the names it has), and the search runs around it as around a given
case. A base case that imports a user catalogue: its candidates, written elsewhere, import the same catalogue."""

from __future__ import annotations

import json
import shutil
from pathlib import Path
from typing import Any

REPO_ROOT = Path(__file__).resolve().parents[2]
TIMEOUT = 300.0
SPEC = """\
rooms: {size: small, density: sparse, humans: 1, seed: 0}
timeout: 120
parameters:
  - {human: walker1, start: [0, 8]}
  - {object: OBJECT, floor: any}
objectives:
  - {metric: clearance_humans_min}
shrink: {budget: 0}
"""
BASE = Path("base") / "small_sparse_h1_s0_01.rei"


def test_a_parameter_is_checked_against_the_generated_room(tmp_path: Path, run_cli: Any) -> None:
    spec = tmp_path / "rooms.yaml"
    spec.write_text(SPEC.replace("OBJECT", "bin9"), encoding="utf-8")
    result = run_cli("search", spec, "-o", tmp_path / "out", timeout=TIMEOUT)
    assert result.returncode == 2, result.stdout + result.stderr
    assert (f"{spec}:5:14: the base case has no object named 'bin9'; it has bin1, shelf1, bin2, box1, chair1"
            in result.stderr), result.stderr
    assert (tmp_path / "out" / BASE).is_file()  # written first, so the names can be read there
    assert "objects: bin1, shelf1, bin2, box1, chair1; humans: walker1" in result.stdout


def test_a_search_runs_around_the_generated_room(tmp_path: Path, run_cli: Any) -> None:
    spec = tmp_path / "rooms.yaml"
    spec.write_text(SPEC.replace("OBJECT", "bin2"), encoding="utf-8")
    out = tmp_path / "out"
    result = run_cli("search", spec, "-o", out, "--workers", "1", "--budget", "2", timeout=TIMEOUT)
    assert result.returncode in (0, 1), result.stdout + result.stderr
    document = json.loads((out / "search.json").read_text(encoding="utf-8"))
    assert document["case"] == str(out / BASE)
    assert document["counts"]["simulated"] == 2 and document["counts"]["errors"] == 0
    for record in document["evaluations"]:
        if record["status"] == "COMPLETED":
            # a candidate is the generated room edited: its layout and the searched element's new floor
            case = Path(record["case"]).read_text(encoding="utf-8")
            assert "testcase SmallSparse_0_1 {" in case
            assert f"object bin2 : Bin on {record['params']['bin2.floor']}" in case


def test_a_base_case_importing_a_catalogue_is_searched(tmp_path: Path, run_cli: Any) -> None:
    shutil.copy(REPO_ROOT / "examples" / "own_types.rei", tmp_path / "own_types.rei")
    shutil.copytree(REPO_ROOT / "examples" / "catalogues", tmp_path / "catalogues")
    spec = tmp_path / "own.yaml"
    spec.write_text("case: own_types.rei\ntimeout: 120\nshrink: {budget: 0}\n"
                    "parameters: [{object: sofa, floor: any}, {furniture: [Plant], count: [0, 1]}]\n"
                    "objectives: [utility]\n", encoding="utf-8")
    out = tmp_path / "out"
    result = run_cli("search", spec, "-o", out, "--workers", "1", "--budget", "1", timeout=TIMEOUT)
    assert result.returncode in (0, 1), result.stdout + result.stderr
    document = json.loads((out / "search.json").read_text(encoding="utf-8"))
    assert document["counts"]["simulated"] == 1 and document["counts"]["errors"] == 0, document["counts"]
    [record] = [r for r in document["evaluations"] if r["status"] == "COMPLETED"]
    assert 'import "../../catalogues/office.rei"' in Path(record["case"]).read_text(encoding="utf-8")
