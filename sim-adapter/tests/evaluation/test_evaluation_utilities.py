# SPDX-License-Identifier: EPL-2.0
"""The utility table: Table 3 defaults, the patterns' declared utilities, YAML overrides and the errors that name
file and key."""

from __future__ import annotations

import csv
import json
from pathlib import Path

import pytest

from rei.evaluation import (
    DEFAULT_UTILITIES,
    KNOWN_SIGNALS,
    Evaluator,
    UtilityError,
    load_declared_utilities,
    load_utilities,
    replay,
)

from .traces import MISSION, MONITOR, WORLD, TraceBuilder

TABLE_3 = {
    "SIG_MISSION_BEGIN": 20, "SIG_MISSION_END": 20, "SIG_MISSION_TASK_START": 5,
    "SIG_MISSION_TASK_FAIL": -100, "SIG_MISSION_TASK_SUCCESS": 10,
    "SIG_GEOM_FAR_TRANSIT_CLOSE": -2, "SIG_GEOM_CLOSE_TRANSIT_FAR": 1,
    "SIG_GEOM_CLOSE_TRANSIT_COLLISION": -10, "SIG_GEOM_COLLISION_TRANSIT_CLOSE": 1,
    "SIG_LASER_CLOSE_TRANSIT_COLLISION": -5, "SIG_LASER_COLLISION_TRANSIT_CLOSE": 1,
}


#: The fault kinds per sensor as the contract states them (each window edge a signal worth 0).
_FAULT_KINDS: dict[str, list[str]] = json.loads(
    (Path(__file__).resolve().parents[3] / "contract" / "vocabulary.json").read_text(encoding="utf-8"))["faults"]["kinds"]


def test_defaults_are_table_3_plus_zero_for_the_signals_it_leaves_out() -> None:
    table = load_utilities(None)
    assert {name: table[name] for name in TABLE_3} == TABLE_3
    assert {name: table[name] for name in set(table) - set(TABLE_3)} == {
        "SIG_LASER_FAR_TRANSIT_CLOSE": 0, "SIG_LASER_CLOSE_TRANSIT_FAR": 0, "SIG_MONITOR_DATA_GAP": 0,
        "SIG_OBJECT_COLLISION_BEGIN": 0, "SIG_OBJECT_COLLISION_END": 0,
        **{f"SIG_FAULT_{sensor.upper()}_{kind.upper()}_{edge}": 0 for sensor, kinds in _FAULT_KINDS.items()
           for kind in kinds for edge in ("BEGIN", "END")}}
    assert set(table) == KNOWN_SIGNALS == set(DEFAULT_UTILITIES)
    assert table.source == "defaults"


def test_yaml_overrides_only_the_signals_it_lists(tmp_path: Path) -> None:
    path = tmp_path / "u.yaml"
    path.write_text("SIG_GEOM_CLOSE_TRANSIT_COLLISION: -50\nSIG_MONITOR_DATA_GAP: -1.5\n")
    table = load_utilities(path)
    assert table["SIG_GEOM_CLOSE_TRANSIT_COLLISION"] == -50 and table["SIG_MONITOR_DATA_GAP"] == -1.5
    assert table["SIG_MISSION_BEGIN"] == 20
    assert table.source == str(path)
    assert table.utility("SIG_SOMETHING_NEW") == 0


def test_empty_yaml_means_defaults(tmp_path: Path) -> None:
    path = tmp_path / "empty.yaml"
    path.write_text("# nothing changed\n")
    assert dict(load_utilities(path)) == dict(DEFAULT_UTILITIES)


@pytest.mark.parametrize(("text", "expected"), [
    ("SIG_GEOM_FAR_TRANSIT_CLOSED: -2\n",
     ":1:1: unknown signal 'SIG_GEOM_FAR_TRANSIT_CLOSED' (did you mean SIG_GEOM_FAR_TRANSIT_CLOSE?; known: "),
    ("SIG_MISSION_END: twenty\n", ":1:18: SIG_MISSION_END: the utility must be a finite number, got 'twenty'"),
    ("SIG_MISSION_END: true\n", ":1:18: SIG_MISSION_END: the utility must be a finite number, got True"),
    ("SIG_MISSION_END: .nan\n", ":1:18: SIG_MISSION_END: the utility must be a finite number, got nan"),
    ("SIG_MISSION_BEGIN: 2\nSIG_MISSION_END: [1]\n",
     ":2:18: SIG_MISSION_END: the utility must be a finite number, got [1]"),
    ("- SIG_MISSION_END\n", ": expected a mapping 'SIGNAL: utility', got list"),
    ("SIG_MISSION_END: [\n", ":2:1: not valid YAML: expected the node content, but found '<stream end>'"),
])
def test_bad_utility_files_name_file_and_key(tmp_path: Path, text: str, expected: str) -> None:
    """At the key's or value's line and column (a YAML mistake too: it named a '<unicode string>' over 7 lines)."""
    path = tmp_path / "bad.yaml"
    path.write_text(text)
    with pytest.raises(UtilityError) as error:
        load_utilities(path)
    assert str(error.value).startswith(f"{path}{expected}")


def test_every_mistake_of_a_utility_file_is_reported_at_once_each_at_its_place(tmp_path: Path) -> None:
    path = tmp_path / "bad.yaml"
    path.write_text("SIG_MISSION_BEGIN: 2\nSIG_MISION_END: 3\nSIG_MISSION_END: x\nSIG_MISSION_BEGIN: 4\n")
    with pytest.raises(UtilityError) as error:
        load_utilities(path)
    lines = str(error.value).splitlines()
    assert [line.split(": ", 1)[0] for line in lines] == [f"{path}:2:1", f"{path}:3:18", f"{path}:4:1"]
    assert "did you mean SIG_MISSION_END?" in lines[0] and "got 'x'" in lines[1]
    assert lines[2].endswith("'SIG_MISSION_BEGIN' is given twice")


