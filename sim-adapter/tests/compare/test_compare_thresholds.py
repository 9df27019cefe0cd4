# SPDX-License-Identifier: EPL-2.0
"""The thresholds file of rei compare: its schema, and every mistake reported with its file, line and column."""

from __future__ import annotations

from pathlib import Path

import pytest

from rei.compare.thresholds import (
    Threshold,
    ThresholdsError,
    default_thresholds,
    load_thresholds,
    parse_thresholds,
)
from rei.evaluation.metrics import Better


def test_a_file_with_sizes_levels_and_a_direction() -> None:
    got = parse_thresholds("""# comment
metrics:
  success: {p: 0.05}
  clearance_static_min: {worse_by: 0.05}
  time: {worse_by: 5, p: 1e-2}
  speed_mean: {better: higher, worse_by: 0.02}
""", "t.yaml")
    assert got.items == (Threshold("success", Better.HIGHER, 0.0, 0.05),
                         Threshold("clearance_static_min", Better.HIGHER, 0.05, None),
                         Threshold("time", Better.LOWER, 5.0, 0.01),
                         Threshold("speed_mean", Better.HIGHER, 0.02, None))
    assert got.source == "t.yaml"
    assert got.items[1].describe() == "clearance_static_min lower by more than 0.05 m"
    assert got.items[0].describe() == "success lower at p < 0.05"
    assert Threshold("oscillations", Better.LOWER).describe() == "oscillations higher at all"


@pytest.mark.parametrize(("text", "where", "message"), [
    ("metrics:\n  sucess: {p: 0.05}\n", "2:3", "unknown metric 'sucess'; known: success, time"),
    ("metrics:\n  time: {worse_by: -1}\n", "2:20", "time: 'worse_by' must be >= 0"),
    ("metrics:\n  time: {worse_by: fast}\n", "2:20", "time: 'worse_by' must be a number, got 'fast'"),
    ("metrics:\n  time: {p: 0}\n", "2:13", "time: 'p' must be a significance level in (0, 1], got 0"),
    ("metrics:\n  time: {p: true}\n", "2:13", "time: 'p' must be a number, got True"),
    ("metrics:\n  time: {}\n", "2:9", "time: give 'worse_by' (a size), 'p' (a significance level) or both"),
    ("metrics:\n  time: {worse: 1}\n", "2:10", "time: unknown key 'worse'; expected one of worse_by, p, better"),
    ("metrics:\n  speed_peak: {worse_by: 0.1}\n", "2:15", "speed_peak has no better direction of its own"),
    ("metrics:\n  time: {better: faster, p: 0.1}\n", "2:18", "time: 'better' must be higher or lower"),
    ("metrics:\n  time: 3\n", "2:9", "metric 'time' must be a mapping"),
    ("metrics:\n  time: {p: 0.1}\n  time: {p: 0.2}\n", "3:3", "'time' is given twice"),
    ("metric:\n  time: {p: 0.1}\n", "1:1", "unknown key 'metric'; expected 'metrics'"),
    ("metrics: {}\n", "1:10", "'metrics' is empty"),
    # keys YAML reads as numbers are placed too (they once escaped as a bare StopIteration)
    ("metrics: {1: {p: 0.05}}\n", "1:11", "unknown metric '1'; known:"),
    ("metrics:\n  time: {p: 0.1}\n2: x\n", "3:1", "unknown key '2'; expected 'metrics'"),
    ("metrics:\n  time: {0.5: 1, p: 0.1}\n", "2:10", "time: unknown key '0.5'; expected one of"),
    ("metrics: [a, b]\n", "1:10", "'metrics' must be a mapping"),
    ("metrics:\n  time: {p: [0.1\n", "3:1", "not YAML"),
    ("", "1:1", "empty: expected a mapping with 'metrics'"),
])
def test_mistakes_name_their_place(text: str, where: str, message: str) -> None:
    with pytest.raises(ThresholdsError) as error:
        parse_thresholds(text, "t.yaml")
    assert str(error.value).startswith(f"t.yaml:{where}: "), str(error.value)
    assert message in str(error.value)


def test_files_and_defaults(tmp_path: Path) -> None:
    with pytest.raises(ThresholdsError, match="nope.yaml: cannot read"):
        load_thresholds(tmp_path / "nope.yaml")
    path = tmp_path / "t.yaml"
    path.write_text("metrics:\n  spl: {worse_by: 0.1}\n")
    assert load_thresholds(path).source == str(path)
    defaults = {t.metric: t for t in default_thresholds().items}
    assert defaults["clearance_static_min"].worse_by == 0.05 and defaults["success"].p == 0.05


def test_every_mistake_is_reported_at_once_in_the_order_of_the_file() -> None:
    # a mistake does not hide the next: another metric's, or another key's of the same metric
    text = "metrics:\n  sucess: {p: 0.05}\n  time: {worse_by: -1, p: 2}\n  spl: {p: 0.1}\nbaseline: a\n"
    with pytest.raises(ThresholdsError) as error:
        parse_thresholds(text, "t.yaml")
    problems = str(error.value).splitlines()
    assert len(problems) == 4, problems
    assert problems[0].startswith("t.yaml:2:3: unknown metric 'sucess'; known: success, time")
    assert problems[1:] == ["t.yaml:3:20: time: 'worse_by' must be >= 0 (a size, in the metric's unit), got -1",
                            "t.yaml:3:27: time: 'p' must be a significance level in (0, 1], got 2",
                            "t.yaml:5:1: unknown key 'baseline'; expected 'metrics'"]
