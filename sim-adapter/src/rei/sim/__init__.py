# SPDX-License-Identifier: EPL-2.0
"""Headless pybullet simulation of a generated test case: world, robot, lidar, odometry, animator, faults."""

from rei.sim.native_output import quiet_native_output

with quiet_native_output():
    import pybullet  # noqa: F401  (first import prints its build time from C; nobody needs it)

from rei.sim.animator import DriveMode
from rei.sim.faults import PRESETS, LaserFault, parse_fault
from rei.sim.simulation import Simulation
from rei.sim.state import ObjectState, RobotState, SimState

__all__ = [
    "PRESETS",
    "DriveMode",
    "LaserFault",
    "ObjectState",
    "RobotState",
    "SimState",
    "Simulation",
    "parse_fault",
]