def test_missing_utility_file_is_an_error_naming_it(tmp_path: Path) -> None:
    with pytest.raises(UtilityError, match="missing.yaml: cannot read the utility file"):
        load_utilities(tmp_path / "missing.yaml")


# --- utilities the VEPL patterns declare (the monitor's --utilities-out): YAML > patterns > Table 3 > 0 ---

DECLARED = {"SIG_GEOM_FAR_TRANSIT_CLOSE": -3.0, "SIG_LASER_FAR_TRANSIT_CLOSE": None,
            "SIG_USER_TASK_STARTED": 7.0, "SIG_USER_UNSCORED": None}


def test_declared_utilities_override_table_3_and_add_the_users_signals() -> None:
    table = load_utilities(None, DECLARED, patterns="patterns (defaults + mine)")
    assert table["SIG_GEOM_FAR_TRANSIT_CLOSE"] == -3  # declared beats Table 3
    assert table["SIG_USER_TASK_STARTED"] == 7  # a new signal is worth what its pattern says
    assert table["SIG_LASER_FAR_TRANSIT_CLOSE"] == 0 and table["SIG_MISSION_BEGIN"] == 20  # Table 3 still holds
    assert "SIG_USER_UNSCORED" in table and table["SIG_USER_UNSCORED"] == 0  # declared without one: known, 0
    assert table.utility("SIG_NOBODY_DECLARED") == 0 and "SIG_NOBODY_DECLARED" not in table
    assert table.source == "Table 3 + patterns (defaults + mine)"


def test_yaml_beats_the_declared_utilities_and_may_name_the_users_signals(tmp_path: Path) -> None:
    path = tmp_path / "u.yaml"
    path.write_text("SIG_GEOM_FAR_TRANSIT_CLOSE: -4\nSIG_USER_UNSCORED: 2.5\n")
    table = load_utilities(path, DECLARED)
    assert table["SIG_GEOM_FAR_TRANSIT_CLOSE"] == -4 and table["SIG_USER_UNSCORED"] == 2.5
    assert table["SIG_USER_TASK_STARTED"] == 7
    assert table.source == f"Table 3 + patterns + {path}"
    with pytest.raises(UtilityError, match="unknown signal 'SIG_USER_UNSCORED'"):
        load_utilities(path)  # without the patterns the user's signal is unknown


def test_hand_written_rules_declare_nothing_and_change_no_utility() -> None:
    assert load_utilities(None, {}).source == "Table 3 + patterns"  # the monitor's --rules DIR writes {}
    assert dict(load_utilities(None, {})) == dict(DEFAULT_UTILITIES)


def test_the_declared_utilities_file_reads_numbers_and_nulls(tmp_path: Path) -> None:
    path = tmp_path / "utilities.json"
    path.write_text('{"SIG_MISSION_BEGIN": 20.0, "SIG_USER_X": -2, "SIG_LASER_FAR_TRANSIT_CLOSE": null}\n')
    assert load_declared_utilities(path) == {"SIG_MISSION_BEGIN": 20.0, "SIG_USER_X": -2.0,
                                             "SIG_LASER_FAR_TRANSIT_CLOSE": None}
    (tmp_path / "empty.json").write_text("{}")
    assert load_declared_utilities(tmp_path / "empty.json") == {}


@pytest.mark.parametrize(("text", "expected"), [
    ("[1]", "expected a JSON object"),
    ('{"SIG_X": "high"}', "SIG_X: the utility must be a finite number or null, got 'high'"),
    ('{"SIG_X": true}', "SIG_X: the utility must be a finite number or null, got True"),
    ('{"SIG_X": NaN}', "SIG_X: the utility must be a finite number or null, got nan"),
    ('{"SIG_X": ', "not valid JSON"),
])
def test_a_bad_declared_utilities_file_names_file_and_key(tmp_path: Path, text: str, expected: str) -> None:
    path = tmp_path / "utilities.json"
    path.write_text(text)
    with pytest.raises(UtilityError) as error:
        load_declared_utilities(path)
    assert str(error.value).startswith(f"{path}: ") and expected in str(error.value)
    with pytest.raises(UtilityError, match="cannot read the declared utilities"):
        load_declared_utilities(tmp_path / "missing.json")


def test_the_evaluator_scores_a_declared_signal_and_does_not_count_it_unknown(tmp_path: Path) -> None:
    evaluator = Evaluator(tmp_path, utilities=load_utilities(None, DECLARED, patterns="patterns (mine)"),
                          mission_info=MISSION, monitor_config=MONITOR, world=WORLD)
    messages = TraceBuilder().begin().at(1.0, "SIG_USER_TASK_STARTED", "task_0").at(2.0, "SIG_OTHER").messages
    summary = replay(messages, evaluator, run_id="r")
    rows = list(csv.DictReader((tmp_path / "events.csv").open()))
    assert [(r["signal"], r["utility"], r["total"]) for r in rows] == [
        ("SIG_MISSION_BEGIN", "20", "20"), ("SIG_MISSION_TASK_START", "5", "25"),
        ("SIG_USER_TASK_STARTED", "7", "32"), ("SIG_OTHER", "0", "32")]
    assert summary.unknown_signals == {"SIG_OTHER": 1}
    assert json.loads((tmp_path / "summary.json").read_text())["utilities"] == "Table 3 + patterns (mine)"
