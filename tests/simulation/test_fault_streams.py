# SPDX-License-Identifier: EPL-2.0
"""Faults on a timeline checked from the recorded streams of real runs (real pybullet, the mission loop, the
recorder): each kind against its definition, the window edges as mission events, the same seed byte for byte.

The robot turns on the spot at a fixed rate whatever it sees, so a run with faults moves exactly as the run
without them (faults act on the sensor only) and the clean run's scans are what the faulty run's lidar saw."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from fault_run_helpers import Blind

from rei.geometry import Twist2D
from rei.run import MissionRunOptions, run_mission
from rei.wamp.codec import LaserMode
from rei.wamp.collector import CollectorConfig
from rei.wamp.recording import read_recording

SEED = 7
RANGE_MIN, RANGE_MAX = 0.12, 3.5  # examples/simple_navigation.rei's Waffle lidar (world.json)
FAULTS = ("laser:blackout,from=2,to=3;laser:freeze,from=4,to=5.5;"
          "laser:impulse,rate=0.05,width=2,gain=0.1@6/0.9@11,from=6,period=2,pulse=0.5")
END = 11.5


def _run(case: Path, out: Path, fault: str | None) -> Path:
    options = MissionRunOptions(seed=SEED, humans=False, fault=fault,
                                collector=CollectorConfig(rate_hz=20.0, laser=LaserMode.FULL))
    turner = Blind(lambda k: Twist2D(0.0, 0.6), rate=20.0, end=END)  # turns on the spot
    run_mission(case, out, options, run_id="faults", controller=turner)
    return out


def _scans(out: Path) -> dict[float, np.ndarray]:
    """The scan each state message carries, by the time it was taken (the lidar runs at 10 Hz, the states at
    20 Hz: a state at t carries the scan of the last tenth of a second at or before t)."""
    scans: dict[float, np.ndarray] = {}
    for m in read_recording(out / "streams" / "state.msgpack"):
        scan_t = round(math.floor(m["t"] * 10 + 1e-6) / 10, 6)
        ranges = np.array(m["robot"]["laser_ranges"], dtype=float)
        if scan_t in scans:
            np.testing.assert_array_equal(scans[scan_t], ranges)
        scans[scan_t] = ranges
    return scans


@pytest.fixture(scope="module")
def runs(case: Path, tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    return {"clean": _run(case, tmp_path_factory.mktemp("clean"), None),
            "faulty": _run(case, tmp_path_factory.mktemp("faulty"), FAULTS),
            "again": _run(case, tmp_path_factory.mktemp("again"), FAULTS)}


def _impulse_active(t: float) -> bool:
    return t >= 6.0 - 1e-9 and (t - 6.0 + 1e-9) % 2.0 < 0.5


def test_each_kind_acts_by_its_definition_and_only_inside_its_window(runs: dict[str, Path]) -> None:
    clean, faulty = _scans(runs["clean"]), _scans(runs["faulty"])
    assert sorted(clean) == sorted(faulty) and max(clean) >= 11.0
    # the fault seed is the run seed sequence's first child; the impulse noise is the schedule's third fault,
    # so it draws from that seed's second child, and only on the scans inside its pulses
    twin = np.random.default_rng(np.random.SeedSequence(SEED).spawn(2)[0].spawn(2)[1])
    frozen = faulty[3.9]
    counted = {"blackout": 0, "freeze": 0, "impulse": 0, "normal": 0}
    for t in sorted(clean):
        got, truth = faulty[t], clean[t]
        if 2.0 <= t < 3.0 - 1e-9:
            assert np.all(np.isinf(got)), t  # every beam: no return
            counted["blackout"] += 1
        elif 4.0 <= t < 5.5 - 1e-9:
            np.testing.assert_array_equal(got, frozen)  # the last scan before the window, bit for bit
            counted["freeze"] += 1
        elif _impulse_active(t):
            gain = 0.1 + 0.8 * (t - 6.0) / 5.0
            count = int(twin.poisson(0.05 * truth.shape[0]))
            starts = twin.integers(0, truth.shape[0], size=count)
            amplitudes = twin.uniform(-gain, gain, size=count) * RANGE_MAX
            added = np.zeros(truth.shape[0])
            for start, amplitude in zip(starts, amplitudes, strict=True):
                added[(start + np.arange(2)) % truth.shape[0]] += amplitude
            expected = truth.copy()
            hit = added != 0.0
            value = np.minimum(expected[hit], RANGE_MAX) + added[hit]
            value[value >= RANGE_MAX] = np.inf
            expected[hit] = np.maximum(value, RANGE_MIN)
            np.testing.assert_allclose(got, expected, rtol=0, atol=1e-12)
            assert count > 0 and not np.array_equal(got, truth)
            counted["impulse"] += 1
        else:
            np.testing.assert_array_equal(got, truth)  # outside every window the lidar is left alone
            counted["normal"] += 1
    assert counted == {"blackout": 10, "freeze": 15, "impulse": 15, "normal": counted["normal"]}
    # the freeze is not trivially true: the robot turns, so the scans it replaced differed from each other
    assert not np.array_equal(clean[4.0], clean[5.4])
    assert not np.array_equal(frozen, clean[4.5])


def test_window_edges_are_mission_events(runs: dict[str, Path]) -> None:
    events = [(m["t"], m["event"]) for m in read_recording(runs["faulty"] / "streams" / "mission.msgpack")
              if m["event"].startswith("FAULT_")]
    assert events == [(2.0, "FAULT_LASER_BLACKOUT_BEGIN"), (3.0, "FAULT_LASER_BLACKOUT_END"),
                      (4.0, "FAULT_LASER_FREEZE_BEGIN"), (5.5, "FAULT_LASER_FREEZE_END"),
                      (6.0, "FAULT_LASER_IMPULSE_BEGIN"), (6.5, "FAULT_LASER_IMPULSE_END"),
                      (8.0, "FAULT_LASER_IMPULSE_BEGIN"), (8.5, "FAULT_LASER_IMPULSE_END"),
                      (10.0, "FAULT_LASER_IMPULSE_BEGIN"), (10.5, "FAULT_LASER_IMPULSE_END")]
    clean = [m["event"] for m in read_recording(runs["clean"] / "streams" / "mission.msgpack")]
    assert not any(e.startswith("FAULT_") for e in clean)


def test_same_seed_same_streams_byte_for_byte(runs: dict[str, Path]) -> None:
    for stream in ("state.msgpack", "mission.msgpack"):
        a = (runs["faulty"] / "streams" / stream).read_bytes()
        assert a == (runs["again"] / "streams" / stream).read_bytes()
        assert a != (runs["clean"] / "streams" / stream).read_bytes()
