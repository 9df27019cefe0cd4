# SPDX-License-Identifier: EPL-2.0
"""Everything a report needs from one run folder, read once and tolerant of what is missing.

Why one loader: the HTML report and the MCAP file show the same run, and a run folder is often incomplete (the
run ended in ERROR, the evaluator was not part of it, the case was generated elsewhere). Each missing piece is
noted in `RunData.notes` in words a person understands, so a report says "no signals recorded" instead of
failing or showing an empty plot without explanation.
"""

from __future__ import annotations

import csv
import json
import math
import xml.etree.ElementTree as ET
from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from rei.artifacts import ArtifactError, read_world_map
from rei.maps import MapPicture, OccupancyMap, map_picture
from rei.wamp.recording import iter_recording, stream_path


@dataclass(frozen=True, slots=True)
class SignalRecord:
    """One monitor signal (`{seq, t, signal, subject, object, distance}`); distance is NaN when not known."""

    t: float
    signal: str
    subject: str
    object: str
    distance: float = math.nan


@dataclass(frozen=True, slots=True)
class EventRow:
    """One line of the evaluator's events.csv: a signal with its utility and the running total."""

    t: float
    signal: str
    utility: float
    total: float
    subject: str
    object: str


@dataclass(frozen=True, slots=True)
class Goal:
    """A mission goal from mission.xml (world frame, metres)."""

    index: int
    x: float
    y: float
    tolerance: float


@dataclass(slots=True)
class RunData:
    """What was found in a run folder. `None` / empty means "not there"; `notes` says why."""

    out_dir: Path
    case_dir: Path
    world: dict[str, Any] | None = None
    occupancy: OccupancyMap | None = None  # a room from an occupancy map: its map
    picture: MapPicture | None = None  # ... and the map's picture, drawn under the floors
    mission_name: str | None = None
    goals: list[Goal] = field(default_factory=list)
    mission_events: list[dict[str, Any]] = field(default_factory=list)
    signals: list[SignalRecord] = field(default_factory=list)
    signals_source: str | None = None
    events: list[EventRow] | None = None
    summary: dict[str, Any] | None = None
    sim: dict[str, Any] | None = None
    state_count: int = 0
    notes: list[str] = field(default_factory=list)

    def states(self) -> Iterator[dict[str, Any]]:
        """The recorded state messages, streamed (a long run's recording does not fit comfortably in memory).

        A truncated last message (a crashed writer) ends the stream quietly: what was recorded is still shown.
        """
        path = stream_path(self.out_dir, "state")
        if not path.is_file():
            return
        try:
            yield from iter_recording(path)
        except ValueError:
            return

    def fact(self, *keys: str) -> Any:
        """The first of `keys` found in summary.json, else in sim.json (so facts survive without an evaluator)."""
        for source in (self.summary, self.sim):
            if source is None:
                continue
            for key in keys:
                if source.get(key) is not None:
                    return source[key]
        return None


def load_run(out_dir: Path, case_dir: Path | None = None) -> RunData:
    """Read the run folder `out_dir`; the case (world.json, mission.xml) is in `case_dir`, default OUT/case."""
    out_dir = Path(out_dir)
    data = RunData(out_dir=out_dir, case_dir=Path(case_dir) if case_dir else out_dir / "case")
    data.world = _read_json(data.case_dir / "world.json", data.notes, "no world.json: the map is not drawn")
    data.occupancy = _read_occupancy(data)
    data.picture = map_picture(data.occupancy) if data.occupancy is not None else None
    _read_mission_xml(data)
    data.summary = _read_json(out_dir / "summary.json", data.notes,
                              "no summary.json: no verdicts (the evaluator did not run)")
    data.sim = _read_json(out_dir / "sim.json", None, None)
    data.mission_events = _read_stream(out_dir, "mission", data.notes)
    data.events = _read_events(out_dir / "events.csv", data.notes)
    signals = _read_stream(out_dir, "signal", None)
    if signals:
        data.signals = [_signal(message) for message in signals if isinstance(message, Mapping)]
        data.signals_source = "streams/signal.msgpack"
    elif data.events:
        data.signals = [SignalRecord(e.t, e.signal, e.subject, e.object) for e in data.events]
        data.signals_source = "events.csv"
    else:
        data.notes.append("no signals recorded (neither streams/signal.msgpack nor events.csv)")
    if not stream_path(out_dir, "state").is_file():
        data.notes.append("no streams/state.msgpack: no robot path")
    return data


def _read_json(path: Path, notes: list[str] | None, missing: str | None) -> dict[str, Any] | None:
    if not path.is_file():
        if notes is not None and missing:
            notes.append(missing)
        return None
    try:
        value = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError) as error:
        if notes is not None:
            notes.append(f"{path.name} could not be read: {error}")
        return None
    return value if isinstance(value, dict) else None


def _read_occupancy(data: RunData) -> OccupancyMap | None:
    """The occupancy map of a map room (world.json's ``map``): drawn under the floors, and the MCAP's /map."""
    if data.world is None or data.world.get("map") is None:
        return None
    try:
        spec = read_world_map(data.case_dir / "world.json")
        return spec.load() if spec is not None else None
    except ArtifactError as error:
        data.notes.append(f"the room's occupancy map is not drawn: {error}")
        return None


def _read_mission_xml(data: RunData) -> None:
    path = data.case_dir / "mission.xml"
    if not path.is_file():
        return
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as error:
        data.notes.append(f"mission.xml could not be read: {error}")
        return
    data.mission_name = root.get("name")
    for goal in root.iter("goal"):
        try:
            data.goals.append(Goal(int(goal.get("index", len(data.goals))), float(goal.get("x", "nan")),
                                   float(goal.get("y", "nan")), float(goal.get("tolerance", "0"))))
        except ValueError:
            continue


def _read_stream(out_dir: Path, name: str, notes: list[str] | None) -> list[dict[str, Any]]:
    path = stream_path(out_dir, name)
    if not path.is_file():
        return []
    messages: list[dict[str, Any]] = []
    try:
        for message in iter_recording(path):
            if isinstance(message, dict):
                messages.append(message)
    except ValueError as error:
        if notes is not None:
            notes.append(str(error))
    return messages


def _signal(message: Mapping[str, Any]) -> SignalRecord:
    distance = message.get("distance")
    return SignalRecord(float(message.get("t", math.nan)), str(message.get("signal", "?")),
                        str(message.get("subject", "")), str(message.get("object", "")),
                        float(distance) if isinstance(distance, int | float) else math.nan)


def _read_events(path: Path, notes: list[str]) -> list[EventRow] | None:
    """events.csv as rows; None when the file is absent. Rows that do not parse are skipped and counted."""
    if not path.is_file():
        notes.append("no events.csv: no utility over time (the evaluator did not run)")
        return None
    rows: list[EventRow] = []
    bad = 0
    with open(path, newline="", encoding="utf-8") as f:
        for row in csv.DictReader(f):
            try:
                rows.append(EventRow(float(row["t"]), row["signal"], float(row["utility"]), float(row["total"]),
                                     row.get("subject") or "", row.get("object") or ""))
            except (KeyError, TypeError, ValueError):
                bad += 1
    if bad:
        notes.append(f"events.csv: {bad} line(s) could not be read and were left out")
    return rows
