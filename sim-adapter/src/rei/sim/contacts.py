# SPDX-License-Identifier: EPL-2.0
"""Which named bodies the robot physically touches, read from the physics engine's contact manifold.

Floors are left out: the robot always stands on them. Touching means a contact point at a distance of at most
``TOUCH_DISTANCE`` (the manifold also keeps points that are merely close).
"""

from __future__ import annotations

import pybullet as p

TOUCH_DISTANCE = 1e-3


class ContactSensor:
    __slots__ = ("_body", "_client", "_ignored", "touching")

    def __init__(self, client: int, body: int, ignored: frozenset[int]) -> None:
        self._client = client
        self._body = body
        self._ignored = ignored
        self.touching: frozenset[int] = frozenset()

    def update(self) -> None:
        """Read the contacts of the last physics step."""
        points = p.getContactPoints(bodyA=self._body, physicsClientId=self._client)
        ignored = self._ignored
        found = {pt[2] for pt in points if pt[8] <= TOUCH_DISTANCE and pt[2] not in ignored}
        if found != self.touching:
            self.touching = frozenset(found)
