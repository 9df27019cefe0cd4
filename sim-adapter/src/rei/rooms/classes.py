# SPDX-License-Identifier: EPL-2.0
"""The room classes of thesis 7.4: small rooms with densely placed objects, medium rooms with a walking human,
large rooms. A class fixes the grid, how many objects a density means, the number of goals and the default
number of humans; the generator draws everything else from the seed.

Why these numbers: the thesis's small rooms hold 10 objects densely placed and its missions have two tasks
(Table 6: 8 task starts in 4 executions); a 7 x 5 m grid is the smallest that fits 10 objects with the start,
both goals and their free neighbours, and every floor still reachable. Medium and large scale the floor area by
about 2 and 4.5 and keep the same share of furnished floors per density.
"""

from __future__ import annotations

from dataclasses import dataclass

SIZES = ("small", "medium", "large")
DENSITIES = ("dense", "sparse")


@dataclass(frozen=True, slots=True)
class RoomClass:
    """One size of room: a ``width`` x ``height`` grid of 1 m floors."""

    size: str
    width: int
    height: int
    dense_objects: int
    sparse_objects: int
    goals: int
    default_density: str
    default_humans: int

    def objects(self, density: str) -> int:
        if density not in DENSITIES:
            raise ValueError(f"density must be one of {', '.join(DENSITIES)}, got {density!r}")
        return self.dense_objects if density == "dense" else self.sparse_objects


ROOM_CLASSES: dict[str, RoomClass] = {
    "small": RoomClass("small", 7, 5, dense_objects=10, sparse_objects=5, goals=2,
                       default_density="dense", default_humans=0),
    "medium": RoomClass("medium", 10, 7, dense_objects=18, sparse_objects=9, goals=2,
                        default_density="sparse", default_humans=1),
    "large": RoomClass("large", 15, 10, dense_objects=40, sparse_objects=20, goals=3,
                       default_density="sparse", default_humans=2),
}

#: Humans a room of each class can hold: every human needs its own straight lane of free floors.
MAX_HUMANS = {"small": 2, "medium": 3, "large": 4}


def room_class(size: str) -> RoomClass:
    try:
        return ROOM_CLASSES[size]
    except KeyError:
        raise ValueError(f"size must be one of {', '.join(SIZES)}, got {size!r}") from None
