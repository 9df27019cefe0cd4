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

A map has at most ``MAX_CELLS`` cells, checked from the image's header (PNG IHDR, PGM header) before anything is
decoded, since a small file may declare a huge image (a PNG of 1.4 MB can hold 100,000 x 100,000 one-bit pixels).
Within the limit the image is read a block of rows at a time into the grid, so reading holds the grid (a byte per
cell) and little more.

Every error is a ``MapError`` naming the YAML file, the line and column of the field concerned and the field.
"""

from __future__ import annotations

import itertools
import math
import os
import struct
import zlib
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any, BinaryIO

import numpy as np
import png
import yaml

from rei import located_yaml

MODES = ("trinary", "scale", "raw")
FREE, OCCUPIED, UNKNOWN = 0, 100, -1
#: The most cells (image pixels) a map may have: 50,000,000, e.g. 7,000 x 7,000 cells, 350 x 350 m at 0.05 m. A copy
#: of ``maps.max_cells`` in contract/vocabulary.json, as the Java side's ``OccupancyMap.MAX_CELLS``.
MAX_CELLS = 50_000_000
#: Samples converted at a time: the temporary arrays of a block of rows stay a few megabytes, whatever the map.
_CHUNK_SAMPLES = 1 << 18
#: Bytes of a plain (P2) PGM's text split into words at a time.
_TEXT_PIECE = 1 << 18
#: Compressed bytes of a PNG inflated at a time: at most about 4 MB of pixels (zlib's ratio is at most 1032:1).
_IDAT_PIECE = 1 << 12


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
    """Rows of an image as Nav2 sees them: the mean colour and the alpha as fractions of full scale (image row
    order)."""

    shade_rgb: np.ndarray  # mean of red, green, blue
    alpha: np.ndarray | None  # None: no alpha channel


@dataclass(frozen=True, slots=True)
class _Image:
    """An image whose header has been read: its size, and its pixels as blocks of rows, each with the index of
    its first row (from the top)."""

    width: int
    height: int
    blocks: Iterator[tuple[int, _Pixels]]


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

    read = _read_image(image, fields)
    grid = np.empty((read.height, read.width), dtype=np.int8)  # at most MAX_CELLS: checked from the header
    for first, pixels in read.blocks:
        rows = _cells(pixels, mode, bool(negate), occupied_thresh, free_thresh)
        # row 0 of the grid is the image's last row (the map's bottom)
        grid[read.height - first - len(rows):read.height - first] = rows[::-1]
    return OccupancyMap(path=path, image=image, resolution=resolution,
                        origin=(float(origin[0]), float(origin[1]), float(origin[2])), negate=bool(negate),
                        occupied_thresh=occupied_thresh, free_thresh=free_thresh, mode=mode, grid=grid)


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


def _read_image(image: Path, fields: _Fields) -> _Image:
    try:
        with image.open("rb") as stream:
            head = stream.read(24)  # the signature, then the first chunk's length, type and IHDR's size
    except OSError as error:
        raise fields.error("image", f"cannot read the image {image}: {error.strerror or error}") from None
    if head[:2] in (b"P2", b"P5"):
        return _read_pgm(image, fields)
    if head[:8] == PNG_SIGNATURE:
        if len(head) == 24 and head[12:16] == b"IHDR":
            _check_size(image, fields, *struct.unpack(">II", head[16:24]))
        return _read_png(image, fields)  # else not a PNG pypng reads: it says why
    raise fields.error("image", f"cannot read the image {image}: not a PGM (P2, P5) or PNG file")


PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def _check_size(image: Path, fields: _Fields, width: int, height: int) -> None:
    """The cell limit, before anything is decoded; the same message as the Java side's."""
    if width * height > MAX_CELLS:
        raise fields.error("image", f"{image}: {width} x {height} = {width * height} cells: a map may have at most "
                                    f"{MAX_CELLS} cells (crop it, or save it at a coarser resolution)")


