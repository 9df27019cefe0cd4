# SPDX-License-Identifier: EPL-2.0
"""`rei campaign` end to end with the real simulation, monitor jar and evaluator: a crashing run is recorded
and the campaign completes; an interrupted campaign resumes without redoing finished runs; Ray runs it too."""

from __future__ import annotations

import contextlib
import csv
import json
import os
import secrets
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

REPO_ROOT = Path(__file__).resolve().parents[2]


EXAMPLE = REPO_ROOT / "examples" / "simple_navigation.rei"


def write_spec(tmp_path: Path, text: str) -> Path:
    (tmp_path / "short.txt").write_text("1.0 0.1 0.0\n", encoding="utf-8")  # a controller that gives up at once
    spec = tmp_path / "spec.yaml"
    spec.write_text(text.replace("EXAMPLE", str(EXAMPLE)).replace("SHORT", str(tmp_path / "short.txt")),
                    encoding="utf-8")
    return spec


def runs(out: Path) -> dict[str, dict[str, str]]:
    with open(out / "runs.csv", newline="", encoding="utf-8") as f:
        return {row["key"]: row for row in csv.DictReader(f)}


def test_six_runs_one_crashes_and_the_campaign_still_completes(tmp_path: Path, run_cli: Any) -> None:
    spec = write_spec(tmp_path, """
name: six
timeout: 240
groups:
  - name: small
    rooms: {size: small, count: 1, seed: 4}
    repetitions: 2
    variants: [{name: base}, {name: fault10, fault: "laser:10%"}]
  - name: example
    cases: [EXAMPLE]
    variants: [{name: nav}, {name: crash, sut: {command: "python3 -c 'import sys; sys.exit(3)'"}}]
""")
    out = tmp_path / "out"
    result = run_cli("campaign", spec, "-o", out, "--workers", "2", timeout=400)
    assert result.returncode == 1, result.stdout + result.stderr  # 1: a run ended in ERROR
    assert "6/6 runs finished, 1 in ERROR" in result.stdout
    table = runs(out)
    assert len(table) == 6
    crashed = table["example__simple_navigation__crash__r0"]
    # a system under test that dies is the run's ERROR, with the evidence (a worker that dies is another ERROR:
    # sim-adapter/tests/campaign/test_campaign_supervise.py)
    assert crashed["status"] == "ERROR" and "exited with code 3" in crashed["error"], crashed
    completed = [row for key, row in table.items() if "crash" not in key]
    assert all(row["status"] == "COMPLETED" for row in completed), completed
    for key in table:
        if "crash" in key:
            continue
        summary = json.loads((out / "runs" / key / "summary.json").read_text())
        assert summary["counts"]["SIG_MISSION_BEGIN"] == 1 and summary["counts"]["SIG_MISSION_END"] == 1
        assert {v["requirement"] for v in summary["verdicts"]} >= {"MISSION_SIMPLE", "MISSION_SEQUENCE"}
        timing = json.loads((out / "runs" / key / "timing.json").read_text())
        assert set(timing) == {"simulation", "monitor", "evaluation"}
    # the same seed and room give the same signals: the two repetitions differ only by seed (0, 1)
    assert table["small__small_dense_h0_s4_01__base__r0"]["seed"] == "0"
    with open(out / "summary.csv", newline="", encoding="utf-8") as f:
        rows = {(r["group"], r["room"], r["variant"]): r for r in csv.DictReader(f)}
    assert rows[("small", "Total", "*")]["executions"] == "4"
    assert rows[("example", "Total", "*")]["errors"] == "1"
    assert rows[("small", "*", "fault10")]["executions"] == "2"
    html = (out / "report.html").read_text(encoding="utf-8")
    assert "6 of 6 runs finished, 1 in ERROR" in html and html.count('class="mission"') == 5
    assert 'id="distribution"' in html and "exited with code 3" in html


