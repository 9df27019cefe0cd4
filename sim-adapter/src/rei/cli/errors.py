# SPDX-License-Identifier: EPL-2.0
"""Exit codes and the error type every subcommand raises for a mistake of the user, not of REI.

The codes follow the Java CLI's so a script sees the same meaning whichever side failed.
"""

from __future__ import annotations

from collections.abc import Sequence

EXIT_OK = 0
#: The input was read but is wrong (validation or layout errors, a failed check).
EXIT_INVALID = 1
#: Bad arguments, or a file that cannot be read or written (argparse uses 2 as well).
EXIT_USAGE = 2
#: The run could not be completed (`rei run`, `rei sim`): a part broke it, e.g. an external SUT.
EXIT_RUN_ERROR = 2
#: The environment cannot run REI: no Java, an old Java, jars not built.
EXIT_TOOLCHAIN = 3
#: The reader of the output went away (a pipe closed early): what a shell reports for a writer killed by SIGPIPE.
EXIT_BROKEN_PIPE = 141


class CommandError(Exception):
    """A user error: printed without a traceback, then the process exits with `exit_code`. `message` is one
    problem, or all the problems of an input (a spec's mistakes, rei.located_yaml.Problems): each is printed as
    its own `rei: error: ...` line, as `rei validate` prints one line per problem of a test case."""

    def __init__(self, message: str | Sequence[str], exit_code: int = EXIT_USAGE) -> None:
        self.problems: tuple[str, ...] = (message,) if isinstance(message, str) else tuple(message)
        super().__init__("\n".join(self.problems))
        self.exit_code = exit_code
