# SPDX-License-Identifier: EPL-2.0
"""The campaign's navigation statistics: bootstrap intervals, Wilson rates, paired tests, the metrics table."""

from __future__ import annotations

import csv
import io
import math
from pathlib import Path

import numpy as np
import pytest

from rei.campaign import stats
from rei.campaign.aggregate import metric_rows, metrics_csv, runs_csv
from rei.campaign.report import render
from rei.campaign.results import RunResult
from rei.evaluation.metrics import NAMES


def run(case: str, variant: str, seed: int, status: str = "COMPLETED", **metrics: object) -> RunResult:
    return RunResult(key=f"g__{case}__{variant}__{seed}", group="g", case=case, variant=variant, repetition=seed,
                     seed=seed, humans=True, fault=None, status=status, error=None, wall_time=1.0, cpu_time=1.0,
                     host="h", metrics=dict.fromkeys(NAMES) | metrics)


def test_the_bootstrap_interval_holds_the_mean_and_narrows_with_more_data() -> None:
    rng = np.random.default_rng(3)
    few, many = rng.normal(1.0, 0.2, 8), rng.normal(1.0, 0.2, 200)
    a, b = stats.estimate(few.tolist()), stats.estimate(many.tolist())
    assert a.low < a.mean < a.high and b.low < b.mean < b.high
    assert b.high - b.low < a.high - a.low
    # the percentile bootstrap of a mean is near the normal interval for a normal sample
    half = 1.96 * many.std(ddof=1) / math.sqrt(len(many))
    assert (b.high - b.low) / 2 == pytest.approx(half, rel=0.15)
    assert stats.estimate([2.0]) == stats.Estimate(1, 2.0, 2.0, None, None)
    assert stats.estimate([0.5, 0.5, 0.5]) == stats.Estimate(3, 0.5, 0.5, 0.5, 0.5)
    assert stats.estimate([]).n == 0 and stats.estimate([math.nan]).mean is None


def test_wilson_interval_of_a_success_rate() -> None:
    r = stats.rate([True] * 7 + [False] * 3 + [None])
    assert (r.n, r.k, r.rate) == (10, 7, 0.7)
    z = 1.959963984540054  # Wilson's score interval, written out
    centre, half = (7 + z * z / 2) / (10 + z * z), z / (10 + z * z) * math.sqrt(7 * 3 / 10 + z * z / 4)
    assert (r.low, r.high) == pytest.approx((centre - half, centre + half))
    all_good = stats.rate([True] * 5)
    assert all_good.high == pytest.approx(1.0) and all_good.low < 1.0  # never an interval of nothing


def test_paired_tests() -> None:
    same = stats.paired_continuous([0.0] * 6)
    assert (same.mean, same.low, same.high, same.p) == (0.0, 0.0, 0.0, 1.0)
    worse = stats.paired_continuous([-0.1, -0.12, -0.08, -0.11, -0.09, -0.1, -0.13, -0.1])
    assert worse.mean < 0 and worse.high < 0 and worse.p < 0.01  # exact signed-rank test: 2 / 2**8
    assert worse.p == pytest.approx(2 / 2**8)
    # McNemar's exact test: 6 successes lost, none gained -> two-sided binomial p = 2 * 0.5**6
    lost = stats.paired_success([(True, False)] * 6 + [(True, True)] * 4)
    assert lost.mean == pytest.approx(-0.6) and lost.p == pytest.approx(2 * 0.5**6)
    assert stats.paired_success([(True, True), (False, False)]).p == 1.0