def test_an_interrupted_campaign_resumes_without_redoing_finished_runs(tmp_path: Path, rei_script: Path) -> None:
    spec = write_spec(tmp_path, """
name: resume
groups:
  - name: example
    cases: [EXAMPLE]
    repetitions: 3
    variants: [{name: short, controller: "script:SHORT"}]
""")
    out = tmp_path / "out"
    argv = [str(rei_script), "campaign", str(spec), "-o", str(out), "--workers", "1"]
    first = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                             env={**os.environ, "REI_HOME": str(REPO_ROOT)})
    deadline = time.monotonic() + 180
    while not list(out.glob("runs/*/result.json")):
        assert first.poll() is None and time.monotonic() < deadline, "no run finished"
        time.sleep(0.1)
    first.send_signal(signal.SIGTERM)
    output = first.communicate(timeout=60)[0]
    assert first.returncode == 130, output
    assert "campaign interrupted" in output
    finished = {p.parent.name: p.stat().st_mtime_ns for p in out.glob("runs/*/result.json")}
    assert 1 <= len(finished) < 3
    second = subprocess.run(argv, capture_output=True, text=True, timeout=300, check=False,
                            env={**os.environ, "REI_HOME": str(REPO_ROOT)})
    assert second.returncode == 0, second.stdout + second.stderr
    assert f"3 runs, {len(finished)} finished already, {3 - len(finished)} to run" in second.stdout
    for key, mtime in finished.items():
        assert (out / "runs" / key / "result.json").stat().st_mtime_ns == mtime, f"{key} was run again"
    assert len(runs(out)) == 3 and all(r["status"] == "COMPLETED" for r in runs(out).values())


@pytest.fixture
def ray_root() -> Iterator[Path]:
    """A Ray temporary root of the test's own (``RAY_TMPDIR`` for every Ray process the test starts), so no Ray of
    the test touches the machine's shared /tmp/ray and no other Ray's files there touch the test; short, since
    Ray's unix sockets live below it (108 bytes); removed afterwards."""
    root = Path(tempfile.mkdtemp(prefix="rei-ray-test-"))
    try:
        yield root
    finally:
        shutil.rmtree(root, ignore_errors=True)


@pytest.fixture
def ray_head(tmp_path: Path, ray_root: Path) -> Iterator[dict[str, str]]:
    """A Ray head on loopback with 2 CPUs, its files in the test's Ray root, with a token of its own (a user's
    ``~/.ray/auth_token`` plays no part); yields the environment a client needs, ``RAY_ADDRESS`` among it. Stopped
    as Ray stops a blocking ``ray start``: SIGTERM, on which it stops its own processes (``ray stop`` would stop
    every Ray of this user); its process group is killed only if it has not ended after that."""
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    token = ray_root / "auth_token"
    token.write_text(secrets.token_hex(32), encoding="ascii")
    env = {"RAY_TMPDIR": str(ray_root), "RAY_AUTH_MODE": "token", "RAY_AUTH_TOKEN_PATH": str(token)}
    ray = Path(sys.executable).parent / "ray"
    log = open(tmp_path / "ray.log", "w")  # noqa: SIM115 - closed below
    head = subprocess.Popen([str(ray), "start", "--head", "--block", f"--port={port}", "--node-ip-address=127.0.0.1",
                             "--num-cpus=2", '--resources={"rei": 2}', "--include-dashboard=false",
                             "--disable-usage-stats",
                             "--object-store-memory=100000000", f"--temp-dir={ray_root / 'ray'}"],
                            stdout=log, stderr=subprocess.STDOUT, start_new_session=True, env={**os.environ, **env})
    try:
        yield {**env, "RAY_ADDRESS": f"127.0.0.1:{port}"}
    finally:
        head.send_signal(signal.SIGTERM)
        try:
            head.wait(60)
        except subprocess.TimeoutExpired:
            pass
        with contextlib.suppress(ProcessLookupError):  # whatever of the head's group outlived it
            os.killpg(head.pid, signal.SIGKILL)
        head.wait()
        log.close()


def test_a_campaign_runs_on_a_local_ray_cluster(tmp_path: Path, ray_head: dict[str, str], run_cli: Any) -> None:
    spec = write_spec(tmp_path, """
name: on-ray
groups:
  - name: example
    cases: [EXAMPLE]
    repetitions: 2
    variants: [{name: short, controller: "script:SHORT"}, {name: crash, sut: {command: "python3 -c 'import sys; sys.exit(3)'"}}]
""")
    out = tmp_path / "out"
    result = None
    for _ in range(30):  # the head takes a few seconds to accept clients
        result = run_cli("campaign", spec, "-o", out, "--ray", ray_head["RAY_ADDRESS"], timeout=300, env=ray_head)
        if "cannot connect to Ray" not in result.stderr:
            break
        time.sleep(2)
    assert result is not None and result.returncode == 1, result.stdout + result.stderr
    assert "on 2 ray worker(s)" in result.stdout
    table = runs(out)
    assert sorted(r["status"] for r in table.values()) == ["COMPLETED", "COMPLETED", "ERROR", "ERROR"]
    assert all(json.loads((out / "runs" / k / "summary.json").read_text())["counts"]["SIG_MISSION_END"] == 1
               for k, r in table.items() if r["status"] == "COMPLETED")


