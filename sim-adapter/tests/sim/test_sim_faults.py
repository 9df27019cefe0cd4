# SPDX-License-Identifier: EPL-2.0
"""Laser fault specs and the Poisson impulse noise (no physics needed)."""

from __future__ import annotations

import numpy as np
import pytest

from rei.sim.faults import PRESETS, LaserFault, LaserFaultInjector, parse_fault


def test_parse_full_spec() -> None:
    assert parse_fault("laser:rate=0.01,gain=0.5,width=3") == LaserFault(rate=0.01, gain=0.5, width=3)
    assert parse_fault(" laser: width=2 , rate=0.2, gain=1 ") == LaserFault(rate=0.2, gain=1.0, width=2)


def test_presets_and_overrides() -> None:
    assert parse_fault("laser:1%") == PRESETS["1%"] == PRESETS["low"]
    assert parse_fault("laser:high") == PRESETS["10%"]
    assert PRESETS["1%"].rate * PRESETS["1%"].width == pytest.approx(0.01)
    assert PRESETS["10%"].rate * PRESETS["10%"].width == pytest.approx(0.10)
    assert parse_fault("laser:10%,gain=0.8") == LaserFault(rate=PRESETS["10%"].rate, gain=0.8, width=3)
    assert parse_fault("none") is None and parse_fault("") is None


@pytest.mark.parametrize(
    ("spec", "message"),
    [
        ("lidar:rate=0.1,gain=1,width=2", "expected 'laser:<preset>'"),
        ("laser:", "nothing after 'laser:'"),
        ("laser:5%", "unknown preset '5%'"),
        ("laser:rate=0.1,gain=1", "missing width"),
        ("laser:rate=x,gain=1,width=2", "could not convert"),
        ("laser:rate=0.1,gain=1,width=2,colour=3", "'colour=3' is not one of"),
        ("laser:rate=2,gain=1,width=2", "rate must be in [0, 1]"),
        ("laser:rate=0.1,gain=-1,width=2", "gain must be >= 0"),
        ("laser:rate=0.1,gain=1,width=0", "width must be >= 1"),
        ("laser:rate=0.1,rate=0.2,gain=1,width=1", "rate given twice"),
    ],
)
def test_bad_specs_are_explained(spec: str, message: str) -> None:
    with pytest.raises(ValueError) as info:
        parse_fault(spec)
    assert message in str(info.value) and repr(spec) in str(info.value)


def _scan() -> np.ndarray:
    ranges = np.full(360, 2.0)
    ranges[100:120] = np.inf
    return ranges


def test_same_seed_same_noise_other_seed_other_noise() -> None:
    fault = LaserFault(rate=0.05, gain=0.5, width=3)
    runs = []
    for seed in (7, 7, 8):
        injector = LaserFaultInjector(fault, np.random.default_rng(seed), 0.12, 3.5)
        runs.append([injector.apply(_scan()) for _ in range(5)])
    for a, b in zip(runs[0], runs[1], strict=True):
        np.testing.assert_array_equal(a, b)
    assert any(not np.array_equal(a, c) for a, c in zip(runs[0], runs[2], strict=True))
    assert any(not np.array_equal(a, _scan()) for a in runs[0])


def test_impulses_follow_the_documented_model() -> None:
    """Replays the documented draws (count, starts, amplitudes) with a twin generator and rebuilds each scan."""
    fault = LaserFault(rate=0.004, gain=1.0, width=4)
    injector = LaserFaultInjector(fault, np.random.default_rng(3), 0.12, 3.5)
    twin = np.random.default_rng(3)
    impulses = 0
    for _ in range(100):
        clean = _scan()
        noisy = injector.apply(clean)
        np.testing.assert_array_equal(clean, _scan())  # the input is not modified
        count = int(twin.poisson(fault.rate * 360))
        impulses += count
        if count == 0:
            np.testing.assert_array_equal(noisy, clean)
            continue
        starts = twin.integers(0, 360, size=count)
        amplitudes = twin.uniform(-1.0, 1.0, size=count) * 3.5
        added = [0.0] * 360
        for start, amplitude in zip(starts, amplitudes, strict=True):
            for k in range(fault.width):
                added[(int(start) + k) % 360] += float(amplitude)
        for i in range(360):
            if added[i] == 0.0:
                assert noisy[i] == clean[i]
                continue
            value = min(clean[i], 3.5) + added[i]
            expected = np.inf if value >= 3.5 else max(value, 0.12)
            assert noisy[i] == pytest.approx(expected, abs=1e-12)
    assert impulses > 50  # ~ 1.44 per scan


def test_zero_rate_changes_nothing() -> None:
    injector = LaserFaultInjector(
        LaserFault(rate=0.0, gain=1.0, width=3), np.random.default_rng(1), 0.12, 3.5
    )
    clean = _scan()
    assert injector.apply(clean) is clean
