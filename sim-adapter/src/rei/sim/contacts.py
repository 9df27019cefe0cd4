# SPDX-License-Identifier: EPL-2.0
"""Which named bodies the robot physically touches, read from the physics engine's contact manifold.

Floors are left out: the robot always stands on them. Touching means a contact point at a distance of at most
``TOUCH_DISTANCE`` (the manifold also keeps points that are merely close).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import pybullet as p

TOUCH_DISTANCE = 1e-3


NameAt = Callable[[int, Sequence[float]], str | None]
"""The model a contact point belongs to, from the body and the point's position on it (None: no model)."""


class ContactSensor:
    """Names of the models touched at the last step, and of every one touched since the last :meth:`drain`.

    A bump can begin and end between two samples of the data collector; keeping what was touched in between
    lets a 20 Hz stream still report it (thesis 6.1.3.1: physical contacts count as collision). A body may hold
    many models (a large room's merged walls), hence the name from the body and the point.
    """

    __slots__ = ("_body", "_client", "_ignored", "_name_at", "_since", "touching")

    def __init__(self, client: int, body: int, ignored: frozenset[int], name_at: NameAt) -> None:
        self._client = client
        self._body = body
        self._ignored = ignored
        self._name_at = name_at
        self.touching: frozenset[str] = frozenset()
        self._since: set[str] = set()

    def update(self) -> None:
        """Read the contacts of the last physics step."""
        points = p.getContactPoints(bodyA=self._body, physicsClientId=self._client)
        ignored = self._ignored
        name_at = self._name_at
        found: set[str] = set()
        for pt in points:
            if pt[8] <= TOUCH_DISTANCE and pt[2] not in ignored:
                name = name_at(pt[2], pt[6])
                if name is not None:
                    found.add(name)
        if found != self.touching:
            self.touching = frozenset(found)
        self._since.update(found)

    def drain(self) -> frozenset[str]:
        """Models touched at any step since the previous call (those touching now included)."""
        touched = frozenset(self._since) | self.touching
        self._since.clear()
        return touched
