# SPDX-License-Identifier: EPL-2.0
"""Loads world.sdf into a pybullet client and checks it against world.json.

pybullet's ``loadSDF`` returns bare body ids and ignores ``<static>``; downstream code speaks in model names and
needs fixed bodies to really be fixed. So the loader keeps the name <-> id map and refuses a world whose bodies
(count, names, order, fixedness) differ from world.json, naming the file and the first difference.

Large rooms (an occupancy map's thousands of wall rectangles, a big grid's floors) do not fit one body per model:
``loadSDF`` refuses more than ``SDF_BODY_LIMIT`` models, and every body costs each physics step (about 8 us per
body: 10,000 walls made a step 80 ms). Beyond that limit, the walls and the floors, which never move, are merged:
fixed bodies whose compound shapes hold up to ``COMPOUND_LIMIT`` boxes each (pybullet's most), boxes near each
other together (Z-order of their centres), so the broadphase still sees small bodies where they are; the other
models are loaded from world.sdf as before. A contact with a merged body is named after its box nearest the
contact point.

A room from an occupancy map stands on one ground slab under the whole map, so its floors (the free blocks, named
places only) get no collision body of their own: each floor's name maps to the slab, whose contact points are
named after the floor block nearest them. Only the models that do become bodies count towards the merge limit.

Models named ``fixed`` (the reactive people, whom the simulation places itself at each crowd step) are loaded as
fixed rigid bodies, not as pybullet's multibodies: their own models from a copy of world.sdf, with mass 0, in
maximal coordinates, so their collision shapes are the ones ``loadSDF`` builds for them anyway (a cylinder is a
convex hull of 32 sides). A fixed rigid body costs a physics step nearly nothing; a moving multibody costs its
dynamics and, every few steps, its broadphase bounds. Being fixed, they meet no other fixed body (walls, floors,
furniture, each other) in pybullet's collision filter.
"""

from __future__ import annotations

import math
import tempfile
import xml.etree.ElementTree as ET
from collections.abc import Collection, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from types import MappingProxyType

import numpy as np
import pybullet as p

from rei.artifacts.errors import ArtifactError
from rei.artifacts.world import Category, ObjectSpec, Shape, WorldSpec
from rei.geometry import quaternion_of_yaw, triangulate
from rei.sim.native_output import quiet_native_output

GRAVITY = 9.81
SDF_BODY_LIMIT = 512
"""The most models pybullet's ``loadSDF`` loads from one file ("SDF exceeds body capacity")."""
COMPOUND_LIMIT = 16
"""The most children pybullet's ``createCollisionShapeArray`` keeps (it drops the others silently)."""
MERGE_ABOVE = SDF_BODY_LIMIT
"""Worlds of more models than this (not counting a map room's floors) have their walls and floors merged."""
MERGED_CATEGORIES = (Category.WALL, Category.FLOOR)
GROUND = 0.01
"""Thickness (m) of the ground under a room from an occupancy map: a floor's (the generator's floor slabs)."""


@dataclass(frozen=True, slots=True)
class MergedBoxes:
    """Boxes of many fixed models in one body: which model a point on its surface belongs to."""

    body: int
    names: tuple[str, ...]
    centres: np.ndarray  # (n, 2) world x, y
    half: np.ndarray  # (n, 2) half extents along the box's own axes
    cos_sin: np.ndarray  # (n, 2) cos and sin of each box's yaw

    def name_at(self, x: float, y: float) -> str:
        """The model whose box is nearest ``(x, y)`` (a contact point lies on its surface)."""
        dx, dy = x - self.centres[:, 0], y - self.centres[:, 1]
        c, s = self.cos_sin[:, 0], self.cos_sin[:, 1]
        gx = np.maximum(np.abs(c * dx + s * dy) - self.half[:, 0], 0.0)
        gy = np.maximum(np.abs(-s * dx + c * dy) - self.half[:, 1], 0.0)
        return self.names[int(np.argmin(gx * gx + gy * gy))]


