# SPDX-License-Identifier: EPL-2.0
"""Mission execution (thesis 4.3): feed the mission's goals to the controller and report task events.

The mission itself is read by ``rei.artifacts.mission``.
"""

from rei.mission.executor import MissionEvent, MissionEventKind, MissionExecutor, TaskResult, mission_info

__all__ = ["MissionEvent", "MissionEventKind", "MissionExecutor", "TaskResult", "mission_info"]
