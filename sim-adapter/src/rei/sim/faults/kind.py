# SPDX-License-Identifier: EPL-2.0
"""What every fault kind shares (rei.sim.faults.laser, rei.sim.faults.motion): its name, whether it draws, its
sentence in reports and events, and the checks of its numbers, so that each kind states only its own."""

from __future__ import annotations

import math
from dataclasses import dataclass, fields
from typing import ClassVar


@dataclass(frozen=True, slots=True)
class Kind:
    """A fault kind: its name in specs and events (``kind``), whether it draws random numbers (``draws``: it gets a
    generator of its own, rei.sim.faults.schedule) and how it reads (``text``, formatted with its fields)."""

    kind: ClassVar[str]
    draws: ClassVar[bool] = False
    text: ClassVar[str] = ""

    def describe(self) -> str:
        return self.text.format_map({field.name: getattr(self, field.name) for field in fields(self)})


def within(value: float, what: str, low: float, high: float = math.inf, *, closed: bool = False,
           unit: str = "") -> None:
    """Raise a ``ValueError`` saying what ``value`` must be unless it is a finite number in ``(low, high]``
    (``[low, high]`` when ``closed``)."""
    if math.isfinite(value) and (low <= value if closed else low < value) and value <= high:
        return
    unit = f" {unit}" if unit else ""
    bound = (f"{'>=' if closed else '>'} {low:g}{unit}" if math.isinf(high)
             else f"in {'[' if closed else '('}{low:g}, {high:g}]{unit}")
    raise ValueError(f"{what} must be {bound}, got {value:g}")


def finite(value: float, what: str, unit: str = "") -> None:
    if not math.isfinite(value):
        raise ValueError(f"{what} must be a finite number{' ' + unit if unit else ''}, got {value}")


def number(text: str, what: str) -> float:
    """A finite number written as ``text`` (a spec's value); a ``ValueError`` naming ``what`` otherwise."""
    try:
        value = float(text)
    except ValueError:
        raise ValueError(f"{what} {text!r} is not a number") from None
    if not math.isfinite(value):
        raise ValueError(f"{what} {text!r} is not a finite number")
    return value


def seconds(text: str, what: str) -> float:
    """A time written as ``5`` or ``5s`` (a spec's value); a ``ValueError`` quoting ``text`` as it was written (not
    without its ``s``: ``5ms`` read as ``'5m' is not a number``)."""
    try:
        return number(text.removesuffix("s"), what)
    except ValueError:
        raise ValueError(f"{what} {text!r} is not a finite number of seconds") from None
