# SPDX-License-Identifier: EPL-2.0
"""`rei run CASE -o OUT`: generate, start the router, the monitor and the simulation, evaluate, report.

Exit 0: every verdict passes; 1: a verdict fails; 2: an error (a part died, the run was interrupted, bad
arguments, patterns that do not compile). OUT gets events.csv, summary.json, verdicts.xml, the recorded streams
(streams/), the monitor's model (runtime.xmi), what its patterns declare (utilities.json), a copy of the user's
patterns (patterns/) and queries (queries/) and each part's log.
"""

from __future__ import annotations

import argparse
import secrets
import sys
from pathlib import Path
from typing import TYPE_CHECKING, Any

from rei.cli._case import case_folder, prepare_output, valid_run_id
from rei.cli._mission_options import (
    add_mission_options,
    check_collector_objects,
    check_mission_options,
    collector_config,
    mission_argv,
)
from rei.cli._outcome import print_verdicts, write_views
from rei.cli._router_options import add_router_options, check_router_options
from rei.cli.errors import CommandError

if TYPE_CHECKING:
    from rei.run.patterns import PatternSelection


def register(subparsers: argparse._SubParsersAction[Any]) -> None:
    """Add the `run` subcommand."""
    parser = subparsers.add_parser(
        "run", help="run a test case through the whole pipeline and judge it",
        description=__doc__.split("\n\n", 1)[1] if __doc__ else None)
    parser.add_argument("case", metavar="CASE", help="a .rei test case or a folder generated from one")
    parser.add_argument("-o", "--output", required=True, metavar="OUT", help="output folder")
    add_mission_options(parser)
    parser.add_argument("--utilities", metavar="YAML", type=Path,
                        help="utility per signal, overriding the patterns' and the defaults of thesis Table 3")
    parser.add_argument("--patterns", metavar="DIR", type=Path,
                        help="the *.vepl of DIR: temporal patterns the monitor runs besides the default ones "
                        "(docs/vepl.md); checked before the run, kept in OUT/patterns/")
    parser.add_argument("--no-default-patterns", action="store_true",
                        help="with --patterns: only the patterns of DIR")
    parser.add_argument("--queries", metavar="DIR", type=Path,
                        help="the *.drl of DIR: queries over the monitor's runtime model that --patterns may name "
                        "(docs/monitor.md); checked before the run, kept in OUT/queries/")
    parser.add_argument("--run-id", metavar="ID", help="identifier of the run in topic names (default: random)")
    parser.add_argument("--view", action="store_true",
                        help="watch the run live in the browser: serves a page on 127.0.0.1 and prints its URL")
    add_router_options(parser, "run")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from rei.run.pipeline import PipelineOptions, Progress, run_pipeline

    check_mission_options(args)
    check_router_options(args)
    patterns, declared = _check_patterns(args)
    if args.utilities is not None:
        from rei.evaluation import UtilityError, load_utilities

        try:
            load_utilities(args.utilities, declared)  # it may name the signals of the user's patterns
        except UtilityError as error:
            raise CommandError(str(error)) from None
    run_id = args.run_id or secrets.token_hex(6)
    if not valid_run_id(run_id):
        raise CommandError(f"--run-id {run_id!r}: expected letters, digits, '_' or '-'")
    out = Path(args.output).resolve()  # children and the router run in other working directories
    prepare_output(out)
    case_dir = case_folder(Path(args.case), out)
    check_collector_objects(args, case_dir)

    def show(progress: Progress) -> None:
        if sys.stderr.isatty():
            print(f"\rsim {progress.sim_time:7.1f} s  tasks {progress.tasks_done}/{progress.tasks}  "
                  f"utility {progress.utility:+.0f}   ", end="", file=sys.stderr, flush=True)

    options = PipelineOptions(sim_args=tuple(mission_argv(args)), external_sut=args.sut is not None or args.sut_attach,
                              utilities=args.utilities,
                              humans=not args.no_humans, laser=collector_config(args).laser.value != "none", view=args.view,
                              bind=args.bind, tls_cert=_path(args.tls_cert), tls_key=_path(args.tls_key),
                              patterns=patterns, declared=declared)
    result = run_pipeline(case_dir, out, options,
                          run_id=run_id, on_progress=show)
    if sys.stderr.isatty():
        print(file=sys.stderr)
    print_verdicts(result.summary)
    write_views(out)
    return result.exit_code


def _check_patterns(args: argparse.Namespace) -> tuple[PatternSelection, dict[str, float | None] | None]:
    """The monitor's patterns, compiled now so a bad one fails before anything starts (with file:line:column);
    with them, what they declare (None for the defaults only, which need no check)."""
    from rei.run.patterns import PatternError, PatternSelection, check

    if args.patterns is None and args.no_default_patterns:
        raise CommandError("--no-default-patterns needs --patterns DIR")
    if args.patterns is None and args.queries is None:
        return PatternSelection(), None
    selection = PatternSelection(args.patterns.resolve() if args.patterns is not None else None,
                                 defaults=not args.no_default_patterns,
                                 queries=args.queries.resolve() if args.queries is not None else None)
    try:
        return selection, check(selection)
    except PatternError as error:
        raise CommandError(str(error)) from None


def _path(value: str | None) -> Path | None:
    return Path(value).resolve() if value is not None else None
