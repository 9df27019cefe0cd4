# SPDX-License-Identifier: EPL-2.0
"""The limits that keep a small map file from taking the machine's memory (rei.maps, as the Java side's org.rei.maps):

- a map has at most ``MAX_CELLS`` cells, checked from the image's header (PNG IHDR, PGM header) before anything is
  decoded: a PNG of a few hundred bytes may declare 100,000 x 100,000 pixels, and ``rei gen-rooms --map`` once used
  7.7 GB on one that did;
- a large map within the limit is read in memory of the grid (a byte per cell) and a bounded block of rows;
- a floor size cuts a map into at most ``MAX_BLOCKS`` blocks, counted without overflow before anything is allocated.

Every image is made here, a header and a little zlib data: no big file is kept anywhere.
"""

from __future__ import annotations

import struct
import time
import tracemalloc
import zlib
from pathlib import Path

import numpy as np
import pytest

from rei.maps import MAX_BLOCKS, MAX_CELLS, MapError, block_grid, floor_blocks, load_map

YAML = ("# a map whose image the test writes\nimage: big.{ext}\nresolution: 0.05\norigin: [0.0, 0.0, 0.0]\n"
        "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.25\n")
#: 4,000 x 4,000 cells: large enough that a double per cell (128 MB) or a list of rows could not pass unseen.
SIDE = 4_000
#: What reading may hold besides the grid: a block of rows and its temporary arrays.
SLACK = 32 << 20


def _yaml(folder: Path, ext: str) -> Path:
    path = folder / "big.yaml"
    path.write_text(YAML.format(ext=ext), encoding="utf-8")
    return path


def _chunk(kind: bytes, data: bytes) -> bytes:
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)


def png_bytes(width: int, height: int, depth: int, rows: bytes) -> bytes:
    """A grey, not interlaced PNG declaring ``width x height`` pixels of ``depth`` bits, holding ``rows`` (each with
    its filter byte) compressed: as many rows as the caller gives, fewer than declared if it likes."""
    header = struct.pack(">IIBBBBB", width, height, depth, 0, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + _chunk(b"IHDR", header) + _chunk(b"IDAT", zlib.compress(rows, 9))
            + _chunk(b"IEND", b""))


def refusal(image: Path, width: int, height: int) -> str:
    return (f"{image}: {width} x {height} = {width * height} cells: a map may have at most 50000000 cells (crop it, "
            f"or save it at a coarser resolution)")


def _error(path: Path) -> MapError:
    with pytest.raises(MapError) as caught:
        load_map(path)
    return caught.value


