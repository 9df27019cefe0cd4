# SPDX-License-Identifier: EPL-2.0
"""The runtime monitor survives a crash and restart of the Crossbar router in the middle of a run.

A private authenticated router (rei.wamp.Router); the monitor jar on the test room's case (`--case`, `--until-end`,
`--record`, `--signals-out`); this test publishing the monitor's scripted wall-approach trace
(runtime-monitor/src/test/resources/write_trace.py) as the simulation role and listening to the signals as the
evaluator role. States 0..LAST_BEFORE go out, the router's process group is SIGKILLed and started again on the same
ports with the same configuration (Router.restart), then states RESUME..end (MISSING lost with the router) and the
mission's last events. The monitor must reconnect by itself, serve its snapshot RPC and take events again, report
the lost states as one SIG_MONITOR_DATA_GAP and publish every signal (a reconnected subscriber gets the new ones).
Without a router coming back, the monitor still stops on time (closing is bounded).

Real processes only; every wait is bounded and every process group started here is killed on the way out.
"""

from __future__ import annotations

import contextlib
import json
import os
import signal
import subprocess
import sys
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import pytest
from monitor_helpers import kill_group, wait_for

from rei.wamp import Router, WampClient, WampError, read_recording, stream_path

RUN_ID = "monitor-reconnect-e2e"
#: The last state published before the crash, and the first after it: the states between are lost.
LAST_BEFORE = 170
RESUME = 181
MISSING = RESUME - LAST_BEFORE - 1
TRACE_STATES = 281  # write_trace.py: 20 Hz for 14 s
#: Bounds for one step each; the 2-core machine may be busy with other builds.
START_S = 60.0
MONITOR_S = 240.0
LINGER_S = 8.0


@dataclass
class RestartRun:
    out: Path
    written: list[dict]  # the monitor's --signals-out
    before: list[dict]  # received by the evaluator before the crash
    after: list[dict]  # received by the evaluator that joined the restarted router
    states_before: int  # states the monitor had recorded when the router was killed
    alive_after_crash: bool
    snapshot_after_restart: str
    snapshot_at_end: str
    monitor_stderr: str
    monitor_exit: int


def _trace(resources: Path, case: Path, out: Path) -> tuple[list[dict], list[dict]]:
    """The monitor's scripted wall approach, written by its own Python script, as state and mission messages."""
    done = subprocess.run([sys.executable, str(resources / "write_trace.py"), str(case), str(out)],
                          check=False, capture_output=True, text=True, timeout=START_S)
    assert done.returncode == 0, done.stderr
    return read_recording(stream_path(out, "state")), read_recording(stream_path(out, "mission"))


def _crash_and_restart(router: Router) -> None:
    """SIGKILL the router's process group (a crash: no GOODBYE to anyone), then Router.restart(): the same ports,
    configuration and secrets, as `rei run` does when its router dies."""
    assert router.pid is not None
    os.killpg(router.pid, signal.SIGKILL)
    router.restart()


def _lines(path: Path) -> list[dict]:
    return [json.loads(line) for line in path.read_text().splitlines()] if path.exists() else []


def _messages(path: Path) -> int:
    """Messages in a recording the monitor is writing (-1 while one is half written)."""
    try:
        return len(read_recording(path)) if path.exists() else 0
    except ValueError:
        return -1


def _leave(client: WampClient) -> None:
    with contextlib.suppress(WampError):  # a client of the killed router: its session is gone
        client.close()


