# SPDX-License-Identifier: EPL-2.0
"""``OUT/search.html``: one page, no script: the search's figures beside its random baseline's when one ran in
the same folder, each objective over the evaluations (search and baseline) with the best so far, the Pareto front
for several objectives, parameter importance (optuna.importance's default evaluator, PED-ANOVA), and each distinct
failure (an event, with every requirement it violated: rei.search.failures) with a small map of its run (the run
report's map, rei.report.map_svg) and links to its case, report and shrunk case. A value a run did not have (rei.search.objectives.ABSENT) is left out of the charts, the front and the
importance.
"""

from __future__ import annotations

import html
import re
import warnings
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

from optuna.trial import TrialState

from rei.search.objectives import present

PAGE = "search.html"
#: An id of the run report's map (rei.report.map_svg: the svg's ``map``, its layers' ``map-...``).
_MAP_ID = re.compile(r'\bid="(map(?:-[^"]*)?)"')
_W, _H, _PAD = 560, 220, 36
_CSS = """body{font-family:system-ui,sans-serif;margin:24px;color:#222;max-width:1100px}
table{border-collapse:collapse;font-size:13px}td,th{border:1px solid #ddd;padding:3px 8px;text-align:left}
section{margin:18px 0}.failure{border:1px solid #ddd;padding:10px;margin:10px 0}.failure svg{max-width:520px;height:auto}
.muted{color:#666;font-size:12px}"""


def write_search_report(out: Path, document: Mapping[str, Any]) -> Path:
    path = out / PAGE
    path.write_text(render(out, document), encoding="utf-8")
    return path


def render(out: Path, document: Mapping[str, Any]) -> str:
    counts = document["counts"]
    title = f"rei search {document['name']} ({document['sampler']})"
    parts = [f"<h1>{_e(title)}</h1>",
             (f"<p id=\"counts\">{counts['simulated']} evaluations of {document['budget']} ({counts['errors']} in ERROR); "
             f"{counts['invalid']} invalid and {counts['unplannable']} unplannable candidates not simulated; "
             f"{counts['failing']} failing evaluations, {counts['distinct_failures']} distinct failure(s); first "
             f"failure at evaluation {counts['first_failure_at'] or '-'}.</p>")]
    baseline = document.get("baseline")
    if baseline:
        parts.append(_comparison(document, baseline))
    for i, objective in enumerate(document["objectives"]):
        parts.append(_objective_section(i, objective, document["evaluations"],
                                        baseline["evaluations"] if baseline else None))
    if len(document["objectives"]) >= 2:
        parts.append(_pareto(document))
    parts.append(_importance(out, document))
    parts.append(_failures(out, document))
    return ("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
            f"<title>{_e(title)}</title><style>{_CSS}</style></head><body>\n" + "\n".join(parts) + "\n</body></html>\n")


def _comparison(document: Mapping[str, Any], baseline: Mapping[str, Any]) -> str:
    """The search's figures beside its random baseline's, and the failures only one of them found."""
    sides = (document, baseline)
    rows = [("budget", [str(d.get("budget") or "-") for d in sides])]
    for label, key in (("simulated evaluations", "simulated"), ("in ERROR", "errors"), ("failing evaluations", "failing"),
                       ("distinct failures", "distinct_failures"), ("first failure at evaluation", "first_failure_at")):
        rows.append((label, [str(d["counts"].get(key) if d["counts"].get(key) is not None else "-") for d in sides]))
    body = "".join(f"<tr><td>{_e(label)}</td>" + "".join(f"<td>{_e(v)}</td>" for v in values) + "</tr>"
                   for label, values in rows)
    found = [{f["signature"] for f in d["failures"]} for d in sides]
    only = []
    for name, mine, theirs, side in (("the search", found[0], found[1], document),
                                     ("the random baseline", found[1], found[0], baseline)):
        for f in (f for f in side["failures"] if f["signature"] in mine - theirs):
            only.append(f"<tr><td>{_e(name)}</td><td>{_e(f['signature'])}</td>"
                        f"<td>{_e(', '.join(f.get('requirements') or []))}</td><td>{len(f['evaluations'])}</td>"
                        f"<td>{_e(f['first'])}</td></tr>")
    table = ("<table><tr><th>failure found only by</th><th>signature</th><th>requirements</th><th>evaluations</th>"
             "<th>first</th></tr>"
             + "".join(only) + "</table>") if only else "<p class=\"muted\">both found the same failures</p>"
    return (f"<section id=\"baseline\"><h2>Search and random baseline</h2><table><tr><th></th>"
            f"<th>search ({_e(document['sampler'])})</th><th>random baseline</th></tr>{body}</table>{table}"
            "<p class=\"muted\">the random baseline ran in the same folder (<code>--sampler random</code>); its "
            "figures are search.json's <code>baseline</code>; its failures are not shrunk.</p></section>")


