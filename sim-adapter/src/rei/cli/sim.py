# SPDX-License-Identifier: EPL-2.0
"""`rei sim CASE -o OUT`: run a test case's mission once in pybullet and keep the streams it published.

CASE is a ``.rei`` file (generated into ``OUT/case`` first) or a folder of generated artifacts. The state and
mission streams go through a real Crossbar router started on a free loopback port (or one given with
``--router``, with ``--auth-file`` holding the simulation role's credentials), and are recorded under
``OUT/streams/``. The router started here authenticates every client (docs/security.md) and listens on loopback;
``--bind ADDRESS --tls-cert FILE --tls-key FILE`` also exposes it on another interface, over TLS only. Exit 0: every task succeeded; 1: a task failed;
2: bad arguments or files.
"""

from __future__ import annotations

import argparse
import dataclasses
import secrets
import sys
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

from rei.cli._case import case_folder, prepare_output, valid_run_id
from rei.cli._mission_options import (
    add_mission_options,
    check_collector_objects,
    check_mission_options,
    collector_config,
    sut_options,
)
from rei.cli._router_options import add_router_options, check_router_options
from rei.cli.errors import EXIT_INVALID, EXIT_OK, EXIT_RUN_ERROR, CommandError
from rei.lifetime import sigterm_unwinds, skip_exit_collection

if TYPE_CHECKING:
    from rei.wamp.client import WampClient

#: Seconds a reconnected simulation waits for the monitor before sending its queue anyway (--wait-for-monitor).
MONITOR_GATE_S = 10.0


