# SPDX-License-Identifier: EPL-2.0
"""One headless pybullet run of a generated test case: world, robot, lidar, odometry, animator, faults, and the
crowd model that moves the reactive people (rei.sim.people).

Time is counted in physics steps (``t = steps / physics_rate``), never read from a clock, and every random draw
comes from generators seeded from ``seed``: the same case, seed, options and command sequence give the same
state sequence. The lidar and the animator run at their own rates, on the physics steps where they fall due.
"""

from __future__ import annotations

import math
from pathlib import Path
from types import TracebackType
from typing import Self

import numpy as np
import pybullet as p

from rei.artifacts.case import Case, read_case
from rei.artifacts.world import Category, ObjectSpec, RobotSpec, Shape
from rei.geometry import Pose2D, Twist2D, yaw_of_quaternion
from rei.sim.animator import AnimatedBody, Animator, DriveMode
from rei.sim.clearance import clearance_for
from rei.sim.contacts import ContactSensor
from rei.sim.drive import DiffDrive, HolonomicDrive
from rei.sim.faults import FaultSchedule, LaserFault, LaserFaults, MotionFaults, as_schedule, fault_generators
from rei.sim.lidar import Lidar, Prisms
from rei.sim.native_output import quiet_native_output
from rei.sim.odometry import BodyOdometry, WheelOdometry
from rei.sim.people import DT as CROWD_DT
from rei.sim.people import Crowd, Mover, RobotView, footprint_radius
from rei.sim.robot_model import ROBOT_COLLISION_GROUP, load_robot, wheel_torque_for
from rei.sim.state import ObjectState, RobotState, SimState
from rei.sim.world_loader import GRAVITY, load_world
from rei.spline import Trajectory
from rei.sut.api import LaserScan, Observation, StaticMap

#: The collision filter mask of the reactive people's fixed bodies, which are in no collision group: pybullet's other
#: fixed bodies (walls, floors, furniture, the other people) never meet them, nor do its rays (the lidar meets them
#: by their shape, rei.sim.lidar.Prisms); the robot and the moving bodies (pybullet's default group 1) do.
PEOPLE_COLLISION_MASK = ROBOT_COLLISION_GROUP | 0x1

MAX_ACCELERATION = 2.5
"""m/s^2 the wheel motors can give the robot: sets their torque limit (a TurtleBot3 manages about this)."""


