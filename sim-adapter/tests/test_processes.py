# SPDX-License-Identifier: EPL-2.0
"""rei.processes: what a user reads of a child that died (the ROS 2 bridge, external SUTs and the JVMs quote it)."""

from __future__ import annotations

import sys
from pathlib import Path

from rei.processes import ManagedProcess

# What a Rust program prints when it panics with RUST_BACKTRACE=1: the cause, then many frames.
_PANIC = ("print('ros2-client navigation node, pid 1, on ROS domain 1');"
          "import sys; sys.stderr.write(\"thread 'main' panicked at src/main.rs:459:79:\\n"
          "accept goal: DDSWriteError(WouldBlock)\\nstack backtrace:\\n\");"
          "sys.stderr.write(''.join(f'  {i}: frame {i}\\n      at lib.rs:{i}\\n' for i in range(12)));"
          "sys.exit(101)")


def test_a_panics_cause_leads_the_log_tail_when_its_backtrace_is_longer(tmp_path: Path) -> None:
    process = ManagedProcess("navigation stack", [sys.executable, "-c", _PANIC], tmp_path / "stack.log")
    assert process.wait(30) == 101
    tail = process.log_tail(10).splitlines()
    assert tail[:3] == ["thread 'main' panicked at src/main.rs:459:79:", "accept goal: DDSWriteError(WouldBlock)",
                        "[...]"]
    assert len(tail) == 10 and tail[-1] == "      at lib.rs:11"
    assert process.log_tail(40).splitlines()[0].startswith("ros2-client navigation node")  # all of it fits: as is
    process.stop()


def test_a_log_without_a_panic_gives_its_last_lines(tmp_path: Path) -> None:
    process = ManagedProcess("sut", [sys.executable, "-c", "print('\\n'.join(map(str, range(30))))"],
                             tmp_path / "sut.log")
    assert process.wait(30) == 0
    assert process.log_tail(5).splitlines() == ["25", "26", "27", "28", "29"]
    process.stop()
