# SPDX-License-Identifier: EPL-2.0
"""The room seen from above: floors, walls, furniture, where people walked, where the robot went and believed it
went, and where each signal happened.

Why both paths: the gap between the true path (simulator) and the believed one (odometry) is what explains many
collisions - the robot hit the table it "knew" was 20 cm further away. Signals sit on the true path at the time
of the state message that caused them, so a reader sees *where* the robot got close, not just when.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

from rei.artifacts.world import FOOTPRINT_TYPES
from rei.maps import MapPicture
from rei.report.colours import HUMAN_PATH, ROBOT_BELIEVED, ROBOT_TRUE, css_colour, signal_colour
from rei.report.decimate import MAX_PATH_POINTS, decimate
from rei.report.run_data import Goal, SignalRecord
from rei.report.svg import MapTransform, box_corners, esc, num
from rei.report.tracks import Track, Tracks

#: Width of the map in pixels; the height follows the room's aspect ratio (capped).
MAP_WIDTH = 900.0
MAP_MAX_HEIGHT = 700.0
#: Humans are context, not the subject: fewer points and faint.
MAX_OTHER_POINTS = 800
#: Beyond this many markers the map stops being readable and slow to hover; the rest are listed, not drawn.
MAX_MARKERS = 4000


def map_bounds(world: Mapping[str, Any] | None, tracks: Tracks) -> tuple[float, float, float, float]:
    """The area to draw: the room's bounds grown to whatever the paths reach (drifting odometry can leave it)."""
    boxes: list[tuple[float, float, float, float]] = []
    if world is not None:
        bounds = world.get("bounds")
        if isinstance(bounds, list) and len(bounds) == 4:
            boxes.append(tuple(float(b) for b in bounds))  # type: ignore[arg-type]
        for body in world.get("objects") or ():
            corners = _footprint(body)
            if corners:
                xs, ys = zip(*corners, strict=True)
                boxes.append((min(xs), min(ys), max(xs), max(ys)))
    for track in (tracks.robot, tracks.believed, *tracks.others.values()):
        b = track.bounds()
        if b is not None:
            boxes.append(b)
    if not boxes:
        return 0.0, 0.0, 1.0, 1.0
    xmin, ymin = min(b[0] for b in boxes), min(b[1] for b in boxes)
    xmax, ymax = max(b[2] for b in boxes), max(b[3] for b in boxes)
    margin = 0.3
    return xmin - margin, ymin - margin, max(xmax, xmin + 0.5) + margin, max(ymax, ymin + 0.5) + margin


def render_map(world: Mapping[str, Any] | None, tracks: Tracks, goals: Sequence[Goal],
               signals: Sequence[SignalRecord], picture: MapPicture | None = None) -> str:
    """The map as an inline `<svg id="map">`; layers have ids too (`map-robot-path`, `map-signals`, ...).
    ``picture``: a map room's occupancy map, drawn under the floors (`map-occupancy`)."""
    tf = MapTransform.fit(map_bounds(world, tracks), MAP_WIDTH, max_height_px=MAP_MAX_HEIGHT)
    parts = [(f'<svg id="map" xmlns="http://www.w3.org/2000/svg" width="{num(tf.width)}" '
             f'height="{num(tf.height)}" viewBox="0 0 {num(tf.width)} {num(tf.height)}" role="img" '
             f'aria-label="map of the room with the robot\'s path">'),
             f'<rect x="0" y="0" width="{num(tf.width)}" height="{num(tf.height)}" fill="#fbfbf8"/>']
    if picture is not None:
        parts.append(_picture(picture, tf))
    if world is not None:
        parts.append(_world_layer(world, tf, see_through=picture is not None))
    parts.append(_grid_labels(tf))
    parts.append(_others_layer(tracks.others.values(), tf))
    parts.append(_goals_layer(goals, tf))
    # The belief is drawn over the truth, thin and dashed: they often coincide within centimetres, and the
    # thick true path would hide it completely.
    parts.append(_path(tracks.robot, tf, "map-robot-path", ROBOT_TRUE, dashed=False, label="true path"))
    parts.append(_path(tracks.believed, tf, "map-believed-path", ROBOT_BELIEVED, dashed=True,
                       label="believed path (odometry)"))
    parts.append(_robot_poses(world, tracks.robot, tf))
    parts.append(_markers(signals, tracks.robot, tf))
    parts.append("</svg>")
    return "\n".join(p for p in parts if p)


