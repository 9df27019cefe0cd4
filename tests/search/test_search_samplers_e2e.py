# SPDX-License-Identifier: EPL-2.0
"""`rei search --sampler` with each optimizer besides TPE, end to end with the real room editor engine,
generator, simulation, monitor jar and evaluator, on the example's crossing (a person's start time and speed):
short searches of 4 evaluations. Each runs its budget under its own name and in its own study of the journal, and
the journal shows the sampler itself chose points: random's are the draws of Optuna's RandomSampler with the
spec's seed, QMC's (after the first) the Sobol sequence over the ranges, CMA-ES sampled from its distribution (a
generation), NSGA-II with two objectives put its trials in a generation, and search.html shows the Pareto front
of their values."""

from __future__ import annotations

import json
import re
import shutil
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import optuna
import pytest
from scipy.stats.qmc import Sobol

from rei.search.study import journal

REPO_ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = REPO_ROOT / "examples" / "search"
TIMEOUT = 300.0
BUDGET = 4
SEED = 6
SPEC = f"""\
case: crossing.rei
seed: {SEED}
budget: {BUDGET}
timeout: 120
parameters:
  - {{human: walker, start: [5, 11], speed: [0.6, 1.5]}}
objectives:
OBJECTIVES
shrink: {{budget: 0}}
"""
ONE = "  - {metric: clearance_humans_min}"
TWO = "  - utility\n  - {metric: clearance_humans_min}"
SAMPLERS = ("random", "qmc", "cmaes", "nsga2")


@dataclass(frozen=True, slots=True)
class Searched:
    out: Path
    result: Any  # the CliResult
    document: dict[str, Any]  # search.json
    study: optuna.Study  # the sampler's study in the journal


@pytest.fixture(scope="module")
def searches(tmp_path_factory: pytest.TempPathFactory, run_cli: Any) -> dict[str, Searched]:
    folder = tmp_path_factory.mktemp("samplers")
    shutil.copy(EXAMPLE / "crossing.rei", folder / "crossing.rei")
    (folder / "one.yaml").write_text(SPEC.replace("OBJECTIVES", ONE), encoding="utf-8")
    (folder / "two.yaml").write_text(SPEC.replace("OBJECTIVES", TWO), encoding="utf-8")
    found = {}
    for sampler in SAMPLERS:
        out = folder / sampler  # a folder each: a random search beside another would be its baseline
        spec = folder / ("two.yaml" if sampler == "nsga2" else "one.yaml")
        result = run_cli("search", spec, "-o", out, "--sampler", sampler, "--workers", "1", timeout=TIMEOUT)
        document = json.loads((out / "search.json").read_text(encoding="utf-8"))
        study = optuna.load_study(study_name=sampler, storage=journal(out))
        found[sampler] = Searched(out, result, document, study)
    return found


@pytest.mark.parametrize("sampler", SAMPLERS)
def test_each_sampler_runs_its_budget_under_its_own_name(searches: dict[str, Searched], sampler: str) -> None:
    searched = searches[sampler]
    assert searched.result.returncode in (0, 1), searched.result.stdout + searched.result.stderr
    document = searched.document
    assert document["sampler"] == sampler and document["budget"] == BUDGET
    assert document["counts"]["simulated"] == BUDGET and document["counts"]["errors"] == 0
    assert [r["key"] for r in document["evaluations"]] == [f"{sampler}-{n:04d}" for n in range(BUDGET)]
    points = [(r["params"]["walker.start"], r["params"]["walker.speed"]) for r in document["evaluations"]]
    assert len(set(points)) == BUDGET, points  # four points, not one asked four times
    assert all(5 <= start <= 11 and 0.6 <= speed <= 1.5 for start, speed in points), points
    assert len(document["objectives"]) == (2 if sampler == "nsga2" else 1)
    for record in document["evaluations"]:
        assert record["status"] == "COMPLETED" and len(record["values"]) == len(document["objectives"]), record
        assert (searched.out / "runs" / record["key"] / "summary.json").is_file()
    assert [s.study_name for s in optuna.get_all_study_summaries(journal(searched.out))] == [sampler]
    assert (searched.out / "search.html").is_file() and (searched.out / "verdicts.xml").is_file()


def test_random_draws_optunas_random_sampler_with_the_specs_seed(searches: dict[str, Searched]) -> None:
    trials = searches["random"].study.trials
    replay = optuna.create_study(sampler=optuna.samplers.RandomSampler(seed=SEED))
    assert [t.params for t in trials] == [replay.ask(trials[0].distributions).params for _ in trials]


def test_qmc_draws_the_sobol_sequence(searches: dict[str, Searched]) -> None:
    storage = journal(searches["qmc"].out)
    attrs = storage.get_study_system_attrs(storage.get_study_id_from_name("qmc"))
    [last] = [value for key, value in attrs.items() if key.startswith("qmc:")]  # the sequence's last index
    # the first points are drawn independently until the sampler knows the space; the others are the Sobol
    # sequence (unscrambled) over the ranges, in order
    trials = searches["qmc"].study.trials
    ranges = trials[-1].distributions
    assert 1 <= last + 1 <= BUDGET == 4
    sobol = Sobol(d=len(ranges), scramble=False).random_base2(2)[:last + 1]  # 2**2 points: Sobol's balanced n
    for trial, row in zip(trials[-(last + 1):], sobol, strict=True):
        assert trial.params == pytest.approx({name: d.low + x * (d.high - d.low)
                                              for (name, d), x in zip(ranges.items(), row, strict=True)})


def test_cmaes_sampled_from_its_distribution(searches: dict[str, Searched]) -> None:
    generations = [t.system_attrs.get("cma:generation") for t in searches["cmaes"].study.trials]
    assert any(g is not None for g in generations), generations
    assert generations[0] is None  # the start-up trial: drawn independently


def test_nsga2_searches_two_objectives_and_the_report_shows_their_pareto_front(
        searches: dict[str, Searched]) -> None:
    searched = searches["nsga2"]
    generations = [t.system_attrs.get("NSGAIISampler:generation") for t in searched.study.trials]
    assert generations == [0] * BUDGET, generations  # one population of four
    assert [t.values is not None and len(t.values) == 2 for t in searched.study.trials] == [True] * BUDGET
    document = searched.document
    assert [o["label"] for o in document["objectives"]] == ["utility", "metric:clearance_humans_min"]
    assert [o["direction"] for o in document["objectives"]] == ["minimize", "minimize"]
    values = {r["key"]: r["values"] for r in document["evaluations"]}

    def dominates(a: list[float], b: list[float]) -> bool:  # both minimized
        return all(x <= y for x, y in zip(a, b, strict=True)) and a != b

    front = {k for k, v in values.items() if not any(dominates(w, v) for w in values.values())}
    html = (searched.out / "search.html").read_text(encoding="utf-8")
    section = re.search(r'<section id="pareto">.*?</section>', html, re.DOTALL)
    assert section, "no Pareto front in search.html"
    assert set(re.findall(r"<tr><td>([a-z0-9-]+)</td>", section[0])) == front, (section[0], values)
    assert f"{len(front)} of {BUDGET} evaluations" in section[0]
