# SPDX-License-Identifier: EPL-2.0
"""Computing the metrics of docs/metrics.md from a run folder.

Why from the recordings and not inside the simulation: a run judged again (``rei evaluate``), a campaign's run
and an imported bag have the same streams, so they get the same figures. The robot's footprint gaps are the
monitor's (rei.geometry.footprint_gaps, one definition with the JTS geometry), so a clearance and the monitor's
CLOSE and COLLISION zones never disagree.
"""

from __future__ import annotations

import itertools
import json
import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from rei.artifacts import (
    ArtifactError,
    Category,
    MonitorSpec,
    Shape,
    WorldSpec,
    read_animation,
    read_mission,
    read_monitor,
    read_world,
)
from rei.artifacts.case import case_of_run
from rei.artifacts.world import footprint_polygon
from rei.evaluation.metrics.definitions import NAMES
from rei.evaluation.metrics.encounter import Encounter, encounters, footprints_of
from rei.evaluation.metrics.social import (
    PersonCollision,
    contact_times,
    path_irregularity,
    person_collisions,
    velocities,
    zone_times,
)
from rei.evaluation.mission_info import MissionInfo, MissionInfoError
from rei.geometry import footprint_gaps, polygon_gaps, wrap_angle
from rei.mission.executor import MISSION_INFO_FILE
from rei.sut.api import StaticMap
from rei.wamp.recording import iter_recording, stream_path

Value = float | int | bool | None
#: Below this speed (m/s) the robot counts as standing: its turning is rotation in place.
STANDING = 0.02
#: A back-and-forth reversal: the robot moved at least this far (m) along its heading one way, then as far the
#: other way (a robot that settles or rocks by millimetres when it stops does not oscillate).
REVERSAL = 0.02
#: Rows of robot poses per block of the gap computation (bounds the temporary arrays to a few MB).
_BLOCK = 2048
#: Robot poses per block when choosing the static obstacles near them (about 3 s of a 20 Hz stream).
_NEAR_BLOCK = 64
#: How far (m) beyond the close threshold a footprint gap may be while the simulator still reports a contact
#: (the robot's bodies are not exactly its footprint); generous, it only keeps a few more obstacles.
_CONTACT_MARGIN = 1.0
#: Below this length (m) a shortest path is empty: the start is at the goal (SPL 1 on success, not 0/0).
_EMPTY_PATH = 1e-9


class MetricsError(ValueError):
    """A run folder the metrics can not be computed from (no state recording, no case); the message says why."""


@dataclass(frozen=True, slots=True)
class _Obstacles:
    names: tuple[str, ...]
    boxes: np.ndarray  # (N, 5): x, y, yaw, size_x, size_y
    circle: np.ndarray  # (N,)
    #: A POLYGON object's outline in the world (K, 2), measured as it is; None for the others (and its box, the
    #: polygon's bounding box, only bounds where it can be).
    polygons: tuple[np.ndarray | None, ...] = ()


@dataclass(slots=True)
class _States:
    t: np.ndarray
    pose: np.ndarray  # (T, 3) true x, y, yaw
    twist: np.ndarray  # (T, 3) vx, vy (world), wz
    odom: np.ndarray  # (T, 2), NaN where not published
    moving: np.ndarray  # (T, M, 3) x, y, yaw of world.json's moving objects, NaN where not published
    moving_twist: np.ndarray  # (T, M, 2) their vx, vy (world frame), NaN where not published
    contacts: list[frozenset[str]]
    skipped: int = 0  # malformed state messages left out
    first_skipped: str = ""  # why the first of them was


#: One state message's sample: t, true (x, y, yaw), twist, odometry (x, y), moving objects' places and their
#: velocities, contacts.
_Row = tuple[float, tuple[float, float, float], tuple[float, ...], tuple[float, ...], np.ndarray, np.ndarray,
             frozenset[str]]


