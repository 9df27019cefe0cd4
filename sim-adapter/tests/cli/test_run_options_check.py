# SPDX-License-Identifier: EPL-2.0
"""`rei run` checks its mission options before anything starts, and with the defaults that check imports none of
the mission's modules: the run takes the service's router over and starts its simulation right after it. With
them imported first (numpy, the artifacts', pybullet through rei.sim) the simulation started 1.7-1.9 s after the
command instead of 0.43-0.65 s (four runs each, alternately, load 9-11)."""

from __future__ import annotations

import subprocess
import sys

import pytest

from rei.cli import build_parser
from rei.cli._mission_options import check_mission_options
from rei.cli.errors import CommandError

HEAVY = ("numpy", "pybullet", "rei.sim", "rei.artifacts", "rei.wamp.codec", "rei.sut.api")

PROBE = f"""
import sys
from rei.cli import build_parser
from rei.cli._mission_options import check_mission_options

args = build_parser("run").parse_args(["run", "case.rei", "-o", "out", *sys.argv[1:]])
check_mission_options(args)
print(",".join(name for name in {HEAVY!r} if name in sys.modules))
"""


def _imported_by_the_check(*options: str) -> list[str]:
    done = subprocess.run([sys.executable, "-c", PROBE, *options], capture_output=True, text=True, timeout=120,
                          check=True)
    return [name for name in done.stdout.strip().split(",") if name]


def test_the_default_options_are_checked_without_the_missions_modules() -> None:
    assert _imported_by_the_check() == []
    assert _imported_by_the_check("--seed", "3", "--state-rate", "10", "--no-humans") == []


def test_options_that_need_the_missions_modules_are_still_checked_with_them() -> None:
    assert "rei.sut.api" in _imported_by_the_check("--controller", "nav:max_linear=0.2")
    assert "rei.sim" in _imported_by_the_check("--fault", "laser:blackout,from=5,to=7")


@pytest.mark.parametrize(("options", "message"), [
    (["--controller", "no-such-controller"], "no-such-controller"),
    (["--controller", "nav:no_such_key=1"], "no_such_key"),
    (["--fault", "laser:no-such-kind"], "no-such-kind"),
    (["--state-rate", "0"], "--state-rate must be positive"),
    (["--laser", "full", "--collector", "no-such-file.yaml"], "no-such-file.yaml"),
])
def test_a_wrong_option_is_refused_before_anything_starts(options: list[str], message: str) -> None:
    args = build_parser("run").parse_args(["run", "case.rei", "-o", "out", *options])
    with pytest.raises(CommandError, match=message):
        check_mission_options(args)
