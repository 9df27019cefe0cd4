# SPDX-License-Identifier: EPL-2.0
"""The report of a real run, rendered by a real browser: `rei sim` (the robot rams the table, laser noise, full
scans), the monitor jar's replay for the signals, the evaluator offline for events.csv and summary.json, then
`python -m rei.report OUT`, and headless Chromium to lay the page out and take a screenshot.

Why a browser and not only the HTML text: the unit tests prove what the SVG says; only a renderer proves that
a person sees it (an SVG that is valid XML can still be zero-sized or drawn off-screen). Chromium comes from the
distribution (`scripts/setup-browser.sh`); nothing is downloaded at test time.
"""

from __future__ import annotations

import json
import re
import struct
import subprocess
import sys
import zlib
from pathlib import Path
from typing import Any

import pytest

from rei import toolchain
from rei.artifacts import read_mission
from rei.evaluation import Evaluator, replay
from rei.mission import mission_info
from rei.report.colours import ROBOT_TRUE
from rei.wamp import read_recording
from rei.wamp.recording import RecordingWriter

#: Turn towards the table, then drive straight into it (scripted controller: `duration v w` per line).
RAM_TABLE = "2.0 0.0 0.2318\n12.0 0.26 0.0\n"
TIMEOUT_S = 180.0


