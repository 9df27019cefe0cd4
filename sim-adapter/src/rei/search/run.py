# SPDX-License-Identifier: EPL-2.0
"""``rei search`` from spec to report: the pool, the search, shrinking each distinct failure, the outputs."""

from __future__ import annotations

import json
import threading
from collections.abc import Callable
from pathlib import Path
from typing import Any

import optuna

from rei.campaign.spec import moves_people
from rei.search.failures import Failure, distinct
from rei.search.outputs import baseline_document, records, write_outputs
from rei.search.pool import LocalPool, Pool, RayPool
from rei.search.shrink import Case, failure_id, shrink
from rei.search.spec import SearchSpec
from rei.search.study import JOURNAL, Search, journal, open_study

SHRUNK = "shrunk.json"
RANDOM = "random"
#: The study's user attribute holding the budget of its last invocation (a baseline's run shows the search's).
BUDGET = "budget"


def make_pool(workers: int, ray: str | None, out: Path, stop: threading.Event, router: bool = False,
              people: bool = False) -> Pool:
    """The local pool, or with ``ray`` the Ray pool (rei.campaign.backends.RayUnavailableError: it can not be, or a
    node cannot run the runs); ``router``: the runs start a WAMP router (an external SUT), ``people``: they move
    people who see the robot (JuPedSim), which its nodes then need."""
    return RayPool(ray, workers, stop, router=router, people=people) if ray else LocalPool(workers, out / "runs",
                                                                                             stop)


def run_search(spec: SearchSpec, out: Path, *, workers: int = 1, ray: str | None = None,
               stop: threading.Event | None = None, shrink_failures: bool = True,
               log: Callable[[str], None] = print) -> dict[str, Any]:
    """Runs (or resumes) the search and writes its outputs; search.json's document, with ``interrupted``."""
    out = out.resolve()
    out.mkdir(parents=True, exist_ok=True)
    stop = stop or threading.Event()
    # a cluster is reached before anything else, so a wrong address fails at once; the local pool starts with the
    # first run (a finished search that only rewrites its outputs starts no JVM)
    # an external SUT's runs start a router, people who see the robot JuPedSim's server: the nodes are checked for
    # them as a campaign's are
    people = spec.humans and moves_people((spec.case,) if spec.case else (), spec.rooms)
    pool: Pool = make_pool(workers, ray, out, stop, router=spec.sut is not None, people=people) if ray else _LazyPool(
        lambda: make_pool(workers, None, out, stop), workers, "local")
    try:
        search = Search(spec, out, pool, stop, log)
    except BaseException:
        stop.set()
        pool.close()
        raise
    try:
        progress = search.run()
        spec = search.spec  # with its base case (a ``rooms:`` spec's, generated into OUT)
        search.study.set_user_attr(BUDGET, spec.budget)
        # a random search in the folder of another sampler's search is that search's baseline (docs/search.md)
        searched = _searched(out) if spec.sampler == RANDOM else None
        if searched is not None:
            document = _baseline_run(spec, out, search.study, searched, log)
        else:
            shrunk = _load(out / SHRUNK)
            if shrink_failures and not progress.interrupted and spec.shrink_budget > 0:
                shrunk = _shrink_all(search, shrunk, log)
            baseline = None
            if spec.sampler != RANDOM and _has_study(out, RANDOM):
                baseline = _baseline(open_study(out, spec.with_options(sampler=RANDOM)), out)
            document = write_outputs(spec, out, search.study, shrunk, baseline)
            _run_reports(document, log)
            _report(spec, out, document, log)
    finally:
        # set before closing: the pool waits for its running workers, which stop on it instead of running out their
        # timeout (an exception or Ctrl-C while shrinking or writing the outputs gets here with it unset)
        stop.set()
        search.close()
        search.pool.close()
    document["interrupted"] = progress.interrupted
    return document


def _baseline_run(spec: SearchSpec, out: Path, study: optuna.Study, searched: str,
                  log: Callable[[str], None]) -> dict[str, Any]:
    """The outputs of a random baseline beside the ``searched`` sampler's search: search.json and search.html
    rewritten with the search's own figures (its study, budget and shrunk cases) and this baseline's beside them;
    verdicts.xml, shrunk.json and shrunk/ stay the search's (a baseline is not shrunk: it is there to compare).
    The baseline's document (its counts and failures), for `rei search`'s summary and exit code."""
    baseline = _baseline(study, out)
    main = spec.with_options(sampler=searched)
    stored = open_study(out, main)
    main = main.with_options(budget=int(stored.user_attrs.get(BUDGET) or main.budget))
    document = write_outputs(main, out, stored, _load(out / SHRUNK), baseline, verdicts=False)
    _report(main, out, document, log)
    log(f"random baseline of the {searched} search in {out}: its figures are search.json's baseline and "
        f"search.html's beside the search's; the search's own outputs are kept")
    return baseline


