# SPDX-License-Identifier: EPL-2.0
"""The options of a mission run, shared by `rei sim` (which uses them) and `rei run` (which passes them on)."""

from __future__ import annotations

import argparse

from rei.cli.errors import CommandError


def add_mission_options(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--controller", default="nav", metavar="SPEC",
                        help="controller under test: nav, nav:key=value,..., script:FILE or a plug-in (default nav)")
    parser.add_argument("--seed", type=int, default=0, help="seed of every random choice (default 0)")
    parser.add_argument("--no-humans", action="store_true", help="leave the humans out of the world")
    parser.add_argument("--fault", metavar="SPEC", help="inject a fault, e.g. laser:1%%, laser:10%% or "
                        "laser:rate=0.01,gain=0.5,width=3")
    parser.add_argument("--realtime", action="store_true", help="pace the simulation at wall-clock speed")
    parser.add_argument("--state-rate", type=float, default=20.0, metavar="HZ",
                        help="state messages per simulated second (default 20)")
    parser.add_argument("--laser", choices=("min", "full", "none"), default="min",
                        help="laser data in state messages: the minimum only (default), every range, or none")


def check_mission_options(args: argparse.Namespace) -> None:
    """Refuse a bad controller or fault before any process starts."""
    from rei.sim.faults import parse_fault
    from rei.sut.registry import UnknownControllerError, create_controller

    try:
        if args.fault:
            parse_fault(args.fault)
        create_controller(args.controller)
    except (ValueError, UnknownControllerError) as error:
        raise CommandError(str(error)) from None
    if not args.state_rate > 0:
        raise CommandError(f"--state-rate must be positive, got {args.state_rate}")


def mission_argv(args: argparse.Namespace) -> list[str]:
    """The same options as arguments for a `rei sim` child process."""
    argv = ["--controller", args.controller, "--seed", str(args.seed), "--state-rate", str(args.state_rate),
            "--laser", args.laser]
    if args.no_humans:
        argv.append("--no-humans")
    if args.fault:
        argv += ["--fault", args.fault]
    if args.realtime:
        argv.append("--realtime")
    return argv