@dataclass(frozen=True, slots=True)
class LoadedWorld:
    """The bodies of world.sdf in one pybullet client, by name and by id."""

    client: int
    body_of: Mapping[str, int]
    name_of: Mapping[int, str]
    spec_of: Mapping[str, ObjectSpec]
    merged: Mapping[int, MergedBoxes]
    """The bodies that hold many models (empty unless the world has more than ``MERGE_ABOVE`` models)."""
    ground: int | None = None
    """A room from an occupancy map: a fixed slab under the whole map, level with the floors' tops. Its floors
    are the free blocks only, and the robot drives between them up to the map's walls; they have no bodies of
    their own: ``body_of`` maps each to the slab, and ``merged`` names a point on the slab after its floor."""

    def contact_name(self, body: int, position: Sequence[float]) -> str | None:
        """The model touched at ``position`` on ``body``, or None for a body that is no model of the world."""
        boxes = self.merged.get(body)
        return boxes.name_at(position[0], position[1]) if boxes is not None else self.name_of.get(body)


def load_world(client: int, sdf_path: Path | str, world: WorldSpec, *, fixed: Collection[str] = ()) -> LoadedWorld:
    """Load ``sdf_path``, set gravity, and verify the bodies against ``world``; the models named in ``fixed`` are
    fixed rigid bodies (mass 0) whatever their category (module docstring)."""
    sdf_path = Path(sdf_path)
    if not sdf_path.is_file():
        raise ArtifactError(sdf_path, "file is missing")
    p.setGravity(0.0, 0.0, -GRAVITY, physicsClientId=client)
    expected = [o.name for o in world.objects]
    merged: dict[int, MergedBoxes] = {}
    placed = [o for o in world.objects if world.map is None or o.category is not Category.FLOOR]
    fixed = frozenset(fixed)
    polygons = any(o.shape is Shape.POLYGON for o in world.objects)
    if not fixed and not polygons and len(placed) == len(world.objects) <= MERGE_ABOVE:
        ids = _load_sdf(client, sdf_path, sdf_path)
        names = [p.getBodyInfo(b, physicsClientId=client)[1].decode("utf-8") for b in ids]
        if names != expected:
            raise ArtifactError(sdf_path, _difference(names, expected, world.path.name))
    else:
        names, ids, merged = _load_large(client, sdf_path, world, merge=len(placed) > MERGE_ABOVE, fixed=fixed)
    ground = _ground(client, world, merged) if world.map is not None else None
    if ground is not None:
        ids = [ground if body < 0 else body for body in ids]
    single = [(body, obj) for body, obj in zip(ids, world.objects, strict=True) if body not in merged]
    for body, obj in single:
        mass = p.getDynamicsInfo(body, -1, physicsClientId=client)[0]
        if obj.name in fixed:
            continue  # made fixed on purpose
        if obj.category.fixed and mass != 0.0:
            raise ArtifactError(
                sdf_path,
                f"model {obj.name!r} is {obj.category.value} but has mass {mass}; fixed bodies need mass 0",
            )
        if not obj.category.fixed and mass == 0.0:
            raise ArtifactError(
                sdf_path, f"model {obj.name!r} is {obj.category.value} but has mass 0 (fixed)"
            )
    return LoadedWorld(
        client=client,
        body_of=MappingProxyType(dict(zip(names, ids, strict=True))),
        name_of=MappingProxyType({body: obj.name for body, obj in single}),
        spec_of=MappingProxyType({o.name: o for o in world.objects}),
        merged=MappingProxyType(merged),
        ground=ground,
    )


