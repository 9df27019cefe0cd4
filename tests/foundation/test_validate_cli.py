# SPDX-License-Identifier: EPL-2.0
"""`rei validate` / `rei generate` as a user runs them: exit codes and `PATH:LINE:COL: severity: message` lines."""

from __future__ import annotations

import re
from collections.abc import Callable
from pathlib import Path
from typing import Any

VALID = """\
testcase Ok {
  room Lab size 3 x 2 {
    object table1 : Table on F_1_1
    robot tb3 : Waffle on F_0_0
  }
  mission Go { goto F_2_1 goto F_0_1 }
}
"""

# Line 3 names a floor the 3 x 2 grid does not have.
UNKNOWN_FLOOR = VALID.replace("on F_1_1", "on F_9_9")

# Lines 3 and 4 declare the same name.
DUPLICATE_NAME = VALID.replace("    robot tb3", "    object table1 : Table on F_2_0\n    robot tb3")


def diagnostics(stderr: str, path: Path, severity: str = "error") -> list[tuple[int, int, str]]:
    """(line, column, message) of every diagnostic line about `path`; the path may be printed as given or
    relative, so it is matched by its file name."""
    pattern = re.compile(rf"^(?:.*/)?{re.escape(path.name)}:(\d+):(\d+): {severity}: (.*)$", re.MULTILINE)
    return [(int(line), int(column), message) for line, column, message in pattern.findall(stderr)]


def test_valid_file_exits_0_without_errors(
    run_cli: Callable[..., Any], write_rei: Callable[..., Path]
) -> None:
    path = write_rei("ok.rei", VALID)
    result = run_cli("validate", path)
    assert result.returncode == 0, result.stderr
    assert diagnostics(result.stderr, path) == []


def test_unknown_floor_exits_1_with_a_located_error(
    run_cli: Callable[..., Any], write_rei: Callable[..., Path]
) -> None:
    path = write_rei("broken.rei", UNKNOWN_FLOOR)
    result = run_cli("validate", path)
    assert result.returncode == 1, result.stderr
    found = diagnostics(result.stderr, path)
    assert found, f"no '{path.name}:LINE:COL: error:' line in:\n{result.stderr}"
    line, column, message = found[0]
    assert line == 3 and column >= 1, found
    assert "F_9_9" in message


def test_duplicate_names_are_errors(run_cli: Callable[..., Any], write_rei: Callable[..., Path]) -> None:
    path = write_rei("duplicate.rei", DUPLICATE_NAME)
    result = run_cli("validate", path)
    assert result.returncode == 1, result.stderr
    assert {line for line, _, _ in diagnostics(result.stderr, path)} & {3, 4}, result.stderr


def test_valid_and_broken_files_together_exit_1_naming_only_the_broken_one(
    run_cli: Callable[..., Any], write_rei: Callable[..., Path]
) -> None:
    good, bad = write_rei("good.rei", VALID), write_rei("bad.rei", UNKNOWN_FLOOR)
    result = run_cli("validate", good, bad)
    assert result.returncode == 1, result.stderr
    assert diagnostics(result.stderr, bad) and not diagnostics(result.stderr, good)


def test_a_map_room_with_a_tiny_floor_size_is_a_located_error_and_the_other_files_are_reported(
    run_cli: Callable[..., Any], write_rei: Callable[..., Path], repo_root: Path, tmp_path: Path
) -> None:
    """Issue #37: examples/maps/two_rooms.rei with `floorSize 0.0000001` (10 x 6 m in 6 * 10^15 blocks) made
    `rei validate` die of a NegativeArraySizeException, unpositioned, and report none of the other files."""
    for name in ("two_rooms.yaml", "two_rooms.pgm"):
        (tmp_path / name).write_bytes((repo_root / "examples" / "maps" / name).read_bytes())
    example = (repo_root / "examples" / "maps" / "two_rooms.rei").read_text(encoding="utf-8")
    tiny = write_rei("tiny.rei", example.replace("floorSize 0.5", "floorSize 0.0000001"))
    bad, good = write_rei("bad.rei", UNKNOWN_FLOOR), write_rei("good.rei", VALID)
    result = run_cli("validate", tiny, bad, good)
    assert result.returncode == 1, result.stderr
    line = example.splitlines().index('  room Office occupancy "two_rooms.yaml" floorSize 0.5 {') + 1
    column = len('  room Office occupancy "two_rooms.yaml" floorSize ') + 1
    assert diagnostics(result.stderr, tiny) == [(line, column, (
        "floorSize 0.0000001 m cuts the map two_rooms.yaml (200 x 120 cells of 0.05 m) into 100000000 x 60000000 "
        "blocks: a room's map may be cut into at most 4000000 blocks (free or not); use a larger floorSize "
        "[org.rei.dsl.roomTooLarge]"))], result.stderr
    assert diagnostics(result.stderr, bad) and not diagnostics(result.stderr, good), result.stderr
    assert "Exception" not in result.stderr, result.stderr


def test_missing_file_exits_2(run_cli: Callable[..., Any], tmp_path: Path) -> None:
    missing = tmp_path / "nowhere.rei"
    result = run_cli("validate", missing)
    assert result.returncode == 2, result.stderr
    assert "nowhere.rei" in result.stderr
    assert "Exception" not in result.stderr and "Traceback" not in result.stderr


def test_generate_of_a_broken_file_exits_1_and_writes_nothing(
    run_cli: Callable[..., Any], write_rei: Callable[..., Path], tmp_path: Path
) -> None:
    out = tmp_path / "out"
    path = write_rei("broken.rei", UNKNOWN_FLOOR)
    result = run_cli("generate", path, "-o", out)
    assert result.returncode == 1, result.stderr
    assert diagnostics(result.stderr, path)
    assert not (out / "world.json").exists()


def test_a_case_reports_the_errors_of_the_catalogue_it_imports_in_that_file(
    run_cli: Callable[..., Any], write_rei: Callable[..., Path]
) -> None:
    catalogue = write_rei("furniture.rei", 'catalogue F {\n  type Sofa : object box 1.1 x 0.8 x -0.8\n}\n')
    case = write_rei("with_sofa.rei", 'import "furniture.rei"\n' + VALID.replace("table1 : Table", "sofa : Sofa"))
    result = run_cli("validate", case)
    assert result.returncode == 1
    assert diagnostics(result.stderr, catalogue) == [(2, 38, "The height must be above 0 [org.rei.dsl.nonPositive]")]
    assert diagnostics(result.stderr, case) == []
    generated = run_cli("generate", case, "-o", case.parent / "out")
    assert generated.returncode == 1 and not (case.parent / "out" / "world.json").exists()
