# SPDX-License-Identifier: EPL-2.0
"""`rei run` through the background service (rei.service): the same results as a run that starts everything
itself, a router and credentials of its own per run, and a service that died or is stale replaced."""

from __future__ import annotations

import json
import os
import re
import signal
import time
from pathlib import Path
from typing import Any

import pytest

from rei.service import DIR_ENV
from rei.service import client as service_client

RUN_TIMEOUT_S = 240.0


@pytest.fixture
def own_service(tmp_path_factory: pytest.TempPathFactory, monkeypatch: pytest.MonkeyPatch) -> Any:
    """A service folder of this test's own (short path: Unix sockets), stopped at the end."""
    import shutil
    import tempfile

    folder = Path(tempfile.mkdtemp(prefix="rei-svc-"))
    monkeypatch.setenv(DIR_ENV, str(folder))
    yield folder
    service_client.stop(folder)
    shutil.rmtree(folder, ignore_errors=True)


def _run(run_cli: Any, repo_root: Path, out: Path, *options: str) -> Any:
    result = run_cli("run", repo_root / "examples" / "simple_navigation.rei", "-o", out, *options,
                     timeout=RUN_TIMEOUT_S)
    assert result.returncode == 0, result.stdout + result.stderr
    return result


def _verdicts(out: Path) -> list[tuple[str, str]]:
    return [(v["requirement"], v["status"]) for v in json.loads((out / "summary.json").read_text())["verdicts"]]


def test_runs_through_the_service_match_a_run_of_its_own_with_a_router_and_secrets_each(
    run_cli: Any, repo_root: Path, tmp_path: Path, own_service: Path
) -> None:
    alone = _run(run_cli, repo_root, tmp_path / "alone", "--no-service")
    assert "background service" not in alone.stdout + alone.stderr
    first, second = tmp_path / "first", tmp_path / "second"
    _run(run_cli, repo_root, first)
    _run(run_cli, repo_root, second)
    # the same streams byte for byte, the same verdicts
    for out in (first, second):
        for stream in ("state", "mission", "signal"):
            assert (out / "streams" / f"{stream}.msgpack").read_bytes() == \
                (tmp_path / "alone" / "streams" / f"{stream}.msgpack").read_bytes(), (out, stream)
        assert _verdicts(out) == _verdicts(tmp_path / "alone")
    # each run had a spare router of the service, now its own folder: its own run id, ports and secrets
    routers = [json.loads((out / "router" / ".crossbar" / "config.json").read_text()) for out in (first, second)]
    ports = [set(re.findall(r"port=(\d+)", json.dumps(r["workers"][0]["transports"]))) for r in routers]
    assert all(len(p) == 2 for p in ports)
    assert ports[0].isdisjoint(ports[1])
    secrets = [json.loads((out / "router" / "auth" / "monitor.json").read_text())["secret"] for out in (first, second)]
    assert secrets[0] != secrets[1]
    run_ids = [json.loads((out / "sim.json").read_text())["run_id"] for out in (first, second)]
    assert run_ids[0] != run_ids[1]
    assert all(f"rei.run.{run_id}.state" in json.dumps(router) for run_id, router in zip(run_ids, routers, strict=True))
    assert not (first / "router").is_symlink()  # moved into the run, not pointing into the service's folder
    # the monitor ran in the service's warm JVM: no JVM of the run's own was started
    assert (own_service / "monitor-jvm.log").is_file()
    assert "processed 665 state" in (first / "monitor.log").read_text()
    # `rei evaluate` replays in the running service's warm JVM: the same signals again
    live = (first / "streams" / "signal.msgpack").read_bytes()
    again = run_cli("evaluate", first, timeout=RUN_TIMEOUT_S)
    assert again.returncode == 0, again.stdout + again.stderr
    assert (first / "streams" / "signal.msgpack").read_bytes() == live
    assert "replayed 665 state" in (first / "monitor-replay.log").read_text()


def test_a_run_starts_its_simulation_on_the_spare_router_before_its_case_is_generated(
    tmp_path: Path, own_service: Path
) -> None:
    """The simulation's start-up (about 0.4 s) overlaps the case's generation: it is started, held, the moment
    the spare router is taken, on the thread that takes it, and it lives on after that thread's work is done (a
    child started with a parent-death signal dies with the *thread* that started it)."""
    import threading

    from rei.cli import build_parser
    from rei.cli._case import prepare_output
    from rei.cli.run import _Warm
    from rei.run.held import HeldSimulation, start_simulation
    from rei.wamp.router import Router

    out = tmp_path / "out"
    prepare_output(out)
    args = build_parser("run").parse_args(["run", "case.rei", "-o", str(out)])
    started = threading.Event()

    def hold(router: Router) -> HeldSimulation:
        held = start_simulation(out / "case", out, router, router.run_id)
        started.set()
        return held

    with _Warm(args, out, hold) as warm:
        assert started.wait(120), "no simulation started on the spare router"
        assert not (out / "case").exists()  # nothing generated: the simulation waits, held
        time.sleep(1.0)
        router, held = warm.taken()
        assert router is not None and held is not None
        try:
            assert held.process.poll() is None, (out / "simulation.log").read_text()
        finally:
            held.process.stop()
            router.stop()


