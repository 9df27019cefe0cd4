# SPDX-License-Identifier: EPL-2.0
"""``OUT/report.html`` of a campaign: the thesis's tables (5-10), verdict pass rates, the utility of every
mission over time (Fig. 36) and the distribution of signals (Fig. 37), one self-contained file.

Inline SVG like the run report (rei.report): opens offline, and tests can count lines and bars in the text.
"""

from __future__ import annotations

import csv
import os
from collections.abc import Sequence
from html import escape
from pathlib import Path
from typing import Any

from rei.campaign.aggregate import (
    ALL,
    TOTAL,
    MetricRow,
    Row,
    by_fault,
    metric_rows,
    signal_table,
    summary_rows,
    verdict_table,
)
from rei.campaign.results import RunResult
from rei.evaluation.metrics import BY_NAME
from rei.report.colours import signal_colour, signal_sort_key
from rei.report.svg import nice_ticks, num

REPORT = "report.html"
_PALETTE = ("#1f3a93", "#c0392b", "#27ae60", "#8e44ad", "#d35400", "#16a085", "#7f8c8d", "#2c3e50")
_W, _H, _L, _R, _T, _B = 900.0, 320.0, 60.0, 150.0, 14.0, 34.0
CSS = """body{font-family:system-ui,sans-serif;margin:24px;color:#222}table{border-collapse:collapse;margin:8px 0 20px}
td,th{border:1px solid #ccc;padding:3px 8px;text-align:right}th{background:#f3f3f3}td:first-child,th:first-child{text-align:left}
tr.total td{font-weight:600;background:#fafafa}.error{color:#b00}svg text{font-size:12px}"""


def write_campaign_report(out: Path, name: str, results: Sequence[RunResult], metrics: dict[str, Any],
                          planned: int, navigation: Sequence[MetricRow] | None = None) -> Path:
    path = out / REPORT
    path.write_text(render(out, name, results, metrics, planned, navigation), encoding="utf-8")
    return path


def render(out: Path, name: str, results: Sequence[RunResult], metrics: dict[str, Any], planned: int,
           navigation: Sequence[MetricRow] | None = None) -> str:
    errors = [r for r in results if r.status != "COMPLETED"]
    campaign = metrics.get("campaign", {})
    parts = [f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>{_e(name)} - REI campaign</title>",
             f"<style>{CSS}</style></head><body>", f"<h1>Campaign {_e(name)}</h1>",
             (f"<p id='facts'>{len(results)} of {planned} runs finished, {len(errors)} in ERROR; wall "
              f"{campaign.get('wall', 0):.0f} s, CPU {campaign.get('cpu', 0):.0f} s on {campaign.get('cores', '?')} "
              f"cores ({100 * campaign.get('cpu_utilisation', 0):.0f} % used by the campaign).</p>")]
    rows = summary_rows(results)
    navigation = metric_rows(results) if navigation is None else navigation
    for group in dict.fromkeys(r.group for r in results):
        runs = [r for r in results if r.group == group]
        parts.append(f"<h2>Group {_e(group)}</h2>")
        parts.append("<h3>Execution summary (thesis Tables 5, 7)</h3>")
        parts.append(_summary_table([r for r in rows if r.group == group and r.variant == ALL], "room"))
        by_variant = [r for r in rows if r.group == group and r.variant != ALL]
        if by_variant:
            parts.append("<h3>Per variant</h3>")
            parts.append(_summary_table(by_variant, "variant"))
        of_faults = [r for r in rows if r.group == group and r.fault != ALL]
        if of_faults:
            parts.append("<h3>Per fault (thesis Tables 9, 10)</h3>")
            parts.append(_summary_table(of_faults, "fault"))
        parts.append("<h3>Navigation metrics (mean [95 % CI], median; success: rate [Wilson 95 %])</h3>")
        parts.append(_navigation_html([r for r in navigation if r.group == group], f"metrics-{group}"))
        parts.append("<h3>Signals per room (Tables 6, 8)</h3>")
        parts.append(_signal_html(*signal_table(runs, "case"), f"signals-{group}"))
        parts.append("<h3>Signals per variant (Tables 9, 10)</h3>")
        parts.append(_signal_html(*signal_table(runs, "variant"), f"variants-{group}"))
        if by_fault(runs):
            parts.append("<h3>Signals per fault (Tables 9, 10)</h3>")
            parts.append(_signal_html(*signal_table(runs, "fault"), f"faults-{group}"))
        parts.append("<h3>Verdicts</h3>")
        parts.append(_verdict_html(runs))
    parts.append("<h2>Utility of each mission over time (Fig. 36)</h2>")
    parts.append(render_utilities(out, results))
    parts.append("<h2>Distribution of signals (Fig. 37)</h2>")
    parts.append(render_distribution(results))
    parts.append("<h2>Runs</h2>")
    parts.append(_runs_table(out, results))
    parts.append("</body></html>")
    return "\n".join(parts)


