# SPDX-License-Identifier: EPL-2.0
"""A search spec with several mistakes reports them all at once, each at its FILE:LINE:COLUMN and in the order of
the file; a check that depends on one that failed (a fault's searched values on the fault, a signal on the
patterns that would declare it) is skipped, the independent ones still run."""

from __future__ import annotations

from pathlib import Path

import pytest
from spec_helpers import error_of

SPEC = """\
case: case.rei
sampler: tpe
parameters:
  - {human: walker, start: [12, 4], speed: [0.5, 1.5]}
  - {object: bin1, flor: any}
objectives:
  - {metric: clearence_humans_min}
shrink: {budget: 3}
nmae: x
"""


@pytest.fixture
def folder(tmp_path: Path) -> Path:
    (tmp_path / "case.rei").write_text("testcase T {}\n", encoding="utf-8")  # only its existence is checked here
    return tmp_path


def test_every_mistake_is_reported_at_its_place_in_the_order_of_the_file(folder: Path) -> None:
    problems = error_of(SPEC, folder).splitlines()
    assert len(problems) == 4, problems
    assert problems[:2] == ["s.yaml:4:28: the range's low end must be below its high end, got [12, 4]",
                            "s.yaml:5:20: 'flor' is not a property of an object; expected floor, yaw"]
    assert problems[2].startswith("s.yaml:7:14: unknown metric 'clearence_humans_min'; known: success, ")
    assert problems[3].startswith("s.yaml:9:1: unknown key 'nmae'; known: name, case")


def test_a_check_that_depends_on_a_failed_one_is_skipped(folder: Path) -> None:
    text = ("case: case.rei\nparameters:\n  - {fault: \"laser:lots\", rate: [0, 5]}\n  - {seed: [9, 0]}\n"
            "objectives:\n  - {signal: SIG_MINE}\n  - {verdict: NEVER}\npatterns: nowhere\nsampler: cmaes\n")
    # the rate is not checked against a fault that did not read, the signal against patterns that did not, nor
    # cmaes against objectives of which one did not
    problems = error_of(text, folder).splitlines()
    assert [p.split(": ", 1)[0] for p in problems] == ["s.yaml:3:13", "s.yaml:4:12", "s.yaml:7:15", "s.yaml:8:11"]
    assert problems[0].startswith("s.yaml:3:13: bad fault spec 'laser:lots': unknown preset 'lots'")
    assert problems[1] == "s.yaml:4:12: the range's low end must be below its high end, got [9, 0]"
    assert problems[2].startswith("s.yaml:7:15: unknown requirement 'NEVER'")
    assert problems[3] == f"s.yaml:8:11: --patterns {folder / 'nowhere'}: not a folder"


def test_a_key_given_twice_does_not_hide_the_rest(folder: Path) -> None:
    text = "case: case.rei\nparameters: [{seed: [0, 9]}]\nobjectives: [utility]\nseed: 1\nseed: 2\nbudget: 0\n"
    assert error_of(text, folder).splitlines() == ["s.yaml:5:1: 'seed' is given twice",
                                                   "s.yaml:6:9: 'budget' must be >= 1, got 0"]


def test_a_range_without_a_finite_end_and_a_negative_seed_are_refused_at_the_range(tmp_path: Path) -> None:
    """Both were taken: an end at .inf stopped the search at its first candidate blaming the room editor's engine,
    a seed below 0 made every run crash in its random generators."""
    import shutil

    shutil.copy(Path(__file__).resolve().parents[3] / "examples" / "search" / "crossing.rei", tmp_path)
    text = ("case: crossing.rei\nparameters:\n  - {human: walker, start: [0, .inf]}\n  - {seed: [-5, 3]}\n"
            "  - {object: bin1, yaw: [-.inf, 0]}\nobjectives: [utility]\n")
    assert error_of(text, tmp_path).splitlines() == [
        "s.yaml:3:28: a range's ends must be finite numbers, got [0, inf]",
        "s.yaml:4:12: a run's seed is 0 or more, got [-5, 3]",
        "s.yaml:5:25: a range's ends must be finite numbers, got [-inf, 0]"]


def test_a_script_controller_is_a_file_relative_to_the_spec(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The candidates' runs build it in their own folders: relative to the current folder it was not found there."""
    import shutil

    from spec_helpers import parse

    shutil.copy(Path(__file__).resolve().parents[3] / "examples" / "search" / "crossing.rei", tmp_path)
    (tmp_path / "short.txt").write_text("1.0 0.1 0.0\n", encoding="utf-8")
    monkeypatch.chdir(tmp_path.parent)
    text = "case: crossing.rei\ncontroller: script:short.txt\nparameters:\n  - {seed: [0, 3]}\nobjectives: [utility]\n"
    assert parse(text, tmp_path).controller == f"script:{tmp_path / 'short.txt'}"


def test_a_metric_without_a_worse_side_needs_a_direction(tmp_path: Path) -> None:
    """speed_mean and the social zone's time describe the drive: neither side is worse, and the search maximized
    them without saying so (rei compare asks 'better:' for the same metrics)."""
    import shutil

    from spec_helpers import parse

    shutil.copy(Path(__file__).resolve().parents[3] / "examples" / "search" / "crossing.rei", tmp_path)
    text = ("case: crossing.rei\nparameters:\n  - {seed: [0, 3]}\nobjectives:\n  - {metric: speed_mean}\n"
            "  - {metric: social_time}\nsampler: nsga2\n")
    assert error_of(text, tmp_path).splitlines() == [
        "s.yaml:5:14: speed_mean has no worse side of its own: give 'direction: minimize' or 'direction: maximize'",
        "s.yaml:6:14: social_time has no worse side of its own: give 'direction: minimize' or 'direction: maximize'"]
    chosen = parse(text.replace("{metric: speed_mean}", "{metric: speed_mean, direction: minimize}")
                   .replace("{metric: social_time}", "{metric: social_time, direction: maximize}"), tmp_path)
    assert [o.direction for o in chosen.objectives] == ["minimize", "maximize"]
