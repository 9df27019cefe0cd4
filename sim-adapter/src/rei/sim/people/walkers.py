# SPDX-License-Identifier: EPL-2.0
"""Where each reactive person wants to go next: its route, its waits, and its behaviour towards the robot.

A walker decides a *target* and a desired speed every crowd step; the pedestrian-dynamics model (the people
server) decides how the person moves towards it without touching anyone. The route's legs come from the model's
routing engine, so a walker only ever heads for the next waypoint of a way that is known to be walkable; after a
detour (a curious look, a scared retreat, a stand in the robot's way) it asks for a new way to its next stop.

A person who sees the robot plans around it as around any obstacle on its way: when the straight line to its next
target passes the robot closer than :data:`CLEARANCE` (both footprints' radii apart), it heads first for a point
beside the robot, on the side it is already on (the right when straight ahead), or on the other side where it
does not fit between the robot and a wall or a piece of furniture, then on. The model alone would not
do it: a collision-free speed model stops a person in front of a standing obstacle, it does not walk around it.

The behaviours (docs/people.md), each reacting to a robot whose centre comes within :data:`NOTICE`:
``avoids`` walks its route around the robot; ``ignores`` does not see the robot at all (the model lets it walk
into it); ``curious`` walks to a spot just in front of the robot and stands there for :data:`LINGER` seconds,
once; ``scared`` passes the robot :data:`SCARED_CLEARANCE` wide and backs away from a robot nearer than
:data:`SCARED_DISTANCE`; ``blocks`` keeps stepping into
the robot's way for :data:`BLOCK_TIME` seconds, once.

A crowd's queue (a :class:`Queue`) is a stop its people pass one at a time: each joins the line as it comes near
its end and moves up as the line does; the first stands on the stop and walks on when its turn comes.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from rei.artifacts.animation import Behaviour, PersonSpec

Point = tuple[float, float]

#: A robot whose centre is this close (m) catches the eye of a curious, scared or blocking person.
NOTICE = 4.0
#: A waypoint on the way is passed within this distance (m) of the person's centre...
ARRIVE = 0.3
#: ...and a stop reached within this one.
ARRIVE_STOP = 0.15
#: Gap (m) a curious person leaves between the robot's front and itself.
CURIOUS_GAP = 0.3
#: How long (s) a curious person stands in front of the robot once there.
LINGER = 8.0
#: Room (m) a person leaves between its footprint and the robot's when it walks around it...
CLEARANCE = 0.3
#: ...and a scared person.
SCARED_CLEARANCE = 1.2
#: A scared person backs away while the robot's centre is nearer than this (m)...
SCARED_DISTANCE = 1.5
#: ...heading for a point this far (m) further from the robot, a fifth faster than it walks.
SCARED_STEP = 1.5
#: A blocking person heads for a point this far (m) in front of the robot's front...
BLOCK_AHEAD = 0.6
#: ...for this long (s), once.
BLOCK_TIME = 10.0
#: Room (m) between two people in a queue, beyond their bodies.
QUEUE_GAP = 0.25
#: A person on its way to a queue joins the line within this distance (m) of the place at its end.
QUEUE_JOIN = 1.0


@dataclass(frozen=True, slots=True)
class RobotView:
    """What a person sees of the robot: its centre, heading and velocity, how far its front is from its centre
    (half its length) and the radius of the disc around its footprint."""

    x: float
    y: float
    yaw: float
    vx: float
    vy: float
    front: float
    radius: float

    def ahead(self, distance: float) -> Point:
        """The point ``distance`` in front of the robot's centre along its heading."""
        return (self.x + distance * math.cos(self.yaw), self.y + distance * math.sin(self.yaw))


Router = Callable[[Point, Point], list[Point]]


