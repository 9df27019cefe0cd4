# SPDX-License-Identifier: EPL-2.0
"""The ROS ``map_server`` occupancy-map format: a YAML file naming a PGM or PNG image.

``load_map(yaml_path)`` returns the ``OccupancyMap`` that Nav2's ``map_server`` would publish on ``/map``: the
same cell values (``-1`` unknown, ``0`` free, ``100`` occupied, ``1..99`` in ``scale`` mode, ``0..100`` as read in
``raw`` mode) in the same order (row 0 at the bottom, like ``nav_msgs/OccupancyGrid.data``). The arithmetic is
Nav2's ``map_io.cpp`` (``loadMapYaml``, ``loadMapFromFile``):

- ``shade`` is a pixel's mean over red, green, blue (a grey pixel's grey), plus its alpha in ``trinary`` mode when
  the image has an alpha channel, as a fraction of the sample's maximum (255, 65535, or a PGM's maxval);
- ``occ = shade`` when ``negate``, else ``1 - shade``;
- ``trinary``: ``occupied_thresh < occ`` is 100, else ``occ < free_thresh`` is 0, else -1;
- ``scale``: a pixel that is not opaque is -1, then as ``trinary`` except that the values between the
  thresholds become ``rint((occ - free_thresh) / (occupied_thresh - free_thresh) * 100)``;
- ``raw``: ``round(shade * 255)`` when it is within 0..100, else -1 (``negate`` does not apply).

PGM (``P2``, ``P5``, maxval up to 65535) is read here, PNG (every colour type and bit depth) by pypng.

Every error is a ``MapError`` naming the YAML file, the line and column of the field concerned and the field.
"""

from __future__ import annotations

import math
import zlib
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import png
import yaml

from rei import located_yaml

MODES = ("trinary", "scale", "raw")
FREE, OCCUPIED, UNKNOWN = 0, 100, -1


class MapError(ValueError):
    """A map that can not be read: ``file:line:column: field: what is wrong`` (line and column from 1)."""

    def __init__(self, path: Path, line: int, column: int, field: str, message: str) -> None:
        self.path, self.line, self.column, self.field, self.detail = path, line, column, field, message
        super().__init__(f"{path}:{line}:{column}: {field}: {message}")


@dataclass(frozen=True, slots=True)
class OccupancyMap:
    """A loaded map. ``grid`` is ``(height, width)`` int8, row 0 the bottom row (the image's last)."""

    path: Path
    image: Path
    resolution: float
    origin: tuple[float, float, float]
    negate: bool
    occupied_thresh: float
    free_thresh: float
    mode: str
    grid: np.ndarray

    @property
    def width(self) -> int:
        return int(self.grid.shape[1])

    @property
    def height(self) -> int:
        return int(self.grid.shape[0])


@dataclass(frozen=True, slots=True)
class _Pixels:
    """An image as Nav2 sees it: the mean colour and the alpha as fractions of full scale (image row order)."""

    shade_rgb: np.ndarray  # mean of red, green, blue
    alpha: np.ndarray | None  # None: no alpha channel


class _Fields:
    """The YAML's top-level mapping, each value with the position of its node (rei.located_yaml)."""

    def __init__(self, path: Path) -> None:
        self.path = path
        try:
            text = path.read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError) as error:
            raise MapError(path, 1, 1, "file", f"cannot read the map file: {error}") from None
        try:
            root = located_yaml.compose(text, not_yaml="not valid YAML")
            self.root_mark = (1, 1) if root is None else located_yaml.position(root)
            if not isinstance(root, yaml.MappingNode):
                raise MapError(path, *self.root_mark, "file", "expected a mapping of map_server fields")
            self.nodes = {name: node for name, (_, node) in located_yaml.mapping(root, "the map file").items()}
        except located_yaml.LocatedError as error:
            raise MapError(path, error.line or 1, error.column or 1, "file", error.message) from None

    def has(self, name: str) -> bool:
        return name in self.nodes

    def position(self, name: str) -> tuple[int, int]:
        node = self.nodes.get(name)
        return located_yaml.position(node) if node is not None else self.root_mark

    def error(self, name: str, message: str) -> MapError:
        return MapError(self.path, *self.position(name), name, message)

    def value(self, name: str) -> Any:
        if name not in self.nodes:
            raise MapError(self.path, *self.root_mark, name, "missing (map_server requires it)")
        try:
            return located_yaml.value(self.nodes[name])
        except located_yaml.LocatedError as error:
            raise self.error(name, error.message) from None

    def number(self, name: str) -> float:
        number = located_yaml.number(self.nodes[name]) if name in self.nodes else None
        if number is None:
            raise self.error(name, f"expected a number, got {self.value(name)!r}")
        return number