@dataclass(frozen=True, slots=True)
class Measured:
    metrics: dict[str, Any]
    #: What was left out of the measurement (malformed state messages, an unreadable animation.json), for the
    #: summary's problems.
    notes: tuple[str, ...]
    #: Each human's encounter: how far off meeting the robot, and the shift of its schedule that meets it (the
    #: search's refinement, rei.search.refine).
    encounters: tuple[Encounter, ...] = ()
    #: The collisions with people, each with the robot's approach speed at its first sample (the requirement
    #: NO_ROBOT_AT_FAULT_COLLISION judges them); None when not measured (no person published, no monitor.json).
    person_collisions: tuple[PersonCollision, ...] | None = None


def compute_metrics(run_dir: Path, case_dir: Path | None = None) -> dict[str, Any]:
    """Every metric of the run in ``run_dir`` (its recorded streams, its case), in the order of ``METRICS``,
    then ``task_times``. Raises MetricsError when there is no state recording or no world.json."""
    return measure(run_dir, case_dir).metrics


def measure(run_dir: Path, case_dir: Path | None = None) -> Measured:
    """:func:`compute_metrics`, with notes on what it had to leave out."""
    run = _read_run(run_dir, case_dir)
    s, spec, robot_shape = run.states, run.spec, run.robot_shape
    statics, static_gaps = _static_gaps(run.statics, s.pose, robot_shape,
                                        spec.close_threshold if spec is not None else 0.0)
    moving_gaps = _gaps(s.pose, robot_shape, _moving_boxes(s.moving, run.moving.boxes), run.moving.circle)
    out: dict[str, Any] = dict.fromkeys(NAMES)
    out.update(_goal_metrics(run.run_dir, run.case_dir, run.world, run.missions, s, run.t0, run.t1))
    out["path_length"] = _path_length(s.pose)
    out.update(_clearances("static", static_gaps))
    out.update(_clearances("humans", moving_gaps[:, run.humans]))
    met, unread = _encounters(run)
    out["encounter_margin_humans"] = min((e.margin for e in met), default=None)
    zones = _zone_matrices(spec, s, np.hstack((static_gaps, moving_gaps)), (*statics.names, *run.moving.names))
    out.update(_zones(s, zones))
    collided = _people(run, moving_gaps, zones[0][:, len(statics.names):] if zones is not None else None, out)
    out.update(_motion(s, run.t1 - run.t0, out["path_length"]))
    out.update(_cost_to_people(run.run_dir))
    return Measured({k: None if isinstance(v, float) and not math.isfinite(v) else v for k, v in out.items()},
                    run.notes + unread, met, collided)


def measure_encounters(run_dir: Path, case_dir: Path | None = None) -> tuple[Encounter, ...]:
    """:func:`measure`'s encounters alone (the same streams, case and window), without the other metrics' gaps
    and planner: what the search's refinement needs after each run. Raises MetricsError as measure does."""
    return _encounters(_read_run(run_dir, case_dir))[0]


def _cost_to_people(run_dir: Path) -> dict[str, float | None]:
    """What the robot cost the people who see it: sim.json's ``people`` (rei.sim.people.cost), the mean and largest
    delay over the people that have one and the mean detour; None without such people."""
    try:
        people = json.loads((run_dir / "sim.json").read_text(encoding="utf-8")).get("people") or {}
    except (OSError, ValueError, AttributeError):
        people = {}
    delays = [float(p["delay"]) for p in people.values() if isinstance(p, dict) and p.get("delay") is not None]
    detours = [float(p["detour"]) for p in people.values() if isinstance(p, dict) and p.get("detour") is not None]
    return {"people_delay_mean": float(np.mean(delays)) if delays else None,
            "people_delay_max": max(delays) if delays else None,
            "people_detour_mean": float(np.mean(detours)) if detours else None}


