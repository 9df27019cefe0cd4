# SPDX-License-Identifier: EPL-2.0
"""Thesis 7.2's simple scenarios, shipped in examples/thesis_7_2: the robot driven by a command timeline (no
navigation) gives the signals listed in each scenario's .expected file, and where it is when they come makes sense
of them: in front of the box it ran into, at the table's short ends while circling it."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from rei.wamp.recording import read_recording

SCENARIOS = Path(__file__).resolve().parents[2] / "examples" / "thesis_7_2"
LINE = re.compile(r"^\s*\d+\s+(\S+)\s+(SIG_\S+)\s+\S+\s+(\S*)\s+\S+\s*$")


def expected(name: str) -> list[tuple[float, str, str]]:
    rows = []
    for line in (SCENARIOS / f"{name}.expected").read_text(encoding="utf-8").splitlines():
        if line.strip() and not line.startswith("#"):
            t, signal, obj = line.split()
            rows.append((float(t), signal, obj))
    return sorted(rows)


def observed(run_cli, name: str, out: Path) -> tuple[list[tuple[float, str, str]], list[dict]]:
    """Simulate the scenario with its script, replay the recording through the monitor: the non-mission signals
    and the state messages."""
    sim = run_cli("sim", SCENARIOS / f"{name}.rei", "-o", out, "--no-router",
                  "--controller", f"script:{SCENARIOS / f'{name}.script'}")
    assert sim.returncode == 0, sim.stderr
    replay = run_cli("monitor", "--replay", out)
    assert replay.returncode == 0, replay.stderr
    rows = [(float(m[1]), m[2], m[3]) for m in map(LINE.match, replay.stdout.splitlines())
            if m is not None and not m[2].startswith("SIG_MISSION_")]
    return sorted(rows), read_recording(out / "streams" / "state.msgpack")


def assert_matches(got: list[tuple[float, str, str]], want: list[tuple[float, str, str]]) -> None:
    assert [(s, o) for _, s, o in got] == [(s, o) for _, s, o in want], got
    for (t_got, signal, _), (t_want, _, _) in zip(got, want, strict=True):
        assert t_got == pytest.approx(t_want, abs=0.1), signal


def robot_at(states: list[dict], t: float) -> tuple[float, float]:
    state = min(states, key=lambda m: abs(m["t"] - t))
    return state["robot"]["pose"][0], state["robot"]["pose"][1]


def test_translation_into_a_box_and_back(run_cli, tmp_path: Path) -> None:
    got, states = observed(run_cli, "translation", tmp_path / "out")
    assert_matches(got, expected("translation"))
    # COLLISION while the front bumper (0.1405 m ahead of the centre) presses on the box's face at x = 3.25
    begin = next(t for t, s, _ in got if s == "SIG_GEOM_CLOSE_TRANSIT_COLLISION")
    end = next(t for t, s, _ in got if s == "SIG_GEOM_COLLISION_TRANSIT_CLOSE")
    for t in (begin, (begin + end) / 2):
        x, _ = robot_at(states, t)
        assert 3.25 - 0.1405 - x < 0.01 + 1e-3, (t, x)
    assert robot_at(states, 0.0) == pytest.approx((0.5, 0.5), abs=1e-3)


def test_circles_around_a_table_are_close_at_its_short_ends_only(run_cli, tmp_path: Path) -> None:
    got, states = observed(run_cli, "circle", tmp_path / "out")
    assert_matches(got, expected("circle"))
    geometry = [(t, s) for t, s, _ in got if s.startswith("SIG_GEOM_")]
    assert len(geometry) == 8  # two laps, two CLOSE episodes each
    entries = [t for t, s in geometry if s == "SIG_GEOM_FAR_TRANSIT_CLOSE"]
    exits = [t for t, s in geometry if s == "SIG_GEOM_CLOSE_TRANSIT_FAR"]
    for a, b in zip(entries, exits, strict=True):  # in the middle of an episode: beside a short end (x = 2.5 +- 0.6)
        x, y = robot_at(states, (a + b) / 2)
        assert abs(x - 2.5) > 0.8 and abs(y - 2.5) < 0.4, (a, b, x, y)
    for a, b in zip(exits, entries[1:], strict=False):  # in the middle of a gap: along a long side (y = 2.5 +- 0.4)
        x, y = robot_at(states, (a + b) / 2)
        assert abs(y - 2.5) > 0.8 and abs(x - 2.5) < 0.4, (a, b, x, y)
