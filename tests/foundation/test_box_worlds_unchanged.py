# SPDX-License-Identifier: EPL-2.0
"""Polygon furniture (docs/language.md#catalogues) changed nothing for boxes and cylinders: a case of box and
cylinder furniture, a user catalogue's types, a dynamic object, a human and the Waffle generates the very bytes,
and records the very state and mission streams, that the generator and the simulator gave before polygons existed
(the SHA-256 below were taken from the commit before them, 1713603)."""

from __future__ import annotations

import hashlib
from collections.abc import Callable
from pathlib import Path
from typing import Any

from rei.run import MissionRunOptions, run_mission

CATALOGUE = """\
catalogue Shapes {
  type Crate : object box 0.6 x 0.4 x 0.5 mass 12 colour "#8B5A2B"
  type Drum : object cylinder 0.45 x 0.45 x 0.9 colour "#3A7D44"
  type Trolley : dynamic box 0.6 x 0.4 x 1.0 mass 15
}
"""
CASE = """\
import "shapes.rei"
testcase BoxesAndCylinders {
  room Lab size 6 x 4 {
    object table1 : Table on F_3_1 yaw 30
    object crate : Crate on F_1_2 yaw 90
    object drum : Drum on F_4_3
    dynamic cart : Trolley trajectory [F_5_0 @ 0s, F_5_2 @ 8s] loop
    human h1 trajectory [F_0_3 @ 0s, F_2_3 @ 10s] loop
    robot tb3 : Waffle on F_0_0
  }
  mission Deliver { goto F_5_3 goto F_0_0 }
  monitor { close 0.25 collision 0.01 }
}
"""
BEFORE = {
    "animation.json": "9b0e99010bee855781d0ac11ecd03b68523464abaa0360675e530531e4d4d9ed",
    "mission.xml": "f1d40924cb048b6f94a8486f7b505ad6cc7fefab485ef9fc0fa4b8379c205418",
    "monitor.json": "cb91bce998c6d4658c863d2ca5782ad1bb4199a334419a949e6d7616d257be6e",
    "world.json": "68ffa45f5e9adf4b205f1dcee3fdc62f212ade46489920a2cd700a39e3ca07d8",
    "world.sdf": "59393a0d1d2cdc5f6c66ccac674dbc1db410decb21113f35c226801518830675",
}
#: The recorded streams of a 4 s weaving drive (a script), seed 3.
STREAMS_BEFORE = {
    "state.msgpack": "910a7d78aea6d210168ace6596ee0b389602d6d155b3353368d633bbed80998a",
    "mission.msgpack": "ce23ee089dbfcd884c65ac4a8fda135c46e23fc77f53bdd49a683643c3389658",
}


def test_boxes_and_cylinders_generate_and_simulate_as_before(tmp_path: Path, run_cli: Callable[..., Any]) -> None:
    (tmp_path / "shapes.rei").write_text(CATALOGUE, encoding="utf-8")
    (tmp_path / "case.rei").write_text(CASE, encoding="utf-8")
    result = run_cli("generate", tmp_path / "case.rei", "-o", tmp_path / "out")
    assert result.returncode == 0, result.stderr
    found = {name: hashlib.sha256((tmp_path / "out" / name).read_bytes()).hexdigest() for name in BEFORE}
    assert found == BEFORE
    script = tmp_path / "weave.script"
    script.write_text("2.0 0.25 0.6\n2.0 0.25 -0.6\n", encoding="utf-8")
    run_mission(tmp_path / "out", tmp_path / "run", MissionRunOptions(controller=f"script:{script}", seed=3),
                run_id="boxes")
    recorded = {name: hashlib.sha256((tmp_path / "run" / "streams" / name).read_bytes()).hexdigest()
                for name in STREAMS_BEFORE}
    assert recorded == STREAMS_BEFORE
