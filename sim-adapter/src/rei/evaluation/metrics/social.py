# SPDX-License-Identifier: EPL-2.0
"""Social navigation metrics: how the robot treats the people around it (docs/metrics.md, "People").

Where they come from: the proxemic zones are Hall's (1966), counted as HuNavSim's evaluator (Perez-Higueras et al.
2023) counts its intimate, personal and social space intrusions: the share of the time the robot spends in the
nearest person's space; the time to collision is the traffic-conflict measure (Hayward 1972) for the robot and
each person; collisions split by who was at fault are SEAN 2.0's (Tsoi et al. 2022) "robot on person" and
"person on robot" collisions, as HuNavSim also reports them; path irregularity is Guzzi et al.'s (2013). Every
distance is the footprint gap of rei.geometry.footprint_gaps, the monitor's geometry, so a zone, a time to
collision and the monitor's COLLISION agree on what touching is.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

#: Hall's proxemic distances (m), the outer edges of the intimate, personal and social spaces (Hall 1966).
ZONES: tuple[tuple[str, float], ...] = (("intimate", 0.45), ("personal", 1.2), ("social", 3.6))
#: How far ahead (s) the time to collision looks: a meeting predicted later is no collision course.
TTC_HORIZON = 10.0
#: The robot is at fault in a collision with a person when its footprint's point nearest to her moves towards her
#: faster than this (m/s) at the collision's first sample or the one before: slower, it stood (a pushed robot jitters by
#: millimetres) or backed away, and the person walked into it.
AT_FAULT_SPEED = 0.05
#: Below this speed (m/s) a person stands: the direction of a step that short is noise, not a heading.
WALKING = 0.1
_PARALLEL = 1e-12  # a relative velocity component below this (m/s) moves along a slab: never enters or leaves it


@dataclass(frozen=True, slots=True)
class PersonCollision:
    """A collision with a person (an episode of the monitor's COLLISION with a HUMAN object) beginning at sample
    time ``t``: ``approach`` is the robot's velocity towards the person's centre (m/s; < 0 moving away, NaN when
    the robot's velocity is not known), the larger of the first sample's and the one before's."""

    person: str
    t: float
    approach: float

    @property
    def robot_at_fault(self) -> bool:
        return self.approach > AT_FAULT_SPEED

    @property
    def person_at_fault(self) -> bool:
        return self.approach <= AT_FAULT_SPEED  # False for NaN: unknown is neither


def zone_times(t: np.ndarray, gaps: np.ndarray, duration: float) -> dict[str, float | None]:
    """Seconds (``<zone>_time``) and share of ``duration`` (``<zone>_share``) the robot spent in the nearest
    person's intimate, personal or social space, Hall's bands: ``g < 0.45``, ``0.45 <= g < 1.2``,
    ``1.2 <= g < 3.6`` for the least footprint gap ``g`` of sample ``k`` to a person (``gaps``: ``(T, H)``, NaN
    where a person is not published), each sample standing until the next. All None without a person."""
    names = [f"{zone}_{what}" for zone, _ in ZONES for what in ("time", "share")]
    seen = ~np.isnan(gaps)
    if not gaps.size or not seen.any():
        return dict.fromkeys(names)
    nearest = np.where(seen, gaps, np.inf).min(axis=1)
    hold = np.append(np.diff(t), 0.0)
    out: dict[str, float | None] = {}
    low = -np.inf
    for zone, high in ZONES:
        time = float(hold[(nearest >= low) & (nearest < high)].sum())
        out[f"{zone}_time"] = time
        out[f"{zone}_share"] = time / duration if duration > 0 else None
        low = high
    return out


def velocities(t: np.ndarray, xy: np.ndarray, twist: np.ndarray) -> np.ndarray:
    """``(T, 2)`` planar velocities: the recorded twist ``(T, 2)`` where it is known, else the positions'
    finite difference (NaN where the positions are not known either)."""
    out = np.array(twist[:, :2], dtype=float)
    unknown = ~np.isfinite(out).all(axis=1)
    if unknown.any() and len(t) >= 2:
        with np.errstate(invalid="ignore", divide="ignore"):
            estimate = np.gradient(xy, t, axis=0)
        out[unknown] = estimate[unknown]
    return out


def contact_times(pose: np.ndarray, velocity: np.ndarray, robot_size: tuple[float, float] | np.ndarray,
                  other: np.ndarray, other_velocity: np.ndarray, circle: np.ndarray, horizon: float = TTC_HORIZON,
                  ) -> np.ndarray:
    """Time to collision ``(N,)``: how long until the robot's footprint (``pose`` ``(N, 3)``, ``robot_size``: the
    rectangle's full size, or a described robot's outline, an ``(M, 2)`` convex polygon counter-clockwise in its
    frame as rei.geometry.outline_gaps takes it) and
    another's (``other`` ``(N, 5)`` of ``x, y, yaw, size_x, size_y``, a circle of diameter ``size_x`` where
    ``circle``) touch (their footprint gap reaches 0) when both keep their velocities (``(N, 2)``, world frame)
    and headings; 0 where they touch or overlap now, inf where they do not meet within ``horizon`` seconds, NaN
    where a place or velocity is not known.

    Exact for the footprints of rei.geometry.footprint_gaps: the other's centre, seen from the robot moving with
    the relative velocity, enters the Minkowski sum of the robot's rectangle and the other's shape: for a circle
    of radius ``r`` the rectangle rounded by ``r`` (two rectangles widened by ``r`` and a disc at each corner), for
    a rectangle the polygon bounded by the four slabs across both rectangles' axes.
    """
    pose, other = np.asarray(pose, dtype=float), np.asarray(other, dtype=float)
    circle = np.broadcast_to(np.asarray(circle, dtype=bool), (len(pose),))
    cos, sin = np.cos(pose[:, 2]), np.sin(pose[:, 2])
    dx, dy = other[:, 0] - pose[:, 0], other[:, 1] - pose[:, 1]
    wx, wy = other_velocity[:, 0] - velocity[:, 0], other_velocity[:, 1] - velocity[:, 1]
    c = np.stack((cos * dx + sin * dy, -sin * dx + cos * dy), axis=1)  # in the robot's frame
    w = np.stack((cos * wx + sin * wy, -sin * wx + cos * wy), axis=1)
    ha, hb = other[:, 3] / 2, other[:, 4] / 2
    if isinstance(robot_size, np.ndarray) and robot_size.ndim == 2:
        found = _outline_contact(c, w, np.asarray(robot_size, dtype=float), other[:, 2] - pose[:, 2], ha, hb, circle)
    else:
        found = _box_contact(c, w, (robot_size[0] / 2, robot_size[1] / 2), other[:, 2] - pose[:, 2], ha, hb, circle)
    found[found > horizon] = np.inf
    unknown = ~(np.isfinite(c).all(axis=1) & np.isfinite(w).all(axis=1) & np.isfinite(other[:, 3:5]).all(axis=1))
    found[unknown] = np.nan
    return found


def _box_contact(c: np.ndarray, w: np.ndarray, half: tuple[float, float], yaw: np.ndarray, ha: np.ndarray,
                 hb: np.ndarray, circle: np.ndarray) -> np.ndarray:
    """:func:`contact_times` for the rectangle of half extents ``half`` (no horizon): ``c``, ``w`` the other's
    centre and relative velocity in the robot's frame, ``yaw`` its heading there."""
    a, b = half
    # a circle: the rectangle widened along x, along y, and the four corner discs
    x_axis, y_axis = np.array([1.0, 0.0]), np.array([0.0, 1.0])
    rounded = np.minimum(_entry(c, w, ((x_axis, a + ha), (y_axis, np.full(len(c), b)))),
                         _entry(c, w, ((x_axis, np.full(len(c), a)), (y_axis, b + ha))))
    for sx, sy in ((1, 1), (-1, 1), (-1, -1), (1, -1)):
        rounded = np.minimum(rounded, _disc_entry(c - np.array([sx * a, sy * b]), w, ha))
    # a rectangle: the Minkowski sum's edges lie across the two rectangles' four axes
    u = np.stack((np.cos(yaw), np.sin(yaw)), axis=1)
    v = np.stack((-np.sin(yaw), np.cos(yaw)), axis=1)
    slabs = []
    for n in (np.broadcast_to(x_axis, u.shape), np.broadcast_to(y_axis, u.shape), u, v):
        reach = a * np.abs(n[:, 0]) + b * np.abs(n[:, 1]) + ha * np.abs((n * u).sum(1)) + hb * np.abs((n * v).sum(1))
        slabs.append((n, reach))
    box = _entry(c, w, slabs)
    return np.where(circle, rounded, box)


def _outline_contact(c: np.ndarray, w: np.ndarray, outline: np.ndarray, yaw: np.ndarray, ha: np.ndarray,
                     hb: np.ndarray, circle: np.ndarray) -> np.ndarray:
    """:func:`contact_times` for a convex, counter-clockwise ``outline`` ``(M, 2)`` (no horizon), the arguments
    as :func:`_box_contact`'s.

    A circle of radius ``r`` touches the outline when its centre enters the outline widened by ``r``: the union of
    the outline, a rectangle ``r`` deep on each edge and a disc at each vertex, so the first time is the least of
    their entry times. A rectangle: the Minkowski sum of the outline and the rectangle is convex, bounded by
    half-planes across the outline's edge normals and the rectangle's two axes both ways, each as far out as the
    two shapes reach along it (their support functions)."""
    n = len(c)
    edge = np.roll(outline, -1, axis=0) - outline
    length = np.hypot(edge[:, 0], edge[:, 1])
    along = edge / length[:, None]
    normal = np.stack((along[:, 1], -along[:, 0]), axis=1)  # outward, counter-clockwise
    at = (normal * outline).sum(axis=1)  # each edge's line: normal . p = at
    start = (along * outline).sum(axis=1)
    rounded = _halfplane_entry(c, w, np.broadcast_to(normal, (n, *normal.shape)), np.broadcast_to(at, (n, len(at))))
    for m in range(len(outline)):
        sides = np.array([normal[m], -normal[m], along[m], -along[m]])
        reach = np.stack((at[m] + ha, np.full(n, -at[m]), np.full(n, start[m] + length[m]), np.full(n, -start[m])),
                         axis=1)
        rounded = np.minimum(rounded, _halfplane_entry(c, w, np.broadcast_to(sides, (n, 4, 2)), reach))
        rounded = np.minimum(rounded, _disc_entry(c - outline[m], w, ha))
    u = np.stack((np.cos(yaw), np.sin(yaw)), axis=1)
    v = np.stack((-np.sin(yaw), np.cos(yaw)), axis=1)
    normals = np.concatenate((np.broadcast_to(normal, (n, *normal.shape)), np.stack((u, -u, v, -v), axis=1)),
                             axis=1)  # (N, M + 4, 2)
    own = (normals[:, :, None, :] * outline[None, None, :, :]).sum(axis=3).max(axis=2)  # the outline's support
    other = ha[:, None] * np.abs((normals * u[:, None, :]).sum(2)) + hb[:, None] * np.abs((normals * v[:, None, :]).sum(2))
    box = _halfplane_entry(c, w, normals, own + other)
    return np.where(circle, rounded, box)


def _halfplane_entry(c: np.ndarray, w: np.ndarray, normals: np.ndarray, reach: np.ndarray) -> np.ndarray:
    """When the points ``c + w τ`` (τ >= 0) first lie in every half-plane ``n · p <= reach`` (``normals``
    ``(N, K, 2)``, ``reach`` ``(N, K)``; 0 inside now, inf never): the Cyrus-Beck clipping of a ray."""
    s = (normals * c[:, None, :]).sum(axis=2)
    d = (normals * w[:, None, :]).sum(axis=2)
    parallel = np.abs(d) < _PARALLEL
    with np.errstate(invalid="ignore", divide="ignore"):
        cross = (reach - s) / d
    outside = s > reach
    enter = np.where(parallel, np.where(outside, np.inf, -np.inf), np.where(d < 0, cross, -np.inf)).max(axis=1)
    leave = np.where(parallel, np.inf, np.where(d > 0, cross, np.inf)).min(axis=1)
    enter = np.maximum(enter, 0.0)
    return np.where(enter <= leave, enter, np.inf)


def _entry(c: np.ndarray, w: np.ndarray, slabs: Sequence[tuple[np.ndarray, np.ndarray]]) -> np.ndarray:
    """When the points ``c + w τ`` (τ >= 0) first lie in every slab ``|n · p| <= reach`` (0 inside now, inf
    never): the slab method of ray casting."""
    enter = np.zeros(len(c))
    leave = np.full(len(c), np.inf)
    with np.errstate(invalid="ignore", divide="ignore"):
        for n, reach in slabs:
            s = (c * n).sum(axis=1) if n.ndim == 2 else c @ n
            d = (w * n).sum(axis=1) if n.ndim == 2 else w @ n
            along = np.abs(d) < _PARALLEL
            t1, t2 = (-reach - s) / d, (reach - s) / d
            first, last = np.minimum(t1, t2), np.maximum(t1, t2)
            outside = np.abs(s) > reach
            first = np.where(along, np.where(outside, np.inf, -np.inf), first)
            last = np.where(along, np.where(outside, -np.inf, np.inf), last)
            enter, leave = np.maximum(enter, first), np.minimum(leave, last)
    return np.where(enter <= leave, enter, np.inf)


def _disc_entry(c: np.ndarray, w: np.ndarray, r: np.ndarray) -> np.ndarray:
    """When the points ``c + w τ`` (τ >= 0) first come within ``r`` of the origin (0 within now, inf never)."""
    a = (w * w).sum(axis=1)
    b = 2 * (c * w).sum(axis=1)
    k = (c * c).sum(axis=1) - r * r
    with np.errstate(invalid="ignore", divide="ignore"):
        root = np.sqrt(b * b - 4 * a * k)
        tau = (-b - root) / (2 * a)
    hits = (a > 0) & (b * b - 4 * a * k >= 0) & (tau >= 0)
    return np.where(k <= 0, 0.0, np.where(hits, tau, np.inf))


def person_collisions(t: np.ndarray, robot_pose: np.ndarray, robot_velocity: np.ndarray, people_xy: np.ndarray,
                      names: Sequence[str], collides: np.ndarray,
                      robot_shape: tuple[float, float] | np.ndarray | None = None, yaw_rate: np.ndarray | None = None,
                      people: np.ndarray | None = None) -> tuple[PersonCollision, ...]:
    """The collisions with people: each run of samples in which ``collides`` (``(T, H)``: the monitor's COLLISION
    with person ``h``) holds, judged at its first sample by the velocity, towards the person, of the robot's
    footprint point nearest to them (``people_xy`` ``(T, H, 2)``, or ``(T, H, 3)`` with their yaws); in time
    order.

    ``robot_pose`` ``(T, 3)`` (or ``(T, 2)``: its origin alone), ``robot_velocity`` ``(T, 2)`` its origin's
    velocity (world frame), ``yaw_rate`` ``(T,)`` its turn rate (rad/s; NaN or None: estimated from the yaws),
    ``robot_shape`` as rei.geometry.footprint_gaps takes it (a box's size, or an outline ``(M, 2)``; None: the
    robot is its origin, as before outlines), ``people`` ``(H, 3)`` each person's ``size_x, size_y, circle``
    (None: circles). A point ``p`` of the outline moves at ``v + w x (p - origin)``: a long robot turning its
    front into a person moves that front at them though its origin may stand or move away (see _contact_point).

    The larger of that component at the first sample and at the sample before it: a contact the simulator reports
    happened at some physics step since the sample before, and by the first sample the impact may already have
    stopped the robot (a robot driving into a standing person at 0.26 m/s is down to 0.03 m/s there)."""
    robot_pose = np.asarray(robot_pose, dtype=float)
    outline = None if robot_shape is None else _outline_of(robot_shape)
    if outline is not None and robot_pose.shape[1] >= 3:
        rate = _yaw_rate(t, robot_pose[:, 2], yaw_rate)
    else:
        outline, rate = None, np.zeros(len(robot_pose))
    before = np.vstack((np.zeros((1, collides.shape[1]), dtype=bool), collides[:-1]))
    found = []
    for k, h in zip(*np.nonzero(collides & ~before), strict=True):
        speeds = []
        for j in (k - 1, k):
            if j < 0:
                continue
            if outline is None:
                speeds.append(_approach(robot_pose[j, :2], robot_velocity[j], people_xy[j, h, :2]))
                continue
            size = (0.0, 0.0, True) if people is None else people[h]
            point, towards = _contact_point(robot_pose[j], outline, people_xy[j, h], size)
            arm = point - robot_pose[j, :2]
            moving = robot_velocity[j] + rate[j] * np.array([-arm[1], arm[0]])  # v + w x r
            speeds.append(float(moving @ towards) if towards is not None else float(np.hypot(*moving)))
        known = [v for v in speeds if not math.isnan(v)]
        found.append(PersonCollision(names[h], float(t[k]), max(known) if known else math.nan))
    return tuple(sorted(found, key=lambda c: (c.t, c.person)))


def _outline_of(robot_shape: tuple[float, float] | np.ndarray) -> np.ndarray:
    """The robot's footprint as a convex polygon ``(M, 2)``, counter-clockwise in its frame: a box's rectangle
    centred on its origin, or the outline itself."""
    if isinstance(robot_shape, np.ndarray) and robot_shape.ndim == 2:
        return np.asarray(robot_shape, dtype=float)
    hx, hy = robot_shape[0] / 2, robot_shape[1] / 2
    return np.array([(-hx, -hy), (hx, -hy), (hx, hy), (-hx, hy)])


def _yaw_rate(t: np.ndarray, yaw: np.ndarray, recorded: np.ndarray | None) -> np.ndarray:
    """The recorded turn rate where it is known, else the unwrapped yaws' finite difference (0 where neither)."""
    out = np.full(len(yaw), np.nan) if recorded is None else np.array(recorded, dtype=float)
    unknown = ~np.isfinite(out)
    if unknown.any() and len(t) >= 2 and np.isfinite(yaw).all():
        with np.errstate(invalid="ignore", divide="ignore"):
            out[unknown] = np.gradient(np.unwrap(yaw), t)[unknown]
    return np.where(np.isfinite(out), out, 0.0)


def _contact_point(pose: np.ndarray, outline: np.ndarray, person: np.ndarray, size: np.ndarray | tuple,
                   ) -> tuple[np.ndarray, np.ndarray | None]:
    """The point of the robot's outline (placed at ``pose``) nearest to the person, and the unit direction from it
    towards the person (None when there is none: the point is the person's centre).

    A round person (``size``: ``size_x, size_y, circle``; a circle of diameter ``size_x``) is nearest where the
    outline is nearest to her centre, and the direction is the contact's normal: towards her centre, or, with her
    centre already inside the outline, the outline's outward one. A rectangle apart from the outline: the nearest
    pair of points of the two shapes (a vertex of one and the other's edge); overlapping it, as a round person at
    its centre."""
    c, s = math.cos(pose[2]), math.sin(pose[2])
    world = pose[:2] + outline @ np.array([[c, s], [-s, c]])  # each vertex rotated by the yaw, then placed
    person = np.asarray(person, dtype=float)
    centre = person[:2]
    if not np.isfinite(world).all() or not np.isfinite(centre).all():
        return pose[:2], None
    if not bool(size[2]):
        yaw = float(person[2]) if len(person) > 2 and math.isfinite(person[2]) else 0.0
        corners = _rectangle(centre, float(size[0]), float(size[1]), yaw)
        if not (_inside(world, corners).any() or _inside(corners, world).any() or _crossing(world, corners)):
            best = None
            for vertex in world:  # the outline's vertices to the rectangle's edges
                q = _nearest_on(corners, vertex)
                if best is None or np.hypot(*(q - vertex)) < best[0]:
                    best = (float(np.hypot(*(q - vertex))), vertex, q)
            for corner in corners:  # the rectangle's corners to the outline's edges
                p = _nearest_on(world, corner)
                if np.hypot(*(corner - p)) < best[0]:
                    best = (float(np.hypot(*(corner - p))), p, corner)
            _, p, q = best
            return p, (q - p) / np.hypot(*(q - p))
    p = _nearest_on(world, centre)
    gap = centre - p
    length = float(np.hypot(*gap))
    if length < 1e-9:
        return p, None
    inside = bool(_inside(world, centre[None, :])[0])
    return p, (-gap if inside else gap) / length


def _rectangle(centre: np.ndarray, size_x: float, size_y: float, yaw: float = 0.0) -> np.ndarray:
    c, s = math.cos(yaw), math.sin(yaw)
    half = np.array([(-size_x, -size_y), (size_x, -size_y), (size_x, size_y), (-size_x, size_y)]) / 2
    return centre + half @ np.array([[c, s], [-s, c]])


def _nearest_on(polygon: np.ndarray, point: np.ndarray) -> np.ndarray:
    """The point of the closed polygon's boundary nearest to ``point``."""
    a, e = polygon, np.roll(polygon, -1, axis=0) - polygon
    u = np.clip(((point - a) * e).sum(axis=1) / (e * e).sum(axis=1), 0.0, 1.0)
    q = a + u[:, None] * e
    return q[int(np.argmin(np.hypot(*(q - point).T)))]


def _inside(polygon: np.ndarray, points: np.ndarray) -> np.ndarray:
    """Which ``points`` lie inside the convex, counter-clockwise ``polygon`` (on its boundary counts)."""
    e = np.roll(polygon, -1, axis=0) - polygon
    side = e[None, :, 0] * (points[:, None, 1] - polygon[None, :, 1]) - e[None, :, 1] * (points[:, None, 0] -
                                                                                           polygon[None, :, 0])
    return (side >= 0).all(axis=1)


def _crossing(a: np.ndarray, b: np.ndarray) -> bool:
    """Whether an edge of polygon ``a`` crosses one of ``b``."""
    for p, p2 in zip(a, np.roll(a, -1, axis=0), strict=True):
        for q, q2 in zip(b, np.roll(b, -1, axis=0), strict=True):
            d1, d2 = _cross(q2 - q, p - q), _cross(q2 - q, p2 - q)
            d3, d4 = _cross(p2 - p, q - p), _cross(p2 - p, q2 - p)
            if d1 * d2 < 0 and d3 * d4 < 0:
                return True
    return False


def _cross(u: np.ndarray, v: np.ndarray) -> float:
    return float(u[0] * v[1] - u[1] * v[0])


def _approach(robot: np.ndarray, velocity: np.ndarray, person: np.ndarray) -> float:
    """The robot's velocity towards the person's centre (m/s); centres that coincide give no direction: then any
    motion of the robot is into the person."""
    towards = person - robot
    distance = math.hypot(*towards)
    return float(velocity @ towards / distance) if distance > 1e-9 else float(np.hypot(*velocity))


def path_irregularity(t: np.ndarray, people_xy: np.ndarray) -> float | None:
    """Mean over the people who walked of their total heading change per metre walked (rad/m; Guzzi et al.
    2013's path irregularity, without subtracting the turning their goals need: REI's people walk a scheduled
    path whose own turns are in it). ``people_xy``: ``(T, H, 2)``, NaN where a person is not published. A step
    (two consecutive published samples) slower than WALKING is standing: it has no heading and is not walked;
    the heading change is taken between consecutive walking steps, so a turn made while standing counts."""
    values = []
    for h in range(people_xy.shape[1]):
        xy = people_xy[:, h]
        both = np.isfinite(xy).all(axis=1)
        pair = both[:-1] & both[1:]
        step = np.diff(xy, axis=0)[pair]
        length = np.hypot(step[:, 0], step[:, 1])
        walking = length >= WALKING * np.diff(t)[pair]
        if not walking.any():
            continue
        heading = np.arctan2(step[walking, 1], step[walking, 0])
        turned = float(np.abs((np.diff(heading) + math.pi) % (2 * math.pi) - math.pi).sum())  # wrap_angle's
        values.append(turned / float(length[walking].sum()))
    return float(np.mean(values)) if values else None
