# SPDX-License-Identifier: EPL-2.0
"""docs/sut.md as a contract: its field tables and examples, checked against real runs and both client kits.

The document is the one source: its `### \\`name\\`` sections hold a table (field, type, meaning) and JSON examples
(msgpack's types: a number with a decimal point is a float64, ``Infinity`` is +inf). The tests check that
- the examples follow the tables and use every documented field;
- in two short real runs (lockstep with the map, realtime without) every message REI sends follows its table
  exactly (no field more or less, integers as integers, floats as float64), every documented type and value
  occurs, and the figures the document promises hold (tick 0's odometry is the start pose, a goal's ``t`` is its
  task's start, ``end``'s ``t`` is the run's ``sim_time``, realtime runs have no round trips);
- the document's ``command`` and ``status`` examples, sent into those runs, are taken, and a float ``tick`` is not;
- the document's ``hello``/``goal``/``tick``/``cancel``/``end`` examples, sent through the real router, are
  understood by the Python and the Java kit, even with the first events ahead of ``hello``'s result.
"""

from __future__ import annotations

import asyncio
import json
import math
import os
import re
import subprocess
import sys
import time
from collections.abc import Iterator
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import msgpack
import pytest

from rei import toolchain
from rei.geometry import Pose2D
from rei.mission.executor import task_outcome
from rei.sut.api import NavStatus
from rei.sut.external import protocol
from rei.sut.external.process import Connection
from rei.wamp.client import WampClient
from rei.wamp.recording import read_recording
from rei.wamp.router import Router

PROGRAMS = Path(__file__).resolve().parent / "programs"
DOC = Path(__file__).resolve().parents[2] / "docs" / "sut.md"
#: The document's section titles, as message names.
SECTIONS = {"`hello` call": "hello_call", "`hello` result": "hello", "`tick`": "tick", "`goal`": "goal",
            "`cancel`": "cancel", "`end`": "end", "`command` (SUT → simulation)": "command",
            "`status` (SUT → simulation)": "status"}
FROM_SIMULATION = ("hello", "tick", "goal", "cancel", "end")
FROM_SUT = ("hello_call", "command", "status")
#: A lidar slower than the control rate (ticks without a scan) that cannot span the room (misses read +inf), and a
#: mission whose first goal times out (cancel) at once. The realtime run's robot is holonomic (hello's drive, the
#: ticks' [v, w, vy]) and round, read from its description (hello's outline a circle); the lockstep run's a
#: differential box (a polygon).
ROUND_BOT = Path(__file__).resolve().parents[2] / "examples" / "robots" / "round_bot.urdf"
CATALOGUE = f"""catalogue ContractTypes {{
  robot type Probe : box 0.281 x 0.306 x 0.141 mass 1.8
    lidar beams 90 range 0.12 to 3.5 rate 5
  robot type OmniProbe : urdf "{ROUND_BOT}" mass 1.8 drive holonomic
    lidar link "laser" beams 90 range 0.12 to 3.5 rate 5
  type Wedge : object polygon (0,0) (0.6,0) (0,0.6) height 0.5
}}
"""
CASE = """import "types.rei"
testcase Contract {
  room Lab size 6 x 4 {
    object table1 : Table on F_2_1
    robot probe : Probe on F_0_0
  }
  mission Short {
    timeout 2s
    goto F_4_0
    goto F_5_3
  }
  monitor { close 0.25 collision 0.01 maxHumanCollisions 1 }
}
"""


# -- the document ------------------------------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class Row:
    path: tuple[str, ...]  # ("odom", "pose")
    optional: bool
    alternatives: tuple[str, ...]  # ("map", "nil")


@dataclass(slots=True)
class Message:
    rows: list[Row] = field(default_factory=list)
    examples: list[Any] = field(default_factory=list)

    def children(self, prefix: tuple[str, ...]) -> dict[str, Row]:
        return {row.path[-1]: row for row in self.rows if row.path[:-1] == prefix}


