# SPDX-License-Identifier: EPL-2.0
"""`rei run CASE -o OUT`: generate, start the router, the monitor and the simulation, evaluate, report.

Exit 0: every verdict passes; 1: a verdict fails; 2: an error (a part died, the run was interrupted, bad
arguments, patterns that do not compile). OUT gets events.csv, summary.json, verdicts.xml, the recorded streams
(streams/), the monitor's model (runtime.xmi), what its patterns declare (utilities.json), a copy of the user's
patterns (patterns/) and queries (queries/) and each part's log.
"""

from __future__ import annotations

import argparse
import dataclasses
import os
import secrets
import shutil
import sys
import threading
from collections.abc import Callable
from concurrent.futures import Future
from pathlib import Path
from typing import TYPE_CHECKING, Any, Self

from rei.cli._case import case_folder, case_target, prepare_output, valid_run_id
from rei.cli._mission_options import (
    add_mission_options,
    check_case_faults,
    check_collector_objects,
    check_mission_options,
    collector_config,
    mission_argv,
)
from rei.cli._outcome import print_verdicts, write_views
from rei.cli._router_options import add_router_options, check_router_options
from rei.cli.errors import CommandError
from rei.lifetime import skip_exit_collection

if TYPE_CHECKING:
    from rei.run.held import HeldSimulation
    from rei.run.patterns import PatternSelection
    from rei.run.pipeline import PipelineOptions
    from rei.wamp.router import Router

#: Seconds a run waits for the background service's spare router (it is being started after the last run took
#: the previous one); starting one of its own would take as long and compete for the CPU.
ROUTER_WAIT = 20.0


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
    parser.add_argument("--no-service", action="store_true",
                        help="start this run's own router and JVMs instead of using the background service that "
                        "keeps them ready between runs (docs/performance.md; also REI_SERVICE=off)")
    parser.add_argument("--view", action="store_true",
                        help="watch the run live in the browser: serves a page on 127.0.0.1 and prints its URL")
    add_router_options(parser, "run")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    skip_exit_collection()  # the user waits for this process's exit
    check_mission_options(args)
    check_router_options(args)
    patterns, declared = _check_patterns(args)
    if args.utilities is not None:
        from rei.evaluation import UtilityError, load_utilities

        try:
            load_utilities(args.utilities, declared)  # it may name the signals of the user's patterns
        except UtilityError as error:
            raise CommandError(error.problems) from None
    if args.run_id is not None and not valid_run_id(args.run_id):
        raise CommandError(f"--run-id {args.run_id!r}: expected letters, digits, '_' or '-'")
    out = Path(args.output).resolve()  # children and the router run in other working directories
    prepare_output(out)
    # the run's own modules load while the case is generated and the router taken over (both wait on sockets)
    threading.Thread(target=_import_run_modules, name="rei-imports", daemon=True).start()
    sim_args, external_sut = tuple(mission_argv(args)), args.sut is not None or args.sut_attach
    target = case_target(Path(args.case), out)

    def hold(router: Router) -> HeldSimulation:
        """The simulation, started held on the spare router the moment it is taken: it starts up (Python, pybullet,
        its router session: about 0.4 s) while the case is generated, not after."""
        from rei.run.held import start_simulation

        return start_simulation(target, out, router, router.run_id, sim_args=sim_args, external_sut=external_sut)

    with _Warm(args, out, hold) as warm:
        case_dir = case_folder(Path(args.case), out, server=warm.cli)
        check_collector_objects(args, case_dir)
        check_case_faults(args, case_dir)
        # the first run of a service: its spare router was starting meanwhile
        router, held = warm.taken()
        run_id = router.run_id if router is not None else args.run_id or secrets.token_hex(6)
        options = _options(args, patterns, declared, warm.monitor, sim_args=sim_args, external_sut=external_sut)
        return _run(out, case_dir, dataclasses.replace(options, router=router, simulation=held), run_id)


def _options(args: argparse.Namespace, patterns: PatternSelection, declared: dict[str, float | None] | None,
             monitor_server: Path | None, *, sim_args: tuple[str, ...], external_sut: bool) -> PipelineOptions:
    from rei.run.pipeline import PipelineOptions

    return PipelineOptions(sim_args=sim_args, external_sut=external_sut,
                           utilities=args.utilities, humans=not args.no_humans,
                           laser=collector_config(args).laser.value != "none", view=args.view, bind=args.bind,
                           tls_cert=_path(args.tls_cert), tls_key=_path(args.tls_key), patterns=patterns,
                           declared=declared, monitor_server=monitor_server)


