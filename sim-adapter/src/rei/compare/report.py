# SPDX-License-Identifier: EPL-2.0
"""``OUT/compare.html``: the verdict per metric, a paired plot per metric (each room a line from its baseline
to its candidate value), the runs that changed most (linked to their reports) and the runs that did not pair.

Inline SVG in the campaign report's style (rei.campaign.report): one file that opens offline.
"""

from __future__ import annotations

from collections.abc import Sequence
from html import escape
from pathlib import Path

from rei.campaign.report import CSS, run_href
from rei.compare.analysis import Comparison, Difference, MetricComparison
from rei.compare.runs import Run
from rei.evaluation.outcome import Status
from rei.report.svg import nice_ticks, num

REPORT = "compare.html"
_W, _H, _L, _R, _T, _B = 420.0, 260.0, 60.0, 150.0, 12.0, 30.0
_WORSE, _BETTER, _SAME = "#c0392b", "#27ae60", "#7f8c8d"
_STYLE = CSS + """.fail{color:#b00;font-weight:600}.pass{color:#27ae60}.skip{color:#888}
.plots{display:flex;flex-wrap:wrap;gap:12px}.plot{border:1px solid #eee;padding:4px}"""
#: Pairs listed per metric under "runs that changed most".
CHANGED = 5


def write_compare_report(out: Path, comparison: Comparison) -> Path:
    path = out / REPORT
    path.write_text(render(out, comparison), encoding="utf-8")
    return path


def render(out: Path, c: Comparison) -> str:
    p = c.pairing
    verdict = (f"<p id='verdict' class='fail'>{len(c.regressions)} regression(s): "
               f"{_e(', '.join(m.metric.name for m in c.regressions))}</p>" if c.regressions
               else "<p id='verdict' class='pass'>no regression</p>")
    if c.by_fault:
        under = c.fault_regressions
        verdict += (f"<p id='fault-verdict' class='fail'>{len(under)} regression(s) under a fault: "
                    f"{_e(', '.join(f'{m.metric.name} under {fault}' for fault, m in under))}</p>" if under
                    else "<p id='fault-verdict' class='pass'>no regression under any fault</p>")
    parts = [(f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>REI comparison</title><style>{_STYLE}</style>"
             "</head><body><h1>Comparison</h1>"),
             (f"<p>baseline <code>{_e(c.baseline)}</code>, candidate <code>{_e(c.candidate)}</code>; "
             f"{len(p.pairs)} pair(s) of runs (same group, case, variant, seed and fault), {len(p.only_baseline)} only in "
             f"the baseline, {len(p.only_candidate)} only in the candidate, {len(p.errors)} with a side in ERROR; thresholds: "
             f"{_e(c.thresholds.source)}.</p>"), verdict,
             "<h2>Metrics (candidate - baseline, over the pairs)</h2>", _verdict_table(c.metrics)]
    for fault, metrics in c.by_fault:
        parts += [f"<h2>Under fault <code>{_e(fault)}</code> (its pairs alone)</h2>",
                  _verdict_table(metrics, fault)]
    parts += ["<h2>Paired plots (each room a line, baseline to candidate; mean over seeds)</h2><div class='plots'>"]
    parts += [_paired_plot(m) for m in c.metrics if m.differences]
    parts.append("</div><h2>Runs that changed most</h2>")
    parts.append(_changed(out, [m for m in c.metrics if m.threshold is not None and m.differences]))
    parts.append("<h2>Runs not compared</h2>")
    parts.append(_unpaired(out, p.only_baseline, p.only_candidate, p.errors))
    parts.append("</body></html>")
    return "\n".join(parts)


def _verdict_table(metrics: Sequence[MetricComparison], fault: str | None = None) -> str:
    head = ("<tr><th>metric</th><th>pairs</th><th>baseline</th><th>candidate</th><th>difference [95 % CI]</th>"
            "<th>test</th><th>p</th><th>threshold</th><th>verdict</th></tr>")
    body = []
    for m in metrics:
        d = m.paired
        interval = "" if d.low is None else f" [{d.low:+.3g}, {d.high:+.3g}]"
        status = {Status.FAIL: "<td class='fail'>regression</td>", Status.PASS: "<td class='pass'>pass</td>",
                  Status.NOT_APPLICABLE: "<td class='skip'>no data</td>"}.get(m.status, "<td class='skip'>-</td>")
        unit = f" [{m.metric.unit}]" if m.metric.unit else ""
        body.append(f"<tr data-metric='{_e(m.metric.name)}'><td>{_e(m.metric.name)}{_e(unit)}</td><td>{d.n}</td>"
                    f"<td>{_n(m.baseline_mean)}</td><td>{_n(m.candidate_mean)}</td>"
                    f"<td>{'' if d.mean is None else f'{d.mean:+.3g}'}{interval}</td><td>{_e(d.test)}</td>"
                    f"<td>{'' if d.p is None else f'{d.p:.3g}'}</td>"
                    f"<td>{_e(m.threshold.describe()) if m.threshold else ''}</td>{status}</tr>")
    ident = "id='metrics'" if fault is None else f"class='fault-metrics' data-fault='{_e(fault)}'"
    return f"<table {ident}>{head}{''.join(body)}</table>"