def _summary_table(rows: Sequence[Row], first: str) -> str:
    head = (f"<tr><th>{first}</th><th>executions</th><th>errors</th><th>mean time [s]</th><th>median time [s]</th>"
            "<th>mean utility</th><th>median utility</th><th>max utility</th><th>min utility</th>"
            "<th>missions succeeded</th><th>verdict pass rate</th></tr>")
    body = []
    for r in rows:
        label = getattr(r, first)
        cls = " class='total'" if r.room == "Total" else ""
        rate = "" if r.verdict_pass_rate is None else f"{100 * r.verdict_pass_rate:.0f} %"
        body.append(f"<tr{cls}><td>{_e(label)}</td><td>{r.executions}</td><td>{r.errors}</td>"
                    + "".join(f"<td>{_n(v)}</td>" for v in (r.mean_time, r.median_time, r.mean_utility,
                                                              r.median_utility, r.max_utility, r.min_utility))
                    + f"<td>{r.missions_succeeded}</td><td>{rate}</td></tr>")
    return f"<table class='summary'>{head}{''.join(body)}</table>"


def _navigation_html(rows: Sequence[MetricRow], ident: str) -> str:
    """One column per metric, one line per room, the group's total, each variant and each fault
    (docs/metrics.md)."""
    lines = list(dict.fromkeys((r.room, r.variant, r.fault) for r in rows))
    metrics = list(dict.fromkeys(r.metric for r in rows))
    cell = {(r.room, r.variant, r.fault, r.metric): r for r in rows}
    head = "<tr><th>room / variant / fault</th><th>runs</th>" + "".join(
        f"<th title='{_e(BY_NAME[m].label)}'>{_e(m)}{f' [{BY_NAME[m].unit}]' if BY_NAME[m].unit else ''}</th>"
        for m in metrics) + "</tr>"
    body = []
    for line in lines:
        room, variant, fault = line
        label = room if room != ALL else variant if variant != ALL else fault
        cls = " class='total'" if room == TOTAL else ""
        runs = max((cell[(*line, m)].n for m in metrics), default=0)
        body.append(f"<tr{cls}><td>{_e(label)}</td><td>{runs}</td>" + "".join(
            f"<td>{_estimate(cell[(*line, m)])}</td>" for m in metrics) + "</tr>")
    return f"<table id='{_e(ident)}' class='metrics'>{head}{''.join(body)}</table>"


def _estimate(row: MetricRow) -> str:
    if row.mean is None:
        return ""
    interval = "" if row.low is None else f" [{row.low:.3g}, {row.high:.3g}]"
    median = "" if row.median is None else f"; {row.median:.3g}"
    return f"{row.mean:.3g}{interval}{median}"


def _signal_html(columns: list[str], table: list[tuple[str, list[int]]], ident: str) -> str:
    head = "<tr><th>signal</th>" + "".join(f"<th>{_e(c)}</th>" for c in columns) + "<th>total</th></tr>"
    body = "".join(f"<tr><td>{_e(s)}</td>" + "".join(f"<td>{c}</td>" for c in counts) + f"<td>{sum(counts)}</td></tr>"
                   for s, counts in table)
    return f"<table id='{_e(ident)}'>{head}{body}</table>"


def _verdict_html(runs: Sequence[RunResult]) -> str:
    statuses = ("pass", "fail", "error", "not-applicable")
    head = "<tr><th>requirement</th>" + "".join(f"<th>{s}</th>" for s in statuses) + "<th>pass rate</th></tr>"
    body = "".join(f"<tr><td>{_e(req)}</td>" + "".join(f"<td>{counts.get(s, 0)}</td>" for s in statuses)
                   + f"<td>{'' if rate is None else f'{100 * rate:.0f} %'}</td></tr>"
                   for req, counts, rate in verdict_table(runs))
    return f"<table class='verdicts'>{head}{body}</table>"


def run_href(out: Path, run_dir: Path) -> str:
    """The link from a page in ``out`` to a run: its report.html, or its folder when the campaign wrote no
    reports (``report: false``)."""
    report = run_dir / "report.html"
    return os.path.relpath(report, out) if report.is_file() else os.path.relpath(run_dir, out) + "/"


def _runs_table(out: Path, results: Sequence[RunResult]) -> str:
    head = ("<tr><th>run</th><th>status</th><th>utility</th><th>tasks</th><th>simulated [s]</th><th>wall [s]</th>"
            "<th>CPU [s]</th><th>error</th></tr>")
    body = []
    for r in results:
        link = run_href(out, out / "runs" / r.key)
        body.append(f"<tr><td><a href='{_e(link)}'>{_e(r.key)}</a></td><td>{r.status}</td><td>{_n(r.total_utility)}</td>"
                    f"<td>{r.tasks_succeeded}/{r.tasks_started}</td><td>{_n(r.sim_duration)}</td><td>{_n(r.wall_time)}</td>"
                    f"<td>{_n(r.cpu_time)}</td><td class='error'>{_e(r.error or '')}</td></tr>")
    return f"<table id='runs'>{head}{''.join(body)}</table>"


