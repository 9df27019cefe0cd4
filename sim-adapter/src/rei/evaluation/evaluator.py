# SPDX-License-Identifier: EPL-2.0
"""The evaluator (thesis 5.2, 6.1.5): scores each signal, logs it, and judges the mission at its end.

Feeding and reading happen on different threads: the WAMP client calls ``on_signal`` / ``on_mission`` on its
loop thread while the main thread reads ``total`` / ``utility_over_time`` for a progress display and finally
calls ``finish``. Every public method takes one lock; a handler does O(1) work plus one CSV row (written and
flushed), so it never holds the loop up. Properties return copies, never live containers. After ``finish``
further signals are counted (``late_signals``) and otherwise ignored: the summary is final.

Bad input never raises from a handler (it would be lost in the WAMP client's log): a malformed signal or a
``seq`` repeated with other content is recorded as a stream problem, which turns the verdicts into errors.

Signals are kept by ``seq``, so a stream interrupted by a router restart can be completed afterwards: a signal
that arrives late fills its hole (``reconcile`` feeds the monitor's own signal file), an identical repeat (a
republish after a reconnection) is ignored, and only the holes still open at ``finish`` count as lost. When
holes were filled, events.csv is rewritten in ``seq`` order at the end.
"""

from __future__ import annotations

import math
import os
import threading
from collections import Counter
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

from rei.evaluation.context import CaseContext, VerdictSettings
from rei.evaluation.faults import fault_windows, run_schedule
from rei.evaluation.junit import write_junit
from rei.evaluation.log import EventLog, format_number
from rei.evaluation.metrics import LIST_KEYS, NAMES, Measured, MetricsError, measure
from rei.evaluation.mission_info import MissionInfo, MissionInfoError
from rei.evaluation.outcome import Evidence
from rei.evaluation.signals import (
    DEFAULT_TRANSITIONS,
    SIG_MISSION_END,
    SIG_MISSION_TASK_FAIL,
    SIG_MISSION_TASK_START,
    SIG_MISSION_TASK_SUCCESS,
    Signal,
    SignalError,
    Transition,
)
from rei.evaluation.summary import Summary, TaskRecord
from rei.evaluation.trace import Trace
from rei.evaluation.utilities import UtilityTable, default_utilities
from rei.evaluation.verdicts import judge

EVENTS_FILE = "events.csv"
SUMMARY_FILE = "summary.json"
VERDICTS_FILE = "verdicts.xml"
#: Stream problems kept as evidence (all are counted); a broken stream must not grow memory without bound.
_MAX_PROBLEMS = 100
RUN_STATUSES = ("COMPLETED", "ERROR")


