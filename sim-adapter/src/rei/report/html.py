# SPDX-License-Identifier: EPL-2.0
"""`OUT/report.html`: one self-contained page a person reads after a run.

Why self-contained (inline SVG and CSS, no script, no fonts or libraries from a CDN): reports are archived next
to the run, mailed, opened on machines without network access, and must look the same in five years. Why no
script at all: hover details come from SVG `<title>` elements, which every browser shows natively, so nothing
can break at view time.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

from rei.evaluation.metrics import LIST_KEYS, METRICS
from rei.report.charts import finite_or, render_signal_bars, render_utility
from rei.report.colours import ROBOT_BELIEVED, ROBOT_TRUE, signal_colour, signal_sort_key
from rei.report.map_svg import MAX_MARKERS, render_map
from rei.report.run_data import RunData, load_run
from rei.report.svg import esc
from rei.report.tracks import Tracks, collect_tracks

REPORT_NAME = "report.html"
#: The signal table is for reading; beyond this many rows a person uses events.csv instead.
MAX_TABLE_ROWS = 2000

_CSS = """
body{font:14px/1.45 system-ui,-apple-system,"Segoe UI",Roboto,"DejaVu Sans",sans-serif;color:#222;margin:0;
 background:#f4f4f1}
main{max-width:960px;margin:0 auto;padding:16px 24px 48px}
h1{font-size:22px;margin:8px 0 4px} h2{font-size:17px;margin:28px 0 8px;border-bottom:1px solid #ddd;
 padding-bottom:4px}
section{background:#fff;border:1px solid #e2e2dc;border-radius:6px;padding:12px 16px;margin-top:16px}
section h2{margin-top:0}
.badge{display:inline-block;padding:2px 10px;border-radius:10px;font-weight:600;color:#fff;font-size:13px;
 vertical-align:middle;margin-left:6px}
.pass,.completed,.succeeded{background:#2e7d32} .fail,.failed{background:#c62828}
.error{background:#ef6c00} .unknown,.skip,.inconclusive,.not-applicable{background:#9e9e9e}
.where{color:#1f3a93;font-variant-numeric:tabular-nums}
table{border-collapse:collapse;width:100%} th,td{text-align:left;padding:4px 8px;border-bottom:1px solid #eee;
 vertical-align:top} th{background:#fafafa;font-weight:600}
table.facts th{width:30%;background:none;font-weight:500;color:#555}
td.num{text-align:right;font-variant-numeric:tabular-nums}
.missing{color:#8a6d3b;background:#fcf8e3;border:1px solid #faebcc;padding:8px 12px;border-radius:4px}
ul.notes{margin:6px 0;padding-left:20px;color:#8a6d3b}
svg{display:block;max-width:100%;height:auto} svg text{font:11px system-ui,"DejaVu Sans",sans-serif;fill:#444}
svg text.label{font-size:11px;fill:#fff;font-weight:600} svg text.goal-label{fill:#2ca02c;font-weight:600}
svg text.final{font-weight:600;fill:#1f3a93} svg text.bar-label{font-size:12px}
.legend{display:flex;flex-wrap:wrap;gap:4px 16px;margin-top:8px;font-size:12px;color:#444}
.legend span.sw{display:inline-block;width:18px;height:10px;margin-right:5px;vertical-align:middle;
 border-radius:2px}
.legend span.ln{display:inline-block;width:22px;height:0;margin-right:5px;vertical-align:middle}
.evidence{margin:0;padding-left:16px;color:#555;font-size:13px}
details summary{cursor:pointer;color:#1f3a93}
code{font-size:12px}
"""


def write_report(out_dir: Path, case_dir: Path | None = None, *, data: RunData | None = None,
                 tracks: Tracks | None = None) -> Path:
    """Write `OUT/report.html` for the run in `out_dir` (case files in `case_dir`, default OUT/case); ``data`` and
    ``tracks``: the run already read (rei.report.write_views reads it once for both views)."""
    data = data or load_run(Path(out_dir), case_dir)
    path = Path(out_dir) / REPORT_NAME
    path.write_text(render_report(data, tracks), encoding="utf-8")
    return path


def render_report(data: RunData, tracks: Tracks | None = None) -> str:
    """The whole page as text."""
    tracks = tracks or collect_tracks(data.states())
    data.state_count = tracks.states
    title = _title(data)
    sections = [
        _facts(data, tracks),
        _map_section(data, tracks),
        _utility_section(data, tracks),
        _signals_section(data),
        _verdicts_section(data),
        _metrics_section(data),
        _mission_section(data),
        _signal_table(data),
    ]
    return ("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
            f"<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>{esc(title)}</title>\n"
            f"<style>{_CSS}</style>\n</head>\n<body>\n<main>\n"
            f"<h1>{esc(title)}{_status_badge(data)}</h1>\n"
            + "\n".join(sections) + "\n</main>\n</body>\n</html>\n")


def _title(data: RunData) -> str:
    testcase = data.fact("testcase") or (data.world or {}).get("testcase")
    mission = data.fact("mission") if isinstance(data.fact("mission"), str) else data.mission_name
    parts = [str(p) for p in (testcase, mission) if p]
    return "REI run report" + (f": {' / '.join(parts)}" if parts else "")


def _status_badge(data: RunData) -> str:
    """The run's status, then the verdict counts: "COMPLETED" alone would read as "passed" to a hurried eye."""
    status = (data.summary or {}).get("status")
    if status is None and data.sim is not None and "succeeded" in data.sim:
        status = "mission succeeded" if data.sim["succeeded"] else "mission failed"
        css = "succeeded" if data.sim["succeeded"] else "failed"
    else:
        css = str(status).lower()
    badges = [f'<span id="status" class="badge {esc(css)}">{esc(status)}</span>'] if status else []
    verdicts = (data.summary or {}).get("verdicts")
    if isinstance(verdicts, list):
        counts: dict[str, int] = {}
        for verdict in verdicts:
            if isinstance(verdict, Mapping):
                key = str(verdict.get("status", "unknown"))
                counts[key] = counts.get(key, 0) + 1
        for key in ("fail", "error", "pass", "not-applicable"):
            if counts.get(key):
                badges.append(f'<span class="badge {key}">{counts[key]} {key}</span>')
    return "".join(badges)


def _facts(data: RunData, tracks: Tracks) -> str:
    rows: list[tuple[str, str]] = []

    def add(label: str, value: Any, unit: str = "") -> None:
        if value is None or value == "":
            return
        if isinstance(value, float):
            value = f"{value:.2f}"
        rows.append((label, f"{esc(value)}{unit}"))

    add("test case", data.fact("testcase") or (data.world or {}).get("testcase"))
    add("mission", data.fact("mission") if isinstance(data.fact("mission"), str) else data.mission_name)
    add("run id", data.fact("run_id"))
    add("run status", data.summary.get("status") if data.summary else None)
    add("error", data.fact("error", "reason"))
    if data.sim is not None and "succeeded" in data.sim:
        add("mission outcome", "succeeded" if data.sim["succeeded"] else "failed")
    add("simulated time", _number(data.fact("sim_duration", "sim_time")), " s")
    add("wall-clock time", _number(data.fact("wall_time")), " s")
    add("total utility", _number(data.fact("total_utility")))
    if data.summary is not None and data.summary.get("utilities"):
        add("utility table", data.summary["utilities"])
    add("tasks", _tasks_text(data))
    add("controller", (data.sim or {}).get("options", {}).get("controller"))
    add("fault", (data.sim or {}).get("options", {}).get("fault"))
    signal_text = f"{len(data.signals)}" + (f" (from {data.signals_source})" if data.signals_source else "")
    add("signals", signal_text)
    add("state messages", tracks.states)
    worst = tracks.odometry_error()
    if worst is not None:
        add("largest odometry error", f"{worst[0]:.3f} m at t = {worst[1]:.2f} s")
    if tracks.laser_scans:
        add("laser scans recorded", tracks.laser_scans)
    table = "".join(f"<tr><th>{label}</th><td>{value}</td></tr>" for label, value in rows)
    notes = ""
    problems = (data.summary or {}).get("problems")
    if isinstance(problems, list) and problems:
        data.notes.extend(f"problem in the signal stream: {p.get('text', p) if isinstance(p, Mapping) else p}"
                          for p in problems[:20])
    if data.notes:
        notes = '<ul class="notes" id="notes">' + "".join(f"<li>{esc(n)}</li>" for n in data.notes) + "</ul>"
    return f'<section id="facts"><h2>Run</h2><table class="facts">{table}</table>{notes}</section>'


def _tasks_text(data: RunData) -> str | None:
    tasks = (data.summary or {}).get("tasks")
    if isinstance(tasks, Mapping) and "succeeded" in tasks:
        goals = tasks.get("goals")
        text = f"{tasks.get('succeeded', 0)} succeeded, {tasks.get('failed', 0)} failed"
        return text + (f" of {goals} goals" if goals is not None else "")
    listed = (data.sim or {}).get("tasks")
    if isinstance(listed, list) and listed:
        ok = sum(1 for task in listed if isinstance(task, Mapping) and task.get("succeeded"))
        return f"{ok} succeeded, {len(listed) - ok} failed"
    return None


def _number(value: Any) -> float | None:
    return float(value) if isinstance(value, int | float) and not isinstance(value, bool) else None


def _map_section(data: RunData, tracks: Tracks) -> str:
    if data.world is None and len(tracks.robot) == 0:
        return ('<section><h2>Map</h2><p class="missing" id="map-missing">no world.json and no state recording: '
                'nothing to draw</p></section>')
    svg = render_map(data.world, tracks, data.goals, data.signals, data.picture)
    kinds = sorted({s.signal for s in data.signals}, key=signal_sort_key)
    legend = [f'<span><span class="ln" style="border-top:3px solid {ROBOT_TRUE}"></span>true path</span>',
              (f'<span><span class="ln" style="border-top:2px dashed {ROBOT_BELIEVED}"></span>believed path '
              f'(odometry)</span>'),
              '<span><span class="ln" style="border-top:2px solid rgba(181,101,29,.45)"></span>humans</span>',
              ('<span><span class="sw" style="background:rgba(44,160,44,.25);border:1px dashed #2ca02c"></span>'
              'goal (tolerance)</span>')]
    legend += [f'<span><span class="sw" style="background:{signal_colour(k)}"></span>{esc(k)}</span>' for k in kinds]
    extra = ""
    if len(data.signals) > MAX_MARKERS:
        extra = f'<p class="missing">only the first {MAX_MARKERS} of {len(data.signals)} signals are marked</p>'
    if len(tracks.believed) == 0 and len(tracks.robot) > 0:
        extra += '<p class="missing">no odometry in the state messages: no believed path</p>'
    return (f'<section id="map-section"><h2>Map</h2>{svg}<div class="legend">{"".join(legend)}</div>{extra}'
            '<p style="color:#666;font-size:12px">Hover a marker for the signal\'s time, kind and object. '
            'Markers sit on the true path at the time of the state that caused them.</p></section>')


def _utility_section(data: RunData, tracks: Tracks) -> str:
    if data.events is None:
        return ('<section><h2>Utility over time</h2><p class="missing" id="utility-missing">no events.csv: the '
                'run was not evaluated, so there is no utility to plot</p></section>')
    end_t = finite_or(data.fact("sim_duration", "sim_time"), tracks.last_t or 0.0)
    faults = _fault_windows(data)
    shaded = " Shaded: the fault windows (summary.json's faults)." if faults else ""
    return (f'<section id="utility-section"><h2>Utility over time</h2>'
            f'{render_utility(data.events, end_t, faults)}'
            '<p style="color:#666;font-size:12px">Running total of the evaluator\'s events.csv (thesis Fig. 33); '
            f'each dot is a signal, coloured by kind.{shaded}</p></section>')


def _fault_windows(data: RunData) -> list[tuple[str, float, float | None]]:
    """The evaluator's fault windows (docs/faults.md), those that read as such."""
    windows = []
    for w in (data.summary or {}).get("faults") or ():
        if not isinstance(w, Mapping):
            continue
        begin, end = w.get("begin"), w.get("end")
        if isinstance(begin, int | float) and math.isfinite(begin) and (
                end is None or isinstance(end, int | float) and math.isfinite(end)):
            windows.append((str(w.get("fault", "fault")), float(begin), None if end is None else float(end)))
    return windows


def _signals_section(data: RunData) -> str:
    if not data.signals:
        return ('<section><h2>Signal distribution</h2><p class="missing" id="signals-missing">no signals recorded'
                '</p></section>')
    return (f'<section id="signals-section"><h2>Signal distribution</h2>{render_signal_bars(data.signals)}'
            '</section>')


def _verdicts_section(data: RunData) -> str:
    verdicts = (data.summary or {}).get("verdicts")
    if not isinstance(verdicts, list) or not verdicts:
        why = "summary.json has no verdicts" if data.summary is not None else "no summary.json: no verdicts"
        return f'<section><h2>Verdicts</h2><p class="missing" id="verdicts-missing">{why}</p></section>'
    rows = []
    for verdict in verdicts:
        if not isinstance(verdict, Mapping):
            continue
        status = str(verdict.get("status", "unknown"))
        name = verdict.get("requirement", verdict.get("name", ""))
        rows.append(f'<tr class="verdict"><td><code>{esc(name)}</code></td><td><span class="badge '
                    f'{esc(status.lower())}">{esc(status)}</span></td><td>{esc(verdict.get("message", ""))}'
                    f'{_evidence(verdict.get("evidence"))}</td></tr>')
    return ('<section id="verdicts-section"><h2>Verdicts</h2><table id="verdicts"><tr><th>requirement</th>'
            f'<th>verdict</th><th>message and evidence</th></tr>{"".join(rows)}</table></section>')


def _metrics_section(data: RunData) -> str:
    """The navigation metrics of summary.json (docs/metrics.md); a metric that does not apply shows as '-'."""
    metrics = (data.summary or {}).get("metrics")
    if not isinstance(metrics, Mapping) or not metrics:
        why = ("summary.json has no navigation metrics (written before they existed: rei evaluate OUT adds them)"
               if data.summary is not None else "no summary.json: no navigation metrics")
        return f'<section><h2>Navigation metrics</h2><p class="missing" id="metrics-missing">{why}</p></section>'
    rows = []
    for metric in METRICS:
        value = metrics.get(metric.name)
        shown = "-" if value is None else str(value).lower() if isinstance(value, bool) else (
            f"{value:.4g}" if isinstance(value, float) else str(value))
        rows.append(f'<tr class="metric" data-metric="{esc(metric.name)}"><td><code>{esc(metric.name)}</code></td>'
                    f'<td class="num">{esc(shown)}</td><td>{esc(metric.unit)}</td><td>{esc(metric.label)}</td></tr>')
    for key in LIST_KEYS:
        values = metrics.get(key)
        if isinstance(values, list):
            shown = ", ".join("-" if v is None else f"{v:.4g}" for v in values)
            rows.append(f'<tr class="metric" data-metric="{esc(key)}"><td><code>{esc(key)}</code></td>'
                        f'<td class="num">{esc(shown)}</td><td>s</td><td>time per task</td></tr>')
    error = (data.summary or {}).get("metrics_error")
    note = f'<p class="missing" id="metrics-error">{esc(error)}</p>' if error else ""
    return ('<section id="metrics-section"><h2>Navigation metrics</h2><table id="metrics"><tr><th>metric</th>'
            f'<th>value</th><th>unit</th><th>what</th></tr>{"".join(rows)}</table>{note}</section>')


#: Evidence items shown at once; the rest fold away (a noisy laser can produce dozens).
_EVIDENCE_SHOWN = 4
_EVIDENCE_MAX = 200


def _evidence(evidence: Any) -> str:
    """Evidence as the evaluator writes it (`{text, t?, signal?, object?, task?}`), or text, or a list."""
    if evidence is None or evidence == [] or evidence == {}:
        return ""
    items = [_evidence_line(item) for item in (evidence if isinstance(evidence, list) else [evidence])]
    shown = "".join(f"<li>{item}</li>" for item in items[:_EVIDENCE_SHOWN])
    rest = items[_EVIDENCE_SHOWN:_EVIDENCE_MAX]
    folded = ""
    if rest:
        more = len(items) - _EVIDENCE_SHOWN
        folded = (f"<li><details><summary>{more} more</summary><ul class=\"evidence\">"
                  + "".join(f"<li>{item}</li>" for item in rest) + "</ul></details></li>")
    return f'<ul class="evidence">{shown}{folded}</ul>'


def _evidence_line(item: Any) -> str:
    if not isinstance(item, Mapping):
        return esc(_short(item))
    where = []
    if isinstance(item.get("t"), int | float):
        where.append(f"t = {item['t']:.2f} s")
    where += [esc(item[key]) for key in ("signal", "object") if item.get(key) is not None]
    if item.get("task") is not None:
        where.append(f"task {esc(item['task'])}")
    others = [f"{esc(k)}: {esc(_short(v))}" for k, v in item.items() if k not in ("text", "t", "signal", "object", "task")]
    text = esc(item.get("text", ""))
    head = f'<span class="where">{" · ".join(where)}</span> ' if where else ""
    return head + text + (f" ({', '.join(others)})" if others else "")


def _short(value: Any) -> str:
    if isinstance(value, float):
        return f"{value:.3f}".rstrip("0").rstrip(".") if math.isfinite(value) else str(value)
    return str(value)


def _mission_section(data: RunData) -> str:
    if not data.mission_events:
        return ""
    rows = []
    for event in data.mission_events:
        task = event.get("task_index")
        rows.append(f'<tr><td class="num">{finite_or(event.get("t"), math.nan):.2f}</td>'
                    f'<td>{esc(event.get("event", ""))}</td><td>{"" if task in (None, -1) else esc(task)}</td>'
                    f'<td>{esc(event.get("reason") or "")}</td></tr>')
    return ('<section id="mission-section"><h2>Mission</h2><table id="mission"><tr><th>t [s]</th><th>event</th>'
            f'<th>task</th><th>reason</th></tr>{"".join(rows)}</table></section>')


def _signal_table(data: RunData) -> str:
    if not data.signals:
        return ""
    utilities = _utilities_by_signal(data)
    rows = []
    for i, record in enumerate(data.signals[:MAX_TABLE_ROWS]):
        utility = utilities[i] if i < len(utilities) else ""
        distance = f"{record.distance:.3f}" if math.isfinite(record.distance) else ""
        rows.append(f'<tr><td class="num">{record.t:.2f}</td><td><span class="sw" style="display:inline-block;'
                    f'width:9px;height:9px;border-radius:50%;margin-right:6px;background:{signal_colour(record.signal)}'
                    f'"></span>{esc(record.signal)}</td><td>{esc(record.object)}</td><td class="num">{distance}</td>'
                    f'<td class="num">{utility}</td></tr>')
    more = (f"<p>... and {len(data.signals) - MAX_TABLE_ROWS} more (see events.csv)</p>"
            if len(data.signals) > MAX_TABLE_ROWS else "")
    return (f'<section id="signal-list-section"><h2>Signals</h2><details><summary>{len(data.signals)} signals '
            f'in order</summary><table id="signal-list"><tr><th>t [s]</th><th>signal</th><th>object</th>'
            f'<th>distance [m]</th><th>utility</th></tr>{"".join(rows)}</table>{more}</details></section>')


def _utilities_by_signal(data: RunData) -> Sequence[str]:
    """The utility of each listed signal, when events.csv lists the same signals in the same order."""
    events = data.events or []
    if len(events) != len(data.signals):
        return []
    if any(e.signal != s.signal for e, s in zip(events, data.signals, strict=True)):
        return []
    return [f"{e.utility:+g}" for e in events]
