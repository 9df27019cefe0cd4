# SPDX-License-Identifier: EPL-2.0 OR GPL-2.0-or-later
#
# This Source Code may also be made available under the following Secondary Licenses when the conditions for such
# availability set forth in the Eclipse Public License, v. 2.0 are satisfied: GNU General Public License, version 2
# or (at your option) any later version. (This one file imports JuPedSim, whose wheel links GPL-3.0-or-later parts
# of CGAL; the secondary licence lets the two be combined. REI's own package never imports it: docs/people.md.)
"""The people server: JuPedSim moves REI's reactive people, one step at a time, for the simulation that starts it.

REI's simulation (``rei.sim.people``) starts this program with the Python of ``.venv-people`` and talks to it
over stdin/stdout: each message is a 4-byte big-endian length and a msgpack map; every request gets one reply,
``{"error": TEXT}`` when it could not be served. REI decides where each person wants to go (routes, waits,
behaviours towards the robot); JuPedSim decides how they get there: the operational model keeps them apart from
each other, the walls, the furniture and, for those who see it, the robot, and its routing engine finds the way
between the stops of a route.

Requests:
``init``  ``dt``, ``seed``, ``floors`` ``[[x0, y0, x1, y1], ...]``, ``obstacles`` ``[[x, y, yaw, sx, sy, circle,
          outline?], ...]`` (``outline``: furniture on a polygon, its vertices in the world; the rectangle is then
          its bounding box), ``movers`` ``[[x, y, radius, robot], ...]`` (the robot and the bodies on rails: seen, not moved),
          ``people`` ``[{name, x, y, radius, speed, sees_robot, stops: [[x, y], ...], loop, time_gap?}, ...]``
          (``time_gap``: the model's time headway to the person ahead, for a group that walks closer than
          strangers; the model's own 1.06 s otherwise).
          Reply: ``legs``, per person the waypoints of each leg of its route (stop i to stop i + 1, and the last
          back to the first for a loop).
``step``  ``movers`` ``[[x, y], ...]`` where they are now; ``targets`` ``[[speed, [x, y], ...], ...]`` per person:
          its desired speed and where it would go, in order of preference: the first point where the person fits
          (its radius from every wall and piece of furniture) is taken, else the first; a point ``[x, y, speed]``
          brings its own desired speed.
          Reply: ``positions`` ``[[x, y], ...]`` per person after one step of ``dt``, and ``seen`` ``[[x, y], ...]``
          where the people who see them had each mover (it may lag behind a mover that pushes into a crowd).
``route`` ``from``, ``to``: reply ``waypoints``, the way the routing engine finds between them (for a person back
          on its route after a detour).
``close`` Reply ``{}``; the server exits.

Two JuPedSim simulations run side by side when some people ignore the robot: one that has the robot, whose
people see it, and one without, whose people do not. Each person is a walking agent in its own simulation and a
*puppet* in the other (steered each step to where the walking agent is), so everyone sees everyone else.
"""

from __future__ import annotations

import itertools
import math
import struct
import sys
import traceback
from typing import Any, BinaryIO

import jupedsim as jps
import msgpack
import numpy as np
import shapely
from shapely.geometry import Point, Polygon, box
from shapely.ops import nearest_points

PROTOCOL = 2
#: A puppet is steered to where its original is; it may not go faster than this (m/s) to catch up.
PUPPET_SPEED = 5.0
#: How far inside the walkable area a target outside it is put (m).
INSIDE = 0.05


def walkable_area(floors: list[list[float]], obstacles: list[list[Any]]) -> Any:
    """The floors less every obstacle's footprint (rectangles turned by their yaw, discs, or polygons)."""
    area = shapely.union_all([box(*f) for f in floors])
    blocked = [_footprint(*o) for o in obstacles]
    if blocked:
        area = area.difference(shapely.union_all(blocked))
    return shapely.set_precision(area, 1e-6)