class Simulation:
    """A running simulation; use as a context manager or call :meth:`close`."""

    def __init__(
        self,
        case: Path | str | Case,
        *,
        seed: int = 0,
        physics_rate: float = 240.0,
        humans: bool = True,
        lidar_rate: float | None = None,
        fault: FaultSchedule | LaserFault | str | None = None,
        odom_noise: float = 0.0,
        animator_rate: float = 60.0,
        animation_mode: DriveMode | str = DriveMode.VELOCITY,
    ) -> None:
        """Load ``case`` (a folder of the five generated files, or an already read :class:`Case`).

        ``humans=False`` removes the HUMAN bodies (a static run of the same room); DYNAMIC objects stay.
        ``lidar_rate`` defaults to world.json's lidar rate. ``fault`` is a :class:`FaultSchedule`, a run-long
        :class:`LaserFault` or a ``--fault`` spec (``laser:1%``, ``laser:blackout,from=5,to=7``); it acts after
        the mission's own faults (mission.xml), in :attr:`faults`. ``odom_noise`` is in m^0.5 (rei.sim.odometry).
        """
        self.case = case if isinstance(case, Case) else read_case(case)
        robot_spec = self.case.world.robot
        lidar_rate = robot_spec.lidar.rate if lidar_rate is None else lidar_rate
        for label, value in (
            ("physics_rate", physics_rate),
            ("lidar_rate", lidar_rate),
            ("animator_rate", animator_rate),
        ):
            if not (math.isfinite(value) and value > 0):
                raise ValueError(f"{label} must be a positive number of Hz, got {value}")
        if odom_noise < 0:
            raise ValueError(f"odom_noise must be >= 0, got {odom_noise}")
        try:
            mode = DriveMode(animation_mode)
        except ValueError:
            modes = ", ".join(m.value for m in DriveMode)
            raise ValueError(f"animation_mode must be one of {modes}, got {animation_mode!r}") from None
        self.physics_rate = float(physics_rate)
        self.dt = 1.0 / self.physics_rate
        self.lidar_rate = float(lidar_rate)
        self.animator_rate = float(animator_rate)
        self.faults = FaultSchedule(self.case.mission.faults) + as_schedule(fault)
        self._steps = 0
        self._next_animation = 0
        self._animations = 0
        self._next_crowd = 0
        self._crowd_steps = 0
        self._next_scan = 0
        self._scans = 0
        self._scan: LaserScan | None = None
        self._laser_min = math.inf
        self._laser_clearance = math.inf
        with quiet_native_output():
            self._client = p.connect(p.DIRECT)
        self._closed = False
        self._crowd: Crowd | None = None
        self._people: list[tuple[int, float, tuple[float, ...]]] = []  # each person's body, height, orientation
        self._person_of: dict[int, int] = {}  # a person's body -> its index in the crowd
        self._placed: list[tuple[float, float]] = []  # where each person's body was last put
        try:
            self._build(np.random.SeedSequence(seed), humans, odom_noise, mode)
        except BaseException:
            self.close()
            raise
        self._update_due()

    def _build(self, seeds: np.random.SeedSequence, humans: bool, odom_noise: float, mode: DriveMode) -> None:
        """Load the world and the robot into the fresh client and wire up sensors and animator."""
        client = self._client
        world = self.case.world
        robot_spec = world.robot
        fault_seed, odom_seed = seeds.spawn(2)
        p.setPhysicsEngineParameter(
            fixedTimeStep=self.dt, numSubSteps=0, deterministicOverlappingPairs=1, physicsClientId=client
        )
        # the reactive people's bodies are fixed, put where the model puts them at each crowd step (moving, each
        # cost the physics step its dynamics and its broadphase bounds). The model keeps people apart from each
        # other, the walls and the furniture, so in the physics they touch only the robot and the moving bodies
        # (touching all, the model's tight spacing pressed them together: hundreds of contacts a step)
        people = list(self.case.animation.people) if humans else []
        self.world = load_world(client, self.case.sdf_path, world, fixed=[person.name for person in people])
        for person in people:  # before the robot is loaded: a filter set later does not part bodies already paired
            p.setCollisionFilterGroupMask(self.world.body_of[person.name], -1, 0, PEOPLE_COLLISION_MASK,
                                          physicsClientId=client)
        removed = {o.name for o in world.objects if o.category is Category.HUMAN and not humans}
        for name in sorted(removed):
            p.removeBody(self.world.body_of[name], physicsClientId=client)
        self._holonomic: HolonomicDrive | None = None
        if robot_spec.drive.holonomic:
            self._build_holonomic(robot_spec, odom_noise, odom_seed)
        else:
            self._build_differential(robot_spec, odom_noise, odom_seed)
        body = self._robot.body
        self._shapes = _shapes(client, [(self.world.body_of[person.name], world.object(person.name))
                                        for person in people])
        self._lidar = Lidar(client, body, robot_spec.lidar, self._shapes if people else None)
        self._clearance = clearance_for(robot_spec)
        lidar = robot_spec.lidar
        # every fault's generator, made once (the commands' faults use them in the mission loop)
        self.fault_generators = fault_generators(self.faults, fault_seed) if self.faults else []
        motion = self.faults.motion()
        self._motion = motion if motion else None
        self._fault = (
            LaserFaults(self.faults, self.fault_generators, range_min=lidar.range_min,
                        range_max=lidar.range_max, angle_min=0.0, angle_increment=self._lidar.angle_increment,
                        beams=lidar.beams)
            if self.faults.of("laser")
            else None
        )
        floors = frozenset(self.world.body_of[o.name] for o in world.objects if o.category is Category.FLOOR)
        if self.world.ground is not None:
            floors |= {self.world.ground}
        self._contacts = ContactSensor(client, body, floors, self.world.contact_name)
        self._moving = [
            (o.name, o.category.value, self.world.body_of[o.name])
            for o in world.objects
            if o.category.moving and o.name not in removed
        ]
        animated = [
            AnimatedBody(
                name=a.name,
                body=self.world.body_of[a.name],
                mass=world.object(a.name).mass,
                trajectory=Trajectory([q.t for q in a.points], [(q.x, q.y) for q in a.points], a.loop),
            )
            for a in self.case.animation.objects
            if a.name not in removed
        ]
        if people:
            # the people see the robot and the bodies on rails; a third seed, so the others' draws stay as they were
            (crowd_seed,) = seeds.spawn(1)
            # what the people see of the robot's shape: its front's distance from its centre, its footprint's disc
            self._robot_extent = (robot_spec.size[0] / 2, footprint_radius(robot_spec.shape, robot_spec.size))
            rails = [world.object(a.name) for a in animated]
            self._rails = [b.body for b in animated]
            self._crowd = Crowd(world, people, [
                Mover(robot_spec.pose[0], robot_spec.pose[1], footprint_radius(robot_spec.shape, robot_spec.size),
                      robot=True),
                *(Mover(o.pose[0], o.pose[1], footprint_radius(o.shape, o.size), robot=False) for o in rails)],
                seed=int(crowd_seed.generate_state(1)[0]))
            # each person's body: put at each crowd step at the model's place after its latest step, upright as it
            # stands in world.sdf; its twist in the state is the model's over that step
            self._people = []
            for i, person in enumerate(people):
                body = self.world.body_of[person.name]
                (_, _, z), orientation = p.getBasePositionAndOrientation(body, physicsClientId=client)
                self._people.append((body, z, orientation))
                self._person_of[body] = i
            self._placed = [self._crowd.position(i) for i in range(len(people))]
        self._animator = Animator(client, animated, mode, self.dt, floors, GRAVITY)
        self._animator.place(0.0)
        # Bodies loaded but never stepped keep stale broadphase bounds: rays would miss them in the first scan.
        p.performCollisionDetection(physicsClientId=client)

    def _build_differential(self, robot_spec: RobotSpec, odom_noise: float, odom_seed: np.random.SeedSequence) -> None:
        """The differential drive: wheel motors, odometry from the wheels' rotation."""
        client = self._client
        self._robot = load_robot(client, robot_spec)
        body = self._robot.body
        self._drive = DiffDrive(
            client,
            body,
            self._robot.left_wheel,
            self._robot.right_wheel,
            robot_spec.drive,
            wheel_torque_for(robot_spec, MAX_ACCELERATION),
        )
        self._wheels = [self._robot.left_wheel, self._robot.right_wheel]
        (la, _, _, _), (ra, _, _, _) = p.getJointStates(body, self._wheels, physicsClientId=client)
        self._odometry = WheelOdometry(
            robot_spec.drive.wheel_radius,
            robot_spec.drive.wheel_separation,
            Pose2D(robot_spec.pose[0], robot_spec.pose[1], robot_spec.pose[3]),
            la,
            ra,
            noise=odom_noise,
            rng=np.random.default_rng(odom_seed) if odom_noise > 0 else None,
        )

    def _build_holonomic(self, robot_spec: RobotSpec, odom_noise: float, odom_seed: np.random.SeedSequence) -> None:
        """The holonomic drive (rei.sim.drive.HolonomicDrive): the same body on frictionless wheels, pushed by its
        drive; odometry from the body's own velocity."""
        if any(fault.sensor == "drive" and fault.kind == "stuck" for fault in self.faults.faults):
            raise ValueError("a stuck wheel is a fault of a differential drive: "
                             f"the robot {robot_spec.name} is holonomic")
        self._robot = load_robot(self._client, robot_spec, wheel_friction=0.0)
        self._holonomic = HolonomicDrive(self._client, self._robot.body, robot_spec.drive, MAX_ACCELERATION,
                                         self.dt)
        self._drive = self._holonomic
        self._wheels = [self._robot.left_wheel, self._robot.right_wheel]
        self._odometry = BodyOdometry(
            Pose2D(robot_spec.pose[0], robot_spec.pose[1], robot_spec.pose[3]),
            noise=odom_noise,
            rng=np.random.default_rng(odom_seed) if odom_noise > 0 else None,
        )

    # --- time -------------------------------------------------------------------------------------------------
    @property
    def t(self) -> float:
        """Simulation time in seconds since the start."""
        return self._steps * self.dt

    @property
    def steps(self) -> int:
        return self._steps

    def step(self, cmd: Twist2D) -> None:
        """Advance one physics step with the velocity command ``cmd`` (clamped to the robot's limits)."""
        if self._holonomic is not None:
            self._step_holonomic(self._holonomic, cmd, self._motion)
            return
        motion = self._motion
        if motion is not None:
            self._step_motion(cmd, motion)
            return
        self._drive.command(cmd)
        client = self._client
        p.stepSimulation(physicsClientId=client)
        self._steps += 1
        (la, lr, _, _), (ra, rr, _, _) = p.getJointStates(
            self._robot.body, self._wheels, physicsClientId=client
        )
        self._odometry.update(la, ra, lr, rr)
        self._contacts.update()
        self._update_due()

    def _step_motion(self, cmd: Twist2D, motion: MotionFaults) -> None:
        """:meth:`step` with drive, odometry and pose faults (rei.sim.faults.motion), those active at the step's
        start: a kidnap moves the body before the step, a jump the odometry after it."""
        t = self.t
        fraction, stuck, travel = motion.drive(t)
        self._drive.command(cmd, fraction, stuck)
        client = self._client
        for kidnap in motion.kidnaps(t):
            (x, y, z), orientation = p.getBasePositionAndOrientation(self._robot.body, physicsClientId=client)
            yaw = yaw_of_quaternion(*orientation) + math.radians(kidnap.dyaw)
            p.resetBasePositionAndOrientation(self._robot.body, (x + kidnap.dx, y + kidnap.dy, z),
                                              p.getQuaternionFromEuler((0.0, 0.0, yaw)), physicsClientId=client)
        p.stepSimulation(physicsClientId=client)
        self._steps += 1
        (la, lr, _, _), (ra, rr, _, _) = p.getJointStates(
            self._robot.body, self._wheels, physicsClientId=client
        )
        scale, bias = motion.odometry(t, self.dt)
        self._odometry.update(la, ra, lr, rr, scale * travel, bias)
        for jump in motion.jumps(t):
            self._odometry.shift(jump.dx, jump.dy, math.radians(jump.dyaw))
        self._contacts.update()
        self._update_due()

    def _step_holonomic(self, drive: HolonomicDrive, cmd: Twist2D, motion: MotionFaults | None) -> None:
        """:meth:`step` for a holonomic drive, its faults as :meth:`_step_motion`'s."""
        t = self.t
        fraction, stuck, travel = motion.drive(t) if motion is not None else (1.0, (False, False), 1.0)
        drive.command(cmd, fraction, stuck)
        client = self._client
        body = self._robot.body
        if motion is not None:
            for kidnap in motion.kidnaps(t):
                (x, y, z), orientation = p.getBasePositionAndOrientation(body, physicsClientId=client)
                yaw = yaw_of_quaternion(*orientation) + math.radians(kidnap.dyaw)
                p.resetBasePositionAndOrientation(body, (x + kidnap.dx, y + kidnap.dy, z),
                                                  p.getQuaternionFromEuler((0.0, 0.0, yaw)), physicsClientId=client)
        drive.push()
        p.stepSimulation(physicsClientId=client)
        self._steps += 1
        _, orientation = p.getBasePositionAndOrientation(body, physicsClientId=client)
        (vx, vy, _), (_, _, wz) = p.getBaseVelocity(body, physicsClientId=client)
        yaw = yaw_of_quaternion(*orientation)
        c, s = math.cos(yaw), math.sin(yaw)
        scale, bias = motion.odometry(t, self.dt) if motion is not None else (1.0, 0.0)
        odometry = self._odometry
        assert isinstance(odometry, BodyOdometry)
        odometry.update(c * vx + s * vy, -s * vx + c * vy, wz, self.dt, scale * travel, bias)
        if motion is not None:
            for jump in motion.jumps(t):
                odometry.shift(jump.dx, jump.dy, math.radians(jump.dyaw))
        self._contacts.update()
        self._update_due()

    def _update_due(self) -> None:
        """Run the lidar and the animator if they fall due on the current step (their schedules are integer)."""
        n = self._steps
        if n >= self._next_scan:
            self._take_scan()
            self._scans += 1
            self._next_scan = math.ceil(self._scans * self.physics_rate / self.lidar_rate - 1e-9)
        if n >= self._next_animation:
            self._animations += 1
            self._next_animation = max(
                n + 1, math.ceil(self._animations * self.physics_rate / self.animator_rate - 1e-9)
            )
            self._animator.update(self.t, self._next_animation * self.dt)
        if self._crowd is not None and n >= self._next_crowd:
            self._crowd_steps += 1
            self._next_crowd = max(n + 1, math.ceil(self._crowd_steps * self.physics_rate * CROWD_DT - 1e-9))
            robot = self._robot_view()
            self._crowd.step(robot, [(robot.x, robot.y), *(self._pose(b)[:2] for b in self._rails)])
            self._place_people()

    def _place_people(self) -> None:
        """Put the bodies of the people who moved at their places in the model after its latest step, and the
        lidar's shapes of them too."""
        assert self._crowd is not None
        client = self._client
        now = self._crowd.positions
        for (body, z, orientation), (x, y), before in zip(self._people, now, self._placed, strict=True):
            if (x, y) != before:
                p.resetBasePositionAndOrientation(body, (x, y, z), orientation, physicsClientId=client)
        self._placed = list(now)
        self._shapes.xy[:] = now

    def _robot_view(self) -> RobotView:
        x, y, _, yaw = self._pose(self._robot.body)
        vx, vy, _ = self._twist(self._robot.body)
        return RobotView(x, y, yaw, vx, vy, *self._robot_extent)

    def _take_scan(self) -> None:
        ranges = self._lidar.scan()
        if self._fault is not None:
            ranges = self._fault.apply(self.t, ranges)
        ranges.flags.writeable = False
        spec = self._lidar.spec
        self._scan = LaserScan(
            t=self.t,
            angle_min=0.0,
            angle_increment=self._lidar.angle_increment,
            range_min=spec.range_min,
            range_max=spec.range_max,
            ranges=ranges,
        )
        self._laser_min = float(ranges.min())
        self._laser_clearance = self._clearance(ranges, 0.0, self._lidar.angle_increment)

    # --- what the controller sees -----------------------------------------------------------------------------
    def observation(self) -> Observation:
        """Odometry and the latest scan: what a real robot's controller would get."""
        return Observation(
            t=self.t, odom=self._odometry.pose, odom_twist=self._odometry.twist, scan=self._scan
        )

    def static_map(self) -> StaticMap:
        """Walls and STATIC objects as footprint rectangles, the floors' bounds and the robot's footprint."""
        return StaticMap.of_world(self.case.world)

    # --- ground truth -----------------------------------------------------------------------------------------
    def robot_pose(self) -> Pose2D:
        """The robot's true planar pose (for judging goals; cheaper than a whole :meth:`state`)."""
        x, y, _, yaw = self._pose(self._robot.body)
        return Pose2D(x, y, yaw)

    def state(self) -> SimState:
        """The true state now, for the data collector: each call is one sample of the published stream.

        ``contacts`` holds every body the robot touched at any physics step since the previous call.
        """
        robot_name = self.case.world.robot.name
        objects = tuple(
            ObjectState(name=name, category=category, pose=self._pose(body), twist=self._twist(body))
            for name, category, body in self._moving
        )
        contacts = tuple(sorted((robot_name, name) for name in self._contacts.drain()))
        scan = self._scan
        robot = RobotState(
            name=robot_name,
            pose=self._pose(self._robot.body),
            twist=self._twist(self._robot.body),
            odom=self._odometry.pose,
            laser_min=self._laser_min,
            laser_ranges=scan.ranges if scan is not None else None,
            laser_clearance=self._laser_clearance,
        )
        return SimState(t=self.t, robot=robot, objects=objects, contacts=contacts)

    def _pose(self, body: int) -> tuple[float, float, float, float]:
        (x, y, z), orientation = p.getBasePositionAndOrientation(body, physicsClientId=self._client)
        return (x, y, z, yaw_of_quaternion(*orientation))

    def _twist(self, body: int) -> tuple[float, float, float]:
        person = self._person_of.get(body)
        if person is not None:  # a fixed body: the model's velocity over its latest step
            assert self._crowd is not None
            return (*self._crowd.velocity(person), 0.0)
        (vx, vy, _), (_, _, wz) = p.getBaseVelocity(body, physicsClientId=self._client)
        return (vx, vy, wz)

    @property
    def robot_body(self) -> int:
        """The robot's pybullet body id (for tests and tools that need the raw engine)."""
        return self._robot.body

    @property
    def client(self) -> int:
        """The pybullet physics client id of this simulation."""
        return self._client

    # --- lifetime ---------------------------------------------------------------------------------------------
    @property
    def crowd(self) -> Crowd | None:
        """The crowd model of the reactive people, None without any (for tests and tools)."""
        return self._crowd

    def close(self) -> None:
        if not self._closed:
            self._closed = True
            if self._crowd is not None:
                self._crowd.close()
            p.disconnect(self._client)

    def __enter__(self) -> Self:
        return self

    def __exit__(
        self, exc_type: type[BaseException] | None, exc: BaseException | None, tb: TracebackType | None
    ) -> None:
        self.close()


def _shapes(client: int, bodies: list[tuple[int, ObjectSpec]]) -> Prisms:
    """What the lidar meets of each body: an upright cylinder of its size (a CYLINDER), else a box of its size (a
    mesh's collision body is one too), standing where its body stands."""
    places = [p.getBasePositionAndOrientation(body, physicsClientId=client) for body, _ in bodies]
    specs = [spec for _, spec in bodies]
    return Prisms(
        xy=[(x, y) for (x, y, _), _ in places],
        z=[(z - spec.size[2] / 2, z + spec.size[2] / 2) for ((_, _, z), _), spec in zip(places, specs, strict=True)],
        radius=[spec.size[0] / 2 if spec.shape is Shape.CYLINDER else 0.0 for spec in specs],
        half=[(spec.size[0] / 2, spec.size[1] / 2) for spec in specs],
        yaw=[yaw_of_quaternion(*orientation) for _, orientation in places],
    )
