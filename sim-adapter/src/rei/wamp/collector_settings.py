# SPDX-License-Identifier: EPL-2.0
"""Collector settings from a YAML file (thesis 5.1.4: which fields, at which rate): ``rei sim|run --collector
FILE``. Every key is optional; what is left out keeps its default::

    rate_hz: 20            # state messages per simulated second (0: every physics step)
    laser: min             # min | full | none
    contacts: true         # the simulator's contact pairs
    odometry: true         # the robot's odometry pose
    nav_state: true        # the navigation's state (IDLE, ACTIVE, ...)
    full_frame_period: 1.0 # seconds between full frames (every published moving object); 0: the first only
    objects: [walker, DYNAMIC]  # the moving objects published, by name or category (default: all)

A problem names the file, the line and column, and what was expected: a typo must not silently run with a
default.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import yaml

from rei.wamp.codec import LaserMode
from rei.wamp.collector import CollectorConfig


class CollectorSettingsError(ValueError):
    """The file cannot be used; the message names it, the line and column, and what was expected."""


_KINDS: dict[str, str] = {"rate_hz": "number", "laser": "laser", "contacts": "bool", "odometry": "bool",
                          "nav_state": "bool", "full_frame_period": "number", "objects": "names"}


def load_collector_settings(path: Path) -> CollectorConfig:
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as error:
        raise CollectorSettingsError(f"{path}: cannot read the collector settings: {error.strerror or error}") \
            from None
    try:
        root = yaml.compose(text)
    except yaml.YAMLError as error:
        raise CollectorSettingsError(f"{path}: not valid YAML: {error}") from None
    if root is None:
        return CollectorConfig()
    if not isinstance(root, yaml.MappingNode):
        raise CollectorSettingsError(f"{_at(path, root)}: expected a mapping of settings ({', '.join(_KINDS)})")
    values: dict[str, Any] = {}
    for key_node, value_node in root.value:
        key = key_node.value
        if key not in _KINDS:
            raise CollectorSettingsError(f"{_at(path, key_node)}: unknown setting {key!r} (expected one of "
                                         f"{', '.join(_KINDS)})")
        values[key] = _value(path, key, value_node)
    try:
        return CollectorConfig(**values)
    except ValueError as error:
        raise CollectorSettingsError(f"{path}: {error}") from None


def _value(path: Path, key: str, node: yaml.Node) -> Any:
    kind = _KINDS[key]
    if kind == "names" and isinstance(node, yaml.SequenceNode):
        for item in node.value:
            if not (isinstance(item, yaml.ScalarNode) and item.tag == "tag:yaml.org,2002:str" and item.value):
                raise CollectorSettingsError(f"{_at(path, item)}: {key} must list object names or categories "
                                             f"(HUMAN, DYNAMIC), got {item.value!r}")
        return tuple(item.value for item in node.value)
    value = yaml.safe_load(yaml.serialize(node)) if isinstance(node, yaml.ScalarNode) else None
    if kind == "bool" and isinstance(value, bool):
        return value
    if kind == "number" and isinstance(value, int | float) and not isinstance(value, bool) \
            and math.isfinite(value) and value >= 0:
        return float(value)
    if kind == "laser" and value in {mode.value for mode in LaserMode}:
        return LaserMode(value)
    expected = {"bool": "true or false", "number": "a finite number >= 0",
                "laser": " | ".join(mode.value for mode in LaserMode),
                "names": "a list of object names or categories, e.g. [walker, HUMAN]"}[kind]
    got = repr(node.value) if isinstance(node, yaml.ScalarNode) else \
        "a list" if isinstance(node, yaml.SequenceNode) else "a mapping"
    raise CollectorSettingsError(f"{_at(path, node)}: {key} must be {expected}, got {got}")


def _at(path: Path, node: yaml.Node) -> str:
    return f"{path}:{node.start_mark.line + 1}:{node.start_mark.column + 1}"