def test_ray_local_starts_its_own_instance_whatever_an_earlier_ray_left_behind(
    tmp_path: Path, ray_root: Path, run_cli: Any
) -> None:
    """A ``ray start`` that was not stopped with ``ray stop`` leaves its address in ``ray_current_cluster``, which
    a plain ``ray.init(num_cpus=...)`` would try to connect to. ``--ray local`` starts its own instance anyway and
    keeps its files in a folder of its own, deleted at the end: the Ray folder is as it was, the temporary
    directory (here the test's Ray root, as TMPDIR) holds nothing more."""
    stale = ray_root / "ray" / "ray_current_cluster"
    stale.parent.mkdir()
    with socket.socket() as s:  # a port nothing listens on once closed: the earlier cluster is gone
        s.bind(("127.0.0.1", 0))
        stale.write_text(f"127.0.0.1:{s.getsockname()[1]}", encoding="utf-8")
    before = stale.read_text(encoding="utf-8")
    home_token = Path.home() / ".ray" / "auth_token"
    had_home_token = home_token.exists()
    spec = write_spec(tmp_path, """
name: ray-local
groups:
  - name: example
    cases: [EXAMPLE]
    repetitions: 2
    variants: [{name: short, controller: "script:SHORT"}]
""")
    out = tmp_path / "out"
    started = time.monotonic()
    result = run_cli("campaign", spec, "-o", out, "--ray", "local", "--workers", "2", timeout=300,
                     env={"RAY_TMPDIR": str(ray_root), "TMPDIR": str(ray_root)})
    print(f"--ray local campaign of 2 runs: {time.monotonic() - started:.1f} s")
    assert result.returncode == 0, result.stdout + result.stderr
    assert "on 2 ray worker(s)" in result.stdout
    table = runs(out)
    assert len(table) == 2 and all(r["status"] == "COMPLETED" for r in table.values()), table
    assert sorted(p.relative_to(ray_root).as_posix() for p in ray_root.rglob("*")) == [
        "ray", "ray/ray_current_cluster"]
    assert stale.read_text(encoding="utf-8") == before
    assert home_token.exists() == had_home_token, "--ray local saved a token in ~/.ray"


def test_the_replay_path_judges_a_run_as_rei_run_does(tmp_path: Path, run_cli: Any) -> None:
    """The same scripted run through the campaign's replay path and through `rei run` (mode: pipeline)."""
    summaries = {}
    for mode in ("replay", "pipeline"):
        spec = write_spec(tmp_path, f"""
name: {mode}
mode: {mode}
groups:
  - name: example
    cases: [EXAMPLE]
    variants: [{{name: short, controller: "script:SHORT"}}]
""")
        out = tmp_path / mode
        # --no-service: the campaign's own warm JVMs, whether or not an earlier test left a service running
        result = run_cli("campaign", spec, "-o", out, "--workers", "1", "--no-service", timeout=300)
        assert result.returncode == 0, result.stdout + result.stderr
        run = out / "runs" / "example__simple_navigation__short__r0"
        summaries[mode] = json.loads((run / "summary.json").read_text())
        if mode == "replay":  # replayed in the campaign's warm monitor JVM; its thread's CPU counts for the run
            monitor = json.loads((run / "timing.json").read_text())["monitor"]
            assert monitor["served"] is True and monitor["cpu"] > 0
            assert json.loads((run / "result.json").read_text())["cpu_time"] >= monitor["cpu"]
            assert (out / "cases" / "generator.log").is_file()  # the case was generated in a warm JVM too
    replay, pipeline = summaries["replay"], summaries["pipeline"]
    assert replay["counts"] == pipeline["counts"] and replay["counts"]["SIG_MISSION_TASK_FAIL"] == 2
    assert replay["total_utility"] == pipeline["total_utility"]
    assert [(v["requirement"], v["status"]) for v in replay["verdicts"]] == [
        (v["requirement"], v["status"]) for v in pipeline["verdicts"]]