# -- reading ---------------------------------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class _Run:
    """A run folder read as every metric starts from it: its case, and its states in the mission's window."""

    run_dir: Path
    case_dir: Path
    world: WorldSpec
    spec: MonitorSpec | None  # None without a readable monitor.json
    statics: _Obstacles
    moving: _Obstacles
    humans: np.ndarray  # (M,): which of ``moving`` are humans
    states: _States  # those from the mission's BEGIN to its END
    missions: list[dict[str, Any]] | None  # None for a recording without a mission
    t0: float
    t1: float
    notes: tuple[str, ...]

    @property
    def robot_size(self) -> tuple[float, float]:
        return self.world.robot.size[0], self.world.robot.size[1]

    @property
    def robot_shape(self) -> tuple[float, float] | np.ndarray:
        """What the clearances measure, as the monitor: a box robot's size, a described robot's outline (M, 2)."""
        footprint = self.world.robot.footprint
        return self.robot_size if footprint is None else np.array(footprint_polygon(footprint))


def _read_run(run_dir: Path, case_dir: Path | None) -> _Run:
    """Raises MetricsError without a case, a readable world.json or a state with a robot pose."""
    run_dir = Path(run_dir)
    case_dir = Path(case_dir) if case_dir is not None else case_of_run(run_dir)
    if case_dir is None:
        raise MetricsError(f"{run_dir}: no generated case (case/world.json, or the folder sim.json names)")
    try:
        world = read_world(case_dir / "world.json")
    except ArtifactError as error:
        raise MetricsError(str(error)) from None
    statics = _obstacles([o for o in world.objects if o.category in (Category.WALL, Category.STATIC)])
    movers = [o for o in world.objects if o.category.moving]
    moving = _obstacles(movers)
    humans = np.array([o.category == Category.HUMAN for o in movers], dtype=bool)
    states = _read_states(run_dir, world.robot.name, moving.names)
    missions = _read_stream(run_dir, "mission")
    recorded = _mission_recorded(run_dir) and bool(missions)
    timed = [m for m in missions if _number(m.get("t"))] if recorded else []
    t0 = next((m["t"] for m in timed if m.get("event") == "BEGIN"), None)
    t1 = next((m["t"] for m in reversed(timed) if m.get("event") == "END"), None)
    t0 = float(t0) if t0 is not None else float(states.t[0])
    t1 = float(t1) if t1 is not None else float(states.t[-1])
    window = (states.t >= t0 - 1e-9) & (states.t <= t1 + 1e-9)
    if window.sum() < 1:
        window = np.ones(len(states.t), dtype=bool)
    s = _States(states.t[window], states.pose[window], states.twist[window], states.odom[window],
                states.moving[window], states.moving_twist[window],
                [c for c, w in zip(states.contacts, window, strict=True) if w])
    notes = ((f"{stream_path(run_dir, 'state')}: {states.skipped} malformed state message(s) left out of the "
              f"metrics (the first: {states.first_skipped})"),) if states.skipped else ()
    try:
        spec = read_monitor(case_dir / "monitor.json")
    except (ArtifactError, OSError):
        spec = None
    return _Run(run_dir, case_dir, world, spec, statics, moving, humans, s, missions if recorded else None, t0, t1,
                notes)


def _obstacles(objects: Sequence[Any]) -> _Obstacles:
    """The monitor's footprints (runtime-monitor Monitor.shape): cylinders are circles of their larger
    extent, boxes and meshes rectangles of their size."""
    boxes = np.array([(o.pose[0], o.pose[1], o.pose[3],
                       max(o.size[0], o.size[1]) if o.shape == Shape.CYLINDER else o.size[0],
                       max(o.size[0], o.size[1]) if o.shape == Shape.CYLINDER else o.size[1]) for o in objects],
                     dtype=float).reshape(-1, 5)
    return _Obstacles(tuple(o.name for o in objects), boxes,
                      np.array([o.shape == Shape.CYLINDER for o in objects], dtype=bool),
                      tuple(None if o.outline is None else np.array(o.outline) for o in objects))


