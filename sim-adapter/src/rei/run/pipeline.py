# SPDX-License-Identifier: EPL-2.0
"""`rei run`: one test case through the whole pipeline (thesis 3.2.2, Fig. 7).

    router (Crossbar) <- simulation (rei sim, child process) publishes state and mission events
                      -> monitor (rei-monitor.jar, child process) publishes signals
                      -> evaluator (here) scores them, writes events.csv, summary.json, verdicts.xml

The monitor is started first and the simulation only once the monitor answers its snapshot procedure: the
router has then processed its subscriptions, so the first state message is not lost. Whatever happens - a
child dying, Ctrl-C, SIGTERM - every child is stopped, the evaluator writes what it has and the run is marked
ERROR with the reason.
"""

from __future__ import annotations

import json
import signal
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

from rei import toolchain
from rei.run.processes import ManagedProcess
from rei.wamp.client import WampClient
from rei.wamp.recording import RecordingWriter, stream_path
from rei.wamp.router import Router
from rei.wamp.topics import Topics

if TYPE_CHECKING:
    from rei.view import ViewServer

#: Seconds the monitor may take to start (JVM, Drools rule compilation) before the run is an error.
MONITOR_START_TIMEOUT = 60.0
#: Seconds the monitor may take to finish after the simulation ended (it processes what is queued).
MONITOR_DRAIN_TIMEOUT = 60.0


@dataclass(frozen=True, slots=True)
class PipelineOptions:
    """What `rei sim` gets, plus the evaluator's utility table."""

    sim_args: tuple[str, ...] = ()
    utilities: Path | None = None
    humans: bool = True  # without humans the human-trajectory requirement does not apply
    laser: bool = True  # without laser data the laser requirements do not apply
    view: bool = False  # serve the live view (rei.view) while the run lasts
    bind: str | None = None  # also expose the router on this interface (TLS required; docs/security.md)
    tls_cert: Path | None = None
    tls_key: Path | None = None


@dataclass(frozen=True, slots=True)
class Progress:
    sim_time: float
    tasks_done: int
    tasks: int
    utility: float


@dataclass(frozen=True, slots=True)
class PipelineResult:
    status: str  # COMPLETED or ERROR
    reason: str | None
    summary: Any  # rei.evaluation summary

    @property
    def exit_code(self) -> int:
        if self.status != "COMPLETED":
            return 2
        return 1 if any(v.status == "fail" for v in self.summary.verdicts) else 0


class _Interrupted(Exception):
    def __init__(self, reason: str) -> None:
        super().__init__(reason)
        self.reason = reason


def run_pipeline(case_dir: Path, out: Path, options: PipelineOptions, *, run_id: str,
                 on_progress: Callable[[Progress], None] | None = None) -> PipelineResult:
    from rei.evaluation import Evaluator, VerdictSettings, attach, load_utilities

    world = _json(case_dir / "world.json")
    monitor_config = _json(case_dir / "monitor.json")
    topics = Topics(run_id)
    evaluator = Evaluator(out, utilities=load_utilities(options.utilities), mission_info=None,
                          monitor_config=monitor_config, world=world,
                          settings=VerdictSettings(humans=options.humans, laser=options.laser))
    status, reason = "COMPLETED", None
    started = time.perf_counter()
    progress = {"t": 0.0, "done": 0, "total": 0}
    previous_term = signal.signal(signal.SIGTERM, _raise_interrupted)
    router = monitor = sim = client = signals = viewer = None
    try:
        # authenticated: one role per component, secrets in OUT/router/auth/<role>.json (0600), docs/security.md
        router = Router(run_dir=out / "router", run_id=run_id, bind=options.bind, tls_cert=options.tls_cert,
                        tls_key=options.tls_key).start()
        if router.exposed_url is not None:
            print(f"router: {router.exposed_url} (TLS, authenticated)", flush=True)
        viewer = _start_view(router, run_id, case_dir, options) if options.view else None
        client = WampClient(router.rs_url, auth=router.credentials("evaluator")).start()
        signals = RecordingWriter(stream_path(out, "signal"))
        attach(client, run_id, evaluator, also=signals.write)
        monitor = ManagedProcess("monitor", [
            str(toolchain.find_java().executable), "-jar", str(toolchain.find_jar("monitor")),
            "--router", router.ws_url, "--auth-file", str(router.auth_file("monitor")),
            "--run", run_id, "--case", str(case_dir), "--until-end", "--quiet",
            "--snapshot-out", str(out / "runtime.xmi")], out / "monitor.log")
        _await_monitor(client, topics, monitor)
        if viewer is not None:
            _await_viewer(viewer)
        sim = ManagedProcess("simulation", [
            sys.executable, "-m", "rei.cli", "sim", str(case_dir), "-o", str(out), "--router", router.rs_url,
            "--auth-file", str(router.auth_file("simulation")), "--run-id", run_id, "--progress", "lines", *options.sim_args],
            out / "simulation.log", on_line=lambda line: _parse_progress(line, progress))
        while sim.poll() is None:
            # --until-end: a monitor that saw the mission's END may finish before the simulation has closed
            if monitor.poll() is not None and not (monitor.poll() == 0 and evaluator.ended):
                raise _Interrupted(f"{monitor.describe_exit()} during the run: {monitor.log_tail(5)}")
            if on_progress is not None:
                on_progress(Progress(progress["t"], progress["done"], progress["total"], evaluator.total))
            time.sleep(0.2)
        # 0 and 1 are a mission that succeeded or failed; anything else, or no summary, is a broken run
        if sim.poll() not in (0, 1) or not (out / "sim.json").is_file():
            raise _Interrupted(f"{sim.describe_exit()}: {sim.log_tail(5)}")
        if monitor.wait(MONITOR_DRAIN_TIMEOUT) is None:
            raise _Interrupted(f"the monitor did not finish within {MONITOR_DRAIN_TIMEOUT:.0f} s of the mission's end")
        if monitor.poll() != 0:
            raise _Interrupted(f"{monitor.describe_exit()}: {monitor.log_tail(5)}")
        evaluator.wait_for_end(timeout=10.0)
    except _Interrupted as error:
        status, reason = "ERROR", error.reason
    except KeyboardInterrupt:
        status, reason = "ERROR", "interrupted"
    except Exception as error:  # noqa: BLE001 - the run must still be written up and its processes stopped
        status, reason = "ERROR", f"{type(error).__name__}: {error}"
    finally:
        for process in (sim, monitor):
            if process is not None:
                process.stop()
        for closing in (client.close if client else None, signals.close if signals else None,
                        router.stop if router else None, viewer.stop if viewer else None):
            if closing is not None:
                try:
                    closing()
                except Exception as error:  # noqa: BLE001 - shutting down; note and go on
                    reason = reason or f"shutdown: {error}"
        signal.signal(signal.SIGTERM, previous_term)
    sim_summary = _json(out / "sim.json") if (out / "sim.json").is_file() else {}
    summary = evaluator.finish(status=status, reason=reason, sim_duration=sim_summary.get("sim_time", progress["t"]),
                               wall_time=time.perf_counter() - started, run_id=run_id)
    return PipelineResult(status, reason, summary)


