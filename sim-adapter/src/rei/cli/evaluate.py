# SPDX-License-Identifier: EPL-2.0
"""`rei evaluate OUT`: judge a run again from the streams it recorded, without simulator or router.

The recorded state and mission streams (OUT/streams/) go through the monitor jar's replay, and the evaluator
writes events.csv, summary.json, verdicts.xml, report.html and run.mcap anew; the first live event log is kept
as events-live.csv. The replay runs the patterns the run kept (OUT/patterns/, from `rei run --patterns`). For a
run whose live judgement was spoiled (the monitor died, the router restarted and lost messages), or to judge it
with other utilities. Exit codes as `rei run`.
"""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from rei.cli._outcome import print_verdicts, write_views
from rei.cli.errors import EXIT_USAGE, CommandError


def register(subparsers: argparse._SubParsersAction[Any]) -> None:
    """Add the `evaluate` subcommand."""
    parser = subparsers.add_parser("evaluate", help="judge a run again from its recorded streams",
                                   description=__doc__.split("\n\n", 1)[1] if __doc__ else None)
    parser.add_argument("out", metavar="OUT", type=Path, help="the run folder (with streams/ and case/)")
    parser.add_argument("--case", metavar="DIR", type=Path, help="generated case folder (default: OUT/case)")
    parser.add_argument("--utilities", metavar="YAML", type=Path,
                        help="utility per signal, overriding the patterns' and the defaults of thesis Table 3")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from rei.evaluation import UtilityError, load_declared_utilities, load_utilities
    from rei.run.patterns import UTILITIES_FILE
    from rei.run.reevaluate import ReevaluationError, reevaluate

    out: Path = args.out.resolve()
    if not out.is_dir():
        raise CommandError(f"{out}: no such run folder", EXIT_USAGE)
    if args.utilities is not None:
        try:  # checked before the replay; the run's patterns may declare the signals it names
            recorded = out / UTILITIES_FILE
            load_utilities(args.utilities, load_declared_utilities(recorded) if recorded.is_file() else None)
        except UtilityError as error:
            raise CommandError(error.problems) from None
    from rei.service.client import running_monitor

    try:  # in the background service's warm monitor JVM when one runs (docs/performance.md)
        judged = reevaluate(out, args.case.resolve() if args.case else None, utilities=args.utilities,
                            notes=("re-evaluated from the recorded streams (rei evaluate)",),
                            monitor_server=running_monitor())
    except ReevaluationError as error:
        raise CommandError(str(error)) from None
    print_verdicts(judged.summary)
    write_views(out)
    return int(judged.summary.exit_code)
