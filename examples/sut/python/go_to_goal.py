# SPDX-License-Identifier: EPL-2.0
"""A small external system under test: turn towards the goal, drive, and wait while the laser sees something
close ahead (a person crossing). Written with REI's Python kit; see docs/sut.md.

    ./rei run examples/simple_navigation.rei -o out --sut "python3 examples/sut/python/go_to_goal.py"

It knows only what a real robot would: wheel odometry (in world coordinates: the mission's start pose at
tick 0, so it is comparable with goal poses) and the laser. No map, no planner: a room with furniture in the way needs more.
"""

from __future__ import annotations

import math

import numpy as np

from rei.geometry import Twist2D, wrap_angle
from rei.sut.api import NavGoal, NavStatus
from rei.sut.client import Session, SystemUnderTest, Tick, main

FRONT = math.radians(30)  # half-width of the sector watched for obstacles
STOP_AT = 0.35  # m from the lidar: stand still
SLOW_FROM = 0.6  # m: slow down linearly between here and STOP_AT
GIVE_UP_AFTER = 60.0  # s without getting 5 cm closer


class GoToGoal(SystemUnderTest):
    def on_start(self, session: Session) -> None:
        self.max_linear = session.robot["max_linear"]
        self.max_angular = session.robot["max_angular"]
        self.best, self.best_t = math.inf, 0.0

    def on_goal(self, goal: NavGoal) -> None:
        self.best, self.best_t = math.inf, -1.0

    def on_tick(self, tick: Tick) -> Twist2D:
        goal = self.goal
        if goal is None or self.status is not NavStatus.ACTIVE:
            return Twist2D()
        dx, dy = goal.pose.x - tick.odom.x, goal.pose.y - tick.odom.y
        distance = math.hypot(dx, dy)
        if distance < 0.6 * goal.tolerance:  # margin: odometry drifts a little from the true pose
            self.succeed(f"reached the goal by odometry ({distance:.2f} m)")
            return Twist2D()
        if self.best_t < 0 or distance < self.best - 0.05:
            self.best, self.best_t = distance, tick.t
        elif tick.t - self.best_t > GIVE_UP_AFTER:
            self.abort(f"no progress for {GIVE_UP_AFTER:g} s, {distance:.2f} m from the goal")
            return Twist2D()
        error = wrap_angle(math.atan2(dy, dx) - tick.odom.yaw)
        w = max(-self.max_angular, min(self.max_angular, 2.0 * error))
        if abs(error) > 0.5:
            return Twist2D(0.0, w)  # turn on the spot first
        v = min(self.max_linear, 0.5 * distance) * math.cos(error) * self.clearance(tick)
        self.feedback(f"{distance:.2f} m to go")
        return Twist2D(v, w)

    def clearance(self, tick: Tick) -> float:
        """1 with nothing close ahead, 0 when something is within STOP_AT."""
        scan = tick.scan
        if scan is None:
            return 0.0  # no scan yet: do not drive blind
        angles = scan.angle_min + scan.angle_increment * np.arange(len(scan.ranges))
        ahead = scan.ranges[np.abs(np.vectorize(wrap_angle)(angles)) <= FRONT]
        nearest = float(ahead.min()) if len(ahead) else math.inf
        return min(1.0, max(0.0, (nearest - STOP_AT) / (SLOW_FROM - STOP_AT)))


if __name__ == "__main__":
    main(GoToGoal())
