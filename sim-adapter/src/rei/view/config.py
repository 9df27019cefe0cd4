# SPDX-License-Identifier: EPL-2.0
"""What the live view's page gets as ``/config.json``: everything it needs besides the router's stream.

Why the server hands over the room and the mission instead of the page calling ``config`` and ``mission_info``
over WAMP: the page then only subscribes (a read-only viewer role needs no call permission), it can draw the
room before the simulation registers anything, and it works the same for a replayed run where nobody answers
those procedures. The humans' trajectories are sampled here with the simulator's own Catmull-Rom code, so the
faint line on the page is the path the humans really walk.
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from rei.artifacts import ArtifactError, read_animation, read_mission, read_world_map
from rei.evaluation import load_utilities
from rei.maps import map_picture
from rei.mission.executor import FAULT_KINDS
from rei.report.colours import SIGNAL_COLOURS
from rei.spline import Trajectory
from rei.wamp.topics import Topics

FORMAT = "rei-view/1"
#: Samples per trajectory drawn on the page; a path is context, not data.
PATH_SAMPLES = 240


@dataclass(frozen=True, slots=True)
class RouterAuth:
    """Credentials of the viewer's role for a router that authenticates (a later issue adds roles)."""

    authid: str
    secret: str
    method: str = "ticket"  # or "wampcra"

    def __post_init__(self) -> None:
        if self.method not in ("ticket", "wampcra"):
            raise ValueError(f"authentication method {self.method!r}: expected ticket or wampcra")


def view_config(router_url: str, run_id: str, case_dir: Path | None, *, realm: str = "rei",
                utilities: Path | None = None, auth: RouterAuth | None = None,
                declared: Mapping[str, float | None] | None = None) -> dict[str, Any]:
    """The page's configuration; the case folder's files are optional (what is missing is simply not drawn).

    ``declared``: the utilities the run's VEPL patterns declare (rei.run.patterns.check), so the page scores a
    user's own signals as the evaluator does.

    Raises ValueError for a bad run id or router URL, ``ArtifactError`` for a case file that exists but can
    not be read, ``UtilityError`` for a bad utility file.
    """
    if not router_url.startswith(("ws://", "wss://")):
        raise ValueError(f"the page connects over WebSocket: expected ws://host:port/path, got {router_url!r}")
    topics = Topics(run_id)
    world = _json(case_dir / "world.json") if case_dir is not None else None
    return {
        "format": FORMAT,
        "router": {"url": router_url, "realm": realm,
                   "auth": None if auth is None else {"authid": auth.authid, "method": auth.method,
                                                      "secret": auth.secret}},
        "run_id": run_id,
        "topics": {"state": topics.state, "mission": topics.mission, "signal": topics.signal},
        "world": world,
        "occupancy": _occupancy(case_dir) if world is not None and world.get("map") is not None else None,
        "paths": _paths(case_dir / "animation.json") if case_dir is not None else [],
        "mission": _mission(case_dir / "mission.xml") if case_dir is not None else None,
        "utilities": dict(load_utilities(utilities, declared)),
        "colours": dict(SIGNAL_COLOURS),
        "faults": _fault_events(),
        "hello": None,
    }


def _fault_events() -> dict[str, dict[str, Any]]:
    """Each fault window's edge as the mission event it is (contract/vocabulary.json "faults"), with the fault it
    names and whether it begins the window: the page shades the windows on its utility chart."""
    return {f"FAULT_{sensor.upper()}_{kind.upper()}_{edge}": {"fault": f"{sensor} {kind}", "begin": edge == "BEGIN"}
            for sensor, kinds in FAULT_KINDS.items() for kind in kinds for edge in ("BEGIN", "END")}


def _json(path: Path) -> dict[str, Any] | None:
    if not path.is_file():
        return None
    try:
        value = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as error:
        raise ArtifactError(path, f"not readable JSON: {error}") from None
    if not isinstance(value, Mapping):
        raise ArtifactError(path, "expected a JSON object")
    return dict(value)


def _occupancy(case_dir: Path) -> dict[str, Any] | None:
    """A map room's occupancy map as the picture the page draws under the floors (rei.maps.map_picture)."""
    spec = read_world_map(case_dir / "world.json")
    if spec is None:
        return None
    picture = map_picture(spec.load())
    return {"png": picture.data_uri(), "extent": list(picture.extent)}


def _mission(path: Path) -> dict[str, Any] | None:
    if not path.is_file():
        return None
    mission = read_mission(path)
    return {"name": mission.name,
            "goals": [{"index": g.index, "x": g.pose.x, "y": g.pose.y, "yaw": g.pose.yaw,
                       "tolerance": g.tolerance, "timeout": g.timeout, "floor": g.floor} for g in mission.goals]}


def _paths(path: Path) -> list[dict[str, Any]]:
    """Each animated object's trajectory over one period (a loop) or from its first to its last point."""
    if not path.is_file():
        return []
    out = []
    for obj in read_animation(path).objects:
        trajectory = Trajectory([p.t for p in obj.points], [(p.x, p.y) for p in obj.points], obj.loop)
        span = trajectory.period if trajectory.period > 0 else 0.0
        count = PATH_SAMPLES if span > 0 else 1
        points = []
        for k in range(count + (1 if span > 0 else 0)):
            x, y = trajectory.position(trajectory.start + span * k / count)
            if math.isfinite(x) and math.isfinite(y):
                points.append([round(x, 4), round(y, 4)])
        out.append({"name": obj.name, "category": obj.category.value, "points": points})
    return out
