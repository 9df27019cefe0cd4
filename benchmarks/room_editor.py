# SPDX-License-Identifier: EPL-2.0
"""How long does the room editor take to open a large room, and to apply one move in it?

The room is a 100 x 100 floor graph written out (10,000 floor statements, walls all around, four tables, the
robot), as `benchmarks/generation.py` writes it. Measured as a user meets it, with Debian's chromium:
- open: from starting the edit engine until the page shows the robot (engine start and model, the state over
  HTTP, the page's drawing), beside its floor, `rei-cli.jar validate` of the same file (a JVM that parses, links
  and validates it once and exits): what the editor adds to reading the file at all;
- move: from releasing a table dragged onto another floor until the page shows it there (the engine applies
  the move through the serializer, parses the result again to check it, validates, and the page redraws),
  beside its floor, the engine's `reset` to the same text (parse, link, validate and diagram in the warm JVM).

Usage: .venv/bin/python benchmarks/room_editor.py [--floors 10000] [--moves 3]
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import tempfile
import time
from pathlib import Path

from generation import grid_for, room_text
from playwright.sync_api import Page, sync_playwright

from rei import toolchain
from rei.edit import EditEngine, EditServer, EditSession, engine_command

PAGE_TIMEOUT_MS = 600_000


def _centre(page: Page, selector: str) -> tuple[float, float]:
    box = page.locator(selector).first.bounding_box()
    if box is None:
        raise SystemExit(f"{selector} is not drawn")
    return box["x"] + box["width"] / 2, box["y"] + box["height"] / 2


def _move(page: Page, name: str, floor: str) -> float:
    """Seconds from releasing ``name`` over ``floor`` until the page draws it there."""
    (x0, y0), (x1, y1) = _centre(page, f'[data-kind="object"][data-name="{name}"]'), \
        _centre(page, f'[data-kind="floor"][data-name="{floor}"]')
    page.mouse.move(x0, y0)
    page.mouse.down()
    page.mouse.move(x1, y1, steps=8)
    started = time.perf_counter()
    page.mouse.up()
    page.wait_for_function(
        "([name, floor]) => document.querySelector(`[data-kind=\"object\"][data-name=\"${name}\"]`)"
        "?.getAttribute('data-floor') === floor", arg=[name, floor], timeout=PAGE_TIMEOUT_MS)
    return time.perf_counter() - started


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n", 1)[0])
    parser.add_argument("--floors", type=int, default=10_000)
    parser.add_argument("--moves", type=int, default=3)
    args = parser.parse_args(argv)
    java = toolchain.find_java()
    chromium = os.environ.get("REI_CHROMIUM") or shutil.which("chromium")
    if chromium is None:
        raise SystemExit("no chromium: run scripts/setup-browser.sh")
    columns, rows = grid_for(args.floors)
    with tempfile.TemporaryDirectory(prefix="rei-edit-bench-") as folder:
        case = Path(folder) / "room.rei"
        case.write_text(room_text(args.floors), encoding="utf-8")
        started = time.perf_counter()
        subprocess.run([str(java.executable), "-jar", str(toolchain.find_jar("cli")), "validate", str(case),
                        "--quiet"], check=True, capture_output=True)
        validate = time.perf_counter() - started

        with sync_playwright() as playwright:
            browser = playwright.chromium.launch(executable_path=chromium, args=["--no-sandbox"])
            page = browser.new_page(viewport={"width": 1400, "height": 900})
            started = time.perf_counter()
            engine = EditEngine(engine_command(toolchain.find_jar("room-editor"), java.executable))
            session = EditSession(case, engine)
            engine_open = time.perf_counter() - started
            server = EditServer(session).start()
            try:
                page.goto(server.url)
                page.locator('[data-kind="robot"]').wait_for(timeout=PAGE_TIMEOUT_MS)
                opened = time.perf_counter() - started
                targets = [f"F_{columns // 4 + 1 + i}_{rows // 4}" for i in range(args.moves)]
                moves = [_move(page, "table1", floor) for floor in targets]
                resets = []
                for _ in range(args.moves):
                    started = time.perf_counter()
                    engine.request("reset", text=session.text)
                    resets.append(time.perf_counter() - started)
            finally:
                server.stop()
                session.close()
                browser.close()
    load = os.getloadavg()
    move, reset = statistics.median(moves), statistics.median(resets)
    print(f"room editor, {args.floors} floors ({columns} x {rows} graph), load average {load[0]:.2f} "
          f"{load[1]:.2f} {load[2]:.2f}")
    print(f"  open: {opened:.2f} s to the drawn page (engine {engine_open:.2f} s); floor: rei-cli validate "
          f"{validate:.2f} s; ratio {opened / validate:.2f}")
    print(f"  move: {move:.2f} s median of {', '.join(f'{m:.2f}' for m in moves)}; floor: engine reset of the "
          f"same text {reset:.2f} s; ratio {move / reset:.2f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
