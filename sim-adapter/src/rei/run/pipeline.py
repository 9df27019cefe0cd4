# SPDX-License-Identifier: EPL-2.0
"""`rei run`: one test case through the whole pipeline (thesis 3.2.2, Fig. 7).

    router (Crossbar) <- simulation (rei sim, child process) publishes state and mission events
                      -> monitor (rei-monitor.jar, child process) publishes signals
                      -> evaluator (here) scores them, writes events.csv, summary.json, verdicts.xml

The simulation process is started first but held (``rei sim --held``) before its first step; it starts up while
the monitor does. It is let go only once the monitor answers its snapshot procedure: the router has then processed
its subscriptions, so the first state message is not lost. By then the monitor has also written what its
patterns declare (``OUT/utilities.json``), so the evaluator is made and subscribed between the two - still before
the simulation's first step, hence before the first signal.

With the background service (rei.service, docs/performance.md) the router is one it had ready, taken over by
this run, and the monitor runs in its warm JVM; nothing else changes.

Faults during the run (docs/security.md, "Faults mid-run"):

- the router dies: it is restarted on the same ports with the same secrets and every component reconnects;
  the simulation holds what it queued meanwhile until the monitor answers again (the router drops events nobody
  is subscribed to). What was lost inside the dying router shows as the monitor's SIG_MONITOR_DATA_GAP, which
  turns the verdicts that would pass into errors. Signals the evaluator missed while reconnecting are recovered
  from the monitor's own signal file (``OUT/signals.jsonl``) at the end.
- the monitor dies: the simulation goes on (it records everything it publishes); at the end the recorded
  streams are replayed through a fresh monitor (``rei.run.reevaluate``) - the same signals the live monitor
  would have given - and the live event log is kept as ``events-live.csv``.
- anything else (the simulation dying, Ctrl-C, SIGTERM): every child is stopped, the evaluator writes what it
  has and the run is marked ERROR with the reason.
"""

from __future__ import annotations

import json
import signal
import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from rei import toolchain
from rei.processes import ManagedProcess
from rei.run.held import ROUTER_RECONNECT, HeldSimulation, start_simulation
from rei.run.jvm import ServedCommand
from rei.run.patterns import UTILITIES_FILE, PatternSelection
from rei.run.patterns import record as record_patterns
from rei.run.reevaluate import (
    LIVE_EVENTS_FILE,
    SIGNALS_FILE,
    ReevaluationError,
    RunSettings,
    read_signals,
    reevaluate,
)
from rei.wamp.client import WampClient
from rei.wamp.recording import RecordingWriter, stream_path
from rei.wamp.router import UNKNOWN_EXIT, Router
from rei.wamp.topics import Topics

if TYPE_CHECKING:
    from rei.view import ViewServer

#: Seconds the monitor may take to start (JVM, Drools rule compilation) before the run is an error.
MONITOR_START_TIMEOUT = 60.0
#: Seconds the monitor may take to finish after the simulation ended (it processes what is queued).
MONITOR_DRAIN_TIMEOUT = 60.0
#: Router deaths a run survives; one more and the run is an ERROR (a router that keeps dying is not a blip).
MAX_ROUTER_RESTARTS = 3
#: Seconds the mission's END signal may take to reach the evaluator after the monitor that sent it has exited.
MONITOR_END_GRACE = 5.0


@dataclass(frozen=True, slots=True)
class PipelineOptions:
    """What `rei sim` gets, plus the evaluator's utility table."""

    sim_args: tuple[str, ...] = ()
    external_sut: bool = False  # sim_args start or await an external SUT: it gets the sut role's credentials
    utilities: Path | None = None
    humans: bool = True  # without humans the human-trajectory requirement does not apply
    laser: bool = True  # without laser data the laser requirements do not apply
    view: bool = False  # serve the live view (rei.view) while the run lasts
    bind: str | None = None  # also expose the router on this interface (TLS required; docs/security.md)
    tls_cert: Path | None = None
    tls_key: Path | None = None
    patterns: PatternSelection = field(default_factory=PatternSelection)  # the monitor's VEPL patterns
    # what they declare when checked before the run (rei.run.patterns.check): the live view starts before the
    # monitor and scores with it; the evaluator uses the monitor's own OUT/utilities.json
    declared: Mapping[str, float | None] | None = None
    # from the background service (rei.service): a router already running for this run id, taken over
    # (Router.adopt), and a warm monitor JVM's socket to run the monitor in; None: started here as before
    router: Router | None = None
    monitor_server: Path | None = None
    # a simulation already started, held (start_simulation): it started up while the case was generated
    simulation: HeldSimulation | None = None


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
        return 2 if self.status != "COMPLETED" else self.summary.exit_code


