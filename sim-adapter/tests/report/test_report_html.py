# SPDX-License-Identifier: EPL-2.0
"""report.html from synthetic run folders: what each plot contains, and what the page says when pieces are
missing. The SVGs are parsed as XML, so a malformed drawing fails here, not in someone's browser."""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from rei.report import write_report
from rei.report.__main__ import main
from rei.report.decimate import MAX_PATH_POINTS

from .runs import SIGNALS, make_run

SVG = "{http://www.w3.org/2000/svg}"


def svg(page: str, element_id: str) -> ET.Element:
    match = re.search(rf'<svg id="{element_id}".*?</svg>', page, re.DOTALL)
    assert match, f"no <svg id={element_id!r}> in the report"
    return ET.fromstring(match[0])


def by_id(root: ET.Element, element_id: str) -> ET.Element:
    found = root.find(f".//*[@id='{element_id}']")
    assert found is not None, element_id
    return found


def points(polyline: ET.Element) -> list[tuple[float, float]]:
    return [tuple(map(float, p.split(","))) for p in polyline.get("points", "").split()]  # type: ignore[misc]


@pytest.fixture
def page(tmp_path: Path) -> str:
    return write_report(make_run(tmp_path / "out")).read_text(encoding="utf-8")


def test_map_draws_room_paths_and_one_marker_per_place(page: str) -> None:
    room = svg(page, "map")
    true_path, believed = points(by_id(room, "map-robot-path")), points(by_id(room, "map-believed-path"))
    assert len(true_path) == len(believed) == 81
    # the robot drives right along y = 0.5: one pixel row, x growing; the belief drifts upwards on screen
    assert len({y for _, y in true_path}) == 1 and true_path[-1][0] > true_path[0][0]
    assert believed[-1][1] < true_path[-1][1]
    world = by_id(room, "map-world")
    assert len(world.findall(f"{SVG}polygon[@class='wall']")) > 0
    assert [t.text for t in world.iter(f"{SVG}text")] == ["table1"]
    assert len(by_id(room, "map-humans").findall(f"{SVG}polyline")) == 1
    assert len(by_id(room, "map-goals").findall(f"{SVG}circle")) == 2
    markers = by_id(room, "map-signals").findall(f"{SVG}circle")
    assert len(markers) == len(SIGNALS)  # four signals at four different places
    collision = next(m for m in markers if m.get("data-signal") == "SIG_GEOM_CLOSE_TRANSIT_COLLISION")
    title = collision.find(f"{SVG}title")
    assert title is not None and "t = 3.00 s" in title.text and "table1" in title.text  # type: ignore[operator]
    # the marker sits where the robot was at t = 3 s: x = 0.8 m
    assert float(collision.get("cx", "0")) == pytest.approx(true_path[60][0], abs=0.1)


def test_utility_is_a_step_line_of_the_running_total(page: str) -> None:
    chart = svg(page, "utility")
    line = points(by_id(chart, "utility-line"))
    assert len(line) == 2 + 2 * len(SIGNALS)  # start, a jump per event, flat to the end
    assert [y for _, y in line[1:-1:2]] == [y for _, y in line[0:-2:2]]  # each jump starts at the last level
    assert line[-1][1] == line[-2][1]  # flat after the last signal
    y_of = dict(zip([20, 18, 8, 28], [line[2 + 2 * i][1] for i in range(4)], strict=True))
    assert y_of[28] < y_of[20] < y_of[18] < y_of[8]  # a higher total is higher on the screen
    assert line[0][1] > y_of[8]  # the start (0) is below every total of this run
    assert len(by_id(chart, "utility-events").findall(f"{SVG}circle")) == 4
    assert "total 28" in page


def test_signal_bars_count_each_kind(page: str) -> None:
    bars = svg(page, "signals").findall(f"{SVG}rect[@class='bar']")
    assert {b.get("data-signal"): int(b.get("data-count", "0")) for b in bars} == {s["signal"]: 1 for s in SIGNALS}


def test_verdicts_facts_and_no_script_or_remote_resource(page: str) -> None:
    verdicts = re.search(r'<table id="verdicts">.*?</table>', page, re.DOTALL)
    assert verdicts and verdicts[0].count('<tr class="verdict">') == 2
    assert "MISSION_SIMPLE" in verdicts[0] and "t = 3.00 s" in verdicts[0] and "&lt;no&gt; collision" in verdicts[0]
    assert '<span class="badge fail">1 fail</span>' in page
    for fact in ("abc123", "4.00 s", "28.00", "0.040 m at t = 4.00 s"):
        assert fact in page
    assert "<script" not in page.lower()
    assert not re.search(r'(src|href)\s*=\s*"(https?:)?//', page)  # nothing loaded at view time


