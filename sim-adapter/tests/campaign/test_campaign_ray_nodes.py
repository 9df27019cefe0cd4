# SPDX-License-Identifier: EPL-2.0
"""The connect-time check of a Ray cluster's nodes (rei.campaign.nodes), through `rei campaign --ray local` (a real
Ray instance; in a process of its own, as Ray keeps a first instance's token for the process's life) whose tasks
run in the runtime environment ``$REI_RAY_RUNTIME_ENV`` names: one that points ``JAVA_HOME`` at a folder without
Java makes the node unfit, named with what it lacks, before any run; a runtime environment that is not JSON is
refused saying so. (A node whose PATH has no java, on a multi-node cluster: tests/campaign/test_campaign_ray_cluster.)"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

from rei.campaign.backends import RUNTIME_ENV_ENV

EXAMPLE = Path(__file__).resolve().parents[3] / "examples" / "simple_navigation.rei"


def _campaign(tmp_path: Path, runtime_env: str) -> subprocess.CompletedProcess[str]:
    spec = tmp_path / "spec.yaml"
    spec.write_text(f"groups:\n  - name: example\n    cases: [{EXAMPLE}]\n", encoding="utf-8")
    return subprocess.run([sys.executable, "-m", "rei.cli", "campaign", str(spec), "-o", str(tmp_path / "out"),
                           "--ray", "local", "--workers", "1"], capture_output=True, text=True, timeout=300,
                          env={**os.environ, RUNTIME_ENV_ENV: runtime_env}, check=False)


def test_a_node_the_runtime_env_leaves_without_java_is_named_at_connect_time(tmp_path: Path) -> None:
    settings = tmp_path / "runtime_env.json"  # as a user names one: a file
    settings.write_text(json.dumps({"env_vars": {"JAVA_HOME": str(tmp_path)}}), encoding="utf-8")
    done = _campaign(tmp_path, str(settings))
    assert done.returncode == 2, done.stdout + done.stderr
    lines = done.stderr.strip().splitlines()
    assert lines[-2] == "rei: error: 1 of 1 Ray node(s) cannot run REI's runs:", done.stderr
    assert re.fullmatch(rf"rei: error: node \S+ \([0-9a-f]{{12}}\): JAVA_HOME={re.escape(str(tmp_path))} has no "
                        r"bin/java; fix JAVA_HOME or unset it", lines[-1]), done.stderr
    assert not (tmp_path / "out" / "runs.csv").exists()  # no run was tried


def test_a_runtime_env_that_is_not_json_is_refused(tmp_path: Path) -> None:
    done = _campaign(tmp_path, "{py_modules: [rei.whl]}")
    assert done.returncode == 2, done.stdout + done.stderr
    assert done.stderr.startswith("rei: error: cannot connect to Ray at local: $REI_RAY_RUNTIME_ENV: not a JSON "
                                  "object nor a JSON file"), done.stderr


def _closed_port() -> int:
    import socket

    with socket.socket() as s:  # bound, not listening: a connection there is refused
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def test_a_wrong_address_is_refused_at_once_naming_it(tmp_path: Path) -> None:
    """A user's typo in --ray HOST:PORT: Ray alone retried for many minutes (a warning every few seconds) before
    failing; REI refuses it within seconds, saying nothing answers there."""
    import time

    address = f"127.0.0.1:{_closed_port()}"
    spec = tmp_path / "spec.yaml"
    spec.write_text(f"groups:\n  - name: example\n    cases: [{EXAMPLE}]\n", encoding="utf-8")
    started = time.monotonic()
    done = subprocess.run([sys.executable, "-m", "rei.cli", "campaign", str(spec), "-o", str(tmp_path / "out"),
                           "--ray", address], capture_output=True, text=True, timeout=120, check=False)
    assert time.monotonic() - started < 60, done.stderr
    assert done.returncode == 2, done.stdout + done.stderr
    assert done.stderr.strip().splitlines()[-1].startswith(
        f"rei: error: cannot connect to Ray at {address}: nothing answers at {address} (Connection refused); is the "
        "cluster's head started there"), done.stderr
    assert not (tmp_path / "out" / "runs.csv").exists()


def test_a_missing_token_is_named_when_the_driver_cannot_connect(monkeypatch: Any) -> None:
    """A head started as the docs say asks for Ray's token (Ray's default); a driver without it got only Ray's
    'Failed to connect to Ray cluster', and now the fix besides."""
    import socket

    import ray

    from rei.campaign import backends

    def refuse(**_: Any) -> None:
        raise ConnectionError("Failed to connect to Ray cluster at 127.0.0.1:6379")

    monkeypatch.setattr(ray, "init", refuse)
    monkeypatch.delenv("RAY_AUTH_MODE", raising=False)
    with socket.socket() as head:  # something listens: the address is right
        head.bind(("127.0.0.1", 0))
        head.listen()
        address = f"127.0.0.1:{head.getsockname()[1]}"
        with pytest.raises(backends.RayUnavailableError) as refused:
            backends.connect_ray(address, 1)
    assert str(refused.value) == (f"cannot connect to Ray at {address}: Failed to connect to Ray cluster at "
                                  f"127.0.0.1:6379; {backends.AUTH_HINT}")
    assert "RAY_AUTH_MODE=token" in backends.AUTH_HINT

    def mismatch(**_: Any) -> None:  # a failure that says its cause gets no token hint
        raise RuntimeError("Version mismatch: the cluster was started with Ray 2.59.0, this process has 2.60.0")

    monkeypatch.setattr(ray, "init", mismatch)
    with socket.socket() as head:
        head.bind(("127.0.0.1", 0))
        head.listen()
        address = f"127.0.0.1:{head.getsockname()[1]}"
        with pytest.raises(backends.RayUnavailableError) as refused:
            backends.connect_ray(address, 1)
    assert str(refused.value) == (f"cannot connect to Ray at {address}: Version mismatch: the cluster was started "
                                  "with Ray 2.59.0, this process has 2.60.0")


def test_a_node_whose_rei_is_another_build_is_named_at_connect_time(tmp_path: Path) -> None:
    """A node left with an older wheel (every wheel is rei 0.1.0), or one built from an edited tree, ran the
    driver's runs with other code, unnoticed; now the check compares the node's REI sources with the driver's.
    Here the runtime environment puts a copy of REI with one line changed ahead of the installed one."""
    import shutil

    import rei
    from rei.campaign.nodes import build_id, check_node

    assert check_node(False, False, build=build_id()) == check_node(False, False)  # the same build: no lack
    other = tmp_path / "other" / "rei"
    shutil.copytree(Path(rei.__file__).resolve().parent, other, ignore=shutil.ignore_patterns("__pycache__"))
    with open(other / "campaign" / "plan.py", "a", encoding="utf-8") as f:
        f.write("# edited after the driver's wheel was built\n")
    done = _campaign(tmp_path, json.dumps({"py_modules": [str(other)]}))
    assert done.returncode == 2, done.stdout + done.stderr
    assert re.search(r"rei: error: node \S+ \([0-9a-f]{12}\): its REI is another build than the driver's "
                     rf"\([0-9a-f]{{12}} there, {build_id()[:12]} here\): install the driver's REI there",
                     done.stderr), done.stderr
    assert not (tmp_path / "out" / "runs.csv").exists()  # no run was tried


def test_exit_code_3_of_a_driver_that_cannot_run_rei_is_documented(tmp_path: Path) -> None:
    """A driver without Java (or installed from a wheel without the cli jar) exits 3, which neither `rei campaign
    --help` nor `rei search --help` listed among their exit codes."""
    spec = tmp_path / "spec.yaml"
    spec.write_text(f"groups:\n  - name: example\n    cases: [{EXAMPLE}]\n", encoding="utf-8")
    done = subprocess.run([sys.executable, "-m", "rei.cli", "campaign", str(spec), "-o", str(tmp_path / "out"),
                           "--no-service"], capture_output=True, text=True, timeout=120, check=False,
                          env={**os.environ, "JAVA_HOME": str(tmp_path)})
    assert done.returncode == 3, done.stdout + done.stderr
    assert done.stderr.strip().endswith(f"JAVA_HOME={tmp_path} has no bin/java; fix JAVA_HOME or unset it")
    for command in ("campaign", "search"):
        helped = subprocess.run([sys.executable, "-m", "rei.cli", command, "--help"], capture_output=True, text=True,
                                timeout=60, check=True)
        assert re.search(r"3: this\s+machine cannot run REI \(no Java", helped.stdout), helped.stdout
