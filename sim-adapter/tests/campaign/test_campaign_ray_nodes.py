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
