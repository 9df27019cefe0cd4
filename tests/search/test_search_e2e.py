# SPDX-License-Identifier: EPL-2.0
"""`rei search` end to end with the real room editor engine, generator, simulation, monitor jar and evaluator, on
the example where a person's lane crosses the robot's only corridor: the search finds the collision; a stopped
search resumes without running a finished evaluation again; candidates that are not valid never reach the
simulator; the saved case and seed re-run to the same failure with byte-identical streams; shrinking keeps the
failure and removes the bin it does not need; a SUT that crashes gives ERROR evaluations, not failures."""

from __future__ import annotations

import json
import re
import shutil
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest

REPO_ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = REPO_ROOT / "examples" / "search"
TIMEOUT = 300.0
REQUIREMENT = "MISSION_WITH_HUMAN_TRAJECTORY"


@dataclass(frozen=True, slots=True)
class Searched:
    out: Path
    first: Any  # the CliResult of the search stopped at budget 4
    second: Any  # the CliResult of the same search resumed to budget 8
    results_after_first: dict[str, float]  # run key -> mtime of its result.json after the first invocation
    document: dict[str, Any]


@pytest.fixture(scope="module")
def searched(tmp_path_factory: pytest.TempPathFactory, run_cli: Any) -> Searched:
    folder = tmp_path_factory.mktemp("search")
    for name in ("crossing.rei", "crossing.yaml"):
        shutil.copy(EXAMPLE / name, folder / name)
    spec = folder / "crossing.yaml"
    spec.write_text(spec.read_text(encoding="utf-8").replace("shrink: {budget: 4}", "shrink: {budget: 2}"),
                    encoding="utf-8")
    out = folder / "out"
    # one worker: the sampler is told the runs in the order it asked for them, whatever the machine's load, so the
    # search makes the same candidates every time
    first = run_cli("search", spec, "-o", out, "--workers", "1", "--budget", "4", "--no-shrink", timeout=TIMEOUT)
    results = {p.parent.name: p.stat().st_mtime_ns for p in (out / "runs").glob("*/result.json")}
    second = run_cli("search", spec, "-o", out, "--workers", "1", "--budget", "8", timeout=TIMEOUT)
    document = json.loads((out / "search.json").read_text(encoding="utf-8"))
    return Searched(out, first, second, results, document)


def simulated(document: dict[str, Any]) -> list[dict[str, Any]]:
    return [r for r in document["evaluations"] if r["status"] in ("COMPLETED", "ERROR")]


def test_the_search_finds_the_collision_in_the_corridor(searched: Searched) -> None:
    assert searched.second.returncode == 1, searched.second.stdout + searched.second.stderr  # 1: failures found
    document = searched.document
    assert document["counts"]["simulated"] == 8 and document["counts"]["errors"] == 0
    signatures = [f["signature"] for f in document["failures"]]
    crossing = [f for f in document["failures"] if f["signature"].startswith("COLLISION/walker/")]
    assert crossing, signatures
    # one collision with the person is one failure, listing both requirements it violates (issue #37: it was two)
    assert not [s for s in signatures if s.startswith((f"{REQUIREMENT}/", "MISSION_SIMPLE/"))], signatures
    assert all({"MISSION_SIMPLE", REQUIREMENT} <= set(f["requirements"]) for f in crossing), crossing
    assert document["counts"]["distinct_failures"] == len(signatures) == len(set(signatures))

    def collides(record: dict[str, Any]) -> bool:
        return any(REQUIREMENT in f["requirements"] for f in record["failures"])

    # the objective has a slope: every run that hit the person came closer to them than any run that did not
    hits = [r["values"][0] for r in simulated(document) if collides(r)]
    misses = [r["values"][0] for r in simulated(document) if not collides(r)]
    assert hits and misses and max(hits) < min(misses), (hits, misses)
    assert re.search(r"\[\d/8\] tpe-\d{4}: metric:clearance_humans_min -?[0-9.e-]+; .*failing \d", searched.second.stdout)
    cases = ET.parse(searched.out / "verdicts.xml").getroot().findall("testcase")
    assert [c.get("name") for c in cases] == signatures  # one test case per event
    [case] = [c for c in cases if c.get("name") == crossing[0]["signature"]]
    message = case.find("failure").get("message")  # type: ignore[union-attr]
    assert f"fails {', '.join(crossing[0]['requirements'])} (reproduce: " in message, message
    html = (searched.out / "search.html").read_text(encoding="utf-8")
    assert 'id="objective-0"' in html and 'id="failure-1-map"' in html and crossing[0]["signature"] in html
    assert f"fails {', '.join(crossing[0]['requirements'])}" in html


