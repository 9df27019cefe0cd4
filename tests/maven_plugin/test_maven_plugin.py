# SPDX-License-Identifier: EPL-2.0
"""The Maven plugin in a consuming build: it generates every test case and fails the build on an invalid one.

Runs real Maven against the plugin the reactor build installed into the local repository.
"""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
CONSUMER = Path(__file__).resolve().parent / "consumer"
ARTIFACTS = ("world.sdf", "world.json", "mission.xml", "animation.json", "monitor.json")


def run_maven(project: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        ["mvn", "-B", "-Dstyle.color=never", "-s", str(REPO / ".mvn" / "settings.xml"), "generate-test-resources"],
        check=False,
        cwd=project,
        capture_output=True,
        text=True,
        timeout=300,
    )


def copy_consumer(tmp_path: Path) -> Path:
    project = tmp_path / "consumer"
    shutil.copytree(CONSUMER, project)
    return project


def test_generates_every_test_case_into_target(tmp_path: Path) -> None:
    project = copy_consumer(tmp_path)
    result = run_maven(project)
    assert result.returncode == 0, result.stdout[-3000:]
    for case in ("corridor", "rooms/lab"):
        for artifact in ARTIFACTS:
            assert (project / "target" / "rei" / case / artifact).stat().st_size > 0, (case, artifact)
    assert "Generated 2 REI test case(s)" in result.stdout


def test_invalid_test_case_fails_the_build_with_its_position(tmp_path: Path) -> None:
    project = copy_consumer(tmp_path)
    bad = project / "src" / "test" / "rei" / "broken.rei"
    bad.write_text(
        "testcase Broken {\n"
        "  room R size 2 x 2 {\n"
        "    robot tb3 : Waffle on F_7_7\n"
        "  }\n"
        "  mission M { goto F_1_0 goto F_1_1 }\n"
        "}\n"
    )
    result = run_maven(project)
    assert result.returncode != 0
    assert f"{bad}:3:27: error: Unknown floor 'F_7_7'" in result.stdout
    assert "1 of 3 REI test case(s) have errors" in result.stdout
    assert "BUILD FAILURE" in result.stdout
