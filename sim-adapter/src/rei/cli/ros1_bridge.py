# SPDX-License-Identifier: EPL-2.0
"""`rei ros1-bridge [options] -- COMMAND...`: a ROS 1 navigation stack as REI's external SUT (docs/ros.md).

Started by `rei run CASE --sut "ros1:COMMAND"` with the environment of an external SUT; it starts a private ROS
master (or joins --ros-master), starts COMMAND with ROS_MASTER_URI set and plays the robot to it: /clock, /scan,
/odom, /tf, /map, /cmd_vel and the move_base action. Exit 0 at the run's end, 1 on a bug of the bridge, 2 when
ROS or the stack is missing or the stack exited.
"""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from rei.sut.ros_conventions import CMD_WAIT


def register(subparsers: argparse._SubParsersAction[Any]) -> None:
    """Add the `ros1-bridge` subcommand."""
    parser = subparsers.add_parser(
        "ros1-bridge", help="play the robot to a ROS 1 navigation stack (used by --sut \"ros1:COMMAND\")",
        description=__doc__.split("\n\n", 1)[1] if __doc__ else None)
    parser.add_argument("--ros-home", type=Path, default=Path("ros"), metavar="DIR",
                        help="ROS_HOME of the master and the stack: their logs (default ./ros)")
    parser.add_argument("--ros-master", metavar="URI", help="join this ROS master instead of starting one")
    parser.add_argument("--cmd-wait", type=float, default=CMD_WAIT, metavar="S",
                        help=f"wall seconds a tick waits for the stack's /cmd_vel (default {CMD_WAIT:g})")
    parser.add_argument("command", nargs=argparse.REMAINDER, metavar="-- COMMAND...",
                        help="the navigation stack to start (none: it is started by someone else)")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from rei.sut.ros1.bridge import BridgeSettings, main

    command = args.command[1:] if args.command[:1] == ["--"] else args.command
    return main(command, ros_home=args.ros_home.resolve(), master_uri=args.ros_master,
                settings=BridgeSettings(cmd_wait=args.cmd_wait))
