# SPDX-License-Identifier: EPL-2.0
"""The search loop on a fake maker and pool (search_fakes): what the study is told and what search.json says for
each kind of candidate."""

from __future__ import annotations

import shutil
import threading
from pathlib import Path
from typing import Any

import pytest
from optuna.trial import TrialState
from search_fakes import FakeMaker, FakePool
from test_search_space import DIAGRAM

from rei.run.jvm import JvmResult
from rei.search import candidates, study
from rei.search.candidates import VALID, Candidate, CandidateMaker
from rei.search.failures import OldRecordError, distinct
from rei.search.outputs import records
from rei.search.reproduce import RunOptions
from rei.search.space import Edit
from rei.search.spec import SearchSpec, parse_search_spec

SPEC = """\
name: fake
case: case.rei
seed: 1
budget: 3
sampler: random
parameters:
  - {object: bin1, floor: any}
  - {seed: [0, 100]}
objectives:
  - utility
"""


def spec(folder: Path, text: str = SPEC) -> SearchSpec:
    (folder / "case.rei").write_text("testcase T {}\n", encoding="utf-8")
    return parse_search_spec(text, base=folder, file="s.yaml")


def search(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, pool: FakePool, broken: tuple[str, ...] = (),
           text: str = SPEC) -> study.Search:
    out = tmp_path / "out"
    monkeypatch.setattr(study, "CandidateMaker",
                        lambda case, folder, log=print, **_: FakeMaker(folder, DIAGRAM, broken))
    return study.Search(spec(tmp_path, text), out, pool, threading.Event(), log=lambda _: None)


def constraints(trial: Any) -> list[float]:
    return [v for k, v in trial.system_attrs.items() if "constraint" in k]