def load_map(path: Path | str) -> OccupancyMap:
    """Read a ``map_server`` YAML file and its image into the grid ``map_server`` would publish."""
    path = Path(path)
    fields = _Fields(path)

    image_name = fields.value("image")
    if not isinstance(image_name, str) or not image_name.strip():
        raise fields.error("image", f"expected the image file's name, got {image_name!r}")
    image = Path(image_name) if Path(image_name).is_absolute() else path.parent / image_name

    resolution = fields.number("resolution")
    if resolution <= 0:
        raise fields.error("resolution", f"expected metres per cell above 0, got {resolution:g}")

    origin = fields.value("origin")
    if (not isinstance(origin, list) or len(origin) != 3
            or any(isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v)
                   for v in origin)):
        raise fields.error("origin", f"expected [x, y, yaw], three numbers, got {origin!r}")
    if origin[2] != 0:
        # REI rooms are axis-aligned; a rotated map would need every floor and wall rotated with it.
        raise fields.error("origin", f"a yaw of {origin[2]:g} is not supported: REI rooms are axis-aligned (use 0)")

    free_thresh = fields.number("free_thresh")
    occupied_thresh = fields.number("occupied_thresh")
    for name, value in (("free_thresh", free_thresh), ("occupied_thresh", occupied_thresh)):
        if not 0.0 <= value <= 1.0:
            raise fields.error(name, f"expected a fraction within 0..1, got {value:g}")
    if not free_thresh < occupied_thresh:
        raise fields.error("free_thresh", f"{free_thresh:g} must be below occupied_thresh {occupied_thresh:g}")

    mode = fields.value("mode") if fields.has("mode") else "trinary"  # Nav2's default
    if mode not in MODES:
        raise fields.error("mode", f"expected one of {', '.join(MODES)}, got {mode!r}")

    negate = fields.value("negate")
    if negate not in (0, 1) or not isinstance(negate, (int, bool)):
        raise fields.error("negate", f"expected 0, 1, true or false, got {negate!r}")

    pixels = _read_image(image, fields)
    grid = _cells(pixels, mode, bool(negate), occupied_thresh, free_thresh)
    return OccupancyMap(path=path, image=image, resolution=resolution,
                        origin=(float(origin[0]), float(origin[1]), float(origin[2])), negate=bool(negate),
                        occupied_thresh=occupied_thresh, free_thresh=free_thresh, mode=mode,
                        grid=np.ascontiguousarray(grid[::-1]))


def _cells(pixels: _Pixels, mode: str, negate: bool, occupied_thresh: float, free_thresh: float) -> np.ndarray:
    """Nav2's ``loadMapFromFile`` per-pixel arithmetic, over whole arrays (image row order)."""
    shade = pixels.shade_rgb
    if mode == "raw":
        value = np.floor(shade * 255 + 0.5)  # std::round: half away from zero (values are >= 0)
        return np.where((value >= FREE) & (value <= OCCUPIED), value, UNKNOWN).astype(np.int8)
    if mode == "trinary" and pixels.alpha is not None:
        shade = (shade * 3 + pixels.alpha) / 4  # the alpha averaged in with the three colour channels
    occ = shade if negate else 1.0 - shade
    if mode == "trinary":
        middle = np.full(occ.shape, UNKNOWN, dtype=np.float64)
    else:
        middle = np.rint((occ - free_thresh) / (occupied_thresh - free_thresh) * 100.0)
    cells = np.where(occupied_thresh < occ, OCCUPIED, np.where(occ < free_thresh, FREE, middle))
    if mode == "scale" and pixels.alpha is not None:
        cells = np.where(pixels.alpha < 1.0, UNKNOWN, cells)
    return cells.astype(np.int8)