def _ground(client: int, world: WorldSpec, merged: dict[int, MergedBoxes]) -> int:
    """A slab over the world's bounds whose top is the floors' top (z = 0), as thick as a floor; entered in
    ``merged`` with the floors' boxes, so a point on it is named after the floor it lies on."""
    xmin, ymin, xmax, ymax = world.bounds
    shape = p.createCollisionShape(p.GEOM_BOX, halfExtents=[(xmax - xmin) / 2, (ymax - ymin) / 2, GROUND / 2],
                                   physicsClientId=client)
    body = p.createMultiBody(0.0, shape, -1, basePosition=[(xmin + xmax) / 2, (ymin + ymax) / 2, -GROUND / 2],
                             useMaximalCoordinates=True, physicsClientId=client)
    floors = [o for o in world.objects if o.category is Category.FLOOR]
    yaws = np.array([o.pose[3] for o in floors], dtype=float)
    merged[body] = MergedBoxes(
        body=body,
        names=tuple(o.name for o in floors),
        centres=np.array([o.pose[:2] for o in floors], dtype=float).reshape(-1, 2),
        half=np.array([o.size[:2] for o in floors], dtype=float).reshape(-1, 2) / 2,
        cos_sin=np.column_stack([np.cos(yaws), np.sin(yaws)]).reshape(-1, 2),
    )
    return body


def _load_sdf(client: int, path: Path, shown: Path, *, maximal: bool = False) -> list[int]:
    try:
        with quiet_native_output():
            return list(p.loadSDF(str(path), useMaximalCoordinates=maximal, physicsClientId=client))
    except p.error as exc:
        raise ArtifactError(shown, f"pybullet could not load it: {exc}") from None


def _load_large(
    client: int, sdf_path: Path, world: WorldSpec, *, merge: bool, fixed: frozenset[str] = frozenset()
) -> tuple[list[str], list[int], dict[int, MergedBoxes]]:
    """The walls and floors merged per category (when ``merge``), a map room's floors left out (body id -1), the
    models named in ``fixed`` loaded as fixed rigid bodies from a copy of world.sdf holding only them, the other
    models from a copy holding only them; names and body ids in world.json's order."""
    root = ET.parse(sdf_path).getroot()
    holder = root.find("world")
    holder = holder if holder is not None else root
    models = holder.findall("model")
    loaded = [m.get("name") for m in models]
    expected = [o.name for o in world.objects]
    if loaded != expected:
        raise ArtifactError(sdf_path, _difference([n or "" for n in loaded], expected, world.path.name))
    boxes: dict[Category, list[tuple[str, tuple[float, ...], tuple[float, ...]]]] = {c: [] for c in MERGED_CATEGORIES}
    body_of: dict[str, int] = {}
    pinned: list[ET.Element] = []
    for model, obj in zip(models, world.objects, strict=True):
        if world.map is not None and obj.category is Category.FLOOR:
            body_of[obj.name] = -1
            holder.remove(model)
            continue
        if obj.shape is Shape.POLYGON:  # pybullet's loadSDF knows no <polyline>: its prism, built here
            holder.remove(model)
            body_of[obj.name] = _polygon_body(client, obj)
            continue
        if obj.name in fixed:
            pinned.append(model)
            holder.remove(model)
            continue
        box = _fixed_box(model) if merge and obj.category in MERGED_CATEGORIES else None
        if box is not None:
            boxes[obj.category].append((obj.name, *box))
            holder.remove(model)
    rest = holder.findall("model")
    if len(rest) > SDF_BODY_LIMIT:
        raise ArtifactError(
            sdf_path,
            f"{len(rest)} models besides walls and floors: pybullet loads at most {SDF_BODY_LIMIT} from one file",
        )
    for uri in root.iter("uri"):  # mesh files are relative to world.sdf's folder
        if uri.text and not Path(uri.text.strip()).is_absolute():
            uri.text = str((sdf_path.parent / uri.text.strip()).resolve())
    if rest:
        body_of.update(_load_part(client, root, sdf_path, world))
    if pinned:
        for model in rest:
            holder.remove(model)
        for model in pinned:
            for link in model.findall("link"):
                _massless(link)
            holder.append(model)
        body_of.update(_load_part(client, root, sdf_path, world, maximal=True))
    merged: dict[int, MergedBoxes] = {}
    for parts in boxes.values():
        order = sorted(range(len(parts)), key=lambda k: (_z_order(parts[k][1][0], parts[k][1][1]), k))
        for start in range(0, len(order), COMPOUND_LIMIT):
            chunk = _merge(client, [parts[k] for k in order[start:start + COMPOUND_LIMIT]])
            merged[chunk.body] = chunk
            body_of.update((name, chunk.body) for name in chunk.names)
    return expected, [body_of[n] for n in expected], merged