def test_metrics_per_room_total_and_variant_over_completed_runs() -> None:
    results = [run("A", "base", 0, success=True, clearance_static_min=0.2),
               run("A", "base", 1, success=False, clearance_static_min=0.1),
               run("A", "worse", 0, success=True, clearance_static_min=0.05),
               run("B", "base", 0, status="ERROR"),
               run("B", "worse", 0, success=True, clearance_static_min=0.0)]
    rows = {(r.room, r.variant, r.metric): r for r in metric_rows(results)}
    a = rows[("A", "*", "clearance_static_min")]
    assert a.n == 3 and a.mean == pytest.approx(0.35 / 3) and a.median == 0.1 and a.low <= a.mean <= a.high
    assert rows[("B", "*", "clearance_static_min")].n == 1  # the ERROR run has no metrics to average
    total = rows[("Total", "*", "success")]
    assert (total.n, total.mean) == (4, 0.75) and total.median is None and 0 < total.low < 0.75 < total.high
    assert rows[("*", "worse", "clearance_static_min")].mean == pytest.approx(0.025)
    assert rows[("A", "*", "clearance_humans_min")].n == 0  # a room without humans: nothing to average
    table = list(csv.DictReader(io.StringIO(metrics_csv(metric_rows(results)))))
    assert {k: v for k, v in table[0].items() if not k.startswith("ci_")} == {
        "group": "g", "room": "A", "variant": "*", "metric": "success", "n": "3", "mean": "0.6667", "median": "",
        "fault": "*"}  # a row per fault only when the runs carry several
    # 2 of 3: the Wilson score interval, by its formula (z = 1.96), around the rate and inside [0, 1]
    z, rate, n = 1.959964, 2 / 3, 3
    centre = (rate + z**2 / (2 * n)) / (1 + z**2 / n)
    half = z * math.sqrt(rate * (1 - rate) / n + z**2 / (4 * n**2)) / (1 + z**2 / n)
    low, high = float(table[0]["ci_low"]), float(table[0]["ci_high"])
    assert 0 < low < 2 / 3 < high <= 1
    assert low == pytest.approx(centre - half, abs=1e-4) and high == pytest.approx(centre + half, abs=1e-4)
    runs = list(csv.DictReader(io.StringIO(runs_csv(results))))
    assert runs[0]["clearance_static_min"] == "0.2" and runs[0]["success"] == "True"
    html = render(Path("."), "c", results, {}, 5)
    assert "id='metrics-g'" in html and "clearance_static_min [m]" in html


SOCIAL = ["intimate_time", "intimate_share", "personal_time", "personal_share", "social_time", "social_share",
          "ttc_humans_min", "collisions_robot_at_fault", "collisions_person_at_fault", "path_irregularity_humans"]


def test_runs_csv_and_the_metrics_table_carry_the_social_metrics() -> None:
    """The social metrics (docs/metrics.md "People") are columns of runs.csv after collision_objects, and rows of
    metrics.csv like any other: a run without people has none of them to average."""
    results = [run("A", "base", 0, intimate_time=1.5, ttc_humans_min=2.25, collisions_robot_at_fault=1),
               run("A", "base", 1, intimate_time=0.5, ttc_humans_min=None, collisions_robot_at_fault=0),
               run("B", "base", 0)]  # no people: every social metric None
    header = runs_csv(results).splitlines()[0].split(",")
    start = header.index("collision_objects") + 1
    assert header[start:start + len(SOCIAL)] == SOCIAL
    runs = list(csv.DictReader(io.StringIO(runs_csv(results))))
    assert [(r["intimate_time"], r["ttc_humans_min"], r["collisions_robot_at_fault"]) for r in runs] == [
        ("1.5", "2.25", "1"), ("0.5", "", "0"), ("", "", "")]
    rows = {(r.room, r.metric): r for r in metric_rows(results) if r.variant == "*"}
    assert (rows[("A", "intimate_time")].n, rows[("A", "intimate_time")].mean) == (2, 1.0)
    assert (rows[("A", "ttc_humans_min")].n, rows[("A", "collisions_robot_at_fault")].mean) == (1, 0.5)
    assert rows[("B", "intimate_time")].n == 0
    assert "collisions_robot_at_fault" in render(Path("."), "c", results, {}, 5)
