# SPDX-License-Identifier: EPL-2.0
"""What the fault stream tests share: a controller blind to its sensors, so that a run with a fault and the run
without it are commanded alike and differ by what the fault did only."""

from __future__ import annotations

from collections.abc import Callable

from rei.geometry import Pose2D, Twist2D
from rei.sut.api import Controller, NavGoal, NavStatus, Observation, StaticMap


class Blind(Controller):
    """Commands ``plan(k)`` at control tick ``k`` of ``rate`` Hz (``applied`` may rewrite it, as a fault would);
    gives up on every goal from ``end`` s on (a short run)."""

    def __init__(self, plan: Callable[[int], Twist2D], applied: Callable[[int, Twist2D], Twist2D] | None = None,
                 *, rate: float, end: float) -> None:
        self._plan, self._applied = plan, applied
        self._rate, self._end = rate, end
        self._status = NavStatus.IDLE

    def reset(self, static_map: StaticMap, start: Pose2D) -> None:
        pass

    def set_goal(self, goal: NavGoal) -> None:
        self._status = NavStatus.ACTIVE

    def cancel(self) -> None:
        self._status = NavStatus.CANCELLED

    def step(self, observation: Observation) -> Twist2D:
        if observation.t >= self._end:
            self._status = NavStatus.ABORTED
        k = round(observation.t * self._rate)
        command = self._plan(k)
        return command if self._applied is None else self._applied(k, command)

    @property
    def status(self) -> NavStatus:
        return self._status