def register(subparsers: argparse._SubParsersAction[Any]) -> None:
    """Add the `sim` subcommand."""
    parser = subparsers.add_parser(
        "sim",
        help="run a test case's mission once in the simulator and record the published streams",
        description=__doc__.split("\n\n", 1)[1] if __doc__ else None,
    )
    parser.add_argument("case", metavar="CASE", help="a .rei test case or a folder generated from one")
    parser.add_argument("-o", "--output", required=True, metavar="OUT", help="output folder")
    add_mission_options(parser)
    parser.add_argument("--progress", choices=("auto", "lines", "none"), default="auto",
                        help="progress display: on a terminal (auto), one machine-readable line per simulated "
                        "second on stdout (lines, for a supervising process), or none")
    parser.add_argument("--run-id", metavar="ID", help="identifier of the run in topic names (default: random); "
                        "lets a monitor or evaluator subscribe before the run starts")
    router = parser.add_mutually_exclusive_group()
    router.add_argument("--router", metavar="URL", help="publish through this router (ws:// or rs://) instead "
                        "of starting one")
    router.add_argument("--no-router", action="store_true", help="record the streams without publishing them")
    parser.add_argument("--auth-file", metavar="FILE", help="with --router: the simulation role's credentials "
                        "(a 0600 JSON file written by REI's router, e.g. OUT/router/auth/simulation.json)")
    parser.add_argument("--reconnect", type=float, default=0.0, metavar="SECONDS",
                        help="with --router: if the connection is lost, keep trying this long to reach the "
                        "restarted router (the simulation waits meanwhile; default 0: the run ends in error)")
    parser.add_argument("--wait-for-monitor", action="store_true",
                        help="with --reconnect: after a reconnection, send the queued messages only once the run's "
                        f"monitor answers again (at most {MONITOR_GATE_S:g} s), so the router does not drop them")
    parser.add_argument("--held", action="store_true",
                        help="with --router: once connected, wait for a line on standard input before simulating "
                        "(`rei run` starts the simulation while the monitor starts, and says go once it listens)")
    parser.add_argument("--sut-auth-file", metavar="FILE", type=Path,
                        help="with --router and --sut/--sut-attach: the sut role's credentials, for the SUT")
    parser.add_argument("--sut-router", metavar="URL",
                        help="with --router: the URL the SUT connects to (default: the --router URL)")
    add_router_options(parser, "sim")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    # Heavy imports here, so `rei --help` stays fast.
    from rei.artifacts import ArtifactError
    from rei.run import MissionRunOptions, run_mission
    from rei.sim.people import PeopleError
    skip_exit_collection()  # `rei run` waits for this process's exit
    check_mission_options(args)
    _check_router_options(args)
    out = Path(args.output).resolve()  # children and the router run in other working directories
    prepare_output(out)
    try:
        options = MissionRunOptions(
            controller=args.controller, seed=args.seed, humans=not args.no_humans, fault=args.fault,
            animation=args.animation, realtime=args.realtime, collector=collector_config(args))
    except ValueError as error:
        raise CommandError(str(error)) from None
    # held (`rei run`): the case may still be being generated; it is read once the simulation is let go
    case_dir = None if args.held else _case(args, out)
    run_id = args.run_id or secrets.token_hex(6)
    if not valid_run_id(run_id):
        raise CommandError(f"--run-id {run_id!r}: expected letters, digits, '_' or '-' (it becomes part of topic URIs)")
    try:
        publisher = _publisher(args, out, run_id)
        # stopped by `rei run` or a campaign: unwind, so a started SUT and the router are stopped too
        with sigterm_unwinds(), publisher as client:
            if args.held:
                if not sys.stdin.readline():
                    raise CommandError("--held: standard input ended before the line that starts the simulation")
                case_dir = _case(args, out)
            assert case_dir is not None
            url, auth_file = publisher.sut_connection(client)
            options = dataclasses.replace(options, sut=sut_options(args, router_url=url, auth_file=auth_file))
            result = run_mission(case_dir, out, options, run_id=run_id, client=client,
                                 progress=_PROGRESS[args.progress])
    except ArtifactError as error:
        raise CommandError(str(error)) from None
    except PeopleError as error:  # a person the model refuses (where it stands, a stop off the area), a dead server
        _clear_progress()
        raise CommandError(str(error), EXIT_RUN_ERROR) from None
    _clear_progress()
    if result.error is not None:
        print(f"rei sim: error: {result.error}", file=sys.stderr, flush=True)
        print(f"the run ended in error after {result.sim_time:.1f} s simulated; streams so far: {out / 'streams'}")
        return EXIT_RUN_ERROR
    for task in result.tasks:
        verdict = "ok  " if task.succeeded else "FAIL"
        print(f"task {task.index}: {verdict} {task.ended - task.started:7.1f} s" + (f"  {task.reason}" if task.reason else ""))
    if result.cut_off:
        print(f"the run was cut off after {result.sim_time:.1f} s of simulated time")
    print(f"mission {'succeeded' if result.succeeded else 'failed'}: {result.sim_time:.1f} s simulated in "
          f"{result.wall_time:.1f} s ({result.real_time_factor:.0f}x real time); run {run_id}")
    print(f"streams: {out / 'streams'} ({result.state_messages} state, {result.mission_messages} mission messages)")
    return EXIT_OK if result.succeeded else EXIT_INVALID


def _case(args: argparse.Namespace, out: Path) -> Path:
    case_dir = case_folder(Path(args.case), out)
    check_collector_objects(args, case_dir)
    return case_dir


def _check_router_options(args: argparse.Namespace) -> None:
    if not args.reconnect >= 0:
        raise CommandError(f"--reconnect must be a number of seconds >= 0, got {args.reconnect}")
    if args.held and args.router is None:
        raise CommandError("--held applies with --router URL only")
    if args.wait_for_monitor and not args.reconnect:
        raise CommandError("--wait-for-monitor applies with --reconnect SECONDS only")
    if args.auth_file is not None and args.router is None:
        raise CommandError("--auth-file applies with --router URL only (a router started here makes its own)")
    if (args.sut_auth_file is not None or args.sut_router is not None) and args.router is None:
        raise CommandError("--sut-auth-file and --sut-router apply with --router URL only")
    if (args.sut is not None or args.sut_attach) and args.no_router:
        raise CommandError("--sut and --sut-attach need a router: the SUT talks to the simulation through it")
    if (args.sut is not None or args.sut_attach) and args.auth_file is not None and args.sut_auth_file is None:
        raise CommandError("--sut/--sut-attach on an authenticating router (--auth-file) need --sut-auth-file: the "
                           "sut role's credentials, e.g. OUT/router/auth/sut.json")
    if (args.router is not None or args.no_router) and (args.bind or args.tls_cert or args.tls_key):
        raise CommandError("--bind/--tls-cert/--tls-key apply to the router `rei sim` starts (not with "
                           "--router or --no-router)")
    check_router_options(args)


