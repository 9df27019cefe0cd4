# SPDX-License-Identifier: EPL-2.0
"""When a difference is a regression: the thresholds file of ``rei compare --thresholds FILE.yaml``.

Format (docs/metrics.md, "Comparing two versions", its regression verdicts)::

    metrics:
      success: {p: 0.05}                    # success rate lower, McNemar's exact test p < 0.05
      clearance_static_min: {worse_by: 0.05} # mean paired minimum clearance lower by more than 0.05 m
      time: {worse_by: 5, p: 0.05}          # slower by more than 5 s on average, and Wilcoxon p < 0.05
      speed_mean: {better: higher, worse_by: 0.02}

A metric is regressed when its mean paired difference (candidate - baseline) is worse, in the metric's better
direction, by more than ``worse_by`` (default 0: any worsening) and, when ``p`` is given, the paired test's p is
below it. ``better`` is needed only for the metrics that have no direction of their own (the speeds). Every
mistake is reported at once, each with the file, line and column, as ``rei validate`` reports a test case's.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import yaml

from rei import located_yaml
from rei.evaluation.metrics import BY_NAME, Better

KEYS = ("worse_by", "p", "better")


class ThresholdsError(located_yaml.Problems):
    """A thresholds file that can not be used: each of its mistakes starts with ``FILE:LINE:COLUMN:``."""


@dataclass(frozen=True, slots=True)
class Threshold:
    metric: str
    better: Better
    worse_by: float = 0.0
    p: float | None = None

    def describe(self) -> str:
        unit = BY_NAME[self.metric].unit
        size = f" by more than {self.worse_by:g}{f' {unit}' if unit else ''}" if self.worse_by else ""
        direction = "lower" if self.better == Better.HIGHER else "higher"
        test = f" at p < {self.p:g}" if self.p is not None else "" if size else " at all"
        return f"{self.metric} {direction}{size}{test}"


@dataclass(frozen=True, slots=True)
class Thresholds:
    items: tuple[Threshold, ...]
    source: str  # the file, or "defaults"


def default_thresholds() -> Thresholds:
    """Without a file: fewer successes, worse SPL or more collisions beyond chance (p < 0.05), minimum clearances
    5 cm closer on average; and among people: any more collisions in which the robot drove into a person (a
    requirement, NO_ROBOT_AT_FAULT_COLLISION, so one more in one pair is a regression: no test waits for chance),
    2 % more of the mission within a person's intimate space (0.45 m) and people delayed 1 s more by the robot on
    average. The people's metrics are judged only where both sides had people (else not applicable)."""
    return Thresholds((
        Threshold("success", Better.HIGHER, 0.0, 0.05),
        Threshold("spl", Better.HIGHER, 0.0, 0.05),
        Threshold("collision_episodes", Better.LOWER, 0.0, 0.05),
        Threshold("clearance_static_min", Better.HIGHER, 0.05),
        Threshold("clearance_humans_min", Better.HIGHER, 0.05),
        Threshold("collisions_robot_at_fault", Better.LOWER, 0.0),
        Threshold("intimate_share", Better.LOWER, 0.02),
        Threshold("people_delay_mean", Better.LOWER, 1.0),
    ), "defaults")


def load_thresholds(path: Path) -> Thresholds:
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as error:
        raise ThresholdsError(f"{path}: cannot read: {error.strerror or error}") from None
    return parse_thresholds(text, str(path))


