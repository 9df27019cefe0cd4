# SPDX-License-Identifier: EPL-2.0
"""A whole campaign: plan, prepare the cases, run what is not finished yet, summarize.

    OUT/spec.yaml                 the spec as given (a copy)
    OUT/rooms/*.rei, OUT/cases/*  the generated rooms and every case's generated artifacts
    OUT/runs/<key>/               one folder per run: task.json, worker.log, streams/, signals.jsonl,
                                  events.csv, summary.json, verdicts.xml, timing.json, result.json
    OUT/summary.csv, runs.csv     the thesis's tables (see rei.campaign.aggregate), one line per run
    OUT/report.html               tables and plots
    OUT/campaign.json             counts, wall and CPU time, utilisation of this machine

Interrupted (Ctrl-C, or SIGTERM under rei.lifetime.sigterm_unwinds as `rei campaign` runs it): running workers
are stopped, their runs stay unfinished, the summary covers the finished ones, and the same command resumes.
"""

from __future__ import annotations

import dataclasses
import json
import shutil
import threading
from collections.abc import Callable, Sequence
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Protocol

from rei.campaign.aggregate import metric_rows, metrics_csv, runs_csv, summary_csv
from rei.campaign.machine import Sample, usage
from rei.campaign.plan import Plan, RunTask, plan_campaign, write_task
from rei.campaign.prepare import STAMP, Prepared, needs_generation, prepare_case
from rei.campaign.results import RunResult, finished_result, make_result, write_result
from rei.campaign.spec import Spec
from rei.campaign.supervise import Outcome
from rei.run.jvm import JarServer, JarServerError


class Backend(Protocol):
    name: str
    workers: int

    def warm_up(self) -> None: ...  # starts what run() needs, while the cases are generated

    def run(self, tasks: Any, on_outcome: Callable[[RunTask, Outcome], None], stop: threading.Event) -> None: ...

    def close(self) -> None: ...


@dataclass(frozen=True, slots=True)
class CampaignResult:
    results: tuple[RunResult, ...]  # finished runs, in plan order
    planned: int
    executed: int  # runs executed by this invocation
    interrupted: bool
    metrics: dict[str, Any]

    @property
    def errors(self) -> int:
        return sum(r.status != "COMPLETED" for r in self.results)


def run_campaign(spec: Spec, out: Path, backend: Backend, *, retry_errors: bool = False,
                 prepare_workers: int = 2, generator: Path | None = None, helpers: Sequence[int] = (),
                 log: Callable[[str], None] = print) -> CampaignResult:
    """``generator``: the socket of a warm generator JVM to generate the cases in (the background service's),
    else the campaign starts one; ``helpers``: pids of processes that work for the campaign without being its
    children (that service), whose CPU counts as the campaign's. Ctrl-C, or SIGTERM under
    rei.lifetime.sigterm_unwinds (as `rei campaign` runs it), while the cases are prepared or the runs run
    interrupts the campaign: its outputs are still written, ``interrupted`` says so."""
    out = out.resolve()
    start = Sample.now(helpers)
    plan = plan_campaign(spec, out)  # first: a spec it refuses leaves OUT's spec.yaml as the runs there had it
    out.mkdir(parents=True, exist_ok=True)
    if spec.source is not None and spec.source.resolve() != (out / "spec.yaml"):
        shutil.copyfile(spec.source, out / "spec.yaml")
    stop = threading.Event()
    executed = 0
    interrupted = False
    metrics: dict[str, Any] = {}
    try:
        backend.warm_up()
        prepared, prepare_cpu = _prepare(plan, out, prepare_workers, generator, log)
        plan = stamped(plan, out)
        metrics["prepare"] = {"cases": len(plan.cases), "generated": sum(p.generated for p in prepared.values()),
                              "cpu": round(prepare_cpu, 3),
                              "wall": round(Sample.now().wall - start.wall, 3)}
        todo = []
        ungenerated = 0  # runs recorded as ERROR now, their case not generated: not "finished already"
        # by the folder a run runs (a behaviour variant's case is not its room's: rei.campaign.plan)
        by_folder = {str(source.case_dir(out.resolve())): prepared[source.key] for source in plan.cases}
        for task in plan.runs:
            done = finished_result(task)
            if done is not None and not (retry_errors and done.status != "COMPLETED"):
                continue
            problem = by_folder[task.case_dir].error
            if problem is not None:  # the case could not be generated: the run is an ERROR, not a crash
                # recorded as a run that ended in ERROR is (its folder, the task.json that makes it finished)
                write_task(task, Path(task.run_dir))
                _record(task, Outcome(task.key, None, False, False, 0.0, 0.0, problem, "-"), log, problem)
                executed += 1
                ungenerated += 1
                continue
            todo.append(task)
        todo = longest_first(todo)
        not_generated = f", {ungenerated} in ERROR (case not generated)" if ungenerated else ""
        log(f"campaign {spec.name}: {len(plan.runs)} runs, {len(plan.runs) - len(todo) - ungenerated} finished "
            f"already{not_generated}, {len(todo)} to run on {backend.workers} {backend.name} worker(s)")

        def on_outcome(task: RunTask, outcome: Outcome) -> None:
            nonlocal executed
            if outcome.interrupted:
                return
            executed += 1
            _record(task, outcome, log, None, f"[{executed}/{len(todo)}] ")

        backend.run(todo, on_outcome, stop)
    except (KeyboardInterrupt, SystemExit):
        interrupted = True
        stop.set()
        log("campaign interrupted: finished runs are kept; run the same command to resume")
    moved = getattr(backend, "moved", None)  # a Ray backend's bytes to and from the nodes
    if moved is not None:
        metrics["transfer"] = dict(moved)
    plan = stamped(plan, out)  # as the cases are now (an interruption may have come before the first stamping)
    results = tuple(r for r in (finished_result(t) for t in plan.runs) if r is not None)
    metrics["campaign"] = usage(start, Sample.now(helpers))
    metrics["runs"] = _run_metrics(results)
    result = CampaignResult(results, len(plan.runs), executed, interrupted, metrics)
    write_outputs(spec, out, plan, result)
    return result


