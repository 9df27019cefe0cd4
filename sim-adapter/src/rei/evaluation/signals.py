# SPDX-License-Identifier: EPL-2.0
"""The signals the monitor publishes (docs/monitor.md) and one received signal, checked once at the door.

Why a parsed type: the evaluator's thread is fed by the WAMP client, and a bad message must be counted and
skipped there, never raise deep inside a verdict at the end of a two-hour run.
"""

from __future__ import annotations

import enum
import math
import re
from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

from rei.mission.executor import FAULT_EVENTS

SIG_MISSION_BEGIN = "SIG_MISSION_BEGIN"
SIG_MISSION_END = "SIG_MISSION_END"
SIG_MISSION_TASK_START = "SIG_MISSION_TASK_START"
SIG_MISSION_TASK_SUCCESS = "SIG_MISSION_TASK_SUCCESS"
SIG_MISSION_TASK_FAIL = "SIG_MISSION_TASK_FAIL"
SIG_MONITOR_DATA_GAP = "SIG_MONITOR_DATA_GAP"

MISSION_SIGNALS = (SIG_MISSION_BEGIN, SIG_MISSION_END, SIG_MISSION_TASK_START, SIG_MISSION_TASK_FAIL,
                   SIG_MISSION_TASK_SUCCESS)


class Source(enum.StrEnum):
    """What measured a zone: the footprint geometry (ground truth) or the robot's laser."""

    GEOM = "GEOM"
    LASER = "LASER"


class Zone(enum.IntEnum):
    """Geometric states of thesis Fig. 21, ordered by depth: FAR < CLOSE < COLLISION."""

    FAR = 0
    CLOSE = 1
    COLLISION = 2


@dataclass(frozen=True, slots=True)
class Transition:
    """A change of the robot's zone, as a pattern declares it for its signal (``signal SIG_X transition geometry
    FAR -> CLOSE``, docs/vepl.md): the evaluator judges zones from these declarations, never from signal names."""

    source: Source
    before: Zone
    after: Zone
    per_object: bool = False  # the zone of the signal's object, not the robot's single zone (``per object``)

    @classmethod
    def from_json(cls, value: Any) -> Transition:
        """``{"source": "GEOM", "from": "FAR", "to": "CLOSE", "per_object": true}`` as the monitor writes it (the
        last key only when true); ValueError otherwise."""
        if not isinstance(value, Mapping):
            raise ValueError(f"a transition must be a map of source, from and to, got {value!r}")  # noqa: TRY004 - one error type for callers
        try:
            return cls(Source(value.get("source")), Zone[str(value.get("from"))], Zone[str(value.get("to"))],
                       value.get("per_object") is True)
        except (KeyError, ValueError):
            raise ValueError(f"a transition needs source GEOM or LASER and zones FAR, CLOSE or COLLISION, got "
                             f"{dict(value)!r}") from None


#: The transitions the default patterns declare (Table 2): FAR<->CLOSE<->COLLISION, for geometry and laser. They
#: stand in for declarations where a run has none (hand-written rules); the contract test checks them against
#: cep/patterns.
_STEPS = ((Zone.FAR, Zone.CLOSE), (Zone.CLOSE, Zone.FAR), (Zone.CLOSE, Zone.COLLISION),
          (Zone.COLLISION, Zone.CLOSE))
SIG_OBJECT_COLLISION_BEGIN = "SIG_OBJECT_COLLISION_BEGIN"
SIG_OBJECT_COLLISION_END = "SIG_OBJECT_COLLISION_END"
DEFAULT_TRANSITIONS: Mapping[str, Transition] = MappingProxyType({
    **{f"SIG_{source}_{a.name}_TRANSIT_{b.name}": Transition(source, a, b) for source in Source for a, b in _STEPS},
    SIG_OBJECT_COLLISION_BEGIN: Transition(Source.GEOM, Zone.CLOSE, Zone.COLLISION, per_object=True),
    SIG_OBJECT_COLLISION_END: Transition(Source.GEOM, Zone.COLLISION, Zone.CLOSE, per_object=True),
})
TRANSITION_SIGNALS = tuple(DEFAULT_TRANSITIONS)
#: The default patterns' fault signals (cep/patterns/faults.vepl): SIG_ + each fault window edge of the mission
#: topic (rei.mission.executor.FAULT_EVENTS, contract/vocabulary.json "faults").
FAULT_SIGNALS = tuple(f"SIG_{event}" for event in FAULT_EVENTS)
KNOWN_SIGNALS: frozenset[str] = frozenset((*MISSION_SIGNALS, *TRANSITION_SIGNALS, SIG_MONITOR_DATA_GAP,
                                           *FAULT_SIGNALS))
_TASK_OBJECT = re.compile(r"task_(\d+)")


class SignalError(ValueError):
    """A signal message that does not have the documented shape; the message says which field."""


#: The fields of a signal message, in order (contract/vocabulary.json ``signal_record``).
SIGNAL_RECORD = ("seq", "t", "signal", "subject", "object", "distance")


@dataclass(frozen=True, slots=True)
class Signal:
    """One message of ``rei.run.<id>.signal``: ``{seq, t, signal, subject, object, distance}``. ``object`` is empty
    when no object is concerned (a robot-level transition with nothing near: the monitor's RobotFact)."""

    seq: int
    t: float
    signal: str
    subject: str
    object: str
    distance: float

    @classmethod
    def from_message(cls, message: Mapping[str, Any]) -> Signal:
        if not isinstance(message, Mapping):
            raise SignalError(f"a signal must be a map, got {type(message).__name__}")
        seq = message.get("seq")
        if not isinstance(seq, int) or isinstance(seq, bool) or seq < 0:
            raise SignalError(f"signal field 'seq' must be an integer >= 0, got {seq!r}")
        t = _real(message, "t")
        if not math.isfinite(t):
            raise SignalError(f"signal field 't' must be finite, got {t!r}")
        distance = _real(message, "distance")
        texts = [message.get(key) for key in SIGNAL_RECORD[2:5]]
        for key, value in zip(SIGNAL_RECORD[2:5], texts, strict=True):
            if not isinstance(value, str) or (not value and key != "object"):
                raise SignalError(f"signal field {key!r} must be a non-empty string, got {value!r}")
        return cls(seq, t, texts[0], texts[1], texts[2], distance)  # type: ignore[arg-type]

    @property
    def task_index(self) -> int | None:
        """The task of a ``SIG_MISSION_TASK_*`` signal (object ``task_<i>``), else None."""
        match = _TASK_OBJECT.fullmatch(self.object)
        return int(match[1]) if match else None


def _real(message: Mapping[str, Any], key: str) -> float:
    value = message.get(key)
    if isinstance(value, bool) or not isinstance(value, int | float) or math.isnan(value):
        raise SignalError(f"signal field {key!r} must be a number, got {value!r}")
    return float(value)
