# SPDX-License-Identifier: EPL-2.0
"""The thesis's tables from run results: statistics over COMPLETED runs, ERROR runs counted apart."""

from __future__ import annotations

import csv
import io
from pathlib import Path

from rei.campaign.aggregate import signal_table, summary_csv, summary_rows, verdict_table
from rei.campaign.report import render
from rei.campaign.results import RunResult


def result(case: str, variant: str, utility: float | None, time: float | None, status: str = "COMPLETED",
           counts: dict[str, int] | None = None, verdicts: dict[str, str] | None = None) -> RunResult:
    return RunResult(key=f"g__{case}__{variant}", group="g", case=case, variant=variant, repetition=0, seed=0,
                     humans=True, fault=None, status=status, error=None if status == "COMPLETED" else "crashed: x",
                     wall_time=1.0, cpu_time=1.0, host="h", sim_duration=time, total_utility=utility,
                     mission_succeeded=status == "COMPLETED", tasks_started=2, tasks_succeeded=2,
                     counts=counts or {}, verdicts=verdicts or {})


RESULTS = [
    result("A", "base", 109, 16.0, counts={"SIG_GEOM_FAR_TRANSIT_CLOSE": 3}, verdicts={"MISSION_SIMPLE": "pass"}),
    result("A", "f1", -174, 20.0, counts={"SIG_GEOM_FAR_TRANSIT_CLOSE": 5, "SIG_MISSION_TASK_FAIL": 1},
           verdicts={"MISSION_SIMPLE": "fail", "MISSION_WITH_HUMAN_TRAJECTORY": "not-applicable"}),
    result("A", "base", 23, 17.0, verdicts={"MISSION_SIMPLE": "error"}),
    result("B", "base", None, None, status="ERROR"),
    result("B", "f1", -8, 1.0, verdicts={"MISSION_SIMPLE": "pass"}),
]


def test_rows_per_room_total_and_variant() -> None:
    rows = {(r.room, r.variant): r for r in summary_rows(RESULTS)}
    a = rows[("A", "*")]
    assert (a.executions, a.errors, a.mean_utility, a.median_utility, a.max_utility, a.min_utility) == (
        3, 0, (109 - 174 + 23) / 3, 23, 109, -174)
    assert (a.mean_time, a.median_time) == (53 / 3, 17.0)
    b = rows[("B", "*")]
    assert (b.executions, b.errors, b.mean_utility) == (1, 1, -8)
    total = rows[("Total", "*")]
    assert (total.executions, total.errors, total.median_utility, total.min_utility) == (4, 1, (23 - 8) / 2, -174)
    assert total.verdict_pass_rate == 2 / 4, "not-applicable verdicts are not judged"
    assert rows[("*", "f1")].executions == 2 and rows[("*", "base")].errors == 1


def test_csv_and_tables() -> None:
    lines = list(csv.DictReader(io.StringIO(summary_csv(RESULTS))))
    assert [(r["room"], r["variant"]) for r in lines] == [("A", "*"), ("B", "*"), ("Total", "*"), ("*", "base"), ("*", "f1")]
    assert lines[0]["mean_utility"] == "-14" and lines[1]["mean_time"] == "1"
    columns, table = signal_table(RESULTS, "case")
    assert columns == ["A", "B"] and dict(table)["SIG_GEOM_FAR_TRANSIT_CLOSE"] == [8, 0]
    verdicts = {req: (counts, rate) for req, counts, rate in verdict_table(RESULTS)}
    assert verdicts["MISSION_SIMPLE"] == ({"pass": 2, "fail": 1, "error": 1}, 0.5)
    assert verdicts["MISSION_WITH_HUMAN_TRAJECTORY"][1] is None


def test_report_has_the_tables_and_one_line_per_completed_mission(tmp_path: Path) -> None:
    events = tmp_path / "runs" / "g__A__base" / "events.csv"
    events.parent.mkdir(parents=True)
    events.write_text("t,signal,utility,total,subject,object\n0,SIG_MISSION_BEGIN,20,20,tb3,mission\n"
                      "4.5,SIG_GEOM_FAR_TRANSIT_CLOSE,-2,18,tb3,wall\n", encoding="utf-8")
    html = render(tmp_path, "demo", RESULTS, {"campaign": {"wall": 10, "cpu": 15, "cores": 2}}, 6)
    assert "5 of 6 runs finished, 1 in ERROR" in html
    assert html.count('class="mission"') == 4
    assert 'data-signal="SIG_GEOM_FAR_TRANSIT_CLOSE" data-count="8"' in html
    assert "crashed: x" in html and "<table class='summary'>" in html
