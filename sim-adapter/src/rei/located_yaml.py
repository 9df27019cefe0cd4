# SPDX-License-Identifier: EPL-2.0
"""YAML read with positions: every value with the line and column where it was written, so that a message about
it can say ``FILE:LINE:COLUMN``, as ``rei validate`` reports a test case's.

PyYAML's ``compose`` keeps each node's start mark; these functions read nodes and raise ``LocatedError`` (the
position and the message) for the caller to turn into its own error type with its file (rei.search.spec's
``SpecError``, rei.compare.thresholds' ``ThresholdsError``, rei.maps.occupancy's ``MapError``).
"""

from __future__ import annotations

import math
from typing import Any

import yaml

#: A mapping's entries by key text: (key node, value node). The key node places a message about the key itself,
#: whatever YAML made of it (``1:`` is a number, ``[a]:`` no scalar at all).
Entries = dict[str, tuple[yaml.Node, yaml.Node]]


class LocatedError(ValueError):
    """``message`` about the text at ``line``, ``column`` (from 1; None when YAML gave no position)."""

    def __init__(self, line: int | None, column: int | None, message: str) -> None:
        self.line, self.column, self.message = line, column, message
        super().__init__(message if line is None else f"{line}:{column}: {message}")

    def at(self, file: str) -> str:
        """``FILE:LINE:COLUMN: message`` (``FILE: message`` without a position)."""
        return f"{file}: {self.message}" if self.line is None else f"{file}:{self.line}:{self.column}: {self.message}"


def compose(text: str, not_yaml: str = "not YAML") -> yaml.Node | None:
    """The document's root node (None for an empty one); text that is not YAML raises ``LocatedError`` at the
    problem, its message ``<not_yaml>: <problem>``."""
    try:
        return yaml.compose(text, Loader=yaml.SafeLoader)
    except yaml.MarkedYAMLError as error:
        mark = error.problem_mark or error.context_mark
        line, column = (mark.line + 1, mark.column + 1) if mark is not None else (None, None)
        raise LocatedError(line, column, f"{not_yaml}: {error.problem}") from None
    except yaml.YAMLError as error:
        raise LocatedError(None, None, f"{not_yaml}: {error}") from None


def position(node: yaml.Node) -> tuple[int, int]:
    """Where ``node`` starts: line and column, from 1."""
    return node.start_mark.line + 1, node.start_mark.column + 1


def error(node: yaml.Node, message: str) -> LocatedError:
    return LocatedError(*position(node), message)


def value(node: yaml.Node) -> Any:
    """The Python value of ``node`` and everything under it (YAML's safe types)."""
    try:
        return yaml.constructor.SafeConstructor().construct_object(node, deep=True)
    except yaml.YAMLError as problem:
        raise error(node, f"not a valid value: {problem}") from None


def scalar(node: yaml.Node) -> object:
    """The value of a scalar node; None for a mapping or a list."""
    return value(node) if isinstance(node, yaml.ScalarNode) else None


def mapping(node: yaml.Node, what: str) -> Entries:
    """A mapping node's entries by key text; not a mapping, or a key given twice, is a ``LocatedError``."""
    if not isinstance(node, yaml.MappingNode):
        raise error(node, f"{what} must be a mapping")
    entries: Entries = {}
    for key, item in node.value:
        name = str(scalar(key))
        if name in entries:
            raise error(key, f"'{name}' is given twice")
        entries[name] = (key, item)
    return entries


def number(node: yaml.Node) -> float | None:
    """A finite number (also YAML 1.1's ``1e-2``, which it reads as text without a dot); None when it is not one."""
    found = scalar(node)
    if isinstance(found, str):
        try:
            found = float(found)
        except ValueError:
            return None
    if isinstance(found, bool) or not isinstance(found, int | float) or not math.isfinite(found):
        return None
    return float(found)