def _await_monitor(client: WampClient, topics: Topics, monitor: ManagedProcess) -> None:
    """Until the monitor answers its snapshot procedure (see the module's docstring)."""
    deadline = time.monotonic() + MONITOR_START_TIMEOUT
    while time.monotonic() < deadline:
        if monitor.poll() is not None:
            raise _Interrupted(f"{monitor.describe_exit()} while starting: {monitor.log_tail(10)}")
        try:
            client.call(topics.snapshot, timeout=5.0)
            return
        except Exception:  # noqa: BLE001 - not registered yet
            time.sleep(0.25)
    raise _Interrupted(f"the monitor did not start within {MONITOR_START_TIMEOUT:.0f} s")


def _start_view(router: Router, run_id: str, case_dir: Path, options: PipelineOptions) -> ViewServer:
    """The live view's server (`--view`), started before the monitor so the page can connect meanwhile."""
    from rei.view import RouterAuth, ViewServer, view_config

    # The page runs in the browser, so the viewer role's secret is in /config.json (served on loopback only):
    # anyone on this machine who can reach that port can subscribe - and nothing more (docs/security.md).
    credentials = router.credentials("viewer")
    auth = None if credentials is None else RouterAuth(credentials.authid, credentials.secret, credentials.method)
    viewer = ViewServer(view_config(router.ws_url, run_id, case_dir, utilities=options.utilities,
                                    auth=auth)).start()
    print(f"view:   {viewer.url}", flush=True)
    return viewer


def _await_viewer(viewer: ViewServer) -> None:
    """Until a page is subscribed (so it sees the run from its first message), at most VIEWER_WAIT s."""
    from rei.view import VIEWER_WAIT

    if not viewer.wait_for_viewer(0.0):
        print(f"view:   waiting up to {VIEWER_WAIT:.0f} s for the page to connect...", flush=True)
        if not viewer.wait_for_viewer(VIEWER_WAIT):
            print("view:   no page connected; running anyway", flush=True)


def _parse_progress(line: str, progress: dict[str, float]) -> None:
    if not line.startswith("progress "):
        return
    fields = dict(item.split("=", 1) for item in line.split()[1:] if "=" in item)
    try:
        progress["t"], progress["done"], progress["total"] = (
            float(fields["t"]), int(fields["done"]), int(fields["total"]))
    except (KeyError, ValueError):
        pass


def _raise_interrupted(signum: int, frame: object) -> None:
    raise _Interrupted(f"stopped by {signal.Signals(signum).name}")


def _json(path: Path) -> dict[str, Any]:
    return json.loads(path.read_text(encoding="utf-8"))


__all__ = ["PipelineOptions", "PipelineResult", "Progress", "run_pipeline"]
