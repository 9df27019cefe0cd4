# SPDX-License-Identifier: EPL-2.0
"""A search spec's fault on a timeline (#39, "Searchable"): ``{fault: laser, kind: [...], start: [...], ...}`` read
into parameters, a point of them written as the ``--fault`` spec the fault model reads back, and each mistake
placed at the YAML it is about."""

from __future__ import annotations

from pathlib import Path

import pytest

from rei.run import MissionRunOptions
from rei.search.space import Space
from rei.search.spec import SearchSpecError, parse_search_spec
from rei.sim.faults import parse_faults

DIAGRAM = {"room": {"floors": [{"name": "F_0_0", "centreX": 0.5, "centreY": 0.5}]}}


def _spec(tmp_path: Path, parameter: str) -> str:
    (tmp_path / "c.rei").write_text("testcase C {}\n", encoding="utf-8")
    return f"case: c.rei\nparameters:\n  - {parameter}\nobjectives: [utility]\n"


def _problems(tmp_path: Path, parameter: str) -> list[str]:
    with pytest.raises(SearchSpecError) as caught:
        parse_search_spec(_spec(tmp_path, parameter), base=tmp_path, file="s.yaml")
    return list(caught.value.problems)


def test_a_blackout_s_start_and_duration_make_its_from_and_to(tmp_path: Path) -> None:
    spec = parse_search_spec(_spec(tmp_path, "{fault: laser, kind: [blackout, freeze], start: [2, 20], "
                                             "duration: [0.2, 5]}"), base=tmp_path, file="s.yaml")
    assert next((p.key, p.domain) for p in spec.parameters) == ("fault.kind", ("blackout", "freeze"))
    assert [p.key for p in spec.parameters] == ["fault.kind", "fault.start", "fault.duration"]
    space = Space(spec.parameters, DIAGRAM)
    fault = space.edit({"fault.kind": "freeze", "fault.start": 3.25, "fault.duration": 1.5}).fault
    assert fault == "laser:freeze,from=3.25,to=4.75"
    [parsed] = parse_faults(fault).faults
    assert (parsed.kind, parsed.timing.start, parsed.timing.end) == ("freeze", 3.25, 4.75)
    assert space.edit({}).fault is None  # the base case's own point: no fault
    # shrinking: a shorter duration first, the boldest step first; then a later start
    assert space.smaller("fault.duration", 4.2, "walker") == pytest.approx([0.2, 1.2, 2.2, 3.2])
    assert space.smaller("fault.start", 4.0, "walker") == pytest.approx([20, 16, 12, 8])
    assert space.smaller("fault.kind", "freeze", "walker") == []
    assert space.shrink_order(["fault.start", "fault.kind", "fault.duration"])[0] == "fault.duration"


def test_a_gated_noise_s_values_and_pulse_train_are_written_for_its_kind_only(tmp_path: Path) -> None:
    spec = parse_search_spec(_spec(tmp_path, "{fault: laser, kind: [noise, blackout], sigma: [0.01, 0.1], "
                                             "period: [1, 4], pulse: [0.5, 2]}"), base=tmp_path, file="s.yaml")
    space = Space(spec.parameters, DIAGRAM)
    values = {"fault.kind": "noise", "fault.sigma": 0.05, "fault.period": 1.0, "fault.pulse": 1.5}
    assert space.edit(values).fault == "laser:noise,sigma=0.05,from=0.0,period=1.0,pulse=1.0"  # pulse <= period
    assert space.edit({**values, "fault.kind": "blackout"}).fault == "laser:blackout,from=0.0,period=1.0,pulse=1.0"


