# SPDX-License-Identifier: EPL-2.0
"""The per-run navigation metrics: their names, units, kinds and which way is better (docs/metrics.md).

One table for ``summary.json``, the run report, ``runs.csv``, the campaign's aggregation and ``rei compare``, so
a metric is named and judged the same everywhere. The names are also the search's objectives: they do not change.
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import StrEnum


class Kind(StrEnum):
    BOOL = "bool"  # aggregated as a rate (Wilson interval), compared with McNemar's exact test
    COUNT = "count"  # integers, aggregated and compared like continuous values
    CONTINUOUS = "continuous"


class Better(StrEnum):
    HIGHER = "higher"
    LOWER = "lower"
    NEITHER = "neither"  # a description of the drive (speed): no direction is a regression by itself


@dataclass(frozen=True, slots=True)
class Metric:
    name: str
    unit: str
    kind: Kind
    better: Better
    label: str
    goal: bool = False  # needs a mission: None for a recording without one


METRICS: tuple[Metric, ...] = (
    Metric("success", "", Kind.BOOL, Better.HIGHER, "all goals reached", goal=True),
    Metric("time", "s", Kind.CONTINUOUS, Better.LOWER, "mission time", goal=True),
    Metric("path_length", "m", Kind.CONTINUOUS, Better.LOWER, "path length (true pose)"),
    Metric("spl", "", Kind.CONTINUOUS, Better.HIGHER, "success weighted by path length", goal=True),
    Metric("clearance_static_min", "m", Kind.CONTINUOUS, Better.HIGHER, "min. clearance, static"),
    Metric("clearance_static_mean_min", "m", Kind.CONTINUOUS, Better.HIGHER, "mean min. clearance, static"),
    Metric("clearance_humans_min", "m", Kind.CONTINUOUS, Better.HIGHER, "min. clearance, humans"),
    Metric("clearance_humans_mean_min", "m", Kind.CONTINUOUS, Better.HIGHER, "mean min. clearance, humans"),
    Metric("encounter_margin_humans", "s", Kind.CONTINUOUS, Better.HIGHER, "encounter margin, humans"),
    Metric("close_time", "s", Kind.CONTINUOUS, Better.LOWER, "time in CLOSE"),
    Metric("collision_time", "s", Kind.CONTINUOUS, Better.LOWER, "time in COLLISION"),
    Metric("collision_episodes", "", Kind.COUNT, Better.LOWER, "collision episodes"),
    Metric("collision_objects", "", Kind.COUNT, Better.LOWER, "objects collided with"),
    Metric("intimate_time", "s", Kind.CONTINUOUS, Better.LOWER, "time in a person's intimate space (< 0.45 m)"),
    Metric("intimate_share", "", Kind.CONTINUOUS, Better.LOWER, "share of the mission in intimate space"),
    Metric("personal_time", "s", Kind.CONTINUOUS, Better.LOWER, "time in a person's personal space (0.45-1.2 m)"),
    Metric("personal_share", "", Kind.CONTINUOUS, Better.LOWER, "share of the mission in personal space"),
    Metric("social_time", "s", Kind.CONTINUOUS, Better.NEITHER, "time in a person's social space (1.2-3.6 m)"),
    Metric("social_share", "", Kind.CONTINUOUS, Better.NEITHER, "share of the mission in social space"),
    Metric("ttc_humans_min", "s", Kind.CONTINUOUS, Better.HIGHER, "min. time to collision with a person"),
    Metric("collisions_robot_at_fault", "", Kind.COUNT, Better.LOWER, "collisions with people, robot at fault"),
    Metric("collisions_person_at_fault", "", Kind.COUNT, Better.LOWER, "collisions with people, person at fault"),
    Metric("path_irregularity_humans", "rad/m", Kind.CONTINUOUS, Better.LOWER, "people's path irregularity"),
    Metric("people_delay_mean", "s", Kind.CONTINUOUS, Better.LOWER, "people's mean delay by the robot"),
    Metric("people_delay_max", "s", Kind.CONTINUOUS, Better.LOWER, "people's largest delay by the robot"),
    Metric("people_detour_mean", "m", Kind.CONTINUOUS, Better.LOWER, "people's mean detour round the robot"),
    Metric("speed_mean", "m/s", Kind.CONTINUOUS, Better.NEITHER, "mean speed"),
    Metric("speed_peak", "m/s", Kind.CONTINUOUS, Better.NEITHER, "peak speed"),
    Metric("jerk_linear", "m²/s⁵", Kind.CONTINUOUS, Better.LOWER, "integrated squared linear jerk"),
    Metric("jerk_angular", "rad²/s⁵", Kind.CONTINUOUS, Better.LOWER, "integrated squared angular jerk"),
    Metric("rotation_in_place", "rad", Kind.CONTINUOUS, Better.LOWER, "rotation in place"),
    Metric("oscillations", "", Kind.COUNT, Better.LOWER, "back-and-forth reversals"),
    Metric("odom_drift", "m", Kind.CONTINUOUS, Better.LOWER, "max. odometry drift"),
)

BY_NAME: dict[str, Metric] = {m.name: m for m in METRICS}
NAMES: tuple[str, ...] = tuple(m.name for m in METRICS)
#: Keys of summary.json's ``metrics`` that are not one number per run (``task_times``: seconds per task).
LIST_KEYS: tuple[str, ...] = ("task_times",)
