# SPDX-License-Identifier: EPL-2.0
"""Faults as text: ``--fault`` specs and the ``<fault>`` elements of mission.xml share these keys.

``--fault`` takes faults separated by ``;``, each ``SENSOR:KIND,key=value,...``:

* ``laser:blackout,from=5,to=7``; ``laser:freeze,from=10,to=11``; ``laser:noise,sigma=0.02``;
  ``laser:occlusion,angles=-30..30,range=0.2``; ``laser:impulse,rate=0.03,gain=0.2@0/0.8@30,width=3,period=10,duty=10%``;
* timing keys (every kind): ``from``, ``to`` (seconds), ``period`` with ``pulse`` (seconds) or ``duty`` (a fraction
  or a percentage); without any of them a fault acts for the whole run;
* the run-long impulse noise as before: ``laser:1%``, ``laser:10%,gain=0.8``, ``laser:rate=R,gain=G,width=W``;
* the thesis's gated presets ``laser:gated-1%`` and ``laser:gated-10%`` (pulses of 1 % and 10 % of a 10 s period,
  the ``10%`` preset's noise inside them), which take further keys too (``laser:gated-10%,gain=0.8,from=5``);
* the motion's: ``commands:latency,delay=0.2``; ``commands:loss,probability=0.3``; ``drive:slip,fraction=0.5``;
  ``drive:stuck,wheel=left``; ``odometry:drift,scale=1.05,bias=2``; ``odometry:jump,dx=0.5,dy=0,dyaw=10``;
  ``pose:kidnap,dx=1,dy=-0.5,dyaw=90`` (degrees for angles).
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping

from rei.sim.faults.impulse import PRESETS, LaserFault
from rei.sim.faults.kind import number, seconds
from rei.sim.faults.laser import Blackout, Freeze, Impulse, LaserKind, Occlusion, RangeNoise
from rei.sim.faults.motion import WHEELS, Drift, Jump, Kidnap, Latency, Loss, Slip, Stuck
from rei.sim.faults.schedule import Fault, FaultSchedule
from rei.sim.faults.timing import Ramp, Timing, parse_ramp

TIMING_KEYS = ("from", "to", "period", "pulse", "duty")
KIND_KEYS: dict[str, tuple[str, ...]] = {
    "impulse": ("rate", "gain", "width"),
    "freeze": (),
    "blackout": (),
    "occlusion": ("angles", "range"),
    "noise": ("sigma",),
}
MOTION_KIND_KEYS: dict[str, dict[str, tuple[str, ...]]] = {
    "odometry": {"drift": ("scale", "bias"), "jump": ("dx", "dy", "dyaw")},
    "drive": {"slip": ("fraction",), "stuck": ("wheel",)},
    "commands": {"latency": ("delay",), "loss": ("probability",)},
    "pose": {"kidnap": ("dx", "dy", "dyaw")},
}
SENSOR_KIND_KEYS: dict[str, dict[str, tuple[str, ...]]] = {"laser": KIND_KEYS, **MOTION_KIND_KEYS}
"""Every sensor's kinds and their keys (``KIND_KEYS`` is the laser's), in contract/vocabulary.json's order."""
GATED_PERIOD = 10.0
"""Seconds per period of the thesis's gated presets: a 1 % pulse is 0.1 s, one scan of a 10 Hz lidar."""
GATED = {"gated-1%": 0.01, "gated-10%": 0.10}


def as_schedule(fault: FaultSchedule | LaserFault | str | None) -> FaultSchedule:
    """A schedule from what the simulation accepts: a schedule, a run-long impulse noise or a ``--fault`` spec."""
    if isinstance(fault, FaultSchedule):
        return fault
    if isinstance(fault, LaserFault):
        return FaultSchedule((Fault("laser", Impulse(fault.rate, Ramp.constant(fault.gain), fault.width),
                                    Timing.always()),))
    return parse_faults(fault)


def parse_faults(spec: str | None) -> FaultSchedule:
    """The schedule a ``--fault`` spec describes (empty for None, ``""`` and ``none``). Raises ``ValueError``
    naming the spec and what is wrong."""
    if spec is None or spec.strip() in ("", "none"):
        return FaultSchedule()
    faults = []
    for item in spec.split(";"):
        if not item.strip():
            continue
        try:
            faults.append(_one(item))
        except ValueError as error:
            raise ValueError(f"bad fault spec {item.strip()!r}: {error}") from None
    return FaultSchedule(tuple(faults))


