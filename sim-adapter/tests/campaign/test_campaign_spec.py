# SPDX-License-Identifier: EPL-2.0
"""The campaign spec is checked at the door and expands into a stable list of runs."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from rei.campaign import SpecError, parse_spec, plan_campaign

EXAMPLES = Path(__file__).resolve().parents[3] / "examples"


def spec(**top: Any) -> dict[str, Any]:
    data: dict[str, Any] = {"groups": [{"name": "small", "rooms": {"size": "small", "count": 2, "seed": 3}}]}
    data.update(top)
    return data


def test_rooms_variants_and_repetitions_expand_in_a_stable_order(tmp_path: Path) -> None:
    parsed = parse_spec(spec(seed=10, repetitions=2, variants=[{"name": "base"}, {"name": "f1", "fault": "laser:1%"}],
                             groups=[{"name": "small", "rooms": {"size": "small", "count": 2, "seed": 3}},
                                     {"name": "ex", "cases": ["simple_navigation.rei"], "repetitions": 1,
                                      "variants": [{"name": "alone", "humans": False}]}]),
                        base=EXAMPLES)
    plan = plan_campaign(parsed, tmp_path)
    assert [c.key for c in plan.cases] == ["small_dense_h0_s3_01", "small_dense_h0_s3_02", "simple_navigation"]
    keys = [r.key for r in plan.runs]
    assert keys[:4] == ["small__small_dense_h0_s3_01__base__r0", "small__small_dense_h0_s3_01__base__r1",
                        "small__small_dense_h0_s3_01__f1__r0", "small__small_dense_h0_s3_01__f1__r1"]
    assert len(keys) == 2 * 2 * 2 + 1 and len(set(keys)) == len(keys)
    assert [r.seed for r in plan.runs[:2]] == [10, 11]
    alone = plan.runs[-1]
    assert (alone.humans, alone.fault, alone.case_dir) == (False, None, str(tmp_path.resolve() / "cases" / "simple_navigation"))
    assert plan_campaign(parsed, tmp_path) == plan, "a resumed campaign must plan the same runs"


@pytest.mark.parametrize(("data", "message"), [
    (spec(mode="fast"), r"'mode' must be one of replay, pipeline"),
    (spec(timeout=0), r"'timeout' must be positive"),
    (spec(repetitions=True), r"'repetitions' must be an integer"),
    (spec(extra=1), r"unknown key 'extra'"),
    (spec(groups=[]), r"'groups' must be a non-empty list"),
    (spec(groups=[{"name": "g"}]), r"groups\[0\]: give exactly one of 'cases'"),
    (spec(groups=[{"name": "g", "cases": ["nope.rei"]}]), r"nope.rei is neither a .rei file"),
    (spec(groups=[{"name": "g/x", "rooms": {"size": "small"}}]), r"'name' 'g/x': use letters"),
    (spec(groups=[{"name": "g", "rooms": {"size": "tiny"}}]), r"groups\[0\]: rooms: size must be one of"),
    (spec(variants=[{"name": "v", "fault": "laser:200%"}]), r"variants\[0\]: fault:"),
    (spec(variants=[{"name": "v", "fault": "laser:blackout,from=7,to=5"}]),
     r"variants\[0\]: fault: bad fault spec 'laser:blackout,from=7,to=5': 'to' \(5 s\) must be after"),
    (spec(variants=[{"name": "v", "controller": "warp"}]), r"unknown controller 'warp'"),
    (spec(variants=[{"name": "v"}, {"name": "v"}]), r"two variants have the same name"),
])
def test_mistakes_name_the_key(data: dict[str, Any], message: str) -> None:
    with pytest.raises(SpecError, match=message):
        parse_spec(data, base=EXAMPLES, where="c.yaml")


def test_the_example_campaigns_are_valid(tmp_path: Path) -> None:
    from rei.campaign import load_spec

    thesis = plan_campaign(load_spec(EXAMPLES / "campaigns" / "thesis.yaml"), tmp_path)
    groups = [r.group for r in thesis.runs]
    assert (groups.count("small"), groups.count("medium"), groups.count("large")) == (14, 8, 1)
    assert plan_campaign(load_spec(EXAMPLES / "campaigns" / "faults.yaml"), tmp_path).runs
    gated = load_spec(EXAMPLES / "campaigns" / "faults_gated.yaml")
    runs = plan_campaign(gated, tmp_path).runs
    assert sorted({r.fault or "" for r in runs}) == ["", "laser:gated-1%", "laser:gated-10%"]


def test_an_external_sut_is_a_variant_setting_with_the_spec_s_folder_as_its_working_folder(tmp_path: Path) -> None:
    script = tmp_path / "sut" / "go.sh"
    script.parent.mkdir()
    script.write_text("#!/bin/sh\n")
    script.chmod(0o755)
    parsed = parse_spec(spec(sut={"command": "rei nav-sut", "map": True, "deadline": 5},
                             variants=[{"name": "external"}, {"name": "inproc", "controller": "nav"},
                                       {"name": "mine", "sut": {"command": "sut/go.sh", "clock": "realtime"}}]),
                        base=tmp_path)
    external, inproc, mine = (r.sut for r in plan_campaign(parsed, tmp_path / "out").runs[:3])
    assert external == {"command": "rei nav-sut", "clock": "lockstep", "deadline": 5.0, "map": True,
                        "join_timeout": 60.0, "cwd": str(tmp_path)}
    assert inproc is None
    assert mine is not None and (mine["command"], mine["clock"]) == ("sut/go.sh", "realtime")


@pytest.mark.parametrize(("sut", "message"), [
    ({"command": "no-such-program"}, "program 'no-such-program' not found"),
    ({"command": "rei nav-sut", "clock": "fast"}, "'clock' must be one of lockstep, realtime"),
    ({"command": "rei nav-sut", "deadline": 0}, "'deadline' must be positive"),
    ({"command": "rei nav-sut", "attach": True}, "unknown key 'attach'"),
    ({"map": True}, "'command' is required"),
])
def test_a_bad_external_sut_is_refused_with_its_key_path(sut: dict, message: str) -> None:
    with pytest.raises(SpecError, match="spec: variants\\[0\\]: sut: ") as error:
        parse_spec(spec(variants=[{"name": "v", "sut": sut}]), base=EXAMPLES)
    assert message in str(error.value)


def test_a_variant_is_either_in_process_or_external() -> None:
    with pytest.raises(SpecError, match="either 'controller' .* or 'sut'"):
        parse_spec(spec(variants=[{"name": "v", "controller": "nav", "sut": {"command": "rei nav-sut"}}]),
                   base=EXAMPLES)


def test_rooms_furnished_from_a_user_catalogue_import_it_from_the_rooms_folder(tmp_path: Path) -> None:
    parsed = parse_spec(spec(groups=[{"name": "own", "rooms": {"size": "small", "count": 1, "seed": 3,
                                                              "catalogue": "catalogues/office.rei"}}]), base=EXAMPLES)
    (case,) = plan_campaign(parsed, tmp_path).cases
    rooms = tmp_path.resolve() / "rooms"
    imported = (rooms / case.text.splitlines()[2].split('"')[1]).resolve()  # after the two header comments
    assert imported == (EXAMPLES / "catalogues" / "office.rei").resolve()
    assert "robot tb3 : Burger on" in case.text
    with pytest.raises(SpecError, match=r"groups\[0\]: rooms: 'robot' picks a robot type of 'catalogue'"):
        parse_spec(spec(groups=[{"name": "g", "rooms": {"size": "small", "robot": "Burger"}}]), base=EXAMPLES)
    with pytest.raises(SpecError, match=r"groups\[0\]: rooms: cannot read catalogue .*nope.rei: no such file"):
        parse_spec(spec(groups=[{"name": "g", "rooms": {"size": "small", "catalogue": "nope.rei"}}]), base=EXAMPLES)


def test_a_case_is_generated_again_when_the_catalogue_it_imports_changed(tmp_path: Path) -> None:
    from rei.campaign.prepare import source_digest

    (tmp_path / "office.rei").write_text("catalogue A { type Sofa : object box 1 x 1 x 1 }\n", encoding="utf-8")
    case = tmp_path / "case.rei"
    case.write_text('// a test case\nimport "office.rei"\ntestcase T { }\n', encoding="utf-8")
    before = source_digest(case)
    (tmp_path / "office.rei").write_text("catalogue A { type Sofa : object box 1 x 0.9 x 1 }\n", encoding="utf-8")
    assert source_digest(case) != before
    assert source_digest(case) == source_digest(case)


NAV_PARAMETERS = "expected key=value with key one of acc_angular, acc_linear, "


@pytest.mark.parametrize(("text", "expected"), [
    # the top level's default controller: placed at its value, before any run
    ('controller: "nav:inflaton_margin=0"\ngroups: [{name: g, cases: [CASE]}]\n',
     "c.yaml:1:13: nav parameter 'inflaton_margin=0': " + NAV_PARAMETERS),
    # a variant of the spec, one of a group (flow and block style), a value out of range, an unknown name
    (('variants:\n  - {name: base}\n  - {name: tuned, controller: "nav:inflaton_margin=0"}\n'
      "groups: [{name: g, cases: [CASE]}]\n"),
     "c.yaml:3:31: variants[1]: nav parameter 'inflaton_margin=0': " + NAV_PARAMETERS),
    (("groups:\n  - name: g\n    cases: [CASE]\n    variants:\n      - name: slow\n"
      "        controller: nav:max_linear=-1\n"),
     "c.yaml:6:21: groups[0]: variants[0]: nav parameter max_linear must be a finite number >= 0, got -1.0"),
    ("groups:\n  - {name: g, cases: [CASE]}\n  - {name: h, variants: [{name: w, controller: warp}], cases: [CASE]}\n",
     "c.yaml:3:48: groups[1]: variants[0]: unknown controller 'warp'; available: "),
])
def test_a_controller_that_cannot_be_built_is_refused_at_its_line_and_column(tmp_path: Path, text: str,
                                                                             expected: str) -> None:
    from rei.campaign import load_spec

    (tmp_path / "c.yaml").write_text(text.replace("CASE", str(EXAMPLES / "simple_navigation.rei")), encoding="utf-8")
    with pytest.raises(SpecError) as raised:
        load_spec(tmp_path / "c.yaml")
    assert str(raised.value).replace(str(tmp_path) + "/", "").startswith(expected)


def test_good_controller_arguments_pass(tmp_path: Path) -> None:
    parsed = parse_spec(spec(controller="nav:inflation_margin=0", variants=[{"name": "a"}, {
        "name": "b", "controller": "nav:max_linear=0.2,v_samples=5"}]), base=EXAMPLES)
    assert [v.controller for v in parsed.groups[0].variants] == ["nav:inflation_margin=0",
                                                                 "nav:max_linear=0.2,v_samples=5"]


TWO_GROUPS_WRONG = """\
mode: fast
groups:
  - name: g
    cases: [CASE]
    repetitions: 0
  - name: h
    rooms: {size: tiny}
    variants: [{name: v, humans: maybe}]