def read_doc(text: str) -> dict[str, Message]:
    messages: dict[str, Message] = {}
    for section in re.split(r"^### ", text, flags=re.MULTILINE)[1:]:
        title, _, body = section.partition("\n")
        name = SECTIONS.get(title.strip())
        if name is None:
            continue
        message = messages.setdefault(name, Message())
        for line in body.split("\n## ")[0].splitlines():
            cells = [c.strip() for c in re.split(r"(?<!\\)\|", line)[1:-1]]
            if len(cells) == 3 and cells[0].startswith("`"):
                path = cells[0].strip("`")
                message.rows.append(Row(tuple(path.rstrip("?").split(".")), path.endswith("?"),
                                        alternatives(cells[1].replace("\\|", "|"))))
        message.examples = [json.loads(block) for block in re.findall(r"```json\n(.*?)```", body, flags=re.DOTALL)]
    return messages


def alternatives(union: str) -> tuple[str, ...]:
    """The sides of a type's ``|`` outside parentheses: ``(float[2][] | nil)[] | nil`` has two."""
    sides, depth, start = [], 0, 0
    for i, char in enumerate(union + "|"):
        depth += {"(": 1, ")": -1}.get(char, 0)
        if char == "|" and depth == 0:
            sides.append(union[start:i].strip().strip("`"))
            start = i + 1
    return tuple(sides)


def type_errors(value: Any, alternative: str) -> bool:
    """True when ``value`` is NOT of the documented type ``alternative`` (one side of a ``|``)."""
    is_int = isinstance(value, int) and not isinstance(value, bool)
    simple = {"int": is_int, "float": isinstance(value, float), "number": is_int or isinstance(value, float),
              "string": isinstance(value, str), "nil": value is None, "map": isinstance(value, dict)}
    if alternative in simple:
        return not simple[alternative]
    if alternative.startswith('"'):
        return value != alternative.strip('"')
    listed = re.fullmatch(r"\((.*)\)\[\]", alternative)  # (A | B)[]: a list, each element one of them
    if listed:
        return not isinstance(value, list) or any(
            all(type_errors(item, side) for side in alternatives(listed[1])) for item in value)
    array = re.fullmatch(r"float((?:\[\d*\])+)", alternative)
    assert array, f"docs/sut.md: unknown type {alternative!r}"
    sizes = re.findall(r"\[(\d*)\]", array[1])[::-1]  # outermost first

    def wrong(item: Any, depth: int) -> bool:
        if depth == len(sizes):
            return not isinstance(item, float)
        if not isinstance(item, list) or (sizes[depth] and len(item) != int(sizes[depth])):
            return True
        return any(wrong(element, depth + 1) for element in item)
    return wrong(value, 0)


def conformance(message: Message, payload: Any, seen: set[tuple[tuple[str, ...], str]] | None = None,
                prefix: tuple[str, ...] = ()) -> list[str]:
    """What in ``payload`` breaks ``message``'s table; ``seen`` collects the (field, type) pairs that occurred."""
    where = ".".join(prefix) or "the payload"
    if not isinstance(payload, dict):
        return [f"{where} is not a map: {payload!r}"]
    rows = message.children(prefix)
    problems = [f"{where}: undocumented field {key!r}" for key in payload if key not in rows]
    problems += [f"{where}: no field {key!r}" for key, row in rows.items() if not row.optional and key not in payload]
    for key, value in payload.items():
        row = rows.get(key)
        if row is None:
            continue
        matching = [a for a in row.alternatives if not type_errors(value, a)]
        if not matching:
            problems.append(f"{'.'.join(row.path)} = {str(value)[:80]} is not {' | '.join(row.alternatives)}")
            continue
        if seen is not None:
            seen.add((row.path, matching[0]))
        if matching[0] == "map":
            problems += conformance(message, value, seen, row.path)
    return problems


