# SPDX-License-Identifier: EPL-2.0
"""Cost of one control step of the reference ``nav`` controller, with a 360-beam scan.

The simulation must run >= 20x real time on one core with control at 10-20 Hz, so a nav step has to stay well
under 5 ms. This drives the controller through an L-shaped room with a table and a walking human in the
kinematic fake of the unit tests (``sim-adapter/tests/sut/kinematic.py``) and measures the CPU time
(``process_time``, robust to a loaded machine) of ``step()`` only; the first
step of each goal (global plan) and steps that replanned are reported separately.

Run: ``.venv/bin/python benchmarks/nav_step.py [repetitions]``
"""

from __future__ import annotations

import math
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "sim-adapter" / "tests"))

from sut.kinematic import Disc, KinematicWorld, room, shuttle

from rei.geometry import Pose2D
from rei.sut.api import NavGoal, NavStatus
from rei.sut.nav import NavController


def main() -> None:
    repetitions = int(sys.argv[1]) if len(sys.argv) > 1 else 3
    cells = [(i, j) for i in range(6) for j in range(2)] + [(i, j) for i in (4, 5) for j in range(2, 6)]
    static_map = room(cells, inner_walls=[((4, 1), (4, 2))], furniture=[(2.5, 1.0, 0.3, 0.8, 0.6)])
    goals = [Pose2D(4.5, 5.5), Pose2D(0.5, 0.5)]
    steps: list[float] = []
    plans: list[float] = []
    replans: list[float] = []
    resets: list[float] = []
    for _ in range(repetitions):
        world = KinematicWorld(
            static_map, Pose2D(0.5, 0.5, 0.0), discs=[Disc(0.25, shuttle((3.5, 0.4), (3.5, 1.6), 0.3))]
        )
        nav = NavController()
        t0 = time.process_time()
        nav.reset(static_map, world.pose)
        resets.append(time.process_time() - t0)
        for index, goal in enumerate(goals):
            nav.set_goal(NavGoal(index, goal, 0.25))
            first = True
            while nav.status is NavStatus.ACTIVE and world.t < 200.0:
                obs = world.observation()
                before = nav.replans
                t0 = time.process_time()
                cmd = nav.step(obs)
                elapsed = time.process_time() - t0
                (plans if first else replans if nav.replans != before else steps).append(elapsed)
                first = False
                world.apply(cmd)
            print(f"goal {index}: {nav.status.value} at t={world.t:.1f} s {nav.status_text}")
    ms = np.array(steps) * 1e3
    print(
        f"nav step (360 beams): n={len(ms)} mean={ms.mean():.3f} ms p50={np.percentile(ms, 50):.3f} ms "
        f"p99={np.percentile(ms, 99):.3f} ms max={ms.max():.3f} ms"
    )
    if replans:
        print(f"steps that replanned: n={len(replans)} mean={np.mean(replans) * 1e3:.2f} ms")
    print(
        f"first step incl. global plan: mean={np.mean(plans) * 1e3:.2f} ms max={np.max(plans) * 1e3:.2f} ms"
    )
    print(
        f"reset (cost grid {math.ceil(6.6 / 0.05)}x{math.ceil(6.6 / 0.05)}): mean={np.mean(resets) * 1e3:.2f} ms"
    )


if __name__ == "__main__":
    main()
