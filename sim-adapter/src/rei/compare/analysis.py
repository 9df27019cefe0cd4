# SPDX-License-Identifier: EPL-2.0
"""Per metric: the paired difference of candidate and baseline, its interval, a paired test and the verdict.

Continuous metrics and counts: mean difference with its 95 % bootstrap interval and the Wilcoxon signed-rank
test; success: change of the success rate and McNemar's exact test (rei.campaign.stats). The verdict of a metric
with a threshold (rei.compare.thresholds) is ``fail`` when it regressed, ``pass`` when not, ``not-applicable``
when no pair has it (e.g. clearance to humans in rooms without humans); metrics without a threshold are
reported, not judged.

When the pairs carry more than one fault (a campaign whose variants inject different faults), every metric is also
compared and judged over each fault's pairs alone (``Comparison.by_fault``): a regression under one fault level
that the others' pairs would average away shows there, and makes the comparison exit 1 as an overall one does.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from rei.campaign import stats
from rei.compare.runs import CompareError, Pairing, Run, load_side, pair
from rei.compare.thresholds import Threshold, Thresholds, default_thresholds
from rei.evaluation.metrics import METRICS, Better, Kind, Metric
from rei.evaluation.outcome import Status


@dataclass(frozen=True, slots=True)
class Difference:
    baseline: Run
    candidate: Run
    value: float  # candidate - baseline (success: -1, 0 or 1)


@dataclass(frozen=True, slots=True)
class MetricComparison:
    metric: Metric
    paired: stats.Paired
    baseline_mean: float | None
    candidate_mean: float | None
    differences: tuple[Difference, ...]
    threshold: Threshold | None
    status: Status | None  # None: no threshold, reported only
    message: str

    @property
    def regressed(self) -> bool:
        return self.status == Status.FAIL

    def worst(self, count: int) -> list[Difference]:
        """The pairs that changed most for the worse (by the threshold's or the metric's direction)."""
        sign = _worse_sign(self.threshold.better if self.threshold else self.metric.better)
        if sign == 0:  # no direction: the largest changes either way
            return sorted((d for d in self.differences if d.value != 0), key=lambda d: -abs(d.value))[:count]
        return sorted((d for d in self.differences if sign * d.value > 0), key=lambda d: -sign * d.value)[:count]


@dataclass(frozen=True, slots=True)
class Comparison:
    baseline: Path
    candidate: Path
    pairing: Pairing
    thresholds: Thresholds
    metrics: tuple[MetricComparison, ...]
    #: per fault (canonical text), every metric over that fault's pairs; empty when the pairs share one fault
    by_fault: tuple[tuple[str, tuple[MetricComparison, ...]], ...] = ()

    @property
    def regressions(self) -> list[MetricComparison]:
        return [m for m in self.metrics if m.regressed]

    @property
    def fault_regressions(self) -> list[tuple[str, MetricComparison]]:
        """(fault, metric) for every metric that regressed over one fault's pairs."""
        return [(fault, m) for fault, metrics in self.by_fault for m in metrics if m.regressed]

    @property
    def exit_code(self) -> int:
        """0: no regression; 1: at least one metric regressed, overall or under one fault."""
        return 1 if self.regressions or self.fault_regressions else 0


def compare(baseline: Path, candidate: Path, thresholds: Thresholds | None = None) -> Comparison:
    """Pair the two sides' runs and compare every metric; raises CompareError when nothing pairs."""
    thresholds = thresholds or default_thresholds()
    pairing = pair(load_side(baseline), load_side(candidate))
    if not pairing.pairs:
        raise CompareError(
            f"no run of {candidate} pairs with one of {baseline} (same group, case, variant, seed and fault, both "
            f"COMPLETED): {len(pairing.only_baseline)} only in the baseline, {len(pairing.only_candidate)} only "
            f"in the candidate, {len(pairing.errors)} with a side in ERROR")
    by_metric = {t.metric: t for t in thresholds.items}
    results = tuple(_compare_metric(m, pairing.pairs, by_metric.get(m.name)) for m in METRICS)
    faults: dict[str, list[tuple[Run, Run]]] = {}
    for b, c in pairing.pairs:
        faults.setdefault(b.fault, []).append((b, c))
    by_fault = tuple((fault, tuple(_compare_metric(m, tuple(pairs), by_metric.get(m.name)) for m in METRICS))
                     for fault, pairs in faults.items()) if len(faults) > 1 else ()
    return Comparison(Path(baseline), Path(candidate), pairing, thresholds, results, by_fault)


def _compare_metric(metric: Metric, pairs: tuple[tuple[Run, Run], ...], threshold: Threshold | None,
                    ) -> MetricComparison:
    differences = []
    for b, c in pairs:
        x, y = b.metrics.get(metric.name), c.metrics.get(metric.name)
        if metric.kind == Kind.BOOL:
            if isinstance(x, bool) and isinstance(y, bool):
                differences.append(Difference(b, c, float(int(y) - int(x))))
        elif _number(x) and _number(y):
            differences.append(Difference(b, c, float(y) - float(x)))
    if metric.kind == Kind.BOOL:
        paired = stats.paired_success([(bool(d.baseline.metrics[metric.name]), bool(d.candidate.metrics[metric.name]))
                                       for d in differences])
    else:
        paired = stats.paired_continuous([d.value for d in differences])
    base = _mean([float(d.baseline.metrics[metric.name]) for d in differences])
    cand = _mean([float(d.candidate.metrics[metric.name]) for d in differences])
    status, message = _verdict(metric, paired, threshold)
    return MetricComparison(metric, paired, base, cand, tuple(differences), threshold, status, message)


def _verdict(metric: Metric, paired: stats.Paired, threshold: Threshold | None) -> tuple[Status | None, str]:
    unit = f" {metric.unit}" if metric.unit else ""
    if paired.n == 0 or paired.mean is None:
        return (Status.NOT_APPLICABLE if threshold else None), f"{metric.name}: no pair has this metric"
    interval = "" if paired.low is None else f" [95 % CI {paired.low:+.4g}, {paired.high:+.4g}]"
    test = "McNemar exact" if paired.test == "mcnemar-exact" else "Wilcoxon"
    facts = (f"{metric.name}: mean difference {paired.mean:+.4g}{unit}{interval} over {paired.n} pair(s), "
             f"{test} p = {paired.p:.3g}")
    if threshold is None:
        return None, facts
    worse = _worse_sign(threshold.better) * paired.mean
    significant = threshold.p is None or (paired.p is not None and paired.p < threshold.p)
    if worse > threshold.worse_by and significant:
        return Status.FAIL, f"{facts}: regression ({threshold.describe()})"
    return Status.PASS, f"{facts}: no regression ({threshold.describe()})"


def _worse_sign(better: Better) -> int:
    """+1 when a larger value is worse, -1 when a smaller one is, 0 when neither."""
    return {Better.HIGHER: -1, Better.LOWER: 1}.get(better, 0)


def _number(value: object) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


def _mean(values: list[float]) -> float | None:
    return sum(values) / len(values) if values else None
