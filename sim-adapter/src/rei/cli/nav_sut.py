# SPDX-License-Identifier: EPL-2.0
"""`rei nav-sut [SPEC]`: one of REI's in-process controllers as an external system under test (docs/sut.md).

It joins the run from the environment `rei run --sut "rei nav-sut"` gives it (REI_ROUTER_URL, REI_RUN_ID,
REI_AUTH_FILE) and drives the robot over the router exactly as the in-process controller would: with the same
seed, `rei run CASE --sut "rei nav-sut" --sut-map` records the same streams as `rei run CASE`. SPEC is a
controller as for --controller (default nav). Exit 0 at the run's end; 1 if the controller raised; 2 if the run
could not be joined or was lost.
"""

from __future__ import annotations

import argparse
from typing import Any


def register(subparsers: argparse._SubParsersAction[Any]) -> None:
    """Add the `nav-sut` subcommand."""
    parser = subparsers.add_parser(
        "nav-sut", help="run the reference navigation (or another built-in controller) as an external SUT",
        description=__doc__.split("\n\n", 1)[1] if __doc__ else None)
    parser.add_argument("spec", nargs="?", default="nav", metavar="SPEC",
                        help="nav, nav:key=value,..., script:FILE or a plug-in (default nav)")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from rei.cli.errors import CommandError
    from rei.sut.client import ControllerSut, main
    from rei.sut.nav import NavController
    from rei.sut.registry import UnknownControllerError, create_controller

    try:
        controller = create_controller(args.spec)
    except (ValueError, UnknownControllerError) as error:
        raise CommandError(str(error)) from None
    main(ControllerSut(controller, needs_map=isinstance(controller, NavController)), name=f"rei nav-sut {args.spec}")