"""


def test_every_mistake_is_reported_at_once_each_at_its_line_and_column(tmp_path: Path) -> None:
    from rei.campaign import load_spec

    (tmp_path / "c.yaml").write_text(TWO_GROUPS_WRONG.replace("CASE", str(EXAMPLES / "simple_navigation.rei")))
    with pytest.raises(SpecError) as raised:
        load_spec(tmp_path / "c.yaml")
    file = tmp_path / "c.yaml"
    assert str(raised.value).splitlines() == [
        f"{file}:1:7: 'mode' must be one of replay, pipeline, got 'fast'",
        f"{file}:5:18: groups[0]: 'repetitions' must be >= 1, got 0",
        f"{file}:7:19: groups[1]: rooms: size must be one of small, medium, large, got 'tiny'",
        f"{file}:8:34: groups[1]: variants[0]: 'humans' must be true or false, got 'maybe'"]


def test_the_command_prints_every_mistake_on_its_own_line(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    from rei.cli import main

    spec_file = tmp_path / "c.yaml"
    spec_file.write_text("timeout: 0\ngroups:\n  - {name: g/x, cases: [nope.rei]}\n")
    assert main(["campaign", str(spec_file), "-o", str(tmp_path / "out")]) == 2
    assert capsys.readouterr().err.splitlines() == [
        f"rei: error: {spec_file}:1:10: 'timeout' must be positive, got 0",
        f"rei: error: {spec_file}:3:12: groups[0]: 'name' 'g/x': use letters, digits, '_' and '-' (it names folders)",
        (f"rei: error: {spec_file}:3:25: groups[0]: {tmp_path / 'nope.rei'} is neither a .rei file nor a "
         "generated case folder")]
    assert not (tmp_path / "out").exists()


def test_every_mistake_of_a_group_s_room_settings_is_reported_at_its_value(tmp_path: Path) -> None:
    """The generator stops at its first mistake; the spec names each setting's own, where it is written."""
    from rei.campaign import load_spec

    file = tmp_path / "c.yaml"
    file.write_text("groups:\n"
                    "  - name: g\n"
                    "    rooms: {size: small, density: thick, humans: 9, count: 1}\n"
                    "  - name: h\n"
                    "    rooms: {size: medium, humans: two}\n"
                    "  - name: i\n"
                    "    rooms: {size: medium, humans: 1.5}\n")
    with pytest.raises(SpecError) as raised:
        load_spec(file)
    assert str(raised.value).splitlines() == [
        f"{file}:3:35: groups[0]: rooms: density must be one of dense, sparse, got 'thick'",
        f"{file}:3:50: groups[0]: rooms: a small room holds 0 to 2 humans, got 9",
        f"{file}:5:35: groups[1]: rooms: 'humans' must be an integer, got 'two'",
        f"{file}:7:35: groups[2]: rooms: 'humans' must be an integer, got 1.5"]