def _read_states(run_dir: Path, robot: str, moving: Sequence[str]) -> _States:
    """The state messages with a robot pose; a malformed one is left out and counted (a running system keeps
    what it recorded around a bad message), a torn last message (a crashed writer) ends the stream."""
    path = stream_path(run_dir, "state")
    if not path.is_file():
        raise MetricsError(f"{path}: no recorded state stream")
    column = {name: k for k, name in enumerate(moving)}
    rows: list[_Row] = []
    skipped, first = 0, ""
    messages = iter_recording(path)
    for index in itertools.count():
        try:
            state = next(messages)
        except StopIteration:
            break
        except ValueError:
            break  # a torn last message: what was recorded before it is measured
        try:
            row = _state_row(state, robot, column)
        except (TypeError, ValueError) as error:
            skipped += 1
            first = first or f"message {index}: {error}"
            continue
        if row is not None:
            rows.append(row)
    if not rows:
        raise MetricsError(f"{path}: no state with a robot pose")
    t, pose, twist, odom, places, moved, contacts = zip(*rows, strict=True)
    return _States(np.array(t), np.array(pose), np.array(twist), np.array(odom),
                   np.array(places).reshape(len(t), len(moving), 3), np.array(moved).reshape(len(t), len(moving), 2),
                   list(contacts), skipped, first)


def _state_row(state: Any, robot: str, column: Mapping[str, int]) -> _Row | None:
    """One state message's sample; None for a state without a robot pose (a collector's first messages),
    TypeError or ValueError for a malformed one."""
    r = state.get("robot") if isinstance(state, Mapping) else None
    p = _floats(r.get("pose"), 4) if isinstance(r, Mapping) else None
    if p is None or not _number(state.get("t")):
        return None
    v = _floats(r.get("twist"), 3)
    o = _floats(r.get("odom"), 2)
    row = np.full((len(column), 3), math.nan)
    moved = np.full((len(column), 2), math.nan)
    for body in state.get("objects") or ():
        # type() first: an ABC's isinstance costs 20 times more, and older recordings' full frames list every wall
        if type(body) is not dict and not isinstance(body, Mapping):
            raise TypeError(f"an 'objects' entry is {type(body).__name__}, expected a mapping")
        k = column.get(body.get("name"))
        q = _floats(body.get("pose"), 4) if k is not None else None
        if k is not None and q is not None:
            row[k] = (q[0], q[1], q[3])
            w = _floats(body.get("twist"), 2)
            if w is not None:
                moved[k] = w
    touched = set()
    for pair in state.get("contacts") or ():
        if not isinstance(pair, list | tuple) or len(pair) != 2 or not all(isinstance(n, str) for n in pair):
            raise ValueError(f"a 'contacts' entry is {pair!r}, expected two body names")
        a, b = pair
        if robot in (a, b):
            touched.add(b if a == robot else a)
    return (float(state["t"]), (p[0], p[1], p[3]), v if v is not None else (math.nan,) * 3,
            o if o is not None else (math.nan, math.nan), row, moved, frozenset(touched))


def _number(value: Any) -> bool:
    return isinstance(value, int | float) and not isinstance(value, bool)


def _floats(value: Any, size: int) -> tuple[float, ...] | None:
    if not isinstance(value, list | tuple) or len(value) < size:
        return None
    if not all(isinstance(v, int | float) and not isinstance(v, bool) for v in value[:size]):
        return None
    return tuple(float(v) for v in value[:size])


def _read_stream(run_dir: Path, name: str) -> list[dict[str, Any]]:
    path = stream_path(run_dir, name)
    messages: list[dict[str, Any]] = []
    if path.is_file():
        try:
            messages.extend(m for m in iter_recording(path) if isinstance(m, dict))
        except ValueError:
            pass
    return messages


def _json(path: Path) -> Any:
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None


def _mission_recorded(run_dir: Path) -> bool:
    """False for an imported recording without goals (sim.json ``options.mission``)."""
    sim = _json(run_dir / "sim.json")
    options = sim.get("options") if isinstance(sim, Mapping) else None
    return not isinstance(options, Mapping) or bool(options.get("mission", True))


def _goals(run_dir: Path, case_dir: Path) -> list[tuple[float, float]] | None:
    recorded = _json(run_dir / MISSION_INFO_FILE)
    if isinstance(recorded, Mapping):
        try:
            return [(g.x, g.y) for g in MissionInfo.from_message(recorded).goals]
        except MissionInfoError:
            pass
    try:
        return [(g.pose.x, g.pose.y) for g in read_mission(case_dir / "mission.xml").goals]
    except (ArtifactError, OSError):
        return None