def _footprint(body: Mapping[str, Any]) -> list[tuple[float, float]] | None:
    """The body's outline in the world: a POLYGON object's polygon placed and turned (not its bounding box), any
    other body's ``size`` rectangle."""
    try:
        x, y, _z, yaw = (float(v) for v in body["pose"][:4])
        sx, sy = (float(v) for v in body["size"][:2])
        points = (body.get("footprint") or {}).get("points") if body.get("shape") == "POLYGON" else None
        if points:
            c, s = math.cos(yaw), math.sin(yaw)
            return [(x + c * float(u) - s * float(v), y + s * float(u) + c * float(v)) for u, v in points]
    except (KeyError, TypeError, ValueError, AttributeError):
        return None
    return box_corners(x, y, sx, sy, yaw)


def _picture(picture: MapPicture, tf: MapTransform) -> str:
    """The map's PNG over its extent: its first row is the top, as SVG's y axis goes (no flip needed)."""
    xmin, ymin, xmax, ymax = picture.extent
    x, y = tf.point(xmin, ymax)
    return (f'<image id="map-occupancy" x="{num(x)}" y="{num(y)}" width="{num(tf.length(xmax - xmin))}" '
            f'height="{num(tf.length(ymax - ymin))}" preserveAspectRatio="none" style="image-rendering:pixelated" '
            f'data-cells-per-pixel="{picture.factor}" href="{picture.data_uri()}"><title>the occupancy map'
            f'</title></image>')


def _world_layer(world: Mapping[str, Any], tf: MapTransform, *, see_through: bool = False) -> str:
    """``see_through``: over a map's picture, floors and walls are translucent, so the map shows beneath them."""
    order = {"FLOOR": 0, "STATIC": 1, "DYNAMIC": 2, "WALL": 3}
    bodies = sorted((b for b in world.get("objects") or () if b.get("category") in order),
                    key=lambda b: order[b["category"]])
    out = ['<g id="map-world">']
    for body in bodies:
        category = body["category"]
        corners = _footprint(body)
        if corners is None:
            continue
        name = esc(body.get("name", ""))
        title = f"<title>{name} ({esc(body.get('type', category))})</title>"
        if category == "FLOOR":
            opacity = ' fill-opacity="0.45"' if see_through else ""
            out.append(f'<polygon class="floor" points="{tf.points_attr(corners)}" fill="#efebe4"{opacity} '
                       f'stroke="#ddd6ca" stroke-width="0.5"/>')
            continue
        fill = "#4a4a4a" if category == "WALL" else css_colour(body.get("colour"))
        dash = ' stroke-dasharray="4 3"' if category == "DYNAMIC" else ""
        if body.get("shape") == "CYLINDER":
            cx, cy = tf.point(float(body["pose"][0]), float(body["pose"][1]))
            r = tf.length(float(body["size"][0]) / 2)
            out.append(f'<circle class="{category.lower()}" cx="{num(cx)}" cy="{num(cy)}" r="{num(r)}" '
                       f'fill="{fill}" fill-opacity="0.85" stroke="#333" stroke-width="0.8"{dash}>{title}</circle>')
        else:
            opacity = ("0.3" if see_through else "1") if category == "WALL" else "0.85"
            out.append(f'<polygon class="{category.lower()}" points="{tf.points_attr(corners)}" fill="{fill}" '
                       f'fill-opacity="{opacity}" stroke="#333" stroke-width="0.8"{dash}>{title}</polygon>')
            if category == "STATIC":
                cx, cy = tf.point(float(body["pose"][0]), float(body["pose"][1]))
                out.append(f'<text class="label" x="{num(cx)}" y="{num(cy + 4)}" text-anchor="middle">{name}</text>')
    out.append("</g>")
    return "\n".join(out)


