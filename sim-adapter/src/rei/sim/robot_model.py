# SPDX-License-Identifier: EPL-2.0
"""Builds the robot's URDF from world.json's ``robot`` and loads it into pybullet.

The robot is not part of world.sdf: its dimensions come from the test case, its structure (two driven wheels on
the footprint's centre line, two frictionless casters) from the template ``robots/diffdrive.urdf``. A robot read
from a URDF description is built the same way around its footprint extruded to the lidar's height, not from the
description's own links: their meshes are often absent (package:// paths), and the extruded hull is exactly the
outline the monitor and the metrics judge, so a contact in pybullet is a collision in the monitor (docs/robots.md).
"""

from __future__ import annotations

import tempfile
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from string import Template

import pybullet as p

from rei.artifacts.world import CircleFootprint, RobotSpec, footprint_polygon

GROUND_CLEARANCE = 0.01
WHEEL_WIDTH = 0.018
CASTER_RADIUS = 0.012
FRONT_CASTER_LIFT = 0.003
ROBOT_COLLISION_GROUP = 0x8000
"""The robot's links are in this collision group alone, so the lidar's rays can leave them out."""
ROBOT_COLLISION_MASK = 0xFFFF & ~0x1
"""The robot's links' collision mask leaves out group 1, a ray's: Bullet's ray test skips a body whose mask leaves
out the ray's group before testing the ray against its shape, where pybullet's ``collisionFilterMask`` of a ray
drops a body only after the test (every lidar ray starts inside the robot: a test each against its chassis, a
millisecond a scan against a footprint's hull). Bodies still meet the robot: pybullet pairs two bodies when either's
group is in the other's mask, and every other body's mask has the robot's group."""


@dataclass(frozen=True, slots=True)
class RobotBody:
    """Handles of a loaded robot: its body id and the indices of what the simulator drives and reads."""

    body: int
    left_wheel: int
    right_wheel: int
    casters: tuple[int, int]
    links: tuple[int, ...]


CHASSIS_MESH = "chassis.obj"
"""The extruded footprint of a robot read from a description, written beside its URDF."""


def chassis_obj(points: list[tuple[float, float]], height: float) -> str:
    """An OBJ prism of ``points`` from ``-height/2`` to ``height/2`` (the chassis link's origin is its middle);
    pybullet takes a mesh's convex hull as its collision shape, which for a convex footprint is the prism."""
    n = len(points)
    lines = [f"v {x!r} {y!r} {z!r}" for z in (-height / 2, height / 2) for x, y in points]
    lines.append("f " + " ".join(str(i) for i in range(n, 0, -1)))  # bottom, facing down
    lines.append("f " + " ".join(str(n + i) for i in range(1, n + 1)))  # top, facing up
    lines += [f"f {i + 1} {(i + 1) % n + 1} {n + (i + 1) % n + 1} {n + i + 1}" for i in range(n)]
    return "\n".join(lines) + "\n"


