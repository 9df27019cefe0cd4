# SPDX-License-Identifier: EPL-2.0
"""The `rei` console script: one argparse parser, one module per subcommand.

Each subcommand lives in `rei.cli.<name>` (the command with underscores for dashes, and a trailing underscore for
a Python keyword: `rei import` is `rei.cli.import_`) and exposes `register(subparsers)`, which adds its parser and sets
`handler` (a function `Namespace -> int`) as a default. Adding a command is one module plus one entry in
`COMMANDS`; no other command is touched. Modules are imported here only for their `register`; anything heavy
(pybullet, the router) is imported inside the handler so `rei --help` stays fast.
"""

from __future__ import annotations

import argparse
import importlib
import os
import select
import sys
from collections.abc import Sequence

from rei import __version__
from rei.cli.errors import EXIT_BROKEN_PIPE, EXIT_TOOLCHAIN, CommandError
from rei.toolchain import ToolchainError

#: Subcommand modules under `rei.cli`, in the order `rei --help` lists them.
COMMANDS: tuple[str, ...] = ("validate", "generate", "sim", "run", "evaluate", "import_", "monitor", "report",
                            "gen_rooms", "campaign", "compare", "search", "view", "edit", "robot", "service", "nav_sut", "ros1_bridge", "ros2_bridge")


def build_parser(only: str | None = None) -> argparse.ArgumentParser:
    """The full parser with every registered subcommand; ``only``: with that subcommand module's alone (a command
    starts faster without importing the others: ``rei run`` starts ``rei sim`` once per run)."""
    parser = argparse.ArgumentParser(
        prog="rei",
        description="REI - Robotic Event Interceptor: generate, simulate, monitor and judge robot test cases.",
    )
    parser.add_argument("--version", action="version", version=f"rei {__version__}")
    subparsers = parser.add_subparsers(dest="command", metavar="COMMAND", required=True)
    for name in COMMANDS if only is None else (only,):
        importlib.import_module(f"rei.cli.{name}").register(subparsers)
    return parser


def _command_module(argv: Sequence[str]) -> str | None:
    """The subcommand module ``argv`` names in first place (``gen-rooms`` -> ``gen_rooms``), if any."""
    if not argv or argv[0].startswith("-"):
        return None
    name = {"import": "import_"}.get(argv[0], argv[0].replace("-", "_"))
    return name if name in COMMANDS else None


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the console script; returns the process exit code.

    User errors (a `CommandError`, a `ToolchainError`) become a `rei: error: ...` line on stderr (one per problem
    of the input) and a non-zero exit code; anything else is a bug and keeps its traceback.
    """
    command_line = argv is None  # not a campaign worker's call: the run's CPU is counted as the worker's
    argv = sys.argv[1:] if argv is None else list(argv)
    if command_line and argv[:1] == ["run"] and (code := _warm_run(argv)) is not None:
        return code
    parser = build_parser(_command_module(argv))
    args = parser.parse_args(argv)
    try:
        return int(args.handler(args))
    except CommandError as error:
        for problem in error.problems:
            print(f"rei: error: {problem}", file=sys.stderr)
        return error.exit_code
    except ToolchainError as error:
        print(f"rei: error: {error}", file=sys.stderr)
        return EXIT_TOOLCHAIN
    except KeyboardInterrupt:
        print("rei: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:
        if not _stdout_closed():  # another pipe or socket (a process that died): a bug's, it keeps its traceback
            raise
        # the reader went away (`rei robot X --json | head`): no traceback; stdout to /dev/null so the
        # interpreter's own flush at exit does not fail again
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return EXIT_BROKEN_PIPE


def _warm_run(argv: list[str]) -> int | None:
    """``rei run`` forked from the background service's warm Python (rei.service.warm), which has imported what a
    run needs; None: run here (no service yet, another REI's, ``--no-service``, or this is that fork)."""
    from rei import service
    from rei.service.warm import SOCKET_ENV, delegate

    if os.environ.get(SOCKET_ENV) or "--no-service" in argv or not service.enabled():
        return None
    return delegate(argv, service.service_dir())


def _stdout_closed() -> bool:
    """Whether stdout's reader went away: its pipe or socket polls as an error or a hang-up (nothing is written)."""
    try:
        fd = sys.stdout.fileno()
    except (AttributeError, OSError, ValueError):  # not a file (captured): not the pipe that broke
        return False
    poll = select.poll()
    poll.register(fd, select.POLLOUT)
    return any(events & (select.POLLERR | select.POLLHUP) for _, events in poll.poll(0))


__all__ = ["COMMANDS", "CommandError", "build_parser", "main"]
