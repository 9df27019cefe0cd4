# SPDX-License-Identifier: EPL-2.0
"""The campaign's tables, as thesis 7.4-7.5 presents them.

* Execution summary per room, with a total per group (Tables 5, 7): executions, mean/median execution
  (simulated) time, mean/median/max/min utility - over the COMPLETED runs; ERROR runs are counted apart,
  because a crashed run has no utility to average.
* Signal counts per room (Tables 6, 8), per variant and per fault (Tables 9, 10).
* Per fault: when a group's runs carry more than one fault (variants with ``fault``), its summary and metrics get a
  row per fault too (``room`` and ``variant`` ``*``), the fault named by its canonical text (:func:`fault_label`),
  so two variants that write the same fault differently, or differ in something else, count as one fault level.
* Verdict pass rates per requirement: pass / (pass + fail + error); not-applicable verdicts are left out.
* Navigation metrics (docs/metrics.md) with the same rows: mean, median and the 95 % bootstrap interval of the
  mean of each; success as a rate with its Wilson interval (rei.campaign.stats).
"""

from __future__ import annotations

import csv
import io
import statistics
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from functools import lru_cache

from rei.campaign import stats
from rei.campaign.results import RunResult
from rei.evaluation.metrics import LIST_KEYS, METRICS, NAMES, Kind

SUMMARY_COLUMNS = ("group", "room", "variant", "executions", "errors", "mean_time", "median_time",
                   "mean_utility", "median_utility", "max_utility", "min_utility", "missions_succeeded",
                   "verdict_pass_rate", "fault")
TOTAL = "Total"
ALL = "*"
NO_FAULT = "none"


@lru_cache(maxsize=256)
def fault_label(spec: str | None) -> str:
    """The canonical text of a run's ``--fault`` spec: each fault as rei.sim.faults ``format_fault`` writes it,
    joined by ``;``; ``none`` without one. A spec that does not parse (a result written by another version) stays
    as written rather than failing the report."""
    from rei.sim.faults import format_fault, parse_faults

    try:
        faults = parse_faults(spec).faults
    except ValueError:
        return (spec or "").strip() or NO_FAULT
    return ";".join(format_fault(f) for f in faults) or NO_FAULT


@dataclass(frozen=True, slots=True)
class Row:
    """One line of an execution summary: ``room`` is a room, or ``Total``; ``variant`` a variant or ``*``;
    ``fault`` a fault's canonical text (a row per fault) or ``*``."""

    group: str
    room: str
    variant: str
    executions: int
    errors: int
    mean_time: float | None
    median_time: float | None
    mean_utility: float | None
    median_utility: float | None
    max_utility: float | None
    min_utility: float | None
    missions_succeeded: int
    verdict_pass_rate: float | None
    fault: str = ALL

    def values(self) -> tuple[object, ...]:
        return tuple(getattr(self, c) for c in SUMMARY_COLUMNS)


def summarize(group: str, room: str, variant: str, runs: Sequence[RunResult], fault: str = ALL) -> Row:
    done = [r for r in runs if r.status == "COMPLETED"]
    times = [r.sim_duration for r in done if r.sim_duration is not None]
    utilities = [r.total_utility for r in done if r.total_utility is not None]
    return Row(group, room, variant, len(done), len(runs) - len(done), _mean(times), _median(times),
               _mean(utilities), _median(utilities), max(utilities, default=None), min(utilities, default=None),
               sum(bool(r.mission_succeeded) for r in done), pass_rate(runs), fault)


def pass_rate(runs: Iterable[RunResult], requirement: str | None = None) -> float | None:
    judged = [s for r in runs for req, s in r.verdicts.items()
              if (requirement is None or req == requirement) and s in ("pass", "fail", "error")]
    return sum(s == "pass" for s in judged) / len(judged) if judged else None


def summary_rows(results: Sequence[RunResult]) -> list[Row]:
    """Per group: one row per room, the group's total, one row per variant (all rooms), then one row per fault
    when the group's runs carry more than one."""
    rows = []
    for group in _ordered(r.group for r in results):
        runs = [r for r in results if r.group == group]
        for room in _ordered(r.case for r in runs):
            rows.append(summarize(group, room, ALL, [r for r in runs if r.case == room]))
        rows.append(summarize(group, TOTAL, ALL, runs))
        variants = _ordered(r.variant for r in runs)
        if len(variants) > 1:
            for variant in variants:
                rows.append(summarize(group, ALL, variant, [r for r in runs if r.variant == variant]))
        for fault, of_fault in by_fault(runs):
            rows.append(summarize(group, ALL, ALL, of_fault, fault))
    return rows


def by_fault(runs: Sequence[RunResult]) -> list[tuple[str, list[RunResult]]]:
    """``runs`` grouped by their fault's canonical text, in order of appearance; empty when they all carry one
    fault (or none), as a table by fault then says nothing the totals do not."""
    groups: dict[str, list[RunResult]] = {}
    for r in runs:
        groups.setdefault(fault_label(r.fault), []).append(r)
    return list(groups.items()) if len(groups) > 1 else []


METRIC_COLUMNS = ("group", "room", "variant", "metric", "n", "mean", "median", "ci_low", "ci_high", "fault")


