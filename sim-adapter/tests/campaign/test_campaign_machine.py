# SPDX-License-Identifier: EPL-2.0
"""A campaign's CPU counts its helpers' whole process trees (the background service and its JVMs)."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time

from rei.campaign.machine import Sample, tree_cpu, usage

BURN = "import time\nend = time.process_time() + 0.6\nwhile time.process_time() < end: pass\ntime.sleep(60)"


def test_a_helpers_cpu_includes_its_live_grandchildren() -> None:
    # a helper (sleeping itself) whose child burns 0.6 s of CPU and then lives on: only /proc sees that time
    spawn = f"import subprocess, sys, time\nsubprocess.Popen([sys.executable, '-c', {BURN!r}])\ntime.sleep(60)"
    helper = subprocess.Popen([sys.executable, "-c", spawn], start_new_session=True)
    try:
        start = Sample.now((helper.pid,))
        deadline = time.monotonic() + 30
        while tree_cpu(helper.pid) - start.helpers_cpu < 0.6 and time.monotonic() < deadline:
            time.sleep(0.05)
        measured = usage(start, Sample.now((helper.pid,)))
        assert 0.6 <= measured["helpers_cpu"] < 5.0
        assert measured["cpu"] >= measured["helpers_cpu"]
    finally:
        os.killpg(helper.pid, signal.SIGKILL)
        helper.wait()


def test_a_process_that_is_gone_counts_nothing() -> None:
    gone = subprocess.Popen([sys.executable, "-c", "pass"])
    gone.wait()
    assert tree_cpu(gone.pid) == 0.0
