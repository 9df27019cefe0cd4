# SPDX-License-Identifier: EPL-2.0
"""The utility table: Table 3 defaults, YAML overrides and the errors that name file and key."""

from __future__ import annotations

from pathlib import Path

import pytest

from rei.evaluation import DEFAULT_UTILITIES, KNOWN_SIGNALS, UtilityError, load_utilities

TABLE_3 = {
    "SIG_MISSION_BEGIN": 20, "SIG_MISSION_END": 20, "SIG_MISSION_TASK_START": 5,
    "SIG_MISSION_TASK_FAIL": -100, "SIG_MISSION_TASK_SUCCESS": 10,
    "SIG_GEOM_FAR_TRANSIT_CLOSE": -2, "SIG_GEOM_CLOSE_TRANSIT_FAR": 1,
    "SIG_GEOM_CLOSE_TRANSIT_COLLISION": -10, "SIG_GEOM_COLLISION_TRANSIT_CLOSE": 1,
    "SIG_LASER_CLOSE_TRANSIT_COLLISION": -5, "SIG_LASER_COLLISION_TRANSIT_CLOSE": 1,
}


def test_defaults_are_table_3_plus_zero_for_the_signals_it_leaves_out() -> None:
    table = load_utilities(None)
    assert {name: table[name] for name in TABLE_3} == TABLE_3
    assert {name: table[name] for name in set(table) - set(TABLE_3)} == {
        "SIG_LASER_FAR_TRANSIT_CLOSE": 0, "SIG_LASER_CLOSE_TRANSIT_FAR": 0, "SIG_MONITOR_DATA_GAP": 0}
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
    ("SIG_GEOM_FAR_TRANSIT_CLOSED: -2\n", "unknown signal 'SIG_GEOM_FAR_TRANSIT_CLOSED'"),
    ("SIG_MISSION_END: twenty\n", "SIG_MISSION_END: the utility must be a finite number, got 'twenty'"),
    ("SIG_MISSION_END: true\n", "SIG_MISSION_END: the utility must be a finite number, got True"),
    ("SIG_MISSION_END: .nan\n", "SIG_MISSION_END: the utility must be a finite number, got nan"),
    ("SIG_MISSION_END: [1]\n", "SIG_MISSION_END: the utility must be a finite number, got [1]"),
    ("- SIG_MISSION_END\n", "expected a mapping 'SIGNAL: utility', got list"),
    ("SIG_MISSION_END: [\n", "not valid YAML"),
])
def test_bad_utility_files_name_file_and_key(tmp_path: Path, text: str, expected: str) -> None:
    path = tmp_path / "bad.yaml"
    path.write_text(text)
    with pytest.raises(UtilityError) as error:
        load_utilities(path)
    assert str(error.value).startswith(f"{path}: ")
    assert expected in str(error.value)


def test_missing_utility_file_is_an_error_naming_it(tmp_path: Path) -> None:
    with pytest.raises(UtilityError, match="missing.yaml: cannot read the utility file"):
        load_utilities(tmp_path / "missing.yaml")
