# SPDX-License-Identifier: EPL-2.0
"""`rei edit CASE.rei`: edit a test case's room as a diagram in the browser (docs/room-editor.md).

Serves the editor on loopback and prints its address, which holds the session's token. Floors, walls, furniture,
the robot, the humans' paths, the routes of people who see the robot, crowds and the goals are edited in the
diagram; Save writes the `.rei` file through the
language's serializer, keeping the text you did not touch. Runs until Ctrl-C; unsaved edits are then written to
CASE.rei.unsaved, never dropped.
"""

from __future__ import annotations

import argparse
import os
import signal
import tempfile
import threading
import webbrowser
from html import escape
from pathlib import Path
from typing import Any

from rei.cli.errors import CommandError
from rei.lifetime import wait_for_stop


def register(subparsers: argparse._SubParsersAction[Any]) -> None:
    """Add the `edit` subcommand."""
    parser = subparsers.add_parser(
        "edit", help="edit a test case's room as a diagram in the browser",
        description=__doc__.split("\n\n", 1)[1] if __doc__ else None)
    parser.add_argument("case", type=Path, metavar="CASE.rei", help="the test case to edit")
    parser.add_argument("--port", type=int, default=0, help="HTTP port on 127.0.0.1 (default: a free one)")
    parser.add_argument("--open", action="store_true", help="open the editor in the default browser")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from rei import toolchain
    from rei.edit import EditEngine, EditServer, EditServerError, EditSession, EngineError, engine_command

    case: Path = args.case
    if not case.is_file():
        raise CommandError(f"{case}: no such file")
    if case.suffix != ".rei":
        raise CommandError(f"{case}: expected a .rei test case")
    command = engine_command(toolchain.find_jar("room-editor"), toolchain.find_java().executable)
    engine = EditEngine(command)
    try:
        session = EditSession(case, engine)
    except EngineError as error:
        engine.close()
        raise CommandError(f"{case}: {error}") from None
    try:
        server = EditServer(session, port=args.port).start()
    except EditServerError as error:
        session.close()
        raise CommandError(str(error)) from None
    stop = threading.Event()
    previous = signal.signal(signal.SIGTERM, lambda signum, frame: stop.set())
    try:
        print(f"edit: {server.url}  ({case}; Ctrl-C to stop)", flush=True)
        if args.open:
            _open_privately(server.url)
        wait_for_stop(stop)  # not stop.wait(): see there
    except KeyboardInterrupt:
        pass
    finally:
        server.stop()
        _keep_unsaved(session, case)
        session.close()
        signal.signal(signal.SIGTERM, previous)
    return 0


def _keep_unsaved(session: Any, case: Path) -> None:
    if not session.dirty:
        return
    rescue = case.with_name(case.name + ".unsaved")
    rescue.write_bytes(session.text.encode("utf-8"))
    print(f"rei: the editor had unsaved edits; they are in {rescue}", flush=True)


def _open_privately(url: str) -> None:
    """Opens ``url`` through a small page that only this user can read, so the token is not on the browser's
    command line, where any local user could read it."""
    folder = Path(tempfile.mkdtemp(prefix="rei-edit-"))
    page = folder / "open.html"
    fd = os.open(page, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
    with os.fdopen(fd, "w", encoding="utf-8") as out:
        out.write(f'<!doctype html><meta http-equiv="refresh" content="0;url={escape(url)}">'
                  f'<a href="{escape(url)}">open the REI room editor</a>\n')
    webbrowser.open(page.as_uri())
