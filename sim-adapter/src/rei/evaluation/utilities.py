# SPDX-License-Identifier: EPL-2.0
"""The utility of each signal (thesis 5.2.1, Table 3), the utilities the VEPL patterns declare, and the YAML file
that overrides both.

Precedence, highest first (docs/evaluation.md, "Utilities"): the user's YAML file, the utility the patterns in use
declare (``signal SIG_X utility -2``; the monitor writes them with ``--utilities-out``), the defaults below, 0.

The total utility of a mission is the plain sum of its signals' utilities (thesis 5.2). Table 3 leaves some
signals out; their defaults are chosen here (docs/evaluation.md, "Utilities"):

- ``SIG_LASER_FAR_TRANSIT_CLOSE`` / ``SIG_LASER_CLOSE_TRANSIT_FAR``: 0. The geometric twin already scores the
  real approach; scoring the sensor's reading of the same approach again would count it twice. The thesis
  scores the laser only at the collision boundary, where the sensor's own view is a presage of damage.
- ``SIG_MONITOR_DATA_GAP``: 0. A lost message is a fault of the test harness, not behaviour of the robot; it
  makes the affected verdicts ``error`` instead (rei.evaluation.verdicts).
- ``SIG_FAULT_...`` (a fault window's edges, docs/faults.md): 0. A fault is what the test does to the robot, not
  behaviour to score; requirements relative to a fault score what the robot does.
- ``SIG_OBJECT_COLLISION_BEGIN`` / ``_END``: 0. Collisions per object are counted for the human requirement; the
  score stays that of Table 2's robot-level transitions.

A signal that is in no table at run time is worth 0 and counted by the evaluator (summary
``unknown_signals``). A signal a pattern declares without a utility is known: it falls through to the defaults,
else 0, and is not counted.
"""

from __future__ import annotations

import difflib
import json
import math
import os
from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from pathlib import Path
from types import MappingProxyType
from typing import Any

import yaml

from rei import located_yaml
from rei.evaluation.signals import DEFAULT_TRANSITIONS, FAULT_SIGNALS, KNOWN_SIGNALS, Transition

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
    "SIG_OBJECT_COLLISION_BEGIN": 0.0,
    "SIG_OBJECT_COLLISION_END": 0.0,
    **dict.fromkeys(FAULT_SIGNALS, 0.0),
})
assert set(DEFAULT_UTILITIES) == KNOWN_SIGNALS


class UtilityError(located_yaml.Problems):
    """A utility file that can not be used: each mistake names the file and, where it applies, the line and
    column of its key or value (``problems``, one per mistake)."""


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


#: How ``UtilityTable.source`` names the defaults when other sources are combined with them.
TABLE_3 = "Table 3"


def load_utilities(path: str | os.PathLike[str] | None = None,
                   declared: Mapping[str, float | None] | None = None, *,
                   patterns: str = "patterns") -> UtilityTable:
    """The defaults, overridden by the utilities the patterns ``declared`` (signal -> number, or None for a
    signal declared without one), overridden in turn by the mapping ``signal: number`` in the YAML file ``path``.

    Only the listed signals change. A YAML key that is neither a known nor a declared signal, one given twice, or
    a value that is not a finite number, raises UtilityError naming the file, line and column of each (a line
    each): a typo must not silently score a run with the default. ``patterns`` names the declaring patterns in ``source`` ("Table 3 + patterns + FILE");
    without ``declared`` the source is "defaults" or the file, as before.
    """
    values = dict(DEFAULT_UTILITIES)
    sources = [TABLE_3]
    if declared is not None:
        values.update(_declared(declared))
        sources.append(patterns)
    if path is None:
        return UtilityTable(values, source=" + ".join(sources) if declared is not None else "defaults")
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as error:
        raise UtilityError(f"{path}: cannot read the utility file: {error.strerror or error}") from None
    # composed, so that a mistake names its line and column (a file of tens of signals is edited by hand)
    try:
        node = located_yaml.compose(text, "not valid YAML")
        if node is not None and not isinstance(node, yaml.MappingNode):
            raise UtilityError(f"{path}: expected a mapping 'SIGNAL: utility', got "
                               f"{type(located_yaml.value(node)).__name__}")
        entries = [(k, located_yaml.scalar(k), v, located_yaml.value(v)) for k, v in node.value] if node else []
    except located_yaml.LocatedError as error:
        raise UtilityError(error.at(str(path))) from None
    # every mistake at once, each at its place, as rei validate reports a case's
    problems: list[str] = []
    given: set[object] = set()
    for key_node, key, value_node, value in entries:
        line, column = located_yaml.position(key_node)
        if key in given:  # YAML would keep the later silently
            problems.append(f"{path}:{line}:{column}: {key!r} is given twice")
        elif key not in values:
            near = difflib.get_close_matches(str(key), list(values), n=1)
            hint = f"did you mean {near[0]}?; " if near else ""
            problems.append(f"{path}:{line}:{column}: unknown signal {key!r} ({hint}known: "
                            f"{', '.join(sorted(values))})")
        elif not _is_number(value):
            line, column = located_yaml.position(value_node)
            problems.append(f"{path}:{line}:{column}: {key}: the utility must be a finite number, got {value!r}")
        else:
            values[str(key)] = float(value)
        given.add(key)
    if problems:
        raise UtilityError.of(problems)
    return UtilityTable(values, source=" + ".join((*sources, str(path))) if declared is not None else str(path))