def parse_thresholds(text: str, source: str = "thresholds") -> Thresholds:
    """The thresholds of ``text``; every mistake in it at once (a ``ThresholdsError``), in the order of the file."""
    try:
        root = located_yaml.compose(text)
    except located_yaml.LocatedError as error:
        raise ThresholdsError(error.at(source)) from None
    if root is None:
        raise ThresholdsError(f"{source}:1:1: empty: expected a mapping with 'metrics'")
    problems = located_yaml.Collector()
    top = _mapping(root, source, "the file", problems)
    for key, (key_node, _) in top.items():
        if key != "metrics":
            problems.add(_message(source, key_node, f"unknown key {key!r}; expected 'metrics'"))
    items = []
    if "metrics" not in top:
        problems.add(_message(source, root, "'metrics' is required: a mapping of metric names to thresholds"))
    with problems.check():
        metrics_node = top["metrics"][1] if "metrics" in top else None
        metrics = _mapping(metrics_node, source, "'metrics'", problems) if metrics_node is not None else {}
        if metrics_node is not None and not metrics:
            raise _error(source, metrics_node, "'metrics' is empty: name at least one metric")
        for name, (key_node, node) in metrics.items():
            with problems.check():
                if name not in BY_NAME:
                    raise _error(source, key_node, f"unknown metric {name!r}; known: {', '.join(BY_NAME)}")
                items.append(_threshold(name, node, source))
    problems.raise_if_any(ThresholdsError)
    return Thresholds(tuple(items), source)


def _threshold(name: str, node: yaml.Node, source: str) -> Threshold:
    """The threshold of metric ``name``; each of its keys checked (a mistake does not hide another's)."""
    problems = located_yaml.Collector()
    entries = _mapping(node, source, f"metric {name!r}", problems)
    unknown = [key for key in entries if key not in KEYS]
    for key in unknown:
        problems.add(_message(source, entries[key][0], f"{name}: unknown key {key!r}; expected one of "
                                                       f"{', '.join(KEYS)}"))
    fields = {key: value for key, (_, value) in entries.items()}
    if "worse_by" not in fields and "p" not in fields and not unknown:  # a mistyped key may be the one meant
        problems.add(_message(source, node, f"{name}: give 'worse_by' (a size), 'p' (a significance level) or both"))
    better = BY_NAME[name].better
    with problems.check():
        if "better" in fields:
            value = _scalar(fields["better"])
            if value not in ("higher", "lower"):
                raise _error(source, fields["better"], f"{name}: 'better' must be higher or lower, got {value!r}")
            better = Better(value)
        elif better == Better.NEITHER:
            raise _error(source, node, f"{name} has no better direction of its own: say 'better: higher' or "
                                       "'better: lower'")
    worse_by = 0.0
    with problems.check():
        if "worse_by" in fields:
            worse_by = _number(fields["worse_by"], source, f"{name}: 'worse_by'")
            if worse_by < 0:
                raise _error(source, fields["worse_by"], f"{name}: 'worse_by' must be >= 0 (a size, in the "
                             f"metric's unit), got {worse_by:g}")
    p = None
    with problems.check():
        if "p" in fields:
            p = _number(fields["p"], source, f"{name}: 'p'")
            if not 0 < p <= 1:
                raise _error(source, fields["p"], f"{name}: 'p' must be a significance level in (0, 1], got {p:g}")
    problems.raise_if_any(ThresholdsError)
    return Threshold(name, better, worse_by, p)


def _mapping(node: yaml.Node, source: str, what: str, problems: located_yaml.Collector) -> located_yaml.Entries:
    """The entries of a mapping; a key given twice is one of ``problems`` (its first entry is read)."""
    twice: list[located_yaml.LocatedError] = []
    try:
        entries = located_yaml.mapping(node, what, twice)
    except located_yaml.LocatedError as error:
        raise ThresholdsError(error.at(source)) from None
    for error in twice:
        problems.add(error.at(source))
    return entries


def _scalar(node: yaml.Node) -> object:
    return located_yaml.scalar(node)


def _number(node: yaml.Node, source: str, what: str) -> float:
    value = located_yaml.number(node)
    if value is None:
        raise _error(source, node, f"{what} must be a number, got {_scalar(node)!r}")
    return value


def _message(source: str, node: yaml.Node, message: str) -> str:
    return located_yaml.error(node, message).at(source)


def _error(source: str, node: yaml.Node, message: str) -> ThresholdsError:
    return ThresholdsError(_message(source, node, message))
