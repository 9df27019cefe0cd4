# SPDX-License-Identifier: EPL-2.0
"""The utility of each signal (thesis 5.2.1, Table 3) and the YAML file that overrides it.

The total utility of a mission is the plain sum of its signals' utilities (thesis 5.2). Table 3 leaves some
signals out; their defaults are chosen here (docs/evaluation.md, "Utilities"):

- ``SIG_LASER_FAR_TRANSIT_CLOSE`` / ``SIG_LASER_CLOSE_TRANSIT_FAR``: 0. The geometric twin already scores the
  real approach; scoring the sensor's reading of the same approach again would count it twice. The thesis
  scores the laser only at the collision boundary, where the sensor's own view is a presage of damage.
- ``SIG_MONITOR_DATA_GAP``: 0. A lost message is a fault of the test harness, not behaviour of the robot; it
  makes the affected verdicts ``error`` instead (rei.evaluation.verdicts).

A signal that is in no table at run time is worth 0 and counted by the evaluator (summary
``unknown_signals``).
"""

from __future__ import annotations

import math
import os
from collections.abc import Iterator, Mapping
from pathlib import Path
from types import MappingProxyType

import yaml

from rei.evaluation.signals import KNOWN_SIGNALS

#: Table 3 of the thesis, plus the documented defaults for the signals it does not list.
DEFAULT_UTILITIES: Mapping[str, float] = MappingProxyType({
    "SIG_MISSION_BEGIN": 20.0,
    "SIG_MISSION_END": 20.0,
    "SIG_MISSION_TASK_START": 5.0,
    "SIG_MISSION_TASK_FAIL": -100.0,
    "SIG_MISSION_TASK_SUCCESS": 10.0,
    "SIG_GEOM_FAR_TRANSIT_CLOSE": -2.0,
    "SIG_GEOM_CLOSE_TRANSIT_FAR": 1.0,
    "SIG_GEOM_CLOSE_TRANSIT_COLLISION": -10.0,
    "SIG_GEOM_COLLISION_TRANSIT_CLOSE": 1.0,
    "SIG_LASER_CLOSE_TRANSIT_COLLISION": -5.0,
    "SIG_LASER_COLLISION_TRANSIT_CLOSE": 1.0,
    "SIG_LASER_FAR_TRANSIT_CLOSE": 0.0,
    "SIG_LASER_CLOSE_TRANSIT_FAR": 0.0,
    "SIG_MONITOR_DATA_GAP": 0.0,
})
assert set(DEFAULT_UTILITIES) == KNOWN_SIGNALS


class UtilityError(ValueError):
    """A utility file that can not be used; the message names the file and, where it applies, the key."""


class UtilityTable(Mapping[str, float]):
    """Signal name -> utility; ``utility()`` answers 0 for a signal the table does not know."""

    def __init__(self, values: Mapping[str, float], source: str = "defaults") -> None:
        self._values = dict(values)
        self.source = source

    def utility(self, signal: str) -> float:
        return self._values.get(signal, 0.0)

    def __getitem__(self, signal: str) -> float:
        return self._values[signal]

    def __iter__(self) -> Iterator[str]:
        return iter(self._values)

    def __len__(self) -> int:
        return len(self._values)

    def __repr__(self) -> str:
        return f"UtilityTable({self._values!r}, source={self.source!r})"


def default_utilities() -> UtilityTable:
    return UtilityTable(DEFAULT_UTILITIES)


def load_utilities(path: str | os.PathLike[str] | None = None) -> UtilityTable:
    """The defaults, overridden by the mapping ``signal: number`` in the YAML file ``path`` (None: defaults).

    Only the listed signals change. A key that is not a known signal, or a value that is not a finite number,
    raises UtilityError naming the file and the key: a typo must not silently score a run with the default.
    """
    if path is None:
        return default_utilities()
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as error:
        raise UtilityError(f"{path}: cannot read the utility file: {error.strerror or error}") from None
    try:
        data = yaml.safe_load(text)
    except yaml.YAMLError as error:
        raise UtilityError(f"{path}: not valid YAML: {error}") from None
    if data is None:
        data = {}
    if not isinstance(data, dict):
        raise UtilityError(f"{path}: expected a mapping 'SIGNAL: utility', got {type(data).__name__}")
    values = dict(DEFAULT_UTILITIES)
    for key, value in data.items():
        if key not in KNOWN_SIGNALS:
            known = ", ".join(sorted(KNOWN_SIGNALS))
            raise UtilityError(f"{path}: unknown signal {key!r} (known: {known})")
        if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
            raise UtilityError(f"{path}: {key}: the utility must be a finite number, got {value!r}")
        values[key] = float(value)
    return UtilityTable(values, source=str(path))