def _one(item: str) -> Fault:
    sensor, sep, body = (s.strip() for s in item.strip().partition(":"))
    if sep and sensor in MOTION_KIND_KEYS:
        return _motion(sensor, body)
    if sensor != "laser" or not sep:
        raise ValueError("expected 'SENSOR:KIND,key=value,...' (SENSOR one of "
                         f"{', '.join(SENSOR_KIND_KEYS)}; laser KIND one of {', '.join(KIND_KEYS)}), "
                         "'laser:<preset>' or 'laser:rate=R,gain=G,width=W'")
    parts = [p.strip() for p in body.split(",") if p.strip()]
    if not parts:
        raise ValueError("nothing after 'laser:'")
    head = parts[0] if "=" not in parts[0] else None
    values = _keys(parts[1:] if head is not None else parts)
    if head is None or head in PRESETS:
        # today's run-long impulse noise, written as it always was
        base = PRESETS.get(head or "")
        defaults = {} if base is None else {"rate": f"{base.rate!r}", "gain": f"{base.gain!r}",
                                            "width": str(base.width)}
        if base is None:
            missing = sorted({"rate", "gain", "width"} - set(values))
            if missing:
                raise ValueError(f"missing {', '.join(missing)} (or start with a preset: {', '.join(PRESETS)})")
        return fault_from_fields("laser", "impulse", {**defaults, **values})
    if head in GATED:
        base = PRESETS["10%"]
        preset = {"rate": f"{base.rate!r}", "gain": f"{base.gain!r}", "width": str(base.width),
                  "period": f"{GATED_PERIOD:g}", "duty": f"{GATED[head]!r}"}
        if "pulse" in values:
            preset.pop("duty")
        return fault_from_fields("laser", "impulse", {**preset, **values})
    if head not in KIND_KEYS:
        raise ValueError(f"unknown laser fault {head!r}: known kinds {', '.join(KIND_KEYS)}, presets "
                         f"{', '.join([*PRESETS, *GATED])}")
    return fault_from_fields("laser", head, values)


def _motion(sensor: str, body: str) -> Fault:
    kinds = MOTION_KIND_KEYS[sensor]
    head, *parts = [p.strip() for p in body.split(",")]
    if head not in kinds:
        raise ValueError(f"unknown {sensor} fault {head!r}: known kinds {', '.join(kinds)}")
    return fault_from_fields(sensor, head, _keys(filter(None, parts)))


def _keys(parts: Iterable[str]) -> dict[str, str]:
    """``key=value`` parts as a mapping; each key once."""
    values: dict[str, str] = {}
    for part in parts:
        key, eq, value = (s.strip() for s in part.partition("="))
        if not eq:
            raise ValueError(f"{part!r} is not key=value")
        if key in values:
            raise ValueError(f"{key} given twice")
        values[key] = value
    return values


def fault_from_fields(sensor: str, kind: str, fields: Mapping[str, str]) -> Fault:
    """A fault from its keys as text (``--fault`` and mission.xml). Raises ``ValueError`` naming the key."""
    known = SENSOR_KIND_KEYS.get(sensor, {}).get(kind)
    if known is None:
        others = (f"known {sensor} kinds {', '.join(MOTION_KIND_KEYS[sensor])}" if sensor in MOTION_KIND_KEYS
                  else f"known sensors {', '.join(SENSOR_KIND_KEYS)}, laser kinds {', '.join(KIND_KEYS)}")
        raise ValueError(f"unknown fault {sensor} {kind}: {others}")
    for key in fields:
        if key not in known and key not in TIMING_KEYS:
            allowed = ", ".join(f"{k}=" for k in (*known, *TIMING_KEYS))
            raise ValueError(f"{key!r} is not a key of {_a(sensor)} {kind} fault (keys: {allowed})")
    effect = _motion_effect(sensor, kind, fields) if sensor in MOTION_KIND_KEYS else _effect(kind, fields)
    return Fault(sensor, effect, timing_from_fields(fields))


def timing_from_fields(fields: Mapping[str, str]) -> Timing:
    if not any(k in fields for k in TIMING_KEYS):
        return Timing.always()
    start = _seconds(fields, "from", 0.0)
    end = _seconds(fields, "to", math.inf)
    period = _maybe_seconds(fields, "period")
    if "pulse" in fields and "duty" in fields:
        raise ValueError("give the pulse width as pulse= (seconds) or duty= (a share of the period), not both")
    pulse = _maybe_seconds(fields, "pulse")
    if "duty" in fields:
        duty = _duty(fields["duty"])
        if period is None:
            raise ValueError("duty= needs period=")
        pulse = duty * period
    return Timing(start, end, period, pulse)


