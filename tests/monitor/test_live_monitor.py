# SPDX-License-Identifier: EPL-2.0
"""The runtime monitor live on a real router, following a mission that `rei sim` runs, against its replay.

One run, shared by the tests of this module: a private Crossbar router (rei.wamp.Router); the monitor jar
subscribed to run RUN_ID before the run starts (`--case`, `--until-end`, `--record`, `--signals-out`, `--linger`);
`rei sim` running the l-shaped office's mission with the same run id through that router; this test subscribed
to the signal topic and calling the monitor's `snapshot` RPC before the run and after its END. Then the sim's
recording and the monitor's own recording are replayed with `--replay`, and the snapshots are reloaded into EMF
by `org.rei.monitor.cli.SnapshotCheck` (Java: EMF has no Python binding).

Real processes only; every wait is bounded and every process group started here is killed on the way out.
"""

from __future__ import annotations

import json
import subprocess
import threading
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path
from urllib.parse import urlparse

import pytest
from monitor_helpers import kill_group, wait_for

from rei.wamp.client import WampClient
from rei.wamp.recording import read_recording
from rei.wamp.router import Router
from rei.wamp.sockets import tcp_nodelay

RUN_ID = "monitor-live-e2e"
EXAMPLE = "l_shaped_office.rei"
SEED = "3"
#: Bounds for one step each; the 2-core machine may be busy with other builds.
START_S = 60.0
JAVA_S = 120.0
#: How long the monitor keeps serving its snapshot RPC after END (the test calls it as soon as END is seen).
LINGER_S = 8.0
DISTANCE_TOLERANCE = 1e-9


@dataclass
class LiveRun:
    case: Path
    out: Path
    live_signals: list[dict]
    monitor_stdout: str
    monitor_stderr: str
    monitor_exit: int
    snapshot_before: str
    snapshot_after: str
    nodelay: list[int]
    sim_stdout: str


@pytest.fixture(scope="module")
def run_bounded(request: pytest.FixtureRequest, repo_root: Path) -> Callable[..., tuple[int, str, str]]:
    """tests/conftest.py's `run_bounded` (a helper, not a fixture). Test modules must not import conftest modules
    (pytest may hold several under one name), so it is taken from the conftest plug-in pytest registered."""
    conftest = repo_root / "tests" / "conftest.py"
    for plugin in request.config.pluginmanager.get_plugins():
        if getattr(plugin, "__file__", None) == str(conftest) and hasattr(plugin, "run_bounded"):
            return plugin.run_bounded
    pytest.fail(f"{conftest} with run_bounded is not loaded", pytrace=False)


@pytest.fixture(scope="module")
def live_run(run_cli, repo_root: Path, monitor_jar: Path, java_exe: str, tmp_path_factory) -> Iterator[LiveRun]:
    base = tmp_path_factory.mktemp("live-monitor")
    case = base / "case"
    generated = run_cli("generate", repo_root / "examples" / EXAMPLE, "-o", case, "--quiet")
    assert generated.returncode == 0, generated.stderr
    out = base / "sim"
    received: list[dict] = []
    ended = threading.Event()

    def on_signal(payload: dict) -> None:
        received.append(payload)
        if payload.get("signal") == "SIG_MISSION_END":
            ended.set()

    with Router(run_dir=base / "router", run_id=RUN_ID) as router:  # authenticated: one role per component
        stdout_path, stderr_path = base / "monitor.out", base / "monitor.err"
        with open(stdout_path, "w") as stdout, open(stderr_path, "w") as stderr:
            monitor = subprocess.Popen(
                [java_exe, "-jar", str(monitor_jar), "--router", router.ws_url,
                 "--auth-file", str(router.auth_file("monitor")), "--run", RUN_ID, "--case", str(case),
                 "--until-end", "--linger", str(LINGER_S), "--timeout", str(JAVA_S), "--record", str(base / "received"),
                 "--signals-out", str(base / "live-signals.jsonl"), "--snapshot-out", str(base / "exit.xmi")],
                stdout=stdout, stderr=stderr, stdin=subprocess.DEVNULL, start_new_session=True)
        try:
            wait_for(lambda: "monitoring " in stderr_path.read_text(), START_S, "monitor start", monitor, stderr_path)
            with WampClient(router.rs_url, auth=router.credentials("evaluator")) as client:
                client.subscribe(f"rei.run.{RUN_ID}.signal", on_signal)
                snapshot = f"rei.run.{RUN_ID}.snapshot"
                before = client.call_when_registered(snapshot, timeout=START_S)
                nodelay = tcp_nodelay(monitor.pid, peer_port=urlparse(router.ws_url).port)
                sim = run_cli("sim", case, "-o", out, "--router", router.rs_url, "--auth-file",
                              router.auth_file("simulation"), "--run-id", RUN_ID, "--seed", SEED)
                assert sim.returncode == 0, sim.stdout + sim.stderr
                wait_for(ended.is_set, START_S, "SIG_MISSION_END over WAMP", monitor, stderr_path)
                after = client.call(snapshot, timeout=30)  # the monitor lingers after END for this
            code = monitor.wait(timeout=LINGER_S + START_S)
        finally:
            kill_group(monitor)
    yield LiveRun(case=case, out=base, live_signals=received, monitor_stdout=stdout_path.read_text(),
                  monitor_stderr=stderr_path.read_text(), monitor_exit=code, snapshot_before=before,
                  snapshot_after=after, nodelay=nodelay, sim_stdout=sim.stdout)


@pytest.fixture(scope="module")
def java_run(run_bounded, java_exe: str) -> Callable[[list[str]], tuple[int, str, str]]:
    """Run `java ARGS...` to completion within JAVA_S (its process group is killed after that)."""
    return lambda argv: run_bounded([java_exe, *argv], JAVA_S)