def test_a_motion_fault_s_values_are_written_for_its_kind_only(tmp_path: Path) -> None:
    """The motion's kinds searched as the laser's are: a kidnap's offset and when it happens, an odometry fault's
    kind from a list with each kind's own keys only in its spec."""
    spec = parse_search_spec(_spec(tmp_path, "{fault: pose, kind: kidnap, start: [2, 8], dx: [-1, 1], "
                                             "dyaw: [0, 90]}"), base=tmp_path, file="s.yaml")
    assert [p.key for p in spec.parameters] == ["fault.kind", "fault.start", "fault.dx", "fault.dyaw"]
    space = Space(spec.parameters, DIAGRAM)
    fault = space.edit({"fault.kind": "kidnap", "fault.start": 3.5, "fault.dx": -0.25, "fault.dyaw": 45.0}).fault
    assert fault == "pose:kidnap,dx=-0.25,dy=0.0,dyaw=45.0,from=3.5"
    [parsed] = parse_faults(fault).faults
    assert (parsed.sensor, parsed.kind, parsed.effect.dx, parsed.effect.dyaw, parsed.timing.start) == (
        "pose", "kidnap", -0.25, 45.0, 3.5)
    assert space.smaller("fault.start", 3.5, "wall") == pytest.approx([8, 6.875, 5.75, 4.625])

    spec = parse_search_spec(_spec(tmp_path, "{fault: odometry, kind: [drift, jump], start: [0, 5], "
                                             "duration: [1, 3], bias: [-5, 5], dy: [0.1, 0.5]}"),
                             base=tmp_path, file="s.yaml")
    space = Space(spec.parameters, DIAGRAM)
    values = {"fault.kind": "drift", "fault.start": 1.0, "fault.duration": 2.0, "fault.bias": 3.0, "fault.dy": 0.2}
    assert space.edit(values).fault == "odometry:drift,scale=1.0,bias=3.0,from=1.0,to=3.0"
    assert space.edit({**values, "fault.kind": "jump"}).fault == "odometry:jump,dx=0.0,dy=0.2,dyaw=0.0,from=1.0,to=3.0"
    spec = parse_search_spec(_spec(tmp_path, "{fault: drive, kind: [slip, stuck], fraction: [0.2, 0.8], "
                                             "wheel: [left, right], start: [1, 4]}"), base=tmp_path, file="s.yaml")
    assert next(p.domain for p in spec.parameters if p.key == "fault.wheel") == ("left", "right")
    space = Space(spec.parameters, DIAGRAM)
    values = {"fault.kind": "stuck", "fault.fraction": 0.5, "fault.wheel": "right", "fault.start": 2.0}
    assert space.edit(values).fault == "drive:stuck,wheel=right,from=2.0"
    assert space.edit({**values, "fault.kind": "slip"}).fault == "drive:slip,fraction=0.5,from=2.0"
    assert space.smaller("fault.wheel", "right", "wall") == []  # shrinking keeps the wheel
    # a latency's delay: the nearest whole number of the runs' control periods (rei run's 10 Hz), one at least
    spec = parse_search_spec(_spec(tmp_path, "{fault: commands, kind: [loss, latency], delay: [0.01, 0.5], "
                                             "probability: [0.1, 0.9]}"), base=tmp_path, file="s.yaml")
    space = Space(spec.parameters, DIAGRAM)
    written = [space.edit({"fault.kind": "latency", "fault.delay": delay, "fault.probability": 0.5}).fault
               for delay in (0.26, 0.34, 0.01)]
    assert written == ["commands:latency,delay=0.3", "commands:latency,delay=0.3", "commands:latency,delay=0.1"]
    assert [parse_faults(w).commands([], MissionRunOptions().control_rate) for w in written]  # whole periods
    for sensor, kind, key, value in (("drive", "slip", "fraction", 0.4), ("commands", "loss", "probability", 0.3)):
        spec = parse_search_spec(_spec(tmp_path, f"{{fault: {sensor}, kind: {kind}, {key}: [0.1, 0.9]}}"),
                                 base=tmp_path, file="s.yaml")
        fault = Space(spec.parameters, DIAGRAM).edit({"fault.kind": kind, f"fault.{key}": value}).fault
        assert fault == f"{sensor}:{kind},{key}={value}"
        assert getattr(parse_faults(fault).faults[0].effect, key) == value  # it reads back


