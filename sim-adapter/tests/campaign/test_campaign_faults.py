# SPDX-License-Identifier: EPL-2.0
"""A campaign's tables per fault: runs grouped by their fault's canonical text, so two variants that write the
same fault differently are one fault level, and a campaign of one fault gets no such rows."""

from __future__ import annotations

import csv
import io
from pathlib import Path

from rei.campaign.aggregate import (
    fault_label,
    metric_rows,
    metrics_csv,
    signal_table,
    summary_csv,
    summary_rows,
)
from rei.campaign.report import render
from rei.campaign.results import RunResult

GATED = "laser:impulse,rate=0.03333333333333333,gain=0.5,width=3,from=0.0,period=10.0,pulse=0.1"


def result(case: str, variant: str, fault: str | None, utility: float, collisions: int) -> RunResult:
    return RunResult(key=f"g__{case}__{variant}", group="g", case=case, variant=variant, repetition=0, seed=0,
                     humans=True, fault=fault, status="COMPLETED", error=None, wall_time=1.0, cpu_time=1.0, host="h",
                     sim_duration=10.0, total_utility=utility, mission_succeeded=True, tasks_started=1,
                     tasks_succeeded=1, counts={"SIG_GEOM_CLOSE_TRANSIT_COLLISION": collisions},
                     metrics={"collision_episodes": collisions})


RESULTS = [
    result("A", "none", None, 100, 0),
    result("A", "gated1", "laser:gated-1%", 80, 1),
    # the same fault as gated1, written out: one fault level with it
    result("A", "spelled", "laser:impulse,rate=0.03333333333333333,width=3,gain=0.5,period=10,pulse=0.1", 60, 2),
    result("B", "none", "none", 90, 0),
    result("B", "gated1", "laser:gated-1%", 70, 3),
    result("B", "spelled", "laser:impulse,rate=0.03333333333333333,width=3,gain=0.5,period=10,pulse=0.1", 50, 4),
]


def test_fault_label_is_the_canonical_text() -> None:
    assert fault_label(None) == fault_label("") == fault_label("none") == "none"
    assert fault_label("laser:gated-1%") == GATED
    assert fault_label("laser:blackout,to=8, from=5;commands:loss,probability=0.3") == (
        "laser:blackout,from=5.0,to=8.0;commands:loss,probability=0.3")
    assert fault_label("laser:bogus") == "laser:bogus"  # a result of another version: shown as written


def test_summary_and_metrics_have_a_row_per_fault() -> None:
    rows = [r for r in summary_rows(RESULTS) if r.fault != "*"]
    assert [(r.room, r.variant, r.fault, r.executions) for r in rows] == [("*", "*", "none", 2), ("*", "*", GATED, 4)]
    assert rows[0].mean_utility == 95 and rows[1].mean_utility == 65 and rows[1].min_utility == 50
    lines = list(csv.DictReader(io.StringIO(summary_csv(RESULTS))))
    assert [line["fault"] for line in lines] == ["*"] * 6 + ["none", GATED]  # rooms, total, 3 variants, 2 faults
    collisions = {r.fault: r for r in metric_rows(RESULTS) if r.metric == "collision_episodes"}
    assert collisions["none"].mean == 0 and collisions[GATED].mean == 2.5 and collisions[GATED].n == 4
    by_fault = [row for row in csv.DictReader(io.StringIO(metrics_csv(metric_rows(RESULTS))))
                if row["metric"] == "collision_episodes" and row["fault"] != "*"]
    assert [(row["fault"], row["mean"]) for row in by_fault] == [("none", "0"), (GATED, "2.5")]
    columns, table = signal_table(RESULTS, "fault")
    assert columns == ["none", GATED] and dict(table)["SIG_GEOM_CLOSE_TRANSIT_COLLISION"] == [0, 10]


def test_one_fault_gives_no_fault_rows(tmp_path: Path) -> None:
    same = [r for r in RESULTS if r.variant != "none"]  # every run under the gated fault
    assert all(r.fault == "*" for r in summary_rows(same)) and all(r.fault == "*" for r in metric_rows(same))
    html = render(tmp_path, "demo", same, {}, len(same))
    assert "Per fault" not in html and "id='faults-g'" not in html


def test_report_has_the_tables_per_fault(tmp_path: Path) -> None:
    html = render(tmp_path, "demo", RESULTS, {}, len(RESULTS))
    assert "<h3>Per fault (thesis Tables 9, 10)</h3>" in html
    faults = html.split("id='faults-g'>")[1].split("</table>")[0]
    assert f"<th>none</th><th>{GATED}</th>" in faults
    assert "<td>SIG_GEOM_CLOSE_TRANSIT_COLLISION</td><td>0</td><td>10</td><td>10</td>" in faults
    metrics = html.split("id='metrics-g'")[1].split("</table>")[0]
    assert f"<td>{GATED}</td><td>4</td>" in metrics