def _polygon_body(client: int, obj: ObjectSpec) -> int:
    """A POLYGON object (furniture, fixed): the prism of its footprint, convex or not, from the floor to its
    height, as one concave triangle mesh (pybullet's static trimesh: the robot's bodies collide with it and the
    lidar's rays hit it where the monitor's polygon is), placed at its pose (its centre, turned by its yaw)."""
    assert obj.footprint is not None
    points = obj.footprint.points
    n, half = len(points), obj.size[2] / 2
    vertices = [[x, y, -half] for x, y in points] + [[x, y, half] for x, y in points]
    indices: list[int] = []
    for a, b, c in triangulate(points):
        indices += [n + a, n + b, n + c, c, b, a]  # the top faces up, the bottom down
    for i in range(n):
        j = (i + 1) % n  # each side faces out of the counter-clockwise outline
        indices += [i, j, n + j, i, n + j, n + i]
    shape = p.createCollisionShape(p.GEOM_MESH, vertices=vertices, indices=indices,
                                   flags=p.GEOM_FORCE_CONCAVE_TRIMESH, physicsClientId=client)
    visual = p.createVisualShape(p.GEOM_MESH, vertices=vertices, indices=indices, rgbaColor=list(obj.colour),
                                 physicsClientId=client)
    x, y, z, yaw = obj.pose
    return p.createMultiBody(0.0, shape, visual, basePosition=[x, y, z],
                             baseOrientation=quaternion_of_yaw(yaw), useMaximalCoordinates=True,
                             physicsClientId=client)


def _load_part(client: int, root: ET.Element, sdf_path: Path, world: WorldSpec, *,
               maximal: bool = False) -> dict[str, int]:
    """The models left in ``root`` (a part of world.sdf) loaded from a copy of it; body ids by name. In maximal
    coordinates pybullet names a body after its (first) link, not its model."""
    holder = root.find("world")
    models = (holder if holder is not None else root).findall("model")
    expected = [m.get("name") or "" for m in models]
    with tempfile.TemporaryDirectory(prefix="rei-world-") as folder:
        part = Path(folder) / sdf_path.name
        ET.ElementTree(root).write(part, encoding="utf-8", xml_declaration=True)
        ids = _load_sdf(client, part, sdf_path, maximal=maximal)
    names = [p.getBodyInfo(b, physicsClientId=client)[1].decode("utf-8") for b in ids]
    if maximal and len(names) == len(models):
        links = [link.get("name") if (link := m.find("link")) is not None else None for m in models]
        names = [model if name == link else name for name, model, link in zip(names, expected, links, strict=True)]
    if names != expected:
        raise ArtifactError(sdf_path, _difference(names, expected, world.path.name))
    if maximal:  # pybullet leaves such a body at the origin: put it where its model says
        for body, model in zip(ids, models, strict=True):
            link = model.find("link")
            if link is not None and link.find("pose") is not None:
                raise ArtifactError(sdf_path, f"model {model.get('name')!r}: a fixed body's link has no pose of its own")
            position, orientation = _pose_of(model, sdf_path)
            p.resetBasePositionAndOrientation(body, position, orientation, physicsClientId=client)
    return dict(zip(names, ids, strict=True))


def _pose_of(model: ET.Element, sdf_path: Path) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """A model's ``<pose>x y z roll pitch yaw</pose>`` as a position and a quaternion (in double precision, as
    ``loadSDF`` places a model; pybullet's own conversions are single precision)."""
    text = model.findtext("pose") or "0 0 0 0 0 0"
    try:
        x, y, z, roll, pitch, yaw = (float(v) for v in text.split())
    except ValueError:
        raise ArtifactError(sdf_path, f"model {model.get('name')!r}: its pose is not six numbers: {text!r}") from None
    cr, sr, cp, sp = math.cos(roll / 2), math.sin(roll / 2), math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return (x, y, z), (sr * cp * cy - cr * sp * sy, cr * sp * cy + sr * cp * sy,
                       cr * cp * sy - sr * sp * cy, cr * cp * cy + sr * sp * sy)