class _Interrupted(Exception):
    def __init__(self, reason: str) -> None:
        super().__init__(reason)
        self.reason = reason


def run_pipeline(case_dir: Path, out: Path, options: PipelineOptions, *, run_id: str,
                 on_progress: Callable[[Progress], None] | None = None) -> PipelineResult:
    run = _Run(case_dir, out, options, run_id, on_progress)
    status, reason = "COMPLETED", None
    previous_term = signal.signal(signal.SIGTERM, _raise_interrupted)
    try:
        run.start()
        run.supervise()
        run.drain()
    except _Interrupted as error:
        status, reason = "ERROR", error.reason + (run.when() if isinstance(error, _Signalled) else "")
    except KeyboardInterrupt:
        status, reason = "ERROR", f"interrupted (Ctrl-C){run.when()}"
    except Exception as error:  # noqa: BLE001 - the run must still be written up and its processes stopped
        status, reason = "ERROR", f"{type(error).__name__}: {error}"
    finally:
        shutdown_problem = run.stop()
        signal.signal(signal.SIGTERM, previous_term)
    return run.write_up(status, reason or shutdown_problem)


class _Run:
    """One run's parts and what they reported; ``run_pipeline`` calls the phases in order."""

    def __init__(self, case_dir: Path, out: Path, options: PipelineOptions, run_id: str,
                 on_progress: Callable[[Progress], None] | None) -> None:
        self.case_dir, self.out, self.options, self.run_id = case_dir, out, options, run_id
        self.on_progress = on_progress
        self.topics = Topics(run_id)
        self.world = _json(case_dir / "world.json")
        self.monitor_config = _json(case_dir / "monitor.json")
        self.started = time.perf_counter()
        self.progress = {"t": 0.0, "done": 0, "total": 0}
        self.patterns = options.patterns
        self.router: Router | None = None
        self.viewer: ViewServer | None = None
        self.client: WampClient | None = None
        self.signals: RecordingWriter | None = None
        self.monitor: ManagedProcess | ServedCommand | None = None
        self.sim: ManagedProcess | None = None
        self.evaluator: Any = None  # made once the monitor says which utilities its patterns declare
        self.monitor_lost: str | None = None  # how the live monitor ended during the run, if it did
        self.emitted: list[Any] = []  # the monitor's own record of its signals, when the received copy is not whole
        (out / UTILITIES_FILE).unlink(missing_ok=True)  # a previous run's must not stand in for this one's

    def start(self) -> None:
        """Router, view, simulation (held), the evaluator's client, monitor, evaluator, then the simulation goes
        (module docstring)."""
        from rei.evaluation import attach, load_declared, load_utilities

        out, options = self.out, self.options
        self.patterns = record_patterns(options.patterns, out)  # so a replay runs the patterns the live monitor ran
        # authenticated: one role per component, secrets in OUT/router/auth/<role>.json (0600), docs/security.md
        router = self.router = options.router or Router(
            run_dir=out / "router", run_id=self.run_id, bind=options.bind, tls_cert=options.tls_cert,
            tls_key=options.tls_key, die_with_parent=True).start()
        if router.exposed_url is not None:
            print(f"router: {router.exposed_url} (TLS, authenticated)", flush=True)
        self.viewer = _start_view(router, self.run_id, self.case_dir, options) if options.view else None
        # the simulation starts up (Python, pybullet, its router session) while the monitor does, held before
        # its first step until both monitor and evaluator listen
        held = options.simulation or start_simulation(self.case_dir, out, router, self.run_id,
                                                      sim_args=options.sim_args, external_sut=options.external_sut)
        self.sim, self.progress = held.process, held.progress
        client = self.client = WampClient(router.rs_url, auth=router.credentials("evaluator"),
                                          reconnect=ROUTER_RECONNECT).start()
        self.signals = RecordingWriter(stream_path(out, "signal"))
        monitor = self.monitor = _start_monitor([
            "--router", router.ws_url, "--auth-file", str(router.auth_file("monitor")),
            "--run", self.run_id, "--case", str(self.case_dir), "--until-end", "--quiet",
            "--snapshot-out", str(out / "runtime.xmi"), "--signals-out", str(out / SIGNALS_FILE),
            *self.patterns.monitor_args(), "--utilities-out", str(out / UTILITIES_FILE)],
            out / "monitor.log", options.monitor_server)
        _await_monitor(client, self.topics, monitor)
        # the monitor wrote what its patterns declare before it answered; signals only come once the simulation
        # runs, so subscribing here still sees the first one
        declared = load_declared(out / UTILITIES_FILE)
        self.evaluator = self._evaluator(load_utilities(options.utilities, declared.utilities,
                                                        patterns=self.patterns.describe()), declared.transitions)
        attach(client, self.run_id, self.evaluator, also=self.signals.write)
        if self.viewer is not None:
            _await_viewer(self.viewer)
        self.sim.release()  # monitor and evaluator listen: the simulation may publish

    def supervise(self) -> None:
        """While the simulation runs: restart a dead router, note a dead monitor, report progress."""
        assert self.sim is not None and self.monitor is not None and self.router is not None
        sim, monitor, evaluator = self.sim, self.monitor, self.evaluator
        while sim.poll() is None:
            if self.router.poll() is not None:
                _restart_router(self.router, evaluator, self.progress["t"])
            if self.monitor_lost is None and monitor_lost(monitor.poll(), evaluator):
                self.monitor_lost = f"{monitor.describe_exit()} at about {self.progress['t']:.1f} s simulated"
                print(f"rei: the live {self.monitor_lost}; the simulation goes on and the run will be judged from "
                      "its recorded streams", flush=True)
            if self.on_progress is not None:
                p = self.progress
                self.on_progress(Progress(p["t"], int(p["done"]), int(p["total"]), evaluator.total))
            sim.wait(0.05)
        # 0 and 1 are a mission that succeeded or failed; anything else, or no summary, is a broken run
        summary = _json(self.out / "sim.json") if (self.out / "sim.json").is_file() else None
        if summary is not None and summary.get("error"):  # the simulation's own account (an external SUT broke it)
            raise _Interrupted(summary["error"])
        if sim.poll() not in (0, 1) or summary is None:
            raise _Interrupted(f"{sim.describe_exit()}: {sim.log_tail(5)}")
        self._note_sut(summary.get("sut"))

    def _note_sut(self, sut: Mapping[str, Any] | None) -> None:
        """What an external SUT sent that was not applied as is: in the summary's notes (docs/sut.md)."""
        if not sut or not (sut["rejected"] or sut["clamped"]):
            return
        first = f"; first: {sut['first_rejections'][0]}" if sut["first_rejections"] else ""
        self.evaluator.note(f"the system under test sent {sut['commands']} valid commands, {sut['clamped']} of them "
                            f"clamped to the robot's limits; {sut['rejected']} messages were rejected{first}",
                            self.progress["t"])

    def drain(self) -> None:
        """The simulation is done: let the monitor finish, then complete the received signals from its record."""
        assert self.monitor is not None and self.router is not None
        monitor = self.monitor
        if self.monitor_lost is None:
            if monitor.wait(MONITOR_DRAIN_TIMEOUT) is None:
                raise _Interrupted(f"the monitor did not finish within {MONITOR_DRAIN_TIMEOUT:.0f} s of the "
                                   "mission's end")
            if monitor.poll() != 0:
                self.monitor_lost = f"{monitor.describe_exit()} after the mission: {monitor.log_tail(3)}"
        if self.monitor_lost is None:
            restarts = self.router.restarts
            # in the usual case END arrives live at once; after a router restart it may be in the file only
            self.evaluator.wait_for_end(timeout=2.0 if restarts else 10.0)
            # after a reconnection the received stream may have holes or repeats: the monitor's record has neither
            record = read_signals(self.out / SIGNALS_FILE)
            if self.evaluator.reconcile(record) or restarts:
                self.emitted = record

    def when(self) -> str:
        """Where the simulation was, for a run stopped from outside: the recorded streams end about there."""
        if self.sim is None:
            return " before the simulation started"
        return f" at about t={self.progress['t']:.0f} s simulated"

    def stop(self) -> str | None:
        """Stop every part, whatever happened; returns a problem met on the way, if any."""
        problem = None
        for process in (self.sim, self.monitor):
            if process is not None:
                process.stop()
        for closing in (self.client.close if self.client else None, self.signals.close if self.signals else None,
                        self.router.stop if self.router else None, self.viewer.stop if self.viewer else None):
            if closing is not None:
                try:
                    closing()
                except Exception as error:  # noqa: BLE001 - shutting down; note and go on
                    problem = problem or f"shutdown: {error}"
        return problem

    def write_up(self, status: str, reason: str | None) -> PipelineResult:
        """The evaluator's files (or, after a monitor's death, the re-evaluation's) and the run's result."""
        out = self.out
        if self.evaluator is None:  # the run broke before the monitor was up: no signal was scored, write it up
            self.evaluator = self._evaluator(_utilities_without_monitor(self.options, self.patterns))
        if self.emitted:  # the report and run.mcap read this copy of the signals: make it whole
            with RecordingWriter(stream_path(out, "signal")) as recording:
                for message in self.emitted:
                    recording.write(message)
        sim_summary = _json(out / "sim.json") if (out / "sim.json").is_file() else {}
        sim_duration = sim_summary.get("sim_time", self.progress["t"])
        if status == "COMPLETED" and self.monitor_lost is not None:
            return _judge_from_recording(out, self.case_dir, self.options, self.evaluator, self.monitor_lost,
                                         run_id=self.run_id, sim_duration=sim_duration, started=self.started)
        summary = self.evaluator.finish(status=status, reason=reason, sim_duration=sim_duration,
                                        wall_time=time.perf_counter() - self.started, run_id=self.run_id)
        return PipelineResult(status, reason, summary)

    def _evaluator(self, utilities: Any, transitions: Any = None) -> Any:
        from rei.evaluation import Evaluator, VerdictSettings

        return Evaluator(self.out, utilities=utilities, transitions=transitions, mission_info=None,
                         monitor_config=self.monitor_config,
                         world=self.world, settings=VerdictSettings(humans=self.options.humans,
                                                                    laser=self.options.laser))