def write_outputs(spec: Spec, out: Path, plan: Plan, result: CampaignResult) -> None:
    from rei.campaign.report import write_campaign_report

    (out / "summary.csv").write_text(summary_csv(result.results), encoding="utf-8")
    (out / "runs.csv").write_text(runs_csv(result.results), encoding="utf-8")
    navigation = metric_rows(result.results)
    (out / "metrics.csv").write_text(metrics_csv(navigation), encoding="utf-8")
    document = {"format": "rei-campaign/1", "name": spec.name, "planned": result.planned,
                "finished": len(result.results), "executed": result.executed, "errors": result.errors,
                "interrupted": result.interrupted, "metrics": result.metrics,
                "runs": [t.key for t in plan.runs]}
    (out / "campaign.json").write_text(json.dumps(document, indent=2) + "\n", encoding="utf-8")
    write_campaign_report(out, spec.name, result.results, result.metrics, result.planned, navigation)


def stamped(plan: Plan, out: Path) -> Plan:
    """``plan`` with each run's ``case_stamp``: the stamp its case folder has now (None without one: a generated
    folder given as the case, or a case that could not be generated), so that a run of another version of its case
    does not count as finished."""
    stamps = {}
    for source in plan.cases:
        folder = source.case_dir(out)
        try:
            stamps[str(folder)] = (folder / STAMP).read_text(encoding="utf-8").strip()
        except OSError:
            stamps[str(folder)] = None
    return dataclasses.replace(plan, runs=tuple(dataclasses.replace(t, case_stamp=stamps.get(t.case_dir))
                                                for t in plan.runs))


def longest_first(tasks: list[RunTask]) -> list[RunTask]:
    """Biggest rooms first (floor area as the estimate of a run's cost), plan order among equals.

    Why: with a few workers the campaign's wall time is set by its last runs; a large room started last runs
    alone while the other workers idle (measured: the thesis campaign's large room, 18 s, ran last).
    """
    areas: dict[str, float] = {}
    for task in tasks:
        if task.case_dir not in areas:
            world = _json_or_none(Path(task.case_dir) / "world.json") or {}
            bounds = world.get("bounds") or [0, 0, 0, 0]
            areas[task.case_dir] = float(bounds[2] - bounds[0]) * float(bounds[3] - bounds[1])
    return sorted(tasks, key=lambda task: -areas[task.case_dir])


def _json_or_none(path: Path) -> Any:
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None


def _prepare(plan: Plan, out: Path, workers: int, generator: Path | None,
             log: Callable[[str], None]) -> tuple[dict[str, Prepared], float]:
    """Every case generated (in one warm generator JVM when any needs it: ``generator``, else one started here);
    and the CPU seconds generation took."""
    server = None
    if generator is None and any(needs_generation(source, out) for source in plan.cases):
        try:
            server = JarServer("cli", out / "cases" / "generator.log").start()
        except (JarServerError, OSError) as error:  # each case then starts a JVM of its own
            log(f"campaign: no warm generator JVM ({error}); each case is generated in a JVM of its own")
    socket = server.socket if server is not None else generator
    try:
        with ThreadPoolExecutor(max(1, workers), thread_name_prefix="rei-prepare") as pool:
            prepared = {p.key: p for p in pool.map(lambda source: prepare_case(source, out, server=socket),
                                                    plan.cases)}
    finally:
        if server is not None:
            server.stop()
    # started here: the whole JVM's; else what each command's thread took (in the helper's JVM, or in a JVM each)
    cpu = server.cpu if server is not None else sum(p.cpu for p in prepared.values())
    for p in prepared.values():
        if p.error:
            log(f"case {p.key}: {p.error}")
    return prepared, cpu


def _record(task: RunTask, outcome: Outcome, log: Callable[[str], None], error: str | None,
            prefix: str = "") -> None:
    result = make_result(task, outcome)
    if error is not None:
        result = RunResult.from_dict({**result.to_dict(), "status": "ERROR", "error": error})
    write_result(task, result)
    if result.status == "COMPLETED":
        how = (f"utility {result.total_utility:+g}, {result.tasks_succeeded}/{result.tasks_started} tasks, "
               f"{result.sim_duration or 0:.1f} s simulated")
    else:
        how = f"ERROR {result.error}"
    log(f"{prefix}{task.key}: {how} ({result.wall_time:.1f} s wall, {result.cpu_time:.1f} s CPU)")


def _run_metrics(results: tuple[RunResult, ...]) -> dict[str, Any]:
    """Where the time of the runs went: sums of wall and CPU seconds per phase (from each run's timing.json)."""
    phases: dict[str, dict[str, float]] = {}
    for r in results:
        for name, t in r.timing.items():
            if isinstance(t, dict):
                slot = phases.setdefault(name, {"wall": 0.0, "cpu": 0.0})
                slot["wall"] += float(t.get("wall", 0.0))
                slot["cpu"] += float(t.get("cpu", 0.0))
    return {"count": len(results), "wall": round(sum(r.wall_time for r in results), 3),
            "cpu": round(sum(r.cpu_time for r in results), 3),
            "phases": {k: {kk: round(vv, 3) for kk, vv in v.items()} for k, v in phases.items()}}
