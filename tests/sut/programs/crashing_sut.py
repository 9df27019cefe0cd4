# SPDX-License-Identifier: EPL-2.0
"""A SUT that drives forward for 20 ticks and then dies with exit code 3 (a crashing navigation stack)."""

import sys

from rei.geometry import Twist2D
from rei.sut.client import SystemUnderTest, Tick, main


class Crashing(SystemUnderTest):
    def on_tick(self, tick: Tick) -> Twist2D:
        if tick.tick == 20:
            print("segmentation fault in the planner (simulated)", file=sys.stderr, flush=True)
            sys.exit(3)
        return Twist2D(0.1, 0.0)


main(Crashing())