def _values(evaluations: Sequence[Mapping[str, Any]] | None, i: int) -> list[float | None]:
    """Objective ``i`` of each completed evaluation, None where the run did not have it (left out of the chart)."""
    return [r["values"][i] if present(r["values"][i]) else None for r in evaluations or () if r.get("values")]


def _objective_section(i: int, objective: Mapping[str, Any], evaluations: Sequence[Mapping[str, Any]],
                       baseline: Sequence[Mapping[str, Any]] | None) -> str:
    minimize = objective["direction"] == "minimize"
    series = [("search", _values(evaluations, i), "#1f77b4")]
    if baseline:
        series.append(("random baseline", _values(baseline, i), "#ff7f0e"))
    svg = _chart(series, minimize)
    return (f"<section id=\"objective-{i}\"><h2>{_e(objective['label'])} ({_e(objective['direction'])})</h2>{svg}"
            "<p class=\"muted\">dots: each evaluation; line: the best so far. "
            + ", ".join(f"<span style=\"color:{c}\">{_e(n)}</span>" for n, _, c in series) + "</p></section>")


def _chart(series: Sequence[tuple[str, list[float | None], str]], minimize: bool) -> str:
    values = [v for _, vs, _ in series for v in vs if v is not None]
    if not values:
        return "<p class=\"muted\">no completed evaluation with a value</p>"
    lo, hi = min(values), max(values)
    hi = hi if hi > lo else lo + 1
    n = max(len(vs) for _, vs, _ in series)

    def x(k: int) -> float:
        return _PAD + (_W - 2 * _PAD) * (k / max(1, n - 1))

    def y(v: float) -> float:
        return _H - _PAD - (_H - 2 * _PAD) * (v - lo) / (hi - lo)

    parts = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{_W}" height="{_H}" role="img">',
             f'<text x="4" y="{_PAD}" font-size="11">{hi:g}</text>',
             f'<text x="4" y="{_H - _PAD}" font-size="11">{lo:g}</text>',
             f'<text x="{_W - _PAD}" y="{_H - 8}" font-size="11">{n}</text>']
    for _, vs, colour in series:
        best: list[tuple[int, float]] = []  # (evaluation, best so far) from the first one with a value
        for k, v in enumerate(vs):
            if v is not None:
                best.append((k, v if not best else (min(best[-1][1], v) if minimize else max(best[-1][1], v))))
            elif best:
                best.append((k, best[-1][1]))
        parts += [f'<circle cx="{x(k):.1f}" cy="{y(v):.1f}" r="3" fill="{colour}" opacity=".6"/>'
                  for k, v in enumerate(vs) if v is not None]
        if best:
            points = " ".join(f"{x(k):.1f},{y(v):.1f}" for k, v in best)
            parts.append(f'<polyline points="{points}" fill="none" stroke="{colour}" stroke-width="2"/>')
    parts.append("</svg>")
    return "".join(parts)


def _pareto(document: Mapping[str, Any]) -> str:
    """The non-dominated evaluations, one row each with every objective's value (any number of objectives)."""
    objectives = document["objectives"]
    points = [(tuple(r["values"]), r["key"]) for r in document["evaluations"]
              if r.get("values") and all(present(v) for v in r["values"])]
    if not points:
        return ""
    # as minimized values, so one comparison serves every direction
    signs = [1.0 if o["direction"] == "minimize" else -1.0 for o in objectives]

    def dominates(a: tuple[float, ...], b: tuple[float, ...]) -> bool:
        pairs = [(s * x, s * y) for s, x, y in zip(signs, a, b, strict=True)]
        return all(x <= y for x, y in pairs) and any(x < y for x, y in pairs)

    front = sorted(p for p in points if not any(dominates(q[0], p[0]) for q in points))
    rows = "".join(f"<tr><td>{_e(k)}</td>" + "".join(f"<td>{v:g}</td>" for v in values) + "</tr>"
                   for values, k in front)
    heads = "".join(f"<th>{_e(o['label'])} ({_e(o['direction'])})</th>" for o in objectives)
    return (f"<section id=\"pareto\"><h2>Pareto front</h2><p class=\"muted\">{len(front)} of {len(points)} "
            "evaluations with every objective's value: none of the others is at least as good in every objective "
            f"and better in one.</p><table><tr><th>evaluation</th>{heads}</tr>{rows}</table></section>")


