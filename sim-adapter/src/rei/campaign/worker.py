# SPDX-License-Identifier: EPL-2.0
"""One campaign run, in its own process: ``python -m rei.campaign.worker RUN_DIR`` (reads RUN_DIR/task.json).

A process per run keeps runs apart: a run that crashes (even in pybullet's C code) or hangs is stopped and
recorded by the supervisor without touching the others, and memory never accumulates over a campaign.

Two paths, both with the real components:

* ``replay`` (default, for throughput): the simulation runs in this process without a router
  (``rei.run.run_mission``, recording its state and mission streams), the real monitor jar replays the
  recording (``--replay ... --signals-out``) and the evaluator scores the signals offline
  (``rei.evaluation.replay``). Same simulation, same monitor rules, same evaluator as ``rei run``; what it leaves
  out is the router, the live monitor's JVM start before the run and the waits for drains (~10 s a run).
* ``pipeline``: ``rei run`` in this process (router, live monitor, simulation child, evaluator, report).

Exit 0 once ``summary.json`` is written (whatever the verdicts); anything else is a broken run.
``timing.json`` says where the time went (wall and CPU seconds per phase).
"""

from __future__ import annotations

import json
import sys
import time
from pathlib import Path
from typing import Any, Self

from rei.campaign.jvm import run_jar
from rei.campaign.plan import RunTask

TASK_FILE = "task.json"
TIMING_FILE = "timing.json"
SIGNALS_FILE = "signals.jsonl"


class _Phase:
    """Wall and CPU seconds of this process for one phase."""

    def __init__(self, timing: dict[str, Any], name: str) -> None:
        self.timing, self.name = timing, name

    def __enter__(self) -> Self:
        self.wall, self.cpu = time.perf_counter(), time.process_time()
        return self

    def __exit__(self, *exc: object) -> None:
        self.timing[self.name] = {"wall": round(time.perf_counter() - self.wall, 3),
                                  "cpu": round(time.process_time() - self.cpu, 3)}


def execute(task: RunTask) -> int:
    run_dir = Path(task.run_dir)
    run_dir.mkdir(parents=True, exist_ok=True)
    if task.mode == "pipeline":
        return _pipeline(task, run_dir)
    return _replay(task, run_dir)


def _replay(task: RunTask, run_dir: Path) -> int:
    from rei.artifacts import read_case
    from rei.evaluation import Evaluator, VerdictSettings, replay
    from rei.mission import mission_info
    from rei.run import MissionRunOptions, run_mission
    from rei.wamp.recording import RecordingWriter, read_recording, stream_path

    started = time.perf_counter()
    case_dir = Path(task.case_dir)
    timing: dict[str, Any] = {}
    with _Phase(timing, "simulation"):
        options = MissionRunOptions(controller=task.controller, seed=task.seed, humans=task.humans,
                                    fault=task.fault)
        result = run_mission(case_dir, run_dir, options, run_id=task.key)
    signals_file = run_dir / SIGNALS_FILE
    signals_file.unlink(missing_ok=True)
    monitor = run_jar("monitor", ["--replay", str(run_dir), "--case", str(case_dir), "--signals-out",
                                  str(signals_file), "--quiet"], run_dir / "monitor.log")
    timing["monitor"] = {"wall": round(monitor.wall, 3), "cpu": round(monitor.cpu, 3)}
    with _Phase(timing, "evaluation"):
        status, reason = "COMPLETED", None
        if monitor.code != 0:
            status, reason = "ERROR", f"the monitor exited with {monitor.code}: {monitor.log_tail}"
        signals = _read_signals(signals_file)
        with RecordingWriter(stream_path(run_dir, "signal")) as recording:  # as `rei run` keeps it
            for signal in signals:
                recording.write(signal)
        evaluator = Evaluator(run_dir, mission_info=mission_info(read_case(case_dir).mission),
                              monitor_config=_json(case_dir / "monitor.json"), world=_json(case_dir / "world.json"),
                              settings=VerdictSettings(humans=task.humans))
        replay(signals, evaluator, missions=read_recording(stream_path(run_dir, "mission")), status=status,
               reason=reason, sim_duration=result.sim_time, wall_time=time.perf_counter() - started,
               run_id=task.key)
    if task.report:
        with _Phase(timing, "report"):
            _write_report(run_dir, case_dir)
    _write_timing(run_dir, timing)
    return 0


def _pipeline(task: RunTask, run_dir: Path) -> int:
    from rei.cli import main

    timing: dict[str, Any] = {}
    argv = ["run", task.case_dir, "-o", str(run_dir), "--seed", str(task.seed), "--controller", task.controller,
            "--run-id", task.key.replace("__", "-")]
    if not task.humans:
        argv.append("--no-humans")
    if task.fault:
        argv += ["--fault", task.fault]
    with _Phase(timing, "pipeline"):
        code = main(argv)
    _write_timing(run_dir, timing)
    return 0 if code in (0, 1, 2) and (run_dir / "summary.json").is_file() else (code or 2)


def _read_signals(path: Path) -> list[dict[str, Any]]:
    if not path.is_file():
        return []
    return [json.loads(line) for line in path.read_text(encoding="utf-8").splitlines() if line.strip()]


def _write_report(run_dir: Path, case_dir: Path) -> None:
    from rei.report import write_report

    write_report(run_dir, case_dir)


def _write_timing(run_dir: Path, timing: dict[str, Any]) -> None:
    (run_dir / TIMING_FILE).write_text(json.dumps(timing, indent=2) + "\n", encoding="utf-8")


def _json(path: Path) -> dict[str, Any]:
    return json.loads(path.read_text(encoding="utf-8"))


def main(argv: list[str] | None = None) -> int:
    args = sys.argv[1:] if argv is None else argv
    if len(args) != 1:
        print("usage: python -m rei.campaign.worker RUN_DIR", file=sys.stderr)
        return 2
    task = RunTask.from_dict(_json(Path(args[0]) / TASK_FILE))
    return execute(task)


if __name__ == "__main__":
    sys.exit(main())
