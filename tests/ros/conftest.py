# SPDX-License-Identifier: EPL-2.0
"""What the ROS 1 and ROS 2 bridge tests share."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

from rei.wamp.recording import read_recording


@pytest.fixture
def strafes(run_cli: Any, repo_root: Path, tmp_path: Path,
            processes_mentioning: Any) -> Callable[[Callable[[Path, Path], str]], None]:
    """Runs the strafe example (examples/robots/strafe.rei: a holonomic robot) with the SUT ``sut(script, out)``
    names, a node that plays the sideways-only script as /cmd_vel's linear.y: the robot moves 2 m to its left with
    its heading unchanged, and nothing of the run is left."""

    def run(sut: Callable[[Path, Path], str]) -> None:
        out = tmp_path / "out"
        script = repo_root / "examples" / "robots" / "strafe.script"
        result = run_cli("sim", repo_root / "examples" / "robots" / "strafe.rei", "-o", out, "--progress", "none",
                         "--sut", sut(script, out), timeout=400)
        assert result.returncode == 0 and "mission succeeded" in result.stdout, \
            result.stdout + result.stderr + (out / "sut.log").read_text()
        poses = [m["robot"]["pose"] for m in read_recording(out / "streams" / "state.msgpack")]
        assert poses[-1][1] - poses[0][1] > 1.9
        assert max(abs(p[0] - poses[0][0]) for p in poses) < 0.005 and max(abs(p[-1]) for p in poses) < 0.005
        assert processes_mentioning(out) == []

    return run
