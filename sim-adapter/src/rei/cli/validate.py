# SPDX-License-Identifier: EPL-2.0
"""`rei validate FILE...`: parse, link and validate test cases, printing `PATH:LINE:COL: error: ...` lines."""

from __future__ import annotations

import argparse
from typing import Any

from rei.cli._java import run_java_cli


def register(subparsers: argparse._SubParsersAction[Any]) -> None:
    """Add the `validate` subcommand."""
    parser = subparsers.add_parser(
        "validate",
        help="check .rei test cases for syntax, linking and validation errors",
        description="Check .rei test cases. Exit 0: no errors; 1: errors found; 2: usage or I/O error.",
    )
    parser.add_argument("files", nargs="+", metavar="FILE", help="a .rei test case")
    parser.add_argument("-q", "--quiet", action="store_true", help="print diagnostics only")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    """Delegate to the Java CLI; its exit code is passed through."""
    return run_java_cli(["validate", *args.files, *(["--quiet"] if args.quiet else [])])