def every_type(message: Message) -> set[tuple[tuple[str, ...], str]]:
    return {(row.path, alternative) for row in message.rows for alternative in row.alternatives}


@pytest.fixture(scope="module")
def doc() -> dict[str, Message]:
    return read_doc(DOC.read_text(encoding="utf-8"))


def test_the_examples_follow_the_tables_and_use_every_field(doc: dict[str, Message]) -> None:
    assert set(doc) == set(SECTIONS.values())
    for name, message in doc.items():
        assert message.rows and message.examples, name
        used: set[tuple[tuple[str, ...], str]] = set()
        for example in message.examples:
            assert conformance(message, example, used) == [], (name, example)
        assert {path for path, _ in used} == {row.path for row in message.rows}, name
    tick = doc["tick"].examples[0]
    scan = tick["scan"]
    assert math.isinf(scan["ranges"][0]) and scan["angle_max"] == pytest.approx(
        scan["angle_min"] + (len(scan["ranges"]) - 1) * scan["angle_increment"])
    assert tick["odom"]["pose"] == doc["hello"].examples[0]["start"]  # tick 0's odometry is the start pose


def test_the_environment_table_names_exactly_what_a_started_sut_gets(repo_root: Path) -> None:
    section = DOC.read_text(encoding="utf-8").split("## Environment of a started SUT")[1].split("\n## ")[0]
    documented = re.findall(r"^\| `(REI_\w+)` \|", section, flags=re.MULTILINE)
    contract = json.loads((repo_root / "contract" / "vocabulary.json").read_text(encoding="utf-8"))["sut"]
    given = Connection("ws://127.0.0.1:1/ws", "rei", "r1", Path("sut.json"), "rs://127.0.0.1:2",
                       Path("out/case")).environment()
    assert sorted(documented) == sorted(given) == sorted(contract["environment"] + contract["optional_environment"])


def test_tolerance_is_a_distance_in_the_plane_and_the_yaw_is_not_judged() -> None:
    goal = Pose2D(5.5, 3.5, 0.0)
    assert task_outcome(NavStatus.SUCCEEDED, "", Pose2D(5.5, 3.3, math.pi - 0.01), goal, 0.25) is None
    assert "false success" in task_outcome(NavStatus.SUCCEEDED, "", Pose2D(5.5, 3.2, 0.0), goal, 0.25)


# -- real runs -------------------------------------------------------------------------------------------------


def _plan(doc: dict[str, Message], realtime: bool) -> dict[str, Any]:
    """What contract_sut.py sends: the document's examples (lockstep: ACTIVE with a text until the cancel, then
    SUCCEEDED; realtime: ABORTED at once)."""
    active, succeeded = doc["status"].examples
    aborted = {"goal_id": 0, "status": "ABORTED", "text": "no path"}
    return {"hello_call": doc["hello_call"].examples[0], "command": doc["command"].examples,
            "status": {"0": aborted, "1": aborted} if realtime else {"0": active, "1": succeeded},
            "cancelled": {"goal_id": 0, "status": "CANCELLED"}}


def _run(run_cli, case: Path, out: Path, plan: dict[str, Any], *options: str) -> tuple[list, dict]:
    out.mkdir(parents=True)
    (out.parent / f"{out.name}.json").write_text(json.dumps(plan))
    sut = f"{sys.executable} {PROGRAMS / 'contract_sut.py'} {out.parent / f'{out.name}.json'} {out}"
    result = run_cli("sim", case, "-o", out, "--progress", "none", "--sut", sut, *options, timeout=180)
    assert result.returncode == 1, result.stdout + result.stderr  # both tasks fail (on purpose), the run does not
    received = msgpack.unpackb((out / "contract.msgpack").read_bytes())
    return received, json.loads((out / "sim.json").read_text())


