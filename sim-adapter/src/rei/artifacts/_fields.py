# SPDX-License-Identifier: EPL-2.0
"""Typed access to decoded JSON with errors that name the file and the path of the offending field.

The readers would otherwise be a thicket of ``isinstance`` checks; this keeps each reader a flat list of the fields
its format declares.
"""

from __future__ import annotations

import json
import math
from collections.abc import Iterator
from pathlib import Path
from typing import Any

from rei.artifacts.errors import ArtifactError


def load_json(path: Path, expected_format: str) -> Fields:
    """Read a JSON artifact and check its ``format`` field before anything else is looked at."""
    if not path.is_file():
        raise ArtifactError(path, "file is missing")
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except json.JSONDecodeError as exc:
        raise ArtifactError(
            path, f"not valid JSON: {exc.msg} at line {exc.lineno} column {exc.colno}"
        ) from None
    except UnicodeDecodeError as exc:
        raise ArtifactError(path, f"not UTF-8 text: {exc.reason}") from None
    root = Fields(path, "", data)
    if not isinstance(data, dict):
        raise ArtifactError(path, "top level must be a JSON object")
    found = root.text("format")
    if found != expected_format:
        raise ArtifactError(
            path, f"format: unknown format {found!r}, this reader understands {expected_format!r}"
        )
    return root


class Fields:
    """A JSON value together with the file and the path it was found at, for error messages."""

    __slots__ = ("path", "value", "where")

    def __init__(self, path: Path, where: str, value: Any) -> None:
        self.path = path
        self.where = where
        self.value = value

    def error(self, message: str, key: str | None = None) -> ArtifactError:
        where = self._child_where(key) if key is not None else self.where
        return ArtifactError(self.path, f"{where}: {message}" if where else message)

    def _child_where(self, key: str | int) -> str:
        if isinstance(key, int):
            return f"{self.where}[{key}]"
        return f"{self.where}.{key}" if self.where else key

    def _get(self, key: str) -> Any:
        if not isinstance(self.value, dict):
            raise self.error("expected an object")
        if key not in self.value:
            raise self.error("required field is missing", key)
        return self.value[key]

    def has(self, key: str) -> bool:
        return isinstance(self.value, dict) and key in self.value and self.value[key] is not None

    def child(self, key: str) -> Fields:
        value = self._get(key)
        if not isinstance(value, dict):
            raise self.error(f"expected an object, got {_kind(value)}", key)
        return Fields(self.path, self._child_where(key), value)

    def items(self, key: str) -> Iterator[Fields]:
        value = self._get(key)
        if not isinstance(value, list):
            raise self.error(f"expected a list, got {_kind(value)}", key)
        where = self._child_where(key)
        for i, item in enumerate(value):
            yield Fields(self.path, f"{where}[{i}]", item)

    def text(self, key: str) -> str:
        value = self._get(key)
        if not isinstance(value, str) or not value:
            raise self.error(f"expected a non-empty string, got {_kind(value)}", key)
        return value

    def optional_text(self, key: str) -> str | None:
        if not isinstance(self.value, dict) or self.value.get(key) is None:
            return None
        return self.text(key)

    def flag(self, key: str) -> bool:
        value = self._get(key)
        if not isinstance(value, bool):
            raise self.error(f"expected true or false, got {_kind(value)}", key)
        return value

    def integer(self, key: str) -> int:
        value = self._get(key)
        if isinstance(value, bool) or not isinstance(value, int):
            raise self.error(f"expected an integer, got {_kind(value)}", key)
        return value

    def number(self, key: str, *, positive: bool = False, non_negative: bool = False) -> float:
        return _number(self, key, self._get(key), positive=positive, non_negative=non_negative)

    def vector(self, key: str, length: int, *, non_negative: bool = False) -> tuple[float, ...]:
        value = self._get(key)
        if not isinstance(value, list) or len(value) != length:
            raise self.error(f"expected a list of {length} numbers, got {_kind(value)}", key)
        return tuple(_number(self, f"{key}[{i}]", v, non_negative=non_negative) for i, v in enumerate(value))


def _number(
    fields: Fields, key: str, value: Any, *, positive: bool = False, non_negative: bool = False
) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
        raise fields.error(f"expected a finite number, got {_kind(value)}", key)
    if positive and value <= 0:
        raise fields.error(f"must be > 0, got {value}", key)
    if non_negative and value < 0:
        raise fields.error(f"must be >= 0, got {value}", key)
    return float(value)


def _kind(value: Any) -> str:
    if value is None:
        return "null"
    if isinstance(value, list):
        return f"a list of {len(value)}"
    if isinstance(value, dict):
        return "an object"
    return f"{type(value).__name__} {value!r}"