def test_a_png_declaring_more_cells_than_a_map_may_have_is_refused_from_its_header(tmp_path: Path) -> None:
    # 100,000 x 100,000 one-bit pixels (5 x 5 km at 0.05 m) announced by IHDR; three rows of data follow
    image = tmp_path / "big.png"
    image.write_bytes(png_bytes(100_000, 100_000, 1, bytes(3 * (1 + 100_000 // 8))))
    path = _yaml(tmp_path, "png")
    start = time.monotonic()
    error = _error(path)
    assert time.monotonic() - start < 2.0, "refused from the header, not after decoding"
    assert (error.line, error.column, error.field) == (2, 8, "image")
    assert error.detail == refusal(image, 100_000, 100_000)
    assert str(error) == f"{path}:2:8: image: {refusal(image, 100_000, 100_000)}"


def test_the_limit_is_the_cells_the_header_declares(tmp_path: Path) -> None:
    """Exactly MAX_CELLS passes the header (this image then fails for its missing rows); one row more does not."""
    image = tmp_path / "big.png"
    path = _yaml(tmp_path, "png")
    assert MAX_CELLS == 10_000 * 5_000
    image.write_bytes(png_bytes(10_000, 5_000, 1, bytes(2 * (1 + 10_000 // 8))))
    assert "cannot read the image" in _error(path).detail
    image.write_bytes(png_bytes(10_000, 5_001, 1, bytes(2 * (1 + 10_000 // 8))))
    assert _error(path).detail == refusal(image, 10_000, 5_001)


@pytest.mark.parametrize("header", [b"P5\n# 5 x 5 km\n100000 100000\n255\n", b"P2\n100000\n100000 255\n"],
                         ids=["P5", "P2"])
def test_a_pgm_declaring_more_cells_than_a_map_may_have_is_refused_from_its_header(tmp_path: Path,
                                                                                   header: bytes) -> None:
    image = tmp_path / "big.pgm"
    image.write_bytes(header + b"\xfe\xfe\xfe")
    error = _error(_yaml(tmp_path, "pgm"))
    assert (error.line, error.column, error.field) == (2, 8, "image")
    assert error.detail == refusal(image, 100_000, 100_000)
    # a size beyond 64 bits is read by int() as it is, and refused the same way (as the Java side does)
    image.write_bytes(b"P2\n123456789012345678901 2\n255\n0 0\n")
    assert _error(_yaml(tmp_path, "pgm")).detail == refusal(image, 123456789012345678901, 2)


def _walled_rows(side: int = SIDE) -> np.ndarray:
    """The image's rows: free (254) but for the top row's wall and the left column's."""
    rows = np.full((side, side), 254, dtype=np.uint8)
    rows[0, :] = 0
    rows[:, 0] = 0
    return rows


def _read_measured(path: Path) -> tuple[np.ndarray, int]:
    """The grid of the map at ``path`` and the most memory reading it held at once (numpy's arrays included)."""
    tracemalloc.start()
    try:
        grid = load_map(path).grid
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    return grid, peak


def _check_walls(grid: np.ndarray, side: int = SIDE) -> None:
    assert grid.shape == (side, side) and grid.dtype == np.int8
    assert (grid[side - 1, 5], grid[7, 0], grid[0, side - 1], grid[0, 0]) == (100, 100, 0, 100)
    assert int((grid == 100).sum()) == 2 * side - 1


def test_a_large_png_within_the_limit_is_read_in_bounded_memory(tmp_path: Path) -> None:
    rows = _walled_rows()
    filtered = np.concatenate([np.zeros((SIDE, 1), dtype=np.uint8), rows], axis=1)  # filter byte 0 per row
    (tmp_path / "big.png").write_bytes(png_bytes(SIDE, SIDE, 8, filtered.tobytes()))
    grid, peak = _read_measured(_yaml(tmp_path, "png"))
    _check_walls(grid)
    assert peak < grid.nbytes + SLACK, f"held {peak} bytes for {grid.size} cells"


@pytest.mark.parametrize(("kind", "side"), [("P5", SIDE), ("P2", 1_500)])
def test_a_large_pgm_within_the_limit_is_read_in_bounded_memory(tmp_path: Path, kind: str, side: int) -> None:
    """P2 is text, a word per cell (here 9 MB of it): its words are read a piece at a time, never all at once."""
    rows = _walled_rows(side)
    header = f"{kind}\n{side} {side}\n255\n".encode()
    # P2: words of one and three digits, so that the pieces of text read cut words in two
    body = rows.tobytes() if kind == "P5" else b"\n".join(b" ".join(b"%d" % v for v in row) for row in rows)
    (tmp_path / "big.pgm").write_bytes(header + body + (b"\n" if kind == "P2" else b""))
    grid, peak = _read_measured(_yaml(tmp_path, "pgm"))
    _check_walls(grid, side)
    assert peak < grid.nbytes + SLACK, f"held {peak} bytes for {grid.size} cells"


def test_a_floor_size_that_cuts_the_map_into_too_many_blocks_is_refused_before_anything_is_allocated(
        tmp_path: Path) -> None:
    """examples/maps/two_rooms is 10 x 6 m of 0.05 m cells; 0.0000001 m floors would be 6 * 10^15 blocks."""
    (tmp_path / "big.pgm").write_bytes(b"P5\n200 120\n255\n" + bytes([254]) * (200 * 120))
    occupancy = load_map(_yaml(tmp_path, "pgm"))
    assert block_grid(occupancy, 0.0000001) == (100_000_000, 60_000_000)
    assert block_grid(occupancy, 1e-300) == pytest.approx((1e301, 6e300))
    with pytest.raises(ValueError) as tiny:
        floor_blocks(occupancy, 0.0000001)
    assert str(tiny.value) == ("floor size 1e-07 m cuts the map's 200 x 120 cells of 0.05 m into 100000000 x 60000000 "
                               "blocks: at most 4000000 (free or not); use a larger floor size")
    with pytest.raises(ValueError, match=r" into 1e\+301 x 6e\+300 blocks"):
        floor_blocks(occupancy, 1e-300)
    # within the limit: 2,000 x 1,200 blocks of 5 mm
    assert MAX_BLOCKS == 4_000_000
    assert floor_blocks(occupancy, 0.005).free.shape == (1200, 2000)
