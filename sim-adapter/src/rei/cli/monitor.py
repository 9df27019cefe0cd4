# SPDX-License-Identifier: EPL-2.0
"""`rei monitor --replay OUT`: feed a run's recorded state and mission streams through the monitor again.

Prints one line per signal (``seq t signal subject object distance``), the same signals the live run produced;
for re-checking a run with other rules or after a monitor change, without a simulator or a router. A run folder
made with ``rei run --patterns DIR --queries DIR`` is replayed with the patterns and queries it kept
(``OUT/patterns/``, ``OUT/queries/``); ``--patterns``/``--queries`` replay it with others instead.
"""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from rei import toolchain
from rei.cli.errors import EXIT_USAGE, CommandError


def register(subparsers: argparse._SubParsersAction[Any]) -> None:
    """Add the `monitor` subcommand."""
    parser = subparsers.add_parser("monitor", help="replay a run's recorded streams through the monitor",
                                   description=__doc__.split("\n\n", 1)[1] if __doc__ else None)
    parser.add_argument("--replay", required=True, metavar="OUT", type=Path,
                        help="a run folder (with streams/ and case/) or a state.msgpack recording")
    parser.add_argument("--case", metavar="DIR", type=Path,
                        help="generated case folder (default: OUT/case, else the case OUT/sim.json names)")
    parser.add_argument("--patterns", metavar="DIR", type=Path,
                        help="the *.vepl of DIR beside the default patterns, instead of the run's own")
    parser.add_argument("--queries", metavar="DIR", type=Path,
                        help="the *.drl of DIR beside the packaged queries, instead of the run's own")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from rei.run.patterns import PatternSelection
    from rei.run.reevaluate import case_of_run

    replay: Path = args.replay
    if not replay.exists():
        raise CommandError(f"{replay}: no such run folder or recording", EXIT_USAGE)
    case = args.case or (case_of_run(replay) if replay.is_dir() else None)
    if case is None or not (case / "world.json").is_file():
        expected = f"{case}/world.json" if case is not None else f"{replay}/case/world.json or a case named in sim.json"
        raise CommandError(f"no generated case found (expected {expected}); give --case DIR")

    patterns = PatternSelection.recorded(replay) if replay.is_dir() else PatternSelection()
    if args.patterns is not None or args.queries is not None:
        from rei.run.patterns import PatternError, check

        patterns = PatternSelection(args.patterns.resolve() if args.patterns is not None else None,
                                    queries=args.queries.resolve() if args.queries is not None else None)
        try:
            check(patterns)
        except PatternError as error:
            raise CommandError(str(error)) from None
    java = toolchain.find_java()
    return toolchain.run_jar(toolchain.find_jar("monitor"),
                             ["--replay", str(replay), "--case", str(case), *patterns.monitor_args()], java=java)