class Queue:
    """A floor that people pass one at a time, at most one every ``every`` seconds (a crowd's ``queue F every D``).

    The first in line stands on it and passes when its turn comes; the others stand ``spacing`` apart behind it
    along the way the first of them came by (a corridor's bend is followed), in the order they joined. A person
    joins when it comes within :data:`QUEUE_JOIN` of the place at the line's end, or nearer the floor than that
    place. ``passed``: who passed when."""

    def __init__(self, at: Point, every: float, spacing: float) -> None:
        self.at = at
        self.every = every
        self.spacing = spacing
        self.passed: list[tuple[float, str]] = []
        self._line: list[Walker] = []
        self._back: list[Point] = []  # the way back from the floor along which the line stands
        self._last = -math.inf

    def joins(self, walker: Walker, at: Point, way: Sequence[Point]) -> bool:
        """Whether ``walker``, at ``at`` on ``way`` (its way on to the floor), is in line: it may join now."""
        if walker in self._line:
            return True
        if self._line:
            end = self.spot(len(self._line))
            if math.dist(at, end) > QUEUE_JOIN and math.dist(at, self.at) > math.dist(end, self.at):
                return False
        elif math.dist(at, self.at) > QUEUE_JOIN:
            return False
        else:  # the first in line: the line forms back along the way it came
            self._back = [self.at, *reversed([at, *way][:-1])]
        self._line.append(walker)
        return True

    def passes(self, walker: Walker, t: float, at: Point) -> bool:
        """Whether ``walker`` passes now: first in line, on the floor, and ``every`` seconds after the last."""
        if not (self._line and self._line[0] is walker and math.dist(at, self.at) < ARRIVE
                and t - self._last >= self.every):
            return False
        self._line.pop(0)
        self._last = t
        self.passed.append((t, walker.spec.name))
        return True

    def spot(self, place: int) -> Point:
        """Where the ``place``-th in line stands (0: on the floor): that far back along the line's way, and on
        in its last direction past its end."""
        left = place * self.spacing
        segments = [(a, b, math.dist(a, b)) for a, b in zip(self._back, self._back[1:])]
        segments = [segment for segment in segments if segment[2] > 1e-9]
        for i, (a, b, length) in enumerate(segments):
            if left <= length or i == len(segments) - 1:
                f = left / length
                return (a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]))
            left -= length
        return self.at  # the first joined standing on the floor: no way back to line up along

    def place_of(self, walker: Walker) -> int:
        return self._line.index(walker)