# -- metrics ---------------------------------------------------------------------------------------------------


def _goal_metrics(run_dir: Path, case_dir: Path, world: WorldSpec, missions: list[dict[str, Any]] | None,
                  s: _States, t0: float, t1: float) -> dict[str, Any]:
    goals = _goals(run_dir, case_dir) if missions is not None else None
    if missions is None or not goals:
        return {"success": None, "time": None, "spl": None, "task_times": None}
    started: dict[int, float] = {}
    ended: dict[int, tuple[str, float]] = {}
    for m in missions:
        index, event = m.get("task_index"), m.get("event")
        if not isinstance(index, int) or not _number(m.get("t")):
            continue
        if event == "TASK_START":
            started.setdefault(index, float(m["t"]))
        elif event in ("TASK_SUCCESS", "TASK_FAIL"):
            ended[index] = (str(event), float(m["t"]))
    success = all(ended.get(i, ("", 0.0))[0] == "TASK_SUCCESS" for i in range(len(goals)))
    end = max(t for _, t in ended.values()) if success else t1
    task_times = [round(ended[i][1] - started[i], 6) if i in ended and i in started else None
                  for i in range(len(goals))]
    # Anderson et al.'s SPL: 0 on failure, L* / max(L*, L) on success, which is 1 when the goal is at the
    # start (L* = 0: any path is as long as needed); None when the planner finds no path to compare with.
    shortest = _shortest_path(world, (float(s.pose[0, 0]), float(s.pose[0, 1])), goals)
    spl: float | None = None
    if shortest is not None and not success:
        spl = 0.0
    elif shortest is not None:
        driven = _path_length(s.pose[s.t <= end + 1e-9])
        spl = 1.0 if shortest < _EMPTY_PATH else shortest / max(shortest, driven)
    return {"success": success, "time": end - t0, "spl": spl, "task_times": task_times}


def _shortest_path(world: WorldSpec, start: tuple[float, float], goals: Sequence[tuple[float, float]],
                   ) -> float | None:
    """start -> goal 1 -> goal 2 ... by the reference global planner on the static map, with its cost gradient
    and inflation margin off: the shortest way the footprint fits at any heading. None when a leg has none."""
    from rei.sut.nav.config import NavConfig
    from rei.sut.nav.global_planner import PlanningError, plan
    from rei.sut.nav.grid import CostGrid

    static_map = StaticMap.of_world(world)
    far, near = static_map.robot_radii if static_map.outline is not None else (0.0, 0.0)  # a box robot's: its box
    config = NavConfig(footprint_x=static_map.robot_size[0], footprint_y=static_map.robot_size[1],
                       outline_circumscribed=far, outline_inscribed=near, inflation_margin=0.0, cost_scale=0.0)
    grid = CostGrid(static_map, config)
    total = 0.0
    points = [start, *goals]
    for a, b in itertools.pairwise(points):
        try:
            total += plan(grid, grid.cost, a, b, goal_radius=0.25).length
        except PlanningError:
            return None
    return total


def _path_length(pose: np.ndarray) -> float:
    return float(np.hypot(np.diff(pose[:, 0]), np.diff(pose[:, 1])).sum())


