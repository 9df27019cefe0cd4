# SPDX-License-Identifier: EPL-2.0
"""The page's /config.json: the room, sampled trajectories, goals, utilities and the router's address."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from rei.artifacts import ArtifactError
from rei.evaluation import DEFAULT_UTILITIES
from rei.report.colours import SIGNAL_COLOURS
from rei.spline import Trajectory
from rei.view import RouterAuth, view_config

URL = "ws://127.0.0.1:8080/ws"


def test_everything_the_page_draws_comes_from_the_case(room: Path) -> None:
    config = view_config(URL, "run-1", room)
    assert config["format"] == "rei-view/1"
    assert config["router"] == {"url": URL, "realm": "rei", "auth": None}
    assert config["topics"] == {"state": "rei.run.run-1.state", "mission": "rei.run.run-1.mission",
                                "signal": "rei.run.run-1.signal"}
    assert config["world"] == json.loads((room / "world.json").read_text())
    assert [g["index"] for g in config["mission"]["goals"]] == list(range(len(config["mission"]["goals"])))
    assert config["utilities"] == dict(DEFAULT_UTILITIES)
    assert config["colours"] == SIGNAL_COLOURS
    json.dumps(config, allow_nan=False)  # the page gets strict JSON


def test_a_looping_trajectory_is_sampled_over_one_period_with_the_simulators_spline(room: Path) -> None:
    (path,) = view_config(URL, "r", room)["paths"]
    assert path["name"] == "h1" and path["category"] == "HUMAN"
    points = path["points"]
    assert len(points) == 241
    assert points[0] == pytest.approx(points[-1])  # closed
    # h1: (1.5, 2.7) @ 0 s, (3.5, 2.7) @ 4 s, (3.5, 1.9) @ 6 s, (1.5, 1.9) @ 10 s, loop -> period 14 s
    spline = Trajectory([0.0, 4.0, 6.0, 10.0], [(1.5, 2.7), (3.5, 2.7), (3.5, 1.9), (1.5, 1.9)], True)
    assert points[60] == pytest.approx(spline.position(14.0 * 60 / 240), abs=1e-4)
    assert points[0] == pytest.approx([1.5, 2.7])


def test_missing_case_files_are_simply_not_drawn(tmp_path: Path) -> None:
    config = view_config(URL, "r", tmp_path)
    assert (config["world"], config["paths"], config["mission"]) == (None, [], None)
    bare = view_config(URL, "r", None)
    assert (bare["world"], bare["paths"], bare["mission"]) == (None, [], None)


def test_utilities_come_from_the_runs_file(tmp_path: Path) -> None:
    table = tmp_path / "u.yaml"
    table.write_text("SIG_GEOM_FAR_TRANSIT_CLOSE: -7\n")
    assert view_config(URL, "r", None, utilities=table)["utilities"]["SIG_GEOM_FAR_TRANSIT_CLOSE"] == -7.0


def test_credentials_are_passed_for_a_router_that_authenticates() -> None:
    config = view_config(URL, "r", None, auth=RouterAuth("viewer", "s3cret", "wampcra"))
    assert config["router"]["auth"] == {"authid": "viewer", "method": "wampcra", "secret": "s3cret"}
    with pytest.raises(ValueError, match="cryptosign"):
        RouterAuth("viewer", "x", "cryptosign")


@pytest.mark.parametrize(("url", "run_id"), [("rs://127.0.0.1:1", "r"), ("http://x/ws", "r"), (URL, "a.b")])
def test_bad_addresses_are_refused(url: str, run_id: str) -> None:
    with pytest.raises(ValueError):
        view_config(url, run_id, None)


def test_an_unreadable_world_is_an_error_not_an_empty_room(tmp_path: Path) -> None:
    (tmp_path / "world.json").write_text("{not json")
    with pytest.raises(ArtifactError, match="world.json"):
        view_config(URL, "r", tmp_path)


def test_infinite_values_never_reach_the_json(room: Path) -> None:
    text = json.dumps(view_config(URL, "r", room), allow_nan=False)
    assert "Infinity" not in text and "NaN" not in text
