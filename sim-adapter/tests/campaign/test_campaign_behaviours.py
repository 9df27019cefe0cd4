# SPDX-License-Identifier: EPL-2.0
"""Campaign variants by the people's behaviour (issue #38): each room or case run once per behaviour, its people
behaving so, the runs keeping the room's name so that reports and `rei compare` group them by room and variant; a
behaviour variant without people who see the robot refused at the group."""

from __future__ import annotations

from pathlib import Path

import pytest

from rei.campaign import SpecError, parse_spec, plan_campaign
from rei.campaign.spec import load_spec

EXAMPLES = Path(__file__).resolve().parents[3] / "examples"
BEHAVIOURS = [{"name": b, "behaviour": b} for b in ("avoids", "ignores", "blocks")]


def test_each_generated_room_runs_once_per_behaviour_as_the_same_room(tmp_path: Path) -> None:
    rooms = {"size": "small", "density": "sparse", "humans": 2, "people": "reactive", "count": 2, "seed": 4}
    plan = plan_campaign(parse_spec({"variants": BEHAVIOURS, "groups": [{"name": "g", "rooms": rooms}]},
                                    base=tmp_path), tmp_path)
    # the group's own rooms (avoids) and the same rooms with the other behaviours, each a case of its own
    assert [c.key for c in plan.cases] == ["small_sparse_p2_s4_01", "small_sparse_p2-ignores_s4_01",
                                           "small_sparse_p2-blocks_s4_01", "small_sparse_p2_s4_02",
                                           "small_sparse_p2-ignores_s4_02", "small_sparse_p2-blocks_s4_02"]
    texts = {c.key: c.text or "" for c in plan.cases}
    # the same room: only its header's command and the people's behaviour differ
    blocks, avoids = texts["small_sparse_p2-blocks_s4_01"].splitlines(), texts["small_sparse_p2_s4_01"].splitlines()
    assert [a for a, b in zip(avoids, blocks, strict=True) if a != b and "`rei gen-rooms" not in a] == [
        line for line in avoids if " loop avoids" in line]
    assert texts["small_sparse_p2-blocks_s4_01"].count(" loop blocks") == 2
    first = [r for r in plan.runs if r.case == "small_sparse_p2_s4_01"]
    assert [(r.key, r.variant, Path(r.case_dir).name) for r in first] == [
        ("g__small_sparse_p2_s4_01__avoids__r0", "avoids", "small_sparse_p2_s4_01"),
        ("g__small_sparse_p2_s4_01__ignores__r0", "ignores", "small_sparse_p2-ignores_s4_01"),
        ("g__small_sparse_p2_s4_01__blocks__r0", "blocks", "small_sparse_p2-blocks_s4_01")]
    assert {r.case for r in plan.runs} == {"small_sparse_p2_s4_01", "small_sparse_p2_s4_02"}


def test_a_test_cases_people_crowds_and_groups_are_rewritten_for_each_behaviour(tmp_path: Path) -> None:
    plan = plan_campaign(parse_spec({"variants": [{"name": "base"}, {"name": "scared", "behaviour": "scared"}],
                                     "groups": [{"name": "people", "cases": ["people/crowds.rei"]}]},
                                    base=EXAMPLES), tmp_path)
    [own, scared] = plan.cases
    assert (own.key, own.path, own.text) == ("crowds", EXAMPLES / "people" / "crowds.rei", None)
    assert scared.key == "crowds-scared" and scared.path is None and scared.text is not None
    original = (EXAMPLES / "people" / "crowds.rei").read_text(encoding="utf-8")
    changed = [line for line in scared.text.splitlines() if line not in original.splitlines()]
    assert changed == ["      rate 1 speed 1.0 to 1.4 loop scared",
                       "    group family 3 route [F_5_1, F_5_6 wait 2s] speed 1.0 to 1.2 loop scared"]
    assert [(r.case, r.variant, Path(r.case_dir).name) for r in plan.runs] == [
        ("crowds", "base", "crowds"), ("crowds", "scared", "crowds-scared")]


def test_the_example_spec_reads(tmp_path: Path) -> None:
    spec = load_spec(EXAMPLES / "campaigns" / "behaviours.yaml")
    assert [(v.name, v.behaviour) for v in spec.groups[0].variants] == [
        ("avoids", "avoids"), ("ignores", "ignores"), ("curious", "curious"), ("scared", "scared"),
        ("blocks", "blocks")]
    assert len(plan_campaign(spec, tmp_path).runs) == 5 * spec.groups[0].rooms.count  # type: ignore[union-attr]


SPEC = """\
groups:
  - name: lanes
    rooms: {size: small, humans: 1}
    variants: [{name: i, behaviour: ignores}]
  - name: files
    cases: [alone.rei]
    variants: [{name: m, behaviour: mixed}]
  - name: shy
    cases: [alone.rei]
    variants: [{name: s, behaviour: shy}, {name: h, behaviour: blocks, humans: false}]
"""


def test_a_behaviour_without_people_who_see_the_robot_is_refused_at_the_group(tmp_path: Path) -> None:
    (tmp_path / "alone.rei").write_text((EXAMPLES / "simple_navigation.rei").read_text(encoding="utf-8"),
                                        encoding="utf-8")
    spec = tmp_path / "c.yaml"
    spec.write_text(SPEC, encoding="utf-8")
    with pytest.raises(SpecError) as raised:
        load_spec(spec)
    assert list(raised.value.problems) == [
        (f"{spec}:3:12: groups[0]: variant 'i' sets the people's behaviour (ignores): these rooms' humans walk lanes; "
        "give 'people: reactive'"),
        (f"{spec}:6:12: groups[1]: variant 'm': 'mixed' draws each person's behaviour in generated rooms ('rooms' "
        "with 'people: reactive'); for test cases give one behaviour"),
        (f"{spec}:6:13: groups[1]: variant 'm' sets the people's behaviour (mixed): alone.rei has no person who "
        "sees the robot (a human on a route, a crowd or a group)"),
        (f"{spec}:10:37: groups[2]: variants[0]: 'behaviour' must be one of avoids, ignores, curious, scared, "
        "blocks, mixed, got 'shy'"),
        # a behaviour for runs without people
        (f"{spec}:10:64: groups[2]: variants[1]: 'behaviour' sets how the people behave and 'humans: false' leaves "
         "them out of the runs; remove one of the two")]


def test_rewriting_behaviours_imports_no_room_editor_server() -> None:
    """rei.edit.gatherings is text edits that campaigns and searches use: importing it leaves the room editor's
    server and the live view beneath it (rei.view, rei.evaluation, rei.report) unimported."""
    import subprocess
    import sys

    code = ("import sys, rei.edit.gatherings, rei.search.space; "
            "print(sorted(m for m in sys.modules if m in ('rei.view', 'rei.edit.server', 'rei.report')))")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert done.stdout.strip() == "[]", done.stdout
