# SPDX-License-Identifier: EPL-2.0
"""Where a search's evaluations run: the campaign's backends, one run at a time per worker, as futures.

A search asks for the next candidate as soon as a worker is free (Optuna's ask/tell), so it needs single runs
it can wait on, where a campaign hands its backend the whole plan. Both pools run the campaign's ``supervise``
(a process per run, its timeout, its process group stopped with it): locally forked from one
rei.campaign.forkserver with one warm monitor JVM for the replays, as the local campaign backend does; on Ray
through the campaign's Ray backend, one task per run: the candidate's case goes to a node as bytes and its run
folder comes back into OUT (rei.campaign.transfer), a task lost with its node is tried again, and the study's
journal never leaves this machine.
"""

from __future__ import annotations

import contextlib
import threading
from concurrent.futures import Future, ThreadPoolExecutor
from pathlib import Path
from typing import Protocol

from rei.campaign.backends import connect_ray, warm_start
from rei.campaign.forkserver import ForkServer
from rei.campaign.plan import RunTask
from rei.campaign.supervise import Outcome, supervise

#: Candidates in flight on a Ray cluster at most (a thread of the driver's each).
MAX_IN_FLIGHT = 512


class Pool(Protocol):
    name: str
    workers: int

    def submit(self, task: RunTask) -> Future[Outcome]: ...

    def close(self) -> None: ...


class LocalPool:
    """``workers`` runs at a time on this machine. ``stop``: set to stop the running workers (their outcome then
    says interrupted)."""

    name = "local"

    def __init__(self, workers: int, logs: Path, stop: threading.Event) -> None:
        if workers < 1:
            raise ValueError(f"workers must be >= 1, got {workers}")
        self.workers = workers
        self._stop = stop
        self._stack = contextlib.ExitStack()
        logs.mkdir(parents=True, exist_ok=True)
        warm = self._stack.enter_context(warm_start("search", ForkServer(logs / "forkserver.log"),
                                                    logs / "monitor-server.log"))
        self._env, self._forks = warm.env, warm.forks
        self._threads = ThreadPoolExecutor(workers, thread_name_prefix="rei-search")

    def submit(self, task: RunTask) -> Future[Outcome]:
        return self._threads.submit(supervise, task, self._stop, None, self._env, self._forks)

    def close(self) -> None:
        self._threads.shutdown(wait=True)
        self._stack.close()


class RayPool:
    """Runs as Ray tasks through the campaign's Ray backend (``address``: a cluster's, or ``local`` for an instance
    of ``workers`` CPUs started here), whose nodes are checked as a campaign's (rei.campaign.nodes; ``router``: for
    the router and JuPedSim too)."""

    name = "ray"

    def __init__(self, address: str, workers: int, stop: threading.Event, router: bool = False,
                 people: bool = False) -> None:
        self._backend = connect_ray(address, workers, router=router, people=people)
        self._stop = stop
        # a thread per run in flight, however many nodes join: the search bounds them by ``workers``
        self._threads = ThreadPoolExecutor(MAX_IN_FLIGHT, thread_name_prefix="rei-search-ray")

    @property
    def workers(self) -> int:
        """The cluster's runs at a time now: a node that joins mid-search raises it (the backend's node watch)."""
        return min(self._backend.workers, MAX_IN_FLIGHT)

    def submit(self, task: RunTask) -> Future[Outcome]:
        return self._threads.submit(self._one, task)

    def _one(self, task: RunTask) -> Outcome:
        outcomes: list[Outcome] = []
        self._backend.run([task], lambda _task, outcome: outcomes.append(outcome), self._stop)
        if not outcomes:  # stopped before it ran
            return Outcome(task.key, None, False, True, 0.0, 0.0, "", "-")
        return outcomes[0]

    def close(self) -> None:
        self._threads.shutdown(wait=True)
        self._backend.close()
