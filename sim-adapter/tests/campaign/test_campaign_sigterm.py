# SPDX-License-Identifier: EPL-2.0
"""SIGTERM outside the campaign runner's loop (here: while the summary and report are written) unwinds a real
`rei campaign` process: its finally blocks stop the fork server it launched (a session of its own) and remove the
server's socket folder, and it exits 143, instead of dying on the spot."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

# Runs the real command; the only addition is a SIGTERM sent to itself when the runner starts writing its outputs
# (after its loop, where its own handler is gone), after noting its children (the fork server) for the test.
_DRIVER = """
import json, os, signal, sys
from pathlib import Path
import rei.campaign.runner as runner
from rei.cli import main
from rei.lifetime import stat_fields

real = runner.write_outputs

def write_outputs(*args, **kwargs):
    me = os.getpid()
    children = {}
    for entry in os.listdir("/proc"):
        fields = stat_fields(int(entry)) if entry.isdigit() else None
        if fields is not None and int(fields[1]) == me:
            children[entry] = Path(f"/proc/{entry}/cmdline").read_bytes().decode().split("\\0")
    Path(sys.argv[1]).write_text(json.dumps(children))
    os.kill(me, signal.SIGTERM)
    real(*args, **kwargs)

runner.write_outputs = write_outputs
sys.exit(main(sys.argv[2:]))
"""


def _gone(pgid: int, timeout: float) -> bool:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        try:
            os.killpg(pgid, 0)
        except ProcessLookupError:
            return True
        time.sleep(0.1)
    return False


def test_sigterm_while_the_outputs_are_written_stops_the_fork_server(tmp_path: Path) -> None:
    # a case that cannot be generated is an ERROR without a run: nothing to run, so the fork server launched
    # while the cases were prepared is still up when the outputs are written (the campaign closes it at the end)
    (tmp_path / "broken.rei").write_text("this is not a test case\n", encoding="utf-8")
    (tmp_path / "c.yaml").write_text("groups: [{name: g, cases: [broken.rei]}]\n", encoding="utf-8")
    children_file = tmp_path / "children.json"
    process = subprocess.run(
        [sys.executable, "-c", _DRIVER, str(children_file), "campaign", str(tmp_path / "c.yaml"),
         "-o", str(tmp_path / "out"), "--workers", "1", "--no-service"],
        check=False, capture_output=True, text=True, timeout=240)
    children = json.loads(children_file.read_text(encoding="utf-8"))
    forks = {int(pid): argv for pid, argv in children.items() if "rei.campaign.forkserver" in " ".join(argv)}
    assert len(forks) == 1, (children, process.stdout, process.stderr)
    # before: killed by the signal (-15), the finally blocks never ran
    assert process.returncode == 128 + signal.SIGTERM, (process.returncode, process.stdout, process.stderr)
    (pid, argv), = forks.items()
    assert _gone(pid, 30.0), f"fork server {pid} (its own process group) still running"
    socket = Path(argv[-2] if argv[-1] == "" else argv[-1])
    assert socket.name == "fork.sock"
    assert not socket.parent.exists(), f"{socket.parent} left behind"
    # the case that could not be generated is a finished run in ERROR (it crashed the runner: no run folder)
    run = tmp_path / "out" / "runs" / "g__broken__base__r0"
    assert json.loads((run / "result.json").read_text(encoding="utf-8"))["status"] == "ERROR"
    assert (run / "task.json").is_file()
