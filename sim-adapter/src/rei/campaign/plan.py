# SPDX-License-Identifier: EPL-2.0
"""A spec expanded into what to prepare (one generated case folder per test case) and what to run.

Pure: no files are touched, so the order and names of runs can be tested, and a resumed campaign plans exactly
the same runs. A run's key names its folder (``OUT/runs/<key>``) and stays the same across resumes.
"""

from __future__ import annotations

import re
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

from rei.campaign.spec import Spec, SpecError

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

    def to_dict(self) -> dict[str, Any]:
        return asdict(self)

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> RunTask:
        return cls(**data)


@dataclass(frozen=True, slots=True)
class Plan:
    cases: tuple[CaseSource, ...]
    runs: tuple[RunTask, ...]


def plan_campaign(spec: Spec, out: Path) -> Plan:
    from rei.rooms import render

    out = out.resolve()
    cases: dict[str, CaseSource] = {}
    runs: list[RunTask] = []
    for group in spec.groups:
        sources: list[CaseSource] = []
        if group.rooms is not None:
            r = group.rooms
            for room in r.generate():
                sources.append(CaseSource(room.stem, group.name, None, render(room, r.count, out / "rooms")))
        else:
            for path in group.cases:
                stem = path.stem if path.suffix == ".rei" else path.name
                sources.append(CaseSource(_UNSAFE.sub("_", stem), group.name, path, None))
        for source in sources:
            known = cases.get(source.key)
            if known is not None and (known.path, known.text) != (source.path, source.text):
                raise SpecError(f"two different test cases are both named {source.key!r} (groups {known.group!r} "
                                f"and {source.group!r}); rename one file")
            cases.setdefault(source.key, source)
            for variant in group.variants:
                for rep in range(group.repetitions):
                    key = f"{group.name}__{source.key}__{variant.name}__r{rep}"
                    runs.append(RunTask(
                        key=key, group=group.name, case=source.key, variant=variant.name, repetition=rep,
                        seed=spec.seed + rep, humans=variant.humans, fault=variant.fault,
                        controller=variant.controller, sut=variant.sut.to_dict() if variant.sut else None,
                        mode=spec.mode, timeout=spec.timeout, report=spec.report,
                        case_dir=str(source.case_dir(out)), run_dir=str(out / "runs" / key),
                        patterns=str(spec.patterns) if spec.patterns else None,
                        utilities=str(spec.utilities) if spec.utilities else None))
    return Plan(tuple(cases.values()), tuple(runs))
