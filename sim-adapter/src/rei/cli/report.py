# SPDX-License-Identifier: EPL-2.0
"""`rei report OUT`: write report.html and run.mcap (Foxglove) for a finished run folder."""

from __future__ import annotations

import argparse
from typing import Any


def register(subparsers: argparse._SubParsersAction[Any]) -> None:
    """Add the `report` subcommand."""
    from rei.report.__main__ import add_arguments

    parser = subparsers.add_parser("report", help="write report.html and run.mcap for a run folder",
                                   description=__doc__)
    add_arguments(parser)
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from rei.report.__main__ import main

    return main(args.out, args.case)
