# SPDX-License-Identifier: EPL-2.0
"""Faults on a timeline (issue #39): a schedule of faults, each a kind of one sensor and when it acts.

* :mod:`rei.sim.faults.timing`: windows, pulse trains, ramps;
* :mod:`rei.sim.faults.kind`: what every kind shares (its name, sentence and number checks);
* :mod:`rei.sim.faults.impulse`: the thesis's Poisson impulse noise and the run-long ``--fault laser:...``;
* :mod:`rei.sim.faults.laser`: the laser's kinds and what each does to a scan;
* :mod:`rei.sim.faults.motion`: the odometry's, drive's, commands' and pose's kinds;
* :mod:`rei.sim.faults.schedule`: the schedule, its seeds, the scan pipeline and the window edges (events);
* :mod:`rei.sim.faults.spec`: ``--fault`` specs and mission.xml's ``<fault>`` keys.
"""

from rei.sim.faults.impulse import PRESETS, LaserFault, LaserFaultInjector, parse_fault
from rei.sim.faults.motion import CommandFaults, MotionFaults
from rei.sim.faults.schedule import (
    EDGES,
    SENSORS,
    Fault,
    FaultClock,
    FaultEdge,
    FaultSchedule,
    LaserFaults,
    event_name,
    fault_generators,
)
from rei.sim.faults.spec import (
    KIND_KEYS,
    SENSOR_KIND_KEYS,
    as_schedule,
    fault_fields,
    fault_from_fields,
    format_fault,
    parse_faults,
)
from rei.sim.faults.timing import Ramp, Timing

__all__ = [
    "EDGES",
    "KIND_KEYS",
    "PRESETS",
    "SENSORS",
    "SENSOR_KIND_KEYS",
    "CommandFaults",
    "Fault",
    "FaultClock",
    "FaultEdge",
    "FaultSchedule",
    "LaserFault",
    "LaserFaultInjector",
    "LaserFaults",
    "MotionFaults",
    "Ramp",
    "Timing",
    "as_schedule",
    "event_name",
    "fault_fields",
    "fault_from_fields",
    "fault_generators",
    "format_fault",
    "parse_fault",
    "parse_faults",
]
