# SPDX-License-Identifier: EPL-2.0
"""The VEPL patterns a run's monitor uses, ``rei run --patterns DIR [--no-default-patterns]`` (docs/vepl.md), and
the user's DRL queries they may name, ``--queries DIR`` (queries over the runtime model, docs/monitor.md).

- ``check``: before anything starts, the monitor jar compiles the selection (``--compile-only``), so a pattern
  that does not validate, or a query that does not build, fails the command with the compiler's
  ``file:line[:column]: message`` and no run starts.
- ``record``: the run keeps a copy of the user's ``*.vepl`` in ``OUT/patterns/`` (``*.drl`` in ``OUT/queries/``)
  and the selection in ``OUT/patterns.json``, so a replay (``rei evaluate OUT``, or a monitor that died) runs what
  the live monitor ran.
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
#: The copy of the user's queries in a run folder.
QUERIES_DIR = "queries"
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
    """The patterns the monitor compiles: the packaged defaults (``defaults``) and/or the ``*.vepl`` of ``folder``;
    ``queries``: a folder of the user's ``*.drl`` queries, loaded beside the packaged ones."""

    folder: Path | None = None
    defaults: bool = True
    queries: Path | None = None

    def __post_init__(self) -> None:
        if self.folder is None and not self.defaults:
            raise ValueError("--no-default-patterns needs --patterns DIR")

    def monitor_args(self) -> list[str]:
        """The monitor jar's options for this selection."""
        args = [] if self.folder is None else ["--patterns", str(self.folder)]
        if self.queries is not None:
            args += ["--queries", str(self.queries)]
        return args if self.defaults else [*args, "--no-default-patterns"]

    def describe(self) -> str:
        """How ``summary.json``'s ``utilities`` names them, e.g. ``patterns (defaults + /run/out/patterns)``."""
        parts = (["defaults"] if self.defaults else []) + ([] if self.folder is None else [str(self.folder)])
        return f"patterns ({' + '.join(parts)})"

    @classmethod
    def recorded(cls, out: Path) -> PatternSelection:
        """What ``record`` kept in the run folder ``out``; the defaults for a run without patterns of its own."""
        folder = out / PATTERNS_DIR
        queries = out / QUERIES_DIR if (out / QUERIES_DIR).is_dir() else None
        if not folder.is_dir():
            return cls(queries=queries)
        selection = out / SELECTION_FILE
        try:
            defaults = json.loads(selection.read_text(encoding="utf-8")).get("default_patterns", True)
        except (OSError, ValueError, AttributeError):
            defaults = True  # no record of --no-default-patterns: it was not given
        return cls(folder, bool(defaults), queries)


def check(selection: PatternSelection, *, timeout: float = CHECK_TIMEOUT) -> dict[str, float | None]:
    """Compile the selection as the monitor will; returns what the patterns declare (signal -> utility or None).

    Raises PatternError with the compiler's messages when a pattern does not validate.
    """
    from rei.evaluation import UtilityError, load_declared_utilities

    folder, queries = selection.folder, selection.queries
    if folder is not None and not folder.is_dir():
        raise PatternError(f"--patterns {folder}: not a folder")
    if folder is not None and not any(p.is_file() for p in folder.glob("*.vepl")):
        raise PatternError(f"--patterns {folder}: no .vepl files in it")
    if queries is not None and not queries.is_dir():
        raise PatternError(f"--queries {queries}: not a folder")
    if queries is not None and not any(p.is_file() for p in queries.glob("*.drl")):
        raise PatternError(f"--queries {queries}: no .drl files in it")
    with tempfile.TemporaryDirectory(prefix="rei-patterns-") as tmp:
        utilities, log = Path(tmp) / UTILITIES_FILE, Path(tmp) / "monitor.log"
        result = run_jar("monitor", ["--compile-only", *selection.monitor_args(), "--utilities-out", str(utilities)],
                         log, timeout=timeout)
        if result.code != 0:
            given = " ".join(f"{option} {path}" for option, path in (("--patterns", folder), ("--queries", queries))
                             if path is not None)
            raise PatternError(f"{given}: {_monitor_error(log) or result.log_tail}")
        try:
            return load_declared_utilities(utilities)
        except UtilityError as error:
            raise PatternError(str(error)) from None


def record(selection: PatternSelection, out: Path) -> PatternSelection:
    """Keep the selection in the run folder ``out``; returns it with ``folder`` the copy the monitor should use.

    A previous run's copy in ``out`` is replaced (or removed, for a run without patterns of its own), so a
    replay never picks up patterns this run did not use.
    """
    queries = _copy(selection.queries, out / QUERIES_DIR, "*.drl")
    target = out / PATTERNS_DIR
    (out / SELECTION_FILE).unlink(missing_ok=True)
    folder = _copy(selection.folder, target, "*.vepl")
    if selection.folder is None:
        return PatternSelection(None, selection.defaults, queries)
    (out / SELECTION_FILE).write_text(json.dumps({
        "source": str(selection.folder.resolve()), "default_patterns": selection.defaults}, indent=2) + "\n",
        encoding="utf-8")
    return PatternSelection(folder, selection.defaults, queries)


def _copy(source: Path | None, target: Path, files: str) -> Path | None:
    """``source``'s ``files`` (what the monitor reads: that folder, not below) copied to ``target``, replacing a
    previous run's copy; None (and no copy left) without a source."""
    same = source is not None and source.resolve() == target.resolve()
    if target.exists() and not same:
        shutil.rmtree(target)
    if source is None:
        return None
    if not same:
        target.mkdir()
        for path in sorted(source.glob(files)):
            if path.is_file():
                shutil.copyfile(path, target / path.name)
    return target


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


__all__ = ["CHECK_TIMEOUT", "PATTERNS_DIR", "QUERIES_DIR", "SELECTION_FILE", "UTILITIES_FILE", "PatternError", "PatternSelection",
           "check", "record"]