def _grid_labels(tf: MapTransform) -> str:
    """Metre ticks along the bottom and left edge, so distances can be read off the map."""
    out = ['<g id="map-scale" class="axis">']
    for x in range(math.ceil(tf.xmin), math.floor(tf.xmax) + 1):
        px, py = tf.point(x, tf.ymin)
        out.append(f'<text x="{num(px)}" y="{num(py + 12)}" text-anchor="middle">{x} m</text>')
    for y in range(math.ceil(tf.ymin), math.floor(tf.ymax) + 1):
        px, py = tf.point(tf.xmin, y)
        out.append(f'<text x="{num(px - 2)}" y="{num(py + 3)}" text-anchor="end">{y}</text>')
    out.append("</g>")
    return "\n".join(out)


def _others_layer(others: Sequence[Track] | Any, tf: MapTransform) -> str:
    out = ['<g id="map-humans">']
    for track in others:
        if len(track) == 0:
            continue
        points = tf.points_attr(decimate(track.xy(), MAX_OTHER_POINTS))
        out.append(f'<polyline class="human-path" points="{points}" fill="none" stroke="{HUMAN_PATH}" '
                   f'stroke-opacity="0.35" stroke-width="2"><title>{esc(track.name)} '
                   f'({esc(track.category.lower())}) path</title></polyline>')
        cx, cy = tf.point(track.x[0], track.y[0])
        out.append(f'<circle cx="{num(cx)}" cy="{num(cy)}" r="3" fill="{HUMAN_PATH}" fill-opacity="0.5">'
                   f'<title>{esc(track.name)} at t = {track.t[0]:.2f} s</title></circle>')
    out.append("</g>")
    return "\n".join(out)


def _goals_layer(goals: Sequence[Goal], tf: MapTransform) -> str:
    out = ['<g id="map-goals">']
    for goal in goals:
        if not (math.isfinite(goal.x) and math.isfinite(goal.y)):
            continue
        cx, cy = tf.point(goal.x, goal.y)
        r = max(4.0, tf.length(goal.tolerance))
        out.append(f'<circle class="goal" cx="{num(cx)}" cy="{num(cy)}" r="{num(r)}" fill="#2ca02c" '
                   f'fill-opacity="0.15" stroke="#2ca02c" stroke-width="1.5" stroke-dasharray="3 2">'
                   f'<title>goal {goal.index} at ({goal.x:.2f}, {goal.y:.2f}), tolerance {goal.tolerance:g} m'
                   f'</title></circle>')
        out.append(f'<text class="goal-label" x="{num(cx)}" y="{num(cy - r - 3)}" text-anchor="middle">'
                   f'goal {goal.index}</text>')
    out.append("</g>")
    return "\n".join(out)


def _path(track: Track, tf: MapTransform, element_id: str, colour: str, *, dashed: bool, label: str) -> str:
    if len(track) == 0:
        return f'<g id="{element_id}"></g>'
    points = decimate(track.xy(), MAX_PATH_POINTS)
    dash = ' stroke-dasharray="6 4"' if dashed else ""
    return (f'<polyline id="{element_id}" data-points="{len(points)}" data-samples="{len(track)}" '
            f'points="{tf.points_attr(points)}" fill="none" stroke="{colour}" stroke-width="{1.6 if dashed else 3.5}"'
            f' stroke-linejoin="round" stroke-linecap="round"{dash}><title>{esc(label)}</title></polyline>')


def _outline(world: Mapping[str, Any] | None) -> tuple[tuple[float, float], dict[str, Any] | None]:
    """The robot's size (x, y) and its footprint as world.json gives a robot read from a description (a polygon or
    a circle in the robot's frame), None for a box robot (its ``size`` rectangle centred on its pose)."""
    size, footprint = (0.3, 0.3), None
    robot = world.get("robot") if world is not None else None
    if isinstance(robot, Mapping):
        try:
            size = (float(robot["size"][0]), float(robot["size"][1]))
        except (KeyError, IndexError, TypeError, ValueError):
            pass
        raw = robot.get("footprint")
        polygon, circle = FOOTPRINT_TYPES
        try:
            if isinstance(raw, Mapping) and raw.get("type") == circle:
                footprint = {"type": circle, "x": float(raw["x"]), "y": float(raw["y"]),
                             "radius": float(raw["radius"])}
            elif isinstance(raw, Mapping) and raw.get("type") == polygon and len(raw["points"]) >= 3:
                footprint = {"type": polygon, "points": [(float(px), float(py)) for px, py in raw["points"]]}
        except (KeyError, TypeError, ValueError):
            footprint = None  # a footprint that does not read: the bounding box, as before
    return size, footprint


