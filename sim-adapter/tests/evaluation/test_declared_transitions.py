# SPDX-License-Identifier: EPL-2.0
"""The requirements on zones are judged from what the patterns declare of each signal (``signal SIG_X transition
geometry CLOSE -> COLLISION``), never from the signal's name: a user's own patterns feed the verdicts."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from rei.evaluation import UtilityError, load_declared_transitions, load_declared_utilities
from rei.evaluation.signals import DEFAULT_TRANSITIONS, Source, Transition, Zone

from .traces import TraceBuilder, judge_trace

#: A user's geometric patterns under their own names, as the monitor's --utilities-out file lists them.
DECLARED = {
    "SIG_USER_NEAR": {"utility": -1.0, "transition": {"source": "GEOM", "from": "FAR", "to": "CLOSE"}},
    "SIG_USER_HIT": {"utility": -20.0, "transition": {"source": "GEOM", "from": "CLOSE", "to": "COLLISION"}},
    "SIG_USER_OFF": {"utility": None, "transition": {"source": "GEOM", "from": "COLLISION", "to": "CLOSE"}},
    "SIG_USER_AWAY": {"utility": None, "transition": {"source": "GEOM", "from": "CLOSE", "to": "FAR"}},
    "SIG_USER_PLAIN": {"utility": 3.0},
}


def _bump() -> TraceBuilder:
    b = TraceBuilder().begin()
    b.at(4.0, "USER_NEAR", "table1").at(5.0, "USER_HIT", "table1").at(6.0, "USER_OFF", "table1")
    b.at(7.0, "USER_AWAY", "table1")
    return b.task(10.0, 0).end(20.0)


def test_a_users_declared_collision_fails_mission_simple_and_undeclared_names_mean_nothing(tmp_path: Path) -> None:
    path = tmp_path / "utilities.json"
    path.write_text(json.dumps(DECLARED))
    declared = load_declared_transitions(path)
    verdicts = judge_trace(_bump().messages, transitions=declared)
    assert verdicts["MISSION_SIMPLE"].status.value == "fail"
    assert verdicts["MISSION_SIMPLE"].evidence[0].t == 5.0 and verdicts["MISSION_SIMPLE"].evidence[0].object == "table1"
    # the same signals without their declarations are no zone change at all
    assert judge_trace(_bump().messages)["MISSION_SIMPLE"].status.value == "pass"


def test_the_declarations_come_over_the_defaults_and_the_utilities_read_both_file_shapes(tmp_path: Path) -> None:
    path = tmp_path / "utilities.json"
    path.write_text(json.dumps({**DECLARED, "SIG_GEOM_FAR_TRANSIT_CLOSE": {
        "utility": -2.0, "transition": {"source": "LASER", "from": "FAR", "to": "CLOSE"}}}))
    transitions = load_declared_transitions(path)
    assert transitions["SIG_USER_HIT"] == Transition(Source.GEOM, Zone.CLOSE, Zone.COLLISION)
    assert transitions["SIG_GEOM_FAR_TRANSIT_CLOSE"].source is Source.LASER  # declared wins over the default
    assert transitions["SIG_LASER_CLOSE_TRANSIT_FAR"] == DEFAULT_TRANSITIONS["SIG_LASER_CLOSE_TRANSIT_FAR"]
    assert "SIG_USER_PLAIN" not in transitions
    assert load_declared_utilities(path)["SIG_USER_HIT"] == -20.0
    old = tmp_path / "old.json"
    old.write_text('{"SIG_X": -2, "SIG_Y": null}')
    assert load_declared_utilities(old) == {"SIG_X": -2.0, "SIG_Y": None}
    assert load_declared_transitions(old) == dict(DEFAULT_TRANSITIONS)


def test_a_bad_declared_transition_names_the_file_and_the_signal(tmp_path: Path) -> None:
    path = tmp_path / "utilities.json"
    path.write_text(json.dumps({"SIG_X": {"utility": 1, "transition": {"source": "SONAR", "from": "FAR",
                                                                        "to": "CLOSE"}}}))
    with pytest.raises(UtilityError, match=f"{path}: SIG_X: a transition needs source GEOM or LASER"):
        load_declared_transitions(path)


def test_a_signal_about_no_object_is_valid_and_one_without_a_subject_is_not() -> None:
    """The monitor publishes an empty ``object`` when nothing is near (contract/vocabulary.json); the evaluator
    once refused it as malformed, which turned the verdicts into errors."""
    from rei.evaluation import Signal, SignalError

    base = {"seq": 0, "t": 1.0, "signal": "SIG_GEOM_CLOSE_TRANSIT_FAR", "subject": "tb3", "distance": 0.3}
    assert Signal.from_message({**base, "object": ""}).object == ""
    with pytest.raises(SignalError, match="'subject' must be a non-empty string"):
        Signal.from_message({**base, "object": "", "subject": ""})