def _importance(out: Path, document: Mapping[str, Any]) -> str:
    import optuna

    from rei.search.study import journal

    try:
        stored = optuna.load_study(study_name=document["sampler"], storage=journal(out))
        # the simulated evaluations only: an invalid candidate's penalty says nothing about the robot
        study = optuna.create_study(directions=stored.directions)
        # with the runs' own values, not what a repeated failure was told (``diversity``), and only the runs that
        # have every objective: a 10^6 for a missing one would be all the importance there is
        study.add_trials([optuna.trial.create_trial(params=t.params, distributions=t.distributions,
                                                    values=t.user_attrs["values"])
                          for t in stored.get_trials(deepcopy=False, states=(TrialState.COMPLETE,))
                          if t.user_attrs.get("simulated") and t.user_attrs.get("values")
                          and all(present(v) for v in t.user_attrs["values"])])
        rows = []
        for i, objective in enumerate(document["objectives"]):
            sign = 1.0 if objective["direction"] == "minimize" else -1.0  # PED-ANOVA ranks towards low targets
            with warnings.catch_warnings():  # PED-ANOVA's reminder that it ranks towards low targets: signed above
                warnings.simplefilter("ignore", UserWarning)
                importance = optuna.importance.get_param_importances(
                    study, target=lambda t, i=i, sign=sign: sign * t.values[i])
            rows += [f"<tr><td>{_e(objective['label'])}</td><td>{_e(name)}</td><td>{value:.2f}</td></tr>"
                     for name, value in importance.items()]
    except (ValueError, RuntimeError, KeyError) as error:  # too few completed evaluations, one parameter
        return f"<section id=\"importance\"><h2>Parameter importance</h2><p class=\"muted\">{_e(str(error))}</p></section>"
    return ("<section id=\"importance\"><h2>Parameter importance</h2><table><tr><th>objective</th><th>parameter</th>"
            f"<th>importance</th></tr>{''.join(rows)}</table></section>")


def _failures(out: Path, document: Mapping[str, Any]) -> str:
    failures = document["failures"]
    if not failures:
        return "<section id=\"failures\"><h2>Distinct failures</h2><p>none found</p></section>"
    parts = ["<section id=\"failures\"><h2>Distinct failures (most severe first)</h2>"]
    for n, failure in enumerate(failures, start=1):
        shrunk = failure.get("shrunk") or {}
        links = [f"<a href=\"{_rel(out, failure['case'])}\">case</a>",
                 f"<a href=\"{_rel(out, failure['report'])}\">run report</a>"]
        if shrunk.get("case"):
            links.append(f"<a href=\"{_rel(out, shrunk['case'])}\">shrunk case</a> (removed "
                         f"{_e(', '.join(shrunk.get('removed') or []) or 'nothing')})")
        requirements = ", ".join(failure.get("requirements") or [])
        parts.append(f"<div class=\"failure\"><h3>{_e(failure['signature'])}</h3>"
                     f"<p class=\"requirements\">fails {_e(requirements)}: {_e(failure.get('what') or '')}</p>"
                     f"<p>{_e(failure['message'])}; worst utility {failure['worst_utility']:g}; found in {len(failure['evaluations'])} "
                     f"evaluation(s), first {_e(failure['first'])} (seed {failure.get('seed')}"
                     + (f", fault {_e(failure['fault'])}" if failure.get("fault") else "")
                     + (f"; shrunk to fault {_e(shrunk['fault'])}" if shrunk.get("fault") else "") + "). "
                     + " · ".join(links) + "</p>" + _map(Path(failure["run"]), f"failure-{n}") + "</div>")
    parts.append("</section>")
    return "\n".join(parts)


def _map(run_dir: Path, prefix: str) -> str:
    """The run report's map of ``run_dir``, its ids (``map``, ``map-robot-path``, ...) prefixed with ``prefix``:
    the page holds one map per failure, and an id is unique in a page."""
    from rei.report.map_svg import render_map
    from rei.report.run_data import load_run
    from rei.report.tracks import collect_tracks

    task = run_dir / "task.json"
    try:
        import json

        case_dir = Path(json.loads(task.read_text(encoding="utf-8"))["case_dir"])
        data = load_run(run_dir, case_dir)
        svg = render_map(data.world, collect_tracks(data.states()), data.goals, data.signals, data.picture)
        return _MAP_ID.sub(lambda m: f'id="{prefix}-{m.group(1)}"', svg)
    except (OSError, ValueError, KeyError) as error:
        return f"<p class=\"muted\">no map: {_e(str(error))}</p>"


def _rel(out: Path, path: str | None) -> str:
    if not path:
        return "#"
    try:
        return html.escape(str(Path(path).resolve().relative_to(out.resolve())), quote=True)
    except ValueError:
        return html.escape(Path(path).as_uri(), quote=True)


def _e(text: str) -> str:
    return html.escape(str(text))
