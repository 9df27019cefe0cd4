# SPDX-License-Identifier: EPL-2.0
"""A map's picture (rei.maps.map_picture): map_server's shades in image order, shrunk by a whole factor keeping
the most obstructive cell of each pixel, placed over the map's extent."""

from __future__ import annotations

import io
from pathlib import Path

import numpy as np
import png
import pytest

from rei.maps import load_map, map_picture

SHARED_MAPS = Path(__file__).resolve().parents[3].parent / "shared" / "data" / "maps"


def _pixels(data: bytes) -> np.ndarray:
    width, height, rows, info = png.Reader(file=io.BytesIO(data)).read()
    assert info["greyscale"] and info["bitdepth"] == 8 and not info["alpha"]
    return np.vstack([np.asarray(row, dtype=np.uint8) for row in rows]).reshape(height, width)


def _write_map(folder: Path, pixels: np.ndarray, mode: str = "trinary") -> Path:
    height, width = pixels.shape
    (folder / "m.pgm").write_bytes(f"P5\n{width} {height}\n255\n".encode() + pixels.astype(np.uint8).tobytes())
    (folder / "m.yaml").write_text(f"image: m.pgm\nresolution: 0.1\norigin: [-1.0, 2.0, 0.0]\nnegate: 0\n"
                                   f"occupied_thresh: 0.65\nfree_thresh: 0.196\nmode: {mode}\n", encoding="utf-8")
    return folder / "m.yaml"


def test_a_small_map_is_drawn_cell_for_cell_top_row_first(tmp_path: Path) -> None:
    image = np.full((4, 6), 254)
    image[0, 0], image[3, 5], image[1, 2] = 0, 205, 0  # top-left occupied, bottom-right unknown
    occupancy = load_map(_write_map(tmp_path, image))
    picture = map_picture(occupancy)
    assert (picture.width, picture.height, picture.factor) == (6, 4, 1)
    assert picture.extent == pytest.approx((-1.0, 2.0, -0.4, 2.4))
    pixels = _pixels(picture.png)
    assert pixels.tolist() == np.where(image == 0, 0, np.where(image == 205, 205, 254)).tolist()
    assert picture.data_uri().startswith("data:image/png;base64,iVBOR")


def test_scale_mode_s_grey_levels_are_shaded_between_free_and_occupied(tmp_path: Path) -> None:
    image = np.array([[254, 150, 100, 0]])  # free, two greys between the thresholds, occupied
    occupancy = load_map(_write_map(tmp_path, image, mode="scale"))
    assert occupancy.grid.tolist() == [[0, 48, 91, 100]]
    assert _pixels(map_picture(occupancy).png).tolist() == [[254, 132, 23, 0]]  # 254 - value * 2.54


def test_a_large_map_is_shrunk_keeping_every_wall(tmp_path: Path) -> None:
    image = np.full((10, 25), 254)
    image[:, 12] = 0  # a one-cell wall, every row
    image[0, 0] = 205  # unknown in the top-left corner
    picture = map_picture(load_map(_write_map(tmp_path, image)), max_side=10)
    assert (picture.factor, picture.width, picture.height) == (3, 9, 4)
    pixels = _pixels(picture.png)
    # the picture's bottom row holds the map's bottom row (row 0 of the grid): padding goes above and right
    assert pixels[:, 4].tolist() == [0, 0, 0, 0] and pixels[0, 0] == 205 and pixels[-1, 0] == 254
    assert picture.extent == pytest.approx((-1.0, 2.0, -1.0 + 9 * 0.3, 2.0 + 4 * 0.3))


def test_the_shared_depot_fits_in_a_thousand_pixels() -> None:
    occupancy = load_map(SHARED_MAPS / "depot.yaml")
    picture = map_picture(occupancy)
    assert (picture.width, picture.height, picture.factor) == (604, 307, 1)
    pixels = _pixels(picture.png)[::-1]  # back to grid rows
    assert np.array_equal(pixels == 0, occupancy.grid == 100)
    assert len(picture.png) < 40_000
