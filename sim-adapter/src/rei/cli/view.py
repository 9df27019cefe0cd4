# SPDX-License-Identifier: EPL-2.0
"""`rei view --router URL --run ID [--case DIR]`: watch a running (or replayed) run in the browser.

Serves the live view on loopback and prints its address; the page connects to the router itself and draws
the room, the robot, humans, laser, signals, utility and tasks as they are published. Runs until Ctrl-C.
`rei run --view` does the same for the run it starts.
"""

from __future__ import annotations

import argparse
import signal
import threading
from pathlib import Path
from typing import Any

from rei.cli.errors import CommandError
from rei.lifetime import wait_for_stop


def register(subparsers: argparse._SubParsersAction[Any]) -> None:
    """Add the `view` subcommand."""
    parser = subparsers.add_parser(
        "view", help="watch a running run live in the browser",
        description=__doc__.split("\n\n", 1)[1] if __doc__ else None)
    parser.add_argument("--router", required=True, metavar="URL",
                        help="the router's WebSocket URL, e.g. ws://127.0.0.1:8080/ws")
    parser.add_argument("--run", required=True, metavar="ID", help="the run id in the topic names")
    parser.add_argument("--case", type=Path, metavar="DIR",
                        help="the run's generated case folder (world.json, mission.xml, animation.json); "
                             "without it the room and the tasks are not drawn")
    parser.add_argument("--utilities", type=Path, metavar="YAML", help="utility per signal (as for rei run)")
    parser.add_argument("--realm", default="rei", help="WAMP realm (default: rei)")
    parser.add_argument("--auth-file", type=Path, metavar="FILE",
                        help="viewer credentials for an authenticating router (OUT/router/auth/viewer.json); "
                             "the page receives them in its /config.json, served on loopback (docs/security.md)")
    parser.add_argument("--port", type=int, default=0, help="HTTP port on 127.0.0.1 (default: a free one)")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from rei.artifacts import ArtifactError
    from rei.evaluation import UtilityError
    from rei.view import ViewServer, ViewServerError, view_config

    if args.case is not None and not args.case.is_dir():
        raise CommandError(f"--case {args.case}: not a folder")
    auth = None
    if args.auth_file is not None:
        from rei.view import RouterAuth
        from rei.wamp.auth import load_credentials

        try:
            credentials = load_credentials(args.auth_file)
        except (OSError, ValueError, KeyError) as error:
            raise CommandError(f"--auth-file: {error}") from None
        auth = RouterAuth(credentials.authid, credentials.secret, credentials.method)
    try:
        config = view_config(args.router, args.run, args.case, realm=args.realm, utilities=args.utilities,
                             auth=auth)
        server = ViewServer(config, port=args.port).start()
    except (ValueError, ArtifactError, UtilityError, ViewServerError) as error:
        raise CommandError(str(error)) from None
    stop = threading.Event()
    previous = signal.signal(signal.SIGTERM, lambda signum, frame: stop.set())
    try:
        print(f"view: {server.url}  (run {args.run} at {args.router}; Ctrl-C to stop)", flush=True)
        wait_for_stop(stop)  # not stop.wait(): see there
    except KeyboardInterrupt:
        pass
    finally:
        server.stop()
        signal.signal(signal.SIGTERM, previous)
    return 0
