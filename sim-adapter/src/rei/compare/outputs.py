# SPDX-License-Identifier: EPL-2.0
"""The files of a comparison: ``compare.json`` (every figure), ``verdicts.xml`` (JUnit: one test case per
judged metric, and per metric and fault when the pairs carry several faults, a regression a failure) and
``compare.html``."""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any

from rei.compare.analysis import Comparison, MetricComparison
from rei.compare.report import write_compare_report
from rei.compare.runs import Run
from rei.evaluation.junit import write_junit
from rei.evaluation.outcome import Evidence, Verdict

FORMAT = "rei-compare/1"
JSON_FILE = "compare.json"
VERDICTS_FILE = "verdicts.xml"
CLASSNAME = "rei.metrics"


def write_comparison(comparison: Comparison, out: Path) -> dict[str, Path]:
    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    document = to_dict(comparison)
    tmp = out / (JSON_FILE + ".tmp")
    tmp.write_text(json.dumps(document, indent=2, allow_nan=False) + "\n", encoding="utf-8")
    os.replace(tmp, out / JSON_FILE)
    verdicts = [_junit_verdict(m) for m in comparison.metrics if m.status is not None]
    verdicts += [_junit_verdict(m, fault) for fault, metrics in comparison.by_fault for m in metrics
                 if m.status is not None]
    write_junit(out / VERDICTS_FILE, verdicts, suite="rei.compare", classname=CLASSNAME,
                properties={"baseline": str(comparison.baseline), "candidate": str(comparison.candidate),
                            "pairs": str(len(comparison.pairing.pairs)), "thresholds": comparison.thresholds.source})
    return {"json": out / JSON_FILE, "junit": out / VERDICTS_FILE,
            "html": write_compare_report(out, comparison)}


def to_dict(c: Comparison) -> dict[str, Any]:
    p = c.pairing
    return {
        "format": FORMAT, "baseline": str(c.baseline), "candidate": str(c.candidate),
        "thresholds": c.thresholds.source, "regressions": [m.metric.name for m in c.regressions],
        "pairs": [[b.key, k.key] for b, k in p.pairs],
        "only_baseline": [_run(r) for r in p.only_baseline], "only_candidate": [_run(r) for r in p.only_candidate],
        "errors": [{"baseline": _run(b), "candidate": _run(k)} for b, k in p.errors],
        "metrics": {m.metric.name: _metric(m) for m in c.metrics},
        # per fault (canonical text) when the pairs carry more than one: the same figures over its pairs alone
        "fault_regressions": [{"fault": fault, "metric": m.metric.name} for fault, m in c.fault_regressions],
        "by_fault": {fault: {"pairs": sum(1 for b, _ in p.pairs if b.fault == fault),
                             "regressions": [m.metric.name for m in metrics if m.regressed],
                             "metrics": {m.metric.name: _metric(m) for m in metrics}}
                     for fault, metrics in c.by_fault},
    }


def _metric(m: MetricComparison) -> dict[str, Any]:
    d = m.paired
    return {"pairs": d.n, "baseline_mean": m.baseline_mean, "candidate_mean": m.candidate_mean,
            "difference": d.mean, "ci_low": d.low, "ci_high": d.high, "test": d.test, "p": d.p,
            "threshold": None if m.threshold is None else {
                "better": str(m.threshold.better), "worse_by": m.threshold.worse_by, "p": m.threshold.p},
            "verdict": None if m.status is None else str(m.status), "message": m.message}


def _run(r: Run) -> dict[str, Any]:
    return {"key": r.key, "group": r.group, "case": r.case, "variant": r.variant, "seed": r.seed,
            "status": r.status, "error": r.error, "folder": str(r.folder), "fault": r.fault}


def _junit_verdict(m: MetricComparison, fault: str | None = None) -> Verdict:
    """A metric's test case, named ``METRIC under FAULT`` for one fault's pairs."""
    evidence = tuple(Evidence(f"{d.baseline.key} -> {d.candidate.key}: {d.value:+.4g}") for d in m.worst(5))
    name = m.metric.name if fault is None else f"{m.metric.name} under {fault}"
    message = m.message if fault is None else f"under {fault}: {m.message}"
    return Verdict(name, m.status, message, evidence)  # type: ignore[arg-type]
