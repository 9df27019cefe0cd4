# SPDX-License-Identifier: EPL-2.0
"""Judging a run again from what it recorded: ``OUT/streams/state.msgpack`` and ``mission.msgpack``.

The simulation records every message before it publishes it, so its recording is complete even when the
monitor died or the router lost messages. Feeding the recording through the monitor jar (``--replay``) gives
the signals the live monitor would have given - the same code decides, and live == replay is tested - and a
fresh evaluator turns them into events.csv, summary.json and verdicts.xml, replacing the live ones. The live
event log is kept as ``events-live.csv`` (the first time: a second re-evaluation does not overwrite it).

Used by ``rei run`` when the monitor dies during a run, by ``rei evaluate OUT`` on any finished run, and by
campaigns, whose runs are always judged this way. The replay runs the patterns the run kept in ``OUT/patterns/``
(rei.run.patterns), and the evaluator scores with the utilities they declare.
"""

from __future__ import annotations

import json
import time
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from rei.artifacts.case import case_of_run
from rei.run.jvm import JvmResult, run_jar
from rei.run.patterns import UTILITIES_FILE, PatternSelection
from rei.wamp.recording import RecordingWriter, read_recording, stream_path

#: The monitor's own record of the signals it emitted (``--signals-out``): one JSON object per line.
SIGNALS_FILE = "signals.jsonl"
#: Where the live event log goes when a re-evaluation writes events.csv anew.
LIVE_EVENTS_FILE = "events-live.csv"
#: Seconds a replay may take (a 10-minute mission replays in well under a minute).
REPLAY_TIMEOUT = 600.0


class ReevaluationError(RuntimeError):
    """The run folder lacks what a re-evaluation needs, or the monitor's replay failed; the message says which."""


@dataclass(frozen=True, slots=True)
class RunSettings:
    """What the verdicts depend on besides the signals; read from the run's own files by ``from_run``."""

    humans: bool = True
    laser: bool = True
    mission: bool = True  # False: an imported run without goals (rei.bags)
    run_id: str = "replay"
    sim_duration: float | None = None

    @classmethod
    def from_run(cls, out: Path) -> RunSettings:
        """From ``OUT/sim.json`` (written by the simulation at its end); defaults when it is missing."""
        path = out / "sim.json"
        if not path.is_file():
            return cls()
        sim = _json(path)
        options = sim.get("options", {})
        return cls(humans=bool(options.get("humans", True)), laser=options.get("laser", "min") != "none",
                   mission=bool(options.get("mission", True)), run_id=str(sim.get("run_id", "replay")), sim_duration=sim.get("sim_time"))


def replay_monitor(out: Path, case_dir: Path, *, patterns: PatternSelection | None = None,
                   timeout: float = REPLAY_TIMEOUT, server: Path | None = None) -> tuple[JvmResult, list[Any]]:
    """Run the monitor jar over the run's recorded streams; returns its result and the signals it emitted.

    ``patterns``: default the run's own (``PatternSelection.recorded``). Writes ``OUT/signals.jsonl``,
    ``OUT/utilities.json`` (what the patterns declare), ``OUT/runtime.xmi`` (the final model) and
    ``OUT/monitor-replay.log``. ``server``: a warm monitor JVM's socket (rei.run.jvm.JarServer) to replay in.
    """
    if not stream_path(out, "state").is_file():
        raise ReevaluationError(f"{stream_path(out, 'state')}: no recorded state stream to re-evaluate")
    patterns = patterns or PatternSelection.recorded(out)
    signals_file = out / SIGNALS_FILE
    signals_file.unlink(missing_ok=True)
    (out / UTILITIES_FILE).unlink(missing_ok=True)  # the live monitor's must not stand in for the replay's
    result = run_jar("monitor", ["--replay", str(out), "--case", str(case_dir), "--signals-out", str(signals_file),
                                 "--snapshot-out", str(out / "runtime.xmi"), "--quiet", *patterns.monitor_args(),
                                 "--utilities-out", str(out / UTILITIES_FILE)],
                     out / "monitor-replay.log", timeout=timeout, server=server)
    return result, read_signals(signals_file)


