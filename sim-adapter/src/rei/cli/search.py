# SPDX-License-Identifier: EPL-2.0
"""`rei search SPEC.yaml -o OUT [--workers N | --ray ADDRESS] [--budget N] [--sampler S]`: find the situations
that break the robot.

The spec names a base case (a .rei file, or room settings as in campaign specs: generated into OUT/base/), the
SUT, what may change (objects' floors and yaw, extra furniture, humans' paths and timing, people's behaviour, a
crowd's or group's size and rate, the robot's start, goals, the seed, a fault of the laser, odometry, drive, commands
or pose) and what counts as worse (utility, time, navigation metrics, a requirement's verdict, a signal):
docs/search.md. Candidates are the base case edited by the room
editor's engine and checked by the language's validators and the navigability check; valid ones run on the
campaign's workers (or Ray) while Optuna's sampler (tpe, cmaes, nsga2, qmc, or random as a baseline) picks the
next. Each distinct failure is then shrunk to a smaller case that fails the same way. Writes OUT/search.json,
OUT/verdicts.xml, OUT/search.html, every candidate as OUT/candidates/*.rei and its run in OUT/runs/. A stopped
search resumes when started again with the same OUT. Exit 0: no failure found; 1: failures found; 2: bad spec
or arguments, the room editor's engine failed (the search stops), or no failure found but evaluations in ERROR (or
none simulated), or a Ray cluster that cannot take the runs; 3: this machine cannot run REI (no Java, or a jar
this installation lacks: a wheel built without --jars cli,monitor,room-editor, say); 130: interrupted (Ctrl-C);
143: stopped by SIGTERM.
"""

from __future__ import annotations

import argparse
import threading
from pathlib import Path
from typing import Any

from rei.cli._case import prepare_output
from rei.cli._pool_options import add_pool_options, workers_of
from rei.cli.errors import EXIT_OK, EXIT_RUN_ERROR, CommandError

EXIT_FOUND = 1


def register(subparsers: argparse._SubParsersAction[Any]) -> None:
    """Add the `search` subcommand."""
    from rei.search import SAMPLERS

    parser = subparsers.add_parser("search", help="search for situations that make the robot fail (falsification)",
                                   description=__doc__.split("\n\n", 1)[1] if __doc__ else None)
    parser.add_argument("spec", type=Path, metavar="SPEC.yaml", help="search spec")
    add_pool_options(parser)
    parser.add_argument("--budget", type=int, metavar="N", help="simulated evaluations (default: the spec's)")
    parser.add_argument("--sampler", choices=SAMPLERS, help="the optimizer (default: the spec's, else tpe)")
    parser.add_argument("--no-shrink", action="store_true", help="do not shrink the failures found")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from rei.campaign.backends import RayUnavailableError
    from rei.campaign.spec import SpecError
    from rei.edit import EngineError
    from rei.lifetime import sigterm_unwinds
    from rei.search.base import with_base_case_problems
    from rei.search.run import run_search
    from rei.search.spec import load_search_spec
    from rei.search.study import check_resume

    workers = workers_of(args)
    if args.budget is not None and args.budget < 1:
        raise CommandError(f"--budget must be at least 1, got {args.budget}")
    try:
        spec = load_search_spec(args.spec)
    except SpecError as error:  # with what its base case finds: every mistake at once
        raise CommandError(with_base_case_problems(error).problems) from None
    try:
        spec = spec.with_options(budget=args.budget, sampler=args.sampler)
        check_resume(spec, args.output.resolve())  # before a Ray cluster is reached or a room generated
    except SpecError as error:
        raise CommandError(error.problems) from None
    prepare_output(args.output)  # -o naming a file was a traceback
    stop = threading.Event()
    try:
        # SIGTERM unwinds (SystemExit) wherever it lands: the search then stops as on Ctrl-C, and during shrinking
        # or the outputs run_search's finally still stops the workers and the fork server (their own sessions)
        with sigterm_unwinds():
            result = run_search(spec, args.output, workers=workers, ray=args.ray, stop=stop,
                                shrink_failures=not args.no_shrink)
    except SpecError as error:
        raise CommandError(error.problems) from None
    except RayUnavailableError as error:
        raise CommandError(str(error).splitlines()) from None  # a line per node that cannot run REI
    except EngineError as error:
        # the engine broke, not the candidate: no candidate is told invalid for it, and the one it was making is
        # asked again when the search resumes
        raise CommandError(f"search stopped: {error}; finished evaluations are kept: fix the room editor's engine "
                           f"(rebuild rei-room-editor.jar) and run the same command to resume",
                           EXIT_RUN_ERROR) from None
    counts = result["counts"]
    print(f"{counts['simulated']} evaluations ({counts['errors']} in ERROR), {counts['invalid']} invalid and "
          f"{counts['unplannable']} unplannable candidates not simulated; {counts['failing']} failing, "
          f"{counts['distinct_failures']} distinct failure(s)")
    for failure in result["failures"]:
        shrunk = failure.get("shrunk") or {}
        print(f"  {failure['signature']} ({', '.join(failure['requirements'])}): {len(failure['evaluations'])} "
              f"evaluation(s), worst utility "
              f"{failure['worst_utility']:g}; case {shrunk.get('case') or failure['case']}")
    print(f"report:  {args.output / 'search.html'}")
    if result.get("interrupted"):  # the exit status the stop calls for: 130 after Ctrl-C, 143 after SIGTERM
        return int(result["interrupted"])
    if result["failures"]:
        return EXIT_FOUND
    # nothing found, but evaluations that could not be judged (or none at all) vouch for nothing
    return EXIT_RUN_ERROR if counts["errors"] or not counts["simulated"] else EXIT_OK
