# SPDX-License-Identifier: EPL-2.0
"""A requirement's verdict and the evidence that decided it.

Why evidence is structured (time, signal, object, task) and not only a sentence: a report links it to the
event log and the recorded streams, and tests assert on it without parsing prose.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass
from typing import Any


class Status(enum.StrEnum):
    """``pass`` / ``fail`` (a violation was observed) / ``error`` (the run can not decide it: data missing,
    run incomplete) / ``not-applicable`` (the requirement does not concern this mission)."""

    PASS = "pass"
    FAIL = "fail"
    ERROR = "error"
    NOT_APPLICABLE = "not-applicable"


@dataclass(frozen=True, slots=True)
class Evidence:
    """One fact behind a verdict; ``text`` is a complete sentence, the other fields are its coordinates."""

    text: str
    t: float | None = None
    signal: str | None = None
    object: str | None = None
    task: int | None = None

    def to_dict(self) -> dict[str, Any]:
        fields = {"text": self.text, "t": self.t, "signal": self.signal, "object": self.object,
                  "task": self.task}
        return {key: value for key, value in fields.items() if value is not None}

    def line(self) -> str:
        """One line for the JUnit body: ``t=7.350 SIG_... table1 task=0: text``."""
        parts = []
        if self.t is not None:
            parts.append(f"t={self.t:.3f}")
        parts.extend(value for value in (self.signal, self.object) if value is not None)
        if self.task is not None:
            parts.append(f"task={self.task}")
        return f"{' '.join(parts)}: {self.text}" if parts else self.text


@dataclass(frozen=True, slots=True)
class Verdict:
    requirement: str
    status: Status
    message: str
    evidence: tuple[Evidence, ...] = ()

    def to_dict(self) -> dict[str, Any]:
        return {"requirement": self.requirement, "status": str(self.status), "message": self.message,
                "evidence": [e.to_dict() for e in self.evidence]}
