# SPDX-License-Identifier: EPL-2.0
"""Specs that parse as YAML and name real keys, but ask for what the search cannot do: a single-objective sampler
with several objectives, fault values the fault refuses, signals no pattern sends. Each is refused at its
FILE:LINE:COLUMN with what was expected, before anything runs (tests/search's specs name the same keys)."""

from __future__ import annotations

from pathlib import Path

import pytest
from spec_helpers import error_of, parse

from rei.campaign.spec import SpecError

SPEC = """\
case: case.rei
sampler: tpe
parameters:
  - {seed: [0, 100]}
  - {fault: "laser:1%", rate: [0.0, 0.05], gain: [0.1, 2], width: [1, 4]}
objectives:
  - utility
  - {signal: SIG_OBJECT_COLLISION_BEGIN, of: first}
"""


@pytest.fixture
def folder(tmp_path: Path) -> Path:
    (tmp_path / "case.rei").write_text("testcase T {}\n", encoding="utf-8")
    return tmp_path


def test_the_limits_pass_a_spec_within_them(folder: Path) -> None:
    spec = parse(SPEC, folder)
    assert [p.key for p in spec.parameters] == ["seed", "fault.rate", "fault.gain", "fault.width"]
    assert parse(SPEC.replace("sampler: tpe", "sampler: cmaes").replace(
        "  - {signal: SIG_OBJECT_COLLISION_BEGIN, of: first}\n", ""), folder).sampler == "cmaes"
    for sampler in ("tpe", "nsga2", "qmc", "random"):  # Optuna's multi-objective samplers
        assert parse(SPEC.replace("sampler: tpe", f"sampler: {sampler}"), folder).with_options(
            sampler=sampler).sampler == sampler


@pytest.mark.parametrize(("change", "expected"), [
    (("sampler: tpe", "sampler: cmaes"),
     ("s.yaml:2:10: cmaes searches a single objective, the spec gives 2 (utility, "
     "signal:SIG_OBJECT_COLLISION_BEGIN:first): use nsga2 (or tpe) for several, or keep one objective")),
    (("rate: [0.0, 0.05]", "rate: [0, 5]"),
     ("s.yaml:5:31: rate [0, 5] reaches outside what the fault accepts: laser fault rate must be in [0, 1] impulses "
     "per beam per scan, got 5.0")),
    (("gain: [0.1, 2]", "gain: [-3, 40]"),
     "s.yaml:5:50: gain [-3, 40] reaches outside what the fault accepts: laser fault gain must be >= 0, got -3.0"),
    (("width: [1, 4]", "width: [0, 4]"),
     "s.yaml:5:67: width [0, 4] reaches outside what the fault accepts: laser fault width must be >= 1 beam, got 0"),
    (('"laser:1%"', '"none"'),
     "s.yaml:5:13: 'fault' is the fault the values change, such as \"laser:1%\", got 'none' (no fault)"),
])
def test_a_value_beyond_what_the_search_can_do_is_placed(folder: Path, change: tuple[str, str],
                                                         expected: str) -> None:
    assert SPEC.count(change[0]) == 1
    assert error_of(SPEC.replace(*change), folder) == expected


def test_an_unknown_signal_is_placed_with_the_known_names_and_a_close_one(folder: Path) -> None:
    from rei.evaluation.signals import KNOWN_SIGNALS

    message = error_of(SPEC.replace("SIG_OBJECT_COLLISION_BEGIN", "SIG_OBJECT_COLISION_BEGIN"), folder)
    assert message.startswith("s.yaml:8:14: unknown signal 'SIG_OBJECT_COLISION_BEGIN' "
                              "(did you mean SIG_OBJECT_COLLISION_BEGIN?); known: "), message
    assert all(name in message for name in KNOWN_SIGNALS)
    assert message.endswith("; a signal of your own VEPL patterns: give their folder as 'patterns'"), message
    assert "did you mean" not in error_of(SPEC.replace("SIG_OBJECT_COLLISION_BEGIN", "BUMP"), folder)
    # every signal the default patterns send is one a search may look for
    for name in KNOWN_SIGNALS:
        assert parse(SPEC.replace("SIG_OBJECT_COLLISION_BEGIN", name), folder).objectives[1].key == name


def test_cmaes_from_the_command_line_is_refused_at_the_objectives(folder: Path) -> None:
    spec = parse(SPEC, folder)
    with pytest.raises(SpecError) as raised:
        spec.with_options(sampler="cmaes")
    assert str(raised.value) == ("s.yaml:7:3: --sampler cmaes searches a single objective, the spec gives 2 (utility, "
                                 "signal:SIG_OBJECT_COLLISION_BEGIN:first): use nsga2 (or tpe) for several, or keep "
                                 "one objective")
    assert spec.with_options(budget=3, sampler=None).sampler == "tpe"


def test_the_command_refuses_cmaes_with_two_objectives_before_anything_runs(
        folder: Path, capsys: pytest.CaptureFixture[str]) -> None:
    from rei.cli import main

    (folder / "s.yaml").write_text(SPEC, encoding="utf-8")
    out = folder / "out"
    assert main(["search", str(folder / "s.yaml"), "-o", str(out), "--sampler", "cmaes"]) == 2
    assert capsys.readouterr().err.startswith(f"rei: error: {folder / 's.yaml'}:7:3: --sampler cmaes searches a "
                                              "single objective")
    assert not out.exists()