def _replay(java_run, jar: Path, run: LiveRun, streams: Path, name: str) -> tuple[list[dict], str, str]:
    signals = run.out / f"{name}.jsonl"
    code, stdout, stderr = java_run(["-jar", str(jar), "--replay", str(streams), "--case", str(run.case),
                                     "--signals-out", str(signals)])
    assert code == 0, stderr
    return [json.loads(line) for line in signals.read_text().splitlines()], stdout, stderr


def _assert_same_signals(live: list[dict], replayed: list[dict]) -> None:
    assert len(replayed) == len(live), (live, replayed)
    for a, b in zip(live, replayed, strict=True):
        assert (a["seq"], a["signal"], a["subject"], a["object"]) == (b["seq"], b["signal"], b["subject"], b["object"])
        assert abs(a["t"] - b["t"]) <= DISTANCE_TOLERANCE, (a, b)
        assert abs(a["distance"] - b["distance"]) <= DISTANCE_TOLERANCE, (a, b)


def test_the_live_run_monitored_the_whole_mission(live_run: LiveRun) -> None:
    assert live_run.monitor_exit == 0, live_run.monitor_stderr
    assert "mission succeeded" in live_run.sim_stdout
    states = read_recording(live_run.out / "sim" / "streams" / "state.msgpack")
    missions = read_recording(live_run.out / "sim" / "streams" / "mission.msgpack")
    assert f"processed {len(states)} state and {len(missions)} mission messages" in live_run.monitor_stderr
    assert "problems {}" in live_run.monitor_stderr, live_run.monitor_stderr
    signals = live_run.live_signals
    assert [s["seq"] for s in signals] == list(range(len(signals)))
    kinds = {s["signal"].split("_")[1] for s in signals}
    assert kinds == {"GEOM", "LASER", "MISSION"}, signals  # every kind of transition is compared below
    assert signals[0]["signal"] == "SIG_MISSION_BEGIN" and signals[-1]["signal"] == "SIG_MISSION_END"
    # what the monitor published is what it wrote to --signals-out and printed
    written = [json.loads(line) for line in (live_run.out / "live-signals.jsonl").read_text().splitlines()]
    assert written == signals
    assert len(live_run.monitor_stdout.splitlines()) == len(signals)


def test_a_replay_of_the_sim_recording_gives_the_live_signals(live_run: LiveRun, java_run, monitor_jar: Path) -> None:
    replayed, stdout, stderr = _replay(java_run, monitor_jar, live_run, live_run.out / "sim", "replay-sim")
    _assert_same_signals(live_run.live_signals, replayed)
    assert stdout == live_run.monitor_stdout  # the printed lines too
    assert "problems {}" in stderr, stderr


def test_the_monitor_records_what_it_received_byte_for_byte(live_run: LiveRun, java_run, monitor_jar: Path) -> None:
    for topic in ("state", "mission"):
        sent = (live_run.out / "sim" / "streams" / f"{topic}.msgpack").read_bytes()
        assert (live_run.out / "received" / f"{topic}.msgpack").read_bytes() == sent, topic
    replayed, _, _ = _replay(java_run, monitor_jar, live_run, live_run.out / "received", "replay-received")
    _assert_same_signals(live_run.live_signals, replayed)


def _snapshot_summary(java_run, jar: Path, xmi: Path) -> dict:
    code, stdout, stderr = java_run(["-cp", str(jar), "org.rei.monitor.cli.SnapshotCheck", str(xmi)])
    assert code == 0, stderr
    return json.loads(stdout)


def test_snapshots_served_over_wamp_reload_into_emf(live_run: LiveRun, java_run, monitor_jar: Path) -> None:
    before, after = live_run.out / "rpc-before.xmi", live_run.out / "rpc-after.xmi"
    assert isinstance(live_run.snapshot_before, str) and isinstance(live_run.snapshot_after, str)
    before.write_text(live_run.snapshot_before, encoding="utf-8")
    after.write_text(live_run.snapshot_after, encoding="utf-8")
    world = json.loads((live_run.case / "world.json").read_text())
    states = read_recording(live_run.out / "sim" / "streams" / "state.msgpack")

    start = _snapshot_summary(java_run, monitor_jar, before)
    assert start["runId"] == RUN_ID and start["time"] == 0.0
    assert start["concreteObjects"] == len(world["objects"]) + 1  # every body of world.json and the robot
    assert start["untypedObjects"] == []
    assert start["robot"]["pose"] == pytest.approx(world["robot"]["pose"], abs=1e-12)
    assert not start["missionBegun"] and start["tasks"] == []

    end = _snapshot_summary(java_run, monitor_jar, after)
    last = states[-1]
    assert end["runId"] == RUN_ID and end["time"] == last["t"]
    assert end["robot"]["pose"] == pytest.approx(last["robot"]["pose"], abs=1e-12)
    assert end["robot"]["laserMin"] == pytest.approx(last["robot"]["laser_min"], abs=1e-12)
    assert end["robot"]["laserClearance"] == pytest.approx(last["robot"]["laser_clearance"], abs=1e-12)
    assert end["missionBegun"] and end["missionEnded"]
    assert [t["status"] for t in end["tasks"]] == ["SUCCEEDED"] * len(end["tasks"]) and end["tasks"]
    # after END nothing changes: the RPC's model is the one written on exit
    assert live_run.snapshot_after == (live_run.out / "exit.xmi").read_text(encoding="utf-8")


def test_the_monitors_socket_to_the_router_has_tcp_nodelay(live_run: LiveRun) -> None:
    assert live_run.nodelay == [1], live_run.nodelay  # one WebSocket connection, Nagle off (netty's default)
