# SPDX-License-Identifier: EPL-2.0
"""`rei campaign` beside a running background service (rei.service): it generates and replays in the service's
warm JVMs instead of starting its own, keeps the service from stopping for idleness while it runs, counts the
service's CPU as its own, and judges every run as a campaign with its own JVMs does."""

from __future__ import annotations

import contextlib
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from rei.service import DIR_ENV, SWITCH_ENV
from rei.service import client as service_client

REPO_ROOT = Path(__file__).resolve().parents[2]
IDLE_S = 4.0  # the service's idle time: far shorter than the campaign, which keeps it alive


@pytest.fixture
def idle_service(monkeypatch: pytest.MonkeyPatch) -> Iterator[tuple[service_client.Service, subprocess.Popen[bytes]]]:
    """A service of this test's own that stops after IDLE_S seconds without a request, its JVMs ready; and its
    process (a child of the test's: it stays a zombie when it ends, so ``poll()`` says whether it runs)."""
    folder = Path(tempfile.mkdtemp(prefix="rei-svc-"))  # short: a Unix socket's path has 107 bytes
    monkeypatch.setenv(DIR_ENV, str(folder))
    monkeypatch.delenv(SWITCH_ENV, raising=False)
    with open(folder / "service.log", "ab") as log:
        process = subprocess.Popen([sys.executable, "-m", "rei.service", "--idle", str(IDLE_S)], cwd=folder,
                                   stdin=subprocess.DEVNULL, stdout=log, stderr=subprocess.STDOUT,
                                   start_new_session=True, env={**os.environ, DIR_ENV: str(folder)})
    deadline = time.monotonic() + 120
    found = service_client.running(folder)
    while found is None or found.monitor is None or found.cli is None:
        assert process.poll() is None and time.monotonic() < deadline, (folder / "service.log").read_text()
        time.sleep(0.1)
        found = service_client.running(folder)  # a hello: it also keeps the service from stopping meanwhile
    yield found, process
    with contextlib.suppress(service_client.ServiceError):  # it may have stopped for idleness meanwhile
        service_client.request(folder, {"op": "stop"})
    process.wait(timeout=30)
    shutil.rmtree(folder, ignore_errors=True)


def test_a_campaign_uses_a_running_services_warm_jvms_and_keeps_it_alive(
        tmp_path: Path, run_cli: Any,
        idle_service: tuple[service_client.Service, subprocess.Popen[bytes]]) -> None:
    service, process = idle_service
    spec = tmp_path / "spec.yaml"
    spec.write_text(f"""
name: served
groups:
  - name: example
    cases: [{REPO_ROOT / "examples" / "simple_navigation.rei"}]
    repetitions: 3
    variants: [{{name: nav}}]
""", encoding="utf-8")
    summaries: dict[str, list[Any]] = {}
    for setting in ("service", "own"):
        out = tmp_path / setting
        started = time.monotonic()
        result = run_cli("campaign", spec, "-o", out, "--workers", "1",
                         *(("--no-service",) if setting == "own" else ()), timeout=400)
        took = time.monotonic() - started
        assert result.returncode == 0, result.stdout + result.stderr
        usage = json.loads((out / "campaign.json").read_text())["metrics"]["campaign"]
        keys = sorted(p.name for p in (out / "runs").iterdir() if p.is_dir())
        assert len(keys) == 3
        if setting == "service":
            assert f"background service's warm JVMs (pid {service.pid}" in result.stdout
            # hellos kept it: without them it would have stopped IDLE_S seconds after the campaign's first request
            assert took > 2 * IDLE_S and process.poll() is None, (service.folder / "service.log").read_text()
            assert not (out / "cases" / "generator.log").exists()  # generated in the service's JVM
            assert not (out / "runs" / "monitor-server.log").exists()  # and replayed there
            for key in keys:
                assert json.loads((out / "runs" / key / "timing.json").read_text())["monitor"]["served"] is True
            assert usage["helpers_cpu"] > 0 and usage["cpu"] > usage["helpers_cpu"]
        else:
            assert "background service" not in result.stdout and usage["helpers_cpu"] == 0
            assert (out / "cases" / "generator.log").is_file() and (out / "runs" / "monitor-server.log").is_file()
        summaries[setting] = [json.loads((out / "runs" / key / "summary.json").read_text()) for key in keys]
    for served, own in zip(summaries["service"], summaries["own"], strict=True):
        assert served["counts"] == own["counts"] and served["total_utility"] == own["total_utility"]
        assert [(v["requirement"], v["status"]) for v in served["verdicts"]] == [
            (v["requirement"], v["status"]) for v in own["verdicts"]]
    # the campaign over, nothing renews the lease: the service stops by itself
    deadline = time.monotonic() + 20 * IDLE_S
    while process.poll() is None and time.monotonic() < deadline:
        time.sleep(0.1)
    assert process.poll() == 0
    assert f"idle for {IDLE_S:.0f} s; stopping" in (service.folder / "service.log").read_text()
