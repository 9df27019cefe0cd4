# SPDX-License-Identifier: EPL-2.0
"""The Java client kit (sut-kits/java) and its example SUT, run by `rei run --sut` as real processes."""

from __future__ import annotations

import json
import os
import shlex
import subprocess
from pathlib import Path

from rei import toolchain

EXAMPLE_SUT = "examples/sut/java/GoToGoalSut.java"


def _example_command(java: toolchain.Java, sut_kit_jar: Path, repo_root: Path, *args: str | Path) -> list[str]:
    """`java -cp rei-sut-kit.jar GoToGoalSut.java ARGS...`: the example, compiled by the source launcher."""
    return [str(java.executable), "-cp", str(sut_kit_jar), str(repo_root / EXAMPLE_SUT), *map(str, args)]


def test_the_java_example_completes_the_simple_navigation_mission(
    run_cli, repo_root: Path, tmp_path: Path, processes_mentioning, java: toolchain.Java, sut_kit_jar: Path
) -> None:
    out = tmp_path / "out"
    # `out` as the program's (ignored) argument: a SUT left behind would name the run folder on its command line
    sut = shlex.join(_example_command(java, sut_kit_jar, repo_root, out))
    result = run_cli("run", repo_root / "examples" / "simple_navigation.rei", "-o", out, "--sut", sut, timeout=300)
    assert result.returncode == 0, result.stdout + result.stderr
    summary = json.loads((out / "summary.json").read_text())
    assert summary["status"] == "COMPLETED", summary["error"]
    assert {v["status"] for v in summary["verdicts"]} <= {"pass", "not-applicable"}, summary["verdicts"]
    assert summary["tasks"]["succeeded"] == summary["tasks"]["goals"] == 2
    assert (out / "sut.log").is_file()
    sut_stats = json.loads((out / "sim.json").read_text())["sut"]
    assert sut_stats["exit_code"] == 0 and sut_stats["rejected"] == 0, sut_stats
    assert processes_mentioning(out) == []


def test_the_java_kit_names_a_missing_variable_and_exits_2(
    repo_root: Path, tmp_path: Path, java: toolchain.Java, sut_kit_jar: Path
) -> None:
    env = {k: v for k, v in os.environ.items() if not k.startswith("REI_")}
    env |= {"REI_ROUTER_URL": "ws://127.0.0.1:9/ws", "REI_REALM": "rei", "REI_AUTH_FILE": str(tmp_path / "none")}
    result = subprocess.run(_example_command(java, sut_kit_jar, repo_root), env=env, capture_output=True, text=True,
                            timeout=120, check=False)
    assert result.returncode == 2, result.stderr
    assert "REI_RUN_ID is not set" in result.stderr
