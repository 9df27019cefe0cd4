# SPDX-License-Identifier: EPL-2.0
"""The external SUT of one mission: ``hello`` offered, the SUT started or awaited, told to leave at the end."""

from __future__ import annotations

import contextlib
import os
from collections.abc import Callable, Iterator
from pathlib import Path
from urllib.parse import urlparse

from rei.artifacts.case import Case
from rei.sut.api import StaticMap
from rei.sut.external import process as sut_process
from rei.sut.external import protocol
from rei.sut.external.controller import ExternalController, SutError
from rei.sut.external.options import SutOptions
from rei.sut.external.process import Connection, SutLaunchError
from rei.wamp.client import WampClient, WampError


@contextlib.contextmanager
def external_sut(options: SutOptions, client: WampClient, run_id: str, out_dir: Path, *, case: Case,
                 static_map: StaticMap, control_rate: float, now: Callable[[], float],
                 log: Callable[[str], None] = print) -> Iterator[ExternalController]:
    """The connected SUT as a controller; on leaving, ``end`` is published and a started SUT is stopped."""
    robot = case.world.robot
    limits = protocol.RobotLimits(robot.drive.max_linear_velocity, robot.drive.max_angular_velocity,
                                  robot.drive.max_lateral_velocity)
    controller = ExternalController(client, run_id, clock=options.clock, deadline=options.deadline, limits=limits,
                                    scan_time=1.0 / robot.lidar.rate, first_deadline=options.join_timeout, now=now,
                                    log=log)
    controller.attach(protocol.hello_answer(
        run_id=run_id, clock=options.clock, control_rate=control_rate, deadline=options.deadline,
        start=case.mission.start, goals=len(case.mission.goals),
        static_map=static_map if options.offer_map else None,
        occupancy=_in_case(case.world.map.yaml, case.folder) if case.world.map is not None else None,
        robot={"name": robot.name, "footprint": [float(robot.size[0]), float(robot.size[1])],
               "max_linear": limits.max_linear, "max_angular": limits.max_angular,
               "drive": robot.drive.kind, "max_lateral": limits.max_lateral,
               "outline": protocol.outline(robot.outline),
               "lidar": {"beams": robot.lidar.beams, "range_min": float(robot.lidar.range_min),
                         "range_max": float(robot.lidar.range_max), "rate": float(robot.lidar.rate),
                         "x": float(robot.lidar.x), "y": float(robot.lidar.y), "yaw": float(robot.lidar.yaw)}}))
    url = options.router_url or client.url
    # the simulation's own session is RawSocket when it can be (rei sim, rei run): offered to the SUT too, but
    # only where it reaches the same router as the URL the SUT was given
    rawsocket = client.url if client.url.startswith(("rs://", "rss://")) and _host(client.url) == _host(url) else None
    connection = Connection(url, client.realm, run_id, options.auth_file, rawsocket, case.folder.resolve())
    started = None
    try:
        if options.command is not None:
            try:
                started = sut_process.start(options.command, connection, out_dir, options.cwd)
            except SutLaunchError as error:
                raise SutError(str(error)) from None
            controller.attach_process(started)
            what = f"the system under test ({options.command})"
        else:
            env_file = connection.write_env_file(out_dir / sut_process.ENV_FILE)
            log(f"sut: waiting up to {options.join_timeout:g} s for your system under test to join; start it "
                f"with the variables of {env_file}: {' '.join(f'{k}={v}' for k, v in connection.environment().items())}")
            what = "the attached system under test"
        controller.wait_joined(options.join_timeout, what)
        log(f"sut: {what} joined ({options.clock})" + (f" as {controller.name!r}" if controller.name else ""))
        yield controller
    finally:
        with contextlib.suppress(WampError):
            controller.end(now(), "the run is over")
        if started is not None:
            controller.stats.exit_code = sut_process.stop(started)


def _host(url: str) -> str | None:
    return urlparse(url).hostname


def _in_case(path: Path, folder: Path) -> str:
    """``path`` named relative to the case's folder: a name, not a path of this machine (docs/sut.md)."""
    return Path(os.path.relpath(path.resolve(), folder.resolve())).as_posix()