def _static_gaps(statics: _Obstacles, pose: np.ndarray, robot_size: tuple[float, float] | np.ndarray,
                 close: float) -> tuple[_Obstacles, np.ndarray]:
    """The gaps to the static obstacles that can matter to the run, and those obstacles: for each sample, its
    nearest one and every one within the close threshold (a contact included) get their gap; any other is +inf,
    as it changes no metric. A large room has thousands of walls and all gaps are samples x obstacles, so each
    block of samples measures only the obstacles whose least possible gap (centre distance to the block's box of
    robot positions, less both circumradii) is within the block's bound on the nearest gap (a gap is at most the
    centres' distance) or within the close threshold and a margin.
    """
    n = len(statics.names)
    if n == 0 or len(pose) == 0:
        return statics, _polygon_gaps(statics, pose, robot_size, _gaps(pose, robot_size, statics.boxes,
                                                                        statics.circle))
    centres = statics.boxes[:, :2]
    radii = np.where(statics.circle, statics.boxes[:, 3] / 2, np.hypot(statics.boxes[:, 3], statics.boxes[:, 4]) / 2)
    robot_radius = (math.hypot(*robot_size) / 2 if not isinstance(robot_size, np.ndarray)
                    else float(np.hypot(*robot_size.T).max()))  # an outline's reach from the robot's origin
    blocks = []
    for a in range(0, len(pose), _NEAR_BLOCK):
        xy = pose[a:a + _NEAR_BLOCK, :2]
        low, high = xy.min(axis=0), xy.max(axis=0)
        inside = np.clip(centres, low, high)
        nearest = np.hypot(*(centres - inside).T)  # least centre distance over the block's box
        farthest = np.hypot(*np.maximum(np.abs(centres - low), np.abs(centres - high)).T)
        bound = max(float(farthest.min()), close + _CONTACT_MARGIN)
        blocks.append(np.nonzero(nearest - robot_radius - radii <= bound)[0])
    keep = np.zeros(n, dtype=bool)
    for columns in blocks:
        keep[columns] = True
    column_of = np.cumsum(keep) - 1
    gaps = np.full((len(pose), int(keep.sum())), np.inf)
    for a, columns in zip(range(0, len(pose), _NEAR_BLOCK), blocks, strict=True):
        gaps[a:a + _NEAR_BLOCK, column_of[columns]] = footprint_gaps(
            pose[a:a + _NEAR_BLOCK], robot_size, statics.boxes[columns], statics.circle[columns])
    kept = _Obstacles(tuple(name for name, k in zip(statics.names, keep, strict=True) if k), statics.boxes[keep],
                      statics.circle[keep],
                      tuple(q for q, k in zip(statics.polygons, keep, strict=True) if k) if statics.polygons else ())
    return kept, _polygon_gaps(kept, pose, robot_size, gaps)


def _polygon_gaps(statics: _Obstacles, pose: np.ndarray, robot_size: tuple[float, float] | np.ndarray,
                  gaps: np.ndarray) -> np.ndarray:
    """``gaps`` with each POLYGON object's column measured to its polygon (rei.geometry.polygon_gaps), as the
    monitor measures it, not to its bounding box (the other columns as they are)."""
    for k, polygon in enumerate(statics.polygons):
        if polygon is not None and len(pose):
            gaps[:, k] = polygon_gaps(pose, robot_size, polygon)
    return gaps


def _gaps(pose: np.ndarray, robot_size: tuple[float, float] | np.ndarray, boxes: np.ndarray,
          circle: np.ndarray) -> np.ndarray:
    n = boxes.shape[-2] if boxes.ndim >= 2 else 0
    out = np.empty((len(pose), n))
    if n == 0:
        return out
    for a in range(0, len(pose), _BLOCK):
        block = boxes[a:a + _BLOCK] if boxes.ndim == 3 else boxes
        out[a:a + _BLOCK] = footprint_gaps(pose[a:a + _BLOCK], robot_size, block, circle)
    return out


def _moving_boxes(places: np.ndarray, boxes: np.ndarray) -> np.ndarray:
    """(T, M, 5): each moving object's footprint at its published place (world.json's size)."""
    out = np.empty((places.shape[0], places.shape[1], 5))
    out[..., :3] = places
    out[..., 3:] = boxes[None, :, 3:] if len(boxes) else 0.0
    return out