class Walker:
    """One person's intentions; :meth:`target` is asked once per crowd step. ``speed``: its desired speed (the
    spec's, or drawn from its range); ``arrivals`` the times it reached a stop."""

    def __init__(self, spec: PersonSpec, radius: float, legs: Sequence[Sequence[Point]], route: Router,
                 speed: float | None = None, queues: dict[int, Queue] | None = None) -> None:
        self.spec = spec
        self._queues = queues or {}  # by the index of the route's stop that is a queue
        self.radius = radius
        self.speed = spec.speed if speed is None else speed
        self.arrivals: list[float] = []
        self._legs = [list(leg) for leg in legs]
        self._route = route
        self._leg = 0
        self._waypoint = 1  # legs start at their stop: the first point to walk to is the next
        self._wait_until: float | None = None
        self._started = False
        self._done = not self._legs
        if spec.loop and not any(stop.wait > 0 for stop in spec.route) and all(
                math.dist(point, self._legs[0][0]) < ARRIVE_STOP for leg in self._legs for point in leg):
            self._done = True  # a loop round one place without a wait would arrive at every step: it stands there
        self._engaged: float | None = None  # when a curious or blocking person turned to the robot
        self._linger_until: float | None = None
        self._spent = False  # curious and blocking people react once
        self._rejoin = False  # back from a detour: ask for a new way to the next stop
        self._home: list[Point] | None = None  # a standing person's way back to its place after a look

    @property
    def engaged(self) -> bool:
        return self._engaged is not None

    def target(self, t: float, at: Point, robot: RobotView) -> tuple[float, list[tuple[float, ...]]]:
        """``(speed, points)``: how fast the person at ``at`` would like to walk at time ``t``, and where: the first
        of ``points`` where it fits (a way round the robot has two sides); a point ``(x, y, speed)`` brings its
        own speed."""
        speed = self.speed
        if t < self.spec.start:
            return (0.0, [at])
        if not self._started:
            self._started = True
            self._wait_until = t + self.spec.route[0].wait
        reaction = self._react(t, at, robot)
        if reaction is not None:
            self._rejoin = True
            return (reaction[2], self._around(at, reaction[:2], robot))
        if self._wait_until is not None and t < self._wait_until:
            return (0.0, [at])  # a model's walker keeps its heading at its target: standing is a speed of 0
        if self._done:
            return self._go_home(at, robot)
        in_line = self._in_line(t, at)
        if in_line is not None:
            return (0.0 if math.dist(at, in_line) < ARRIVE_STOP else speed, self._around(at, in_line, robot))
        if self._rejoin:
            self._rejoin = False
            leg = self._legs[self._leg]
            stop = leg[-1]
            self._legs[self._leg] = [at, *self._route(at, stop)[1:]] if math.dist(at, stop) > ARRIVE else [at, stop]
            self._waypoint = 1
        point = self._next(t, at)
        standing = self._done or (self._wait_until is not None and t < self._wait_until)
        return (0.0 if standing else speed, self._around(at, point, robot))

    def _go_home(self, at: Point, robot: RobotView) -> tuple[float, list[tuple[float, ...]]]:
        """A person done with its route stands; one who left its place to look at the robot or to stand in its
        way walks back to it (a scared one stays away: back at its place it would be near the robot again)."""
        if self._rejoin and self._spent:
            self._rejoin = False
            place = self._legs[self._leg][-1] if self._legs else (self.spec.route[-1].x, self.spec.route[-1].y)
            self._home = self._route(at, place)[1:] if math.dist(at, place) > ARRIVE_STOP else None
        while self._home and math.dist(at, self._home[0]) < (ARRIVE if len(self._home) > 1 else ARRIVE_STOP):
            self._home.pop(0)
        if not self._home:
            self._home = None
            return (0.0, [at])
        return (self.speed, self._around(at, self._home[0], robot))

    def _in_line(self, t: float, at: Point) -> Point | None:
        """The place in line of a person on its way to a queue who has joined it, None when it walks on (not there
        yet, or its turn has come: then it has arrived at the queue's stop)."""
        stop = (self._leg + 1) % len(self.spec.route)
        queue = self._queues.get(stop)
        if queue is None or not queue.joins(self, at, self._legs[self._leg][self._waypoint:]):
            return None
        if not queue.passes(self, t, at):
            return queue.spot(queue.place_of(self))
        self.arrivals.append(t)
        self._wait_until = t + self.spec.route[stop].wait
        self._leg, self._waypoint = stop if stop else len(self._legs), 1
        if self._leg == len(self._legs):  # a queue at a route's first stop, passed at the end of a round
            if not self.spec.loop:
                self._done, self._leg = True, self._leg - 1
                return None
            self._leg = 0
        self._rejoin = True  # on from where it stood, a little off the stop maybe
        return None

    def _around(self, at: Point, target: Point, robot: RobotView) -> list[Point]:
        """``[target]``, or the points beside the robot, the preferred side first, when the way there passes it too
        close (module docstring)."""
        behaviour = self.spec.behaviour
        if behaviour is Behaviour.IGNORES or math.dist(at, (robot.x, robot.y)) >= NOTICE:
            return [target]
        wide = SCARED_CLEARANCE if behaviour is Behaviour.SCARED else CLEARANCE
        dx, dy = target[0] - at[0], target[1] - at[1]
        length = math.hypot(dx, dy)
        if length < 1e-9:
            return [target]
        ux, uy = dx / length, dy / length
        rx, ry = robot.x - at[0], robot.y - at[1]
        along = rx * ux + ry * uy
        across = rx * uy - ry * ux  # > 0: the robot is right of the way
        # a target beside the robot (a curious look) must stay reachable: the disc to pass ends short of it
        clear = min(robot.radius + self.radius + wide, math.dist(target, (robot.x, robot.y)) - 0.05)
        if along <= 0 or along >= length or abs(across) >= clear:
            return [target]
        # pass on the side of the way the robot is not on; straight ahead, keep right
        side = 1.0 if across > 1e-6 else -1.0
        return [(robot.x - uy * s * (clear + 0.1), robot.y + ux * s * (clear + 0.1)) for s in (side, -side)]

    def _next(self, t: float, at: Point) -> Point:
        """The waypoint to head for, moving on past those reached."""
        leg = self._legs[self._leg]
        last = len(leg) - 1
        point = leg[min(self._waypoint, last)]
        if math.dist(at, point) >= (ARRIVE if self._waypoint < last else ARRIVE_STOP):
            return point  # most steps: the same waypoint, not reached yet
        for _ in range(sum(len(leg) for leg in self._legs) + 1):  # a loop of stops all within ARRIVE ends here
            leg = self._legs[self._leg]
            point = leg[min(self._waypoint, len(leg) - 1)]
            if math.dist(at, point) >= (ARRIVE if self._waypoint < len(leg) - 1 else ARRIVE_STOP):
                return point
            if self._waypoint < len(leg) - 1:
                self._waypoint += 1
                continue
            # the leg's last point is its stop: wait there, then take the next leg
            self.arrivals.append(t)
            stops = self.spec.route
            arrived = (self._leg + 1) % len(stops)
            self._wait_until = t + stops[arrived].wait
            self._leg += 1
            self._waypoint = 1
            if self._leg == len(self._legs):
                if not self.spec.loop:
                    self._done = True
                    self._leg -= 1
                    return point
                self._leg = 0
            if t < self._wait_until:
                return point
        return point

    def _react(self, t: float, at: Point, robot: RobotView) -> tuple[float, float, float] | None:
        behaviour = self.spec.behaviour
        if behaviour is Behaviour.AVOIDS or behaviour is Behaviour.IGNORES:
            return None
        near = math.dist(at, (robot.x, robot.y))
        if behaviour is Behaviour.SCARED:
            if near >= SCARED_DISTANCE:
                return None
            away = (at[0] - robot.x, at[1] - robot.y)
            norm = math.hypot(*away) or 1.0
            return (at[0] + SCARED_STEP * away[0] / norm, at[1] + SCARED_STEP * away[1] / norm,
                    min(self.speed * 1.2, 3.0))
        if behaviour not in (Behaviour.CURIOUS, Behaviour.BLOCKS) or self._spent:
            return None
        if self._engaged is None:
            if near >= NOTICE:
                return None
            self._engaged = t
        elif near >= 2 * NOTICE:  # the robot drove off: give up
            return self._release()
        if behaviour is Behaviour.CURIOUS:
            spot = robot.ahead(robot.front + CURIOUS_GAP + self.radius)
            if self._linger_until is None and math.dist(at, spot) < ARRIVE + 0.2:
                self._linger_until = t + LINGER
            if self._linger_until is not None and t >= self._linger_until:
                return self._release()
            return (*spot, self.speed)
        if t - self._engaged >= BLOCK_TIME:
            return self._release()
        return (*robot.ahead(robot.front + BLOCK_AHEAD + self.radius), self.speed)

    def _release(self) -> None:
        """The curious look or the stand in the way is over, for good."""
        self._spent = True
        self._engaged = None