def _read_image(image: Path, fields: _Fields) -> _Pixels:
    try:
        with image.open("rb") as stream:
            head = stream.read(8)
    except OSError as error:
        raise fields.error("image", f"cannot read the image {image}: {error.strerror or error}") from None
    if head[:2] in (b"P2", b"P5"):
        return _read_pgm(image, fields)
    if head == PNG_SIGNATURE:
        return _read_png(image, fields)
    raise fields.error("image", f"cannot read the image {image}: not a PGM (P2, P5) or PNG file")


PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def _read_png(image: Path, fields: _Fields) -> _Pixels:
    """A PNG's samples as stored (pypng's ``read``: no gamma or significant-bits rescaling, which ImageMagick
    does not apply either), the palette and a ``tRNS`` transparent colour resolved as ImageMagick reads them."""
    try:
        width, height, rows, info = png.Reader(filename=str(image)).read()
        samples = np.vstack([np.asarray(row, dtype=np.int64) for row in rows]) if height else np.zeros((0, 0))
    except (png.Error, OSError, ValueError, zlib.error) as error:
        raise fields.error("image", f"cannot read the image {image}: {error}") from None
    planes, full = int(info["planes"]), float(2 ** int(info["bitdepth"]) - 1)
    samples = samples.reshape(height, width, planes)
    if "palette" in info:
        palette = np.asarray(info["palette"], dtype=np.int64)
        samples, full = palette[samples[..., 0]], 255.0
        planes = palette.shape[1]
    elif "transparent" in info:  # one colour (or grey) stands for transparent: alpha 0 there, opaque elsewhere
        key = np.asarray(info["transparent"], dtype=np.int64).reshape(-1)
        alpha = np.where((samples == key).all(axis=2), 0, int(full))[..., None]
        samples, planes = np.concatenate([samples, alpha], axis=2), planes + 1
    colour = samples[..., :1] if planes in (1, 2) else samples[..., :3]
    shade = colour.mean(axis=2) / full
    return _Pixels(shade, samples[..., -1] / full if planes in (2, 4) else None)


def _read_pgm(image: Path, fields: _Fields) -> _Pixels:
    """A PGM: three header numbers and the samples, whose shade is ``sample / maxval`` as map_server reads it."""
    data = image.read_bytes()
    tokens: list[bytes] = []
    at = 2
    while len(tokens) < 3:
        while at < len(data) and data[at:at + 1].isspace():
            at += 1
        if data[at:at + 1] == b"#":
            while at < len(data) and data[at:at + 1] not in (b"\n", b"\r"):
                at += 1
            continue
        start = at
        while at < len(data) and not data[at:at + 1].isspace() and data[at:at + 1] != b"#":
            at += 1
        if start == at:
            raise fields.error("image", f"{image}: truncated PGM header")
        tokens.append(data[start:at])
    try:
        width, height, maxval = (int(t) for t in tokens)
    except ValueError:
        raise fields.error("image", f"{image}: PGM header {b' '.join(tokens)!r} is not three integers") from None
    if width <= 0 or height <= 0:
        raise fields.error("image", f"{image}: PGM size {width} x {height}: expected at least 1 x 1")
    if not 0 < maxval <= 65535:
        raise fields.error("image", f"{image}: PGM maxval {maxval}: expected 1..65535 (8 or 16 bits per sample)")
    count = width * height
    if data[:2] == b"P5":
        dtype = np.dtype(">u2") if maxval > 255 else np.dtype("u1")
        body = data[at + 1:]  # exactly one whitespace byte ends the header
        if len(body) < count * dtype.itemsize:
            raise fields.error("image", f"{image}: PGM data holds {len(body) // dtype.itemsize} samples, "
                                        f"expected {width} x {height} = {count}")
        samples = np.frombuffer(body, dtype=dtype, count=count)
    else:
        words = data[at:].split()
        if len(words) < count:
            raise fields.error("image", f"{image}: PGM data holds {len(words)} samples, "
                                        f"expected {width} x {height} = {count}")
        try:
            samples = np.array([int(w) for w in words[:count]], dtype=np.int64)
        except ValueError:
            raise fields.error("image", f"{image}: PGM samples are not integers") from None
    if samples.size and samples.max() > maxval:
        raise fields.error("image", f"{image}: a PGM sample of {int(samples.max())} exceeds maxval {maxval}")
    return _Pixels(samples.reshape(height, width).astype(np.float64) / maxval, None)
