# SPDX-License-Identifier: EPL-2.0
"""`rei run --view` end to end: a real run (router, monitor jar, simulation ~20x real time, evaluator) watched
in headless Chromium. The drawn robot follows the true pose, every signal is listed within a second of its
publication, and a screenshot is left in target/view/live-run.png."""

from __future__ import annotations

import contextlib
import json
import os
import queue
import subprocess
import threading
import time
import urllib.request
from pathlib import Path
from typing import Any

import pytest
from playwright.sync_api import Browser
from view_helpers import SHOTS, ViewPage

from rei.wamp import Topics, WampClient, WampError, read_recording
from rei.wamp.auth import Credentials

RUN_ID = "viewlive"
RUN_TIMEOUT_S = 300.0


class Arrivals:
    """Wall time (Unix ms) at which this process received each message of a topic, by seq."""

    def __init__(self) -> None:
        self.at: dict[int, float] = {}

    def __call__(self, payload: Any) -> None:
        self.at.setdefault(int(payload["seq"]), time.time() * 1000)


def lines_of(process: subprocess.Popen[str]) -> queue.Queue[str]:
    lines: queue.Queue[str] = queue.Queue()

    def pump() -> None:
        assert process.stdout is not None
        for line in process.stdout:
            lines.put(line)

    threading.Thread(target=pump, daemon=True).start()
    return lines


def view_url(lines: queue.Queue[str], process: subprocess.Popen[str], timeout: float) -> str:
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        try:
            line = lines.get(timeout=0.5)
        except queue.Empty:
            assert process.poll() is None, f"rei run exited with {process.returncode} before serving the view"
            continue
        if line.startswith("view:") and "http://" in line:
            return line.split()[1]
    pytest.fail(f"rei run printed no view URL within {timeout:.0f} s")


def test_the_page_follows_a_real_run(cli_jar: Path, rei_script: Path, repo_root: Path, browser: Browser,
                                     tmp_path: Path) -> None:
    # cli_jar: the shared fixture that fails with the build hint when the jars are missing
    out = tmp_path / "out"
    process = subprocess.Popen(
        [str(rei_script), "run", str(repo_root / "examples" / "simple_navigation.rei"), "-o", str(out), "--view",
         "--run-id", RUN_ID, "--laser", "full"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, stdin=subprocess.DEVNULL, text=True, start_new_session=True,
        env={**os.environ, "REI_HOME": str(repo_root)})
    page = client = None
    try:
        lines = lines_of(process)
        url = view_url(lines, process, timeout=120)
        with urllib.request.urlopen(url + "config.json", timeout=5) as response:
            config = json.loads(response.read())
        start = config["world"]["robot"]["pose"]
        # This process listens too, before the page says hello (the simulation starts only after it).
        topics = Topics(RUN_ID)
        states, signals = Arrivals(), Arrivals()
        # the router authenticates: this process listens as the page does, with the viewer role it was given
        auth = config["router"]["auth"]
        assert auth["authid"] == "viewer" and auth["method"] == "wampcra"
        client = WampClient(config["router"]["url"],
                            auth=Credentials(auth["authid"], auth["secret"], auth["method"])).start()
        client.subscribe(topics.state, states)
        client.subscribe(topics.signal, signals)
        page = ViewPage(browser, url)
        page.wait_for(f"state.robot !== null && Math.hypot(state.robot.pose[0] - {start[0]}, "
                      f"state.robot.pose[1] - {start[1]}) > 0.3")
        samples: list[dict[str, Any]] = []
        shot = SHOTS / "live-run.png"
        SHOTS.mkdir(parents=True, exist_ok=True)
        shot.unlink(missing_ok=True)
        deadline = time.monotonic() + RUN_TIMEOUT_S
        while time.monotonic() < deadline:
            state = page.state()
            samples.append(state)
            if not shot.exists() and any("_GEOM_" in s["signal"] for s in state["signals"]):
                page.page.screenshot(path=str(shot))  # mid-run, near something: the zone's colour shows
            if state["condition"] == "ended":
                break
            time.sleep(0.1)
        # The mission topic's END can arrive before the monitor's last signals, and a signal received is listed at
        # the page's next frame: give both a moment.
        final = page.state()
        deadline = time.monotonic() + 10.0
        while (not any(s["signal"] == "SIG_MISSION_END" for s in final["signals"])
               or any(s["shownAtMs"] is None for s in final["signals"])) and time.monotonic() < deadline:
            time.sleep(0.1)
            final = page.state()
        page.page.screenshot(path=str(SHOTS / "live-run-end.png"))
        if not shot.exists():
            page.page.screenshot(path=str(shot))
        rows = page.page.locator("#signal-list li").count()
        assert process.wait(timeout=RUN_TIMEOUT_S) == 0, process.stderr.read() if process.stderr else ""
    finally:
        if page is not None:
            page.close()
        if client is not None:
            with contextlib.suppress(WampError):  # the router stopped with the run: the session was lost
                client.close()
        if process.poll() is None:
            process.kill()
            process.wait(timeout=10)

    assert final["condition"] == "ended" and page.errors == []
    recorded = {m["seq"]: m for m in read_recording(out / "streams" / "state.msgpack")}
    drawn = [s for s in samples if s["robot"] is not None]
    assert len({s["robot"]["seq"] for s in drawn}) >= 10
    for sample in drawn:
        robot, tf = sample["robot"], sample["transform"]
        truth = recorded[robot["seq"]]["robot"]["pose"]
        assert robot["pose"] == pytest.approx([truth[0], truth[1], truth[3]], abs=1e-9)
        assert robot["px"] == pytest.approx([tf["ox"] + truth[0] * tf["scale"], tf["oy"] - truth[1] * tf["scale"]],
                                            abs=1e-6)
        assert sample["drawnAtMs"] - states.at[robot["seq"]] < 1000, "the page lagged more than a second"
    published = read_recording(out / "streams" / "signal.msgpack")
    listed = final["signals"]
    assert [s["signal"] for s in listed] == [m["signal"] for m in published] and len(listed) >= 6
    delays = [s["shownAtMs"] - signals.at[s["seq"]] for s in listed]
    print(f"{len(drawn)} samples, {len(listed)} signals, listed after publication: max {max(delays):.0f} ms; "
          f"states dropped {final['dropped']} of {final['received']['state']}; screenshot {shot}")
    assert max(delays) < 1000
    assert rows == min(len(listed), 400)
    assert final["total"] == pytest.approx(json.loads((out / "summary.json").read_text())["total_utility"])
    assert {t["state"] for t in final["tasks"]} == {"SUCCEEDED"}
