# SPDX-License-Identifier: EPL-2.0
"""The evaluator lists a run's fault windows from the SIG_FAULT_ signals."""

from __future__ import annotations

from rei.evaluation.faults import FaultWindow, fault_windows
from rei.evaluation.signals import Signal


def _signals(*items: tuple[float, str]) -> list[Signal]:
    return [Signal(i, t, name, "tb3", "", 0.0) for i, (t, name) in enumerate(items)]


def test_windows_pair_begin_and_end_of_the_same_fault() -> None:
    signals = _signals((0.0, "SIG_MISSION_BEGIN"), (2.0, "SIG_FAULT_LASER_BLACKOUT_BEGIN"),
                       (3.0, "SIG_FAULT_LASER_FREEZE_BEGIN"), (4.0, "SIG_FAULT_LASER_BLACKOUT_END"),
                       (5.0, "SIG_FAULT_LASER_FREEZE_END"), (6.0, "SIG_FAULT_LASER_BLACKOUT_BEGIN"),
                       (7.0, "SIG_FAULT_LASER_NOISE_END"))
    windows = fault_windows(signals)
    assert windows == (FaultWindow("laser", "blackout", 2.0, 4.0), FaultWindow("laser", "freeze", 3.0, 5.0),
                       FaultWindow("laser", "blackout", 6.0, None))
    assert windows[0].to_dict() == {"fault": "laser blackout", "begin": 2.0, "end": 4.0}
    assert fault_windows(_signals((1.0, "SIG_MISSION_END"))) == ()