def _encounters(run: _Run) -> tuple[tuple[Encounter, ...], tuple[str, ...]]:
    """rei.evaluation.metrics.encounter over the humans the recording published (none with ``--no-humans``), and
    a note when animation.json, their schedule, cannot be read."""
    s, moving = run.states, run.moving
    published = [k for k in np.nonzero(run.humans)[0] if not np.isnan(s.moving[:, k, 0]).all()]
    if not published:
        return (), ()
    path = run.case_dir / "animation.json"
    try:
        animation = read_animation(path)
    except (ArtifactError, OSError) as error:
        why = str(error) if isinstance(error, ArtifactError) else f"{path}: {error.strerror or error}"
        return (), (f"{why}; without the humans' schedules encounter_margin_humans has no value",)
    footprints = footprints_of([moving.names[k] for k in published], moving.boxes[published],
                               moving.circle[published])
    threshold = run.spec.collision_threshold if run.spec is not None else 0.0
    return tuple(encounters(animation, footprints, s.t, s.pose, run.robot_shape, threshold)), ()


def _clearances(which: str, gaps: np.ndarray) -> dict[str, float | None]:
    """The least gap, and the mean over the samples of each sample's least gap (samples that saw none of them
    are left out)."""
    seen = ~np.isnan(gaps)
    rows = seen.any(axis=1) if gaps.size else np.zeros(len(gaps), dtype=bool)
    if not rows.any():
        return {f"clearance_{which}_min": None, f"clearance_{which}_mean_min": None}
    least = np.where(seen, gaps, np.inf)[rows].min(axis=1)
    return {f"clearance_{which}_min": float(least.min()), f"clearance_{which}_mean_min": float(least.mean())}


def _zone_matrices(spec: MonitorSpec | None, s: _States, gaps: np.ndarray, names: Sequence[str],
                   ) -> tuple[np.ndarray, np.ndarray] | None:
    """The monitor's zones per sample and object (queries/geometry.drl), ``(collides, close)``: COLLISION with an
    object when the simulator reports contact or the gap is below the collision threshold, CLOSE when it is
    below the close threshold; None without a monitor.json (no thresholds)."""
    if spec is None:
        return None
    column = {name: k for k, name in enumerate(names)}
    contact = np.zeros(gaps.shape, dtype=bool)
    for row, touched in enumerate(s.contacts):
        for name in touched:
            if name in column:
                contact[row, column[name]] = True
    with np.errstate(invalid="ignore"):
        collides = contact | (gaps < spec.collision_threshold)
        close = ~contact & (gaps >= spec.collision_threshold) & (gaps < spec.close_threshold)
    return collides, close


def _zones(s: _States, zones: tuple[np.ndarray, np.ndarray] | None) -> dict[str, Value]:
    """The robot is in COLLISION when it collides with anything, else CLOSE when it is close to anything."""
    if zones is None:
        return {"close_time": None, "collision_time": None, "collision_episodes": None, "collision_objects": None}
    collides, close = zones
    in_collision = collides.any(axis=1)
    in_close = close.any(axis=1) & ~in_collision
    hold = np.append(np.diff(s.t), 0.0)  # a sample stands until the next one
    starts = collides & ~np.vstack((np.zeros((1, collides.shape[1]), dtype=bool), collides[:-1]))
    return {"close_time": float(hold[in_close].sum()), "collision_time": float(hold[in_collision].sum()),
            "collision_episodes": int(starts.sum()), "collision_objects": int(collides.any(axis=0).sum())}