def utility_steps(events_csv: Path, end: float | None) -> list[tuple[float, float]]:
    """The running total of a run's events.csv as step points from (0, 0)."""
    points = [(0.0, 0.0)]
    try:
        with open(events_csv, newline="", encoding="utf-8") as f:
            for row in csv.DictReader(f):
                t, total = float(row["t"]), float(row["total"])
                points += [(t, points[-1][1]), (t, total)]
    except (OSError, KeyError, ValueError):
        return points
    points.append((max(end or 0.0, points[-1][0]), points[-1][1]))
    return points


def render_utilities(out: Path, results: Sequence[RunResult]) -> str:
    """``<svg id="utilities">``: one step line per COMPLETED run, coloured by group."""
    lines = [(r, utility_steps(out / "runs" / r.key / "events.csv", r.sim_duration))
             for r in results if r.status == "COMPLETED"]
    t_max = max((p[0] for _, pts in lines for p in pts), default=1.0) or 1.0
    values = [v for _, pts in lines for _, v in pts] or [0.0]
    lo, hi = min(0.0, *values), max(0.0, *values)
    if hi - lo < 1e-9:
        lo, hi = lo - 1, hi + 1
    pw, ph = _W - _L - _R, _H - _T - _B

    def px(t: float) -> float:
        return _L + t / t_max * pw

    def py(v: float) -> float:
        return _T + (hi - v) / (hi - lo) * ph

    groups = list(dict.fromkeys(r.group for r, _ in lines))
    colour = {g: _PALETTE[i % len(_PALETTE)] for i, g in enumerate(groups)}
    svg = [(f'<svg id="utilities" xmlns="http://www.w3.org/2000/svg" width="{num(_W)}" height="{num(_H)}" '
            f'viewBox="0 0 {num(_W)} {num(_H)}">')]
    for v in nice_ticks(lo, hi, 5):
        svg.append(f'<line x1="{num(_L)}" x2="{num(_L + pw)}" y1="{num(py(v))}" y2="{num(py(v))}" stroke="#e5e5e5"/>'
                   f'<text x="{num(_L - 6)}" y="{num(py(v) + 4)}" text-anchor="end">{v:g}</text>')
    for t in nice_ticks(0.0, t_max, 8):
        svg.append(f'<text x="{num(px(t))}" y="{num(_T + ph + 16)}" text-anchor="middle">{t:g}</text>')
    svg.append(f'<text x="{num(_L + pw / 2)}" y="{num(_H - 4)}" text-anchor="middle">simulation time [s]</text>')
    for r, pts in lines:
        path = " ".join(f"{num(px(t))},{num(py(v))}" for t, v in pts)
        svg.append(f'<polyline class="mission" data-run="{_e(r.key)}" points="{path}" fill="none" '
                   f'stroke="{colour[r.group]}" stroke-width="1.5" opacity="0.8"><title>{_e(r.key)}: '
                   f'{pts[-1][1]:g}</title></polyline>')
    for i, g in enumerate(groups):
        y = _T + 10 + 18 * i
        svg.append(f'<rect x="{num(_W - _R + 12)}" y="{num(y - 9)}" width="12" height="12" fill="{colour[g]}"/>'
                   f'<text x="{num(_W - _R + 30)}" y="{num(y + 2)}">{_e(g)}</text>')
    svg.append("</svg>")
    return "\n".join(svg)


def render_distribution(results: Sequence[RunResult]) -> str:
    """``<svg id="distribution">``: one bar per signal with its count over all runs."""
    totals: dict[str, int] = {}
    for r in results:
        for s, c in r.counts.items():
            totals[s] = totals.get(s, 0) + c
    counts = sorted(totals.items(), key=lambda item: signal_sort_key(item[0]))
    row, label_w, right = 24.0, 300.0, 60.0
    height = max(1, len(counts)) * row + 12
    top = max((c for _, c in counts), default=1) or 1
    svg = [(f'<svg id="distribution" xmlns="http://www.w3.org/2000/svg" width="{num(_W)}" height="{num(height)}" '
            f'viewBox="0 0 {num(_W)} {num(height)}">')]
    for i, (name, count) in enumerate(counts):
        y = 6 + i * row
        w = max(1.0, count / top * (_W - label_w - right))
        svg.append(f'<text x="{num(label_w - 8)}" y="{num(y + row * 0.62)}" text-anchor="end">{_e(name)}</text>'
                   f'<rect class="bar" data-signal="{_e(name)}" data-count="{count}" x="{num(label_w)}" '
                   f'y="{num(y + 3)}" width="{num(w)}" height="{num(row - 6)}" fill="{signal_colour(name)}"/>'
                   f'<text x="{num(label_w + w + 6)}" y="{num(y + row * 0.62)}">{count}</text>')
    svg.append("</svg>")
    return "\n".join(svg)


def _n(value: float | None) -> str:
    return "" if value is None else f"{value:.4g}"


def _e(text: object) -> str:
    return escape(str(text), quote=True)