def _effect(kind: str, fields: Mapping[str, str]) -> LaserKind:
    if kind == "freeze":
        return Freeze()
    if kind == "blackout":
        return Blackout()
    if kind == "noise":
        return RangeNoise(_required(fields, "sigma", kind))
    if kind == "occlusion":
        text = fields.get("angles")
        if text is None:
            raise ValueError("an occlusion needs angles=FROM..TO (degrees)")
        low, dots, high = text.partition("..")
        if not dots:
            raise ValueError(f"angles {text!r}: expected FROM..TO in degrees, e.g. -30..30")
        return Occlusion(number(low, "angle"), number(high, "angle"), _required(fields, "range", kind))
    # what is not given is the "10%" preset's (docs/faults.md)
    base = PRESETS["10%"]
    gain = parse_ramp(fields["gain"]) if "gain" in fields else Ramp.constant(base.gain)
    width_text = fields.get("width", str(base.width))
    try:
        width = int(width_text)
    except ValueError:
        raise ValueError(f"width {width_text!r} is not a whole number of beams") from None
    rate = number(fields["rate"], "rate") if "rate" in fields else base.rate
    return Impulse(rate, gain, width)


def _motion_effect(sensor: str, kind: str, fields: Mapping[str, str]
                   ) -> Drift | Jump | Slip | Stuck | Latency | Loss | Kidnap:
    if kind == "latency":
        return Latency(_required(fields, "delay", kind, sensor))
    if kind == "loss":
        return Loss(_required(fields, "probability", kind, sensor))
    if kind == "slip":
        return Slip(_required(fields, "fraction", kind, sensor))
    if kind == "stuck":
        if "wheel" not in fields:
            raise ValueError(f"a drive stuck fault needs wheel= ({' or '.join(WHEELS)})")
        return Stuck(fields["wheel"])
    if kind == "drift":
        if "scale" not in fields and "bias" not in fields:
            raise ValueError("an odometry drift fault needs scale= or bias= (or both)")
        return Drift(number(fields.get("scale", "1"), "scale"), number(fields.get("bias", "0"), "bias"))
    offset = {key: number(fields.get(key, "0"), key) for key in ("dx", "dy", "dyaw")}
    return Jump(**offset) if kind == "jump" else Kidnap(**offset)


def _required(fields: Mapping[str, str], key: str, kind: str, sensor: str = "laser") -> float:
    if key not in fields:
        raise ValueError(f"{_a(sensor)} {kind} fault needs {key}=")
    return number(fields[key], key)


def _a(sensor: str) -> str:
    return ("an " if sensor[0] in "aeiou" else "a ") + sensor


def _seconds(fields: Mapping[str, str], key: str, default: float) -> float:
    return seconds(fields[key], key) if key in fields else default


def _maybe_seconds(fields: Mapping[str, str], key: str) -> float | None:
    return seconds(fields[key], key) if key in fields else None


def _duty(text: str) -> float:
    share = number(text[:-1], "duty") / 100.0 if text.endswith("%") else number(text, "duty")
    if not 0.0 < share <= 1.0:
        raise ValueError(f"duty must be in (0, 1] (or (0 %, 100 %]), got {text}")
    return share


def format_fault(fault: Fault) -> str:
    """The ``--fault`` spec of one fault, ``SENSOR:KIND,key=value,...``: what :func:`parse_faults` reads back as
    ``fault`` (the one writer of fault specs: a search's candidates carry their fault to the run as this text)."""
    fields = fault_fields(fault)
    return ",".join([f"{fault.sensor}:{fault.kind}", *(f"{key}={value}" for key, value in fields.items())])


def fault_fields(fault: Fault) -> dict[str, str]:
    """The keys of a fault as text, the inverse of :func:`fault_from_fields` (for writing a schedule back)."""
    out: dict[str, str] = {}
    effect = fault.effect
    if isinstance(effect, Impulse):
        out.update(rate=repr(effect.rate), gain=effect.gain.text(), width=str(effect.width))
    elif isinstance(effect, Occlusion):
        out.update(angles=f"{effect.angle_from!r}..{effect.angle_to!r}", range=repr(effect.range))
    elif isinstance(effect, RangeNoise):
        out.update(sigma=repr(effect.sigma))
    elif isinstance(effect, Latency):
        out.update(delay=repr(effect.delay))
    elif isinstance(effect, Loss):
        out.update(probability=repr(effect.probability))
    elif isinstance(effect, Slip):
        out.update(fraction=repr(effect.fraction))
    elif isinstance(effect, Stuck):
        out.update(wheel=effect.wheel)
    elif isinstance(effect, Drift):
        out.update(scale=repr(effect.scale), bias=repr(effect.bias))
    elif isinstance(effect, Jump | Kidnap):
        out.update(dx=repr(effect.dx), dy=repr(effect.dy), dyaw=repr(effect.dyaw))
    timing = fault.timing
    if not timing.whole_run:
        out["from"] = repr(timing.start)
        if math.isfinite(timing.end):
            out["to"] = repr(timing.end)
        if timing.period is not None and timing.pulse is not None:
            out.update(period=repr(timing.period), pulse=repr(timing.pulse))
    return out
