# SPDX-License-Identifier: EPL-2.0
"""Candidates: the base case edited by the room editor's engine, checked, written and generated.

One edit engine (``rei-room-editor.jar``, rei.edit.engine) holds the base case for the whole search: each candidate
is a ``reset`` to the base text and one ``apply`` of its operations (tens of milliseconds, no JVM start), so it is
``.rei`` text in the base's layout, checked by the language's own validators. A candidate the validators refuse,
or whose mission the reference global planner finds no path for (the room generator's check,
rei.rooms.check), is never simulated. Valid ones are written to ``OUT/candidates/<key>.rei`` and generated into
``OUT/cases/<key>/`` in one warm generator JVM.

An engine that fails inside (``EngineFailure``: an exception in it, such as its jar rebuilt under it), dies or hangs
says nothing about the candidate: it is started again once, and if it fails again an ``EngineFailure`` goes to the
caller (`rei search` stops), never an invalid candidate.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from rei import toolchain
from rei.campaign.prepare import relocated_imports
from rei.campaign.spec import SpecError
from rei.edit import EditEngine, EngineError, EngineFailure, engine_command
from rei.rooms.check import diagram_static_map, unplannable
from rei.run.jvm import JarServer, JarServerError, run_jar
from rei.search.reproduce import RunOptions, header
from rei.search.space import Edit

VALID, INVALID, UNPLANNABLE = "valid", "invalid", "unplannable"


@dataclass(frozen=True, slots=True)
class Candidate:
    """One edited test case. ``status``: valid, invalid (the validators refused it) or unplannable (no path);
    ``problems``: why not valid, one message each."""

    key: str
    edit: Edit
    status: str
    text: str | None
    problems: tuple[str, ...] = ()
    diagram: dict[str, Any] = field(default_factory=dict, compare=False, repr=False)


class CandidateMaker:
    """Edits the base case ``base`` (a .rei file) into candidates; ``out``: the search's folder; ``engine``: the
    edit engine's argument vector (default: the built ``rei-room-editor.jar``); ``log`` gets a restart's line;
    ``runs``: the options the search runs every candidate with (default: nav with the humans), for the `rei run`
    line in each written case."""

    def __init__(self, base: Path, out: Path, *, engine: Sequence[str] | None = None,
                 log: Callable[[str], None] = print, runs: RunOptions | None = None) -> None:
        self.out = out
        self.runs = runs or RunOptions()
        self._base = base.resolve()
        self._base_folder = self._base.parent  # the engine resolves the base's imports from there
        self._command = list(engine) if engine is not None else engine_command(
            toolchain.find_jar("room-editor"), toolchain.find_java().executable)
        self._log = log
        self._engine = EditEngine(self._command)
        try:
            answer = self._engine.request("open", path=str(self._base))
        except EngineError as error:
            self._engine.close()
            if not error.refused:  # the engine's own failure, not the base case's
                raise
            raise SpecError(f"{base}: {error}") from None
        errors = [i for i in answer.get("issues") or [] if i.get("severity") == "error"]
        if errors:
            self._engine.close()
            first = errors[0]
            raise SpecError(f"{base}:{first['line']}:{first['column']}: the base case is not valid: {first['message']}")
        self.base_text: str = answer["text"]
        self.diagram: dict[str, Any] = answer["diagram"]
        self.palette: list[dict[str, Any]] = answer.get("palette") or []
        self._generator: JarServer | None = None

    def make(self, key: str, edit: Edit) -> Candidate:
        """The candidate ``key`` from the base case and ``edit``; nothing is written for one that is not valid."""
        try:
            answer = self._edited(key, edit)
        except EngineError as error:
            if not error.refused:  # EngineFailure, or an engine that died or hung: not the candidate's fault
                raise
            return Candidate(key, edit, INVALID, None, (f"refused by the room editor: {error}",))
        errors = [f"{i['line']}:{i['column']}: {i['message']}" for i in answer.get("issues") or []
                  if i.get("severity") == "error"]
        if errors:
            return Candidate(key, edit, INVALID, answer["text"], tuple(errors))
        diagram = answer["diagram"]
        no_path = unplannable(diagram_static_map(diagram), stops(diagram))
        if no_path:
            return Candidate(key, edit, UNPLANNABLE, answer["text"], tuple(no_path))
        return Candidate(key, edit, VALID, answer["text"], diagram=diagram)

    def _edited(self, key: str, edit: Edit) -> dict[str, Any]:
        """The engine's answer to the base case edited by ``edit``; after a failure of the engine (``EngineFailure``,
        or an engine that died or hung) it is started again and asked once more, and a second failure is raised as
        an ``EngineFailure``."""
        try:
            return self._apply(edit)
        except EngineError as error:
            if error.refused:  # the candidate's own fault
                raise
            first = error
        self._log(f"  {key}: the room editor's engine failed inside ({first}); starting it again")
        self._engine.close()
        self._engine = EditEngine(self._command)
        try:
            self._engine.request("open", path=str(self._base))
        except EngineError as error:  # the base case opened before: whatever fails now is the engine's
            raise EngineFailure(f"the room editor's engine failed inside on candidate {key} ({first}) and could not "
                                f"be started again: {error}") from None
        try:
            return self._apply(edit)
        except EngineError as error:
            if error.refused:  # the candidate's own fault
                raise
            raise EngineFailure(f"the room editor's engine failed inside on candidate {key}, and again after a "
                                f"restart: {error}") from None

    def _apply(self, edit: Edit) -> dict[str, Any]:
        # the crowds' and groups' values are set in the text (no operation sets a behaviour or a group's count),
        # so validated with the rest
        answer = self._engine.request("reset", text=edit.text(self.base_text))
        # a point that only sets the run's seed or fault edits nothing: the engine refuses an empty apply
        return self._engine.request("apply", operations=list(edit.operations)) if edit.operations else answer

    def validate(self, text: str) -> list[dict[str, Any]]:
        """The language's issues of ``text`` (another version of the base case), as the engine reports them."""
        issues: list[dict[str, Any]] = self._engine.request("reset", text=text).get("issues") or []
        return issues

    def write(self, candidate: Candidate, path: Path | None = None) -> Path:
        """``OUT/candidates/<key>.rei`` (or ``path``), with the `rei run` line that reproduces its run (seed, fault,
        controller, humans, SUT: rei.search.reproduce) in a comment at its top."""
        assert candidate.text is not None
        path = path or self.out / "candidates" / f"{candidate.key}.rei"
        path.parent.mkdir(parents=True, exist_ok=True)
        first = header(candidate.key, path, candidate.edit.seed, candidate.edit.fault, self.runs)
        path.write_text(f"{first}\n" + relocated_imports(candidate.text, self._base_folder, path.parent),
                        encoding="utf-8")
        return path

    def generate(self, candidate: Candidate) -> tuple[Path, str | None]:
        """Writes the candidate and generates its case folder; (folder, None) or (folder, why it failed: then
        no ``candidates/<key>.rei`` is left)."""
        rei = self.write(candidate)
        target = self.out / "cases" / candidate.key
        target.mkdir(parents=True, exist_ok=True)
        if self._generator is None:
            try:
                self._generator = JarServer("cli", self.out / "cases" / "generator.log").start()
            except (JarServerError, OSError):
                self._generator = None  # each generation then starts a JVM of its own
        result = run_jar("cli", ["generate", str(rei), "-o", str(target), "--quiet"],
                         target.parent / f"{candidate.key}.log",
                         server=self._generator.socket if self._generator is not None else None)
        if result.code != 0:
            rei.unlink(missing_ok=True)  # candidates/ holds cases that ran; cases/<key>.log says what went wrong
            return target, f"{rei.name} could not be generated (exit {result.code}): {result.log_tail}"
        return target, None

    def close(self) -> None:
        self._engine.close()
        if self._generator is not None:
            self._generator.stop()
            self._generator = None


def stops(diagram: dict[str, Any]) -> list[tuple[str, tuple[float, float]]]:
    """The robot's start, then each goal, named by floor."""
    robot = diagram["robot"]
    goals = (diagram.get("mission") or {}).get("goals") or []
    return [(robot["floor"], (float(robot["x"]), float(robot["y"]))),
            *((g["floor"], (float(g["x"]), float(g["y"]))) for g in goals)]
