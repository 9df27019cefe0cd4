# SPDX-License-Identifier: EPL-2.0
"""The Ray backend's tries, on a real local Ray instance with a task that stands in for a run and fails as a lost
one does: a task lost once is tried again and recorded once with its try, one lost on every try is an ERROR that
says so, and a run that crashed in its worker is its result, not tried again."""

from __future__ import annotations

import threading
from pathlib import Path
from typing import Any

from rei.campaign.backends import RayBackend
from rei.campaign.plan import RunTask
from rei.campaign.supervise import Outcome


def _task(tmp_path: Path, key: str) -> RunTask:
    return RunTask(key=key, group="g", case="c", variant="v", repetition=0, seed=1, humans=False, fault=None,
                   controller="nav", mode="replay", timeout=60.0, report=False, case_dir=str(tmp_path / "case"),
                   run_dir=str(tmp_path / "runs" / key))


def test_lost_tasks_are_tried_again_and_recorded_once(tmp_path: Path) -> None:
    (tmp_path / "case").mkdir()
    (tmp_path / "case" / "world.json").write_text("{}", encoding="utf-8")
    tasks = [_task(tmp_path, key) for key in ("once-lost", "always-lost", "crashes")]
    logs: list[str] = []
    backend = RayBackend("local", workers=1, attempts=3, log=logs.append)
    try:
        import ray

        def stand_in(task: dict[str, Any], case: dict[str, bytes], extra: dict[str, bytes], fields: dict[str, Any],
                     attempt: int, needs: tuple[bool, bool] = (False, False)) -> dict[str, Any]:
            assert case == {"world.json": b"{}"}  # the case folder arrived
            if task["key"] == "always-lost" or (task["key"] == "once-lost" and attempt == 1):
                raise ConnectionError("the node is gone")
            code = 3 if task["key"] == "crashes" else 0
            outcome = Outcome(task["key"], code, False, False, 1.0, 1.0, "boom", "node", attempt)
            return {"outcome": outcome.to_dict(), "files": [("summary.json", [ray.put(b"{}")])], "work": "/nowhere"}

        backend._remote = ray.remote(num_cpus=1, max_retries=0)(stand_in)
        seen: list[tuple[str, int, str | None]] = []
        backend.run(tasks, lambda task, outcome: seen.append((task.key, outcome.attempt, outcome.error)),
                    threading.Event())
    finally:
        backend.close()
    errors = {key: error for key, _, error in seen}
    assert sorted((key, attempt) for key, attempt, _ in seen) == [("always-lost", 3), ("crashes", 1),
                                                                    ("once-lost", 2)], seen  # each once
    assert (errors["always-lost"] or "").startswith(
        "ray task lost on each of 3 tries: RayTaskError(ConnectionError): ray::stand_in()"), errors
    assert errors["crashes"] == "crashed: the worker exited with 3: boom" and errors["once-lost"] is None
    assert sum("trying again" in line for line in logs) == 3, logs  # once-lost once, always-lost twice
    assert (tmp_path / "runs" / "once-lost" / "summary.json").read_bytes() == b"{}"
    assert not (tmp_path / "runs" / "always-lost").exists()

