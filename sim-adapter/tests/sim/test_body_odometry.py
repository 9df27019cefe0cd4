# SPDX-License-Identifier: EPL-2.0
"""A holonomic base's odometry (rei.sim.odometry.BodyOdometry): the body's velocity in its own frame, integrated in
the frame of the odometry's own heading; its faults and noise as the wheel odometry's."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rei.geometry import Pose2D, Twist2D
from rei.sim.odometry import BodyOdometry

DT = 1 / 240


def drive(odometry: BodyOdometry, v: float, vy: float, w: float, seconds: float, **faults: float) -> None:
    for _ in range(round(seconds / DT)):
        odometry.update(v, vy, w, DT, **faults)


def test_sideways_is_the_robot_s_left_in_the_world() -> None:
    odometry = BodyOdometry(Pose2D(1.0, 2.0, math.pi / 2))  # facing +y: its left is -x
    drive(odometry, 0.0, 0.3, 0.0, 2.0)
    assert (odometry.pose.x, odometry.pose.y, odometry.pose.yaw) == pytest.approx((0.4, 2.0, math.pi / 2))
    assert odometry.twist == Twist2D(0.0, 0.0, 0.3)


def test_strafing_while_turning_follows_a_circle_about_the_start() -> None:
    # sideways at 0.2 m/s while turning at 1 rad/s: a circle of radius 0.2 m whose centre is behind the start
    odometry = BodyOdometry(Pose2D(0.0, 0.0, 0.0))
    drive(odometry, 0.0, 0.2, 1.0, math.pi)
    # (754 steps of 1/240 s are pi + 6e-5 s: 1e-4 m is that, a wrong frame would be off by decimetres)
    assert (odometry.pose.x, odometry.pose.y) == pytest.approx((-0.4, 0.0), abs=1e-4)
    assert abs(odometry.pose.yaw) == pytest.approx(math.pi, abs=1e-4)


def test_a_slip_s_scale_and_a_bias_change_the_belief() -> None:
    odometry = BodyOdometry(Pose2D(0.0, 0.0, 0.0))
    drive(odometry, 0.1, 0.1, 0.0, 1.0, scale=2.0)
    assert (odometry.pose.x, odometry.pose.y) == pytest.approx((0.2, 0.2))
    drive(odometry, 0.0, 0.0, 0.0, 1.0, yaw_bias=0.001)
    assert odometry.pose.yaw == pytest.approx(0.24)


def test_noise_grows_with_the_square_root_of_the_distance_and_is_seeded() -> None:
    ends = []
    for seed in range(200):
        odometry = BodyOdometry(Pose2D(0.0, 0.0, 0.0), noise=0.05, rng=np.random.default_rng(seed))
        drive(odometry, 0.0, 0.5, 0.0, 2.0)
        ends.append(odometry.pose.y - 1.0)
    assert float(np.std(ends)) == pytest.approx(0.05 * math.sqrt(1.0), rel=0.2)
    again = BodyOdometry(Pose2D(0.0, 0.0, 0.0), noise=0.05, rng=np.random.default_rng(199))
    drive(again, 0.0, 0.5, 0.0, 2.0)
    assert again.pose.y - 1.0 == ends[-1]
    with pytest.raises(ValueError, match="needs a seeded generator"):
        BodyOdometry(Pose2D(0.0, 0.0), noise=0.1)