def test_what_rei_sends_and_takes_is_what_the_document_says(
    run_cli, doc: dict[str, Message], tmp_path: Path, processes_mentioning
) -> None:
    case = tmp_path / "contract.rei"
    case.write_text(CASE)
    (tmp_path / "types.rei").write_text(CATALOGUE)
    # the lockstep run's room is the same room made from an occupancy map (all free, 6 x 4 m), so that hello's
    # map carries its occupancy too
    map_case = tmp_path / "contract_map.rei"
    # and furniture on a polygon, so that it carries map.polygons
    map_case.write_text(CASE.replace("room Lab size 6 x 4 {", 'room Lab occupancy "lab.yaml" {\n'
                                     "    object wedge : Wedge on F_3_3"))
    (tmp_path / "lab.pgm").write_bytes(b"P5\n120 80\n255\n" + bytes([254]) * (120 * 80))
    (tmp_path / "lab.yaml").write_text("image: lab.pgm\nresolution: 0.05\norigin: [0.0, 0.0, 0.0]\nnegate: 0\n"
                                       "occupied_thresh: 0.65\nfree_thresh: 0.196\n")
    lockstep, realtime = tmp_path / "lockstep", tmp_path / "realtime"
    with ThreadPoolExecutor(2) as pool:  # both at once: the realtime run mostly waits for the wall clock
        first = pool.submit(_run, run_cli, map_case, lockstep, _plan(doc, False), "--sut-map")
        holonomic = tmp_path / "contract_holonomic.rei"
        holonomic.write_text(CASE.replace(": Probe on", ": OmniProbe on"))
        second = pool.submit(_run, run_cli, holonomic, realtime, _plan(doc, True), "--sut-clock", "realtime")
        runs = {lockstep: first.result(), realtime: second.result()}
    seen: dict[str, set] = {name: set() for name in doc}
    for received, _ in runs.values():
        assert received[0][0] == "hello" and received[-1][0] == "end"
        for name, payload in received:
            assert conformance(doc[name], payload, seen[name]) == [], (name, payload)
    for name in FROM_SIMULATION:  # every documented field and type occurred (map and nil, lockstep and realtime)
        assert seen[name] == every_type(doc[name]), (name, every_type(doc[name]) - seen[name])

    received, sim = runs[lockstep]
    hello = received[0][1]
    assert hello["map"]["occupancy"] == "map.yaml"  # relative to REI_CASE_DIR, the run's case folder
    # one polygon entry per obstacle: the wedge's, in the world, where its bounding box (its obstacle) stands
    polygons, obstacles = hello["map"]["polygons"], hello["map"]["obstacles"]
    assert len(polygons) == len(obstacles) and sum(p is not None for p in polygons) == 1
    wedge, box = next((p, o) for p, o in zip(polygons, obstacles, strict=True) if p is not None)
    assert [v for vertex in wedge for v in vertex] == pytest.approx([3.2, 3.2, 3.8, 3.2, 3.2, 3.8])
    assert box == pytest.approx([3.5, 3.5, 0.0, 0.6, 0.6])
    ticks = [p for name, p in received if name == "tick"]
    assert [p["tick"] for p in ticks] == list(range(len(ticks)))
    assert ticks[0]["odom"]["pose"] == hello["start"] and ticks[1]["odom"]["pose"] != hello["start"]
    assert all(abs(p["t"] - p["tick"] / hello["control_rate"]) < 1e-9 for p in ticks)
    scans = [p["scan"] for p in ticks if p["scan"] is not None]
    lidar = hello["robot"]["lidar"]
    assert all(len(s["ranges"]) == lidar["beams"] and s["angle_max"] == pytest.approx(
        s["angle_min"] + (lidar["beams"] - 1) * s["angle_increment"]) for s in scans)
    assert any(math.isinf(r) for r in scans[0]["ranges"]) and any(math.isfinite(r) for r in scans[0]["ranges"])
    mission = read_recording(lockstep / "streams" / "mission.msgpack")
    starts = [m["t"] for m in mission if m["event"] == "TASK_START"]
    goals = [(i, p) for i, (name, p) in enumerate(received) if name == "goal"]
    assert len(goals) == hello["goals"] == 2 and [p["t"] for _, p in goals] == starts
    for i, goal in goals:  # the tick a goal applies to is the next one, with the goal's t
        assert next(p for name, p in received[i:] if name == "tick")["t"] == goal["t"]
    cancels = [p for name, p in received if name == "cancel"]
    assert [(c["goal_id"], c["t"]) for c in cancels] == [(0, m["t"]) for m in mission if m["event"] == "TASK_FAIL"
                                                            and m["reason"].startswith("timeout")]
    assert received[-1][1]["t"] == sim["sim_time"] and received[-1][1]["t"] % 0.1 > 1e-6  # not a tick's time
    stats = sim["sut"]
    assert stats["commands"] == len(ticks) and stats["rejected"] == len(ticks)  # each tick: the float tick
    assert all("tick must be an integer" in r for r in stats["first_rejections"])
    assert stats["stale"] == 1 and stats["statuses"] == 2  # CANCELLED after the cancel is stale
    # the differential robot's vy is clamped to 0: the ticks answered with the example that has one
    commands = doc["command"].examples
    sideways = sum(1 for p in ticks if commands[p["tick"] % len(commands)].get("vy", 0) != 0)
    assert sideways > 0 and stats["clamped"] == sideways and set(stats["round_trip_ms"]) == {"p50", "p99", "max"}
    assert hello["robot"]["drive"] == "differential" and hello["robot"]["max_lateral"] == 0.0
    assert hello["robot"]["outline"] == {"type": "polygon", "points": [[-0.1405, -0.153], [0.1405, -0.153],
                                                                      [0.1405, 0.153], [-0.1405, 0.153]]}
    assert all(len(p["odom"]["twist"]) == 2 for p in ticks)

    received, sim = runs[realtime]
    assert received[0][1]["map"] is None and received[0][1]["clock"] == "realtime"
    robot = received[0][1]["robot"]
    assert robot["drive"] == "holonomic" and robot["max_lateral"] == robot["max_linear"]
    assert robot["outline"] == {"type": "circle", "x": 0.0, "y": 0.0, "radius": 0.17}  # round_bot.urdf's body
    # the lidar where round_bot.urdf's laser joint puts it (a box robot's at its centre: the lockstep run's)
    assert (robot["lidar"]["x"], robot["lidar"]["y"], robot["lidar"]["yaw"]) == (0.05, 0.0, 0.0)
    assert (hello["robot"]["lidar"]["x"], hello["robot"]["lidar"]["y"], hello["robot"]["lidar"]["yaw"]) == (0, 0, 0)
    assert all(len(p["odom"]["twist"]) == 3 for name, p in received if name == "tick")
    assert sim["sut"]["clamped"] == 0  # its vy is within its limit
    assert sim["sut"]["round_trip_ms"] is None and sim["sut"]["clock"] == "realtime"
    assert sim["sut"]["statuses"] == 2 and sim["sut"]["stale"] == 0
    assert [t["reason"] for t in sim["tasks"]] == ["planner failure: the navigation aborted: no path"] * 2
    assert processes_mentioning(tmp_path) == []


