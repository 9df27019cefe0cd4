# SPDX-License-Identifier: EPL-2.0
"""A spec expanded into what to prepare (one generated case folder per test case) and what to run.

Pure: no files are written (a behaviour variant of a .rei file reads it), so the order and names of runs can be
tested, and a resumed campaign plans exactly the same runs. A run's key names its folder (``OUT/runs/<key>``) and
stays the same across resumes.

A variant with a ``behaviour`` runs the group's cases with every person who sees the robot behaving so: a generated
room is generated again with that behaviour (the same room: the people's draws do not depend on it, only the word
after their route), a .rei file is rewritten (rei.edit.gatherings.with_behaviour); each is a case of its own
(``OUT/cases/<its key>``), while its runs keep the room's name as their ``case``, so reports and `rei compare`
pair and group them by room and by variant.
"""

from __future__ import annotations

import dataclasses
import json
import re
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

from rei.campaign.spec import Group, Spec, SpecError

_UNSAFE = re.compile(r"[^A-Za-z0-9_-]+")


@dataclass(frozen=True, slots=True)
class CaseSource:
    """One test case of the campaign: a .rei file, a generated case folder, or a generated room's text."""

    key: str
    group: str
    path: Path | None  # .rei file or generated folder; None for a generated room
    text: str | None  # .rei text of a generated room

    def rei_file(self, out: Path) -> Path | None:
        """Where the .rei file to generate from is (generated rooms are written to ``OUT/rooms`` first)."""
        if self.text is not None:
            return out / "rooms" / f"{self.key}.rei"
        return self.path if self.path is not None and self.path.suffix == ".rei" else None

    def case_dir(self, out: Path) -> Path:
        if self.path is not None and self.path.suffix != ".rei":
            return self.path
        return out / "cases" / self.key


@dataclass(frozen=True, slots=True)
class RunTask:
    """Everything a worker needs for one run; JSON-able (it travels to worker processes and Ray nodes)."""

    key: str
    group: str
    case: str
    variant: str
    repetition: int
    seed: int
    humans: bool
    fault: str | None
    controller: str
    mode: str
    timeout: float
    report: bool
    case_dir: str
    run_dir: str
    sut: dict[str, Any] | None = None  # rei.campaign.spec.ExternalSut as a dict; None: the in-process controller
    # the user's VEPL patterns (a folder of *.vepl, as `rei run --patterns`) besides the defaults, and a utility
    # YAML file (`rei run --utilities`); absolute paths, None: the defaults only / the declared utilities
    patterns: str | None = None
    utilities: str | None = None
    #: the digest of what its case folder was generated from (rei.campaign.prepare's stamp), set once the cases
    #: are prepared: a run of an earlier version of its case (its .rei edited since) is not finished
    case_stamp: str | None = None

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> RunTask:
        return cls(**data)


#: A run folder's task (what the run is): written before it runs, or by the driver for a run that ran nowhere; with
#: a result.json beside it, the run is finished.
TASK_FILE = "task.json"


def write_task(task: RunTask, folder: Path) -> None:
    """``folder``/task.json, the folder made if need be."""
    folder.mkdir(parents=True, exist_ok=True)
    (folder / TASK_FILE).write_text(json.dumps(task.to_dict(), indent=2) + "\n", encoding="utf-8")


@dataclass(frozen=True, slots=True)
class Plan:
    cases: tuple[CaseSource, ...]
    runs: tuple[RunTask, ...]


def _sources(group: Group, out: Path, behaviour: str | None = None) -> list[CaseSource]:
    """The group's cases, with every person who sees the robot behaving ``behaviour`` (None: as written)."""
    from rei.campaign.prepare import relocated_imports
    from rei.edit.gatherings import with_behaviour
    from rei.rooms import render

    sources: list[CaseSource] = []
    if group.rooms is not None:
        r = group.rooms if behaviour is None else dataclasses.replace(group.rooms, reactive=behaviour)
        for room in r.generate():
            sources.append(CaseSource(room.stem, group.name, None, render(room, r.count, out / "rooms")))
        return sources
    for path in group.cases:
        stem = _UNSAFE.sub("_", path.stem if path.suffix == ".rei" else path.name)
        if behaviour is None:
            sources.append(CaseSource(stem, group.name, path, None))
        else:  # checked by the spec: a .rei file with people who see the robot; written to OUT/rooms
            text = with_behaviour(path.read_text(encoding="utf-8"), behaviour)
            sources.append(CaseSource(f"{stem}-{behaviour}", group.name, None,
                                      relocated_imports(text, path.parent, out / "rooms")))
    return sources


def _uncommented(text: str | None) -> str | None:
    """A generated room's text without its comments: the same room of two groups whose settings differ only in
    ``count`` is written with another header ('room 1 of 2'), and is the same case."""
    if text is None:
        return None
    return "\n".join(line for line in text.splitlines() if not line.lstrip().startswith("//"))


def plan_campaign(spec: Spec, out: Path) -> Plan:
    out = out.resolve()
    cases: dict[str, CaseSource] = {}
    runs: list[RunTask] = []

    def add(source: CaseSource) -> None:
        known = cases.get(source.key)
        if known is not None and (known.path, _uncommented(known.text)) != (source.path, _uncommented(source.text)):
            what = ("give one group other room settings" if known.text is not None and source.text is not None
                    else "rename one file")
            raise SpecError(f"two different test cases are both named {source.key!r} (groups {known.group!r} "
                            f"and {source.group!r}); {what}")
        cases.setdefault(source.key, source)

    for group in spec.groups:
        sources = _sources(group, out)
        behaviours = {b: _sources(group, out, b) for b in dict.fromkeys(v.behaviour for v in group.variants) if b}
        for index, source in enumerate(sources):
            if any(v.behaviour is None for v in group.variants):
                add(source)
            for variant in group.variants:
                # the variant's own version of the case: the same room, its people behaving as the variant says
                own = source if variant.behaviour is None else behaviours[variant.behaviour][index]
                if own is not source:
                    add(own)
                for rep in range(group.repetitions):
                    key = f"{group.name}__{source.key}__{variant.name}__r{rep}"
                    runs.append(RunTask(
                        key=key, group=group.name, case=source.key, variant=variant.name, repetition=rep,
                        seed=spec.seed + rep, humans=variant.humans, fault=variant.fault,
                        controller=variant.controller, sut=variant.sut.to_dict() if variant.sut else None,
                        mode=spec.mode, timeout=spec.timeout, report=spec.report,
                        case_dir=str(own.case_dir(out)), run_dir=str(out / "runs" / key),
                        patterns=str(spec.patterns) if spec.patterns else None,
                        utilities=str(spec.utilities) if spec.utilities else None))
    return Plan(tuple(cases.values()), tuple(runs))
