# SPDX-License-Identifier: EPL-2.0
"""Running a mission: the simulation loop that ties simulator, controller, mission executor and collector."""

from rei.run.mission_run import MissionRunOptions, MissionRunResult, run_mission

__all__ = ["MissionRunOptions", "MissionRunResult", "run_mission"]
