# SPDX-License-Identifier: EPL-2.0
"""A campaign's resume keeps a generated case only while everything it was generated from is unchanged: the case,
its catalogues, and the files its robot's description was read from (the generator lists them in the case's
robot.sources), with the real generator."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

from rei.campaign.plan import CaseSource
from rei.campaign.prepare import needs_generation, prepare_case

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "robots"


def test_a_case_is_generated_again_when_its_robot_description_changed(tmp_path: Path) -> None:
    for name in ("round_bot.rei", "catalogue.rei", "round_bot.urdf"):
        shutil.copy(EXAMPLES / name, tmp_path / name)
    source, out = CaseSource("round", "g", tmp_path / "round_bot.rei", None), tmp_path / "out"
    assert prepare_case(source, out).generated
    case = source.case_dir(out)
    assert (case / "robot.sources").read_text(encoding="utf-8").splitlines() == [str(tmp_path / "round_bot.urdf")]
    assert not needs_generation(source, out) and not prepare_case(source, out).generated  # unchanged: kept

    urdf = tmp_path / "round_bot.urdf"  # the body grows: the catalogue and the case are as they were
    urdf.write_text(urdf.read_text(encoding="utf-8").replace('radius="0.17"', 'radius="0.2"'), encoding="utf-8")
    assert needs_generation(source, out)
    assert prepare_case(source, out).generated
    assert json.loads((case / "world.json").read_text(encoding="utf-8"))["robot"]["footprint"]["radius"] == 0.2
    assert not prepare_case(source, out).generated

    urdf.unlink()  # gone: generated again, and the generator says so
    prepared = prepare_case(source, out)
    assert prepared.generated and "round_bot.urdf" in (prepared.error or "")
