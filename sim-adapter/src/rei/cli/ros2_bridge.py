# SPDX-License-Identifier: EPL-2.0
"""`rei ros2-bridge [options] -- COMMAND...`: a ROS 2 navigation stack (Nav2, on any DDS) as REI's external SUT
(docs/ros.md).

Started by `rei run CASE --sut "ros2:COMMAND"` with the environment of an external SUT; it takes a ROS domain of
the run's own, joins it on loopback, starts COMMAND with ROS_DOMAIN_ID, ROS 2's localhost-only switches and
CYCLONEDDS_URI set, and plays the robot to it: /clock, /scan, /odom, /tf, /map, /cmd_vel and the NavigateToPose action. The
stack's nodes must run with use_sim_time. Exit 0 at the run's end, 1 on a bug of the bridge, 2 when the stack is
missing or exited.
"""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from rei.sut.ros_conventions import CMD_WAIT


def register(subparsers: argparse._SubParsersAction[Any]) -> None:
    """Add the `ros2-bridge` subcommand."""
    from rei.sut.ros2.environment import MAX_DOMAIN, RUN_DOMAINS

    parser = subparsers.add_parser(
        "ros2-bridge", help="play the robot to a ROS 2 navigation stack on DDS (used by --sut \"ros2:COMMAND\")",
        description=__doc__.split("\n\n", 1)[1] if __doc__ else None)
    parser.add_argument("--ros-home", type=Path, default=Path("ros"), metavar="DIR",
                        help="ROS_HOME of the stack: its logs (default ./ros)")
    parser.add_argument("--domain", type=_domain(MAX_DOMAIN), metavar="N",
                        help=f"ROS domain (default: the first of {RUN_DOMAINS.start}..{RUN_DOMAINS.stop - 1} that no "
                             "other run or ROS 2 participant on this machine uses; $ROS_DOMAIN_ID is not read)")
    parser.add_argument("--action", default="navigate_to_pose", metavar="NAME",
                        help="the NavigateToPose action's name (default navigate_to_pose)")
    parser.add_argument("--cmd-wait", type=float, default=CMD_WAIT, metavar="S",
                        help=f"wall seconds a tick waits for the stack's /cmd_vel (default {CMD_WAIT:g})")
    parser.add_argument("command", nargs=argparse.REMAINDER, metavar="-- COMMAND...",
                        help="the navigation stack to start (none: it is started by someone else)")
    parser.set_defaults(handler=run)


def _domain(maximum: int) -> Any:
    def parse(text: str) -> int:
        value = int(text)
        if not 0 <= value <= maximum:
            raise argparse.ArgumentTypeError(f"a DDS domain is 0..{maximum}, got {value}")
        return value
    return parse


def run(args: argparse.Namespace) -> int:
    from rei.cli.errors import CommandError

    try:
        import cyclonedds  # noqa: F401
    except ImportError:
        raise CommandError("the ROS 2 bridge needs Cyclone DDS's Python binding: pip install 'rei[ros2]' "
                           "(./rei installs it)") from None
    from rei.sut.ros2.bridge import Ros2BridgeSettings, main

    command = args.command[1:] if args.command[:1] == ["--"] else args.command
    settings = Ros2BridgeSettings(cmd_wait=args.cmd_wait, action=args.action, domain=args.domain)
    return main(command, ros_home=args.ros_home.resolve(), settings=settings)
