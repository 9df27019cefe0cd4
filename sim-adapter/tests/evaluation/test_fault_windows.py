# SPDX-License-Identifier: EPL-2.0
"""The evaluator lists a run's fault windows from the SIG_FAULT_ signals, paired by the run's schedule."""

from __future__ import annotations

import json
import math
from pathlib import Path

from rei.evaluation.faults import FaultWindow, fault_windows, run_schedule
from rei.evaluation.signals import Signal
from rei.sim.faults import fault_fields, parse_faults


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


def _edges(*items: tuple[float, str]) -> list[Signal]:
    """Window edges as the monitor publishes them: at the first 240 Hz physics step at or after the edge's time."""
    return _signals(*((math.ceil(t * 240 - 1e-6) / 240, f"SIG_FAULT_LASER_BLACKOUT_{edge}") for t, edge in items))


def test_an_end_closes_the_window_of_the_fault_that_ends_then_when_windows_of_one_kind_overlap() -> None:
    # one blackout inside another: the inner one ends first (before: 2-6 and 4-10, windows that were not there)
    nested = parse_faults("laser:blackout,from=2,to=10;laser:blackout,from=4,to=6").faults
    windows = fault_windows(_edges((2, "BEGIN"), (4, "BEGIN"), (6, "END"), (10, "END")), nested)
    assert [(w.begin, w.end) for w in windows] == [(2.0, 10.0), (4.0, 6.0)]
    # overlapping, the first ends first
    crossed = parse_faults("laser:blackout,from=2,to=6;laser:blackout,from=4,to=8").faults
    windows = fault_windows(_edges((2, "BEGIN"), (4, "BEGIN"), (6, "END"), (8, "END")), crossed)
    assert [(w.begin, w.end) for w in windows] == [(2.0, 6.0), (4.0, 8.0)]
    # pulses of 0.3 s every 1 s inside a long window, edges off the physics steps
    pulses = parse_faults("laser:blackout,from=0.5,to=3.2;laser:blackout,from=1.1,period=1,pulse=0.3").faults
    edges = [(0.5, "BEGIN"), (1.1, "BEGIN"), (1.4, "END"), (2.1, "BEGIN"), (2.4, "END"), (3.1, "BEGIN"),
             (3.2, "END"), (3.4, "END")]
    windows = fault_windows(_edges(*edges), pulses)
    assert [(round(w.begin, 3), w.end and round(w.end, 3)) for w in windows] == [
        (0.5, 3.2), (1.1, 1.4), (2.1, 2.4), (3.1, 3.4)]


def test_the_schedule_is_read_from_the_run_s_sim_json(tmp_path: Path) -> None:
    faults = parse_faults("laser:blackout,from=2,to=10;laser:noise,sigma=0.02,period=4,pulse=1;"
                          "odometry:drift,scale=1.05").faults
    # sim.json's faults as the simulation writes them (rei.run.mission_run)
    listed = [{"sensor": f.sensor, "kind": f.kind, **fault_fields(f), "description": f.describe()} for f in faults]
    (tmp_path / "sim.json").write_text(json.dumps({"run_id": "r", "faults": listed}))
    assert run_schedule(tmp_path) == faults
    (tmp_path / "sim.json").write_text(json.dumps({"run_id": "r"}))
    assert run_schedule(tmp_path) == ()
    assert run_schedule(tmp_path / "missing") == ()