def _run(argv: list[str], cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    try:
        return subprocess.run(argv, capture_output=True, text=True, timeout=TIMEOUT_S, cwd=cwd,
                              stdin=subprocess.DEVNULL, check=False)
    except subprocess.TimeoutExpired:
        pytest.fail(f"{' '.join(argv)} did not finish within {TIMEOUT_S} s")


def browser(chromium: str, *args: str, profile: Path) -> subprocess.CompletedProcess[str]:
    """Headless Chromium with a throw-away profile; --no-sandbox because tests may run as root in a container."""
    return _run([chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                 "--no-first-run", "--hide-scrollbars", f"--user-data-dir={profile}", *args])


def monitor_signals(out: Path, java: toolchain.Java, repo_root: Path) -> list[dict[str, Any]]:
    """The monitor's replay of the recorded streams, one `seq t signal subject object distance` line each."""
    try:
        jar = toolchain.find_jar("monitor", repo_root)
    except toolchain.ToolchainError as error:
        pytest.fail(str(error), pytrace=False)
    result = _run([str(java.executable), "-jar", str(jar), "--replay", str(out), "--case", str(out / "case")])
    assert result.returncode == 0, result.stderr[-2000:]
    signals = []
    for line in result.stdout.splitlines():
        seq, t, name, subject, obj, distance = line.split()
        signals.append({"seq": int(seq), "t": float(t), "signal": name, "subject": subject, "object": obj,
                        "distance": float(distance)})
    return signals


@pytest.fixture(scope="module")
def run_folder(run_cli, java: toolchain.Java, repo_root: Path, tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A complete run folder as `rei run` leaves it: case/, streams/{state,mission,signal}.msgpack, sim.json,
    events.csv, summary.json, verdicts.xml."""
    tmp = tmp_path_factory.mktemp("browser")
    script = tmp / "ram.txt"
    script.write_text(RAM_TABLE)
    out = tmp / "out"
    sim = run_cli("sim", repo_root / "examples" / "simple_navigation.rei", "-o", out, "--no-router",
                  "--controller", f"script:{script}", "--fault", "laser:10%", "--laser", "full")
    assert sim.returncode in (0, 1), sim.stderr
    signals = monitor_signals(out, java, repo_root)
    with RecordingWriter(out / "streams" / "signal.msgpack") as writer:
        for message in signals:
            writer.write(message)
    case = out / "case"
    evaluator = Evaluator(out, mission_info=mission_info(read_mission(case / "mission.xml")),
                          monitor_config=json.loads((case / "monitor.json").read_text()),
                          world=json.loads((case / "world.json").read_text()))
    facts = json.loads((out / "sim.json").read_text())
    replay(signals, evaluator, missions=read_recording(out / "streams" / "mission.msgpack"),
           sim_duration=facts["sim_time"], wall_time=facts["wall_time"], run_id=facts["run_id"])
    report = _run([sys.executable, "-m", "rei.report", str(out)])
    assert report.returncode == 0, report.stderr
    assert f"report: {out / 'report.html'}" in report.stdout and str(out / "run.mcap") in report.stdout
    return out


def test_the_browser_renders_every_plot(run_folder: Path, tmp_path: Path, chromium: str) -> None:
    result = browser(chromium, "--dump-dom", (run_folder / "report.html").as_uri(), profile=tmp_path / "profile")
    assert result.returncode == 0, result.stderr[-2000:]
    dom = result.stdout
    path = re.search(r'<polyline id="map-robot-path"[^>]*\spoints="([^"]*)"', dom)
    assert path, "the map has no robot path"
    assert len(path[1].split()) > 10
    assert re.search(r'<polyline id="map-believed-path"[^>]*\spoints="[^"]+"', dom)
    assert dom.count('class="signal"') >= 5  # markers on the map
    assert re.search(r'<svg id="utility".*?<polyline id="utility-line"[^>]*points="[^"]+"', dom, re.DOTALL)
    bars = re.findall(r'<rect class="bar" data-signal="([A-Z_]+)" data-count="(\d+)"', dom)
    assert dict(bars)["SIG_GEOM_CLOSE_TRANSIT_COLLISION"] == "1"  # the table, hit once
    assert re.search(r'<table id="verdicts">.*MISSION_SIMPLE.*badge fail', dom, re.DOTALL)
    assert "<script" not in dom.lower()  # nothing to fail at view time
    assert "Uncaught" not in result.stderr


def test_the_screenshot_shows_the_map(run_folder: Path, tmp_path: Path, chromium: str) -> None:
    shot = tmp_path / "report.png"
    result = browser(chromium, "--window-size=1000,1400", f"--screenshot={shot}", (run_folder / "report.html").as_uri(),
                     profile=tmp_path / "profile")
    assert result.returncode == 0 and shot.is_file(), result.stderr[-2000:]
    width, height, pixels = read_png(shot)
    assert (width, height) == (1000, 1400)
    # The true path is drawn in ROBOT_TRUE at full opacity; the legend's sample alone is ~70 pixels of it.
    target = bytes.fromhex(ROBOT_TRUE.lstrip("#"))
    assert pixels.count_colour(target) > 300, f"too few path pixels in {shot}"
    print(f"screenshot: {shot}")


class Pixels:
    """Decoded 8-bit RGB(A) rows of a PNG."""

    def __init__(self, rows: list[bytes], channels: int) -> None:
        self.rows, self.channels = rows, channels

    def count_colour(self, rgb: bytes) -> int:
        n = self.channels
        return sum(1 for row in self.rows for i in range(0, len(row), n) if row[i:i + 3] == rgb)


def read_png(path: Path) -> tuple[int, int, Pixels]:
    """A minimal PNG reader (8-bit RGB/RGBA, not interlaced: what Chromium writes), so the test needs no imaging
    library."""
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    pos, idat, header = 8, b"", b""
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        chunk = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = chunk
        elif kind == b"IDAT":
            idat += chunk
        pos += 12 + length
    width, height, depth, colour_type, _, _, interlace = struct.unpack(">IIBBBBB", header)
    assert depth == 8 and colour_type in (2, 6) and interlace == 0, (depth, colour_type, interlace)
    channels = 3 if colour_type == 2 else 4
    raw, stride = zlib.decompress(idat), width * channels
    rows: list[bytes] = []
    previous = bytearray(stride)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            left = line[i - channels] if i >= channels else 0
            up, corner = previous[i], previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + left) & 0xFF
            elif kind == 2:
                line[i] = (line[i] + up) & 0xFF
            elif kind == 3:
                line[i] = (line[i] + (left + up) // 2) & 0xFF
            elif kind == 4:
                p = left + up - corner
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - corner)
                line[i] = (line[i] + (left if pa <= pb and pa <= pc else up if pb <= pc else corner)) & 0xFF
        rows.append(bytes(line))
        previous = line
    return width, height, Pixels(rows, channels)