@dataclass(frozen=True, slots=True)
class MetricRow:
    """One metric over the COMPLETED runs of a row (as ``summary_rows``): for ``success`` the rate (``mean``) and
    its Wilson interval, else the mean with its bootstrap interval and the median."""

    group: str
    room: str
    variant: str
    metric: str
    n: int
    mean: float | None
    median: float | None
    low: float | None
    high: float | None
    fault: str = ALL

    def values(self) -> tuple[object, ...]:
        return (self.group, self.room, self.variant, self.metric, self.n, self.mean, self.median, self.low,
                self.high, self.fault)


def describe(group: str, room: str, variant: str, runs: Sequence[RunResult], fault: str = ALL) -> list[MetricRow]:
    done = [r for r in runs if r.status == "COMPLETED"]
    rows = []
    for metric in METRICS:
        values = [r.metrics.get(metric.name) for r in done]
        if metric.kind == Kind.BOOL:
            s = stats.rate([v for v in values if isinstance(v, bool)])
            rows.append(MetricRow(group, room, variant, metric.name, s.n, s.rate, None, s.low, s.high, fault))
        else:
            e = stats.estimate([float(v) for v in values if isinstance(v, int | float) and not isinstance(v, bool)])
            rows.append(MetricRow(group, room, variant, metric.name, e.n, e.mean, e.median, e.low, e.high, fault))
    return rows


def metric_rows(results: Sequence[RunResult]) -> list[MetricRow]:
    """Per group: every metric per room, for the group's total, per variant (all rooms), then per fault (as
    ``summary_rows``)."""
    rows = []
    for group in _ordered(r.group for r in results):
        runs = [r for r in results if r.group == group]
        for room in _ordered(r.case for r in runs):
            rows += describe(group, room, ALL, [r for r in runs if r.case == room])
        rows += describe(group, TOTAL, ALL, runs)
        variants = _ordered(r.variant for r in runs)
        if len(variants) > 1:
            for variant in variants:
                rows += describe(group, ALL, variant, [r for r in runs if r.variant == variant])
        for fault, of_fault in by_fault(runs):
            rows += describe(group, ALL, ALL, of_fault, fault)
    return rows


def metrics_csv(rows: Sequence[MetricRow]) -> str:
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(METRIC_COLUMNS)
    for row in rows:
        writer.writerow(_cell(v) for v in row.values())
    return buffer.getvalue()


def signal_table(runs: Sequence[RunResult], by: str) -> tuple[list[str], list[tuple[str, list[int]]]]:
    """(column names, [(signal, counts per column)]) with columns the rooms (``by="case"``), variants
    (``"variant"``) or faults (``"fault"``: their canonical text)."""
    from rei.report.colours import signal_sort_key

    def column(r: RunResult) -> str:
        return fault_label(r.fault) if by == "fault" else getattr(r, by)

    columns = _ordered(column(r) for r in runs)
    signals = sorted({s for r in runs for s in r.counts}, key=signal_sort_key)
    table = [(s, [sum(r.counts.get(s, 0) for r in runs if column(r) == c) for c in columns]) for s in signals]
    return columns, table


def verdict_table(runs: Sequence[RunResult]) -> list[tuple[str, dict[str, int], float | None]]:
    """(requirement, counts per status, pass rate) for every requirement judged in ``runs``."""
    requirements = _ordered(req for r in runs for req in r.verdicts)
    out = []
    for req in requirements:
        counts: dict[str, int] = {}
        for r in runs:
            status = r.verdicts.get(req)
            if status is not None:
                counts[status] = counts.get(status, 0) + 1
        out.append((req, counts, pass_rate(runs, req)))
    return out


def summary_csv(results: Sequence[RunResult]) -> str:
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(SUMMARY_COLUMNS)
    for row in summary_rows(results):
        writer.writerow(_cell(v) for v in row.values())
    return buffer.getvalue()


RUN_COLUMNS = ("key", "group", "case", "variant", "repetition", "seed", "humans", "fault", "status", "error",
               "sim_duration", "total_utility", "mission_succeeded", "tasks_started", "tasks_succeeded",
               "tasks_failed", "wall_time", "cpu_time", "host", "attempt")


def runs_csv(results: Sequence[RunResult]) -> str:
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow((*RUN_COLUMNS, "verdicts_passed", "verdicts_failed", *NAMES, *LIST_KEYS))
    for r in results:
        passed = sum(s == "pass" for s in r.verdicts.values())
        failed = sum(s == "fail" for s in r.verdicts.values())
        metrics = [_cell(r.metrics.get(name)) for name in NAMES]
        lists = [" ".join("" if v is None else f"{v:g}" for v in r.metrics.get(key) or ()) for key in LIST_KEYS]
        writer.writerow((*(_cell(getattr(r, c)) for c in RUN_COLUMNS), passed, failed, *metrics, *lists))
    return buffer.getvalue()


def _cell(value: object) -> object:
    if value is None:
        return ""
    if isinstance(value, float):
        return f"{value:.4g}" if abs(value) < 1e4 else f"{value:.0f}"
    return value


def _mean(values: Sequence[float]) -> float | None:
    return statistics.fmean(values) if values else None


def _median(values: Sequence[float]) -> float | None:
    return statistics.median(values) if values else None


def _ordered(items: Iterable[str]) -> list[str]:
    return list(dict.fromkeys(items))