def _people(run: _Run, moving_gaps: np.ndarray, moving_collides: np.ndarray | None,
            out: dict[str, Any]) -> tuple[PersonCollision, ...] | None:
    """The social metrics (rei.evaluation.metrics.social) into ``out``, over the humans the recording published
    (none: every one None); returns the collisions with them (None without a monitor.json's thresholds)."""
    s, humans = run.states, np.nonzero(run.humans)[0]
    humans = humans[~np.isnan(s.moving[:, humans, 0]).all(axis=0)] if len(humans) else humans
    if not len(humans):
        out.update(zone_times(s.t, np.empty((len(s.t), 0)), 0.0))
        return None
    out.update(zone_times(s.t, moving_gaps[:, humans], run.t1 - run.t0))
    robot = velocities(s.t, s.pose[:, :2], s.twist[:, :2])
    xy = s.moving[:, humans, :2]
    times, count = [], len(s.t)
    for column, k in enumerate(humans):
        person = velocities(s.t, xy[:, column], s.moving_twist[:, k])
        other = np.hstack((s.moving[:, k], np.broadcast_to(run.moving.boxes[k, 3:], (count, 2))))
        times.append(contact_times(s.pose, robot, run.robot_shape, other, person, run.moving.circle[k]))
    ttc = np.concatenate(times)
    out["ttc_humans_min"] = float(np.nanmin(ttc)) if np.isfinite(ttc).any() else None
    out["path_irregularity_humans"] = path_irregularity(s.t, xy)
    if moving_collides is None:
        return None
    names = [run.moving.names[k] for k in humans]
    shapes = np.column_stack((run.moving.boxes[humans, 3:5], run.moving.circle[humans]))
    # a described robot by its outline's nearest point; a box robot by its origin, as it always was (its figures
    # stay those it had)
    outline = run.robot_shape if isinstance(run.robot_shape, np.ndarray) else None
    collided = person_collisions(s.t, s.pose, robot, s.moving[:, humans], names, moving_collides[:, humans],
                                 outline, s.twist[:, 2], shapes)
    out["collisions_robot_at_fault"] = sum(c.robot_at_fault for c in collided)
    out["collisions_person_at_fault"] = sum(c.person_at_fault for c in collided)
    return collided


def _motion(s: _States, duration: float, path_length: float) -> dict[str, Value]:
    t, (x, y, yaw) = s.t, s.pose.T
    vx, vy, wz = s.twist.T
    speed = np.hypot(vx, vy)
    forward = vx * np.cos(yaw) + vy * np.sin(yaw)
    step = np.hypot(np.diff(x), np.diff(y))
    dt = np.diff(t)
    turn = np.abs([wrap_angle(a) for a in np.diff(yaw)])
    standing = step < STANDING * dt
    drift = np.hypot(s.odom[:, 0] - x, s.odom[:, 1] - y)
    return {
        "speed_mean": path_length / duration if duration > 0 else None,
        "speed_peak": float(np.nanmax(speed)) if np.isfinite(speed).any() else None,
        "jerk_linear": _squared_jerk(t, forward),
        "jerk_angular": _squared_jerk(t, wz),
        "rotation_in_place": float(np.sum(turn[standing])) if len(turn) else 0.0,
        "oscillations": _reversals(np.diff(x) * np.cos(yaw[:-1]) + np.diff(y) * np.sin(yaw[:-1])),
        "odom_drift": float(np.nanmax(drift)) if np.isfinite(drift).any() else None,
    }


def _reversals(advance: np.ndarray) -> int:
    """How often the travel along the heading (``advance``: signed steps, m) turned round after at least
    REVERSAL one way and then at least REVERSAL the other way.

    Hysteresis on the cumulative signed travel: a leg's direction is set once the travel has left the leg's
    start by REVERSAL; it turns round when the travel has come back REVERSAL from the leg's extreme. Pauses and
    millimetre jitter against the direction of a leg neither end it nor start a new one."""
    count, direction, position, extreme, low, high = 0, 0, 0.0, 0.0, 0.0, 0.0
    for step in advance.tolist():
        position += step
        if direction == 0:  # the first leg: which way, once it has gone REVERSAL from its lowest or highest
            low, high = min(low, position), max(high, position)
            if position - low >= REVERSAL:
                direction, extreme = 1, position
            elif high - position >= REVERSAL:
                direction, extreme = -1, position
        elif (position - extreme) * direction > 0:
            extreme = position
        elif (extreme - position) * direction >= REVERSAL:  # back REVERSAL from a leg of at least REVERSAL
            count += 1
            direction, extreme = -direction, position
    return count


def _squared_jerk(t: np.ndarray, velocity: np.ndarray) -> float | None:
    """The integral of the squared second derivative of ``velocity`` over time, by finite differences."""
    if len(t) < 3 or not np.isfinite(velocity).all():
        return None
    dt = np.diff(t)
    acceleration = np.diff(velocity) / dt
    middle = (t[:-1] + t[1:]) / 2
    jerk = np.diff(acceleration) / np.diff(middle)
    return float(np.sum(jerk**2 * np.diff(middle)))