def render_urdf(spec: RobotSpec) -> str:
    """The URDF text for ``spec``; masses are split so the whole robot weighs ``spec.mass``. A robot read from a
    description gets its footprint extruded as its chassis (:data:`CHASSIS_MESH`, see :func:`load_robot`): the
    body pybullet collides is the outline the monitor and the metrics measure, and the drive stays the template's
    (two wheels on the origin's axle, as a description's differential drive has them, and two casters)."""
    sx, sy, sz = spec.size
    r = spec.drive.wheel_radius
    if sz <= GROUND_CLEARANCE + 0.01:
        raise ValueError(
            f"robot height {sz} m is too small for a chassis above {GROUND_CLEARANCE} m clearance"
        )
    wheel_mass = min(0.1, 0.1 * spec.mass)
    caster_mass = min(0.01, 0.01 * spec.mass)
    footprint_mass = min(0.05, 0.05 * spec.mass)
    chassis_mass = spec.mass - 2 * wheel_mass - 2 * caster_mass - footprint_mass
    chassis_h = sz - GROUND_CLEARANCE
    chassis_xy = "0 0"  # a box robot's URDF is the text it always was
    if spec.footprint is None:
        xmin, xmax = -sx / 2, sx / 2
        chassis_geometry = f'<box size="{float(sx)!r} {float(sy)!r} {float(chassis_h)!r}"/>'
    elif isinstance(spec.footprint, CircleFootprint):
        # an upright cylinder, the circle itself: a 64-gon hull cost each lidar ray a GJK test against its 128
        # vertices (pybullet's ray filter drops the robot's own links only after testing them), 2 ms a scan
        circle = spec.footprint
        xmin, xmax = circle.x - circle.radius, circle.x + circle.radius
        chassis_xy = f"{float(circle.x)!r} {float(circle.y)!r}"
        chassis_geometry = f'<cylinder radius="{float(circle.radius)!r}" length="{float(chassis_h)!r}"/>'
    else:
        xs = [x for x, _ in footprint_polygon(spec.footprint)]
        xmin, xmax = min(xs), max(xs)
        chassis_geometry = f'<mesh filename="{CHASSIS_MESH}"/>'
    values = {
        "name": spec.name,
        "footprint_mass": footprint_mass,
        "chassis_mass": chassis_mass,
        "com_x": (xmin + xmax) / 2 - 0.05 * sx,
        "chassis_z": GROUND_CLEARANCE + chassis_h / 2,
        "chassis_h": chassis_h,
        "chassis_ixx": chassis_mass * (sy**2 + chassis_h**2) / 12,
        "chassis_iyy": chassis_mass * (sx**2 + chassis_h**2) / 12,
        "chassis_izz": chassis_mass * (sx**2 + sy**2) / 12,
        "chassis_geometry": chassis_geometry,
        "chassis_xy": chassis_xy,
        "wheel_mass": wheel_mass,
        "wheel_r": r,
        "wheel_w": WHEEL_WIDTH,
        "wheel_ixx": wheel_mass * (3 * r**2 + WHEEL_WIDTH**2) / 12,
        "wheel_iyy": wheel_mass * r**2 / 2,
        "half_track": spec.drive.wheel_separation / 2,
        "caster_mass": caster_mass,
        "caster_r": CASTER_RADIUS,
        # a box robot's casters as they always were (the same floats: its runs record what they recorded before)
        "caster_rear_x": -(sx / 2 - CASTER_RADIUS - 0.02) if spec.footprint is None else xmin + CASTER_RADIUS + 0.02,
        "caster_front_x": xmax - CASTER_RADIUS - 0.02,
        "caster_front_z": CASTER_RADIUS + FRONT_CASTER_LIFT,
    }
    template = resources.files("rei.sim").joinpath("robots/diffdrive.urdf").read_text(encoding="utf-8")
    return Template(template).substitute(
        {k: v if isinstance(v, str) else repr(float(v)) for k, v in values.items()}
    )


def load_robot(client: int, spec: RobotSpec, wheel_friction: float = 1.0) -> RobotBody:
    """Load the robot standing at ``spec.pose`` and set up friction and its collision group."""
    with tempfile.TemporaryDirectory(prefix="rei-robot-") as folder:
        urdf = Path(folder) / f"{spec.name}.urdf"
        urdf.write_text(render_urdf(spec), encoding="utf-8")
        if spec.footprint is not None and not isinstance(spec.footprint, CircleFootprint):
            (Path(folder) / CHASSIS_MESH).write_text(
                chassis_obj(list(footprint_polygon(spec.footprint)), spec.size[2] - GROUND_CLEARANCE), encoding="utf-8")
        x, y, _, yaw = spec.pose
        body = p.loadURDF(
            str(urdf),
            basePosition=[x, y, 0.0],
            baseOrientation=p.getQuaternionFromEuler([0.0, 0.0, yaw]),
            # A true cylinder: the default convex-hull wheel rolls on its collision margin, ~3 % too far per turn.
            flags=p.URDF_USE_IMPLICIT_CYLINDER,
            physicsClientId=client,
        )
    joints = {
        p.getJointInfo(body, j, physicsClientId=client)[1].decode(): j
        for j in range(p.getNumJoints(body, physicsClientId=client))
    }
    left, right = joints["wheel_left_joint"], joints["wheel_right_joint"]
    casters = (joints["caster_rear_joint"], joints["caster_front_joint"])
    links = (-1, *sorted(joints.values()))
    for link in links:
        p.setCollisionFilterGroupMask(body, link, ROBOT_COLLISION_GROUP, ROBOT_COLLISION_MASK, physicsClientId=client)
    for wheel in (left, right):
        p.changeDynamics(body, wheel, lateralFriction=wheel_friction, physicsClientId=client)
        # Without this the velocity motor would fight a default joint damping; the wheels spin freely.
        p.changeDynamics(
            body, wheel, jointDamping=0.0, linearDamping=0.0, angularDamping=0.0, physicsClientId=client
        )
    for caster in casters:
        p.changeDynamics(
            body,
            caster,
            lateralFriction=0.0,
            spinningFriction=0.0,
            rollingFriction=0.0,
            physicsClientId=client,
        )
    return RobotBody(body=body, left_wheel=left, right_wheel=right, casters=casters, links=links)


def wheel_torque_for(spec: RobotSpec, max_acceleration: float) -> float:
    """Motor torque per wheel that accelerates the robot at ``max_acceleration`` (m/s^2) on flat ground."""
    return spec.mass * max_acceleration * spec.drive.wheel_radius / 2.0
