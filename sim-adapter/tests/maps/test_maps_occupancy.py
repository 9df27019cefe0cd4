# SPDX-License-Identifier: EPL-2.0
"""rei.maps.occupancy against the map_server format's definition (Nav2 map_io.cpp), on tiny images made here,
and on the two real maps from Nav2's bringup (read where they are shared, beside the repository)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import png
import pytest

from rei.maps import MapError, load_map

SHARED_MAPS = Path(__file__).resolve().parents[3].parent / "shared" / "data" / "maps"
U, F, O = -1, 0, 100


def _yaml(folder: Path, image: str = "m.pgm", mode: str | None = "trinary", negate: object = 0,
          occ: float = 0.65, free: float = 0.25, extra: str = "") -> Path:
    lines = [f"image: {image}", "resolution: 0.05", "origin: [1.0, -2.0, 0.0]", f"negate: {negate}",
             f"occupied_thresh: {occ}", f"free_thresh: {free}"]
    if mode is not None:
        lines.append(f"mode: {mode}")
    path = folder / "m.yaml"
    path.write_text("\n".join(lines) + "\n" + extra, encoding="utf-8")
    return path


def _pgm(folder: Path, rows: list[list[int]], maxval: int = 255, plain: bool = False) -> None:
    height, width = len(rows), len(rows[0])
    if plain:
        body = "\n".join(" ".join(str(v) for v in row) for row in rows).encode()
        data = f"P2\n# made by the test\n{width} {height}\n{maxval}\n".encode() + body + b"\n"
    else:
        dtype = ">u2" if maxval > 255 else "u1"
        data = f"P5\n{width} {height}\n{maxval}\n".encode() + np.array(rows, dtype=dtype).tobytes()
    (folder / "m.pgm").write_bytes(data)


def _png(folder: Path, pixels: np.ndarray, mode: str) -> None:
    png.from_array(pixels.reshape(pixels.shape[0], -1).tolist(), mode).save(folder / "m.png")


def _row(path: Path) -> list[int]:
    return load_map(path).grid[0].tolist()


# -- the format's definition ------------------------------------------------------------------------------------
# occ = (255 - v) / 255 (negate: v / 255); trinary: occ > 0.65 occupied, occ < 0.25 free, else unknown.


@pytest.mark.parametrize("plain", [False, True], ids=["P5", "P2"])
def test_trinary_thresholds_are_strict(tmp_path: Path, plain: bool) -> None:
    # v = 89: occ 0.651 > 0.65; v = 90: occ 0.647; v = 191: occ 0.251; v = 192: occ 0.247 < 0.25.
    _pgm(tmp_path, [[0, 89, 90, 191, 192, 254, 255]], plain=plain)
    assert _row(_yaml(tmp_path)) == [O, O, U, U, F, F, F]


def test_trinary_negate_reads_dark_as_free(tmp_path: Path) -> None:
    # occ = v / 255: v = 166 is 0.651 (occupied), 165 is 0.647, 64 is 0.251, 63 is 0.247 (free).
    _pgm(tmp_path, [[0, 63, 64, 165, 166, 255]])
    assert _row(_yaml(tmp_path, negate=1)) == [F, F, U, U, O, O]
    assert _row(_yaml(tmp_path, negate="true")) == [F, F, U, U, O, O]


def test_mode_defaults_to_trinary_and_thresholds_come_from_the_yaml(tmp_path: Path) -> None:
    # tb3_sandbox's free_thresh 0.196 makes 205 (occ 0.19608) unknown; 0.25 makes it free.
    _pgm(tmp_path, [[205, 206]])
    assert _row(_yaml(tmp_path, mode=None, free=0.196)) == [U, F]
    assert _row(_yaml(tmp_path, mode=None, free=0.25)) == [F, F]


def test_scale_maps_between_thresholds_linearly(tmp_path: Path) -> None:
    # v = 120: occ 0.52941 -> (0.52941 - 0.25) / 0.4 * 100 = 69.85 -> 70; v = 150: occ 0.41176 -> 40.44 -> 40.
    _pgm(tmp_path, [[0, 120, 150, 254]])
    assert _row(_yaml(tmp_path, mode="scale")) == [O, 70, 40, F]


def test_scale_reads_any_transparency_as_unknown(tmp_path: Path) -> None:
    pixels = np.array([[[0, 0, 0, 255], [0, 0, 0, 254], [255, 255, 255, 255], [120, 120, 120, 255]]], np.uint8)
    _png(tmp_path, pixels, "RGBA")
    assert _row(_yaml(tmp_path, image="m.png", mode="scale")) == [O, U, F, 70]


def test_trinary_averages_alpha_with_the_colour(tmp_path: Path) -> None:
    # shade = (r + g + b + alpha) / 4 / 255: white transparent 0.75 -> occ 0.25 (not < 0.25): unknown;
    # 170 transparent 0.5 -> occ 0.5: unknown; black transparent 0 -> occ 1: occupied; white opaque: free.
    pixels = np.array([[[255, 255, 255, 0], [170, 170, 170, 0], [0, 0, 0, 0], [255, 255, 255, 255]]], np.uint8)
    _png(tmp_path, pixels, "RGBA")
    assert _row(_yaml(tmp_path, image="m.png")) == [U, U, O, F]


def test_colour_pixels_average_their_channels(tmp_path: Path) -> None:
    # red: shade 1/3 -> occ 0.667 (occupied); yellow: shade 2/3 -> occ 0.333 (unknown); white: free.
    _png(tmp_path, np.array([[[255, 0, 0], [255, 255, 0], [255, 255, 255]]], np.uint8), "RGB")
    assert _row(_yaml(tmp_path, image="m.png")) == [O, U, F]


def test_grey_alpha_png(tmp_path: Path) -> None:
    _png(tmp_path, np.array([[[0, 255], [255, 255], [255, 0]]], np.uint8), "LA")
    assert _row(_yaml(tmp_path, image="m.png")) == [O, F, U]
    assert _row(_yaml(tmp_path, image="m.png", mode="scale")) == [O, F, U]


def test_palette_and_transparent_colour_pngs(tmp_path: Path) -> None:
    # A palette with alpha: transparent white (shade 0.75, occ 0.25: not below 0.25), black, white.
    with (tmp_path / "m.png").open("wb") as stream:
        png.Writer(3, 1, palette=[(255, 255, 255, 0), (0, 0, 0, 255), (255, 255, 255, 255)]).write(stream, [[0, 1, 2]])
    assert _row(_yaml(tmp_path, image="m.png")) == [U, O, F]
    # A grey PNG whose tRNS makes grey 255 transparent: that grey is alpha 0, the others opaque.
    with (tmp_path / "m.png").open("wb") as stream:
        png.Writer(3, 1, greyscale=True, transparent=255).write(stream, [[255, 0, 254]])
    assert _row(_yaml(tmp_path, image="m.png")) == [U, O, F]
    assert _row(_yaml(tmp_path, image="m.png", mode="scale")) == [U, O, F]


def test_low_bit_depths_use_their_full_scale(tmp_path: Path) -> None:
    # 1-bit grey: 1 is white (free); 2-bit grey: 1 is shade 1/3, occ 0.667 (occupied), 2 is occ 0.333 (unknown).
    _png(tmp_path, np.array([[0, 1]]), "L;1")
    assert _row(_yaml(tmp_path, image="m.png")) == [O, F]
    _png(tmp_path, np.array([[1, 2, 3]]), "L;2")
    assert _row(_yaml(tmp_path, image="m.png")) == [O, U, F]


def test_raw_takes_the_value_and_ignores_negate(tmp_path: Path) -> None:
    _pgm(tmp_path, [[0, 37, 100, 101, 255]])
    assert _row(_yaml(tmp_path, mode="raw")) == [0, 37, 100, U, U]
    assert _row(_yaml(tmp_path, mode="raw", negate=1)) == [0, 37, 100, U, U]


def test_sixteen_bit_pgm_and_png_use_their_full_scale(tmp_path: Path) -> None:
    # occ = 1 - v / 65535: v = 22936 is 0.650019 (occupied), 22938 is 0.649988 (unknown).
    _pgm(tmp_path, [[22936, 22938, 65535]], maxval=65535)
    assert _row(_yaml(tmp_path)) == [O, U, F]
    _pgm(tmp_path, [[22936, 22938, 65535]], maxval=65535, plain=True)
    assert _row(_yaml(tmp_path)) == [O, U, F]
    _png(tmp_path, np.array([[22936, 22938, 65535]], np.uint16), "L;16")
    assert _row(_yaml(tmp_path, image="m.png")) == [O, U, F]


def test_pgm_maxval_is_the_full_scale(tmp_path: Path) -> None:
    # maxval 1000: v = 349 is occ 0.651 (occupied), 351 is 0.649 (unknown), 751 is 0.249 (free).
    _pgm(tmp_path, [[349, 351, 751]], maxval=1000)
    assert _row(_yaml(tmp_path)) == [O, U, F]


def test_rows_run_from_the_bottom_and_metadata_is_kept(tmp_path: Path) -> None:
    _pgm(tmp_path, [[0, 0, 0], [254, 254, 254]])  # the image's top row occupied
    occupancy = load_map(_yaml(tmp_path))
    assert occupancy.grid.tolist() == [[F, F, F], [O, O, O]]
    assert (occupancy.width, occupancy.height) == (3, 2)
    assert occupancy.resolution == 0.05 and occupancy.origin == (1.0, -2.0, 0.0)
    assert occupancy.image == tmp_path / "m.pgm"


# -- the real maps ----------------------------------------------------------------------------------------------


def test_depot_loads() -> None:
    depot = load_map(SHARED_MAPS / "depot.yaml")
    assert (depot.width, depot.height, depot.resolution, depot.origin) == (604, 307, 0.05, (0.0, 0.0, 0.0))
    values, counts = np.unique(depot.grid, return_counts=True)
    # 254 free, 0 occupied; its 205 cells read free too: occ 0.196 is below the depot's free_thresh 0.25.
    assert dict(zip(values.tolist(), counts.tolist(), strict=True)) == {F: 170587 + 8894, O: 5947}
    assert depot.grid[-1, 0] == F  # the image's top-left pixel, 205


def test_tb3_sandbox_loads() -> None:
    sandbox = load_map(SHARED_MAPS / "tb3_sandbox.yaml")
    assert (sandbox.width, sandbox.height, sandbox.resolution) == (384, 384, 0.05)
    assert sandbox.origin == (-10.0, -10.0, 0.0) and sandbox.mode == "trinary"
    values, counts = np.unique(sandbox.grid, return_counts=True)
    assert dict(zip(values.tolist(), counts.tolist(), strict=True)) == {U: 138683, F: 7903, O: 870}


# -- bad input: file, line, column, field -----------------------------------------------------------------------


def _error(path: Path) -> MapError:
    with pytest.raises(MapError) as caught:
        load_map(path)
    return caught.value


@pytest.mark.parametrize(("line", "replacement", "field", "at", "words"), [
    ("resolution: 0.05", "resolution: fine", "resolution", (2, 13), "expected a number"),
    ("resolution: 0.05", "resolution: 0", "resolution", (2, 13), "above 0"),
    ("origin: [1.0, -2.0, 0.0]", "origin: [1.0, -2.0]", "origin", (3, 9), "three numbers"),
    ("origin: [1.0, -2.0, 0.0]", "origin: [1.0, -2.0, 0.5]", "origin", (3, 9), "axis-aligned"),
    ("negate: 0", "negate: 2", "negate", (4, 9), "0, 1, true or false"),
    ("occupied_thresh: 0.65", "occupied_thresh: 1.5", "occupied_thresh", (5, 18), "within 0..1"),
    ("free_thresh: 0.25", "free_thresh: 0.7", "free_thresh", (6, 14), "below occupied_thresh"),
    ("mode: trinary", "mode: fuzzy", "mode", (7, 7), "trinary, scale, raw"),
    ("image: m.pgm", "image: ''", "image", (1, 8), "image file's name"),
    ("image: m.pgm", "image: gone.pgm", "image", (1, 8), "cannot read the image"),
])
def test_bad_field_is_positioned(tmp_path: Path, line: str, replacement: str, field: str, at: tuple[int, int],
                                 words: str) -> None:
    _pgm(tmp_path, [[0, 254]])
    path = _yaml(tmp_path)
    path.write_text(path.read_text().replace(line, replacement), encoding="utf-8")
    error = _error(path)
    assert (error.path, (error.line, error.column), error.field) == (path, at, field)
    assert words in str(error) and str(error).startswith(f"{path}:{at[0]}:{at[1]}: {field}: ")


def test_missing_field_is_named(tmp_path: Path) -> None:
    _pgm(tmp_path, [[0]])
    path = _yaml(tmp_path)
    path.write_text(path.read_text().replace("free_thresh: 0.25\n", ""), encoding="utf-8")
    error = _error(path)
    assert (error.line, error.column, error.field) == (1, 1, "free_thresh") and "missing" in str(error)


def test_yaml_syntax_error_is_positioned(tmp_path: Path) -> None:
    path = tmp_path / "m.yaml"
    path.write_text("image: m.pgm\nresolution: [0.05\n", encoding="utf-8")
    error = _error(path)
    assert error.field == "file" and error.line == 3 and "not valid YAML" in str(error)


def test_missing_yaml_file(tmp_path: Path) -> None:
    error = _error(tmp_path / "none.yaml")
    assert (error.line, error.column, error.field) == (1, 1, "file") and "cannot read" in str(error)


@pytest.mark.parametrize(("content", "words"), [
    (b"not an image at all", "not a PGM (P2, P5) or PNG file"),
    (b"\x89PNG\r\n\x1a\n" + b"garbage", "cannot read the image"),
    (b"P5\n4 4\n255\n\x00\x00", "holds 2 samples, expected 4 x 4 = 16"),
    (b"P5\n2 1\n70000\n\x00\x00\x00\x00", "maxval 70000"),
    (b"P2\n2 1\n255\n0 300\n", "300 exceeds maxval 255"),
    (b"P5\n2\n", "truncated PGM header"),
])
def test_bad_image_is_positioned_at_the_image_field(tmp_path: Path, content: bytes, words: str) -> None:
    (tmp_path / "m.pgm").write_bytes(content)
    error = _error(_yaml(tmp_path))
    assert (error.line, error.column, error.field) == (1, 8, "image") and words in str(error)
