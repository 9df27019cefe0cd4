# SPDX-License-Identifier: EPL-2.0
"""What the robot cost the people (docs/metrics.md, People): the run without the robot is the same people walking
the same model, so a robot that is in nobody's way costs nobody anything."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from rei.geometry import Twist2D
from rei.sim.people.cost import people_cost
from rei.sim.simulation import Simulation

STILL = Twist2D(0.0, 0.0)


def test_a_robot_far_from_everyone_costs_nothing_though_some_ignore_it(run_cli, write_rei: Callable[[str, str], Path],
                                                                      tmp_path: Path) -> None:
    # ann ignores the robot and bob sees it: they cross each other 8 m from a robot that stands in a corner. The run
    # with the robot walks two models (one with the robot, one without), the run without it walked one, where people
    # meet each other a step sooner than as puppets: ann's detour was 0.052 m for a robot 8 m away (in a crowd with
    # more people who ignore it, delays of -0.3 to 0.05 s)
    source = write_rei("far.rei", """
testcase Far {
  room Hall size 12 x 8 {
    human ann route [F_0_2, F_6_2] speed 1.2 loop ignores
    human bob route [F_3_0, F_3_5] speed 1.1 loop avoids
    robot tb3 : Waffle on F_11_7
  }
  mission Go { goto F_11_6 goto F_10_7 }
  monitor { close 0.25 collision 0.01 }
}
""")
    folder = tmp_path / "case"
    result = run_cli("generate", source, "-o", folder)
    assert result.returncode == 0, result.stderr
    with Simulation(folder, seed=1) as sim:
        for _ in range(round(14.0 * sim.physics_rate)):
            sim.step(STILL)
        assert sim.crowd is not None
        cost = people_cost(sim.crowd, sim.t)
    for name in ("ann", "bob"):
        assert len(cost[name]["arrivals"]) >= 2, cost[name]
        assert cost[name]["arrivals"] == cost[name]["arrivals_without_robot"], (name, cost[name])
        assert (cost[name]["delay"], cost[name]["detour"], cost[name]["censored"]) == (0.0, 0.0, False)