def _massless(link: ET.Element) -> None:
    """Give ``link`` mass 0: pybullet makes a body of massless links fixed."""
    inertial = link.find("inertial")
    if inertial is None:  # pybullet refuses an <inertial> without its <inertia>
        inertial = ET.SubElement(link, "inertial")
        inertia = ET.SubElement(inertial, "inertia")
        for name in ("ixx", "ixy", "ixz", "iyy", "iyz", "izz"):
            ET.SubElement(inertia, name).text = "1" if name[1] == name[2] else "0"
    mass = inertial.find("mass")
    if mass is None:
        mass = ET.SubElement(inertial, "mass")
    mass.text = "0"


def _z_order(x: float, y: float) -> int:
    """The Morton code of the 1 m tile holding ``(x, y)``: near tiles have near codes."""
    tx, ty = math.floor(x) + (1 << 15), math.floor(y) + (1 << 15)
    code = 0
    for bit in range(17):
        code |= ((tx >> bit) & 1) << (2 * bit) | ((ty >> bit) & 1) << (2 * bit + 1)
    return code


def _fixed_box(model: ET.Element) -> tuple[tuple[float, ...], tuple[float, ...]] | None:
    """``(pose, size)`` of a fixed model whose one link collides as one box at the model's pose, else None."""
    links = model.findall("link")
    if len(links) != 1 or (model.findtext("static") or "").strip().lower() not in ("true", "1"):
        return None
    collisions = links[0].findall("collision")
    if len(collisions) != 1 or collisions[0].find("pose") is not None or links[0].find("pose") is not None:
        return None
    size = collisions[0].findtext("geometry/box/size")
    if size is None:
        return None
    try:
        pose = tuple(float(v) for v in (model.findtext("pose") or "0 0 0 0 0 0").split())
        extent = tuple(float(v) for v in size.split())
    except ValueError:
        return None
    return (pose, extent) if len(pose) == 6 and len(extent) == 3 else None


def _merge(client: int, parts: list[tuple[str, tuple[float, ...], tuple[float, ...]]]) -> MergedBoxes:
    """One fixed body whose compound shape holds every part's box at its pose (at most ``COMPOUND_LIMIT``)."""
    poses = [pose for _, pose, _ in parts]
    sizes = [size for _, _, size in parts]
    shape = p.createCollisionShapeArray(
        [p.GEOM_BOX] * len(parts),
        halfExtents=[[v / 2 for v in size] for size in sizes],
        collisionFramePositions=[list(pose[:3]) for pose in poses],
        collisionFrameOrientations=[p.getQuaternionFromEuler(pose[3:]) for pose in poses],
        physicsClientId=client,
    )
    # A plain rigid body (maximal coordinates): a fixed one costs a step less than a multibody.
    body = p.createMultiBody(0.0, shape, -1, useMaximalCoordinates=True, physicsClientId=client)
    yaws = np.array([pose[5] for pose in poses])
    return MergedBoxes(
        body=body,
        names=tuple(name for name, _, _ in parts),
        centres=np.array([pose[:2] for pose in poses], dtype=float),
        half=np.array([[size[0] / 2, size[1] / 2] for size in sizes], dtype=float),
        cos_sin=np.column_stack([np.cos(yaws), np.sin(yaws)]) if len(yaws) else np.zeros((0, 2)),
    )


def _difference(loaded: list[str], expected: list[str], world_name: str) -> str:
    head = f"pybullet loaded {len(loaded)} bodies but {world_name} lists {len(expected)} objects"
    missing = [n for n in expected if n not in loaded]
    extra = [n for n in loaded if n not in expected]
    if missing:
        head += f"; not loaded: {', '.join(missing[:10])}"
    if extra:
        head += f"; not in {world_name}: {', '.join(extra[:10])}"
    if not missing and not extra:
        first = next(i for i, (a, b) in enumerate(zip(loaded, expected, strict=True)) if a != b)
        head = f"bodies are not in {world_name}'s order: body #{first} is {loaded[first]!r}, expected {expected[first]!r}"
    return head
