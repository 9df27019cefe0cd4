# SPDX-License-Identifier: EPL-2.0
"""Give-up rules: the navigation cancels a goal when the robot only oscillates or stops making progress.

The thesis's robot controller "cancel[s] a task if the robot is only oscillating back and forth" (7.4.4), which
is what bounds the duration of blocked runs. Two watchdogs, both on simulation time:

- oscillation: the robot has not moved ``oscillation_distance`` away from where it was ``oscillation_timeout``
  seconds ago (waiting, turning on the spot, rocking back and forth);
- no progress: the remaining path length has not dropped by ``progress_distance`` for ``no_progress_timeout``
  seconds (driving around without getting closer). A replan restarts the reference length (a detour is
  longer) but not the clock, so replanning in circles still ends.
"""

from __future__ import annotations

import math

from rei.sut.nav.config import NavConfig


class ProgressMonitor:
    def __init__(self, config: NavConfig) -> None:
        self.config = config
        self._anchor: tuple[float, float] | None = None
        self._anchor_t = 0.0
        self._best = math.inf
        self._progress_t = 0.0

    def start(self, t: float, x: float, y: float, remaining: float) -> None:
        self._anchor, self._anchor_t = (x, y), t
        self._best, self._progress_t = remaining, t

    def replanned(self, remaining: float) -> None:
        self._best = remaining

    def update(self, t: float, x: float, y: float, remaining: float) -> str | None:
        """The reason to give up, or ``None`` while the robot is still getting somewhere."""
        cfg = self.config
        if self._anchor is None:
            self.start(t, x, y, remaining)
            return None
        if math.hypot(x - self._anchor[0], y - self._anchor[1]) > cfg.oscillation_distance:
            self._anchor, self._anchor_t = (x, y), t
        if remaining < self._best - cfg.progress_distance:
            self._best, self._progress_t = remaining, t
        if t - self._anchor_t > cfg.oscillation_timeout:
            return (
                f"oscillating: moved less than {cfg.oscillation_distance:.2f} m in "
                f"{cfg.oscillation_timeout:.1f} s"
            )
        if t - self._progress_t > cfg.no_progress_timeout:
            return f"no progress towards the goal for {cfg.no_progress_timeout:.1f} s"
        return None
