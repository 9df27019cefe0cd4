# SPDX-License-Identifier: EPL-2.0
"""Zone episodes: the intervals in which the geometry (or the laser) had the robot CLOSE or in COLLISION.

The monitor publishes transitions only (FAR->CLOSE, CLOSE->COLLISION, ...), one state machine per source
that starts in FAR (docs/monitor.md). Comparing the laser with the geometry, and counting collisions, needs
the intervals between them: a *proximity* episode lasts from leaving FAR until returning to FAR (it may pass
through COLLISION), a *collision* episode from entering COLLISION until leaving it. An episode still open when
the run ends has ``end`` None.

A transition whose "from" zone is not the zone the source is in means a signal was lost or the monitor is
inconsistent; it is recorded (and the verdicts that depend on zones become errors), then followed.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field

from rei.evaluation.outcome import Evidence
from rei.evaluation.signals import Signal, Source, Transition, Zone


@dataclass(slots=True)
class Episode:
    source: Source
    level: Zone  # CLOSE: proximity episode (CLOSE or deeper); COLLISION: collision episode
    start: float
    object: str  # what the monitor named at entry (geometry: the nearest / colliding obstacle; laser: laser)
    end: float | None = None

    def end_or(self, run_end: float) -> float:
        return self.end if self.end is not None else max(run_end, self.start)


@dataclass(slots=True)
class Timeline:
    episodes: dict[tuple[Source, Zone], list[Episode]] = field(default_factory=dict)
    inconsistencies: dict[Source, list[Evidence]] = field(default_factory=dict)

    def inconsistent(self, *sources: Source) -> list[Evidence]:
        """The inconsistencies of ``sources``: a missing transition only taints the zones it belongs to."""
        return [e for source in sources for e in self.inconsistencies.get(source, [])]

    def of(self, source: Source, level: Zone) -> list[Episode]:
        return self.episodes.get((source, level), [])


def build_timeline(signals: Iterable[Signal], transitions: Mapping[str, Transition]) -> Timeline:
    """The episodes of the zone changes among ``signals``; ``transitions``: what each signal declares."""
    timeline = Timeline({(s, z): [] for s in Source for z in (Zone.CLOSE, Zone.COLLISION)},
                        {s: [] for s in Source})
    zone = dict.fromkeys(Source, Zone.FAR)
    open_: dict[tuple[Source, Zone], Episode | None] = dict.fromkeys(timeline.episodes, None)
    for signal in signals:
        step = transitions.get(signal.signal)
        if step is None or step.per_object:  # the robot's own zone only: objects have episodes of their own
            continue
        source, before, after = step.source, zone[step.source], step.after
        if step.before != before:
            timeline.inconsistencies[source].append(Evidence(
                f"{signal.signal} while the {source.lower()} zone was {before.name}: a transition is missing",
                signal.t, signal.signal, signal.object))
        if before == Zone.FAR and after >= Zone.CLOSE:
            episode = Episode(source, Zone.CLOSE, signal.t, signal.object)
            open_[(source, Zone.CLOSE)] = episode
            timeline.episodes[(source, Zone.CLOSE)].append(episode)
        if after == Zone.COLLISION and before < Zone.COLLISION:
            episode = Episode(source, Zone.COLLISION, signal.t, signal.object)
            open_[(source, Zone.COLLISION)] = episode
            timeline.episodes[(source, Zone.COLLISION)].append(episode)
        if before == Zone.COLLISION and after < Zone.COLLISION:
            _close(open_, (source, Zone.COLLISION), signal.t)
        if after == Zone.FAR and before >= Zone.CLOSE:
            _close(open_, (source, Zone.CLOSE), signal.t)
        zone[source] = after
    return timeline


def _close(open_: dict[tuple[Source, Zone], Episode | None], key: tuple[Source, Zone], t: float) -> None:
    episode = open_[key]
    if episode is not None:
        episode.end = t
        open_[key] = None