def _rows_per_block(width: int) -> int:
    return max(1, _CHUNK_SAMPLES // max(1, width))


class _PngReader(png.Reader):
    """pypng's reader, handing each ``IDAT`` chunk to its decompressor in pieces of ``_IDAT_PIECE`` bytes: pypng
    inflates what it is given at once, and a well-compressed chunk of a megabyte may inflate to a gigabyte."""

    def chunk(self, lenient: bool = False) -> tuple[bytes, bytes]:
        pieces: list[bytes] = self.__dict__.setdefault("_pieces", [])
        if pieces:
            return b"IDAT", pieces.pop()
        kind, data = super().chunk(lenient=lenient)
        if kind == b"IDAT" and len(data) > _IDAT_PIECE:
            pieces.extend(data[at:at + _IDAT_PIECE] for at in reversed(range(_IDAT_PIECE, len(data), _IDAT_PIECE)))
            data = data[:_IDAT_PIECE]
        return kind, data


def _read_png(image: Path, fields: _Fields) -> _Image:
    """A PNG's samples as stored (pypng's ``read``: no gamma or significant-bits rescaling, which ImageMagick
    does not apply either), the palette and a ``tRNS`` transparent colour resolved as ImageMagick reads them;
    pypng decodes a row at a time (an interlaced image at once)."""

    def failed(error: Exception) -> MapError:
        return fields.error("image", f"cannot read the image {image}: {error}")

    try:
        width, height, rows, info = _PngReader(filename=str(image)).read()
    except (png.Error, OSError, ValueError, zlib.error) as error:
        raise failed(error) from None
    _check_size(image, fields, width, height)  # an IHDR that is not the first chunk: pypng found it
    planes, full = int(info["planes"]), float(2 ** int(info["bitdepth"]) - 1)
    palette = np.asarray(info["palette"], dtype=np.int64) if "palette" in info else None
    key = np.asarray(info["transparent"], dtype=np.int64).reshape(-1) if "transparent" in info else None

    def pixels(samples: np.ndarray) -> _Pixels:
        samples = samples.reshape(len(samples), width, planes)
        scale, depth = full, planes
        if palette is not None:
            samples, scale = palette[samples[..., 0]], 255.0
            depth = palette.shape[1]
        elif key is not None:  # one colour (or grey) stands for transparent: alpha 0 there, opaque elsewhere
            alpha = np.where((samples == key).all(axis=2), 0, int(full))[..., None]
            samples, depth = np.concatenate([samples, alpha], axis=2), planes + 1
        colour = samples[..., :1] if depth in (1, 2) else samples[..., :3]
        return _Pixels(colour.mean(axis=2) / scale, samples[..., -1] / scale if depth in (2, 4) else None)

    def blocks() -> Iterator[tuple[int, _Pixels]]:
        per_block = _rows_per_block(width * planes)
        first = 0
        try:
            while first < height:
                count = min(per_block, height - first)
                samples = np.empty((count, width * planes), dtype=np.int64)
                got = 0
                for row in itertools.islice(rows, count):
                    samples[got] = row
                    got += 1
                if got < count:
                    raise png.FormatError(f"the image data holds {first + got} rows, expected {height}")
                yield first, pixels(samples)
                first += count
        except (png.Error, OSError, ValueError, zlib.error) as error:
            raise failed(error) from None

    return _Image(width, height, blocks())


class _Bytes:
    """A file read through a buffer, byte by byte (a PGM header), counting where it is."""

    def __init__(self, stream: BinaryIO) -> None:
        self.stream, self.buffer, self.at, self.offset = stream, b"", 0, 0

    def peek(self) -> bytes:
        """The next byte without taking it, ``b""`` at the end."""
        if self.at == len(self.buffer):
            self.buffer, self.at = self.stream.read(1 << 16), 0
        return self.buffer[self.at:self.at + 1]

    def take(self) -> bytes:
        byte = self.peek()
        self.at += len(byte)
        self.offset += len(byte)
        return byte


def _read_pgm(image: Path, fields: _Fields) -> _Image:
    """A PGM: three header numbers and the samples, whose shade is ``sample / maxval`` as map_server reads it;
    read as a stream, the header first."""
    stream = image.open("rb")
    try:
        data = _Bytes(stream)
        binary = data.take() + data.take() == b"P5"
        tokens: list[bytes] = []
        while len(tokens) < 3:
            while data.peek().isspace():
                data.take()
            if data.peek() == b"#":
                while data.peek() not in (b"\n", b"\r", b""):
                    data.take()
                continue
            token = bytearray()
            while data.peek() and not data.peek().isspace() and data.peek() != b"#":
                token += data.take()
            if not token:
                raise fields.error("image", f"{image}: truncated PGM header")
            tokens.append(bytes(token))
        try:
            width, height, maxval = (int(t) for t in tokens)
        except ValueError:
            raise fields.error("image", f"{image}: PGM header {b' '.join(tokens)!r} is not three integers") from None
        if width <= 0 or height <= 0:
            raise fields.error("image", f"{image}: PGM size {width} x {height}: expected at least 1 x 1")
        _check_size(image, fields, width, height)
        if not 0 < maxval <= 65535:
            raise fields.error("image", f"{image}: PGM maxval {maxval}: expected 1..65535 (8 or 16 bits per sample)")
        if binary:
            data.take()  # exactly one whitespace byte ends the header
            blocks = _pgm_binary(image, fields, stream, data.offset, width, height, maxval)
        else:
            blocks = _pgm_plain(image, fields, stream, data.offset, width, height, maxval)
    except BaseException:
        stream.close()
        raise
    return _Image(width, height, _closing(stream, blocks))


def _closing(stream: BinaryIO, blocks: Iterator[tuple[int, _Pixels]]) -> Iterator[tuple[int, _Pixels]]:
    with stream:
        yield from blocks


def _pgm_binary(image: Path, fields: _Fields, stream: BinaryIO, body: int, width: int, height: int,
                maxval: int) -> Iterator[tuple[int, _Pixels]]:
    """P5: the samples from ``body`` on, two bytes big-endian above 255."""
    dtype = np.dtype(">u2") if maxval > 255 else np.dtype("u1")
    count = width * height
    available = max(0, os.fstat(stream.fileno()).st_size - body) // dtype.itemsize
    if available < count:
        raise fields.error("image", f"{image}: PGM data holds {available} samples, "
                                    f"expected {width} x {height} = {count}")

    def blocks() -> Iterator[tuple[int, _Pixels]]:
        stream.seek(body)
        largest, per_block = 0, _rows_per_block(width)
        for first in range(0, height, per_block):
            rows = min(per_block, height - first)
            samples = np.frombuffer(stream.read(rows * width * dtype.itemsize), dtype=dtype).reshape(rows, width)
            largest = max(largest, int(samples.max()))
            yield first, _Pixels(samples / maxval, None)
        if largest > maxval:
            raise fields.error("image", f"{image}: a PGM sample of {largest} exceeds maxval {maxval}")

    return blocks()


def _pgm_plain(image: Path, fields: _Fields, stream: BinaryIO, start: int, width: int, height: int,
               maxval: int) -> Iterator[tuple[int, _Pixels]]:
    """P2: the samples as decimal words from ``start`` on, read as ``int()`` reads them, a block of rows at a time
    (a word cut by the end of a read is completed by the next)."""
    count = width * height

    def words() -> Iterator[list[bytes]]:
        stream.seek(start)
        rest = b""
        while piece := stream.read(_TEXT_PIECE):
            text = rest + piece
            cut = len(text) if text[-1:].isspace() else max(text.rfind(c) for c in b" \t\n\r\x0b\x0c") + 1
            rest = text[cut:]
            yield text[:cut].split()
        if rest:
            yield [rest]

    def blocks() -> Iterator[tuple[int, _Pixels]]:
        largest, read, first = 0, 0, 0
        per_block = _rows_per_block(width)
        samples = np.empty(min(per_block, height) * width, dtype=np.int64)
        filled = 0
        for chunk in words():
            at = 0
            while at < len(chunk) and read < count:
                take = min(len(chunk) - at, len(samples) - filled, count - read)
                try:
                    values = [int(w) for w in chunk[at:at + take]]
                except ValueError:
                    raise fields.error("image", f"{image}: PGM samples are not integers") from None
                try:
                    samples[filled:filled + take] = values
                except OverflowError:  # beyond 64 bits
                    samples[filled:filled + take] = [min(max(v, -2**63), 2**31 - 1) for v in values]
                at, filled, read = at + take, filled + take, read + take
                if filled == len(samples) or read == count:
                    rows = filled // width
                    # as the Java side says it: beyond 2^31 - 1 a sample is 2^31 - 1 (above any maxval)
                    largest = max(largest, min(int(samples[:filled].max()), 2**31 - 1))
                    yield first, _Pixels(samples[:filled].reshape(rows, width) / maxval, None)
                    first, filled = first + rows, 0
            if read == count:
                break
        if read < count:
            raise fields.error("image", f"{image}: PGM data holds {read} samples, "
                                        f"expected {width} x {height} = {count}")
        if largest > maxval:
            raise fields.error("image", f"{image}: a PGM sample of {largest} exceeds maxval {maxval}")

    return blocks()
