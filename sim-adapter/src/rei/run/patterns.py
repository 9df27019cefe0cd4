# SPDX-License-Identifier: EPL-2.0
"""The VEPL patterns a run's monitor uses: ``rei run --patterns DIR [--no-default-patterns]`` (docs/vepl.md).

- ``check``: before anything starts, the monitor jar compiles the selection (``--compile-only``), so a pattern
  that does not validate fails the command with the compiler's ``file:line:column: message`` and no run starts.
- ``record``: the run keeps a copy of the user's ``*.vepl`` in ``OUT/patterns/`` and the selection in
  ``OUT/patterns.json``, so a replay (``rei evaluate OUT``, or a monitor that died) runs what the live monitor ran.
- ``UTILITIES_FILE``: the monitor writes the utilities the patterns in use declare there (``--utilities-out``),
  before it processes any message; the evaluator scores with them (rei.evaluation.load_utilities).
"""

from __future__ import annotations

import json
import shutil
import tempfile
from dataclasses import dataclass
from pathlib import Path

from rei.run.jvm import run_jar

#: The copy of the user's patterns in a run folder.
PATTERNS_DIR = "patterns"
#: Whether the default patterns were on, beside the copy (its absence means they were).
SELECTION_FILE = "patterns.json"
#: The monitor's ``--utilities-out`` file in a run folder.
UTILITIES_FILE = "utilities.json"
#: Seconds the check may take (a JVM start and the VEPL compiler: about 1-3 s).
CHECK_TIMEOUT = 120.0


class PatternError(ValueError):
    """The patterns can not be used; the message has the compiler's ``file:line:column: message`` lines."""


@dataclass(frozen=True, slots=True)
class PatternSelection:
    """The patterns the monitor compiles: the packaged defaults (``defaults``) and/or the ``*.vepl`` of ``folder``."""

    folder: Path | None = None
    defaults: bool = True

    def __post_init__(self) -> None:
        if self.folder is None and not self.defaults:
            raise ValueError("--no-default-patterns needs --patterns DIR")

    def monitor_args(self) -> list[str]:
        """The monitor jar's options for this selection."""
        args = [] if self.folder is None else ["--patterns", str(self.folder)]
        return args if self.defaults else [*args, "--no-default-patterns"]

    def describe(self) -> str:
        """How ``summary.json``'s ``utilities`` names them, e.g. ``patterns (defaults + /run/out/patterns)``."""
        parts = (["defaults"] if self.defaults else []) + ([] if self.folder is None else [str(self.folder)])
        return f"patterns ({' + '.join(parts)})"

    @classmethod
    def recorded(cls, out: Path) -> PatternSelection:
        """What ``record`` kept in the run folder ``out``; the defaults for a run without patterns of its own."""
        folder = out / PATTERNS_DIR
        if not folder.is_dir():
            return cls()
        selection = out / SELECTION_FILE
        try:
            defaults = json.loads(selection.read_text(encoding="utf-8")).get("default_patterns", True)
        except (OSError, ValueError, AttributeError):
            defaults = True  # no record of --no-default-patterns: it was not given
        return cls(folder, bool(defaults))


def check(selection: PatternSelection, *, timeout: float = CHECK_TIMEOUT) -> dict[str, float | None]:
    """Compile the selection as the monitor will; returns what the patterns declare (signal -> utility or None).

    Raises PatternError with the compiler's messages when a pattern does not validate.
    """
    from rei.evaluation import UtilityError, load_declared_utilities

    folder = selection.folder
    if folder is not None and not folder.is_dir():
        raise PatternError(f"--patterns {folder}: not a folder")
    if folder is not None and not any(p.is_file() for p in folder.glob("*.vepl")):
        raise PatternError(f"--patterns {folder}: no .vepl files in it")
    with tempfile.TemporaryDirectory(prefix="rei-patterns-") as tmp:
        utilities, log = Path(tmp) / UTILITIES_FILE, Path(tmp) / "monitor.log"
        result = run_jar("monitor", ["--compile-only", *selection.monitor_args(), "--utilities-out", str(utilities)],
                         log, timeout=timeout)
        if result.code != 0:
            raise PatternError(f"--patterns {folder}: {_monitor_error(log) or result.log_tail}")
        try:
            return load_declared_utilities(utilities)
        except UtilityError as error:
            raise PatternError(str(error)) from None


def record(selection: PatternSelection, out: Path) -> PatternSelection:
    """Keep the selection in the run folder ``out``; returns it with ``folder`` the copy the monitor should use.

    A previous run's copy in ``out`` is replaced (or removed, for a run without patterns of its own), so a
    replay never picks up patterns this run did not use.
    """
    target = out / PATTERNS_DIR
    same = selection.folder is not None and selection.folder.resolve() == target.resolve()
    if target.exists() and not same:
        shutil.rmtree(target)
    (out / SELECTION_FILE).unlink(missing_ok=True)
    if selection.folder is None:
        return selection
    if not same:
        target.mkdir()
        for source in sorted(selection.folder.glob("*.vepl")):  # what the monitor reads: *.vepl, not below
            if source.is_file():
                shutil.copyfile(source, target / source.name)
    (out / SELECTION_FILE).write_text(json.dumps({
        "source": str(selection.folder.resolve()), "default_patterns": selection.defaults}, indent=2) + "\n",
        encoding="utf-8")
    return PatternSelection(target, selection.defaults)


def _monitor_error(log: Path) -> str:
    """The monitor's own error message (``rei-monitor: ...`` and the lines after it), without the prefix."""
    try:
        lines = log.read_text(encoding="utf-8", errors="replace").splitlines()
    except OSError:
        return ""
    for index, line in enumerate(lines):
        if line.startswith("rei-monitor: "):
            return "\n".join([line.removeprefix("rei-monitor: "), *lines[index + 1:]]).rstrip()
    return ""


__all__ = ["CHECK_TIMEOUT", "PATTERNS_DIR", "SELECTION_FILE", "UTILITIES_FILE", "PatternError", "PatternSelection",
           "check", "record"]
