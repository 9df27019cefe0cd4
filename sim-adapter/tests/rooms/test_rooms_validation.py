# SPDX-License-Identifier: EPL-2.0
"""Thousands of generated rooms pass the real validator (rei-cli.jar, one JVM for the whole batch), and the CLI
writes them deterministically."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from rei import toolchain
from rei.rooms import MAX_HUMANS, ROOM_CLASSES, generate_room, render

SEEDS_PER_SETTING = 100  # x 22 settings = 2200 rooms


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
