# SPDX-License-Identifier: EPL-2.0
"""One campaign run, in its own process: ``python -m rei.campaign.worker RUN_DIR`` (reads RUN_DIR/task.json).

A process per run keeps runs apart: a run that crashes (even in pybullet's C code) or hangs is stopped and
recorded by the supervisor without touching the others, and memory never accumulates over a campaign.

Two paths, both with the real components:

* ``replay`` (default, for throughput): the simulation runs in this process without a router
  (``rei.run.run_mission``, recording its state and mission streams), the real monitor jar replays the
  recording and the evaluator scores the signals offline (``rei.run.reevaluate``). Same simulation, same monitor rules, same evaluator as ``rei run``; what it leaves
  out is the router, the live monitor's JVM start before the run and the waits for drains (~10 s a run).
* ``pipeline``: ``rei run`` in this process (router, live monitor, simulation child, evaluator, report).

The local backend keeps one warm monitor JVM for all its runs and names its socket in ``$REI_MONITOR_SERVER``:
replays go there (a tenth of a second each instead of a JVM start and rule compilation), and to a JVM of their
own when it does not answer.

Exit 0 once ``summary.json`` is written (whatever the verdicts); anything else is a broken run.
``timing.json`` says where the time went (wall and CPU seconds per phase).
"""

from __future__ import annotations

import json
import os
import sys
import time
from pathlib import Path
from typing import Any, Self

from rei.campaign.plan import TASK_FILE, RunTask
from rei.lifetime import sigterm_unwinds

#: The warm monitor JVM's socket (rei.run.jvm.JarServer), set by the local backend for its workers.
MONITOR_SERVER_ENV = "REI_MONITOR_SERVER"
TIMING_FILE = "timing.json"


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
    from rei.run import MissionRunOptions, run_mission
    from rei.run.patterns import PatternSelection, record
    from rei.run.reevaluate import RunSettings, reevaluate

    timing: dict[str, Any] = {}
    with _Phase(timing, "simulation"):
        options = MissionRunOptions(controller=task.controller, seed=task.seed, humans=task.humans,
                                    fault=task.fault)
        if task.sut is None:
            result = run_mission(Path(task.case_dir), run_dir, options, run_id=task.key)
        else:
            result = _with_external_sut(task, run_dir, options)
    # an external SUT that broke the run: what was recorded is still judged, as an ERROR naming it (as `rei run`)
    broken = {} if result.error is None else {"status": "ERROR", "reason": result.error}
    server = os.environ.get(MONITOR_SERVER_ENV)
    # the run keeps a copy of the user's patterns (OUT/patterns/) as `rei run --patterns` does, so the replay below,
    # a later `rei evaluate` of the run and the warm JVM (which takes the options per command) all run them
    patterns = record(PatternSelection(Path(task.patterns) if task.patterns else None), run_dir)
    with _Phase(timing, "evaluation"):  # this process's CPU only: the monitor's replay is in another JVM
        judged = reevaluate(run_dir, Path(task.case_dir), settings=RunSettings(
            humans=task.humans, run_id=task.key, sim_duration=result.sim_time), **broken,
            patterns=patterns, utilities=Path(task.utilities) if task.utilities else None,
            monitor_server=Path(server) if server else None)
    # served: the replay's CPU was spent in the warm JVM, not in this worker's children (results.make_result)
    timing["monitor"] = {"wall": round(judged.monitor.wall, 3), "cpu": round(judged.monitor.cpu, 3),
                         **({"served": True} if server and judged.monitor.served else {})}
    timing["evaluation"]["wall"] = round(judged.evaluation_wall, 3)
    if task.report:
        with _Phase(timing, "report"):
            _write_report(run_dir, Path(task.case_dir))
    _write_timing(run_dir, timing)
    return 0


def _with_external_sut(task: RunTask, run_dir: Path, options: Any) -> Any:
    """The mission with an external SUT: it needs a router, so the run gets its own (as `rei sim` does)."""
    import dataclasses

    from rei.campaign.spec import ExternalSut
    from rei.run import run_mission
    from rei.sut.external.options import SutOptions
    from rei.wamp.client import WampClient
    from rei.wamp.router import Router

    assert task.sut is not None
    sut = ExternalSut(**task.sut)
    with Router(run_dir=run_dir / "router", run_id=task.key, die_with_parent=True) as router, \
            WampClient(router.rs_url, auth=router.credentials("simulation")) as client:
        options = dataclasses.replace(options, sut=SutOptions(
            command=sut.command, clock=sut.clock, deadline=sut.deadline,  # type: ignore[arg-type]
            offer_map=sut.map, join_timeout=sut.join_timeout, router_url=router.ws_url,
            auth_file=router.auth_file("sut"), cwd=Path(sut.cwd) if sut.cwd else None))
        return run_mission(Path(task.case_dir), run_dir, options, run_id=task.key, client=client)


def _pipeline(task: RunTask, run_dir: Path) -> int:
    from rei.cli import main

    timing: dict[str, Any] = {}
    argv = ["run", task.case_dir, "-o", str(run_dir), "--seed", str(task.seed), "--run-id", task.key.replace("__", "-")]
    if task.sut is None:
        argv += ["--controller", task.controller]
    else:
        from rei.campaign.spec import ExternalSut

        sut = ExternalSut(**task.sut)
        argv += sut.argv()
        if sut.cwd:  # the command's relative paths are the spec's; every path of argv is absolute
            os.chdir(sut.cwd)
    if not task.humans:
        argv.append("--no-humans")
    if task.fault:
        argv += ["--fault", task.fault]
    if task.patterns:
        argv += ["--patterns", task.patterns]
    if task.utilities:
        argv += ["--utilities", task.utilities]
    with _Phase(timing, "pipeline"):
        code = main(argv)
    _write_timing(run_dir, timing)
    return 0 if code in (0, 1, 2) and (run_dir / "summary.json").is_file() else (code or 2)


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
    with sigterm_unwinds():  # a timed-out run is stopped with SIGTERM: its SUT and router must go with it
        return execute(task)


if __name__ == "__main__":
    sys.exit(main())