def test_a_generator_failure_is_an_evaluation_in_error_not_an_infeasible_point(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    pool = FakePool(lambda text, seed, fault: [])
    s = search(tmp_path, monkeypatch, pool, broken=("random-0001",))
    progress = s.run()
    assert (progress.simulated, progress.errors, progress.invalid) == (3, 1, 0)
    assert len(pool.ran) == 2
    trial = s.study.trials[1]
    assert trial.state == TrialState.FAIL
    assert constraints(trial) == []  # not told as infeasible
    assert constraints(s.study.trials[0]) == [0.0]  # a simulated one is feasible
    record = records(s.study, s.out)[1]
    assert (record["status"], record["error"]) == ("ERROR", "random-0001 could not be generated (exit 1): disk full")
    assert not (s.out / "candidates" / "random-0001.rei").exists()


def test_the_real_maker_leaves_no_candidate_file_when_generation_fails(tmp_path: Path,
                                                                      monkeypatch: pytest.MonkeyPatch) -> None:
    def no_server(*_: Any) -> Any:
        raise OSError("no warm JVM here")

    monkeypatch.setattr(candidates, "JarServer", no_server)
    monkeypatch.setattr(candidates, "run_jar", lambda *_, **__: JvmResult(1, 0.1, 0.1, "No space left on device"))
    maker = CandidateMaker.__new__(CandidateMaker)  # the engine is not needed to generate
    maker.out, maker._generator, maker._base_folder, maker.runs = tmp_path, None, tmp_path, RunOptions()
    _, problem = maker.generate(Candidate("tpe-0001", Edit((), 0, None), VALID, "testcase T {}\n"))
    assert problem == "tpe-0001.rei could not be generated (exit 1): No space left on device"
    assert not (tmp_path / "candidates" / "tpe-0001.rei").exists()


ABSENT_SPEC = SPEC.replace("  - utility\n", "  - {metric: clearance_humans_min}\n  - utility\n")


def test_a_value_a_run_does_not_have_is_no_best_value(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # the fake runs have no metrics: no clearance to humans, scored 10^6 for the sampler but shown as absent
    lines: list[str] = []
    s = search(tmp_path, monkeypatch, FakePool(lambda text, seed, fault: []), text=ABSENT_SPEC)
    s.log = lines.append
    s.run()
    assert s.study.trials[0].values[0] == 1e6  # what the sampler is told
    assert lines and all("1e+06" not in line for line in lines)
    assert "metric:clearance_humans_min absent" in lines[-1]
    assert lines[-1].endswith("best metric:clearance_humans_min -, utility 10")


# -- the failure archive (``diversity``) and TPE's initial design ----------------------------------------------------

def even_seed_fails(text: str, seed: int, fault: str | None) -> list[str]:
    return ["wall"] if seed % 2 == 0 else []  # one failure, R1/wall/-, found again and again


def told(trial: Any) -> float:
    return float(trial.values[0])


def test_a_run_that_only_repeats_a_known_failure_is_told_the_least_interesting_value(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    s = search(tmp_path, monkeypatch, FakePool(even_seed_fails), text=SPEC.replace("budget: 3", "budget: 12"))
    s.run()
    trials = [t for t in s.study.trials if t.user_attrs.get("simulated")]
    failing = [t for t in trials if t.user_attrs["failures"]]
    assert len(failing) >= 2 and any(not t.user_attrs["failures"] for t in trials)  # the rule had both kinds
    assert not failing[0].user_attrs.get("repeat") and told(failing[0]) == -10.0  # found: its own utility
    for t in failing[1:]:  # found again: the worst utility seen so far (a passing run's 10 once there was one)
        own_so_far = [x.user_attrs["values"][0] for x in trials if x.number <= t.number]
        assert t.user_attrs["repeat"] and t.user_attrs["values"] == [-10.0]
        assert told(t) == max(own_so_far)
    assert any(told(t) == 10.0 for t in failing[1:])
    for record in records(s.study, s.out):  # search.json keeps the runs' own values
        assert record["values"] == ([-10.0] if record["failures"] else [10.0])


def test_without_diversity_every_run_is_told_its_own_value(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    text = SPEC.replace("budget: 3", "budget: 8") + "diversity: false\n"
    s = search(tmp_path, monkeypatch, FakePool(even_seed_fails), text=text)
    s.run()
    simulated = [t for t in s.study.trials if t.user_attrs.get("simulated")]
    assert sum(bool(t.user_attrs["failures"]) for t in simulated) >= 2
    assert all(told(t) == t.user_attrs["values"][0] and not t.user_attrs.get("repeat") for t in simulated)


def test_a_resumed_search_rebuilds_the_archive_from_the_journal(tmp_path: Path,
                                                                monkeypatch: pytest.MonkeyPatch) -> None:
    first = search(tmp_path, monkeypatch, FakePool(even_seed_fails), text=SPEC.replace("budget: 3", "budget: 6"))
    first.run()
    found = {f["signature"] for t in first.study.trials for f in t.user_attrs.get("failures") or []}
    assert found == {"R1/wall/-"}
    before = len(first.study.trials)
    resumed = search(tmp_path, monkeypatch, FakePool(even_seed_fails), text=SPEC.replace("budget: 3", "budget: 14"))
    resumed.run()
    assert resumed._known == found
    later = [t for t in resumed.study.trials[before:] if t.user_attrs.get("failures")]
    # the first of them too: its failure is known from the first invocation's runs, not from this one's
    assert later and all(t.user_attrs["repeat"] for t in later)


def collided(*requirements: str) -> list[str | dict[str, Any]]:
    """One collision with the walker failing ``requirements``, as summary.json's verdicts have it."""
    return [{"requirement": r, "status": "fail", "message": "hit", "evidence": [
        {"text": "collision with walker", "t": 2.0, "signal": "SIG_OBJECT_COLLISION_BEGIN", "object": "walker"}]}
        for r in requirements]


BOTH = ("MISSION_SIMPLE", "MISSION_WITH_HUMAN_TRAJECTORY")


def test_the_same_collision_failing_one_more_requirement_is_nothing_new(tmp_path: Path,
                                                                        monkeypatch: pytest.MonkeyPatch) -> None:
    # the first collision fails MISSION_SIMPLE alone, the later ones both requirements: the same event, so every
    # later one only repeats it (by requirement, the second requirement was new once)
    failing = []

    def rule(text: str, seed: int, fault: str | None) -> list[str | dict[str, Any]]:
        if seed % 2:
            return []
        failing.append(seed)
        return collided("MISSION_SIMPLE") if len(failing) == 1 else collided(*BOTH)

    s = search(tmp_path, monkeypatch, FakePool(rule), text=SPEC.replace("budget: 3", "budget: 12"))
    s.run()
    hits = [t for t in s.study.trials if t.user_attrs.get("failures")]
    assert len(hits) >= 2 and s._known == {"COLLISION/walker/-"}
    assert not hits[0].user_attrs.get("repeat") and all(t.user_attrs["repeat"] for t in hits[1:])
    [failure] = records(s.study, s.out)[hits[0].number]["failures"]
    assert failure["requirements"] == ["MISSION_SIMPLE"]
    [group] = distinct([r for r in records(s.study, s.out) if r["status"] == "COMPLETED"])
    assert group.requirements == BOTH and len(group.keys) == len(hits)


class PerRequirement:
    """A failure as an earlier rei search recorded it in the journal: one per failed requirement."""

    def __init__(self, requirement: str, element: str) -> None:
        self.requirement, self.element = requirement, element
        self.signature = f"{requirement}/{element}/-"

    def to_dict(self) -> dict[str, Any]:
        return {"requirement": self.requirement, "element": self.element, "place": "-", "t": 2.0,
                "message": "hit", "signature": self.signature}


def per_requirement(summary: dict[str, Any], *_: Any) -> list[PerRequirement]:
    return [PerRequirement(v["requirement"], v["evidence"][0]["object"]) for v in summary["verdicts"]]


def test_a_journal_recorded_per_requirement_resumes_counting_events(tmp_path: Path,
                                                                    monkeypatch: pytest.MonkeyPatch) -> None:
    def rule(text: str, seed: int, fault: str | None) -> list[str | dict[str, Any]]:
        return collided(*BOTH) if seed % 2 == 0 else []

    text = SPEC.replace("budget: 3", "budget: 6")
    with monkeypatch.context() as earlier:
        earlier.setattr(study, "failures_of", per_requirement)
        earlier.setattr(study.Search, "_line", lambda *_: "")  # its progress line read its own records
        first = search(tmp_path, earlier, FakePool(rule), text=text)
        first.run()
    recorded = {f["signature"] for t in first.study.trials for f in t.user_attrs.get("failures") or []}
    assert recorded == {"MISSION_SIMPLE/walker/-", "MISSION_WITH_HUMAN_TRAJECTORY/walker/-"}  # two of one event
    before = len(first.study.trials)
    resumed = search(tmp_path, monkeypatch, FakePool(rule), text=text.replace("budget: 6", "budget: 12"))
    resumed.run()
    assert resumed._known == {"COLLISION/walker/-"}  # found again from the earlier runs' folders
    later = [t for t in resumed.study.trials[before:] if t.user_attrs.get("failures")]
    assert later and all(t.user_attrs["repeat"] for t in later)
    evaluations = [r for r in records(resumed.study, resumed.out) if r["status"] == "COMPLETED"]
    [group] = distinct(evaluations)  # the earlier evaluations and the new ones: one distinct failure
    assert group.failure.signature == "COLLISION/walker/-" and group.requirements == BOTH
    assert len(group.keys) == sum(bool(r["failures"]) for r in evaluations) > len(later)


def test_a_journal_recorded_per_requirement_without_its_runs_is_refused(tmp_path: Path,
                                                                        monkeypatch: pytest.MonkeyPatch) -> None:
    def rule(text: str, seed: int, fault: str | None) -> list[str | dict[str, Any]]:
        return collided(*BOTH) if seed % 2 == 0 else []

    text = SPEC.replace("budget: 3", "budget: 6")
    with monkeypatch.context() as earlier:
        earlier.setattr(study, "failures_of", per_requirement)
        earlier.setattr(study.Search, "_line", lambda *_: "")  # its progress line read its own records
        first = search(tmp_path, earlier, FakePool(rule), text=text)
        first.run()
    failing = next(t.user_attrs["key"] for t in first.study.trials if t.user_attrs.get("failures"))
    shutil.rmtree(tmp_path / "out" / "runs" / failing)
    resumed = search(tmp_path, monkeypatch, FakePool(rule), text=text.replace("budget: 6", "budget: 12"))
    with pytest.raises(OldRecordError, match=rf"runs/{failing}: this evaluation was recorded by an earlier rei "
                                             r"search, one failure per requirement"):
        resumed.run()


TPE_SPEC = SPEC.replace("sampler: random", "sampler: tpe").replace("budget: 3", "budget: 40")


def test_tpe_starts_from_a_sobol_design_not_from_random_samplings_draws(tmp_path: Path,
                                                                         monkeypatch: pytest.MonkeyPatch) -> None:
    from rei.search.design import sobol_design, startup_trials

    s = search(tmp_path, monkeypatch, FakePool(even_seed_fails), text=TPE_SPEC.replace("budget: 40", "budget: 10"))
    design = sobol_design(s.space.distributions, startup_trials(40), 1)
    assert len(design) == 8 and design == sobol_design(s.space.distributions, 8, 1)  # deterministic
    assert len({d["seed"] for d in design}) == 8  # spread over the range, no repeated draw
    s.run()
    asked = [t.params for t in s.study.trials]
    assert asked[:2] == sobol_design(s.space.distributions, startup_trials(10), 1)
    (tmp_path / "r").mkdir()
    randomly = search(tmp_path / "r", monkeypatch, FakePool(even_seed_fails))
    randomly.run()
    assert asked[0] != randomly.study.trials[0].params  # the same seed no longer gives random's first point


def test_a_resumed_tpe_search_does_not_enqueue_its_design_again(tmp_path: Path,
                                                                 monkeypatch: pytest.MonkeyPatch) -> None:
    from rei.search.design import sobol_design

    first = search(tmp_path, monkeypatch, FakePool(even_seed_fails), text=TPE_SPEC)
    design = sobol_design(first.space.distributions, 8, 1)
    submit = first.pool.submit

    def stop_after_five(task: Any) -> Any:  # stopped inside the design: 5 of its 8 points ran
        if len(first.pool.ran) == 4:
            first.stop.set()
        return submit(task)

    monkeypatch.setattr(first.pool, "submit", stop_after_five)
    first.run()
    assert [t.params for t in first.study.trials if t.user_attrs.get("simulated")] == design[:5]
    resumed = search(tmp_path, monkeypatch, FakePool(even_seed_fails), text=TPE_SPEC.replace("budget: 40", "budget: 12"))
    resumed.run()
    asked = [t.params for t in resumed.study.trials if t.user_attrs.get("simulated")]
    assert len(asked) == 12 and asked[:8] == design  # the rest of the design, once, then TPE's own points
    assert all(params not in design for params in asked[8:])


class LatePool(FakePool):
    """FakePool's runs, each ending a little later in a thread of its own (the ready candidate is waiting then)."""

    def submit(self, task: Any) -> Any:
        from concurrent.futures import Future

        done = super().submit(task)
        late: Future[Any] = Future()
        threading.Timer(0.05 * (1 + len(self.ran) % 3), lambda: late.set_result(done.result())).start()
        return late


def test_with_one_worker_the_candidates_do_not_depend_on_when_runs_end(tmp_path: Path,
                                                                      monkeypatch: pytest.MonkeyPatch) -> None:
    # the ready candidate starts before the finished run is told; asks and tells keep their order, so TPE asks for
    # the same points whether a run ends before its successor is ready or after
    text = TPE_SPEC.replace("budget: 40", "budget: 14")
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    at_once = search(tmp_path / "a", monkeypatch, FakePool(even_seed_fails), text=text)
    at_once.run()
    later = search(tmp_path / "b", monkeypatch, LatePool(even_seed_fails), text=text)
    later.run()
    assert len(at_once.study.trials) == len(later.study.trials) == 14
    assert [t.params for t in at_once.study.trials] == [t.params for t in later.study.trials]
    assert [t.values for t in at_once.study.trials] == [t.values for t in later.study.trials]