class Follower(Walker):
    """A member of a group who is not its leader: it keeps its place beside or behind the leader, or, where that
    place is a wall or furniture (a group along a wall, through a door), walks in file on the leader's trail; it
    goes round the robot as the leader does, and reaches the leader's stops when the leader does. ``place``: the
    leader's place now, its heading and its trail (rei.sim.people.crowd)."""

    def __init__(self, spec: PersonSpec, radius: float, slot: int, leader: Walker,
                 place: Callable[[], tuple[Point, float, Callable[[float], Point] | None]],
                 speed: float | None = None) -> None:
        super().__init__(spec, radius, [], lambda a, b: [a, b], speed)
        self._leader = leader
        self._place = place
        self.arrivals = leader.arrivals  # the group arrives together
        spacing = self._spacing = 2 * radius + 0.1
        self._slot = slot
        row, side = (slot - 1) // 2, 1.0 if slot % 2 else -1.0
        # the first two abreast of the leader, the others in pairs behind
        self._offset = (0.0, side * spacing) if row == 0 else (-spacing * row, side * spacing / 2)

    def target(self, t: float, at: Point, robot: RobotView) -> tuple[float, list[tuple[float, ...]]]:
        (lx, ly), heading, trail = self._place()
        if t < self.spec.start or trail is None:  # the leader has not set off: it has no heading yet
            return (0.0, [at])
        c, s = math.cos(heading), math.sin(heading)
        lon, lat = self._offset
        slot = (lx + c * lon - s * lat, ly + s * lon + c * lat)
        in_file = trail(self._spacing * self._slot)
        ways = self._around(at, slot, robot)
        if ways != [slot]:  # going round the robot
            return (self._pace(math.dist(at, slot)), ways)
        # each place with the pace that gets there: the model takes the first where the person fits
        return (self._pace(math.dist(at, slot)), [(*slot, self._pace(math.dist(at, slot))),
                                                  (*in_file, self._pace(math.dist(at, in_file)))])

    def _pace(self, far: float) -> float:
        """Stand when at the place (the leader stands, the place is taken); behind, hurry: up to twice the pace
        a metre off."""
        if far < ARRIVE_STOP:
            return 0.0
        return min(3.0, max(self._leader.speed, self.speed) * (1.0 + min(far, 1.0)))
