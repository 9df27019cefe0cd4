# SPDX-License-Identifier: EPL-2.0
"""The bridge from subcommands to the Java CLI (`rei-cli.jar`), shared by `validate` and `generate`."""

from __future__ import annotations

from collections.abc import Sequence

from rei import toolchain


def run_java_cli(args: Sequence[str]) -> int:
    """Run `rei-cli.jar` with `args`, its output streaming to ours; its exit code is ours.

    Java is checked before the jar so a user without Java hears about Java, not about a missing build.
    """
    java = toolchain.find_java()
    jar = toolchain.find_jar("cli")
    return toolchain.run_jar(jar, args, java=java)
