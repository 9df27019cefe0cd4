# SPDX-License-Identifier: EPL-2.0
"""Helpers of the live view's browser tests: the page's state, a synthetic world and state messages."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from playwright.sync_api import Browser, Page

#: Bounded waits in the page (milliseconds, Playwright's unit).
PAGE_TIMEOUT_MS = 15_000
VIEWPORT = {"width": 1280, "height": 800}
#: Screenshots the tests leave for people (target/ is build output, git-ignored).
SHOTS = Path(__file__).resolve().parents[2] / "target" / "view"


class ViewPage:
    """A page showing the live view, with the errors it logged."""

    def __init__(self, browser: Browser, url: str) -> None:
        self.errors: list[str] = []
        self.page: Page = browser.new_page(viewport=VIEWPORT)  # type: ignore[arg-type]
        self.page.set_default_timeout(PAGE_TIMEOUT_MS)
        self.page.on("pageerror", lambda error: self.errors.append(str(error)))
        self.page.on("console", lambda m: self.errors.append(m.text) if m.type == "error" else None)
        self.page.goto(url)
        self.page.wait_for_function("window.reiView !== undefined && window.reiView.state.subscribed")

    def state(self) -> dict[str, Any]:
        return self.page.evaluate("window.reiView.state")

    def wait_for(self, condition: str, timeout_s: float = 120.0) -> None:
        """Until the JavaScript expression over `state` (window.reiView.state) is true. Generous by default: on
        a busy 2-core machine the monitor's JVM alone can take half a minute to start."""
        self.page.wait_for_function(f"(state => {condition})(window.reiView.state)", timeout=timeout_s * 1000)

    def close(self) -> None:
        self.page.close()


def synthetic_world(columns: int = 6, rows: int = 4, humans: int = 1) -> dict[str, Any]:
    """A world.json (rei-world/1) of columns x rows 1 m floors, walls around, a table and `humans` humans."""
    objects: list[dict[str, Any]] = []
    floors = []
    for i in range(columns):
        for j in range(rows):
            name = f"F_{i}_{j}"
            floors.append({"name": name, "center": [i + 0.5, j + 0.5], "cell": [i, j]})
            objects.append({"name": name, "category": "FLOOR", "type": "Floor", "shape": "BOX",
                            "size": [1.0, 1.0, 0.01], "pose": [i + 0.5, j + 0.5, -0.005, 0.0],
                            "colour": [0.85, 0.82, 0.77, 1.0], "floor": name})
    for name, pose, size in (("W_bottom", [columns / 2, 0.0], [columns + 0.1, 0.1]),
                             ("W_top", [columns / 2, rows], [columns + 0.1, 0.1]),
                             ("W_left", [0.0, rows / 2], [0.1, rows + 0.1]),
                             ("W_right", [columns, rows / 2], [0.1, rows + 0.1])):
        objects.append({"name": name, "category": "WALL", "type": "Wall", "shape": "BOX", "size": [*size, 1.0],
                        "pose": [*pose, 0.5, 0.0], "colour": [0.3, 0.3, 0.3, 1.0], "floor": "F_0_0"})
    objects.append({"name": "table1", "category": "STATIC", "type": "Table", "shape": "BOX", "size": [1.2, 0.8, 0.75],
                    "pose": [3.5, 1.5, 0.375, 0.0], "colour": [0.55, 0.35, 0.17, 1.0], "floor": "F_3_1"})
    for k in range(humans):
        objects.append({"name": f"h{k}", "category": "HUMAN", "type": "Human", "shape": "CYLINDER",
                        "size": [0.5, 0.5, 1.7], "pose": [0.5, 0.5, 0.85, 0.0], "colour": [0.88, 0.67, 0.41, 1.0],
                        "floor": "F_0_0"})
    return {"format": "rei-world/1", "testcase": "Synthetic", "environment": "Lab", "floorSize": 1.0,
            "bounds": [0.0, 0.0, float(columns), float(rows)], "floors": floors, "objects": objects,
            "robot": {"name": "tb3", "type": "Waffle", "shape": "BOX", "size": [0.281, 0.306, 0.141],
                      "pose": [0.5, 0.5, 0.0, 0.0], "floor": "F_0_0",
                      "lidar": {"beams": 360, "rangeMin": 0.12, "rangeMax": 3.5, "rate": 10.0, "mountHeight": 0.17}}}


def state_message(seq: int, t: float, robot_xy: tuple[float, float],
                  humans: list[tuple[str, float, float]] | None = None) -> dict[str, Any]:
    """A state message as the collector publishes it (docs/protocol.md), every real number a float."""
    x, y = robot_xy
    return {"seq": seq, "t": t,
            "objects": [{"name": name, "type": "HUMAN", "pose": [hx, hy, 0.85, 0.0], "twist": [0.0, 0.0, 0.0]}
                        for name, hx, hy in humans or []],
            "robot": {"name": "tb3", "pose": [x, y, 0.0, 0.5], "twist": [0.1, 0.0, 0.0], "odom": [x + 0.01, y, 0.5],
                      "laser_min": float("inf")}}


def write_case(folder: Path, world: dict[str, Any]) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "world.json").write_text(json.dumps(world))
    return folder
