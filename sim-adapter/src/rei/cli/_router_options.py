# SPDX-License-Identifier: EPL-2.0
"""The options of the router a command starts (`rei sim`, `rei run`): loopback unless bound, with TLS."""

from __future__ import annotations

import argparse

from rei.cli.errors import CommandError


def add_router_options(parser: argparse.ArgumentParser, command: str) -> None:
    parser.add_argument("--bind", metavar="ADDRESS", help=f"also expose the router `rei {command}` starts on this "
                        "interface (IP address); requires --tls-cert and --tls-key (docs/security.md)")
    parser.add_argument("--tls-cert", metavar="FILE", help="with --bind: the TLS certificate (PEM)")
    parser.add_argument("--tls-key", metavar="FILE", help="with --bind: the TLS private key (PEM)")


def check_router_options(args: argparse.Namespace) -> None:
    """Refuse a non-loopback address without TLS, half a TLS pair or a missing file, before anything starts."""
    from rei.wamp.router import check_bind

    try:
        check_bind(args.bind, args.tls_cert, args.tls_key)
    except ValueError as error:
        raise CommandError(str(error)) from None