def monitor_lost(code: int | None, evaluator: Any, grace: float = MONITOR_END_GRACE) -> bool:
    """Whether a monitor that exited with ``code`` (None: it runs) before the simulation did left the run without its
    signals. Not one that exited 0 after the mission's END (--until-end): the router delivers that END signal to
    the evaluator a moment after the monitor has gone, so it is waited for (``grace`` seconds) before the run is
    judged from its recording instead."""
    if code is None:
        return False
    return not (code == 0 and evaluator.wait_for_end(grace))


def _start_monitor(args: list[str], log: Path, server: Path | None) -> ManagedProcess | ServedCommand:
    """The live monitor: a command in the warm monitor JVM when there is one that answers, else a JVM of its own."""
    if server is not None:
        try:
            return ServedCommand("monitor", server, args, log)
        except ConnectionError as error:
            print(f"rei: {error}; starting the monitor in a JVM of its own", flush=True)
    return ManagedProcess("monitor", [str(toolchain.find_java().executable), "-jar", str(toolchain.find_jar("monitor")),
                                      *args], log)


def _utilities_without_monitor(options: PipelineOptions, patterns: PatternSelection) -> Any:
    """The utility table of a run that broke before the monitor said what its patterns declare."""
    from rei.evaluation import UtilityError, load_utilities

    try:
        return load_utilities(options.utilities, options.declared, patterns=patterns.describe())
    except UtilityError:  # the file names a signal only the patterns know; nothing was scored with it anyway
        return load_utilities()