def test_a_killed_service_is_replaced_by_the_next_run_with_one_line(
    run_cli: Any, repo_root: Path, tmp_path: Path, own_service: Path
) -> None:
    _run(run_cli, repo_root, tmp_path / "before")
    pid = int((own_service / "service.pid").read_text())
    os.kill(pid, signal.SIGKILL)  # no clean-up: socket and pid file stay behind
    deadline = time.monotonic() + 10
    while Path(f"/proc/{pid}").exists() and time.monotonic() < deadline:
        time.sleep(0.05)
    after = _run(run_cli, repo_root, tmp_path / "after")
    assert f"rei: the background service (pid {pid}) is gone; starting a new one" in after.stdout, after.stdout
    assert int((own_service / "service.pid").read_text()) != pid
    assert _verdicts(tmp_path / "after") == _verdicts(tmp_path / "before")
    assert len([line for line in after.stdout.splitlines() if "background service" in line]) == 1


def test_a_service_started_from_other_jars_or_code_is_replaced(own_service: Path,
                                                               monkeypatch: pytest.MonkeyPatch) -> None:
    said: list[str] = []
    first = service_client.connect(said.append, own_service)
    assert first.monitor is not None and first.cli is not None and said == []
    assert service_client.connect(said.append, own_service).pid == first.pid  # the same one, while current
    monkeypatch.setattr(service_client, "fingerprint", lambda: "rebuilt")
    second = service_client.connect(said.append, own_service)
    assert second.pid != first.pid
    assert said == [f"rei: REI was rebuilt since the background service (pid {first.pid}) started; replacing it"]


def test_a_folder_too_deep_for_a_socket_is_refused_at_once(tmp_path: Path, run_cli: Any, repo_root: Path,
                                                           monkeypatch: pytest.MonkeyPatch) -> None:
    """The run goes on without the service and says why in one line; nothing waits for a service that cannot
    listen."""
    deep = tmp_path / ("d" * 120)
    monkeypatch.setenv(DIR_ENV, str(deep))
    result = _run(run_cli, repo_root, tmp_path / "out")
    assert "too deep for a Unix socket" in result.stdout and "this run starts its own router" in result.stdout
    assert not deep.exists()


def test_rei_service_status_start_and_stop(run_cli: Any, own_service: Path) -> None:
    assert run_cli("service", "status").returncode == 1
    started = run_cli("service", "start")
    assert started.returncode == 0, started.stdout + started.stderr
    assert f"in {own_service}" in started.stdout and "warm monitor JVM:   ready" in started.stdout
    pid = int((own_service / "service.pid").read_text())
    stopped = run_cli("service", "stop")
    assert stopped.returncode == 0 and "stopped the service" in stopped.stdout
    assert not Path(f"/proc/{pid}").exists() or "Z" in Path(f"/proc/{pid}/stat").read_text().split(")")[1][:3]
    assert run_cli("service", "status").returncode == 1
    assert list((own_service / "routers").iterdir()) == []  # the spare routers went with it


def test_two_runs_back_to_back_each_find_a_spare_router_ready(run_cli: Any, own_service: Path) -> None:
    """Runs back to back come faster than a router starts (~3.5 s): two spares, so the second need not wait."""
    from rei.wamp.router import Router

    started = run_cli("service", "start")
    assert started.returncode == 0, started.stdout + started.stderr
    service = service_client.connect(folder=own_service)
    deadline = time.monotonic() + 120
    while service_client.request(own_service, {"op": "status"})["spares"] < 2:
        assert time.monotonic() < deadline, service_client.request(own_service, {"op": "status"})
        time.sleep(0.2)
    taken = [service.take_router(os.getpid(), 0.0) for _ in range(2)]  # no waiting: each must be ready
    try:
        assert all(description is not None for description in taken), taken
        assert taken[0]["run_id"] != taken[1]["run_id"]
    finally:
        for description in taken:
            if description is not None:
                Router.adopt(description).stop()
    status = run_cli("service", "status")
    assert "spare routers:" in status.stdout, status.stdout
