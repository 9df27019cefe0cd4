# SPDX-License-Identifier: EPL-2.0
"""What a search leaves besides its runs: ``search.json`` (every figure), ``verdicts.xml`` (JUnit, one test case
per distinct failure) and ``search.html`` (rei.search.report).

``search.json`` (format ``rei-search/2``): the spec's name, sampler, budget and objectives; ``evaluations``, one
record per trial in order (key, status: COMPLETED, ERROR, invalid, unplannable or interrupted; the parameter
values, the run's objective values, whether it only repeated known failures, utility, failures (events, each with
the requirements it violates: rei.search.failures), metrics, seed, fault, candidate and run folder, wall and CPU
seconds, or why it was not simulated); counts; ``failures``, the distinct failures (events) most severe first with
every requirement they violated, every evaluation that found them and their shrunk case; and ``baseline``, a random
search in the same folder (``--sampler random``) for the report's comparison: its sampler, budget, counts, distinct
failures (not shrunk) and evaluations, as the search's own (``baseline_document``), or null.
"""

from __future__ import annotations

import json
import os
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import optuna

from rei.evaluation.junit import write_junit
from rei.search.failures import DistinctFailure, distinct, events_of, failure_verdicts
from rei.search.spec import SearchSpec

#: 2: a failure is an event (kind, element, place, with the requirements it violates); 1 had one per requirement
FORMAT = "rei-search/2"


def records(study: optuna.Study, out: Path) -> list[dict[str, Any]]:
    """One record per trial of ``study``, in order."""
    found = []
    for trial in study.get_trials(deepcopy=False):
        if trial.state == optuna.trial.TrialState.WAITING:
            continue  # enqueued, never asked (a refinement after the budget's last run): no evaluation yet
        attrs = trial.user_attrs
        key = attrs.get("key") or f"{study.study_name}-{trial.number:04d}"
        status = attrs.get("status") or "interrupted"  # running when the search stopped (asked again on resume)
        record: dict[str, Any] = {"key": key, "number": trial.number, "status": status, "params": dict(trial.params)}
        if attrs.get("simulated"):
            record.update({
                "values": attrs.get("values"), "repeat": bool(attrs.get("repeat")),
                "utility": attrs.get("utility"), "sim_duration": attrs.get("sim_duration"),
                "failures": events_of(attrs.get("failures") or [], out / "runs" / key),
                "metrics": attrs.get("metrics"),
                "error": attrs.get("error"), "seed": attrs.get("seed"), "fault": attrs.get("fault"),
                "case": attrs.get("case"), "run": str(out / "runs" / key),
                "report": str(out / "runs" / key / "report.html"),
                "wall": attrs.get("wall"), "cpu": attrs.get("cpu")})
        elif attrs.get("problems"):
            record["problems"] = attrs["problems"]
        found.append(record)
    return found


def counts(evaluations: Sequence[Mapping[str, Any]]) -> dict[str, Any]:
    simulated = [r for r in evaluations if r["status"] in ("COMPLETED", "ERROR")]
    first = next((i + 1 for i, r in enumerate(simulated) if r.get("failures")), None)
    return {"simulated": len(simulated), "errors": sum(r["status"] == "ERROR" for r in simulated),
            "failing": sum(bool(r.get("failures")) for r in simulated),
            "invalid": sum(r["status"] == "invalid" for r in evaluations),
            "unplannable": sum(r["status"] == "unplannable" for r in evaluations),
            "interrupted": sum(r["status"] == "interrupted" for r in evaluations),
            "distinct_failures": len(distinct(simulated)), "first_failure_at": first}


def baseline_document(study: optuna.Study, out: Path, budget: int | None) -> dict[str, Any]:
    """search.json's ``baseline``: a random search's figures, as the search's own but for its failures' shrunk
    cases (a baseline is not shrunk)."""
    evaluations = records(study, out)
    groups = distinct([r for r in evaluations if r["status"] == "COMPLETED"])
    return {"sampler": study.study_name, "budget": budget, "counts": counts(evaluations),
            "failures": [_failure(group, evaluations, None) for group in groups], "evaluations": evaluations}


def write_outputs(spec: SearchSpec, out: Path, study: optuna.Study, shrunk: Mapping[str, Mapping[str, Any]],
                  baseline: Mapping[str, Any] | None = None, *, verdicts: bool = True) -> dict[str, Any]:
    """search.json and, with ``verdicts``, verdicts.xml of ``study``; ``baseline``: a random search's
    (``baseline_document``). search.json's document."""
    evaluations = records(study, out)
    groups = distinct([r for r in evaluations if r["status"] == "COMPLETED"])
    document = {
        "format": FORMAT, "name": spec.name, "case": str(spec.case), "sampler": spec.sampler, "budget": spec.budget,
        "objectives": [{"kind": o.kind, "key": o.key, "direction": o.direction, "of": o.of, "label": o.label}
                       for o in spec.objectives],
        "counts": counts(evaluations),
        "failures": [_failure(group, evaluations, shrunk.get(group.failure.signature)) for group in groups],
        "evaluations": evaluations,
        "baseline": baseline,
    }
    _write_json(out / "search.json", document)
    if not verdicts:
        return document
    cases = {g.failure.signature: (shrunk.get(g.failure.signature) or {}).get("case") or _case_of(g, evaluations)
             for g in groups}
    tally = document["counts"]
    write_junit(out / "verdicts.xml", failure_verdicts(groups, cases, tally["simulated"], tally["errors"]),
                suite=f"rei search {spec.name}",
                properties={"sampler": spec.sampler, "budget": str(spec.budget),
                            "evaluations": str(tally["simulated"])})
    return document


def _case_of(group: DistinctFailure, evaluations: Sequence[Mapping[str, Any]]) -> str:
    return next(str(r.get("case")) for r in evaluations if r["key"] == group.first)


def _failure(group: DistinctFailure, evaluations: Sequence[Mapping[str, Any]],
             shrunk: Mapping[str, Any] | None) -> dict[str, Any]:
    first = next(r for r in evaluations if r["key"] == group.first)
    # the event as its first evaluation had it, with every requirement it violated in any of its evaluations
    return {**group.failure.to_dict(), "requirements": list(group.requirements), "severity": group.severity,
            "worst_utility": group.worst_utility, "evaluations": list(group.keys), "first": group.first,
            "case": first.get("case"), "seed": first.get("seed"), "fault": first.get("fault"), "run": first.get("run"),
            "report": first.get("report"), "shrunk": dict(shrunk) if shrunk else None}


def _write_json(path: Path, document: Mapping[str, Any]) -> None:
    tmp = path.with_name(path.name + ".tmp")
    tmp.write_text(json.dumps(document, indent=2, allow_nan=False, default=str) + "\n", encoding="utf-8")
    os.replace(tmp, path)
