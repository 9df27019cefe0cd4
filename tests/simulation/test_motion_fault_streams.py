# SPDX-License-Identifier: EPL-2.0
"""The motion's faults (commands, drive, pose, odometry; docs/faults.md) checked from the recorded streams of real
runs (real pybullet, the mission loop, the recorder).

The controllers are blind: what they command depends on the time only, so a run whose controller itself delays or
drops its commands as a fault's definition says must record, byte for byte, the state stream of the run with the
fault: the applied commands are the same."""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
from fault_run_helpers import Blind

from rei.geometry import Twist2D
from rei.run import MissionRunOptions, run_mission
from rei.sim.faults import parse_faults
from rei.sut.api import Controller
from rei.wamp.collector import CollectorConfig
from rei.wamp.recording import read_recording

SEED = 11
RATE = 20.0  # control rate: 200 ms are exactly 4 periods
END = 6.0


def wiggle(k: int) -> Twist2D:
    """The command of control tick ``k``: a new turn rate every tick, so a shift by one tick shows."""
    return Twist2D(0.05 * (k % 3), 0.9 * math.sin(0.7 * k) + 0.3 * (k % 4 - 1.5))


def straight(k: int) -> Twist2D:
    return Twist2D(0.2, 0.0)


def still(k: int) -> Twist2D:
    return Twist2D()


def _blind(plan: Callable[[int], Twist2D], applied: Callable[[int, Twist2D], Twist2D] | None = None) -> Blind:
    return Blind(plan, applied, rate=RATE, end=END)


def _run(case: Path, out: Path, controller: Controller, fault: str | None) -> Path:
    options = MissionRunOptions(seed=SEED, humans=False, fault=fault, control_rate=RATE,
                                collector=CollectorConfig(rate_hz=20.0))
    run_mission(case, out, options, run_id="motion", controller=controller)
    return out


def _states(out: Path) -> list[dict]:
    return list(read_recording(out / "streams" / "state.msgpack"))


def _state_bytes(out: Path) -> bytes:
    return (out / "streams" / "state.msgpack").read_bytes()


def _events(out: Path) -> list[tuple[float, str]]:
    return [(m["t"], m["event"]) for m in read_recording(out / "streams" / "mission.msgpack")
            if m["event"].startswith("FAULT_")]


def _delayed(periods: int) -> Callable[[int, Twist2D], Twist2D]:
    """The latency's definition done by the controller: inside [2 s, 5 s) the command of ``periods`` ticks ago."""
    return lambda k, command: wiggle(k - periods) if 40 <= k < 100 else command


def test_latency_applies_each_command_exactly_4_periods_later(case: Path, tmp_path: Path) -> None:
    faulty = _run(case, tmp_path / "faulty", _blind(wiggle), "commands:latency,delay=0.2,from=2,to=5")
    by_hand = _run(case, tmp_path / "by_hand", _blind(wiggle, _delayed(4)), None)
    off_by_one = _run(case, tmp_path / "off", _blind(wiggle, _delayed(3)), None)
    clean = _run(case, tmp_path / "clean", _blind(wiggle), None)
    assert _state_bytes(faulty) == _state_bytes(by_hand)
    assert _state_bytes(faulty) != _state_bytes(off_by_one) and _state_bytes(faulty) != _state_bytes(clean)
    # the recorded twist: equal to the clean run's before the window, different inside it
    twists = [(m["t"], m["robot"]["twist"]) for m in _states(faulty)]
    clean_twists = [(m["t"], m["robot"]["twist"]) for m in _states(clean)]
    assert [tw for t, tw in twists if t <= 2.0] == [tw for t, tw in clean_twists if t <= 2.0]
    assert [tw for t, tw in twists if 2.2 < t < 5.0] != [tw for t, tw in clean_twists if 2.2 < t < 5.0]
    assert _events(faulty) == [(2.0, "FAULT_COMMANDS_LATENCY_BEGIN"), (5.0, "FAULT_COMMANDS_LATENCY_END")]


def test_loss_drops_commands_with_its_seeded_draws_and_the_last_applied_stays(case: Path, tmp_path: Path) -> None:
    spec = "commands:loss,probability=0.4,from=1,to=5"
    # the schedule's only fault draws from the run's fault seed, once per control tick inside its window
    twin = np.random.default_rng(np.random.SeedSequence(SEED).spawn(2)[0])
    last = [Twist2D()]
    dropped = []

    def lossy(k: int, command: Twist2D) -> Twist2D:
        if 20 <= k < 100 and twin.random() < 0.4:
            dropped.append(k)
            return last[0]
        last[0] = command
        return command

    faulty = _run(case, tmp_path / "faulty", _blind(wiggle), spec)
    again = _run(case, tmp_path / "again", _blind(wiggle), spec)
    by_hand = _run(case, tmp_path / "by_hand", _blind(wiggle, lossy), None)
    clean = _run(case, tmp_path / "clean", _blind(wiggle), None)
    assert 15 < len(dropped) < 50  # about 0.4 of the window's 80 ticks
    assert _state_bytes(faulty) == _state_bytes(by_hand) == _state_bytes(again) != _state_bytes(clean)
    assert (faulty / "streams" / "mission.msgpack").read_bytes() == (again / "streams" / "mission.msgpack").read_bytes()


def _xy(m: dict, key: str) -> np.ndarray:
    return np.array(m["robot"][key][:2], dtype=float)


