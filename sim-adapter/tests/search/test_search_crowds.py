# SPDX-License-Identifier: EPL-2.0
"""Crowds and groups in a search: their lines read and rewritten in the text (rei.edit.gatherings), their counts,
rates and behaviours as parameters checked against the base case (rei.search.space), the spec's own checks, and
shrinking towards fewer and slower people. The real room editor engine, generator and runs are in
tests/search/test_search_crowd_e2e.py."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from optuna.distributions import CategoricalDistribution, FloatDistribution, IntDistribution
from search_fakes import FakeMaker, FakePool, task_of
from spec_helpers import error_of, parse
from test_search_space import DIAGRAM, p

from rei.campaign.spec import SpecError
from rei.edit.gatherings import gatherings, number, with_values
from rei.search.candidates import VALID, Candidate
from rei.search.failures import Failure
from rei.search.shrink import shrink
from rei.search.space import Edit, Space
from rei.search.spec import Range

TEXT = """\
testcase T {
  room R size 8 x 4 {
    // a crowd shoppers 99 in a comment is not one
    crowd shoppers 12 : Human from [F_0_0, F_0_1]
                      to [F_7_0, F_7_1]
      speed 1.0 to 1.4 start 2 s loop  // its rate is unwritten: all set off at once
    group family 3 route [F_4_2 wait 1 s, F_6_2] blocks speed 1.1
    crowd q 2 from [F_1_3] to [F_6_3] rate 0.5 scared
    object crowd : Box on F_3_0
    robot r : Waffle on F_4_0
  }
  mission M { goto F_5_1 }
}
"""


def test_the_lines_are_read_with_where_their_values_are() -> None:
    found = gatherings(TEXT)
    assert list(found) == ["shoppers", "family", "q"]
    shoppers, family, q = found.values()
    assert (shoppers.kind, shoppers.count, shoppers.rate, shoppers.behaviour) == ("crowd", 12, None, "avoids")
    assert TEXT[slice(*shoppers.count_at)] == "12" and shoppers.behaviour_at is None
    assert TEXT[:shoppers.end].endswith("start 2 s loop")  # the statement ends before the comment
    assert (family.kind, family.count, family.behaviour) == ("group", 3, "blocks")
    assert TEXT[:family.end].endswith("blocks speed 1.1")
    assert (q.rate, q.behaviour) == (0.5, "scared") and TEXT[slice(*q.rate_at)] == "0.5"
    assert shoppers.people()[-1] == "shoppers_12"


def test_values_are_set_in_place_and_unwritten_ones_appended() -> None:
    text = with_values(TEXT, [{"name": "shoppers", "count": 4, "rate": 0.25, "behaviour": "ignores"},
                              {"name": "family", "count": 2, "behaviour": "avoids"},
                              {"name": "q", "rate": 1.0 / 3, "behaviour": "curious"}])
    changed = [line for line in text.splitlines() if line not in TEXT.splitlines()]
    assert changed == ["    crowd shoppers 4 : Human from [F_0_0, F_0_1]",
                       ("      speed 1.0 to 1.4 start 2 s loop rate 0.25 ignores  // its rate is unwritten: all set "
                       "off at once"),
                       "    group family 2 route [F_4_2 wait 1 s, F_6_2] avoids speed 1.1",
                       "    crowd q 2 from [F_1_3] to [F_6_3] rate 0.333 curious"]
    # avoids, the default, is not written where no behaviour is
    assert with_values(TEXT, [{"name": "shoppers", "behaviour": "avoids"}]) == TEXT
    assert (number(2.0), number(1e-5), number(0.1234)) == ("2", "0", "0.123")


def space(*parameters: Any, humans: bool = True, issues: list[dict[str, Any]] | None = None) -> Space:
    def validate(text: str) -> list[dict[str, Any]]:
        return issues or []

    return Space(list(parameters), DIAGRAM, humans=humans, text=TEXT, validate=validate)


def test_counts_rates_and_behaviours_are_parameters_with_the_lines_values_as_base() -> None:
    s = space(p("crowd", "shoppers", "count", Range(2, 12, True)), p("crowd", "shoppers", "rate", Range(0.2, 2)),
              p("crowd", "q", "behaviour", ("avoids", "blocks")), p("group", "family", "count", Range(2, 4, True)))
    assert s.distributions == {"shoppers.count": IntDistribution(2, 12), "shoppers.rate": FloatDistribution(0.2, 2),
                               "q.behaviour": CategoricalDistribution(["avoids", "blocks"]),
                               "family.count": IntDistribution(2, 4)}
    assert s.base_values() == {"shoppers.count": 12, "shoppers.rate": None, "q.behaviour": "scared",
                               "family.count": 3}
    edit = s.edit({"shoppers.count": 5, "shoppers.rate": 0.5, "q.behaviour": "blocks", "family.count": 2})
    assert edit.operations == () and edit.people == (
        {"name": "shoppers", "count": 5, "rate": 0.5}, {"name": "q", "behaviour": "blocks"},
        {"name": "family", "count": 2})
    assert "crowd shoppers 5 " in edit.text(TEXT) and "rate 0.5" in edit.text(TEXT)
    # a removed crowd is deleted, not set
    removed = s.edit({"shoppers.count": 5, "shoppers.rate": None, "q.behaviour": "blocks", "family.count": 2},
                     ["shoppers"])
    assert removed.operations[-1] == {"op": "deleteObject", "name": "shoppers"}
    assert [person["name"] for person in removed.people] == ["q", "family"]
    assert s.removable() == ["bin1", "walker", "shoppers", "family", "q"]
    assert s.owns("shoppers", "shoppers_7") and not s.owns("shoppers", "shoppers_x") and not s.owns("q", "q2")


def problems_of(*parameters: Any, **options: Any) -> list[str]:
    with pytest.raises(SpecError) as raised:
        space(*parameters, **options)
    return list(raised.value.problems)


def test_a_name_the_base_case_has_not_as_that_kind_is_refused_with_a_hint() -> None:
    assert problems_of(p("crowd", "shopers", "count", Range(2, 4, True)),
                       p("crowd", "family", "behaviour", ("blocks",)),
                       p("group", "nobody", "count", Range(2, 3, True))) == [
        "s.yaml:1:1: the base case has no crowd named 'shopers' (did you mean shoppers?); its crowds: shoppers, q",
        ("s.yaml:1:1: the base case has no crowd named 'family': family is a group, searched as {group: family, "
        "...}; its crowds: shoppers, q"),
        "s.yaml:1:1: the base case has no group named 'nobody'; its groups: family"]
    assert problems_of(p("crowd", "q", "rate", Range(0.1, 1)), humans=False) == [
        ("s.yaml:1:1: q is a crowd of people and the spec runs without humans (humans: false): its rate would change "
        "nothing; remove its parameters or set humans: true")]


def test_a_count_the_room_cannot_take_is_refused_with_the_languages_message() -> None:
    issue = {"severity": "error", "element": "shoppers", "message": "Crowd 'shoppers' of 40: its from floors hold at "
             "most 9 people of radius 0.25"}
    assert problems_of(p("crowd", "shoppers", "count", Range(2, 40, True)), issues=[issue]) == [
        ("s.yaml:1:1: shoppers of 40 people is more than the base case's room takes: Crowd 'shoppers' of 40: its "
        "from floors hold at most 9 people of radius 0.25")]
    # another element's issue is not this count's
    space(p("crowd", "shoppers", "count", Range(2, 40, True)), issues=[{**issue, "element": "q"}])


def test_the_spec_reads_crowds_and_groups_and_checks_their_ranges(tmp_path: Path) -> None:
    (tmp_path / "c.rei").write_text(TEXT, encoding="utf-8")
    spec = parse("case: c.rei\nparameters:\n"
                 "  - {crowd: shoppers, count: [1, 12], rate: [0.2, 2], behaviour: [avoids, blocks]}\n"
                 "  - {group: family, count: [2, 4]}\nobjectives: [utility]\n", tmp_path)
    assert [(q.target, q.name, q.prop, q.domain) for q in spec.parameters] == [
        ("crowd", "shoppers", "count", Range(1, 12, True)), ("crowd", "shoppers", "rate", Range(0.2, 2)),
        ("crowd", "shoppers", "behaviour", ("avoids", "blocks")), ("group", "family", "count", Range(2, 4, True))]
    message = error_of("case: c.rei\nparameters:\n"
                       "  - {crowd: shoppers, count: [0, 12], rate: [0, 2], speed: [1, 2], behaviour: [shy]}\n"
                       "  - {group: family, count: [1, 4], rate: [1, 2]}\n"
                       "  - {crowd: shoppers, count: [2.5, 4]}\n"
                       "  - {crowd: q, rate: [0.0001, 0.0004]}\nobjectives: [utility]\n", tmp_path)
    assert message.splitlines() == [
        "s.yaml:3:30: a crowd has 1 person or more (the language's least), got [0, 12]",
        "s.yaml:3:45: a crowd's rate (people a second) must be positive, got [0, 2]",
        "s.yaml:3:53: 'speed' is not a property of a crowd; expected count, rate, behaviour",
        "s.yaml:3:79: 'shy' is not a behaviour; expected avoids, ignores, curious, scared, blocks",
        "s.yaml:4:28: a group has 2 people or more (the language's least), got [1, 4]",
        "s.yaml:4:36: 'rate' is not a property of a group; expected count, behaviour",
        "s.yaml:5:30: expected a range [low, high] of two integers, got [2.5, 4]",
        # a rate the text would write as 0
        ("s.yaml:6:22: a crowd's rate is written with three decimals: 0.001 people a second at least, got "
         "[0.0001, 0.0004]")]


class TextMaker(FakeMaker):
    """A fake maker whose candidates are the base text with the crowds' values (and the operations)."""

    def make(self, key: str, edit: Edit) -> Candidate:
        candidate = Candidate(key, edit, VALID, edit.text(TEXT) + repr(edit.operations))
        self.made.append(candidate)
        return candidate


