# SPDX-License-Identifier: EPL-2.0
"""A whole search: ask Optuna for candidates, simulate the valid ones on the pool, tell the scores, resume.

    OUT/spec.yaml               the spec as given (a copy)
    OUT/study.journal           Optuna's journal (one study per sampler): a stopped search resumes from it
    OUT/candidates/<key>.rei    every valid candidate (its first line the `rei run` line that re-runs it)
    OUT/cases/<key>/            its generated case
    OUT/runs/<key>/             its run (the campaign's run folder: summary.json, events.csv, streams/, ...; the
                                report.html of the runs that show a distinct failure is written at the end)

Evaluations are named ``<sampler>-<trial number>`` (``tpe-0003``). Budget counts simulated evaluations (those in
ERROR too, and a valid candidate the generator failed on counts as one in ERROR); candidates that are not valid are told to the study as infeasible (``constraints``), counted apart and never
simulated. A trial still running when the search stopped was not finished: it is closed as failed on resume and
its point asked again first, so nothing finished runs twice.
"""

from __future__ import annotations

import json
import shutil
import signal
import threading
from collections.abc import Callable
from concurrent.futures import FIRST_COMPLETED, Future, wait
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import optuna
from optuna.storages import JournalStorage
from optuna.storages.journal import JournalFileBackend
from optuna.trial import TrialState

from rei.campaign.plan import RunTask
from rei.campaign.results import make_result, write_result
from rei.campaign.supervise import Outcome
from rei.search.base import with_base_case
from rei.search.candidates import VALID, Candidate, CandidateMaker
from rei.search.design import sobol_design, startup_trials
from rei.search.failures import events_of, failures_of
from rei.search.objectives import ABSENT, better, present, score
from rei.search.pool import Pool
from rei.search.refine import ATTR, DEPTH, encounters, refined
from rei.search.refine import enabled as refining
from rei.search.reproduce import RunOptions
from rei.search.space import Space
from rei.search.spec import SearchSpec, check_patterns_kept, check_resumable

JOURNAL = "study.journal"
#: The trials' one constraint: 1 for a candidate that was not valid, 0 for a simulated one.
VALIDITY = "valid"
#: Candidates asked per simulated evaluation at most: a space of mostly invalid points ends the search instead of
#: spinning.
MAX_TRIES_PER_EVALUATION = 20
#: The user attribute of a trial of TPE's initial design: its index in the design.
DESIGN = "design"


