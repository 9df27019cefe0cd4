# SPDX-License-Identifier: EPL-2.0
"""The options of a mission run, shared by `rei sim` (which uses them) and `rei run` (which passes them on)."""

from __future__ import annotations

import argparse
import dataclasses
import json
from pathlib import Path
from typing import TYPE_CHECKING

from rei.cli.errors import CommandError
from rei.sut.external.options import DEFAULT_DEADLINE, DEFAULT_JOIN_TIMEOUT, SutOptions

if TYPE_CHECKING:  # imported where needed: it pulls in numpy and the mission's modules (check_mission_options)
    from rei.wamp.collector import CollectorConfig


def add_mission_options(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--controller", default="nav", metavar="SPEC",
                        help="controller under test: nav, nav:key=value,..., script:FILE or a plug-in (default nav)")
    parser.add_argument("--seed", type=int, default=0, help="seed of every random choice (default 0)")
    parser.add_argument("--no-humans", action="store_true", help="leave the humans out of the world")
    parser.add_argument("--fault", metavar="SPEC", help="faults besides the test case's, ';' between two: "
                        "SENSOR:KIND,key=value,... (the laser's, odometry's, drive's, commands' and pose's kinds "
                        "and keys in docs/faults.md) and from=, to= (s), period= with pulse= or duty= (e.g. "
                        "laser:blackout,from=5,to=7; commands:loss,probability=0.3,from=2); the "
                        "run-long impulse noise laser:1%%, laser:10%% or laser:rate=0.01,gain=0.5,width=3; the "
                        "thesis's gated laser:gated-1%%, laser:gated-10%% (docs/faults.md)")
    parser.add_argument("--animation", choices=("velocity", "force"), default="velocity",
                        help="how humans and moving objects follow their trajectories: velocity (default) sets "
                        "their velocity each step; force pushes them with F = m dv/dt through the contact solver, "
                        "so what stands in their way (the robot) is pushed and pushes back (people who see the robot "
                        "are put where their model puts them either way)")
    parser.add_argument("--realtime", action="store_true", help="pace the simulation at wall-clock speed")
    parser.add_argument("--state-rate", type=float, metavar="HZ",
                        help="state messages per simulated second (default 20, or the --collector file's)")
    parser.add_argument("--laser", choices=("min", "full", "none"),
                        help="laser data in state messages: the minimum only (default), every range, or none")
    parser.add_argument("--collector", type=Path, metavar="FILE",
                        help="the data collector's settings (YAML: rate_hz, laser, contacts, odometry, nav_state, "
                        "full_frame_period, objects; docs/protocol.md); --state-rate and --laser override them")
    sut = parser.add_argument_group("external system under test (docs/sut.md)")
    how = sut.add_mutually_exclusive_group()
    how.add_argument("--sut", metavar="COMMAND", help="start COMMAND as the system under test (instead of "
                     "--controller); it connects to the run's router from the environment REI gives it")
    how.add_argument("--sut-attach", action="store_true",
                     help="wait for a system under test you start yourself (connection details in OUT/sut.env)")
    sut.add_argument("--sut-clock", choices=("lockstep", "realtime"), default="lockstep",
                     help="lockstep (default): each control period waits for the SUT's command; realtime: the "
                     "simulation keeps to the wall clock and applies commands when they arrive")
    sut.add_argument("--sut-deadline", type=float, default=DEFAULT_DEADLINE, metavar="S",
                     help=f"seconds the SUT may take to answer a tick (realtime: to say anything) before the run "
                     f"is an ERROR (default {DEFAULT_DEADLINE:g})")
    sut.add_argument("--sut-map", action="store_true", help="offer the static map to the SUT")
    sut.add_argument("--sut-join-timeout", type=float, default=DEFAULT_JOIN_TIMEOUT, metavar="S",
                     help=f"seconds the SUT has to join (default {DEFAULT_JOIN_TIMEOUT:g})")


def check_mission_options(args: argparse.Namespace) -> None:
    """Refuse a bad controller or fault before any process starts.

    The defaults need no check, nor the modules a check imports (numpy, the artifacts', pybullet with a fault):
    `rei run` takes its router over and starts its simulation right after this."""
    sut_options(args)
    if args.fault or args.controller != "nav":
        _check_controller_and_faults(args)
    if args.state_rate is not None and not args.state_rate > 0:
        raise CommandError(f"--state-rate must be positive, got {args.state_rate}")
    if args.collector is not None or args.laser is not None:
        collector_config(args)


