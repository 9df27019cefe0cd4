# SPDX-License-Identifier: EPL-2.0
"""Stand-ins for the search's two expensive parts, for unit tests of its logic: a candidate maker that turns an edit
into text without the room editor's JVM, and a pool whose runs write only a summary.json, failing by a rule of the
case's text, seed and fault (the real ones run in tests/search/test_search_e2e.py)."""

from __future__ import annotations

import json
from collections.abc import Callable
from concurrent.futures import Future
from pathlib import Path
from typing import Any

from rei.campaign.plan import RunTask
from rei.campaign.supervise import Outcome
from rei.search.candidates import VALID, Candidate, CandidateMaker
from rei.search.reproduce import RunOptions
from rei.search.space import Edit

#: Whether a run of (text, seed, fault) fails, as failed verdicts: an evidence object (a verdict R1 naming it, no
#: event), or a verdict as summary.json has it (empty: it passes).
Rule = Callable[[str, int, "str | None"], list["str | dict[str, Any]"]]


class FakeMaker:
    """Candidates whose text is their edit operations; ``broken``: keys whose generation fails."""

    write = CandidateMaker.write

    def __init__(self, out: Path, diagram: dict[str, Any], broken: tuple[str, ...] = ()) -> None:
        self.out, self.diagram, self.palette, self.broken = out, diagram, [], broken
        self.made: list[Candidate] = []
        self.runs = RunOptions()  # read by CandidateMaker.write for each case's `rei run` line (nav, humans)
        self._base_folder = out  # read by CandidateMaker.write (the fake's texts import no catalogue)
        self.base_text = ""  # no crowd or group: nothing for rei.search.space to read or validate

    def validate(self, text: str) -> list[dict[str, Any]]:
        return []

    def make(self, key: str, edit: Edit) -> Candidate:
        candidate = Candidate(key, edit, VALID, json.dumps(edit.operations, sort_keys=True) + "\n")
        self.made.append(candidate)
        return candidate

    def generate(self, candidate: Candidate) -> tuple[Path, str | None]:
        target = self.out / "cases" / candidate.key
        if candidate.key in self.broken:
            return target, f"{candidate.key} could not be generated (exit 1): disk full"
        self.write(candidate)
        target.mkdir(parents=True, exist_ok=True)
        (target / "case.json").write_text(json.dumps({"text": candidate.text, "seed": candidate.edit.seed,
                                                      "fault": candidate.edit.fault}), encoding="utf-8")
        return target, None

    def close(self) -> None:
        pass


class FakePool:
    """Runs at once in the caller's thread: summary.json with one failed verdict per object ``rule`` names (or the
    verdicts it gives)."""

    name = "fake"
    workers = 1

    def __init__(self, rule: Rule) -> None:
        self.rule = rule
        self.ran: list[RunTask] = []

    def submit(self, task: RunTask) -> Future[Outcome]:
        self.ran.append(task)
        case = json.loads((Path(task.case_dir) / "case.json").read_text(encoding="utf-8"))
        objects = self.rule(case["text"], case["seed"], case["fault"])
        run_dir = Path(task.run_dir)
        run_dir.mkdir(parents=True, exist_ok=True)
        (run_dir / "task.json").write_text(json.dumps(task.to_dict()), encoding="utf-8")  # as the supervisor does
        verdicts = [o if isinstance(o, dict) else
                    {"requirement": "R1", "status": "fail", "message": "hit", "evidence": [{"object": o}]}
                    for o in objects]
        summary = {"status": "COMPLETED", "total_utility": -10.0 if objects else 10.0, "verdicts": verdicts,
                   "sim_duration": 1.0, "metrics": {}}
        (run_dir / "summary.json").write_text(json.dumps(summary), encoding="utf-8")
        future: Future[Outcome] = Future()
        future.set_result(Outcome(task.key, 0, False, False, 0.1, 0.1, "", "here"))
        return future

    def close(self) -> None:
        pass


def task_of(key: str, candidate: Candidate, case_dir: Path, run_dir: Path) -> RunTask:
    return RunTask(key=key, group="search", case=key, variant="fake", repetition=0, seed=candidate.edit.seed,
                   humans=True, fault=candidate.edit.fault, controller="reference", mode="replay", timeout=60.0,
                   report=False, case_dir=str(case_dir), run_dir=str(run_dir))