def _run(out: Path, case_dir: Path, options: PipelineOptions, run_id: str) -> int:
    from rei.run.pipeline import Progress, run_pipeline

    def show(progress: Progress) -> None:
        if sys.stderr.isatty():
            print(f"\rsim {progress.sim_time:7.1f} s  tasks {progress.tasks_done}/{progress.tasks}  "
                  f"utility {progress.utility:+.0f}   ", end="", file=sys.stderr, flush=True)

    result = run_pipeline(case_dir, out, options, run_id=run_id, on_progress=show)
    if sys.stderr.isatty():
        print(file=sys.stderr)
    print_verdicts(result.summary)
    write_views(out)
    return result.exit_code


def _import_run_modules() -> None:
    """In the order they are needed: the pipeline at the start, the report at the end."""
    import importlib

    for module in ("rei.run.pipeline", "rei.evaluation", "rei.report"):
        importlib.import_module(module)


class _Warm:
    """What the background service (rei.service) has ready for this run: warm JVMs, and a spare router taken
    over in the background while the case is generated, with the run's simulation started on it at once
    (``hold``). Without the service (``--no-service``, ``REI_SERVICE=off``, or it cannot be reached) every
    attribute is None and the run starts its own."""

    def __init__(self, args: argparse.Namespace, out: Path, hold: Callable[[Router], HeldSimulation]) -> None:
        self.out = out
        self.monitor: Path | None = None
        self.cli: Path | None = None
        self._taking: Future[tuple[Router, HeldSimulation | None] | None] | None = None
        self._lock = threading.Lock()
        self._closed = False  # the run ended before it took the router: whatever is taken later is stopped
        self._over = threading.Event()
        from rei import service

        if args.no_service or not service.enabled():
            return
        from rei.service.client import ServiceError, connect

        try:
            found = connect()
        except ServiceError as error:
            print(f"rei: {error}; this run starts its own router and JVMs", flush=True)
            return
        self.monitor, self.cli = found.monitor, found.cli
        # its own run id, a TLS transport: not what a spare router is made for
        if args.run_id is None and args.bind is None:
            # a daemon thread: a run that stops before it needs the router (Ctrl-C, a case that does not
            # generate) does not wait for it; the service stops a router whose run has gone
            self._taking = taking = Future()

            def take() -> None:
                try:
                    taking.set_result(self._take(found.take_router(os.getpid(), ROUTER_WAIT), hold))
                except BaseException as error:  # noqa: BLE001 - handed to taken()
                    taking.set_exception(error)
                # a child dies with the thread that started it (rei.lifetime: the kernel's parent-death signal
                # is per thread), so this one lives as long as the run
                self._over.wait()

            threading.Thread(target=take, name="rei-take-router", daemon=True).start()

    def _take(self, description: dict[str, Any] | None,
              hold: Callable[[Router], HeldSimulation]) -> tuple[Router, HeldSimulation | None] | None:
        """The spare router moved into OUT/router, and the simulation started held on it (None: the service had
        no router ready in time)."""
        if description is None:
            return None
        from rei.wamp.router import Router

        folder = self.out / "router"
        if folder.is_symlink() or folder.is_file():
            folder.unlink()
        elif folder.exists():
            shutil.rmtree(folder)
        try:
            os.rename(description["run_dir"], folder)  # the run keeps its router's config, log and secrets
        except OSError:  # another file system: the run's folder points to it instead
            folder.symlink_to(description["run_dir"], target_is_directory=True)
        router = Router.adopt(description, folder)
        with self._lock:
            if self._closed:  # the run is over already: nothing to start
                router.stop()
                return None
            try:
                return router, hold(router)
            except Exception as error:  # noqa: BLE001 - the pipeline starts the simulation itself then
                print(f"rei: the simulation did not start early ({error}); the run starts it", flush=True)
                return router, None

    def taken(self) -> tuple[Router | None, HeldSimulation | None]:
        """The spare router and the simulation held on it, waiting for them; (None, None) when the service had no
        router ready in time (the run starts its own)."""
        if self._taking is None:
            return None, None
        from rei.service.client import ServiceError

        taking, self._taking = self._taking, None
        try:
            result = taking.result()
        except ServiceError as error:
            print(f"rei: {error}; this run starts its own router", flush=True)
            return None, None
        return (None, None) if result is None else result

    def __enter__(self) -> Self:
        return self

    def __exit__(self, *exc: object) -> None:
        self._over.set()
        with self._lock:
            self._closed = True
            taking, self._taking = self._taking, None
        # the run ended before taking what was started for it (a case that did not generate, Ctrl-C)
        if taking is not None and taking.done() and taking.exception() is None:
            left = taking.result()
            if left is not None:
                router, held = left
                if held is not None:
                    held.process.stop()
                router.stop()
        folder = self.out / "router"
        if folder.is_symlink():  # the router's folder stayed on another file system: keep a copy of it
            target = folder.resolve()
            folder.unlink()
            if target.is_dir():
                shutil.copytree(target, folder, symlinks=True)


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