class _publisher:
    """The WAMP client the run publishes through: on a router started here, a given one, or none."""

    def __init__(self, args: argparse.Namespace, out: Path, run_id: str) -> None:
        self._args = args
        self._out = out
        self._run_id = run_id
        self._router: Any = None
        self._client: Any = None

    def __enter__(self) -> Any:
        from rei.wamp.auth import load_credentials
        from rei.wamp.client import WampClient
        from rei.wamp.router import Router
        from rei.wamp.topics import Topics

        if self._args.no_router:
            return None
        url = self._args.router
        if url is None:
            self._router = Router(run_dir=self._out / "router", run_id=self._run_id, bind=self._args.bind, die_with_parent=True,
                                  tls_cert=self._args.tls_cert, tls_key=self._args.tls_key).start()
            if self._router.exposed_url is not None:
                print(f"router: {self._router.exposed_url} (TLS, authenticated)", flush=True)
            url, auth = self._router.rs_url, self._router.credentials("simulation")
        elif self._args.auth_file is not None:
            try:
                auth = load_credentials(self._args.auth_file)
            except (OSError, ValueError, KeyError) as error:
                raise CommandError(f"--auth-file: {error}") from None
        else:
            auth = None
        try:
            self._client = WampClient(url, auth=auth, reconnect=self._args.reconnect).start()
            if self._args.wait_for_monitor:
                self._client.hold_after_reconnect(_monitor_gate(self._client, Topics(self._run_id).snapshot))
        except BaseException:
            if self._router is not None:
                self._router.stop()
            raise
        return self._client

    def sut_connection(self, client: Any) -> tuple[str | None, Path | None]:
        """Where an external SUT connects (WebSocket: every WAMP library has it) and its credentials file."""
        if self._router is not None:
            return self._router.ws_url, self._router.auth_file("sut")
        if client is None:
            return None, None
        return self._args.sut_router or client.url, self._args.sut_auth_file

    def __exit__(self, *exc: object) -> None:
        try:
            if self._client is not None:
                self._client.close()
        finally:
            if self._router is not None:
                self._router.stop()


def _monitor_gate(client: WampClient, snapshot: str) -> Callable[[], None]:
    """Returns once the monitor's snapshot procedure answers (its new session's subscriptions are in place: it
    registers after subscribing) or after MONITOR_GATE_S."""

    def gate() -> None:
        try:
            client.call_when_registered(snapshot, timeout=MONITOR_GATE_S)
        except Exception:  # noqa: BLE001 - not back in time (or the call failed): the queue goes out anyway
            print(f"rei sim: the monitor did not answer within {MONITOR_GATE_S:g} s of the reconnection; sending on",
                  file=sys.stderr, flush=True)

    return gate


def _progress(sim_time: float, done: int, total: int) -> None:
    if sys.stderr.isatty():
        print(f"\rsim {sim_time:7.1f} s  tasks {done}/{total}", end="", file=sys.stderr, flush=True)


def _progress_line(sim_time: float, done: int, total: int) -> None:
    print(f"progress t={sim_time:.3f} done={done} total={total}", flush=True)


_PROGRESS = {"auto": _progress, "lines": _progress_line, "none": None}


def _clear_progress() -> None:
    if sys.stderr.isatty():
        print("\r" + " " * 40 + "\r", end="", file=sys.stderr, flush=True)