class Evaluator:
    """Evaluation of one run into ``out_dir`` (events.csv at once; summary.json and verdicts.xml at finish).

    ``mission_info``: the mission_info RPC's result (None: set later by ``set_mission_info``, e.g. by
    ``rei.evaluation.attach``); ``monitor_config`` / ``world``: the run's monitor.json and world.json content.
    """

    def __init__(self, out_dir: str | os.PathLike[str], *, utilities: Mapping[str, float] | None = None,
                 transitions: Mapping[str, Transition] | None = None,
                 mission_info: Mapping[str, Any] | MissionInfo | None = None,
                 monitor_config: Mapping[str, Any] | None = None, world: Mapping[str, Any] | None = None,
                 settings: VerdictSettings | None = None) -> None:
        self.out_dir = Path(out_dir)
        self.out_dir.mkdir(parents=True, exist_ok=True)
        if utilities is None:
            utilities = default_utilities()
        if not isinstance(utilities, UtilityTable):
            utilities = UtilityTable(utilities, "given")
        self.utilities = utilities
        # the zone change each signal declares (load_declared_transitions); the defaults' when none is given
        self.transitions: Mapping[str, Transition] = transitions if transitions is not None else DEFAULT_TRANSITIONS
        self._mission: MissionInfo | None = None
        if mission_info is not None:  # parsed first: a bad one raises before any file is opened
            self._mission = (mission_info if isinstance(mission_info, MissionInfo)
                             else MissionInfo.from_message(mission_info))
        self.monitor_config = monitor_config
        self.world = world
        self.settings = settings or VerdictSettings()
        self._lock = threading.Lock()
        self._ended = threading.Event()
        self._log = EventLog(self.out_dir / EVENTS_FILE)
        self._by_seq: dict[int, Signal] = {}
        self._filled = 0  # signals that arrived after a later one (filled a hole)
        self._repeats = 0  # identical repeats, ignored
        self._total = 0.0
        self._over_time: list[tuple[float, float]] = []
        self._counts: Counter[str] = Counter()
        self._unknown: Counter[str] = Counter()
        self._next_seq = 0
        self._stream_problems: list[Evidence] = []
        self._problem_count = 0
        self._notes: list[Evidence] = []
        self._task_reasons: dict[int, str] = {}
        self._task_goals: dict[int, tuple[float, float]] = {}
        self._late = 0
        self._summary: Summary | None = None

    # -- feeding (any thread) ------------------------------------------------------------------------------

    def on_signal(self, message: Mapping[str, Any]) -> None:
        """One message of ``rei.run.<id>.signal``: scored, logged (flushed) and kept for the verdicts."""
        with self._lock:
            if self._summary is not None:
                self._late += 1
                return
            try:
                signal = Signal.from_message(message)
            except SignalError as error:
                self._problem(Evidence(f"malformed signal skipped: {error}"))
                return
            known = self._by_seq.get(signal.seq)
            if known is not None:
                if known == signal:
                    self._repeats += 1
                else:
                    self._problem(Evidence(f"signal seq {signal.seq} repeated with other content, skipped",
                                           signal.t, signal.signal, signal.object))
                return
            if signal.seq < self._next_seq:
                self._filled += 1
            self._next_seq = max(self._next_seq, signal.seq + 1)
            self._by_seq[signal.seq] = signal
            if signal.signal not in self.utilities:
                self._unknown[signal.signal] += 1
            utility = self.utilities.utility(signal.signal)
            self._total += utility
            self._over_time.append((signal.t, self._total))
            self._counts[signal.signal] += 1
            self._log.write(signal.t, signal.signal, utility, self._total, signal.subject, signal.object)
            if signal.signal == SIG_MISSION_END:
                self._ended.set()

    def on_mission(self, message: Mapping[str, Any]) -> None:
        """One message of ``rei.run.<id>.mission``: only the TASK_FAIL reasons and goal positions are used
        (the signals are the primary input; they carry no reasons)."""
        with self._lock:
            if self._summary is not None or not isinstance(message, Mapping):
                return
            event, index = message.get("event"), message.get("task_index")
            if not isinstance(index, int) or isinstance(index, bool) or index < 0:
                return
            reason, goal = message.get("reason"), message.get("goal")
            if event == "TASK_FAIL" and isinstance(reason, str):
                self._task_reasons[index] = reason
            if event == "TASK_START" and isinstance(goal, list | tuple) and len(goal) >= 2 and all(
                    isinstance(v, int | float) and not isinstance(v, bool) and math.isfinite(v)
                    for v in goal[:2]):
                self._task_goals[index] = (float(goal[0]), float(goal[1]))

    def reconcile(self, messages: Iterable[Mapping[str, Any]]) -> int:
        """Fill the holes of the received stream from another record of it (the monitor's ``--signals-out``
        file); returns how many signals were missing. Signals already received are ignored when identical."""
        with self._lock:
            before = len(self._by_seq)
        for message in messages:
            if not self._has(message):
                self.on_signal(message)
        with self._lock:
            recovered = len(self._by_seq) - before
            if recovered:
                self._notes.append(Evidence(f"{recovered} signal(s) missed live were recovered from the "
                                            "monitor's signal file"))
            return recovered

    def _has(self, message: Mapping[str, Any]) -> bool:
        try:
            signal = Signal.from_message(message)
        except SignalError:
            return False
        with self._lock:
            return self._by_seq.get(signal.seq) == signal

    def note(self, text: str, t: float | None = None) -> None:
        """Something the summary should tell (a restarted router, a re-evaluation); not a problem."""
        with self._lock:
            self._notes.append(Evidence(text, t))

    def set_mission_info(self, message: Mapping[str, Any] | MissionInfo) -> None:
        """Mission information that arrived after construction; an unreadable one is noted, not raised."""
        with self._lock:
            try:
                self._mission = (message if isinstance(message, MissionInfo)
                                 else MissionInfo.from_message(message))
            except MissionInfoError as error:
                self._notes.append(Evidence(f"mission_info ignored: {error}"))

    # -- reading (any thread) ------------------------------------------------------------------------------

    @property
    def total(self) -> float:
        with self._lock:
            return self._total

    @property
    def utility_over_time(self) -> list[tuple[float, float]]:
        """``(t, total)`` after each signal, in arrival order (a copy)."""
        with self._lock:
            return list(self._over_time)

    @property
    def counts(self) -> dict[str, int]:
        with self._lock:
            return dict(self._counts)

    @property
    def has_mission_info(self) -> bool:
        with self._lock:
            return self._mission is not None

    @property
    def finished(self) -> bool:
        with self._lock:
            return self._summary is not None

    @property
    def ended(self) -> bool:
        """SIG_MISSION_END has been received."""
        return self._ended.is_set()

    def wait_for_end(self, timeout: float | None = None) -> bool:
        """Block until SIG_MISSION_END arrives (True) or ``timeout`` seconds pass (False)."""
        return self._ended.wait(timeout)

    # -- the end -------------------------------------------------------------------------------------------

    def finish(self, *, status: str, reason: str | None, sim_duration: float | None, wall_time: float | None,
               run_id: str) -> Summary:
        """Judge the run and write summary.json and verdicts.xml; closes events.csv. Idempotent: a second
        call returns the first summary.

        ``status``: COMPLETED (the pipeline ran to its end) or ERROR (``reason`` says why; verdicts that
        would pass become errors). ``sim_duration``: simulated seconds (the end of observation).
        """
        if status not in RUN_STATUSES:
            raise ValueError(f"status must be one of {RUN_STATUSES}, got {status!r}")
        with self._lock:
            if self._summary is not None:
                return self._summary
            signals = tuple(self._by_seq[seq] for seq in sorted(self._by_seq))
            self._note_holes(signals)
            if self._filled:
                self._rewrite_log(signals)
            if self._repeats:
                self._notes.append(Evidence(f"{self._repeats} identical repeated signal(s) ignored"))
            last = max((s.t for s in signals), default=0.0)
            duration = _finite(sim_duration)
            problems = list(self._stream_problems)
            if self._problem_count > len(problems):
                problems.append(Evidence(f"{self._problem_count - len(problems)} more stream problem(s)"))
            # the metrics first: a requirement on collisions with people reads the recorded state they measure
            measured, metrics_error = _measure(self.out_dir)
            trace = Trace(signals, max(duration or 0.0, last), status == "COMPLETED", reason,
                          dict(self._task_reasons), dict(self._task_goals), tuple(problems),
                          mission_recorded=self.settings.mission, transitions=self.transitions,
                          person_collisions=measured.person_collisions if measured is not None else None)
            context = CaseContext.from_configs(self._mission, self.monitor_config, self.world, self.settings)
            verdicts = judge(trace, context)
            metrics = measured.metrics if measured is not None else dict.fromkeys((*NAMES, *LIST_KEYS))
            metrics_notes = tuple(Evidence(note) for note in measured.notes) if measured is not None else ()
            testcase = (self._mission.testcase if self._mission and self._mission.testcase
                        else _text((self.monitor_config or {}).get("testcase")))
            mission = self._mission.name if self._mission else None
            summary = Summary(
                mission=mission, testcase=testcase, run_id=run_id, status=status, error=reason,
                sim_duration=duration if duration is not None else last, wall_time=_finite(wall_time) or 0.0,
                total_utility=self._total, signals=len(signals), counts=dict(self._counts),
                unknown_signals=dict(self._unknown),
                goals=len(self._mission.goals) if self._mission else None,
                tasks=_tasks(signals, self._task_reasons), verdicts=verdicts,
                problems=(*problems, *self._notes, *metrics_notes), utility_source=self.utilities.source,
                files={"events": EVENTS_FILE, "verdicts": VERDICTS_FILE},
                metrics=metrics, metrics_error=metrics_error, faults=fault_windows(signals, run_schedule(self.out_dir)),
            )
            self._log.close()
            properties = {"run_id": run_id, "testcase": testcase or "", "mission": mission or "",
                          "status": status, "total_utility": format_number(self._total),
                          "sim_duration": f"{summary.sim_duration:.3f}"}
            suite = f"{testcase or 'rei'}.{mission or 'mission'}"
            write_junit(self.out_dir / VERDICTS_FILE, verdicts, suite=suite, time=summary.wall_time,
                        properties=properties)
            summary.write(self.out_dir / SUMMARY_FILE)
            self._summary = summary
            return summary

    @property
    def late_signals(self) -> int:
        with self._lock:
            return self._late

    def _note_holes(self, signals: tuple[Signal, ...]) -> None:
        """Holes in ``seq`` that nothing filled: lost signals, stream problems."""
        expected = 0
        for signal in signals:
            if signal.seq > expected:
                self._problem(Evidence(f"lost {signal.seq - expected} signal(s) (seq {expected} to "
                                       f"{signal.seq - 1})", signal.t, signal.signal, signal.object))
            expected = signal.seq + 1

    def _rewrite_log(self, signals: tuple[Signal, ...]) -> None:
        """events.csv in ``seq`` order (it was written in arrival order, with holes filled later)."""
        self._log.close()
        self._log = EventLog(self.out_dir / EVENTS_FILE)
        total, self._over_time = 0.0, []
        for signal in signals:
            utility = self.utilities.utility(signal.signal)
            total += utility
            self._over_time.append((signal.t, total))
            self._log.write(signal.t, signal.signal, utility, total, signal.subject, signal.object)

    def _problem(self, evidence: Evidence) -> None:
        self._problem_count += 1
        if len(self._stream_problems) < _MAX_PROBLEMS:
            self._stream_problems.append(evidence)