def test_a_stopped_search_resumes_without_running_an_evaluation_again(searched: Searched) -> None:
    assert searched.first.returncode in (0, 1), searched.first.stdout + searched.first.stderr
    assert len(searched.results_after_first) == 4
    assert "4 finished already, 4 to run" in searched.second.stdout
    now = {p.parent.name: p.stat().st_mtime_ns for p in (searched.out / "runs").glob("*/result.json")}
    assert len(now) == 8
    for key, mtime in searched.results_after_first.items():
        assert now[key] == mtime, f"{key} ran again"
    assert {r["key"] for r in simulated(searched.document)} == set(now)


def test_candidates_that_are_not_valid_never_reach_the_simulator(searched: Searched) -> None:
    rejected = [r for r in searched.document["evaluations"] if r["status"] in ("invalid", "unplannable")]
    assert rejected, "the spec's bin floors F_1_1 and F_4_1 make invalid and unplannable candidates"
    assert {r["status"] for r in rejected} == {"invalid", "unplannable"}
    counts = searched.document["counts"]
    assert counts["invalid"] + counts["unplannable"] == len(rejected)
    # the terminal's last progress line counts them as search.json does (it said 'invalid' for both)
    last = [line for line in searched.second.stdout.splitlines() if " | failing " in line][-1]
    assert f"invalid {counts['invalid']}, unplannable {counts['unplannable']}, errors " in last, last
    for record in rejected:
        assert record["problems"], record
        assert record["params"]["bin1.floor"] in ("F_1_1", "F_4_1")
        assert not (searched.out / "runs" / record["key"]).exists()
        assert not (searched.out / "cases" / record["key"]).exists()
        assert not (searched.out / "candidates" / f"{record['key']}.rei").exists()
    assert all(r["params"]["bin1.floor"] == "F_0_0" for r in simulated(searched.document))


def test_the_saved_case_and_seed_rerun_to_the_same_failure_byte_for_byte(searched: Searched, run_cli: Any,
                                                                         tmp_path: Path) -> None:
    failure = next(f for f in searched.document["failures"] if REQUIREMENT in f["requirements"])
    case = Path(failure["case"])
    header = case.read_text(encoding="utf-8").splitlines()[0]
    assert header == f"// rei search candidate {failure['first']}: rei run {case.name} --seed {failure['seed']}"
    result = run_cli("run", case, "-o", tmp_path / "again", "--seed", failure["seed"], timeout=TIMEOUT)
    assert result.returncode == 1, result.stdout + result.stderr
    assert f"FAIL            {REQUIREMENT}" in result.stdout
    recorded = Path(failure["run"]) / "streams"
    streams = sorted(p.name for p in recorded.iterdir())
    assert streams == ["mission.msgpack", "signal.msgpack", "state.msgpack"]
    for name in streams:
        assert (tmp_path / "again" / "streams" / name).read_bytes() == (recorded / name).read_bytes(), name


def test_shrinking_keeps_the_failure_and_removes_the_bin(searched: Searched) -> None:
    failure = next(f for f in searched.document["failures"] if REQUIREMENT in f["requirements"])
    shrunk = failure["shrunk"]
    assert shrunk is not None and shrunk["removed"] == ["bin1"], shrunk
    text = Path(shrunk["case"]).read_text(encoding="utf-8")
    assert "bin1" not in text and "human walker" in text
    run = json.loads((Path(shrunk["run"]) / "summary.json").read_text(encoding="utf-8"))
    assert REQUIREMENT in [v["requirement"] for v in run["verdicts"] if v["status"] == "fail"]
    assert f"shrinking {failure['signature']}" in searched.second.stdout


def test_a_crashing_sut_gives_error_evaluations_not_failures(tmp_path: Path, run_cli: Any) -> None:
    shutil.copy(EXAMPLE / "crossing.rei", tmp_path / "crossing.rei")
    spec = tmp_path / "crash.yaml"
    spec.write_text("case: crossing.rei\nsut: {command: \"python3 -c 'import sys; sys.exit(3)'\"}\nbudget: 2\n"
                    "parameters: [{human: walker, start: [5, 11]}]\nobjectives: [utility]\n", encoding="utf-8")
    result = run_cli("search", spec, "-o", tmp_path / "out", "--workers", "2", timeout=TIMEOUT)
    assert result.returncode == 2, result.stdout + result.stderr  # nothing found, nothing vouched for
    document = json.loads((tmp_path / "out" / "search.json").read_text(encoding="utf-8"))
    assert document["counts"]["simulated"] == 2 and document["counts"]["errors"] == 2
    assert document["failures"] == [] and document["counts"]["failing"] == 0
    for record in simulated(document):
        assert record["status"] == "ERROR" and "exited with code 3" in record["error"], record
        assert record["values"] is None
    assert "ERROR the system under test exited with code 3" in result.stdout, result.stdout
