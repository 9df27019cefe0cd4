# SPDX-License-Identifier: EPL-2.0
"""Which named bodies the robot physically touches, read from the physics engine's contact manifold.

Floors are left out: the robot always stands on them. Touching means a contact point at a distance of at most
``TOUCH_DISTANCE`` (the manifold also keeps points that are merely close).
"""

from __future__ import annotations

import pybullet as p

TOUCH_DISTANCE = 1e-3


class ContactSensor:
    """Touching bodies of the last step, and every body touched since the last :meth:`drain`.

    A bump can begin and end between two samples of the data collector; keeping what was touched in between
    lets a 20 Hz stream still report it (thesis 6.1.3.1: physical contacts count as collision).
    """

    __slots__ = ("_body", "_client", "_ignored", "_since", "touching")

    def __init__(self, client: int, body: int, ignored: frozenset[int]) -> None:
        self._client = client
        self._body = body
        self._ignored = ignored
        self.touching: frozenset[int] = frozenset()
        self._since: set[int] = set()

    def update(self) -> None:
        """Read the contacts of the last physics step."""
        points = p.getContactPoints(bodyA=self._body, physicsClientId=self._client)
        ignored = self._ignored
        found = {pt[2] for pt in points if pt[8] <= TOUCH_DISTANCE and pt[2] not in ignored}
        if found != self.touching:
            self.touching = frozenset(found)
        self._since.update(found)

    def drain(self) -> frozenset[int]:
        """Bodies touched at any step since the previous call (those touching now included)."""
        touched = frozenset(self._since) | self.touching
        self._since.clear()
        return touched