def _restart_router(router: Router, evaluator: Any, sim_time: float) -> None:
    """The router died mid-run: start it again where the components look for it (see the module docstring)."""
    code: int | str | None = router.poll()
    if code == UNKNOWN_EXIT:
        code = "unknown to this run (the service started it)"
    if router.restarts >= MAX_ROUTER_RESTARTS:
        raise _Interrupted(f"the router exited with code {code} for the {router.restarts + 1}th time; not restarted "
                           f"again: {router.log_tail(5)}")
    print(f"rei: the router exited with code {code} at about {sim_time:.1f} s simulated; restarting it on the same ports",
          flush=True)
    try:
        router.restart()
    except Exception as error:
        raise _Interrupted(f"the router exited with code {code} and could not be restarted: {error}") from error
    evaluator.note(f"the router exited with code {code} and was restarted on the same ports; the components "
                   "reconnected", sim_time)


def _judge_from_recording(out: Path, case_dir: Path, options: PipelineOptions, evaluator: Any, monitor_lost: str,
                          *, run_id: str, sim_duration: float, started: float) -> PipelineResult:
    """The live monitor died but the simulation completed: judge the run by replaying what it recorded.

    The live evaluator's results are written first (an ERROR naming the monitor), so a failing re-evaluation
    still leaves a complete record; its event log is kept as events-live.csv.
    """
    reason = f"the live {monitor_lost}"
    live = evaluator.finish(status="ERROR", reason=reason, sim_duration=sim_duration,
                            wall_time=time.perf_counter() - started, run_id=run_id)
    print("rei: judging the run from its recorded streams (monitor replay)", flush=True)
    note = (f"{reason}; the signals were re-computed from the recorded streams by the monitor's replay "
            f"(the live event log is {LIVE_EVENTS_FILE})")
    try:
        judged = reevaluate(out, case_dir, utilities=options.utilities, settings=RunSettings(
            humans=options.humans, laser=options.laser, run_id=run_id, sim_duration=sim_duration), notes=(note,))
    except (ReevaluationError, OSError) as error:
        if not (out / "events.csv").exists():
            (out / LIVE_EVENTS_FILE).replace(out / "events.csv")
        return PipelineResult("ERROR", f"{reason}; re-evaluation failed: {error}", live)
    summary = judged.summary
    return PipelineResult(summary.status, summary.error, summary)


