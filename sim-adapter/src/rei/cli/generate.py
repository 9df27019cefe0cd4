# SPDX-License-Identifier: EPL-2.0
"""`rei generate FILE -o OUT`: write the simulator world, mission, animation and monitor configuration.

See docs/artifacts.md for the five files and their formats.
"""

from __future__ import annotations

import argparse
from typing import Any

from rei.cli._java import run_java_cli


def register(subparsers: argparse._SubParsersAction[Any]) -> None:
    """Add the `generate` subcommand."""
    parser = subparsers.add_parser(
        "generate",
        help="generate world.sdf, world.json, mission.xml, animation.json and monitor.json from a test case",
        description="Generate the artifacts of one .rei test case. "
        "Exit 0: written; 1: validation or layout errors; 2: usage or I/O error.",
    )
    parser.add_argument("file", metavar="FILE", help="the .rei test case")
    parser.add_argument("-o", "--output", required=True, metavar="OUT", help="output directory")
    parser.add_argument("--templates", metavar="DIR", help="EGL templates overriding the built-in ones")
    parser.add_argument("-q", "--quiet", action="store_true", help="do not list the written files")
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    """Delegate to the Java CLI; its exit code is passed through."""
    java_args = ["generate", args.file, "-o", args.output]
    if args.templates:
        java_args += ["--templates", args.templates]
    if args.quiet:
        java_args.append("--quiet")
    return run_java_cli(java_args)