@dataclass(frozen=True, slots=True)
class Declared:
    """What the patterns in use declare of their signals (the monitor's ``--utilities-out`` file): each signal's
    utility (None: none declared), and the zone changes over the defaults' (DEFAULT_TRANSITIONS)."""

    utilities: dict[str, float | None]
    transitions: dict[str, Transition]


def load_declared(path: str | os.PathLike[str]) -> Declared:
    """The monitor's ``--utilities-out`` file, ``{"SIG_X": {"utility": -2.0, "transition": {...}}, "SIG_Y":
    {"utility": null}}``, read once. A file of the earlier shape, ``{"SIG_X": -2.0}``, is read too. The evaluator
    judges zones from the transitions, never from signal names.

    Raises UtilityError naming the file (and the signal) for anything else.
    """
    path = Path(path)
    utilities: dict[str, float | None] = {}
    transitions = dict(DEFAULT_TRANSITIONS)
    for key, value in _declarations(path).items():
        utility = value.get("utility") if isinstance(value, dict) else value
        if utility is not None and not _is_number(utility):
            raise UtilityError(f"{path}: {key}: the utility must be a finite number or null, got {utility!r}")
        utilities[key] = None if utility is None else float(utility)
        if isinstance(value, dict) and value.get("transition") is not None:
            try:
                transitions[key] = Transition.from_json(value["transition"])
            except ValueError as error:
                raise UtilityError(f"{path}: {key}: {error}") from None
    return Declared(utilities, transitions)


def load_declared_utilities(path: str | os.PathLike[str]) -> dict[str, float | None]:
    """The utilities of :func:`load_declared`."""
    return load_declared(path).utilities


def load_declared_transitions(path: str | os.PathLike[str]) -> dict[str, Transition]:
    """The zone changes of :func:`load_declared`, over the defaults."""
    return load_declared(path).transitions


def _declarations(path: Path) -> dict[str, Any]:
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except OSError as error:
        raise UtilityError(f"{path}: cannot read the declared utilities: {error.strerror or error}") from None
    except ValueError as error:
        raise UtilityError(f"{path}: not valid JSON: {error}") from None
    if not isinstance(data, dict):
        raise UtilityError(f"{path}: expected a JSON object 'SIGNAL: declaration', got {type(data).__name__}")
    return data


def _declared(declared: Mapping[str, float | None]) -> dict[str, float]:
    """Declared signals as table entries: a declared utility wins over the default; a signal declared without
    one keeps its default, else 0 (it is known, so it is not counted as unknown)."""
    out: dict[str, float] = {}
    for name, value in declared.items():
        if value is None:
            out[name] = DEFAULT_UTILITIES.get(name, 0.0)
        elif not _is_number(value):
            raise UtilityError(f"declared utility of {name}: expected a finite number or None, got {value!r}")
        else:
            out[name] = float(value)
    return out


def _is_number(value: object) -> bool:
    return not isinstance(value, bool) and isinstance(value, int | float) and math.isfinite(value)
