# SPDX-License-Identifier: EPL-2.0
"""`rei service status|start|stop`: the background service `rei run` uses (docs/performance.md).

It keeps three spare routers and warm monitor and generator JVMs ready between runs, starts on the first `rei run`,
and stops itself after 10 idle minutes. `status` says whether it runs and what it has ready (exit 0 running,
1 not running); `start` starts it now; `stop` stops it and what it keeps (exit 0 whether or not it ran).
"""

from __future__ import annotations

import argparse
from typing import Any


def register(subparsers: argparse._SubParsersAction[Any]) -> None:
    """Add the `service` subcommand."""
    parser = subparsers.add_parser(
        "service", help="the background service that keeps a router and warm JVMs ready between runs",
        description=__doc__.split("\n\n", 1)[1] if __doc__ else None)
    parser.add_argument("action", choices=("status", "start", "stop"), help="what to do")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from rei.cli.errors import CommandError
    from rei.service import service_dir
    from rei.service.client import ServiceError, connect, request, stop

    folder = service_dir()
    if args.action == "stop":
        print(f"stopped the service in {folder}" if stop(folder) else f"no service runs in {folder}")
        return 0
    if args.action == "start":
        try:
            connect(folder=folder)
        except ServiceError as error:
            raise CommandError(str(error)) from None
    try:
        status = request(folder, {"op": "status"}, timeout=5.0)
    except ServiceError:
        print(f"no service runs in {folder}")
        return 1
    print(f"service: pid {status['pid']} in {folder} (log: {folder / 'service.log'})")
    print(f"  warm monitor JVM:   {'ready' if status['monitor'] else 'starting'}")
    print(f"  warm generator JVM: {'ready' if status['cli'] else 'starting'}")
    print(f"  spare routers:      {status['spares']} ready" + (f" (next: run {status['spare']})" if status['spare'] else ""))
    print(f"  routers of runs:    {status['handed']}")
    print(f"  stops when idle for {status['idle_left']:.0f} more s")
    return 0