def _tasks(signals: tuple[Signal, ...], reasons: Mapping[int, str]) -> tuple[TaskRecord, ...]:
    """One record per started task, in start order, with its final state (RUNNING when it has none)."""
    records: dict[int, list[Any]] = {}
    for s in signals:
        index = s.task_index
        if index is None:
            continue
        if s.signal == SIG_MISSION_TASK_START and index not in records:
            records[index] = [index, "RUNNING", s.t, None, None]
        elif s.signal in (SIG_MISSION_TASK_SUCCESS, SIG_MISSION_TASK_FAIL) and index in records:
            record = records[index]
            if record[1] == "RUNNING":
                record[1] = s.signal.removeprefix("SIG_MISSION_TASK_")
                record[3] = s.t
                record[4] = reasons.get(index) if s.signal == SIG_MISSION_TASK_FAIL else None
    return tuple(TaskRecord(*r) for r in records.values())


def _finite(value: float | None) -> float | None:
    return float(value) if value is not None and math.isfinite(value) else None


def _text(value: Any) -> str | None:
    return value if isinstance(value, str) else None


def _measure(out_dir: Path) -> tuple[Measured | None, str | None]:
    """The run's navigation metrics from what it recorded (with notes on what they left out), or None and why
    (a run that broke before it recorded anything, an evaluator fed by hand). Any failure of the metrics is
    caught: it must not cost the run its summary and verdicts."""
    try:
        return measure(out_dir), None
    except (MetricsError, OSError) as error:
        return None, str(error)
    except Exception as error:  # noqa: BLE001 - a bug in the metrics: the summary says so, the run is still judged
        return None, f"metrics failed: {type(error).__name__}: {error}"