def _await_monitor(client: WampClient, topics: Topics, monitor: ManagedProcess | ServedCommand) -> None:
    """Until the monitor answers its snapshot procedure (see the module's docstring)."""
    deadline = time.monotonic() + MONITOR_START_TIMEOUT
    while time.monotonic() < deadline:
        if monitor.poll() is not None:
            raise _Interrupted(f"{monitor.describe_exit()} while starting: {monitor.log_tail(10)}")
        try:
            client.call(topics.snapshot, timeout=5.0)
            return
        except Exception:  # noqa: BLE001 - not registered yet
            time.sleep(0.05)  # a warm monitor registers within a few tenths of a second: do not oversleep it
    raise _Interrupted(f"the monitor did not start within {MONITOR_START_TIMEOUT:.0f} s")


def _start_view(router: Router, run_id: str, case_dir: Path, options: PipelineOptions) -> ViewServer:
    """The live view's server (`--view`), started before the monitor so the page can connect meanwhile."""
    from rei.view import RouterAuth, ViewServer, view_config

    # The page runs in the browser, so the viewer role's secret is in /config.json (served on loopback only):
    # anyone on this machine who can reach that port can subscribe - and nothing more (docs/security.md).
    credentials = router.credentials("viewer")
    auth = None if credentials is None else RouterAuth(credentials.authid, credentials.secret, credentials.method)
    viewer = ViewServer(view_config(router.ws_url, run_id, case_dir, utilities=options.utilities,
                                    declared=options.declared, auth=auth)).start()
    print(f"view:   {viewer.url}", flush=True)
    return viewer


def _await_viewer(viewer: ViewServer) -> None:
    """Until a page is subscribed (so it sees the run from its first message), at most VIEWER_WAIT s."""
    from rei.view import VIEWER_WAIT

    if not viewer.wait_for_viewer(0.0):
        print(f"view:   waiting up to {VIEWER_WAIT:.0f} s for the page to connect...", flush=True)
        if not viewer.wait_for_viewer(VIEWER_WAIT):
            print("view:   no page connected; running anyway", flush=True)


class _Signalled(_Interrupted):
    """The run was stopped by a signal (SIGTERM), not by what one of its parts did."""


def _raise_interrupted(signum: int, frame: object) -> None:
    raise _Signalled(f"stopped by {signal.Signals(signum).name}")


def _json(path: Path) -> dict[str, Any]:
    return json.loads(path.read_text(encoding="utf-8"))


__all__ = ["HeldSimulation", "PipelineOptions", "PipelineResult", "Progress", "run_pipeline", "start_simulation"]
