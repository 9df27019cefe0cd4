# SPDX-License-Identifier: EPL-2.0
"""Running a mission: the simulation loop that ties simulator, controller, mission executor and collector."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from rei.run.mission_run import MissionRunOptions, MissionRunResult, run_mission

_MISSION_RUN = ("MissionRunOptions", "MissionRunResult", "run_mission")


def __getattr__(name: str) -> Any:
    """The mission loop's names, imported on first use: it pulls in pybullet and numpy, which the package's other
    modules (the pipeline's supervisor, the JVM helpers) do not need."""
    if name not in _MISSION_RUN:
        raise AttributeError(f"module 'rei.run' has no attribute {name!r}")
    from rei.run import mission_run

    return getattr(mission_run, name)


__all__ = ["MissionRunOptions", "MissionRunResult", "run_mission"]