def test_humans_true_is_no_number_of_humans() -> None:
    with pytest.raises(SpecError, match=r"'humans' must be an integer, got True"):
        parse_spec(spec(groups=[{"name": "g", "rooms": {"size": "small", "humans": True}}]), base=EXAMPLES)


def test_a_key_given_twice_is_a_mistake_at_its_second_place(tmp_path: Path) -> None:
    """YAML keeps the last value silently: seed 2 ran, and count 2 generated two rooms."""
    from rei.campaign import load_spec

    file = tmp_path / "c.yaml"
    file.write_text("seed: 1\nseed: 2\ngroups:\n  - name: g\n    rooms: {size: small, count: 1, count: 2}\n"
                    "    repetitions: 0\n")
    with pytest.raises(SpecError) as raised:
        load_spec(file)
    assert str(raised.value).splitlines() == [
        f"{file}:2:1: 'seed' is given twice",
        f"{file}:5:36: 'count' is given twice",
        f"{file}:6:18: groups[0]: 'repetitions' must be >= 1, got 0"]


def test_a_script_controller_is_a_file_relative_to_the_spec(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """As the spec's cases, patterns and SUT command are. It was read relative to the current folder at the check,
    then relative to each run's own folder by the run: every run crashed ('short.txt: cannot read the script')."""
    (tmp_path / "short.txt").write_text("1.0 0.1 0.0\n", encoding="utf-8")
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)
    parsed = parse_spec(spec(controller="script:short.txt", variants=[{"name": "a"}, {"name": "b",
                                                                                       "controller": "script:short.txt"}]),
                        base=tmp_path)
    assert {v.controller for v in parsed.groups[0].variants} == {f"script:{tmp_path / 'short.txt'}"}


