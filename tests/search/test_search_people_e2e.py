# SPDX-License-Identifier: EPL-2.0
"""`rei search` over a person who sees the robot (a human on a route), end to end with the real room editor engine,
generator, people server, simulation, monitor jar and evaluator: each candidate's text carries the sampled start,
speed, behaviour and stop floor on the person's route line, its generated case walks them, and its run completes.
A spec that gives a person a key of the other kind is refused at the key, with its other mistakes."""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

CASE = """\
// a person crosses the robot's way
testcase PeopleSearch {
  room Hall size 6 x 3 {
    human ann route [F_3_2, F_3_0 wait 1s] speed 1.0 loop
    human walker trajectory [F_1_2 @ 0s, F_1_0 @ 4s]
    robot tb3 : Waffle on F_0_1
  }
  mission Across { timeout 60s goto F_3_1 goto F_5_1 }
  monitor { close 0.25 collision 0.01 maxHumanCollisions 1 }
}
"""

SPEC = """\
case: people.rei
budget: 3
seed: 2
timeout: 240
parameters:
  - {human: ann, start: [0, 8], speed: [0.6, 1.6], behaviour: [avoids, ignores, curious, scared, blocks]}
  - {human: ann, stop: 1, floor: [F_3_0, F_4_0]}
objectives:
  - {metric: clearance_humans_min}
shrink: {budget: 0}
"""

#: The person's line in a candidate: its stops, then its options in the order the editor keeps them.
ROUTE = re.compile(r"^    human ann route \[F_3_2, (F_\d_\d) wait 1s\] (.*)$", re.MULTILINE)


def options(line: str) -> dict[str, str]:
    """``speed 0.73 loop start 2.5s curious`` as {speed: 0.73, start: 2.5s, loop: '', curious: ''}."""
    words = line.split()
    found: dict[str, str] = {}
    i = 0
    while i < len(words):
        if words[i] in ("speed", "start"):
            found[words[i]] = words[i + 1]
            i += 2
        else:
            found[words[i]] = ""
            i += 1
    return found


def test_a_search_over_a_routed_person_edits_its_route_and_runs_it(tmp_path: Path, run_cli: Any) -> None:
    (tmp_path / "people.rei").write_text(CASE, encoding="utf-8")
    spec = tmp_path / "people.yaml"
    spec.write_text(SPEC, encoding="utf-8")
    out = tmp_path / "out"
    result = run_cli("search", spec, "-o", out, "--workers", "1", timeout=900)
    assert result.returncode in (0, 1), result.stdout + result.stderr
    document = json.loads((out / "search.json").read_text(encoding="utf-8"))
    evaluations = document["evaluations"]
    assert document["counts"]["simulated"] == 3 and document["counts"]["errors"] == 0, document["counts"]
    assert len(evaluations) == 3 and {r["status"] for r in evaluations} == {"COMPLETED"}, evaluations
    for record in evaluations:
        params = record["params"]
        assert set(params) == {"ann.start", "ann.speed", "ann.behaviour", "ann.stops.1"}
        text = (out / "candidates" / f"{record['key']}.rei").read_text(encoding="utf-8")
        match = ROUTE.search(text)
        assert match, text
        written = options(match[2])
        assert match[1] == params["ann.stops.1"]
        assert float(written["speed"]) == round(params["ann.speed"], 3)
        assert float(written["start"].removesuffix("s")) == round(params["ann.start"], 3)
        assert "loop" in written
        behaviours = {"avoids", "ignores", "curious", "scared", "blocks"} & set(written)
        # avoids is the default: the base case does not write it, and neither does a candidate that keeps it
        assert behaviours == ({params["ann.behaviour"]} if params["ann.behaviour"] != "avoids" else set()), written
        # the rest of the case is the base case's, as written (its comment and the trajectory human included)
        others = [line for line in text.splitlines()[1:] if not line.startswith("    human ann")]
        assert others == [line for line in (tmp_path / "people.rei").read_text(encoding="utf-8").splitlines()
                          if not line.startswith("    human ann")]
        # the generated case walks the person as sampled, and the run finished and was judged
        [person] = json.loads((out / "cases" / record["key"] / "animation.json").read_text(encoding="utf-8"))["people"]
        assert (person["behaviour"], person["loop"]) == (params["ann.behaviour"], True)
        assert person["speed"] == round(params["ann.speed"], 3)
        assert person["start"] == round(params["ann.start"], 3)
        assert [stop["floor"] for stop in person["route"]] == ["F_3_2", params["ann.stops.1"]]
        summary = json.loads((out / "runs" / record["key"] / "summary.json").read_text(encoding="utf-8"))
        assert summary["verdicts"], summary
        assert record["values"] and record["values"][0] is not None, record


BAD = """\
case: people.rei
parameters:
  - {human: ann, points: [any, any], behaviour: [curious]}
  - {human: walker, behaviour: [blocks], start: [0, 5]}
  - {human: ann, stop: 4, floor: any}
  - {human: ann, speed: [0.5, 4]}
objectives:
  - {metric: clearence_humans_min}
"""


def test_keys_of_the_other_kind_of_person_are_refused_at_the_key(tmp_path: Path, run_cli: Any) -> None:
    (tmp_path / "people.rei").write_text(CASE, encoding="utf-8")
    spec = tmp_path / "bad.yaml"
    spec.write_text(BAD, encoding="utf-8")
    out = tmp_path / "out"
    result = run_cli("search", spec, "-o", out, timeout=120)
    assert result.returncode == 2, result.stdout + result.stderr
    lines = result.stderr.splitlines()
    assert lines[:5] == [
        (f"rei: error: {spec}:3:18: ann walks a route (a person who sees the robot): 'points' is a trajectory's; a "
        "route's keys are start, speed, loop, behaviour, stop (a stop's floors: {human: ann, stop: INDEX, floor: "
        "[...]})"),
        (f"rei: error: {spec}:4:21: walker is a human on a trajectory: 'behaviour' is a route's (a person who sees the "
        "robot); a trajectory's keys are points, start, speed, loop"),
        f"rei: error: {spec}:5:18: ann's route has 2 stop(s), counted from 0: stop 4 is not one",
        f"rei: error: {spec}:6:25: ann walks a route, at most 3 m/s (the language's limit), got [0.5, 4]",
        f"rei: error: {spec}:8:14: unknown metric 'clearence_humans_min'; known: success, " + lines[4].split(
            "known: success, ", 1)[-1]], result.stderr
    assert len(lines) == 5, result.stderr
    assert not out.exists()  # nothing ran
