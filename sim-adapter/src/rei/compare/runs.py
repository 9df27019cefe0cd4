# SPDX-License-Identifier: EPL-2.0
"""The runs of the two sides of a comparison, and their pairs.

A side is a campaign folder (``OUT/runs/<key>/result.json``, as ``rei campaign`` writes them) or one run folder
(``summary.json``, as ``rei run`` and ``rei evaluate`` write it). Runs pair when they have the same group, case,
variant, seed and fault (the canonical text of the fault the run carried, rei.campaign.aggregate.fault_label,
``none`` without one) - the same room driven under the same conditions - so the difference of a pair is the change
of the system under test alone: a variant whose fault changed between the two campaigns does not pair. Runs without a partner, and runs that ended in ERROR (they have no metrics) with
their partner, are listed, never silently dropped. A campaign's runs are the ones its last invocation planned
(``campaign.json``): a run folder that a resume with an edited spec left behind is not one of them.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from rei.campaign.aggregate import NO_FAULT, fault_label
from rei.campaign.results import RESULT_FILE


class CompareError(ValueError):
    """A side that is neither a campaign nor a run folder; the message names the folder."""


@dataclass(frozen=True, slots=True)
class Run:
    key: str
    group: str
    case: str
    variant: str
    seed: int
    status: str
    folder: Path
    metrics: dict[str, Any] = field(default_factory=dict)
    error: str | None = None
    fault: str = NO_FAULT  # canonical (fault_label)

    @property
    def pair_key(self) -> tuple[str, str, str, int, str]:
        return (self.group, self.case, self.variant, self.seed, self.fault)


@dataclass(frozen=True, slots=True)
class Pairing:
    pairs: tuple[tuple[Run, Run], ...]  # (baseline, candidate), both COMPLETED
    only_baseline: tuple[Run, ...]
    only_candidate: tuple[Run, ...]
    #: (baseline, candidate) with a side not COMPLETED: neither is compared, both are listed
    errors: tuple[tuple[Run, Run], ...]


def load_side(folder: Path) -> list[Run]:
    folder = Path(folder)
    if not folder.is_dir():
        raise CompareError(f"{folder}: no such folder")
    runs_dir = folder / "runs"
    results = sorted(runs_dir.glob(f"*/{RESULT_FILE}")) if runs_dir.is_dir() else []
    planned = _planned(folder)
    if planned is not None:  # a folder left by a variant, group or repetition the spec no longer has is no run of it
        return [_campaign_run(path) for path in results if path.parent.name in planned]
    if results:
        return [_campaign_run(path) for path in results]
    if (folder / "summary.json").is_file():
        return [_single_run(folder)]
    raise CompareError(f"{folder}: neither a campaign folder (runs/*/{RESULT_FILE}) nor a run folder "
                       "(summary.json)")


def pair(baseline: list[Run], candidate: list[Run]) -> Pairing:
    theirs = {r.pair_key: r for r in candidate}
    ours = {r.pair_key: r for r in baseline}
    pairs: list[tuple[Run, Run]] = []
    errors: list[tuple[Run, Run]] = []
    for key, b in ours.items():
        c = theirs.get(key)
        if c is None:
            continue
        if b.status != "COMPLETED" or c.status != "COMPLETED":
            errors.append((b, c))
            continue
        pairs.append((b, c))
    return Pairing(tuple(pairs), tuple(r for k, r in ours.items() if k not in theirs),
                   tuple(r for k, r in theirs.items() if k not in ours), tuple(errors))


def _campaign_run(path: Path) -> Run:
    data = _json(path)
    try:
        return Run(key=str(data["key"]), group=str(data["group"]), case=str(data["case"]),
                   variant=str(data["variant"]), seed=int(data["seed"]), status=str(data["status"]),
                   folder=path.parent, metrics=dict(data.get("metrics") or {}), error=data.get("error"),
                   fault=fault_label(data.get("fault")))
    except (KeyError, TypeError, ValueError) as error:
        raise CompareError(f"{path}: not a campaign run's result ({error})") from None


def _planned(folder: Path) -> frozenset[str] | None:
    """The keys of the runs the campaign's last invocation planned (``campaign.json``'s ``runs``, the runs its
    ``runs.csv`` and summaries are made of); None without that file (a campaign still in its first invocation)."""
    path = folder / "campaign.json"
    if not path.is_file():
        return None
    runs = _json(path).get("runs")
    if not isinstance(runs, list):
        raise CompareError(f"{path}: 'runs' is not a list of run keys")
    return frozenset(map(str, runs))


def _single_run(folder: Path) -> Run:
    """A run folder pairs with the other side's by its test case, seed and ``--fault`` (group and variant are
    empty)."""
    summary = _json(folder / "summary.json")
    sim = _json(folder / "sim.json") if (folder / "sim.json").is_file() else {}
    options = (sim.get("options") or {}) if isinstance(sim, dict) else {}
    seed = options.get("seed", 0)
    case = str(summary.get("testcase") or folder.name)
    return Run(key=folder.name, group="", case=case, variant="", seed=int(seed or 0),
               status=str(summary.get("status", "ERROR")), folder=folder,
               metrics=dict(summary.get("metrics") or {}), error=summary.get("error"),
               fault=fault_label(options.get("fault")))


def _json(path: Path) -> Any:
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as error:
        raise CompareError(f"{path}: cannot read: {error}") from None
    if not isinstance(data, dict):
        raise CompareError(f"{path}: expected a JSON object")
    return data