def _footprint(x: float, y: float, yaw: float, sx: float, sy: float, circle: bool,
               outline: list[list[float]] | None = None) -> Any:
    if outline:
        return Polygon(outline)
    if circle:
        return Point(x, y).buffer(sx / 2, quad_segs=8)
    c, s = math.cos(yaw), math.sin(yaw)
    corners = [(dx, dy) for dx, dy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    return Polygon([(x + c * dx * sx / 2 - s * dy * sy / 2, y + s * dx * sx / 2 + c * dy * sy / 2)
                    for dx, dy in corners])


class _Side:
    """One JuPedSim simulation: its walking agents and its puppets, each on a direct-steering journey."""

    def __init__(self, area: Any, dt: float, seed: int) -> None:
        self.sim = jps.Simulation(model=jps.AnticipationVelocityModel(rng_seed=seed), geometry=area, dt=dt)
        self.stage = self.sim.add_direct_steering_stage()
        self.journey = self.sim.add_journey(jps.JourneyDescription([self.stage]))
        self._steered: dict[int, tuple[float, float, float]] = {}
        self.positions: dict[int, tuple[float, float]] = {}

    def add(self, x: float, y: float, radius: float, speed: float, time_gap: float | None = None) -> int:
        parameters = jps.AnticipationVelocityModelAgentParameters(
            journey_id=self.journey, stage_id=self.stage, position=(x, y), radius=radius, desired_speed=speed)
        if time_gap is not None:
            parameters.time_gap = time_gap
        agent = self.sim.add_agent(parameters)
        self.positions[agent] = (x, y)
        return agent

    def steer(self, agent: int, target: tuple[float, float], speed: float) -> None:
        """Set an agent's target and desired speed, only what changed (JuPedSim's agent access costs)."""
        last = self._steered.get(agent)
        if last is not None and last[:2] == target and last[2] == speed:
            return
        a = self.sim.agent(agent)
        if last is None or last[:2] != target:
            a.target = target
        if last is None or last[2] != speed:
            a.model.desired_speed = speed
        self._steered[agent] = (target[0], target[1], speed)

    def iterate(self) -> None:
        self.sim.iterate()
        self.positions = {a.id: tuple(a.position) for a in self.sim.agents()}  # type: ignore[misc]

    def position(self, agent: int) -> tuple[float, float]:
        return self.positions[agent]


class Server:
    def __init__(self, request: dict[str, Any]) -> None:
        self.dt = float(request["dt"])
        self.area = walkable_area(request["floors"], request["obstacles"])
        if self.area.is_empty:
            raise ValueError("the room has no walkable area: every floor is covered by walls or furniture")
        self._inside = self.area.buffer(-INSIDE)
        shapely.prepare(self._inside)
        people = request["people"]
        movers = request["movers"]
        self.radii = [float(p["radius"]) for p in people]
        self._fits: dict[float, Any] = {}
        self.people = people
        self.sees = [bool(p["sees_robot"]) for p in people]
        seed = int(request["seed"])
        # the model looks at every wall segment near a person at every step: it is given the area without the
        # vertices the union of the floors leaves along straight walls (the same area, 157 corners -> 5 in a 20 x 20
        # m grid room: this server's step among 100 people 1.6 -> 0.7 ms). A wall in pieces was not quite one wall
        # to the model: people beside one step a little differently (0.25 mm in the first step in Nav2's depot)
        stepped = shapely.set_precision(shapely.simplify(self.area, 0.0), 1e-6)
        self.seeing = _Side(stepped, self.dt, seed)
        self.blind = _Side(stepped, self.dt, seed + 1) if not all(self.sees) else None
        # per person: (side that walks it, its agent there), and its puppet's (side, agent) if there is a second side
        self.walkers: list[tuple[_Side, int]] = []
        self.puppets: list[tuple[_Side, int] | None] = []
        self.mover_agents: list[list[tuple[_Side, int]]] = []
        for p in people:
            self._check_inside(p["name"], "stands", (p["x"], p["y"]))
        for p, sees in zip(people, self.sees, strict=True):
            own, other = (self.seeing, self.blind) if sees else (self.blind, self.seeing)
            assert own is not None
            self.walkers.append((own, self._add(own, p["name"], p["x"], p["y"], p["radius"], p["speed"],
                                                p.get("time_gap"))))
            self.puppets.append(None if other is None else
                                (other, self._add(other, p["name"], p["x"], p["y"], p["radius"], p["speed"])))
        for x, y, radius, robot in movers:
            sides = [self.seeing] if robot or self.blind is None else [self.seeing, self.blind]
            self.mover_agents.append([(side, self._add(side, "the robot" if robot else "a body on rails",
                                                       x, y, radius, 0.0)) for side in sides])
        # the ways are found where the widest person fits: the area opened by its radius has no gap narrower than a
        # body (a way through one would stop a person in front of it for good); the area as it is where that fails
        widest = max(self.radii, default=0.0) * 0.95
        opened = shapely.set_precision(self.area.buffer(-widest).buffer(widest).intersection(self.area), 1e-6)
        self.routing = jps.RoutingEngine(opened if not opened.is_empty else self.area)
        self._opened = opened
        self._full_routing: Any = None
        self.legs = [self._legs(p) for p in people]

    def _add(self, side: _Side, name: str, x: float, y: float, radius: float, speed: float,
             time_gap: float | None = None) -> int:
        try:
            return side.add(x, y, radius, speed, time_gap)
        except RuntimeError as error:
            raise ValueError(f"{name} cannot stand at ({x:.2f}, {y:.2f}): {error}") from None

    def _check_inside(self, name: str, what: str, point: tuple[float, float]) -> None:
        if not self.area.contains(Point(point)):
            raise ValueError(f"{name} {what} at ({point[0]:.2f}, {point[1]:.2f}), outside the walkable area "
                             "(the floors less walls and furniture)")

    def _legs(self, person: dict[str, Any]) -> list[list[list[float]]]:
        stops = [tuple(s) for s in person["stops"]]
        for i, stop in enumerate(stops):
            self._check_inside(person["name"], f"has stop {i + 1}", stop)
        pairs = list(itertools.pairwise(stops))
        if person["loop"] and len(stops) > 1:
            pairs.append((stops[-1], stops[0]))
        legs = []
        for a, b in pairs:
            try:
                points = self._way(a, b)
            except RuntimeError as error:
                raise ValueError(f"{person['name']} cannot walk from ({a[0]:.2f}, {a[1]:.2f}) to "
                                 f"({b[0]:.2f}, {b[1]:.2f}): {error}") from None
            kept: list[list[float]] = []
            for q in points:
                if not kept or math.dist(kept[-1], q) > 1e-9:
                    kept.append([float(q[0]), float(q[1])])
            legs.append(kept)
        return legs

    def _way(self, a: tuple[float, float], b: tuple[float, float]) -> list[tuple[float, float]]:
        """The waypoints from ``a`` to ``b`` where the widest person fits, else on the area as it is."""
        if self.routing.is_routable(a) and self.routing.is_routable(b):
            try:
                return list(self.routing.compute_waypoints(a, b))
            except RuntimeError:
                pass  # a and b in parts of the opened area that only a gap joins
        if self._full_routing is None:
            self._full_routing = jps.RoutingEngine(self.area)
        if not (self._full_routing.is_routable(a) and self._full_routing.is_routable(b)):
            raise RuntimeError("a stop is off the walkable area")
        return list(self._full_routing.compute_waypoints(a, b))

    def route(self, start: list[float], end: list[float]) -> list[list[float]]:
        a, b = self._inside_target(*start), self._inside_target(*end)
        try:
            return [[float(q[0]), float(q[1])] for q in self._way(a, b)]
        except RuntimeError:
            return [list(a), list(b)]

    def _first_fitting(self, points: list[list[float]], radius: float) -> list[float]:
        if len(points) > 1:
            room = self._fits.get(radius)
            if room is None:
                room = self._fits[radius] = self.area.buffer(-radius)
                shapely.prepare(room)
            for point in points:
                if shapely.contains_xy(room, point[0], point[1]):
                    return point
        return points[0]

    def _inside_targets(self, points: list[list[float]]) -> list[tuple[float, float]]:
        """:meth:`_inside_target` of every point, tested at once (a point at a time costs more than the model)."""
        if not points:
            return []
        xy = np.asarray([q[:2] for q in points], dtype=float)
        inside = shapely.contains_xy(self._inside, xy[:, 0], xy[:, 1])
        return [(float(x), float(y)) if ok else self._inside_target(x, y)
                for (x, y), ok in zip(xy.tolist(), inside.tolist(), strict=True)]

    def _inside_target(self, x: float, y: float) -> tuple[float, float]:
        if shapely.contains_xy(self._inside, x, y):
            return (x, y)
        near = nearest_points(self._inside, Point(x, y))[0]
        return (near.x, near.y)

    def step(self, request: dict[str, Any]) -> dict[str, Any]:
        for agents, (x, y) in zip(self.mover_agents, request["movers"], strict=True):
            for side, agent in agents:
                self._follow(side, agent, (x, y))
        targets = request["targets"]
        # (a person's lone target needs no fitting: most of them, and this runs for everyone at every step)
        chosen = [target[1] if len(target) == 2 else self._first_fitting(target[1:], radius)
                  for radius, target in zip(self.radii, targets, strict=True)]
        for (side, agent), target, point, wanted in zip(self.walkers, self._inside_targets(chosen), chosen, targets,
                                                        strict=True):
            side.steer(agent, target, point[2] if len(point) > 2 else wanted[0])
        if self.blind is not None:
            for puppet, (side, agent) in zip(self.puppets, self.walkers, strict=True):
                if puppet is not None:
                    self._follow(*puppet, side.position(agent))
        self.seeing.iterate()
        if self.blind is not None:
            self.blind.iterate()
        return {"positions": [side.positions[agent] for side, agent in self.walkers],
                "seen": [agents[0][0].positions[agents[0][1]] for agents in self.mover_agents]}

    def _follow(self, side: _Side, agent: int, where: tuple[float, float]) -> None:
        """Steer a puppet to ``where`` at the speed that gets it there in one step."""
        x, y = side.position(agent)
        target = self._inside_target(*where)
        side.steer(agent, target, min(math.dist((x, y), target) / self.dt, PUPPET_SPEED))


def _read(stream: BinaryIO) -> dict[str, Any] | None:
    head = stream.read(4)
    if len(head) < 4:
        return None
    (size,) = struct.unpack(">I", head)
    return msgpack.unpackb(stream.read(size), raw=False)


def _write(stream: BinaryIO, message: dict[str, Any]) -> None:
    data = msgpack.packb(message, use_bin_type=True)
    stream.write(struct.pack(">I", len(data)) + data)
    stream.flush()


def main() -> int:
    requests, replies = sys.stdin.buffer, sys.stdout.buffer
    server: Server | None = None
    while (request := _read(requests)) is not None:
        op = request.get("op")
        try:
            if op == "init":
                if request.get("protocol") != PROTOCOL:
                    raise ValueError(f"protocol {request.get('protocol')!r}, this server speaks {PROTOCOL}")
                server = Server(request)
                _write(replies, {"legs": server.legs})
            elif op == "step" and server is not None:
                _write(replies, server.step(request))
            elif op == "route" and server is not None:
                _write(replies, {"waypoints": server.route(request["from"], request["to"])})
            elif op == "close":
                _write(replies, {})
                return 0
            else:
                raise ValueError(f"unexpected request {op!r}" + ("" if server else " before init"))
        except (ValueError, RuntimeError, KeyError, TypeError) as error:
            detail = str(error) if isinstance(error, ValueError) else traceback.format_exc(limit=3)
            _write(replies, {"error": detail})
    return 0


if __name__ == "__main__":
    sys.exit(main())