@pytest.fixture(scope="module")
def restart_run(repo_root: Path, monitor_jar: Path, java_exe: str, tmp_path_factory) -> Iterator[RestartRun]:
    base = tmp_path_factory.mktemp("monitor-reconnect")
    resources = repo_root / "runtime-monitor" / "src" / "test" / "resources"
    case = resources / "cases" / "room"
    states, missions = _trace(resources, case, base / "trace")
    begin, task_start, task_fail, end = missions
    topic = {name: f"rei.run.{RUN_ID}.{name}" for name in ("state", "mission", "signal", "snapshot")}
    before: list[dict] = []
    after: list[dict] = []
    stderr_path, signals_path = base / "monitor.err", base / "signals.jsonl"
    with Router(run_dir=base / "router", run_id=RUN_ID) as router:
        with open(base / "monitor.out", "w") as stdout, open(stderr_path, "w") as stderr:
            monitor = subprocess.Popen(
                [java_exe, "-jar", str(monitor_jar), "--router", router.ws_url,
                 "--auth-file", str(router.auth_file("monitor")), "--run", RUN_ID, "--case", str(case),
                 "--until-end", "--linger", str(LINGER_S), "--timeout", str(MONITOR_S), "--record",
                 str(base / "received"), "--signals-out", str(signals_path), "--snapshot-out", str(base / "exit.xmi")],
                stdout=stdout, stderr=stderr, stdin=subprocess.DEVNULL, start_new_session=True)
        try:
            wait_for(lambda: "monitoring " in stderr_path.read_text(), START_S, "monitor start", monitor, stderr_path)
            with contextlib.ExitStack() as clients:  # left after the crash, or on a failure before it
                evaluator = WampClient(router.rs_url, auth=router.credentials("evaluator")).start()
                clients.callback(_leave, evaluator)
                simulation = WampClient(router.rs_url, auth=router.credentials("simulation")).start()
                clients.callback(_leave, simulation)
                evaluator.subscribe(topic["signal"], before.append)
                evaluator.call_when_registered(topic["snapshot"], timeout=START_S)
                simulation.publish(topic["mission"], begin)
                simulation.publish(topic["mission"], task_start)
                for state in states[: LAST_BEFORE + 1]:
                    simulation.publish(topic["state"], state)
                simulation.flush()
                # the monitor has received every state (its recording) and processed it (the snapshot RPC runs on
                # its pipeline thread, after them), and the evaluator has every signal so far: the crash loses
                # exactly the states that are never published
                received = base / "received" / "state.msgpack"
                wait_for(lambda: _messages(received) == LAST_BEFORE + 1, START_S, "states before the crash",
                          monitor, stderr_path)
                evaluator.call(topic["snapshot"], timeout=30)
                wait_for(lambda: len(before) == len(_lines(signals_path)), START_S, "signals before the crash",
                          monitor, stderr_path)
                states_before = _messages(received)
                _crash_and_restart(router)
            wait_for(lambda: "reconnected to the router (1)" in stderr_path.read_text(), START_S,
                      "the monitor's reconnection", monitor, stderr_path)
            alive = monitor.poll() is None
            with WampClient(router.rs_url, auth=router.credentials("evaluator")) as evaluator:
                evaluator.subscribe(topic["signal"], after.append)
                # answered: the monitor's subscriptions of the new session are in place (registered after them)
                snapshot_after_restart = evaluator.call_when_registered(topic["snapshot"], timeout=START_S)
                with WampClient(router.rs_url, auth=router.credentials("simulation")) as simulation:
                    for state in states[RESUME:]:
                        simulation.publish(topic["state"], state)
                        if task_fail is not None and state["t"] >= task_fail["t"]:
                            simulation.publish(topic["mission"], task_fail)  # when the robot stops at the wall
                            task_fail = None
                    simulation.publish(topic["mission"], end)
                wait_for(lambda: any(s["signal"] == "SIG_MISSION_END" for s in after), START_S,
                          "SIG_MISSION_END from the restarted router", monitor, stderr_path)
                snapshot_at_end = evaluator.call(topic["snapshot"], timeout=30)  # the monitor lingers after END
            code = monitor.wait(timeout=LINGER_S + START_S)
        finally:
            kill_group(monitor)
    yield RestartRun(out=base, written=_lines(signals_path), before=before, after=after, states_before=states_before,
                     alive_after_crash=alive, snapshot_after_restart=snapshot_after_restart,
                     snapshot_at_end=snapshot_at_end, monitor_stderr=stderr_path.read_text(), monitor_exit=code)


def test_the_monitor_reconnects_by_itself(restart_run: RestartRun) -> None:
    assert restart_run.alive_after_crash
    assert restart_run.monitor_exit == 0, restart_run.monitor_stderr
    stderr = restart_run.monitor_stderr
    assert stderr.count("router connection lost: ") == 1, stderr
    assert stderr.count("reconnected to the router (") == 1, stderr
    assert "reconnected to the router (1): subscriptions restored" in stderr
    # every published state and mission event was processed: LAST_BEFORE + 1 before, the rest after the restart
    assert restart_run.states_before == LAST_BEFORE + 1
    assert f"processed {TRACE_STATES - MISSING} state and 4 mission messages" in stderr, stderr
    assert "problems {gap-state=1}" in stderr, stderr