def _paired_plot(m: MetricComparison) -> str:
    """``<svg class="paired" data-metric=...>``: per room (group, case, variant), a line from the mean of its
    baseline runs to the mean of its candidate runs, red when worse, green when better."""
    rooms: dict[str, list[Difference]] = {}
    for d in m.differences:
        rooms.setdefault(_room(d.baseline), []).append(d)
    lines = [(room, sum(float(d.baseline.metrics[m.metric.name]) for d in ds) / len(ds),
              sum(float(d.candidate.metrics[m.metric.name]) for d in ds) / len(ds)) for room, ds in rooms.items()]
    values = [v for _, a, b in lines for v in (a, b)]
    lo, hi = min(values), max(values)
    if hi - lo < 1e-12:
        lo, hi = lo - 1, hi + 1
    pw, ph = _W - _L - _R, _H - _T - _B
    x0, x1 = _L + 0.15 * pw, _L + 0.85 * pw

    def py(v: float) -> float:
        return _T + (hi - v) / (hi - lo) * ph

    better = m.threshold.better if m.threshold else m.metric.better
    svg = [(f'<svg class="paired" data-metric="{_e(m.metric.name)}" xmlns="http://www.w3.org/2000/svg" '
           f'width="{num(_W)}" height="{num(_H)}" viewBox="0 0 {num(_W)} {num(_H)}">'),
           (f'<text x="{num(_L)}" y="{num(_T + 2)}" font-weight="600">{_e(m.metric.name)}'
           f'{f" [{_e(m.metric.unit)}]" if m.metric.unit else ""}</text>')]
    for v in nice_ticks(lo, hi, 5):
        svg.append(f'<line x1="{num(_L)}" x2="{num(_L + pw)}" y1="{num(py(v))}" y2="{num(py(v))}" stroke="#eee"/>'
                   f'<text x="{num(_L - 6)}" y="{num(py(v) + 4)}" text-anchor="end">{v:g}</text>')
    svg.append(f'<text x="{num(x0)}" y="{num(_H - 8)}" text-anchor="middle">baseline</text>'
               f'<text x="{num(x1)}" y="{num(_H - 8)}" text-anchor="middle">candidate</text>')
    for room, a, b in lines:
        worse = (b < a) if better.value == "higher" else (b > a) if better.value == "lower" else False
        colour = _SAME if abs(b - a) < 1e-12 else _WORSE if worse else _BETTER if better.value != "neither" else _SAME
        svg.append(f'<g class="room" data-room="{_e(room)}"><line x1="{num(x0)}" y1="{num(py(a))}" x2="{num(x1)}" '
                   f'y2="{num(py(b))}" stroke="{colour}" stroke-width="1.5"/>'
                   f'<circle cx="{num(x0)}" cy="{num(py(a))}" r="3" fill="{colour}"/>'
                   f'<circle cx="{num(x1)}" cy="{num(py(b))}" r="3" fill="{colour}"/>'
                   f'<title>{_e(room)}: {a:.4g} -> {b:.4g}</title></g>')
        svg.append(f'<text x="{num(x1 + 8)}" y="{num(py(b) + 4)}" font-size="10">{_e(_short(room))}</text>')
    svg.append("</svg>")
    return f"<div class='plot'>{''.join(svg)}</div>"


def _changed(out: Path, metrics: Sequence[MetricComparison]) -> str:
    head = ("<tr><th>metric</th><th>group / case / variant / seed</th><th>baseline</th><th>candidate</th>"
            "<th>difference</th></tr>")
    body = []
    for m in metrics:
        for d in m.worst(CHANGED):
            body.append(f"<tr class='changed' data-metric='{_e(m.metric.name)}'><td>{_e(m.metric.name)}</td>"
                        f"<td>{_e(_room(d.baseline))} / {d.baseline.seed}</td>"
                        f"<td>{_link(out, d.baseline, d.baseline.metrics[m.metric.name])}</td>"
                        f"<td>{_link(out, d.candidate, d.candidate.metrics[m.metric.name])}</td>"
                        f"<td>{d.value:+.4g}</td></tr>")
    if not body:
        return "<p>no run changed in a judged metric.</p>"
    return f"<table id='changed'>{head}{''.join(body)}</table>"


def _unpaired(out: Path, only_baseline: Sequence[Run], only_candidate: Sequence[Run],
              errors: Sequence[tuple[Run, Run]]) -> str:
    rows = [(side, r) for side, runs in (("only in the baseline", only_baseline),
                                        ("only in the candidate", only_candidate)) for r in runs]
    for pair in errors:  # both sides of a pair with a run in ERROR: neither is compared
        rows += [(f"{r.status} ({side})" if r.status != "COMPLETED" else f"partner of a run in ERROR ({side})", r)
                 for side, r in zip(("baseline", "candidate"), pair, strict=True)]
    if not rows:
        return "<p>every run pairs.</p>"
    body = "".join(f"<tr class='unpaired'><td>{side}</td><td>{_link(out, r, r.key)}</td><td>{_e(r.error or '')}</td></tr>"
                   for side, r in rows)
    return f"<table id='unpaired'><tr><th>why</th><th>run</th><th>error</th></tr>{body}</table>"


def _link(out: Path, run: Run, text: object) -> str:
    href = run_href(out, run.folder)
    shown = f"{text:.4g}" if isinstance(text, float) else str(text)
    return f"<a href='{_e(href)}'>{_e(shown)}</a>"


def _room(run: Run) -> str:
    return " / ".join(part for part in (run.group, run.case, run.variant) if part)


def _short(room: str) -> str:
    return room if len(room) <= 22 else "..." + room[-19:]


def _n(value: float | None) -> str:
    return "" if value is None else f"{value:.4g}"


def _e(text: object) -> str:
    return escape(str(text), quote=True)