@pytest.mark.parametrize(("parameter", "expected"), [
    ("{fault: laser, kind: [blackot], start: [0, 5]}",
     ("s.yaml:3:26: unknown laser fault kind 'blackot' (did you mean blackout?); known: impulse, freeze, blackout, "
     "noise")),
    ("{fault: laser, kind: [blackout], sigma: [0.1, 0.2]}",
     "s.yaml:3:38: a laser blackout fault has no 'sigma' (its keys: start, duration, period, pulse, duty)"),
    ("{fault: laser, kind: [impulse], rate: [0.1, 2]}",
     ("s.yaml:3:43: rate [0.1, 2] reaches outside what a laser impulse fault accepts: laser fault rate must be in "
     "[0, 1] impulses per beam per scan, got 2.0")),
    ("{fault: laser, kind: blackout, start: [-1, 5]}",
     "s.yaml:3:43: a fault's start must be a time >= 0 s, got [-1, 5]"),
    ("{fault: laser, kind: blackout, duration: [0, 5]}",
     "s.yaml:3:46: a fault's duration must be > 0 s, got [0, 5]"),
    ("{fault: laser, kind: [noise], start: [0, 5]}",
     "s.yaml:3:26: a laser noise fault needs 'sigma': give its range"),
    ("{fault: laser, kind: [occlusion]}",
     ("s.yaml:3:26: an occlusion's sector is not searched yet: search impulse, freeze, blackout, noise, or give the "
     "occlusion in the base case's faults block")),
    ("{fault: laser, start: [0, 5]}",
     ("s.yaml:3:5: give 'kind': the laser fault's kinds to choose from, such as [blackout, freeze] (of impulse, "
     "freeze, blackout, noise)")),
    ("{fault: laser, kind: blackout, pulse: [0.1, 1]}",
     "s.yaml:3:36: a pulse train needs 'period' and 'pulse' (or 'duty')"),
    ("{fault: laser, kind: blackout, period: [1, 2], duty: [0.1, 1.5]}",
     ("s.yaml:3:58: duty [0.1, 1.5] reaches outside what a laser blackout fault accepts: duty must be in (0, 1] (or "
     "(0 %, 100 %]), got 1.5")),
    ("{fault: drive, kind: slip, start: [0, 5]}",
     "s.yaml:3:26: a drive slip fault needs 'fraction': give its range"),
    ("{fault: odometry, kind: [drift, jump], start: [0, 5], dx: [0, 1]}",
     "s.yaml:3:29: an odometry drift fault needs 'scale' or 'bias': give a range of one"),
    ("{fault: drive, kind: [stuck]}",
     "s.yaml:3:26: a drive stuck fault needs 'wheel': give its range"),
    ("{fault: drive, kind: [stuck], wheel: [left, middle]}",
     "s.yaml:3:42: 'wheel' is the stuck wheel or a list to choose from: left or right, got ['left', 'middle']"),
    ("{fault: drive, kind: [slip], fraction: [0.1, 0.5], wheel: left}",
     "s.yaml:3:56: a drive slip fault has no 'wheel' (its keys: fraction, start, duration, period, pulse, duty)"),
    ("{fault: commands, kind: latency}",
     "s.yaml:3:29: a commands latency fault needs 'delay': give its range"),
    ("{fault: commands, kind: latency, delay: [0, 0.5]}",
     ("s.yaml:3:45: delay [0, 0.5] reaches outside what a commands latency fault accepts: latency delay must be > 0 "
      "s, got 0")),
    ("{fault: drive, kind: slip, fraction: [0, 0.5]}",
     ("s.yaml:3:42: fraction [0, 0.5] reaches outside what a drive slip fault accepts: slip fraction must be in "
      "(0, 1], got 0")),
    ("{fault: pose, kind: kidnap, dx: [0, 1], sigma: [0.1, 0.2]}",
     "s.yaml:3:45: a pose kidnap fault has no 'sigma' (its keys: dx, dy, dyaw, start, duration, period, pulse, duty)"),
    ("{fault: commands, kind: [los], probability: [0.1, 0.5]}",
     "s.yaml:3:29: unknown commands fault kind 'los' (did you mean loss?); known: latency, loss"),
    ("{fault: odometry, start: [0, 5]}",
     ("s.yaml:3:5: give 'kind': the odometry fault's kinds to choose from, such as [drift, jump] (of drift, "
      "jump)")),
    ("{fault: \"laser:1%\", start: [0, 5]}",
     ("s.yaml:3:25: 'start' is a key of a fault on a timeline ({fault: laser, kind: [...], start: ...}); a preset's "
     "values are rate, gain, width")),
])
def test_a_mistake_in_a_searched_fault_is_placed_at_what_is_wrong(tmp_path: Path, parameter: str,
                                                                  expected: str) -> None:
    assert _problems(tmp_path, parameter) == [expected]