def _check_controller_and_faults(args: argparse.Namespace) -> None:
    from rei.sut.registry import UnknownControllerError, create_controller

    try:
        if args.fault:
            from rei.run.mission_run import MissionRunOptions
            from rei.sim.faults import parse_faults

            # a command latency must be whole control periods at the rate the run will have
            parse_faults(args.fault).commands([], MissionRunOptions().control_rate)
        create_controller(args.controller)
    except (ValueError, UnknownControllerError) as error:
        raise CommandError(str(error)) from None


def collector_config(args: argparse.Namespace) -> CollectorConfig:
    """The collector's settings: the --collector file's (or the defaults), then --state-rate and --laser."""
    from rei.wamp.codec import LaserMode
    from rei.wamp.collector import CollectorConfig
    from rei.wamp.collector_settings import CollectorSettingsError, load_collector_settings

    try:
        config = load_collector_settings(args.collector) if args.collector is not None else CollectorConfig()
    except CollectorSettingsError as error:
        raise CommandError(str(error)) from None
    if args.state_rate is not None:
        config = dataclasses.replace(config, rate_hz=args.state_rate)
    if args.laser is not None:
        config = dataclasses.replace(config, laser=LaserMode(args.laser))
    return config


def check_collector_objects(args: argparse.Namespace, case_dir: Path) -> None:
    """The collector's ``objects`` name moving objects or categories of the generated case (CommandError if not)."""
    config = collector_config(args)
    if config.objects is None:
        return
    try:
        config.observed(json.loads((case_dir / "world.json").read_text(encoding="utf-8")))
    except (OSError, ValueError) as error:
        raise CommandError(f"{args.collector}: {error}") from None


def check_case_faults(args: argparse.Namespace, case_dir: Path) -> None:
    """The generated case's faults, with --fault's, are ones the run can have (CommandError, exit 2, if not): what
    the simulation would refuse once the monitor runs (rei.run.mission_run.check_faults) is refused before."""
    from rei.artifacts import ArtifactError, read_mission

    try:
        if not args.fault and not read_mission(case_dir / "mission.xml").faults:
            return  # nothing to check: the simulation's modules stay unloaded
        from rei.artifacts import read_case
        from rei.run.mission_run import MissionRunOptions, check_faults

        check_faults(read_case(case_dir), MissionRunOptions(fault=args.fault))
    except ArtifactError as error:
        raise CommandError(str(error)) from None


def sut_options(args: argparse.Namespace, *, router_url: str | None = None,
                auth_file: Path | None = None) -> SutOptions | None:
    """The external SUT the arguments ask for (None: the in-process --controller); CommandError if wrong."""
    from rei.sut.external.process import SutLaunchError, check_command

    wanted = args.sut is not None or args.sut_attach
    if not wanted:
        if (args.sut_map or args.sut_clock != "lockstep" or args.sut_deadline != DEFAULT_DEADLINE
                or args.sut_join_timeout != DEFAULT_JOIN_TIMEOUT):
            raise CommandError("--sut-map, --sut-clock, --sut-deadline and --sut-join-timeout apply with "
                               "--sut COMMAND or --sut-attach only")
        return None
    if args.controller != "nav":
        raise CommandError("--controller is the in-process system under test; --sut/--sut-attach replace it")
    try:
        if args.sut is not None:
            check_command(args.sut)
        return SutOptions(command=args.sut, attach=args.sut_attach, clock=args.sut_clock,
                          deadline=args.sut_deadline, offer_map=args.sut_map, join_timeout=args.sut_join_timeout,
                          router_url=router_url, auth_file=auth_file)
    except (ValueError, SutLaunchError) as error:
        raise CommandError(str(error)) from None


def mission_argv(args: argparse.Namespace) -> list[str]:
    """The same options as arguments for a `rei sim` child process."""
    argv = ["--controller", args.controller, "--seed", str(args.seed)]
    if args.state_rate is not None:
        argv += ["--state-rate", str(args.state_rate)]
    if args.laser is not None:
        argv += ["--laser", args.laser]
    if args.collector is not None:
        argv += ["--collector", str(args.collector.resolve())]
    if args.no_humans:
        argv.append("--no-humans")
    if args.fault:
        argv += ["--fault", args.fault]
    if args.realtime:
        argv.append("--realtime")
    if args.animation != "velocity":
        argv += ["--animation", args.animation]
    if args.sut is not None:
        argv += ["--sut", args.sut]
    if args.sut_attach:
        argv.append("--sut-attach")
    if args.sut is not None or args.sut_attach:
        argv += ["--sut-clock", args.sut_clock, "--sut-deadline", str(args.sut_deadline),
                 "--sut-join-timeout", str(args.sut_join_timeout)] + (["--sut-map"] if args.sut_map else [])
    return argv