def test_missing_pieces_are_said_not_drawn_empty(tmp_path: Path) -> None:
    out = make_run(tmp_path / "out", signals=False, events=False, summary=False, case=False)
    page = write_report(out).read_text(encoding="utf-8")
    assert 'id="signals-missing">no signals recorded' in page
    assert 'id="utility-missing">no events.csv' in page
    assert 'id="verdicts-missing">no summary.json' in page
    assert "no world.json: the map is not drawn" in page
    assert len(points(by_id(svg(page, "map"), "map-robot-path"))) == 81  # the path is still there


def test_signals_fall_back_to_events_csv(tmp_path: Path) -> None:
    page = write_report(make_run(tmp_path / "out", signals=False)).read_text(encoding="utf-8")
    assert "4 (from events.csv)" in page
    assert len(svg(page, "signals").findall(f"{SVG}rect[@class='bar']")) == 4


def test_long_runs_are_decimated(tmp_path: Path) -> None:
    out = make_run(tmp_path / "out", states=12_001, rate=100.0)
    page = write_report(out).read_text(encoding="utf-8")
    path = by_id(svg(page, "map"), "map-robot-path")
    assert len(points(path)) == MAX_PATH_POINTS and path.get("data-samples") == "12001"
    assert len(page) < 1_000_000


def test_command_prints_both_files_and_rejects_a_non_run(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = make_run(tmp_path / "out")
    assert main(out) == 0
    printed = capsys.readouterr().out
    assert f"report: {out / 'report.html'}" in printed and f"{out / 'run.mcap'}" in printed
    assert (out / "report.html").is_file() and (out / "run.mcap").is_file()
    assert main(tmp_path / "nowhere") == 2
    (tmp_path / "empty").mkdir()
    assert main(tmp_path / "empty") == 2
    assert "not a run folder" in capsys.readouterr().err


def test_fault_windows_are_shaded_behind_the_utility_line() -> None:
    from rei.report.charts import render_utility
    from rei.report.run_data import EventRow

    events = [EventRow(0.0, "SIG_MISSION_BEGIN", 20, 20, "tb3", "mission"),
              EventRow(4.0, "SIG_FAULT_LASER_BLACKOUT_BEGIN", 0, 20, "tb3", "mission")]
    svg = ET.fromstring(render_utility(events, 10.0, [("laser blackout", 4.0, 7.0), ("laser noise", 8.0, None)]))
    ns = {"s": "http://www.w3.org/2000/svg"}
    rects = svg.findall("s:g[@id='fault-windows']/s:rect", ns)
    assert [r.findtext("s:title", namespaces=ns) for r in rects] == [
        "laser blackout: 4 s to 7 s", "laser noise: 8 s to the end"]
    blackout, noise = (float(r.get("width", "0")) for r in rects)
    assert blackout == pytest.approx(1.5 * noise, rel=0.01)  # 3 s against the 2 s left of the run
    assert svg.find("s:g[@id='fault-windows']", ns) is not None
    assert ET.fromstring(render_utility(events, 10.0)).find("s:g[@id='fault-windows']", ns) is None


@pytest.mark.parametrize("footprint", [None, {"type": "polygon", "points": [[-0.1, -0.08], [0.04, -0.09], [0.05, 0.0],
                                                                               [0.04, 0.09], [-0.1, 0.08]]},
                                       {"type": "circle", "x": 0.05, "y": 0.0, "radius": 0.17}])
def test_the_map_draws_the_robot_s_outline(tmp_path: Path, footprint: dict | None) -> None:
    """A box robot's rectangle; a described robot's footprint as world.json has it, placed and turned at each end."""
    import json

    out = make_run(tmp_path / "out")
    world_file = out / "case" / "world.json"
    world = json.loads(world_file.read_text())
    if footprint is not None:
        world["robot"]["footprint"] = footprint
        world_file.write_text(json.dumps(world))
    room = svg(write_report(out).read_text(encoding="utf-8"), "map")
    robot, path = by_id(room, "map-robot"), points(by_id(room, "map-robot-path"))
    shapes = [e for e in robot if e.get("class") in ("robot-start", "robot-end")]
    assert len(shapes) == 2
    if footprint is None or footprint["type"] == "polygon":
        assert all(e.tag == f"{SVG}polygon" for e in shapes)
        assert len(points(shapes[0])) == (4 if footprint is None else len(footprint["points"]))
    else:
        # the robot drives along +x (yaw 0): the circle's centre is 0.05 m ahead of the path's end, its radius drawn
        assert all(e.tag == f"{SVG}circle" for e in shapes)
        end = shapes[1]
        scale = (path[-1][0] - path[0][0]) / 0.4  # pixels a metre: make_run's robot drives 0.1 m/s for 4 s
        assert float(end.get("cx")) - path[-1][0] == pytest.approx(0.05 * scale, abs=0.2)
        assert float(end.get("r")) == pytest.approx(0.17 * scale, abs=0.2)