def test_the_snapshot_rpc_answers_again_after_the_restart(restart_run: RestartRun) -> None:
    for xmi in (restart_run.snapshot_after_restart, restart_run.snapshot_at_end):
        assert isinstance(xmi, str) and "tb3" in xmi
    # after END nothing changes: the model served over the new session is the one written on exit
    assert restart_run.snapshot_at_end == (restart_run.out / "exit.xmi").read_text(encoding="utf-8")


def test_the_lost_states_are_reported_as_one_data_gap(restart_run: RestartRun) -> None:
    gaps = [s for s in restart_run.written if s["signal"] == "SIG_MONITOR_DATA_GAP"]
    assert len(gaps) == 1, gaps
    (gap,) = gaps
    assert (gap["subject"], gap["object"], gap["distance"]) == ("tb3", "state", MISSING)
    assert gap["t"] == pytest.approx(RESUME * 0.05, abs=1e-9)  # at the first state after the reconnection


def test_every_signal_is_written_and_published(restart_run: RestartRun) -> None:
    written = restart_run.written
    assert [s["seq"] for s in written] == list(range(len(written)))
    names = [s["signal"] for s in written]
    assert names[0] == "SIG_MISSION_BEGIN" and names[-1] == "SIG_MISSION_END"
    # signals on both sides of the crash, the collision with the wall after it
    crash = len(restart_run.before)
    assert "SIG_GEOM_FAR_TRANSIT_CLOSE" in names[:crash], names
    assert "SIG_GEOM_CLOSE_TRANSIT_COLLISION" in names[crash:], names
    # the evaluator before the crash got everything emitted until then, in order
    assert restart_run.before == written[:crash]
    # the one that joined the restarted router got every later signal; a signal sent again after the reconnection
    # (its acknowledgement died with the router) is a duplicate a receiver drops by seq
    by_seq = {s["seq"]: s for s in restart_run.after}
    assert [by_seq.get(s["seq"]) for s in written[crash:]] == written[crash:]
    assert all(s == written[s["seq"]] for s in restart_run.after)


def test_the_monitor_stops_on_time_when_the_router_is_gone_for_good(
    repo_root: Path,
    monitor_jar: Path,
    java_exe: str,
    tmp_path: Path,
) -> None:
    case = repo_root / "runtime-monitor" / "src" / "test" / "resources" / "cases" / "room"
    timeout_s = 10.0
    stderr_path = tmp_path / "monitor.err"
    with Router(run_dir=tmp_path / "router", run_id=RUN_ID) as router:
        with open(stderr_path, "w") as stderr:
            monitor = subprocess.Popen(
                [java_exe, "-jar", str(monitor_jar), "--router", router.ws_url,
                 "--auth-file", str(router.auth_file("monitor")), "--run", RUN_ID, "--case", str(case),
                 "--until-end", "--timeout", str(timeout_s), "--snapshot-out", str(tmp_path / "exit.xmi")],
                stdout=subprocess.DEVNULL, stderr=stderr, stdin=subprocess.DEVNULL, start_new_session=True)
        try:
            wait_for(lambda: "monitoring " in stderr_path.read_text(), START_S, "monitor start", monitor, stderr_path)
            assert router.pid is not None
            os.killpg(router.pid, signal.SIGKILL)  # and never back: the monitor keeps trying until its timeout
            wait_for(lambda: "router connection lost: " in stderr_path.read_text(), START_S, "the loss", monitor,
                      stderr_path)
            # the timeout counts from the start; closing without a router is bounded (seconds, not minutes)
            code = monitor.wait(timeout=timeout_s + START_S)
        finally:
            kill_group(monitor)
    text = stderr_path.read_text()
    assert code == 0, text
    assert "no END event within" in text and "reconnected" not in text, text
    assert (tmp_path / "exit.xmi").is_file()
