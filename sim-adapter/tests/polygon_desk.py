# SPDX-License-Identifier: EPL-2.0
"""A POLYGON object in the fixture room (docs/language.md#catalogues), as the generator writes one, for the tests of
the simulator, the metrics and the report."""

from __future__ import annotations

import json
from pathlib import Path

#: A C-shaped desk about its centre, counter-clockwise: its notch, 0.7 m wide and 0.6 m deep, opens towards -x.
C_DESK = ((-0.5, -0.7), (0.5, -0.7), (0.5, 0.7), (-0.5, 0.7), (-0.5, 0.35), (0.1, 0.35), (0.1, -0.35), (-0.5, -0.35))
C_DESK_POSE = (3.5, 1.0, 0.375, 0.0)


def add_polygon_desk(case: Path, points: tuple[tuple[float, float], ...] = C_DESK,
                     pose: tuple[float, float, float, float] = C_DESK_POSE) -> Path:
    """Make the fixture room's table1 in ``case`` a POLYGON object (as the generator writes one: world.json's
    footprint about its pose, world.sdf's polyline from the floor up), by default the C-shaped desk at (3.5, 1.0),
    its notch facing the robot on (1, 1): driving straight ahead the robot enters the notch."""
    world = json.loads((case / "world.json").read_text(encoding="utf-8"))
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    height = 2 * pose[2]
    for obj in world["objects"]:
        if obj["name"] == "table1":
            obj.update(shape="POLYGON", type="Desk", size=[max(xs) - min(xs), max(ys) - min(ys), height],
                       pose=list(pose), floor="F_1_0", footprint={"type": "polygon", "points": [list(p) for p in points]})
    (case / "world.json").write_text(json.dumps(world), encoding="utf-8")
    sdf = (case / "world.sdf").read_text(encoding="utf-8")
    start = sdf.index('<model name="table1">')
    end = sdf.index("</model>", start) + len("</model>")
    polyline = "".join(f"<point>{x} {y}</point>" for x, y in points) + f"<height>{height}</height>"
    geometry = f"<pose>0 0 {-height / 2} 0 0 0</pose><geometry><polyline>{polyline}</polyline></geometry>"
    model = (f'<model name="table1"><static>true</static><pose>{pose[0]} {pose[1]} {pose[2]} 0 0 {pose[3]}</pose>'
             '<link name="link"><inertial><mass>0</mass><inertia><ixx>0</ixx><ixy>0</ixy><ixz>0</ixz><iyy>0</iyy>'
             f'<iyz>0</iyz><izz>0</izz></inertia></inertial><collision name="collision">{geometry}</collision>'
             f'<visual name="visual">{geometry}</visual></link></model>')
    (case / "world.sdf").write_text(sdf[:start] + model + sdf[end:], encoding="utf-8")
    return case

