# SPDX-License-Identifier: EPL-2.0
"""`rei view`: arguments checked at the door; serves until SIGTERM, then exits 0 leaving nothing behind."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import urllib.request
from pathlib import Path

import pytest

from rei.cli import main


@pytest.mark.parametrize(("argv", "message"), [
    (["--router", "rs://127.0.0.1:9/", "--run", "r"], "WebSocket"),
    (["--router", "ws://127.0.0.1:9/ws", "--run", "a b"], "run id"),
    (["--router", "ws://127.0.0.1:9/ws", "--run", "r", "--case", "/nonexistent"], "not a folder"),
])
def test_bad_arguments_are_one_error_line(argv: list[str], message: str, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["view", *argv]) != 0
    err = capsys.readouterr().err
    assert err.startswith("rei: error: ") and message in err and err.count("\n") == 1


def test_it_prints_the_pages_address_and_serves_the_case_until_stopped(room: Path) -> None:
    process = subprocess.Popen(
        [sys.executable, "-m", "rei.cli", "view", "--router", "ws://127.0.0.1:9/ws", "--run", "r1",
         "--case", str(room)], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True)
    try:
        assert process.stdout is not None
        line = process.stdout.readline()
        assert line.startswith("view: http://127.0.0.1:"), line + (process.stderr.read() if process.poll() else "")
        url = line.split()[1]
        with urllib.request.urlopen(url + "config.json", timeout=5) as response:
            config = json.loads(response.read())
        assert config["run_id"] == "r1" and config["router"]["url"] == "ws://127.0.0.1:9/ws"
        assert config["world"]["objects"] and config["mission"]["goals"]
        process.send_signal(signal.SIGTERM)
        assert process.wait(timeout=10) == 0
    finally:
        if process.poll() is None:
            os.killpg(process.pid, signal.SIGKILL)
            process.wait(timeout=10)
