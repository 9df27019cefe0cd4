# SPDX-License-Identifier: EPL-2.0
"""The URIs of one run (wire protocol, docs/protocol.md): one place that spells them, checked once."""

from __future__ import annotations

import re
from dataclasses import dataclass

#: Run ids become one URI component; Crossbar's (loose) URI rules forbid dots, '#' and whitespace there
#: (contract/vocabulary.json, as every fact below).
RUN_ID_PATTERN = r"[A-Za-z0-9_-]{1,64}"
_RUN_ID = re.compile(RUN_ID_PATTERN)
#: A run's URIs; ``name`` is one of TOPIC_NAMES, or ``sut.<name>`` for the external SUT's (rei.sut.external).
TOPIC_TEMPLATE = "rei.run.{run_id}.{name}"
TOPIC_NAMES = ("state", "mission", "mission_info", "signal", "config", "snapshot")


@dataclass(frozen=True, slots=True)
class Topics:
    """Topic and procedure URIs of run ``run_id`` (``rei.run.<run_id>.<name>``)."""

    run_id: str

    def __post_init__(self) -> None:
        if not _RUN_ID.fullmatch(self.run_id):
            raise ValueError(f"run id {self.run_id!r} must be 1-64 characters of [A-Za-z0-9_-]")

    def _uri(self, name: str) -> str:
        return TOPIC_TEMPLATE.format(run_id=self.run_id, name=name)

    @property
    def state(self) -> str:
        return self._uri("state")

    @property
    def mission(self) -> str:
        return self._uri("mission")

    @property
    def signal(self) -> str:
        return self._uri("signal")

    @property
    def config(self) -> str:
        return self._uri("config")

    @property
    def mission_info(self) -> str:
        return self._uri("mission_info")

    @property
    def snapshot(self) -> str:
        return self._uri("snapshot")

    def as_dict(self) -> dict[str, str]:
        """Keys as in monitor.json's ``topics`` (camelCase), values resolved for this run."""
        return {
            "state": self.state,
            "mission": self.mission,
            "signal": self.signal,
            "config": self.config,
            "missionInfo": self.mission_info,
            "snapshot": self.snapshot,
        }
