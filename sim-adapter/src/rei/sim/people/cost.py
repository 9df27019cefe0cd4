# SPDX-License-Identifier: EPL-2.0
"""What the robot cost the people: each person's delay and detour against the same people, seed and bodies on
rails without the robot (the model alone, no physics: cheap), run after the mission (docs/people.md).

A person's *delay* is how much later it reached its stops with the robot: the time of its K-th arrival at a stop
with the robot less without, K the last arrival it made in both runs. When without the robot it reached more stops,
the next one was not reached with the robot by the end of the run: the delay is then at least the time from that
arrival without the robot to the end, and it is the larger of the two (``censored``: a lower bound). Its *detour* is
how much farther it had walked by its K-th arrival. A person who reached no stop in one of the runs has no detour,
and no delay unless it is censored.
"""

from __future__ import annotations

from typing import Any

from rei.sim.people.crowd import Crowd


def people_cost(crowd: Crowd, end: float) -> dict[str, dict[str, Any]]:
    """Per person (by name): its arrivals and distance walked in the run and without the robot, delay and detour;
    ``end``: the run's last simulated time."""
    alone = crowd.without_robot()
    found = {}
    for walker, real, ghost in zip(crowd.walkers, crowd.walked, alone, strict=True):
        both = min(len(real.arrivals), len(ghost.arrivals))
        delay = detour = None
        if both:
            delay = real.arrivals[both - 1] - ghost.arrivals[both - 1]
            detour = real.walked_at[both - 1] - ghost.walked_at[both - 1]
        censored = len(ghost.arrivals) > len(real.arrivals)
        if censored:
            bound = end - ghost.arrivals[len(real.arrivals)]
            delay = bound if delay is None else max(delay, bound)
        found[walker.spec.name] = {
            "delay": _round(delay), "detour": _round(detour), "censored": censored,
            "arrivals": [round(t, 3) for t in real.arrivals], "walked": round(real.walked, 3),
            "arrivals_without_robot": [round(t, 3) for t in ghost.arrivals],
            "walked_without_robot": round(ghost.walked, 3)}
    return found


def _round(value: float | None) -> float | None:
    return None if value is None else round(value, 3)

