# SPDX-License-Identifier: EPL-2.0
"""The evaluator (thesis 5.2, 6.1.5): utilities per signal, the event log, Table 4 verdicts, the summary.

Semantics and file formats: docs/evaluation.md. Typical use (``rei run``)::

    declared = load_declared(out / "utilities.json")  # what the monitor's patterns declare of their signals
    evaluator = Evaluator(out, utilities=load_utilities(path, declared.utilities),
                          transitions=declared.transitions, mission_info=None,
                          monitor_config=monitor_json, world=world_json)
    attach(client, run_id, evaluator)              # live; or replay(signals, evaluator) offline
    ...                                            # evaluator.total for progress
    summary = evaluator.finish(status="COMPLETED", reason=None, sim_duration=t, wall_time=w, run_id=run_id)
"""

from rei.evaluation.context import VerdictSettings
from rei.evaluation.evaluator import EVENTS_FILE, SUMMARY_FILE, VERDICTS_FILE, Evaluator
from rei.evaluation.live import Attachment, attach, replay
from rei.evaluation.log import COLUMNS, EventLog
from rei.evaluation.mission_info import MissionInfo, MissionInfoError
from rei.evaluation.outcome import Evidence, Status, Verdict
from rei.evaluation.signals import KNOWN_SIGNALS, Signal, SignalError
from rei.evaluation.summary import Summary, TaskRecord
from rei.evaluation.utilities import (
    DEFAULT_UTILITIES,
    Declared,
    UtilityError,
    UtilityTable,
    default_utilities,
    load_declared,
    load_declared_transitions,
    load_declared_utilities,
    load_utilities,
)
from rei.evaluation.verdicts import REQUIREMENTS, judge

__all__ = [
    "COLUMNS",
    "DEFAULT_UTILITIES",
    "EVENTS_FILE",
    "KNOWN_SIGNALS",
    "REQUIREMENTS",
    "SUMMARY_FILE",
    "VERDICTS_FILE",
    "Attachment",
    "Declared",
    "Evaluator",
    "EventLog",
    "Evidence",
    "MissionInfo",
    "MissionInfoError",
    "Signal",
    "SignalError",
    "Status",
    "Summary",
    "TaskRecord",
    "UtilityError",
    "UtilityTable",
    "Verdict",
    "VerdictSettings",
    "attach",
    "default_utilities",
    "judge",
    "load_declared",
    "load_declared_transitions",
    "load_declared_utilities",
    "load_utilities",
    "replay",
]