def _robot_poses(world: Mapping[str, Any] | None, robot: Track, tf: MapTransform) -> str:
    """The robot's outline where it started (hollow) and where it ended (filled), heading marked: a described
    robot's footprint (polygon or circle, turned about its origin as the monitor turns it), else its box."""
    if len(robot) == 0:
        return ""
    size, footprint = _outline(world)
    out = ['<g id="map-robot">']
    for index, label, fill in ((0, "start", "none"), (len(robot) - 1, "end", ROBOT_TRUE)):
        x, y, yaw = robot.x[index], robot.y[index], robot.yaw[index]
        c, s = math.cos(yaw), math.sin(yaw)
        hx, hy = tf.point(x + c * size[0] * 0.8, y + s * size[0] * 0.8)
        cx, cy = tf.point(x, y)
        title = f'<title>robot {label}: ({x:.2f}, {y:.2f}) at t = {robot.t[index]:.2f} s</title>'
        style = f'fill="{fill}" fill-opacity="0.5" stroke="{ROBOT_TRUE}" stroke-width="1.5"'
        if footprint is not None and footprint["type"] == FOOTPRINT_TYPES[1]:
            ox, oy = footprint["x"], footprint["y"]
            px, py = tf.point(x + c * ox - s * oy, y + s * ox + c * oy)
            out.append(f'<circle class="robot-{label}" cx="{num(px)}" cy="{num(py)}" '
                       f'r="{num(tf.length(footprint["radius"]))}" {style}>{title}</circle>')
        else:
            corners = (box_corners(x, y, size[0], size[1], yaw) if footprint is None else
                       [(x + c * px - s * py, y + s * px + c * py) for px, py in footprint["points"]])
            out.append(f'<polygon class="robot-{label}" points="{tf.points_attr(corners)}" {style}>{title}'
                       f'</polygon>')
        out.append(f'<line x1="{num(cx)}" y1="{num(cy)}" x2="{num(hx)}" y2="{num(hy)}" stroke="{ROBOT_TRUE}" '
                   f'stroke-width="2"/>')
    out.append("</g>")
    return "\n".join(out)


def _severity(signal: str) -> int:
    """Which signal's colour a marker shows when several happened at the same place: the most alarming."""
    if "TRANSIT_COLLISION" in signal or signal.endswith("TASK_FAIL"):
        return 3
    if "FAR_TRANSIT_CLOSE" in signal or "DATA_GAP" in signal:
        return 2
    return 1 if signal.startswith("SIG_MISSION") else 0


def _markers(signals: Sequence[SignalRecord], robot: Track, tf: MapTransform) -> str:
    """One marker per place: signals of the same state message (e.g. BEGIN and TASK_START, or a FAR->CLOSE
    ->COLLISION jump) would otherwise hide each other; the marker's title lists all of them."""
    groups: dict[tuple[float, float], list[SignalRecord]] = {}
    for record in signals[:MAX_MARKERS]:
        pose = robot.at(record.t)
        if pose is None:
            continue
        cx, cy = tf.point(pose[0], pose[1])
        groups.setdefault((round(cx, 1), round(cy, 1)), []).append(record)
    out = ['<g id="map-signals">']
    for (cx, cy), records in groups.items():
        shown = max(records, key=lambda r: _severity(r.signal))
        lines = []
        for record in records:
            distance = f", distance {record.distance:.3f} m" if math.isfinite(record.distance) else ""
            lines.append(f"t = {record.t:.2f} s  {esc(record.signal)}  object {esc(record.object)}{distance}")
        count = len(records)
        out.append(f'<circle class="signal" data-signal="{esc(shown.signal)}" data-count="{count}" '
                   f'cx="{num(cx)}" cy="{num(cy)}" r="{5 if count == 1 else 6.5}" fill="{signal_colour(shown.signal)}" '
                   f'stroke="{"#fff" if count == 1 else "#222"}" stroke-width="1"><title>{"&#10;".join(lines)}'
                   f'</title></circle>')
    out.append("</g>")
    return "\n".join(out)