def _baseline(study: optuna.Study, out: Path) -> dict[str, Any]:
    return baseline_document(study, out, study.user_attrs.get(BUDGET))


def _searched(out: Path) -> str | None:
    """The sampler of the search in ``out`` a random search is the baseline of: the one search.json shows, else
    the first other sampler with trials in the journal; None when there is none (the random search is the
    folder's own search)."""
    if not (out / JOURNAL).is_file():
        return None
    others = [s.study_name for s in optuna.get_all_study_summaries(journal(out), include_best_trial=False)
              if s.study_name != RANDOM and s.n_trials]
    shown = _load(out / "search.json").get("sampler")
    return shown if shown in others else next(iter(others), None)


def _shrink_all(search: Search, shrunk: dict[str, Any], log: Callable[[str], None]) -> dict[str, Any]:
    evaluations = records(search.study, search.out)
    completed = [r for r in evaluations if r["status"] == "COMPLETED"]
    seen: dict[Case, tuple[list[Failure], str]] = {}  # cases simulated while shrinking, shared between failures
    groups = distinct(completed)
    # entries of signatures no evaluation has (a journal of an earlier rei, whose failures were per requirement, was
    # shrunk by those): dropped, its events are shrunk by their own
    stale = set(shrunk) - {group.failure.signature for group in groups}
    if stale:
        log(f"shrunk.json: {len(stale)} entry(ies) of failures no evaluation shows now (an earlier rei search's, "
            f"one per requirement) dropped: {', '.join(sorted(stale))}")
        shrunk = {key: value for key, value in shrunk.items() if key not in stale}
        _write_shrunk(search.out, shrunk)
    for group in groups:  # named by signature, not rank: a resumed search may rank a new one higher
        signature = group.failure.signature
        if signature in shrunk:
            continue
        first = next(r for r in completed if r["key"] == group.first)
        failure = next(Failure.from_dict(f) for f in first["failures"] if f["signature"] == signature)
        log(f"shrinking {signature} (from {group.first})")
        result = shrink(failure, first["params"], search.space, search.maker, search.pool,
                        lambda key, cand, case_dir, run_dir: search.task(key, cand, case_dir, run_dir), search.out,
                        failure_id(signature), search.spec.shrink_budget, log, seen, first["run"])
        shrunk[signature] = result.to_dict()
        _write_shrunk(search.out, shrunk)
        log(f"  shrunk: {result.kept} reduction(s) kept in {result.steps} simulation(s), removed "
            f"{', '.join(result.removed) or 'nothing'}{f', fault {result.fault}' if result.fault else ''}: "
            f"{result.case}")
    return shrunk


def _write_shrunk(out: Path, shrunk: dict[str, Any]) -> None:
    (out / SHRUNK).write_text(json.dumps(shrunk, indent=2, default=str) + "\n", encoding="utf-8")


def _run_reports(document: dict[str, Any], log: Callable[[str], None]) -> None:
    """The run report of each distinct failure's first run (the others' are not written: a run report costs
    about as much as the evaluator, and a passing run's is rarely read; `rei report OUT/runs/KEY` writes one)."""
    from rei.report import write_report

    for failure in document["failures"]:
        run_dir = Path(failure["run"])
        if (run_dir / "report.html").is_file():
            continue
        try:
            case_dir = Path(json.loads((run_dir / "task.json").read_text(encoding="utf-8"))["case_dir"])
            write_report(run_dir, case_dir)
        except (OSError, ValueError, KeyError) as error:
            log(f"search: no report for {run_dir.name}: {error}")


def _report(spec: SearchSpec, out: Path, document: dict[str, Any], log: Callable[[str], None]) -> None:
    from rei.search.report import write_search_report

    try:
        write_search_report(out, document)
    except (OSError, ValueError) as error:  # the figures are in search.json whatever happens to the page
        log(f"search: search.html could not be written: {error}")


def _has_study(out: Path, name: str) -> bool:
    if not (out / JOURNAL).is_file():
        return False
    return any(s.study_name == name for s in optuna.get_all_study_summaries(journal(out), include_best_trial=False))


def _load(path: Path) -> dict[str, Any]:
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}


class _LazyPool:
    """Starts the pool (fork server, warm monitor JVM, Ray) at the first run, not for a search that has nothing
    left to run."""

    def __init__(self, start: Callable[[], Pool], workers: int, name: str) -> None:
        self._start, self.workers, self.name = start, workers, name
        self._pool: Pool | None = None

    def _get(self) -> Pool:
        if self._pool is None:
            self._pool = self._start()
            self.workers = self._pool.workers
        return self._pool

    def submit(self, task: Any) -> Any:
        return self._get().submit(task)

    def close(self) -> None:
        if self._pool is not None:
            self._pool.close()
