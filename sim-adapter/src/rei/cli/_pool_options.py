# SPDX-License-Identifier: EPL-2.0
"""The options of the commands that run many missions on workers (`rei campaign`, `rei search`): the output
folder, local workers or a Ray cluster."""

from __future__ import annotations

import argparse
import os
from pathlib import Path

from rei.cli.errors import CommandError


def add_pool_options(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("-o", "--output", required=True, type=Path, metavar="OUT", help="output folder")
    parser.add_argument("--workers", type=int, metavar="N",
                        help=f"runs at a time on this machine (default: the number of cores, {os.cpu_count()})")
    parser.add_argument("--ray", metavar="ADDRESS", help="run on a Ray cluster (HOST:PORT, or 'local')")


def workers_of(args: argparse.Namespace) -> int:
    """``--workers``, by default the number of cores; refused below 1 before anything starts."""
    # 0 is refused like any count below 1, not taken as the default (it is only when the option is absent)
    workers: int = (os.cpu_count() or 1) if args.workers is None else args.workers
    if workers < 1:
        raise CommandError(f"--workers must be at least 1, got {workers}")
    return workers