# -- the kits --------------------------------------------------------------------------------------------------


class FakeSimulation:
    """The simulation's side played with the document's examples on a real router: ``hello`` answers the
    example after publishing the first events (so they overtake the result), then each tick waits for its
    command."""

    def __init__(self, router: Router, doc: dict[str, Message]) -> None:
        self.doc = doc
        self.run_id = router.run_id
        self.client = WampClient(router.rs_url, auth=router.credentials("simulation")).start()
        self.calls: list[Any] = []
        self.received: list[tuple[str, Any]] = []
        for name in ("command", "status"):
            self.client.subscribe(self.uri(name), lambda payload, name=name: self.received.append((name, payload)))
        self.client.register(self.uri("hello"), self.hello)
        self.goal, (self.tick0, self.tick1) = doc["goal"].examples[0], doc["tick"].examples

    def uri(self, name: str) -> str:
        return protocol.uri(self.run_id, name)

    async def hello(self, *args: Any, **kwargs: Any) -> Any:
        self.calls.append(args[0] if args else None)
        self.client.publish(self.uri("goal"), self.goal)
        self.client.publish(self.uri("tick"), self.tick0)
        await asyncio.sleep(0.5)  # the events go out before the result
        return self.doc["hello"].examples[0]

    def play(self, sut: subprocess.Popen) -> None:
        for tick in (0, 1):
            self.wait(lambda tick=tick: any(n == "command" and p["tick"] == tick for n, p in self.received), sut)
            if tick == 0:
                self.client.publish(self.uri("tick"), self.tick1)
        self.client.publish(self.uri("cancel"), self.doc["cancel"].examples[0])
        self.client.publish(self.uri("end"), self.doc["end"].examples[0])

    @staticmethod
    def wait(condition: Any, sut: subprocess.Popen) -> None:
        deadline = time.monotonic() + 60
        while not condition():
            assert sut.poll() is None, f"the kit exited with {sut.returncode}: {sut.stdout.read() if sut.stdout else ''}"
            assert time.monotonic() < deadline, "no command from the kit"
            time.sleep(0.02)


