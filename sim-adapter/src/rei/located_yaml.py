# SPDX-License-Identifier: EPL-2.0
"""YAML read with positions: every value with the line and column where it was written, so that a message about
it can say ``FILE:LINE:COLUMN``, as ``rei validate`` reports a test case's.

PyYAML's ``compose`` keeps each node's start mark; these functions read nodes and raise ``LocatedError`` (the
position and the message) for the caller to turn into its own error type with its file (rei.search.spec's
``SpecError``, rei.compare.thresholds' ``ThresholdsError``, rei.maps.occupancy's ``MapError``).

A file is checked completely, as ``rei validate`` checks a test case: ``Problems`` is the error type of a file's
mistakes, one or several, each a message ``FILE:LINE:COLUMN: ...`` in the order of their positions; a ``Collector``
gathers them while the checks go on, so one mistake does not hide the next.
"""

from __future__ import annotations

import contextlib
import math
import re
from collections.abc import Callable, Iterable, Iterator
from typing import Any, Self, TypeVar

import yaml

T = TypeVar("T")
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


class Problems(ValueError):
    """Every mistake found in a file, one message each (``FILE:LINE:COLUMN: message``, or ``FILE: message`` where no
    position is known), in the order of their positions: ``problems``; ``str()`` gives them one per line. Raised
    with one message as any error (``Problems(message)``), with several by ``Problems.of(messages)``."""

    def __init__(self, *args: object) -> None:
        super().__init__(*args)
        self.problems: tuple[str, ...] = (str(args[0]),) if args else ()

    @classmethod
    def of(cls, problems: Iterable[str]) -> Self:
        """The error of ``problems``, in the order of their positions, each once."""
        ordered = in_order(problems)
        error = cls("\n".join(ordered))
        error.problems = tuple(ordered)
        return error

    def __str__(self) -> str:
        return "\n".join(self.problems)


#: The position a message starts with: ``FILE:LINE:COLUMN`` (the file may hold a colon, not ': ', which ends it).
_POSITION = re.compile(r"^(?P<file>(?:[^:\n]|:(?! ))*?):(?P<line>\d+):(?P<column>\d+)(?=:|$)")


def in_order(problems: Iterable[str]) -> list[str]:
    """``problems`` each once, ordered by where they are: by file (in the order the files first come), then line
    and column; those without a position (about a whole file, or read without positions) first, as they came."""
    unique = list(dict.fromkeys(problems))
    files: dict[str, int] = {}
    keys = []
    for problem in unique:
        match = _POSITION.match(problem)
        if match is None:
            keys.append((-1, 0, 0))
            continue
        file = files.setdefault(match["file"], len(files))
        keys.append((file, int(match["line"]), int(match["column"])))
    order = sorted(range(len(unique)), key=lambda i: keys[i])
    return [unique[i] for i in order]


class Collector:
    """The mistakes of one file, gathered while its checks go on: a check runs in ``with collector.check():``, and
    a ``Problems`` it raises is kept instead of stopping the others; the rest of that block (the checks that
    depend on the failed one) is skipped. ``raise_if_any`` then raises them all as ``error_type``."""

    def __init__(self) -> None:
        self.problems: list[str] = []

    @contextlib.contextmanager
    def check(self) -> Iterator[None]:
        try:
            yield
        except Problems as error:
            self.problems.extend(error.problems)

    def read(self, read: Callable[[], T], fallback: T) -> T:
        """``read()``; when it raises a ``Problems`` (kept), ``fallback``, for the checks that go on."""
        with self.check():
            return read()
        return fallback

    def add(self, *problems: str) -> None:
        self.problems.extend(problems)

    def __bool__(self) -> bool:
        return bool(self.problems)

    def raise_if_any(self, error_type: type[Problems]) -> None:
        if self.problems:
            raise error_type.of(self.problems)


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


def mapping(node: yaml.Node, what: str, twice: list[LocatedError] | None = None) -> Entries:
    """A mapping node's entries by key text; not a mapping, or a key given twice, is a ``LocatedError`` (with
    ``twice``, a key given twice is added to it instead and its first entry kept)."""
    if not isinstance(node, yaml.MappingNode):
        raise error(node, f"{what} must be a mapping")
    entries: Entries = {}
    for key, item in node.value:
        name = str(scalar(key))
        if name in entries:
            if twice is None:
                raise error(key, f"'{name}' is given twice")
            twice.append(error(key, f"'{name}' is given twice"))
            continue
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
