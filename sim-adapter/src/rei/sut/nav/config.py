# SPDX-License-Identifier: EPL-2.0
"""Parameters of the reference navigation stack, with the TurtleBot3 Waffle as the default robot.

They are one flat dataclass so that a test case can tune them from the command line
(``nav:max_linear=0.2,no_progress_timeout=20``) the way ROS users tune ``move_base`` parameters.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass


@dataclass(frozen=True, slots=True)
class NavConfig:
    """Everything the planners need besides the map; lengths in metres, times in seconds."""

    # Robot (TurtleBot3 Waffle: footprint 0.281 x 0.306 m, 0.26 m/s, 1.82 rad/s).
    max_linear: float = 0.26
    max_angular: float = 1.82
    acc_linear: float = 2.5
    acc_angular: float = 3.2
    footprint_x: float = 0.281
    footprint_y: float = 0.306
    # A robot read from its description: its outline's circumscribed and inscribed radii about its origin
    # (rei.sut.api.StaticMap.robot_radii); 0: the footprint_x x footprint_y box's, centred on the origin.
    outline_circumscribed: float = 0.0
    outline_inscribed: float = 0.0
    # The drive takes a sideways speed: the controller strafes towards its path instead of turning first.
    holonomic: bool = False

    # Global planner: occupancy grid, inflation, cost gradient that keeps paths away from obstacles.
    resolution: float = 0.05
    inflation_margin: float = 0.03
    cost_decay: float = 0.35
    cost_scale: float = 8.0

    # Local planner (DWA).
    sim_time: float = 1.8
    sim_step: float = 0.2
    v_samples: int = 6
    w_samples: int = 15
    lookahead: float = 0.8
    min_clearance: float = 0.02
    dynamic_clearance: float = 0.15
    moving_horizon: float = 5.0
    preferred_clearance: float = 0.25
    w_carrot: float = 1.0
    w_path: float = 0.5
    w_heading: float = 0.4
    w_clearance: float = 0.6
    w_speed: float = 0.25
    rotate_threshold: float = 0.9
    turn_reaction_time: float = 0.3
    use_static_clearance: bool = True

    # Localization: correct the odometry's drift by matching scans to the static map; laser points farther than
    # the gate from the map's outlines are not matched (people, unmapped objects).
    localize: bool = True
    match_gate: float = 0.2

    # Goal: reached when the odometry is this close to the goal (never more than 30 % of the mission tolerance).
    xy_goal_tolerance: float = 0.10

    # Replanning and recovery.
    max_path_deviation: float = 0.5
    replan_after_blocked: float = 1.0
    recovery_after_blocked: float = 4.0
    backup_distance: float = 0.15

    # Sensor loss: stand while the latest scan has no return at all (a lidar gone dark, docs/faults.md) instead
    # of taking it for free space; off by default, as the reference navigation always drove on.
    stop_when_blind: bool = False

    # Cancellation (thesis 7.4.4): abort when the robot only oscillates or makes no progress.
    oscillation_distance: float = 0.3
    oscillation_timeout: float = 20.0
    progress_distance: float = 0.1
    no_progress_timeout: float = 30.0

    @property
    def circumscribed_radius(self) -> float:
        if self.outline_circumscribed > 0:
            return self.outline_circumscribed
        return 0.5 * math.hypot(self.footprint_x, self.footprint_y)

    @property
    def inscribed_radius(self) -> float:
        if self.outline_circumscribed > 0:
            return self.outline_inscribed
        return 0.5 * min(self.footprint_x, self.footprint_y)

    @property
    def inflation_radius(self) -> float:
        """Distance from obstacles within which the robot's centre may not be planned."""
        return self.circumscribed_radius + self.inflation_margin

    def __post_init__(self) -> None:
        for field in dataclasses.fields(self):
            value = getattr(self, field.name)
            if isinstance(value, bool):
                continue
            if not math.isfinite(value) or value < 0:
                raise ValueError(f"nav parameter {field.name} must be a finite number >= 0, got {value}")
        for name in ("max_linear", "max_angular", "acc_linear", "acc_angular", "resolution", "sim_time",
                     "sim_step", "lookahead"):
            if getattr(self, name) <= 0:
                raise ValueError(f"nav parameter {name} must be > 0, got {getattr(self, name)}")
        if self.v_samples < 2 or self.w_samples < 3:
            raise ValueError("nav parameters v_samples >= 2 and w_samples >= 3 are required")

    @classmethod
    def parse(cls, text: str) -> NavConfig:
        """Build from ``key=value,key=value`` (the argument of ``nav:``); unknown keys are an error."""
        known = {f.name: f for f in dataclasses.fields(cls)}
        values: dict[str, object] = {}
        for item in filter(None, (part.strip() for part in text.split(","))):
            key, sep, raw = item.partition("=")
            key = key.strip()
            if not sep or key not in known:
                raise ValueError(
                    f"nav parameter {item!r}: expected key=value with key one of {', '.join(sorted(known))}"
                )
            kind = known[key].type
            try:
                if kind in (bool, "bool"):
                    if raw.strip().lower() not in ("true", "false", "1", "0"):
                        raise ValueError(raw)
                    values[key] = raw.strip().lower() in ("true", "1")
                elif kind in (int, "int"):
                    values[key] = int(raw)
                else:
                    values[key] = float(raw)
            except ValueError:
                raise ValueError(f"nav parameter {key}: {raw.strip()!r} is not a valid {kind}") from None
        return cls(**values)  # type: ignore[arg-type]