def read_signals(path: Path) -> list[dict[str, Any]]:
    """The signals of a ``--signals-out`` file (empty when there is none); a torn last line is dropped."""
    if not path.is_file():
        return []
    signals = []
    for line in path.read_text(encoding="utf-8").splitlines():
        try:
            signals.append(json.loads(line))
        except json.JSONDecodeError:
            break  # the monitor died mid-line: everything before it is intact
    return signals


@dataclass(frozen=True, slots=True)
class Reevaluation:
    summary: Any  # rei.evaluation.Summary
    monitor: JvmResult  # the replay's exit code, wall and CPU time
    evaluation_wall: float


def reevaluate(out: Path, case_dir: Path | None = None, *, utilities: Path | None = None,
               settings: RunSettings | None = None, notes: tuple[str, ...] = (),
               status: str = "COMPLETED", reason: str | None = None,
               patterns: PatternSelection | None = None, monitor_server: Path | None = None) -> Reevaluation:
    """Replay the recorded streams through the monitor and evaluate the signals into ``out``.

    ``notes``: what the summary should say about why the run was re-evaluated. ``patterns``: default the ones
    the run kept (``OUT/patterns/``, else the defaults). A failed replay makes the run an ERROR with the
    monitor's log tail as the reason; a utility file that does not fit the patterns raises ReevaluationError
    before the live results are touched. ``monitor_server``: replay in that warm monitor JVM.
    """
    from rei.artifacts import read_case
    from rei.evaluation import (
        Evaluator,
        UtilityError,
        VerdictSettings,
        load_declared,
        load_utilities,
        replay,
    )
    from rei.mission import mission_info
    from rei.mission.executor import MISSION_INFO_FILE

    case_dir = case_dir or case_of_run(out) or out / "case"
    if not (case_dir / "world.json").is_file():
        raise ReevaluationError(f"no generated case in {case_dir} (world.json missing)")
    settings = settings or RunSettings.from_run(out)
    patterns = patterns or PatternSelection.recorded(out)
    monitor, signals = replay_monitor(out, case_dir, patterns=patterns, server=monitor_server)
    started = time.perf_counter()
    declared_file = out / UTILITIES_FILE  # missing only when the replay failed before compiling its rules
    try:
        declared = load_declared(declared_file) if declared_file.is_file() else None
        transitions = declared.transitions if declared is not None else None
        table = load_utilities(utilities, declared.utilities if declared is not None else None,
                               patterns=patterns.describe())
    except UtilityError as error:
        raise ReevaluationError(str(error)) from None
    if monitor.code != 0 and status == "COMPLETED":
        status, reason = "ERROR", f"the monitor's replay exited with {monitor.code}: {monitor.log_tail}"
    live_events = out / "events.csv"
    if live_events.is_file() and not (out / LIVE_EVENTS_FILE).exists():
        live_events.replace(out / LIVE_EVENTS_FILE)
    with RecordingWriter(stream_path(out, "signal")) as recording:  # the report and the mcap read this copy
        for signal in signals:
            recording.write(signal)
    recorded_mission = out / MISSION_INFO_FILE
    evaluator = Evaluator(out, utilities=table, transitions=transitions,
                          mission_info=(_json(recorded_mission) if recorded_mission.is_file()
                                        else mission_info(read_case(case_dir).mission)),
                          monitor_config=_json(case_dir / "monitor.json"), world=_json(case_dir / "world.json"),
                          settings=VerdictSettings(humans=settings.humans, laser=settings.laser,
                                                                   mission=settings.mission))
    for text in notes:
        evaluator.note(text)
    mission = stream_path(out, "mission")
    summary = replay(signals, evaluator, missions=read_recording(mission) if mission.is_file() else (),
                     status=status, reason=reason, sim_duration=settings.sim_duration,
                     wall_time=monitor.wall + time.perf_counter() - started, run_id=settings.run_id)
    return Reevaluation(summary, monitor, time.perf_counter() - started)


def _json(path: Path) -> Mapping[str, Any]:
    return json.loads(path.read_text(encoding="utf-8"))


__all__ = ["LIVE_EVENTS_FILE", "SIGNALS_FILE", "Reevaluation", "ReevaluationError", "RunSettings", "case_of_run",
           "read_signals", "reevaluate", "replay_monitor"]
