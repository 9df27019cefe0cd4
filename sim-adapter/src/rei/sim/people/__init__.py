# SPDX-License-Identifier: EPL-2.0
"""Reactive people: a pedestrian-dynamics model (JuPedSim, in a process of its own) moves the people who see the
robot, in lockstep with the physics (docs/people.md)."""

from rei.sim.people.crowd import DT, Crowd, Mover, footprint_radius
from rei.sim.people.server import PeopleError, PeopleServer
from rei.sim.people.walkers import RobotView, Walker

__all__ = ["DT", "Crowd", "Mover", "PeopleError", "PeopleServer", "RobotView", "Walker", "footprint_radius"]
