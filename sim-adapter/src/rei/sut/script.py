# SPDX-License-Identifier: EPL-2.0
"""The ``script:FILE`` controller: a fixed timeline of velocity commands, no navigation at all.

It reproduces the thesis's simple scenarios (7.2), where the robot was driven through its low-level controller
(forwards and backwards for the translation scenario, in circles for the circular one) so that the monitor's
geometric events could be checked without a planner in the loop.

File format: plain text, one command per line, ``duration v w [vy]`` (seconds > 0, m/s, rad/s, and a sideways
m/s that only a holonomic robot follows; 0 when left out), whitespace separated; ``#`` starts a comment; blank
lines are ignored. Example, the translation then circle scenario::

    # forwards 2 s, back again, then one circle of radius 0.2 m
    2.0   0.2  0.0
    2.0  -0.2  0.0
    6.2832 0.2  1.0

The timeline starts at the first ``step`` after ``reset``; after its end the robot stands still and the status
is SUCCEEDED. Goals are accepted and ignored (the mission executor will judge where the robot actually is).
Commands are passed on unchanged: limiting them is the simulated robot's business.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

from rei.geometry import Pose2D, Twist2D
from rei.sut.api import Controller, NavGoal, NavStatus, Observation, StaticMap


class ScriptError(ValueError):
    """A script file is missing or malformed; the message names the file and line."""


@dataclass(frozen=True, slots=True)
class Segment:
    duration: float
    v: float
    w: float
    vy: float = 0.0


def parse_script(text: str, source: str = "<script>") -> tuple[Segment, ...]:
    """Segments of a script's text; ``source`` names it in errors."""
    segments = []
    for number, raw in enumerate(text.splitlines(), start=1):
        line = raw.split("#", 1)[0].strip()
        if not line:
            continue
        fields = line.split()
        if len(fields) not in (3, 4):
            raise ScriptError(f"{source}:{number}: expected 'duration v w [vy]', got {len(fields)} field(s): {line!r}")
        try:
            duration, v, w, *rest = (float(f) for f in fields)
        except ValueError:
            raise ScriptError(f"{source}:{number}: not a number in {line!r}") from None
        vy = rest[0] if rest else 0.0
        if not all(math.isfinite(x) for x in (duration, v, w, vy)):
            raise ScriptError(f"{source}:{number}: values must be finite: {line!r}")
        if duration <= 0:
            raise ScriptError(f"{source}:{number}: duration must be > 0, got {fields[0]}")
        segments.append(Segment(duration, v, w, vy))
    if not segments:
        raise ScriptError(f"{source}: the script has no commands")
    return tuple(segments)


def load_script(path: Path | str) -> tuple[Segment, ...]:
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as exc:
        raise ScriptError(f"{path}: cannot read the script: {exc.strerror or exc}") from None
    return parse_script(text, str(path))


class ScriptController(Controller):
    """Plays a command timeline; SUCCEEDED once it has played, CANCELLED (and still) after ``cancel``."""

    def __init__(self, segments: tuple[Segment, ...] | list[Segment]) -> None:
        if not segments:
            raise ScriptError("a script needs at least one command")
        self.segments = tuple(segments)
        self.ends = []
        total = 0.0
        for segment in self.segments:
            total += segment.duration
            self.ends.append(total)
        self._t0: float | None = None
        self._status = NavStatus.IDLE
        self._text = ""

    @classmethod
    def from_file(cls, path: Path | str) -> ScriptController:
        return cls(load_script(path))

    @property
    def duration(self) -> float:
        return self.ends[-1]

    @property
    def status(self) -> NavStatus:
        return self._status

    @property
    def status_text(self) -> str:
        return self._text

    def reset(self, static_map: StaticMap, start: Pose2D) -> None:
        self._t0 = None
        self._status, self._text = NavStatus.ACTIVE, "playing the script"

    def set_goal(self, goal: NavGoal) -> None:
        """Goals do not steer a script; the status stays what the timeline makes it."""

    def cancel(self) -> None:
        if self._status is NavStatus.ACTIVE:
            self._status, self._text = NavStatus.CANCELLED, "cancelled by the client"

    def step(self, observation: Observation) -> Twist2D:
        if self._status is not NavStatus.ACTIVE:
            return Twist2D()
        if self._t0 is None:
            self._t0 = observation.t
        elapsed = observation.t - self._t0
        for end, segment in zip(self.ends, self.segments, strict=True):
            if elapsed < end - 1e-9:
                return Twist2D(segment.v, segment.w, segment.vy)
        self._status, self._text = NavStatus.SUCCEEDED, f"script finished after {self.duration:g} s"
        return Twist2D()
