# SPDX-License-Identifier: EPL-2.0
"""`rei campaign SPEC.yaml -o OUT [--workers N | --ray ADDRESS]`: run many missions and summarize them.

The spec lists test cases or room-generator settings, variants (humans on/off, faults such as laser:1%, the
people's behaviour, a controller or an external SUT), repetitions and seeds (docs/campaigns.md). Runs go to worker processes on this machine (`--workers`, default:
one per core) or to a Ray cluster (`--ray ADDRESS`, or `--ray local` for a Ray instance started here). A run
that crashes or exceeds the spec's timeout is recorded as ERROR and the campaign goes on; an interrupted
campaign resumes where it stopped when started again with the same OUT. When the background service of `rei run`
runs already, the cases are generated and the runs replayed in its warm JVMs (`--no-service`: in the campaign's
own); a campaign never starts one. Writes OUT/summary.csv (the thesis's
Tables 5 and 7), OUT/runs.csv, OUT/metrics.csv (the navigation metrics per room and variant, docs/metrics.md) and
OUT/report.html. `--controller` runs every variant with that in-process controller instead of the spec's (the
same spec against another system under test); `--compare BASELINE` then compares the campaign with an earlier
one as `rei compare BASELINE OUT -o OUT/compare` does. Exit 0: every run completed (and no metric regressed);
1: some ended in ERROR, or a metric regressed; 2: bad spec or arguments, or a Ray cluster that cannot take the
runs; 3: this machine cannot run REI (no Java, or a jar this installation lacks: a wheel built without --jars cli,
say); 130: interrupted; 143: SIGTERM outside the runs (while the outputs are written, say), which stops what the
campaign started and exits at once.
"""

from __future__ import annotations

import argparse
import contextlib
import dataclasses
from pathlib import Path
from typing import Any

from rei.cli._case import prepare_output
from rei.cli._pool_options import add_pool_options, workers_of
from rei.cli.compare import add_compare_options, compare_and_report, load_thresholds_option
from rei.cli.errors import EXIT_INVALID, EXIT_OK, CommandError


def register(subparsers: argparse._SubParsersAction[Any]) -> None:
    """Add the `campaign` subcommand."""
    parser = subparsers.add_parser("campaign", help="run a campaign of missions in parallel and summarize it",
                                   description=__doc__.split("\n\n", 1)[1] if __doc__ else None)
    parser.add_argument("spec", type=Path, metavar="SPEC.yaml", help="campaign spec")
    add_pool_options(parser)
    parser.add_argument("--retry-errors", action="store_true", help="run again the runs that ended in ERROR")
    parser.add_argument("--no-service", action="store_true",
                        help="start the campaign's own JVMs even when the background service runs")
    parser.add_argument("--controller", metavar="NAME[:ARGS]",
                        help="run every variant with this in-process controller instead of the spec's controller "
                        "or sut (e.g. nav:inflation_margin=0, docs/sut.md)")
    parser.add_argument("--compare", type=Path, metavar="BASELINE",
                        help="then compare with the campaign in BASELINE (rei compare; output in OUT/compare)")
    add_compare_options(parser, output=False)
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from rei.lifetime import sigterm_unwinds

    # inside its run loop the runner takes the SystemExit as an interruption (outputs written, exit 130); elsewhere
    # (Ray starting, the summary and report written, --compare) it unwinds (exit 143) instead of killing the
    # process on the spot, so the finally blocks still stop the fork server and Ray and end the service's lease
    with sigterm_unwinds():
        return _run(args)


def _run(args: argparse.Namespace) -> int:
    from rei.campaign import LocalBackend, SpecError, load_spec, run_campaign

    workers = workers_of(args)
    try:
        spec = load_spec(args.spec)
    except SpecError as error:
        raise CommandError(error.problems) from None
    if args.controller:
        spec = _with_controller(spec, args.controller)
    thresholds = None
    if args.compare is not None:
        if not args.compare.is_dir():
            raise CommandError(f"--compare {args.compare}: no such campaign folder")
        thresholds = load_thresholds_option(args.thresholds)
    elif args.thresholds is not None:
        raise CommandError("--thresholds needs --compare BASELINE")
    prepare_output(args.output)  # -o naming a file was a traceback
    if args.ray:
        from rei.campaign.backends import RayUnavailableError, connect_ray
        from rei.campaign.spec import spec_moves_people

        try:
            # the nodes are checked for a router when the runs start one, for JuPedSim when they move people
            router = spec.mode == "pipeline" or any(
                variant.sut is not None for group in spec.groups for variant in group.variants)
            backend: Any = connect_ray(args.ray, workers, router=router, people=spec_moves_people(spec))
        except RayUnavailableError as error:
            raise CommandError(str(error).splitlines()) from None  # a line per node that cannot run REI
    service = None
    if not args.ray:
        from rei.service import SWITCH_ENV
        from rei.service.client import running

        service = None if args.no_service else running()
        if service is not None and service.monitor is None and service.cli is None:
            service = None  # both its JVMs are being replaced: nothing of it to use
        runs = args.output.resolve() / "runs"
        # mode: pipeline runs `rei run`, whose monitor is live: a warm JVM for replays would idle
        backend = LocalBackend(workers, monitor_log=runs / "monitor-server.log" if spec.mode == "replay" else None,
                               fork_log=runs / "forkserver.log",
                               monitor_server=service.monitor if service is not None else None,
                               # mode: pipeline runs `rei run`, which would use (or start) the service
                               worker_env={SWITCH_ENV: "off"} if args.no_service else None)
    try:
        with contextlib.ExitStack() as stack:
            if service is not None:
                from rei.service.client import Lease

                used = " and ".join(what for what, socket in (("generating", service.cli),
                                                                ("replaying", service.monitor)) if socket)
                print(f"campaign: {used} in the background service's warm JVMs (pid {service.pid}; "
                      "--no-service for the campaign's own)", flush=True)
                stack.enter_context(Lease(service))
            result = run_campaign(spec, args.output, backend, retry_errors=args.retry_errors, prepare_workers=workers,
                                  generator=service.cli if service is not None else None,
                                  helpers=(service.pid,) if service is not None else ())
    except SpecError as error:
        raise CommandError(error.problems) from None
    finally:
        backend.close()
    usage = result.metrics.get("campaign", {})
    print(f"{len(result.results)}/{result.planned} runs finished, {result.errors} in ERROR; {usage.get('wall', 0):.1f} s "
          f"wall, {usage.get('cpu', 0):.0f} s CPU ({100 * usage.get('cpu_utilisation', 0):.0f} % of "
          f"{usage.get('cores')} cores)")
    print(f"summary: {args.output / 'summary.csv'}")
    print(f"report:  {args.output / 'report.html'}")
    if result.interrupted:
        return 130
    code = EXIT_INVALID if result.errors or len(result.results) < result.planned else EXIT_OK
    if args.compare is not None:
        code = max(code, compare_and_report(args.compare, args.output, args.output / "compare", thresholds))
    return code


def _with_controller(spec: Any, controller: str) -> Any:
    """The spec with every variant run by ``controller`` (checked here, before any run)."""
    from rei.campaign.spec import anchored
    from rei.sut.registry import controller_problem

    controller = anchored(controller, Path.cwd())  # the runs build it in their own folders
    problem = controller_problem(controller)
    if problem is not None:
        raise CommandError(f"--controller {controller}: {problem}")
    groups = tuple(dataclasses.replace(g, variants=tuple(dataclasses.replace(v, controller=controller, sut=None)
                                                          for v in g.variants)) for g in spec.groups)
    return dataclasses.replace(spec, groups=groups)
