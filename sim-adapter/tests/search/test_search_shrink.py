# SPDX-License-Identifier: EPL-2.0
"""Shrinking with a fake maker and pool (search_fakes): which steps are simulated and which are kept."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from search_fakes import FakeMaker, FakePool, task_of
from test_search_space import DIAGRAM, p

from rei.search.failures import Failure
from rei.search.shrink import shrink
from rei.search.space import Space
from rei.search.spec import Parameter, Range

FAILURE = Failure("R1", "walker", "-", None, ("R1",), "hit", "R1: hit")  # no event evidence: its own kind


def space() -> Space:
    return Space([p("object", "bin1", "floor", None), p("seed", "", "value", Range(0, 100, integer=True)),
                  Parameter("fault", "", "rate", Range(0.0, 1.0), "s.yaml:1:1", "laser-noise")], DIAGRAM)


def test_moving_the_seed_or_fault_back_is_simulated_and_kept_only_when_it_still_fails(tmp_path: Path) -> None:
    # fails with seed 7 whatever the text and fault: the seed must stay, the fault and the bin may go
    pool = FakePool(lambda text, seed, fault: ["walker"] if seed == 7 else [])
    maker = FakeMaker(tmp_path, DIAGRAM)
    values = {"bin1.floor": "F_2_0", "seed": 7, "fault.rate": 0.5}
    result = shrink(FAILURE, values, space(), maker, pool, task_of, tmp_path, "f1", 10, log=lambda _: None,
                    run="original-run")
    assert [(t.seed, t.fault) for t in pool.ran] == [(7, "laser-noise,rate=0.5"), (0, "laser-noise,rate=0.5"),
                                                     (7, None)]
    assert result.values["seed"] == 7 and result.values["fault.rate"] is None
    assert result.removed == ["bin1"]
    assert (result.steps, result.kept) == (3, 2)
    assert result.run == pool.ran[-1].run_dir  # the run of the case written, not of an earlier step
    assert result.case is not None
    assert Path(result.case).read_text(encoding="utf-8").splitlines()[0].endswith("--seed 7")


def test_a_case_already_simulated_with_another_seed_is_simulated_again(tmp_path: Path) -> None:
    # the cache of cases shared between failures holds this text with seed 0, which passed: seed 7 still must run
    pool = FakePool(lambda text, seed, fault: ["walker"] if seed == 7 else [])
    maker = FakeMaker(tmp_path, DIAGRAM)
    values = {"bin1.floor": "F_2_0", "seed": 7, "fault.rate": None}
    seen: dict[Any, tuple[list[Failure], str]] = {}
    shrink(FAILURE, {**values, "seed": 0}, space(), maker, pool, task_of, tmp_path, "f1", 10, log=lambda _: None,
           seen=seen)
    before = len(pool.ran)
    result = shrink(FAILURE, values, space(), maker, pool, task_of, tmp_path, "f2", 10, log=lambda _: None,
                    seen=seen, run="original-run")
    assert result.removed == ["bin1"] and result.values["seed"] == 7
    assert len(pool.ran) > before


def test_nothing_kept_leaves_the_failures_own_run(tmp_path: Path) -> None:
    pool = FakePool(lambda text, seed, fault: ["walker"] if seed == 7 and "F_2_0" in text and fault else [])
    result = shrink(FAILURE, {"bin1.floor": "F_2_0", "seed": 7, "fault.rate": 0.5}, space(),
                    FakeMaker(tmp_path, DIAGRAM), pool, task_of, tmp_path, "f1", 10, log=lambda _: None,
                    run="original-run")
    assert (result.kept, result.removed, result.run) == (0, [], "original-run")


def collided(*requirements: str) -> list[str | dict[str, Any]]:
    """One collision with the walker, failing ``requirements``: the verdicts as summary.json has them."""
    return [{"requirement": r, "status": "fail", "message": "hit", "evidence": [
        {"text": "collision with walker", "t": 2.0, "signal": "SIG_OBJECT_COLLISION_BEGIN", "object": "walker"}]}
        for r in requirements]


def test_a_step_still_fails_the_same_way_only_with_every_requirement_the_event_violated(tmp_path: Path) -> None:
    # the collision fails both requirements with seed 7; with seed 0 it is still a collision with the walker, but
    # one that fails MISSION_SIMPLE alone: not the failure being shrunk, so the seed stays
    both = ("MISSION_SIMPLE", "MISSION_WITH_HUMAN_TRAJECTORY")
    pool = FakePool(lambda text, seed, fault: collided(*both) if seed == 7 else collided("MISSION_SIMPLE"))
    event = Failure("COLLISION", "walker", "-", 2.0, both, "collision with walker", "hit")
    result = shrink(event, {"bin1.floor": "F_2_0", "seed": 7, "fault.rate": None}, space(),
                    FakeMaker(tmp_path, DIAGRAM), pool, task_of, tmp_path, "f1", 10, log=lambda _: None,
                    run="original-run")
    assert [t.seed for t in pool.ran] == [7, 0]  # the bin removed, then the seed moved back
    assert result.removed == ["bin1"] and result.values["seed"] == 7 and result.kept == 1


def test_a_step_that_could_not_be_generated_is_said_and_not_counted_as_a_simulation(tmp_path: Path) -> None:
    """A generator that fails (its warm JVM's jar replaced, a full disk) made the shrink give up silently, and the
    terminal said 'in 2 simulation(s)' with no run behind either."""
    pool = FakePool(lambda text, seed, fault: ["walker"] if seed == 7 else [])
    maker = FakeMaker(tmp_path, DIAGRAM, broken=("shrink-f1-1",))
    lines: list[str] = []
    result = shrink(FAILURE, {"bin1.floor": "F_2_0", "seed": 7, "fault.rate": 0.5}, space(), maker, pool, task_of,
                    tmp_path, "f1", 10, log=lines.append, run="original-run")
    assert lines[0] == "  shrink R1/walker/-: a step not simulated: shrink-f1-1 could not be generated (exit 1): disk full"
    assert result.steps == len(pool.ran), "a step counts as a simulation only when it ran"
