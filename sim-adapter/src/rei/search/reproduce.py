# SPDX-License-Identifier: EPL-2.0
"""The `rei run` line that reproduces one of the search's runs: the first line of every saved case
(``// rei search candidate KEY: rei run KEY.rei --seed 5 --controller nav:moving_horizon=0 --no-humans``) and
the "reproduce:" of ``verdicts.xml``.

Besides the case, its seed and its fault, a run depends on the spec's controller, ``humans``, external
``sut:`` and the user's ``patterns:`` and ``utilities:``: each goes on the line as the `rei run` option that
selects it (the defaults, ``nav`` with the humans and only the default patterns, are left out; the patterns'
folder and the utility file by their absolute paths). An external SUT's command runs in the spec's folder (its relative paths are the spec's), so its
line starts with ``cd`` there and names the case by its absolute path. Only the spec's own options go on the line,
nothing of the run's router or credentials. Each argument is quoted for a POSIX shell; one with a line break in it
(a YAML block scalar's command) is written ``$'...'``, so the line stays one line of a ``//`` comment.
"""

from __future__ import annotations

import re
import shlex
from dataclasses import dataclass
from pathlib import Path

from rei.campaign.spec import ExternalSut

#: The first line of a saved case: ``HEADER_PREFIX`` KEY ``: `` command.
HEADER_PREFIX = "// rei search candidate "
_HEADER = re.compile(re.escape(HEADER_PREFIX) + r"[^:]*: (?P<command>.*)$")
_CONTROL = re.compile(r"[\x00-\x1f\x7f]")


@dataclass(frozen=True, slots=True)
class RunOptions:
    """What every run of a search uses besides its case, seed and fault (the spec's ``controller``, ``humans``,
    ``sut``, ``patterns`` and ``utilities``)."""

    controller: str = "nav"
    humans: bool = True
    sut: ExternalSut | None = None
    patterns: Path | None = None
    utilities: Path | None = None

    def argv(self) -> list[str]:
        """As `rei run` options (the defaults left out)."""
        if self.sut is not None:
            argv = self.sut.argv()
        else:
            argv = [] if self.controller == "nav" else ["--controller", self.controller]
        if not self.humans:
            argv.append("--no-humans")
        # absolute: the line runs in the saved case's folder, not the spec's
        for option, path in (("--patterns", self.patterns), ("--utilities", self.utilities)):
            if path is not None:
                argv += [option, str(path.resolve())]
        return argv


def command(case: Path, seed: int, fault: str | None, options: RunOptions) -> str:
    """The shell line that runs ``case`` as the search ran it (`rei run`'s ``-o OUT`` left to the user); ``case``
    is named by its file name (the line is run in its folder) unless the SUT runs in a folder of its own."""
    argv = ["rei", "run", case.name, "--seed", str(seed), *(["--fault", fault] if fault else []), *options.argv()]
    cwd = options.sut.cwd if options.sut is not None else None
    if cwd is None:
        return join(argv)
    argv[2] = str(case.resolve())
    return f"cd {quote(cwd)} && {join(argv)}"


def header(key: str, case: Path, seed: int, fault: str | None, options: RunOptions) -> str:
    """The first line of a saved case (without its line break)."""
    return f"{HEADER_PREFIX}{key}: {command(case, seed, fault, options)}"


def reproduce(case: str | Path) -> str:
    """The line that re-runs a saved case from any folder: the command of its header, run in its folder; the
    case's path when it has no header (or can not be read)."""
    path = Path(case)
    try:
        with path.open(encoding="utf-8") as file:
            first = file.readline().rstrip("\n")
    except OSError:
        return str(case)
    match = _HEADER.match(first)
    if match is None:
        return str(case)
    line = match["command"]
    return line if line.startswith("cd ") else f"cd {quote(str(path.resolve().parent))} && {line}"


def join(argv: list[str]) -> str:
    return " ".join(quote(a) for a in argv)


def quote(arg: str) -> str:
    """``arg`` quoted for a shell, on one line."""
    if not _CONTROL.search(arg):
        return shlex.quote(arg)
    escaped = arg.replace("\\", "\\\\").replace("'", "\\'")
    escaped = _CONTROL.sub(lambda m: {"\n": "\\n", "\r": "\\r", "\t": "\\t"}.get(m[0], f"\\x{ord(m[0]):02x}"),
                           escaped)
    return f"$'{escaped}'"