def make_sampler(name: str, seed: int, budget: int) -> optuna.samplers.BaseSampler:
    if name == "tpe":  # its start-up trials are the initial design (rei.search.design), enqueued by Search
        return optuna.samplers.TPESampler(seed=seed, n_startup_trials=startup_trials(budget),
                                          multivariate=True, constant_liar=True)
    if name == "cmaes":
        return optuna.samplers.CmaEsSampler(seed=seed, n_startup_trials=1, warn_independent_sampling=False)
    if name == "nsga2":
        return optuna.samplers.NSGAIISampler(seed=seed, population_size=max(4, min(50, budget // 4)))
    if name == "qmc":
        return optuna.samplers.QMCSampler(seed=seed, qmc_type="sobol", warn_independent_sampling=False)
    if name == "random":
        return optuna.samplers.RandomSampler(seed=seed)
    raise ValueError(f"unknown sampler {name!r}")


def penalty(spec: SearchSpec) -> list[float]:
    """What an invalid candidate is told: each objective's value on the side the search moves away from."""
    return [ABSENT if o.direction == "minimize" else -ABSENT for o in spec.objectives]


def journal(out: Path) -> JournalStorage:
    """The search's Optuna storage, ``OUT/study.journal`` (one study per sampler)."""
    return JournalStorage(JournalFileBackend(str(out / JOURNAL)))


def open_study(out: Path, spec: SearchSpec, seed: int | None = None) -> optuna.Study:
    """The study of ``spec.sampler`` in ``OUT/study.journal``, created or loaded."""
    optuna.logging.set_verbosity(optuna.logging.WARNING)
    storage = journal(out)
    directions = [o.direction for o in spec.objectives]
    return optuna.create_study(storage=storage, study_name=spec.sampler, directions=directions, load_if_exists=True,
                               sampler=make_sampler(spec.sampler, spec.seed if seed is None else seed, spec.budget))


def check_resume(spec: SearchSpec, out: Path) -> None:
    """SpecError when ``out`` holds a search started with a spec that differs from ``spec`` in what the search
    does (rei.search.spec.check_resumable): its spec.yaml was overwritten silently, and the old trials lacked the
    new parameters."""
    stored = out / "spec.yaml"
    if spec.source is None or not (out / JOURNAL).is_file() or not stored.is_file():
        return
    if spec.source.resolve() != stored.resolve():
        check_resumable(spec, stored.read_text(encoding="utf-8"), str(stored))
    check_patterns_kept(spec, out / "runs")


@dataclass(slots=True)
class SearchProgress:
    simulated: int = 0
    invalid: int = 0
    unplannable: int = 0  # apart from the invalid ones, as search.json and the last line count them
    errors: int = 0
    failing: int = 0
    #: The exit status the stop calls for, 0 when the search ran to its end: 130 after Ctrl-C, 143 (128 + the
    #: signal) after SIGTERM, so a supervisor that sent SIGTERM sees it was obeyed
    interrupted: int = 0


#: A candidate ready to run: its trial, the candidate, its run.
Prepared = tuple[optuna.Trial, Candidate, RunTask]


class Search:
    """One search of ``spec`` into ``out`` on ``pool``; ``log`` gets the progress lines."""

    def __init__(self, spec: SearchSpec, out: Path, pool: Pool, stop: threading.Event,
                 log: Callable[[str], None] = print) -> None:
        self.spec, self.out, self.pool, self.stop, self.log = spec, out.resolve(), pool, stop, log
        check_resume(spec, self.out)
        self.out.mkdir(parents=True, exist_ok=True)
        if spec.source is not None and spec.source.resolve() != self.out / "spec.yaml":
            shutil.copyfile(spec.source, self.out / "spec.yaml")
        # a ``rooms:`` spec's base case is generated now, into OUT, before the parameters are checked against it
        self.spec = spec = with_base_case(spec, self.out, log)
        assert spec.case is not None
        self.maker = CandidateMaker(spec.case, self.out, log=log,
                                    runs=RunOptions(spec.controller, spec.humans, spec.sut, spec.patterns,
                                                    spec.utilities))
        try:
            self.space = Space(spec.parameters, self.maker.diagram, self.maker.palette, humans=spec.humans,
                               text=self.maker.base_text, validate=self.maker.validate)
        except BaseException:  # a parameter the base case does not have: the engine's JVM goes now
            self.maker.close()
            raise
        if spec.sampler == "cmaes":
            _note_independent(self.space, log)
        started = open_study(self.out, spec)
        so_far = len(started.trials)
        # a resumed sampler must not replay the draws of the first invocation (qmc's sequence is indexed instead)
        self.study = started if spec.sampler == "qmc" else open_study(self.out, spec, spec.seed + so_far)
        # TPE starts from a Sobol design, not random sampling's draws; its points are enqueued one at a time, when
        # nothing else waits, so a refinement (rei.search.refine) goes before the rest of the design. Its size is
        # the first invocation's (a resume with another budget continues the same design); a journal without it
        # enqueued the whole design at its start.
        if spec.sampler == "tpe" and not so_far:
            started.set_user_attr(DESIGN, startup_trials(spec.budget))
        size = int(started.user_attrs.get(DESIGN, 0))
        self._design = sobol_design(self.space.distributions, size, spec.seed) if size else []
        # the next design index (a point asked again on resume is enqueued with its index once more)
        self._designed = 1 + max((int(t.user_attrs[DESIGN]) for t in started.trials if DESIGN in t.user_attrs),
                                 default=-1)
        self.progress = SearchProgress()
        self._refine = refining(spec)
        self._known: set[str] = set()  # the signatures of the events found so far (rei.search.failures)
        self._met: set[str] = set()  # the elements (people, objects, walls) of those failures
        self._raw: list[list[float | None]] = []  # the simulated evaluations' own objective values (None: absent)

    def key(self, number: int) -> str:
        return f"{self.spec.sampler}-{number:04d}"

    def run(self) -> SearchProgress:
        """Runs the search to its budget; Ctrl-C, or SIGTERM under rei.lifetime.sigterm_unwinds (as `rei search`
        runs it), stops it with the outputs of what finished still to write."""
        try:
            self._resume()
            self._loop()
        except KeyboardInterrupt:
            self._stopped(128 + signal.SIGINT)
        except SystemExit as stop:
            self._stopped(stop.code if isinstance(stop.code, int) and stop.code else 128 + signal.SIGTERM)
        return self.progress

    def _stopped(self, status: int) -> None:
        self.progress.interrupted = status
        self.stop.set()
        self.log("search interrupted: finished evaluations are kept; run the same command to resume")

    def close(self) -> None:
        self.maker.close()

    # -- the loop -------------------------------------------------------------------------------------------------

    def _resume(self) -> None:
        for trial in self.study.get_trials(deepcopy=False):
            if trial.state == TrialState.RUNNING:  # the last invocation stopped while it ran: ask it again
                self.study.tell(trial.number, state=TrialState.FAIL)
                # a refinement keeps its depth and a design point its index
                kept = {k: v for k, v in trial.user_attrs.items() if k in (ATTR, DESIGN)}
                self.study.enqueue_trial(trial.params, user_attrs=kept, skip_if_exists=False)
            elif trial.user_attrs.get("simulated"):
                self.progress.simulated += 1
                if trial.user_attrs.get("values"):
                    self._raw.append(_own(trial.user_attrs["values"]))
                # events, also of an evaluation recorded per requirement by an earlier rei (found again from its run)
                found = events_of(trial.user_attrs.get("failures") or [],
                                  self.out / "runs" / str(trial.user_attrs.get("key") or self.key(trial.number)))
                self._known |= {f["signature"] for f in found}
                self._met |= {f["element"] for f in found}
                self.progress.errors += trial.user_attrs.get("status") == "ERROR"
                self.progress.failing += bool(found)
            elif trial.user_attrs.get("status") in ("invalid", "unplannable"):
                self._count_unrun(trial.user_attrs["status"])
        done = self.progress.simulated
        self.log(f"search {self.spec.name} ({self.spec.sampler}): budget {self.spec.budget} evaluations, "
                 f"{done} finished already, {max(0, self.spec.budget - done)} to run on {self.pool.workers} "
                 f"{self.pool.name} worker(s)")

    def _loop(self) -> None:
        """Keeps every worker busy and one candidate ready beside them: the next one is asked, edited and generated
        while the runs go on, so a worker that ends gets it at once, before its run is read and told (TPE's
        constant liar treats the ready one as running)."""
        running: dict[Future[Outcome], Prepared] = {}
        ready: Prepared | None = None
        tries = 0
        cap = MAX_TRIES_PER_EVALUATION * self.spec.budget

        def wanted() -> bool:  # one more run (running, or ready beside them) fits the budget
            return self.progress.simulated + len(running) < self.spec.budget and tries < cap and not self.stop.is_set()

        while True:
            while len(running) < self.pool.workers and (ready is not None or wanted()):
                if ready is None:
                    tries += 1
                    ready = self._prepare()
                    if ready is None:
                        continue
                running[self.pool.submit(ready[2])] = ready
                ready = None
            while ready is None and running and wanted():
                tries += 1
                ready = self._prepare()
            if not running:
                if tries >= cap and self.progress.simulated < self.spec.budget:
                    self.log(f"search: stopped after {tries} candidates, most of them not valid: widen the domains")
                return
            done, _ = wait(running, timeout=0.5, return_when=FIRST_COMPLETED)
            finished = [(future, running.pop(future)) for future in done]
            if finished and ready is not None and not self.stop.is_set():
                # the ready candidate starts on the freed worker before the finished runs are read and told
                # (reading a failing run's streams for its failures' places takes a while); asks and tells keep
                # their order, so the candidates are the same as if it started after them
                running[self.pool.submit(ready[2])] = ready
                ready = None
            for future, (trial, candidate, task) in finished:
                self._finish(trial, candidate, task, future.result())

    def _prepare(self) -> Prepared | None:
        """The next candidate, generated and ready to run; None when it is not valid (told to the study)."""
        if self._designed < len(self._design) and not self.study.get_trials(deepcopy=False,
                                                                             states=(TrialState.WAITING,)):
            self.study.enqueue_trial(self._design[self._designed], user_attrs={DESIGN: self._designed},
                                     skip_if_exists=False)
            self._designed += 1
        trial = self.study.ask(self.space.distributions)
        key = self.key(trial.number)
        candidate = self.maker.make(key, self.space.edit(trial.params))
        if candidate.status != VALID:
            self._invalid(trial, candidate.status, candidate.problems)
            return None
        case_dir, problem = self.maker.generate(candidate)
        if problem is not None:
            self._error(trial, candidate, problem)
            return None
        task = self.task(key, candidate, case_dir)
        for name, value in (("key", key), ("seed", candidate.edit.seed), ("fault", candidate.edit.fault),
                            ("case", str(self.out / "candidates" / f"{key}.rei"))):
            trial.set_user_attr(name, value)
        return trial, candidate, task

    def task(self, key: str, candidate: Candidate, case_dir: Path, run_dir: Path | None = None) -> RunTask:
        spec = self.spec
        return RunTask(key=key, group="search", case=key, variant=spec.sampler, repetition=0,
                       seed=candidate.edit.seed, humans=spec.humans, fault=candidate.edit.fault,
                       controller=spec.controller, sut=spec.sut.to_dict() if spec.sut else None, mode="replay",
                       timeout=spec.timeout, report=False, case_dir=str(case_dir),
                       run_dir=str(run_dir or self.out / "runs" / key),
                       patterns=str(spec.patterns) if spec.patterns else None,
                       utilities=str(spec.utilities) if spec.utilities else None)

    def _count_unrun(self, status: str) -> None:
        """A candidate that did not run: refused by the validators ("invalid") or by the navigability check."""
        if status == "unplannable":
            self.progress.unplannable += 1
        else:
            self.progress.invalid += 1

    def _invalid(self, trial: optuna.Trial, status: str, problems: tuple[str, ...]) -> None:
        self._count_unrun(status)
        trial.set_user_attr("key", self.key(trial.number))
        trial.set_user_attr("status", status)
        trial.set_user_attr("problems", list(problems))
        # violated: TPE and NSGA-II rank it below every simulated trial, so the search learns where the valid cases
        # are; the other samplers see the penalty values
        trial.set_constraint(VALIDITY, 1.0)
        values = penalty(self.spec)
        self.study.tell(trial, values if len(values) > 1 else values[0])
        self.log(f"  {self.key(trial.number)}: {status}, not simulated: {problems[0]}")

    def _error(self, trial: optuna.Trial, candidate: Candidate, problem: str) -> None:
        """A valid candidate the generator could not make a case of (its JVM crashed, the disk is full): an
        evaluation in ERROR, as a run that crashed, counted in the budget; told as failed with no constraint, since
        nothing says the point is infeasible (a sampler told so would learn to avoid a valid region)."""
        self.progress.simulated += 1
        self.progress.errors += 1
        key = self.key(trial.number)
        attrs = {"key": key, "seed": candidate.edit.seed, "fault": candidate.edit.fault, "simulated": True,
                 "status": "ERROR", "error": problem}
        for name, value in attrs.items():
            trial.set_user_attr(name, value)
        self.study.tell(trial, state=TrialState.FAIL)
        self.log(self._line(trial.number, "ERROR", None, attrs))

    def _finish(self, trial: optuna.Trial, candidate: Candidate, task: RunTask, outcome: Outcome) -> None:
        if outcome.interrupted:
            return  # left running in the journal: asked again on resume
        result = make_result(task, outcome)
        write_result(task, result)
        self.progress.simulated += 1
        attrs: dict[str, Any] = {"simulated": True, "status": result.status, "wall": result.wall_time,
                                 "cpu": result.cpu_time, "utility": result.total_utility,
                                 "sim_duration": result.sim_duration}
        values = told = None
        new = False
        if result.status == "COMPLETED":
            summary = json.loads((Path(task.run_dir) / "summary.json").read_text(encoding="utf-8"))
            values = told = score(self.spec.objectives, summary, Path(task.run_dir))
            found = failures_of(summary, Path(task.run_dir), Path(task.case_dir), self.space.floor_at)
            attrs["failures"] = [f.to_dict() for f in found]
            attrs["values"] = values
            self._raw.append(_own(values))
            signatures = {f.signature for f in found}
            new = not signatures <= self._known
            if self.spec.diversity and signatures and not new:
                # only failures found before: told as the least interesting evaluation so far, so the sampler moves
                # on to other failures instead of refining this one (search.json keeps the run's own values)
                told = self._least_interesting()
                attrs["repeat"] = True
            self._known |= signatures
            self._met |= {f.element for f in found}
            trial.set_constraint(VALIDITY, 0.0)
            attrs["metrics"] = summary.get("metrics")
            self.progress.failing += bool(found)
        else:
            attrs["error"] = result.error
            self.progress.errors += 1
        for name, value in attrs.items():
            trial.set_user_attr(name, value)
        if told is None:
            self.study.tell(trial, state=TrialState.FAIL)
        else:
            self.study.tell(trial, told if len(told) > 1 else told[0])
        self.log(self._line(trial.number, result.status, values, {**attrs, "fault": task.fault}))
        if told is not None and not new and self._refine:
            self._refined(trial, task)

    def _refined(self, trial: optuna.Trial, task: RunTask) -> None:
        """Enqueues the evaluation's point with the nearest person's start moved onto the robot (rei.search.refine)
        when it found nothing new; a refinement is refined again up to DEPTH steps."""
        depth = int(trial.user_attrs.get(ATTR, 0))
        if depth >= DEPTH or self.stop.is_set():
            return
        step = refined(trial.params, self.space.distributions, encounters(Path(task.run_dir), Path(task.case_dir)),
                       self._met)
        if step is not None:
            params, encounter = step
            self.study.enqueue_trial(params, user_attrs={ATTR: depth + 1}, skip_if_exists=False)
            self.log(f"  refine {self.key(trial.number)}: {encounter.human} {encounter.margin:.2f} s off a meeting, "
                     f"start moved by {encounter.shift:+.2f} s")

    def _least_interesting(self) -> list[float]:
        told = []
        for i, o in enumerate(self.spec.objectives):
            own = [v[i] for v in self._raw if v[i] is not None]
            worst = ABSENT if o.direction == "minimize" else -ABSENT
            told.append((max if o.direction == "minimize" else min)(own) if own else worst)
        return told

    def _line(self, number: int, status: str, values: list[float] | None, attrs: dict[str, Any]) -> str:
        p = self.progress
        if status != "COMPLETED":
            how = f"ERROR {attrs.get('error')}"
        else:
            failed = ", ".join(f"{f['signature']} ({', '.join(f['requirements'])})"
                               for f in attrs.get("failures") or []) or "no failure"
            how = f"{_figures(self.spec, values)}; {failed}"
        best = self.best_text()
        if attrs.get("fault"):  # the run's fault as `rei run --fault` takes it (a searched fault's values)
            how = f"fault {attrs['fault']}; {how}"
        return (f"[{p.simulated}/{self.spec.budget}] {self.key(number)}: {how} | failing {p.failing}, "
                f"invalid {p.invalid}, {f'unplannable {p.unplannable}, ' if p.unplannable else ''}errors {p.errors}"
                f"{', best ' + best if best else ''}")

    def best_text(self) -> str:
        """The best value of each objective so far among the runs that have it ('-' when none has)."""
        if not self._raw:
            return ""
        parts = []
        for i, objective in enumerate(self.spec.objectives):
            best: float | None = None
            for values in self._raw:
                value = values[i]
                if value is not None and (best is None or better(objective, value, best)):
                    best = value
            parts.append(f"{objective.label} {'-' if best is None else f'{best:g}'}")
        return ", ".join(parts)


def _note_independent(space: Space, log: Callable[[str], None]) -> None:
    """CMA-ES models continuous values only: it draws each categorical parameter (every floor, a loop, an extra
    piece's type) independently at random, a fact its own warning would tell at every ask (switched off in
    make_sampler), so it is said once here."""
    categorical = [k for k, d in space.distributions.items() if isinstance(d, optuna.distributions.CategoricalDistribution)]
    if categorical:
        shown = ", ".join(categorical[:4]) + (f" and {len(categorical) - 4} more" if len(categorical) > 4 else "")
        log(f"note: cmaes draws the categorical parameters ({shown}) independently at random, learning only the "
            f"numeric ones; tpe or nsga2 learn both")


def _figures(spec: SearchSpec, values: list[float] | None) -> str:
    if values is None:
        return "-"
    return ", ".join(f"{o.label} {f'{v:g}' if present(v) else 'absent'}"
                     for o, v in zip(spec.objectives, values, strict=True))


def _own(values: list[float]) -> list[float | None]:
    return [v if present(v) else None for v in values]