def test_shrinking_moves_a_crowd_towards_fewer_and_slower_people(tmp_path: Path) -> None:
    s = space(p("crowd", "shoppers", "count", Range(2, 12, True)), p("crowd", "shoppers", "rate", Range(0.2, 2)))

    def rule(text: str, seed: int, fault: str | None) -> list[str]:
        # shoppers_3 is met while the crowd has 3 people or more and sets off at 0.5 a second or faster
        line = gatherings(text)["shoppers"]
        return ["shoppers_3"] if line.count >= 3 and (line.rate or 9.0) >= 0.5 else []

    failure = Failure("R1", "shoppers_3", "-", None, ("R1",), "hit", "R1: hit")
    pool = FakePool(rule)
    result = shrink(failure, {"shoppers.count": 10, "shoppers.rate": 1.5}, s, TextMaker(tmp_path, DIAGRAM), pool,
                    task_of, tmp_path, "f1", 20, log=lambda _: None, run="original-run")
    # the bin, the walker, the other crowd and the group go; the crowd, which the failure's person is of, stays
    assert result.removed == ["bin1", "walker", "family", "q"]
    # 3 people: the failure's person needs them; the slowest rate passed, so the rate stays
    assert result.values == {"shoppers.count": 3, "shoppers.rate": 1.5}
