# SPDX-License-Identifier: EPL-2.0
"""The random baseline of the docs' recipe, end to end on the crossing example (real engine, simulation, monitor,
evaluator): `rei search SPEC -o OUT` then `rei search SPEC -o OUT --sampler random` keeps the search's own outputs
(verdicts.xml as it was, search.json's figures the search's) and puts the baseline's evaluations and figures beside
them in search.json and search.html; the search run again afterwards (nothing left to run) shows both too."""

from __future__ import annotations

import json
import shutil
from pathlib import Path
from typing import Any

REPO_ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = REPO_ROOT / "examples" / "search"
TIMEOUT = 300.0


def search_json(out: Path) -> dict[str, Any]:
    return json.loads((out / "search.json").read_text(encoding="utf-8"))


def test_the_random_baseline_in_the_search_s_folder_keeps_the_search_s_outputs(tmp_path: Path, run_cli: Any) -> None:
    for name in ("crossing.rei", "crossing.yaml"):
        shutil.copy(EXAMPLE / name, tmp_path / name)
    spec, out = tmp_path / "crossing.yaml", tmp_path / "out"
    # one worker: the candidates are the same whatever the load; no shrinking: its outputs are the unit tests'
    searched = run_cli("search", spec, "-o", out, "--workers", "1", "--budget", "2", "--no-shrink", timeout=TIMEOUT)
    assert searched.returncode in (0, 1), searched.stdout + searched.stderr
    verdicts = (out / "verdicts.xml").read_bytes()
    main = search_json(out)
    assert main["sampler"] == "tpe" and main["baseline"] is None and main["counts"]["simulated"] == 2

    baseline = run_cli("search", spec, "-o", out, "--workers", "1", "--budget", "2", "--sampler", "random",
                       "--no-shrink", timeout=TIMEOUT)
    assert baseline.returncode in (0, 1), baseline.stdout + baseline.stderr
    assert "random baseline of the tpe search" in baseline.stdout
    assert (out / "verdicts.xml").read_bytes() == verdicts
    document = search_json(out)
    side = document.pop("baseline")
    assert document == {k: v for k, v in main.items() if k != "baseline"}  # the search's figures as they were
    assert side["sampler"] == "random" and side["counts"]["simulated"] == 2
    simulated = [r for r in side["evaluations"] if r["status"] in ("COMPLETED", "ERROR")]
    assert len(simulated) == 2 and all(r["key"].startswith("random-") for r in side["evaluations"])
    assert all((out / "runs" / r["key"] / "result.json").is_file() for r in simulated)
    page = (out / "search.html").read_text(encoding="utf-8")
    assert "rei search crossing (tpe)" in page and 'id="baseline"' in page and "random baseline" in page

    again = run_cli("search", spec, "-o", out, "--workers", "1", "--budget", "2", "--no-shrink", timeout=TIMEOUT)
    assert again.returncode == searched.returncode, again.stdout + again.stderr
    assert "2 finished already, 0 to run" in again.stdout
    assert (out / "verdicts.xml").read_bytes() == verdicts
    assert search_json(out)["baseline"] == side and 'id="baseline"' in (out / "search.html").read_text("utf-8")
