# SPDX-License-Identifier: EPL-2.0
"""What the verdicts need to know about the test case besides the signals, and the knobs of their semantics.

Read once from the run's monitor.json and world.json (docs/artifacts.md) and the mission_info RPC, so a
missing or ill-typed field is found in one place and reported by the verdict that needs it.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

from rei.evaluation.mission_info import MissionInfo


@dataclass(frozen=True, slots=True)
class VerdictSettings:
    """Semantics knobs (docs/evaluation.md, "Verdicts").

    ``tolerance``: seconds by which the laser may lag or lead the geometry and still count as the same event.
    The lidar scans at 10 Hz and the state is sampled at 20 Hz; the monitor's laser distance only reaches
    the collision threshold once the robot presses on (0.45 s after the geometric contact when the scripted
    robot rams the table at 0.26 m/s), so 1 s. Every episode is judged: the monitor's laser distance is the
    scan's per-beam distance to the footprint (rei.sim.clearance), so a corner that grazes CLOSE is seen too.
    ``laser``: the run published laser data (``--laser none`` runs: False, the laser verdicts do not apply).
    ``humans``: the humans of world.json are in the simulation (``--no-humans`` runs: False).
    ``mission``: the run recorded its mission (an imported bag without goals: False): then the mission's
    requirements on goals do not apply and the others are judged over the observed span, which has no END.
    """

    tolerance: float = 1.0
    laser: bool = True
    humans: bool = True
    mission: bool = True

    def __post_init__(self) -> None:
        if not self.tolerance >= 0:
            raise ValueError(f"tolerance must be >= 0 s, got {self.tolerance}")


@dataclass(frozen=True, slots=True)
class CaseContext:
    mission: MissionInfo | None
    humans: frozenset[str] = frozenset()
    #: N_COLLISION of Table 4 (monitor.json requirements.maxHumanCollisions); when None,
    #: ``n_collision_problem`` says why.
    n_collision: int | None = None
    n_collision_problem: str | None = None
    settings: VerdictSettings = field(default_factory=VerdictSettings)

    @classmethod
    def from_configs(cls, mission: MissionInfo | None, monitor_config: Mapping[str, Any] | None,
                     world: Mapping[str, Any] | None, settings: VerdictSettings | None = None) -> CaseContext:
        settings = settings or VerdictSettings()
        humans = frozenset(
            str(o.get("name")) for o in (world or {}).get("objects", []) or []
            if isinstance(o, Mapping) and o.get("category") == "HUMAN"
        ) if settings.humans else frozenset()
        n_collision, problem = _n_collision(monitor_config)
        return cls(mission, humans, n_collision, problem, settings)


def _n_collision(monitor_config: Mapping[str, Any] | None) -> tuple[int | None, str | None]:
    if monitor_config is None:
        return None, "no monitor.json was given: N_COLLISION (requirements.maxHumanCollisions) is unknown"
    requirements = monitor_config.get("requirements")
    value = requirements.get("maxHumanCollisions") if isinstance(requirements, Mapping) else None
    if isinstance(value, bool) or not isinstance(value, int) or value < 1:
        return None, (f"monitor.json requirements.maxHumanCollisions must be an integer >= 1 (N_COLLISION), "
                      f"got {value!r}")
    return value, None
