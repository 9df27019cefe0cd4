# SPDX-License-Identifier: EPL-2.0
"""`rei run CASE -o OUT`: generate, start the router, the monitor and the simulation, evaluate, report.

Exit 0: every verdict passes; 1: a verdict fails; 2: an error (a part died, the run was interrupted, bad
arguments). OUT gets events.csv, summary.json, verdicts.xml, the recorded streams (streams/), the monitor's
model (runtime.xmi) and each part's log.
"""

from __future__ import annotations

import argparse
import secrets
import sys
from pathlib import Path
from typing import Any

from rei.cli._case import case_folder, prepare_output, valid_run_id
from rei.cli._mission_options import add_mission_options, check_mission_options, mission_argv
from rei.cli.errors import CommandError


def register(subparsers: argparse._SubParsersAction[Any]) -> None:
    """Add the `run` subcommand."""
    parser = subparsers.add_parser(
        "run", help="run a test case through the whole pipeline and judge it",
        description=__doc__.split("\n\n", 1)[1] if __doc__ else None)
    parser.add_argument("case", metavar="CASE", help="a .rei test case or a folder generated from one")
    parser.add_argument("-o", "--output", required=True, metavar="OUT", help="output folder")
    add_mission_options(parser)
    parser.add_argument("--utilities", metavar="YAML", type=Path,
                        help="utility per signal, overriding the defaults of thesis Table 3")
    parser.add_argument("--run-id", metavar="ID", help="identifier of the run in topic names (default: random)")
    parser.add_argument("--view", action="store_true",
                        help="watch the run live in the browser: serves a page on 127.0.0.1 and prints its URL")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from rei.run.pipeline import PipelineOptions, Progress, run_pipeline

    check_mission_options(args)
    if args.utilities is not None:
        from rei.evaluation import UtilityError, load_utilities

        try:
            load_utilities(args.utilities)
        except UtilityError as error:
            raise CommandError(str(error)) from None
    run_id = args.run_id or secrets.token_hex(6)
    if not valid_run_id(run_id):
        raise CommandError(f"--run-id {run_id!r}: expected letters, digits, '_' or '-'")
    out = Path(args.output).resolve()  # children and the router run in other working directories
    prepare_output(out)
    case_dir = case_folder(Path(args.case), out)

    def show(progress: Progress) -> None:
        if sys.stderr.isatty():
            print(f"\rsim {progress.sim_time:7.1f} s  tasks {progress.tasks_done}/{progress.tasks}  "
                  f"utility {progress.utility:+.0f}   ", end="", file=sys.stderr, flush=True)

    options = PipelineOptions(sim_args=tuple(mission_argv(args)), utilities=args.utilities,
                              humans=not args.no_humans, laser=args.laser != "none", view=args.view)
    result = run_pipeline(case_dir, out, options,
                          run_id=run_id, on_progress=show)
    if sys.stderr.isatty():
        print(file=sys.stderr)
    summary = result.summary
    for verdict in summary.verdicts:
        print(f"{verdict.status.upper():<15} {verdict.requirement}  {verdict.message}")
    if result.status != "COMPLETED":
        print(f"run {run_id} ended in ERROR: {result.reason}")
    print(f"total utility {summary.total_utility:+g}")
    _write_views(out)
    return result.exit_code


def _write_views(out: Path) -> None:
    """The report and the Foxglove recording; a failure here must not hide the verdicts above."""
    from rei.report import write_mcap, write_report

    try:
        print(f"report: {write_report(out)}")
        print(f"mcap:   {write_mcap(out)} (open in Foxglove Studio)")
    except Exception as error:  # noqa: BLE001 - the run's results are already written
        print(f"rei: no report: {type(error).__name__}: {error}", file=sys.stderr)