def test_slip_scales_the_true_displacement_and_the_odometry_counts_the_wheels(case: Path, tmp_path: Path) -> None:
    faulty = _states(_run(case, tmp_path / "faulty", _blind(straight), "drive:slip,fraction=0.5,from=1,to=5"))
    clean = _states(_run(case, tmp_path / "clean", _blind(straight), None))
    at = {round(m["t"], 6): m for m in faulty}
    clean_at = {round(m["t"], 6): m for m in clean}
    for states in (at, clean_at):
        assert 1.5 in states and 4.5 in states
    moved = np.linalg.norm(_xy(at[4.5], "pose") - _xy(at[1.5], "pose"))
    clean_moved = np.linalg.norm(_xy(clean_at[4.5], "pose") - _xy(clean_at[1.5], "pose"))
    assert clean_moved == pytest.approx(0.6, rel=0.02)  # 0.2 m/s for 3 s
    assert moved / clean_moved == pytest.approx(0.5, rel=0.02)
    # the wheels turned as commanded: the odometry believes the clean run's travel
    believed = np.linalg.norm(_xy(at[4.5], "odom") - _xy(at[1.5], "odom"))
    assert believed == pytest.approx(clean_moved, rel=0.02)
    assert [m["robot"]["pose"] for m in faulty if m["t"] <= 1.0] == [m["robot"]["pose"] for m in clean
                                                                        if m["t"] <= 1.0]


def test_kidnap_moves_the_true_pose_and_not_the_odometry(case: Path, tmp_path: Path) -> None:
    out = _run(case, tmp_path / "kidnap", _blind(still), "pose:kidnap,dx=1,dy=0.5,dyaw=90,from=3")
    states = {round(m["t"], 6): m for m in _states(out)}
    before, after = states[2.9], states[4.0]
    np.testing.assert_allclose(_xy(after, "pose") - _xy(before, "pose"), [1.0, 0.5], atol=2e-3)
    turned = math.remainder(after["robot"]["pose"][3] - before["robot"]["pose"][3], 2 * math.pi)
    assert turned == pytest.approx(math.pi / 2, abs=2e-3)
    # the wheels only jiggle as the body lands (a fifth of a milliradian), against the metre and the quarter turn
    np.testing.assert_allclose(after["robot"]["odom"], before["robot"]["odom"], atol=1e-3)
    assert _events(out) == [(3.0, "FAULT_POSE_KIDNAP_BEGIN")]


def test_odometry_drift_and_jump_change_the_belief_not_the_truth(case: Path, tmp_path: Path) -> None:
    spec = "odometry:drift,scale=1.2,from=1,to=4;odometry:jump,dx=-0.3,dy=0.2,from=4.5,to=4.6"
    faulty = _states(_run(case, tmp_path / "faulty", _blind(straight), spec))
    clean = _states(_run(case, tmp_path / "clean", _blind(straight), None))
    assert [m["robot"]["pose"] for m in faulty] == [m["robot"]["pose"] for m in clean]  # the truth untouched
    at = {round(m["t"], 6): m for m in faulty}
    clean_at = {round(m["t"], 6): m for m in clean}
    believed = _xy(at[3.5], "odom") - _xy(at[1.5], "odom")
    truly = _xy(clean_at[3.5], "odom") - _xy(clean_at[1.5], "odom")
    # the heading's small wobble is scaled too, so the path bends a little otherwise: a micrometre in 0.48 m
    np.testing.assert_allclose(believed, 1.2 * truly, atol=1e-6)
    assert np.linalg.norm(truly) == pytest.approx(0.4, rel=0.02)
    shift = (_xy(at[4.75], "odom") - _xy(at[4.4], "odom")) - (_xy(clean_at[4.75], "odom") - _xy(clean_at[4.4], "odom"))
    np.testing.assert_allclose(shift, [-0.3, 0.2], atol=1e-6)  # the drift left the heading a little off


def test_a_stuck_wheel_turns_the_robot_about_it(case: Path, tmp_path: Path) -> None:
    states = {round(m["t"], 6): m for m in _states(_run(case, tmp_path / "stuck", _blind(straight),
                                                         "drive:stuck,wheel=left,from=1,to=4"))}
    turned = math.remainder(states[4.0]["robot"]["pose"][3] - states[1.0]["robot"]["pose"][3], 2 * math.pi)
    assert turned > 0.5  # the right wheel alone drives: the robot turns left, counter-clockwise


@pytest.mark.parametrize(("spec", "message"), [
    ("commands:latency,delay=0.13", "not a whole number of control periods at 20 Hz"),
    ("drive:slip,fraction=1.5", "slip fraction must be in (0, 1]"),
    ("drive:stuck,wheel=front", "'left' or 'right'"),
    ("pose:kidnap,from=2", "needs an offset"),
    ("commands:loss", "a commands loss fault needs probability="),
    ("odometry:drift,sigma=1", "'sigma' is not a key of an odometry drift fault"),
])
def test_bad_specs_are_refused_naming_what_is_wrong(case: Path, tmp_path: Path, spec: str, message: str) -> None:
    with pytest.raises(ValueError, match=None) as error:
        _run(case, tmp_path / "bad", _blind(still), spec) if "delay" in spec else parse_faults(spec)
    assert message in str(error.value)


@pytest.mark.parametrize("spec", [
    "commands:latency,delay=0.2,from=2,to=5", "commands:loss,probability=0.4,from=1,period=2,pulse=0.5",
    "drive:slip,fraction=0.5", "drive:stuck,wheel=right,from=3", "odometry:drift,scale=1.2,bias=-2.5,from=1,to=4",
    "odometry:jump,dx=-0.3,dy=0.2,dyaw=0.0,from=4.5", "pose:kidnap,dx=1.0,dy=0.0,dyaw=90.0,from=3",
])
def test_format_fault_writes_what_parse_faults_reads_back(spec: str) -> None:
    from rei.sim.faults import format_fault

    (fault,) = parse_faults(spec).faults
    assert parse_faults(format_fault(fault)).faults == (fault,)
