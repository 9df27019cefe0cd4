# SPDX-License-Identifier: EPL-2.0
"""How a run reaches its external SUT (``--sut``, ``--sut-attach`` and the other ``--sut-*`` options).

Kept free of the WAMP client and numpy, so the command line can check the options without importing either.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Literal

from rei.sut.external.process import split_command

Clock = Literal["lockstep", "realtime"]
DEFAULT_DEADLINE = 10.0
DEFAULT_JOIN_TIMEOUT = 60.0


@dataclass(frozen=True, slots=True)
class SutOptions:
    """How the run reaches its SUT: ``command`` to start, or ``attach`` to wait for one (exactly one)."""

    command: str | None = None
    attach: bool = False
    clock: Clock = "lockstep"
    deadline: float = DEFAULT_DEADLINE
    offer_map: bool = False
    join_timeout: float = DEFAULT_JOIN_TIMEOUT
    router_url: str | None = None  # what the SUT connects to (default: the simulation's own URL)
    auth_file: Path | None = None  # the sut role's credentials (None on an anonymous router)
    cwd: Path | None = None  # where the command runs (default: the current folder; a campaign: its spec's)

    def __post_init__(self) -> None:
        if (self.command is None) == (not self.attach):
            raise ValueError("an external SUT is either started (--sut COMMAND) or attached (--sut-attach)")
        if self.clock not in ("lockstep", "realtime"):
            raise ValueError(f"--sut-clock must be lockstep or realtime, got {self.clock!r}")
        for name, value in (("--sut-deadline", self.deadline), ("--sut-join-timeout", self.join_timeout)):
            if not value > 0:
                raise ValueError(f"{name} must be a number of seconds > 0, got {value}")
        if self.command is not None:
            split_command(self.command)
