# SPDX-License-Identifier: EPL-2.0
"""rei.maps.blocks: obstacles merged into rectangles that cover exactly the obstacle cells, and free floors."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest

from rei.maps import (
    OCCUPIED,
    UNKNOWN,
    CellRect,
    OccupancyMap,
    box_of,
    floor_blocks,
    load_map,
    merge_rectangles,
    obstacle_mask,
)

SHARED_MAPS = Path(__file__).resolve().parents[3].parent / "shared" / "data" / "maps"


def _map(grid: np.ndarray, resolution: float = 0.05) -> OccupancyMap:
    return OccupancyMap(path=Path("m.yaml"), image=Path("m.pgm"), resolution=resolution, origin=(0.0, 0.0, 0.0),
                        negate=False, occupied_thresh=0.65, free_thresh=0.25, mode="trinary",
                        grid=grid.astype(np.int8))


def _cover(rects: list[CellRect], shape: tuple[int, int]) -> np.ndarray:
    cover = np.zeros(shape, dtype=np.int64)
    for rect in rects:
        cover[rect.row:rect.row + rect.rows, rect.col:rect.col + rect.cols] += 1
    return cover


def test_merge_covers_each_obstacle_cell_once() -> None:
    rng = np.random.default_rng(7)
    mask = rng.random((40, 60)) < 0.3
    rects = merge_rectangles(mask)
    assert np.array_equal(_cover(rects, mask.shape), mask.astype(np.int64))


def test_merge_makes_one_rectangle_per_wall() -> None:
    mask = np.zeros((20, 30), dtype=bool)
    mask[0:2, :] = True  # bottom wall, two cells thick
    mask[2:20, 0] = True  # left wall
    mask[5:8, 10:14] = True  # a block
    rects = merge_rectangles(mask)
    assert set(rects) == {CellRect(0, 0, 30, 2), CellRect(0, 2, 1, 18), CellRect(10, 5, 4, 3)}


def test_merge_picks_the_direction_with_fewer_rectangles() -> None:
    comb = np.zeros((5, 5), dtype=bool)
    comb[0, :] = True  # a comb: its back along the bottom row, teeth up columns 0, 2, 4
    comb[1:, 0::2] = True
    # Along rows: the back and three teeth (4); along columns: five column runs. Turned a quarter, the reverse.
    for mask in (comb, comb.T):
        rects = merge_rectangles(mask)
        assert np.array_equal(_cover(rects, mask.shape), mask.astype(np.int64)) and len(rects) == 4


def test_box_of_places_cells_from_the_origin() -> None:
    occupancy = dataclasses.replace(_map(np.zeros((4, 4)), resolution=0.5), origin=(-1.0, 2.0, 0.0))
    assert box_of(CellRect(col=1, row=2, cols=2, rows=1), occupancy) == (0.0, 3.25, 1.0, 0.5)


def test_unknown_is_an_obstacle_unless_free() -> None:
    grid = np.array([[0, OCCUPIED, UNKNOWN, 40]])
    assert obstacle_mask(_map(grid)).tolist() == [[False, True, True, False]]
    assert obstacle_mask(_map(grid), unknown_free=True).tolist() == [[False, True, False, False]]


def test_floor_block_is_free_when_every_cell_is() -> None:
    grid = np.zeros((40, 60), dtype=np.int8)  # 3 x 2 m at 0.05 m: 3 x 2 blocks of 1 m (20 cells)
    grid[25, 30] = OCCUPIED  # block (1, 1)
    grid[5, 59] = UNKNOWN  # block (2, 0)
    blocks = floor_blocks(_map(grid), 1.0)
    assert blocks.free.tolist() == [[True, True, False], [True, False, True]]
    assert blocks.names() == ["F_0_0", "F_1_0", "F_0_1", "F_2_1"]
    assert floor_blocks(_map(grid), 1.0, unknown_free=True).free.tolist() == [[True, True, True],
                                                                             [True, False, True]]


def test_floor_block_overlapping_a_cell_partly_needs_it_free() -> None:
    # 0.25 m blocks over 0.03 m cells: block 0 overlaps cells 0..8, block 1 cells 8..16; only whole blocks exist.
    grid = np.zeros((9, 30), dtype=np.int8)
    grid[0, 8] = OCCUPIED
    blocks = floor_blocks(_map(grid, 0.03), 0.25)
    assert blocks.free.shape == (1, 3)  # 0.9 m: three whole blocks of 0.25 m; 0.27 m high: one
    assert blocks.free.tolist() == [[False, False, True]]


def test_floor_size_must_be_positive() -> None:
    with pytest.raises(ValueError, match="above 0"):
        floor_blocks(_map(np.zeros((2, 2))), 0.0)


def test_real_maps_merge_and_floor() -> None:
    depot = load_map(SHARED_MAPS / "depot.yaml")
    mask = obstacle_mask(depot)
    rects = merge_rectangles(mask)
    assert np.array_equal(_cover(rects, mask.shape), mask.astype(np.int64))
    assert len(rects) < mask.sum() / 4  # 5,947 occupied cells of a SLAM map; 1,327 rectangles when written
    blocks = floor_blocks(depot, 1.0)
    assert blocks.free.shape == (15, 30) and 250 < blocks.free.sum() < 15 * 30
    sandbox = load_map(SHARED_MAPS / "tb3_sandbox.yaml")
    # Unknown all round the arena: no whole free metre unless the case lets unknown cells be floor.
    assert floor_blocks(sandbox, 1.0).free.sum() == 0
    assert floor_blocks(sandbox, 1.0, unknown_free=True).free.sum() > 0
