# SPDX-License-Identifier: EPL-2.0
"""The run's simulation process, started held (``rei sim --held``): it starts up (Python, pybullet, its router
session) while the rest of the run does, and steps only once ``release()``d. Light on purpose: ``rei run`` starts
it before it imports the pipeline."""

from __future__ import annotations

import sys
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import IO, TYPE_CHECKING, Any

from rei.processes import ManagedProcess

if TYPE_CHECKING:
    from rei.wamp.router import Router

#: Seconds a component keeps trying to reach a restarted router before its part of the run is lost.
ROUTER_RECONNECT = 30.0


@dataclass(frozen=True, slots=True)
class HeldSimulation:
    """``rei sim --held`` started for a run: its process and the progress it reports."""

    process: ManagedProcess
    progress: dict[str, float] = field(default_factory=lambda: {"t": 0.0, "done": 0, "total": 0})


def start_simulation(case_dir: Path, out: Path, router: Router, run_id: str, *, sim_args: Sequence[str] = (),
                     external_sut: bool = False) -> HeldSimulation:
    """The run's simulation, started and held before its first step (it reads ``case_dir`` only once let go, so
    the case may still be being generated); ``run_pipeline`` lets it go once the monitor and evaluator listen."""
    progress: dict[str, float] = {"t": 0.0, "done": 0, "total": 0}
    sut_args = ["--sut-router", router.ws_url, "--sut-auth-file", str(router.auth_file("sut"))] \
        if external_sut else []
    command = ["sim", str(case_dir), "-o", str(out), "--router", router.rs_url,
               "--auth-file", str(router.auth_file("simulation")), "--run-id", run_id, "--progress", "lines",
               "--reconnect", str(ROUTER_RECONNECT), "--wait-for-monitor", "--held", *sut_args, *sim_args]

    def warm(held: bool, stdout: IO[str] | None, stderr: IO[str], env: dict[str, str], cwd: Path | None) -> Any:
        """Forked from the service's warm Python when this run was (it has imported the simulation already)."""
        from rei.service.warm import WarmProcess

        return WarmProcess.start(command, stdin_pipe=held, stdout=stdout, stderr=stderr, env=env, cwd=cwd)

    process = ManagedProcess("simulation", [sys.executable, "-m", "rei.cli", *command], out / "simulation.log",
                             on_line=lambda line: _on_sim_line(line, progress), held=True, launch=warm)
    return HeldSimulation(process, progress)


def _on_sim_line(line: str, progress: dict[str, float]) -> None:
    """A line the simulation printed: progress is parsed, what concerns an external SUT shown to the user."""
    if line.startswith("sut: "):
        print(line, flush=True)
    _parse_progress(line, progress)


def _parse_progress(line: str, progress: dict[str, float]) -> None:
    if not line.startswith("progress "):
        return
    fields = dict(item.split("=", 1) for item in line.split()[1:] if "=" in item)
    try:
        progress["t"], progress["done"], progress["total"] = (
            float(fields["t"]), int(fields["done"]), int(fields["total"]))
    except (KeyError, ValueError):
        pass
