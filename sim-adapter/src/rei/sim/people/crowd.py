# SPDX-License-Identifier: EPL-2.0
"""The reactive people of a run: the people server's model stepped in lockstep with the physics.

The crowd steps every :data:`DT` seconds of simulated time (JuPedSim's models are made for 10-50 ms). Each step it
tells the model where the robot and the bodies on rails are (their true poses: the people see where the robot
really is, not where the model last let it be) and where each person wants to go (``walkers``). The model computes
the step in its own process while the physics runs the next 50 ms (pipelined: on two cores the people cost little
more than their bodies). The simulation puts each person's body, a fixed solid the robot can touch and the lidar
sees, at the model's place after each step taken (rei.sim.simulation).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

import numpy as np

from rei.artifacts.animation import Behaviour, PersonSpec
from rei.artifacts.world import Shape, WorldSpec
from rei.sim.people.server import INIT_TIMEOUT, PROTOCOL, PeopleServer
from rei.sim.people.walkers import QUEUE_GAP, Follower, Point, Queue, RobotView, Walker

#: Crowd step (s).
DT = 0.05
#: The model's time headway (s) of a group's members: they walk a step apart, where strangers keep about a second
#: (the model's own 1.06 s), which would string a group out over metres at a walk.
GROUP_TIME_GAP = 0.3


@dataclass(frozen=True, slots=True)
class Mover:
    """A body the people see but the crowd does not move: the robot, or a body on rails."""

    x: float
    y: float
    radius: float
    robot: bool


@dataclass(slots=True)
class Walked:
    """What a person did in a run: when it reached each stop, and how far it had walked by then and in all."""

    arrivals: list[float] = field(default_factory=list)
    walked_at: list[float] = field(default_factory=list)
    walked: float = 0.0


def footprint_radius(shape: Shape, size: Sequence[float]) -> float:
    """The radius of the disc the model gives a body: a cylinder's own, a box's circumradius."""
    return size[0] / 2 if shape is Shape.CYLINDER else math.hypot(size[0], size[1]) / 2


class Crowd:
    """The people of ``people`` (their bodies are ``world``'s HUMAN objects of the same names)."""

    def __init__(self, world: WorldSpec, people: Sequence[PersonSpec], movers: Sequence[Mover], *, seed: int,
                 server: PeopleServer | None = None) -> None:
        self._server = server or PeopleServer()
        try:
            self._start(world, people, movers, seed)
        except BaseException:
            self._server.close(kill=True)
            raise

    def _start(self, world: WorldSpec, people: Sequence[PersonSpec], movers: Sequence[Mover], seed: int) -> None:
        self._world, self._people, self._movers, self._seed = world, list(people), list(movers), seed
        bodies = {o.name: o for o in world.objects}
        radii = [footprint_radius(bodies[p.name].shape, bodies[p.name].size) for p in people]
        # a person of a speed range gets its speed from the run's seed, in the order people are listed
        draw = np.random.default_rng(seed)
        speeds = [p.speed if p.speed_to is None else float(draw.uniform(p.speed, p.speed_to)) for p in people]
        # where each body stands in world.json: its first stop, or, for a group's follower, its own place beside it
        start = [(bodies[p.name].pose[0], bodies[p.name].pose[1]) for p in people]
        reply = self._server.request(_init(world, people, start, radii, speeds, movers, seed), timeout=INIT_TIMEOUT)
        self.walkers = _walkers(people, radii, speeds, reply["legs"], self._route, self._heading)
        self._before = start
        self._now = start
        self._headings = [0.0] * len(people)
        self.t = 0.0
        self._steps = 0
        self.robot_lag = 0.0  # the farthest the people's robot was from the true robot at a step (m)
        self._seen_robot: Point | None = None
        self._pending = False  # a step asked for whose reply is not read yet
        self.walked = [Walked() for _ in people]
        self._trails: dict[int, list[tuple[float, Point]]] = {  # a group leader's last places, by distance walked
            i: [] for i, p in enumerate(people) if p.group is not None and _leads(p, people)}
        self._rails: list[list[Point]] = []  # the bodies on rails at each step, for the run without the robot

    def _heading(self, index: int) -> tuple[Point, float, Callable[[float], Point] | None]:
        """A leader's place now, its heading (the way it last moved) and its trail: where it was when it had walked
        ``back`` metres less than now (None before it has walked)."""
        walked = self.walked[index].walked
        if walked <= 0.0:
            return self._now[index], self._headings[index], None
        trail = self._trails[index]  # only a group's leader has followers that ask

        def back(distance: float) -> Point:
            wanted = walked - distance
            for at, place in reversed(trail):
                if at <= wanted:
                    return place
            return trail[0][1] if trail else self._now[index]

        return self._now[index], self._headings[index], back

    def _route(self, a: Point, b: Point) -> list[Point]:
        reply = self._server.request({"op": "route", "from": list(a), "to": list(b)})
        return [(q[0], q[1]) for q in reply["waypoints"]]

    def step(self, robot: RobotView, movers: Sequence[Point]) -> None:
        """One crowd step, at a multiple of DT; ``movers`` in the order given at the start, the robot first.

        Pipelined: the model computes the step asked for now while the physics runs the next DT, and its places are
        taken at the next call: the people's places at that call's time, which the model worked out from the
        robot's true pose at this one."""
        if self._pending:
            self._apply(self._server.receive("step"))
            if self._seen_robot is not None:  # where the people saw the robot, and where it really was then
                self.robot_lag = max(self.robot_lag, math.dist(self._seen_robot, movers[0]))
        self._rails.append([tuple(m) for m in movers[1:]])  # type: ignore[misc]
        self._server.send({"op": "step", "movers": [list(m) for m in movers], "targets": self._targets(robot)})
        self._pending = True

    def _step(self, robot: RobotView, movers: Sequence[Point]) -> dict:
        """One crowd step, waiting for the model (the run without the robot)."""
        reply = self._server.request({"op": "step", "movers": [list(m) for m in movers],
                                      "targets": self._targets(robot)})
        self._apply(reply)
        return reply

    def _targets(self, robot: RobotView) -> list[list]:
        t = self.t  # (a point's tuple goes over the pipe as a list would)
        return [[speed, *points] for speed, points in (walker.target(t, at, robot)
                                                       for walker, at in zip(self.walkers, self._now, strict=True))]

    def _apply(self, reply: dict) -> None:
        self._before = self._now
        self._now = [(q[0], q[1]) for q in reply["positions"]]
        self._seen_robot = (reply["seen"][0][0], reply["seen"][0][1]) if reply["seen"] else None
        self._steps += 1
        self.t = self._steps * DT
        jitter = 0.01 * DT  # standing jitter is not a heading
        for i, (walker, walked, (x0, y0), (x1, y1)) in enumerate(zip(self.walkers, self.walked, self._before, self._now,
                                                                      strict=True)):
            step = math.hypot(x1 - x0, y1 - y0)
            if step > jitter:
                self._headings[i] = math.atan2(y1 - y0, x1 - x0)
            walked.walked += step
            if i in self._trails and step > 0.0:
                self._trails[i].append((walked.walked, (x1, y1)))
                if len(self._trails[i]) > 400:  # 20 s of walk: more than any follower looks back
                    del self._trails[i][:200]
            while len(walked.walked_at) < len(walker.arrivals):
                walked.arrivals.append(walker.arrivals[len(walked.walked_at)])
                walked.walked_at.append(walked.walked)

    def without_robot(self) -> list[Walked]:
        """The same people, seed and bodies on rails for as long as this crowd has run, without the robot: the model
        alone, no physics (docs/people.md, what the robot cost the people)."""
        rails = [m for m in self._movers if not m.robot]
        alone = Crowd(self._world, [_seeing(p) for p in self._people], rails, seed=self._seed)
        try:
            nowhere = RobotView(math.inf, math.inf, 0.0, 0.0, 0.0, 0.0, 0.0)
            for movers in self._rails[:self._steps]:  # the steps this crowd took (the last asked may be pending)
                alone._step(nowhere, movers)
            return alone.walked
        finally:
            alone.close()

    def position(self, index: int) -> Point:
        """Person ``index``'s place in the model after the latest step taken."""
        return self._now[index]

    @property
    def positions(self) -> Sequence[Point]:
        """Every person's place in the model after the latest step taken (not to be changed)."""
        return self._now

    def velocity(self, index: int) -> Point:
        """Person ``index``'s velocity in the model over the latest step taken (m/s)."""
        (x0, y0), (x1, y1) = self._before[index], self._now[index]
        return ((x1 - x0) / DT, (y1 - y0) / DT)

    def close(self) -> None:
        if self._pending:
            self._pending = False
            self._server.discard("step")
        self._server.close()


def _seeing(person: PersonSpec) -> PersonSpec:
    """``person`` as one who, there being no robot, reacts to nothing but the other people. One who ignores the
    robot keeps doing so: the model then walks the people in the same two simulations as the run with the robot
    (the others as puppets, a step behind), so a robot that is in nobody's way costs nobody anything; in one
    simulation people met a step sooner, a few tenths of a second and centimetres off for a robot 8 m away."""
    behaviour = Behaviour.IGNORES if person.behaviour is Behaviour.IGNORES else Behaviour.AVOIDS
    return PersonSpec(person.name, behaviour, person.speed, person.start, person.loop, person.route,
                      person.speed_to, person.group)


def _init(world: WorldSpec, people: Sequence[PersonSpec], places: Sequence[Point], radii: Sequence[float],
          speeds: Sequence[float], movers: Sequence[Mover], seed: int) -> dict:
    floors = [[f.center[0] - world.floor_size / 2, f.center[1] - world.floor_size / 2,
               f.center[0] + world.floor_size / 2, f.center[1] + world.floor_size / 2] for f in world.floors]
    # furniture on a polygon brings its outline: people walk into a corner desk's open corner, not round its box
    obstacles = [[o.pose[0], o.pose[1], o.pose[3], o.size[0], o.size[1], o.shape is Shape.CYLINDER,
                  *([[list(v) for v in o.outline]] if o.outline else [])]
                 for o in world.objects if o.category.value in ("WALL", "STATIC")]
    return {"op": "init", "protocol": PROTOCOL, "dt": DT, "seed": seed, "floors": floors, "obstacles": obstacles,
            "movers": [[m.x, m.y, m.radius, m.robot] for m in movers],
            "people": [{"name": p.name, "x": x, "y": y, "radius": r, "speed": v,
                        "sees_robot": p.behaviour is not Behaviour.IGNORES,
                        # a follower walks no route of its own: it keeps its place by its leader
                        "stops": [[s.x, s.y] for s in p.route] if _leads(p, people) else [[x, y]],
                        "loop": p.loop, **({"time_gap": GROUP_TIME_GAP} if p.group is not None else {})}
                       for p, r, v, (x, y) in zip(people, radii, speeds, places, strict=True)]}


def _leads(person: PersonSpec, people: Sequence[PersonSpec]) -> bool:
    """Walks its own route: not in a group, or its group's first listed member."""
    return person.group is None or next(p for p in people if p.group == person.group) is person


def _walkers(people: Sequence[PersonSpec], radii: Sequence[float], speeds: Sequence[float],
             legs: Sequence[Sequence[Sequence[Sequence[float]]]], route, heading) -> list[Walker]:
    walkers: list[Walker] = []
    leaders: dict[str, tuple[int, Walker]] = {}
    members: dict[str, int] = {}
    queues: dict[tuple[float, float, float], Queue] = {}  # one line per place and pace: a crowd's people share it
    for i, (p, r, v, person_legs) in enumerate(zip(people, radii, speeds, legs, strict=True)):
        if p.group is not None and p.group in leaders:
            index, leader = leaders[p.group]
            members[p.group] += 1
            walkers.append(Follower(p, r, members[p.group], leader, lambda index=index: heading(index), v))
            continue
        mine = {k: queues.setdefault((stop.x, stop.y, stop.queue), Queue((stop.x, stop.y), stop.queue,
                                                                          2 * r + QUEUE_GAP))
                for k, stop in enumerate(p.route) if stop.queue is not None}
        walker = Walker(p, r, [[(q[0], q[1]) for q in leg] for leg in person_legs], route, v, mine)
        if p.group is not None:
            leaders[p.group] = (i, walker)
            members[p.group] = 0
        walkers.append(walker)
    return walkers