@pytest.fixture(scope="module")
def router(doc: dict[str, Message], tmp_path_factory: pytest.TempPathFactory) -> Iterator[Router]:
    run_id = doc["hello"].examples[0]["run_id"]
    with Router(run_dir=tmp_path_factory.mktemp("router"), run_id=run_id) as started:
        yield started


def _kits(repo_root: Path, java: toolchain.Java, sut_kit_jar: Path) -> dict[str, list[str]]:
    return {"python": [sys.executable, str(repo_root / "examples" / "sut" / "python" / "go_to_goal.py")],
            "java": [str(java.executable), "-XX:TieredStopAtLevel=1", "-cp", str(sut_kit_jar),
                     str(repo_root / "examples" / "sut" / "java" / "GoToGoalSut.java")]}


@pytest.mark.parametrize("kit", ["python", "java"])
def test_the_kits_understand_the_document_s_examples_and_answer_in_its_shapes(
    kit: str, doc: dict[str, Message], router: Router, repo_root: Path, java: toolchain.Java, sut_kit_jar: Path
) -> None:
    simulation = FakeSimulation(router, doc)
    env = {**os.environ, "REI_ROUTER_URL": router.ws_url, "REI_ROUTER_RAWSOCKET_URL": router.rs_url,
           "REI_REALM": router.realm, "REI_RUN_ID": router.run_id, "REI_AUTH_FILE": str(router.auth_file("sut"))}
    sut = subprocess.Popen(_kits(repo_root, java, sut_kit_jar)[kit], env=env, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, text=True)
    try:
        simulation.play(sut)
        output, _ = sut.communicate(timeout=60)
    finally:
        if sut.poll() is None:
            sut.kill()
        simulation.client.close()
    assert sut.returncode == 0, output
    assert len(simulation.calls) == 1 and conformance(doc["hello_call"], simulation.calls[0]) == []
    commands = [p for name, p in simulation.received if name == "command"]
    statuses = [p for name, p in simulation.received if name == "status"]
    assert [c["tick"] for c in commands] == [0, 1] and statuses
    for name, payload in simulation.received:
        assert conformance(doc[name], payload) == [], (name, payload)
    assert {s["goal_id"] for s in statuses} == {simulation.goal["goal_id"]}
    assert statuses[0]["status"] == "ACTIVE"
