# SPDX-License-Identifier: EPL-2.0
"""Thousands of generated rooms pass the real validator (rei-cli.jar, one JVM for the whole batch), and the CLI
writes them deterministically."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

from rei import toolchain
from rei.rooms import MAX_HUMANS, ROOM_CLASSES, generate_room, render

SEEDS_PER_SETTING = 100  # x 22 settings = 2200 rooms
OFFICE = Path(__file__).resolve().parents[3] / "examples" / "catalogues" / "office.rei"


def test_thousands_of_generated_rooms_pass_the_validator(tmp_path: Path) -> None:
    files = []
    for size in ROOM_CLASSES:
        for density in ("dense", "sparse"):
            for humans in range(MAX_HUMANS[size] + 1):
                for seed in range(SEEDS_PER_SETTING):
                    room = generate_room(size, density, humans, seed)
                    path = tmp_path / f"{room.stem}.rei"
                    path.write_text(render(room), encoding="utf-8")
                    files.append(path)
    assert len(set(files)) == len(files) >= 2000
    # a broken room among them proves that the validator reads every file and reports by file
    broken = tmp_path / "zz_broken.rei"
    broken.write_text(render(generate_room("small", seed=1)).replace("goto F_6_", "goto F_9_"), encoding="utf-8")
    java, jar = toolchain.find_java(), toolchain.find_jar("cli")
    done = subprocess.run([str(java.executable), "-XX:TieredStopAtLevel=1", "-jar", str(jar), "validate",
                           *map(str, files), str(broken), "--quiet"],
                          capture_output=True, text=True, timeout=300, check=False)
    reported = {line.split(":", 1)[0] for line in done.stdout.splitlines() + done.stderr.splitlines() if ": error:" in line}
    assert reported == {str(broken)}, (done.stdout + done.stderr)[-3000:]
    assert done.returncode == 1


def test_gen_rooms_writes_the_same_files_for_the_same_seed(tmp_path: Path) -> None:
    def generate(out: Path) -> dict[str, str]:
        done = subprocess.run([sys.executable, "-m", "rei.cli", "gen-rooms", "--size", "medium", "--count", "3",
                               "--seed", "11", "-o", str(out)], capture_output=True, text=True, timeout=120, check=False)
        assert done.returncode == 0, done.stderr
        assert done.stdout.count("9 objects, 1 humans, 2 goals") == 3
        return {p.name: p.read_text(encoding="utf-8") for p in out.glob("*.rei")}

    first = generate(tmp_path / "a")
    assert sorted(first) == [f"medium_sparse_h1_s11_0{i}.rei" for i in (1, 2, 3)]
    assert generate(tmp_path / "b") == first
    bad = subprocess.run([sys.executable, "-m", "rei.cli", "gen-rooms", "--size", "small", "--humans", "5", "-o",
                          str(tmp_path / "c")], capture_output=True, text=True, timeout=120, check=False)
    assert bad.returncode == 2 and "a small room holds 0 to 2 humans" in bad.stderr


def test_gen_rooms_furnishes_from_a_user_catalogue_and_the_rooms_import_it(tmp_path: Path) -> None:
    catalogue = OFFICE
    out = tmp_path / "rooms"
    done = subprocess.run([sys.executable, "-m", "rei.cli", "gen-rooms", "--size", "small", "--count", "4",
                           "--seed", "3", "--catalogue", str(catalogue), "-o", str(out)],
                          capture_output=True, text=True, timeout=300, check=False)
    assert done.returncode == 0, done.stderr
    files = sorted(out.glob("*.rei"))
    assert len(files) == 4
    declared = {"Sofa", "Pillar", "Plant"}  # the catalogue's `object` types; Trolley is dynamic
    used: set[str] = set()
    for path in files:
        text = path.read_text(encoding="utf-8")
        assert f'import "{Path(os.path.relpath(catalogue, out)).as_posix()}"' in text.splitlines()
        assert "robot tb3 : Burger on" in text
        used |= set(re.findall(r"object \w+ : (\w+) on", text))
    assert used and used <= declared, used
    java, jar = toolchain.find_java(), toolchain.find_jar("cli")
    checked = subprocess.run([str(java.executable), "-jar", str(jar), "validate", *map(str, files)],
                             capture_output=True, text=True, timeout=300, check=False)
    assert checked.returncode == 0, checked.stdout + checked.stderr


def test_gen_rooms_refuses_a_catalogue_it_can_not_use_with_the_reason(tmp_path: Path) -> None:
    def gen_rooms(*options: str) -> subprocess.CompletedProcess[str]:
        return subprocess.run([sys.executable, "-m", "rei.cli", "gen-rooms", "--size", "small", *options, "-o",
                               str(tmp_path / "out")], capture_output=True, text=True, timeout=300, check=False)

    invalid = tmp_path / "invalid.rei"
    invalid.write_text('catalogue C {\n  type Crate : object box 0.5 x 0.5 x 0.5 colour "brown"\n}\n',
                       encoding="utf-8")
    done = gen_rooms("--catalogue", str(invalid))
    assert done.returncode == 2 and "invalid.rei:2:50: error: Colour 'brown'" in done.stderr, done.stderr
    large = tmp_path / "large.rei"
    large.write_text("catalogue C {\n  type Bed : object box 2.0 x 1.4 x 0.5\n}\n", encoding="utf-8")
    done = gen_rooms("--catalogue", str(large))
    assert done.returncode == 2 and "type Bed (2 x 1.4 m) does not fit a generated room's floor" in done.stderr
    done = gen_rooms("--catalogue", str(OFFICE), "--robot", "Rover")
    assert done.returncode == 2 and "declares no such robot type (robot types: Burger, Waffle)" in done.stderr
    assert gen_rooms("--robot", "Burger").returncode == 2