def test_the_campaign_s_controller_option_takes_a_script_relative_to_the_current_folder(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from rei.cli.campaign import _with_controller

    (tmp_path / "short.txt").write_text("1.0 0.1 0.0\n", encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    replaced = _with_controller(parse_spec(spec(), base=EXAMPLES), "script:short.txt")
    assert {v.controller for g in replaced.groups for v in g.variants} == {f"script:{tmp_path / 'short.txt'}"}


def test_the_same_generated_room_in_two_groups_is_one_case(tmp_path: Path) -> None:
    """Room 1 of seed 1 is the same whatever the count; only its header comment says 'room 1 of 2'. The campaign
    was refused ('two different test cases ...; rename one file', no file to rename)."""
    parsed = parse_spec(spec(groups=[{"name": "a", "rooms": {"size": "small", "count": 1, "seed": 1}},
                                     {"name": "b", "rooms": {"size": "small", "count": 2, "seed": 1}}]), base=EXAMPLES)
    plan = plan_campaign(parsed, tmp_path)
    assert [c.key for c in plan.cases] == ["small_dense_h0_s1_01", "small_dense_h0_s1_02"]
    assert [r.key for r in plan.runs] == ["a__small_dense_h0_s1_01__base__r0", "b__small_dense_h0_s1_01__base__r0",
                                          "b__small_dense_h0_s1_02__base__r0"]
    other = parse_spec(spec(groups=[{"name": "a", "rooms": {"size": "small", "count": 1, "seed": 1}},
                                    {"name": "b", "rooms": {"size": "small", "count": 1, "seed": 1,
                                                            "catalogue": "catalogues/office.rei"}}]), base=EXAMPLES)
    with pytest.raises(SpecError, match="both named 'small_dense_h0_s1_01'.*give one group other room settings"):
        plan_campaign(other, tmp_path)


def test_a_case_that_is_no_path_is_placed_at_the_item(tmp_path: Path) -> None:
    from rei.campaign import load_spec

    file = tmp_path / "c.yaml"
    file.write_text(f"groups:\n  - name: g\n    cases:\n      - {EXAMPLES / 'simple_navigation.rei'}\n      - 5\n"
                    "      - {file: x.rei}\n")
    with pytest.raises(SpecError) as raised:
        load_spec(file)
    assert str(raised.value).splitlines() == [
        f"{file}:5:9: groups[0]: a case is a path to a .rei file or a generated case folder, got 5",
        f"{file}:6:9: groups[0]: a case is a path to a .rei file or a generated case folder, got {{'file': 'x.rei'}}"]
