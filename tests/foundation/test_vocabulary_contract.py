# SPDX-License-Identifier: EPL-2.0
"""The contract test: every language's copy of a shared fact equals contract/vocabulary.json, the one source.

Java's copies are read from the built jars' constants (contract/JavaVocabulary.java), Python's from the modules,
TypeScript's from the viewer's source; the threshold rules are checked by behaviour in the DSL's validator, the
Python reader and the Java monitor, which disagreed once (0 was accepted by two, a missing threshold defaulted
in one).
"""

from __future__ import annotations

import dataclasses
import json
import re
import subprocess
from pathlib import Path

import pytest

from rei.artifacts import ArtifactError
from rei.artifacts.monitor import read_monitor
from rei.artifacts.world import FOOTPRINT_TYPES
from rei.edit import TOKEN_HEADER, engine
from rei.edit.server import ROUTES
from rei.evaluation import DEFAULT_UTILITIES, load_declared_transitions, load_declared_utilities
from rei.evaluation.signals import DEFAULT_TRANSITIONS, SIGNAL_RECORD, Signal
from rei.maps import MAX_BLOCKS, MAX_CELLS
from rei.mission.executor import FAULT_EVENTS, FAULT_KINDS, MissionEventKind
from rei.robots import Circle, Polygon
from rei.run import jvm
from rei.sut.external import protocol
from rei.sut.external.process import Connection
from rei.wamp.crossbar_config import MAX_MESSAGE_SIZE
from rei.wamp.topics import RUN_ID_PATTERN, TOPIC_NAMES, TOPIC_TEMPLATE, Topics

HERE = Path(__file__).parent


@pytest.fixture(scope="module")
def contract(repo_root: Path) -> dict:
    return json.loads((repo_root / "contract" / "vocabulary.json").read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def java_facts(java, monitor_jar: Path, sut_kit_jar: Path, room_editor_jar: Path) -> dict:
    result = subprocess.run([java.executable, "-cp", f"{monitor_jar}:{sut_kit_jar}:{room_editor_jar}",
                             str(HERE / "contract" / "JavaVocabulary.java")],
                            capture_output=True, text=True, timeout=120, check=False)
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)


def test_python_copies(contract: dict) -> None:
    assert RUN_ID_PATTERN == contract["run_id_pattern"]
    assert TOPIC_TEMPLATE == contract["topic_template"]
    assert MAX_MESSAGE_SIZE == contract["max_message_size"]
    assert TOPIC_NAMES == tuple(contract["topics"])
    topics = Topics("r1")
    assert [getattr(topics, name) for name in TOPIC_NAMES] == [
        contract["topic_template"].format(run_id="r1", name=name) for name in contract["topics"]]
    assert [kind.value for kind in MissionEventKind] == contract["mission_events"]
    assert SIGNAL_RECORD == tuple(contract["signal_record"]) == tuple(f.name for f in dataclasses.fields(Signal))
    sut = contract["sut"]
    assert protocol.URI_TEMPLATE == sut["uri_template"]
    assert (protocol.FROM_SIMULATION, protocol.FROM_SUT, protocol.PROCEDURES) == (
        tuple(sut["from_simulation"]), tuple(sut["from_sut"]), tuple(sut["procedures"]))
    env = Connection("ws://x", "rei", "r1", Path("auth"), "rs://x", Path("case")).environment()
    assert list(env) == sut["environment"] + sut["optional_environment"]
    assert (jvm.REQUEST_WORDS, jvm.ANSWER_WORD) == (tuple(contract["warm_jvm"]["request"]), contract["warm_jvm"]["answer"])


def test_java_copies(contract: dict, java_facts: dict) -> None:
    assert java_facts["run_id_pattern"] == contract["run_id_pattern"]
    assert java_facts["topic_template"] == contract["topic_template"].removesuffix("{name}")
    assert java_facts["max_message_size"] == java_facts["sut_max_message_size"] == contract["max_message_size"]
    assert java_facts["mission_events"] == contract["mission_events"]
    assert java_facts["fault_events"] == _fault_events(contract)
    assert java_facts["vepl_mission_events"] == contract["mission_events"] + _fault_events(contract)
    assert java_facts["signal_record"] == java_facts["signal_payload"] == contract["signal_record"]
    sut = contract["sut"]
    assert java_facts["sut_uri_template"] == sut["uri_template"]
    assert (java_facts["sut_from_simulation"], java_facts["sut_from_sut"], java_facts["sut_procedures"]) == (
        sut["from_simulation"], sut["from_sut"], sut["procedures"])
    assert java_facts["sut_environment"] == sut["environment"]
    assert java_facts["sut_case_dir"] in sut["optional_environment"]  # hello's map.occupancy is relative to it
    assert java_facts["warm_jvm_request"] == contract["warm_jvm"]["request"]
    assert java_facts["warm_jvm_answer"] == contract["warm_jvm"]["answer"]
    editor = contract["room_editor"]
    assert java_facts["room_editor_commands"] == editor["engine_commands"]
    assert java_facts["room_editor_error_kinds"] == editor["engine_error_kinds"]
    assert java_facts["room_editor_operations"] == editor["operations"]
    assert java_facts["room_editor_point"] == editor["point"]
    assert java_facts["room_editor_sides"] == editor["sides"]


def _fault_events(contract: dict) -> list[str]:
    faults = contract["faults"]
    return [faults["event_template"].format(sensor=sensor, kind=kind, edge=edge).upper()
            for sensor, kinds in faults["kinds"].items() for kind in kinds for edge in faults["edges"]]


def test_fault_copies(contract: dict, repo_root: Path) -> None:
    """The fault kinds: the simulator's (its events and its spec reader), the language's keywords, the default
    patterns' events and signals."""
    from rei.sim.faults import EDGES, KIND_KEYS, SENSOR_KIND_KEYS, SENSORS, event_name

    faults = contract["faults"]
    assert {k: list(v) for k, v in FAULT_KINDS.items()} == faults["kinds"]
    assert list(FAULT_EVENTS) == _fault_events(contract)
    assert list(SENSORS) == list(faults["kinds"]) and list(EDGES) == faults["edges"]
    assert list(KIND_KEYS) == faults["kinds"]["laser"]
    assert {sensor: list(kinds) for sensor, kinds in SENSOR_KIND_KEYS.items()} == faults["kinds"]
    assert event_name("laser", "blackout", True) == "FAULT_LASER_BLACKOUT_BEGIN" in FAULT_EVENTS
    grammar = (repo_root / "bundles" / "org.rei.dsl" / "src" / "main" / "java" / "org" / "rei" / "dsl"
               / "Rei.xtext").read_text(encoding="utf-8")
    every_kind = [kind for kinds in faults["kinds"].values() for kind in kinds]  # one enum: kind names are unique
    assert len(set(every_kind)) == len(every_kind)
    for rule, words in (("FaultSensor", list(faults["kinds"])), ("FaultKind", every_kind)):
        enum = re.search(rf"enum {rule} returns ctx::{rule}:([^;]+);", grammar)
        assert enum is not None, f"Rei.xtext: no enum {rule}"
        assert re.findall(r"='(\w+)'", enum[1]) == words
    patterns = (repo_root / "cep" / "patterns" / "faults.vepl").read_text(encoding="utf-8")
    events = re.findall(r"^atomicEvent \w+\(\) as mission (\w+)$", patterns, re.MULTILINE)
    signals = re.findall(r"^signal (\w+)$", patterns, re.MULTILINE)
    emitted = re.findall(r"^rule \"[^\"]+\" on \w+ emits (\w+)$", patterns, re.MULTILINE)
    assert events == _fault_events(contract)
    assert signals == emitted == [faults["signal_prefix"] + e for e in _fault_events(contract)]


def test_behaviour_copies(contract: dict, repo_root: Path) -> None:
    """The behaviours of people who see the robot: the language's enum (its first literal is EMF's default, what a
    line without one gets), animation.json's, the room generator's, the text edits' and the VS Code keywords."""
    from rei.artifacts.animation import Behaviour
    from rei.edit import gatherings
    from rei.rooms.model import BEHAVIOURS

    behaviours = contract["behaviours"]
    assert behaviours["default"] == behaviours["values"][0] == gatherings.DEFAULT_BEHAVIOUR
    assert [b.value for b in Behaviour] == list(BEHAVIOURS) == list(gatherings.BEHAVIOURS) == behaviours["values"]
    grammar = (repo_root / "bundles" / "org.rei.dsl" / "src" / "main" / "java" / "org" / "rei" / "dsl"
               / "Rei.xtext").read_text(encoding="utf-8")
    enum = re.search(r"enum Behaviour returns ctx::Behaviour:([^;]+);", grammar)
    assert enum is not None, "Rei.xtext: no enum Behaviour"
    assert re.findall(r"='(\w+)'", enum[1]) == behaviours["values"]
    keywords = (repo_root / "editors" / "vscode" / "syntaxes" / "rei.tmLanguage.json").read_text(encoding="utf-8")
    assert f"\\\\b(?:{'|'.join(behaviours['values'])})\\\\b" in keywords


def test_drive_copies(contract: dict, repo_root: Path, java_facts: dict) -> None:
    """A robot's drive: the language's enum (its first literal is EMF's default, what a robot type that says no
    drive gets), the catalogue metamodel's literals, world.json's reader, hello's robot.drive as the simulation
    writes it and the Java kit reads it, and the VS Code keywords."""
    import xml.etree.ElementTree as ET

    from rei.artifacts.world import DRIVE_KINDS, DriveSpec

    drives = contract["drives"]
    assert list(DRIVE_KINDS) == drives["types"] and drives["default"] == drives["types"][0]
    assert java_facts["sut_drives"] == drives["types"]
    assert DriveSpec(0.033, 0.287, 0.26, 1.82).kind == drives["default"]
    grammar = (repo_root / "bundles" / "org.rei.dsl" / "src" / "main" / "java" / "org" / "rei" / "dsl"
               / "Rei.xtext").read_text(encoding="utf-8")
    enum = re.search(r"enum Drive returns cat::Drive:([^;]+);", grammar)
    assert enum is not None, "Rei.xtext: no enum Drive"
    assert re.findall(r"='(\w+)'", enum[1]) == drives["types"]
    model = ET.parse(repo_root / "metamodels" / "model" / "catalogue.ecore").getroot()
    literals = [c for c in model.findall("eClassifiers") if c.get("name") == "Drive"]
    assert len(literals) == 1
    assert [(literal.get("literal"), literal.get("value")) for literal in literals[0].findall("eLiterals")] == [
        (kind, str(i)) for i, kind in enumerate(drives["types"])]
    session = (repo_root / "sim-adapter" / "src" / "rei" / "sut" / "external" / "session.py").read_text(encoding="utf-8")
    assert '"drive": robot.drive.kind' in session  # hello's robot.drive is world.json's, one of these
    keywords = (repo_root / "editors" / "vscode" / "syntaxes" / "rei.tmLanguage.json").read_text(encoding="utf-8")
    assert f"\\\\b(?:{'|'.join(drives['types'])})\\\\b" in keywords


def test_the_map_limits_are_one_fact_of_both_readers_and_of_the_language_page(contract: dict, java_facts: dict,
                                                                             repo_root: Path) -> None:
    """The most cells a map may have and the most blocks a floor size may cut it into: Python's rei.maps and Java's
    org.rei.maps refuse the same maps with the same message (tests/maps), and the language page says the numbers."""
    limits = (contract["maps"]["max_cells"], contract["maps"]["max_blocks"])
    assert (MAX_CELLS, MAX_BLOCKS) == limits
    assert (java_facts["map_max_cells"], java_facts["map_max_blocks"]) == limits
    page = (repo_root / "docs" / "language.md").read_text(encoding="utf-8")
    assert f"**{limits[0]:,} cells**" in page and f"**{limits[1]:,} blocks**" in page


def test_room_editor_python_copies(contract: dict) -> None:
    editor = contract["room_editor"]
    assert TOKEN_HEADER == editor["token_header"]
    assert [engine.REFUSED, engine.INTERNAL] == editor["engine_error_kinds"]
    assert [f"{method} {path}" for method, path in ROUTES] == editor["api"]


def test_room_editor_typescript_copies(contract: dict, repo_root: Path) -> None:
    editor = contract["room_editor"]
    source = repo_root / "viewer" / "src" / "edit"
    types = (source / "types.ts").read_text(encoding="utf-8")
    operations = {op: re.findall(r"(\w+)\??:", fields) for op, fields in
                  re.findall(r'\{ op: "(\w+)";([^}]*)\}', types)}
    assert operations == editor["operations"]
    point = re.search(r"export interface PointSpec \{([^}]*)\}", types)
    assert point is not None, "viewer/src/edit/types.ts: no `export interface PointSpec`"
    assert re.findall(r"(\w+):", point[1]) == editor["point"]
    side = re.search(r"export type Side = ([^;]+);", types)
    assert side is not None, "viewer/src/edit/types.ts: no `export type Side = ...;`"
    assert re.findall(r'"(\w+)"', side[1]) == editor["sides"]
    api = (source / "api.ts").read_text(encoding="utf-8")
    assert set(re.findall(r'"(X-REI-[\w-]+)"', api)) == {editor["token_header"]}
    calls = {f"{method} {path}" for method, path in re.findall(r'"(GET|POST)", "(/api/\w+)"', api)}
    commands = re.search(r"command\(name: ([^)]*)\)", api)
    assert commands is not None, "viewer/src/edit/api.ts: no `command(name: ...)`"
    calls |= {f"POST /api/{name}" for name in re.findall(r'"(\w+)"', commands[1])}
    assert calls == set(editor["api"])


def test_typescript_copies(contract: dict, repo_root: Path) -> None:
    source = (repo_root / "viewer" / "src" / "config.ts").read_text(encoding="utf-8")
    union = re.search(r"export type MissionEvent = ([^;]+);", source)
    assert union is not None, "viewer/src/config.ts: no `export type MissionEvent = ...;`"
    assert re.findall(r'"([A-Z_]+)"', union[1]) == contract["mission_events"]
    fields = re.search(r"export interface SignalMessage \{([^}]*)\}", source)
    assert fields is not None, "viewer/src/config.ts: no `export interface SignalMessage`"
    assert re.findall(r"readonly (\w+)", fields[1]) == contract["signal_record"]


def test_the_generated_monitor_config_names_the_contracts_topics(contract: dict, repo_root: Path) -> None:
    template = (repo_root / "generators" / "org.rei.generator" / "src" / "main" / "resources" / "org" / "rei"
                / "generator" / "templates" / "monitor.json.egl").read_text(encoding="utf-8")
    uris = dict(re.findall(r'"(\w+)": "(rei\.run\.[^"]+)"', template))
    names = {"missionInfo" if name == "mission_info" else name: name for name in contract["topics"]}
    assert uris == {key: contract["topic_template"].format(run_id="{run_id}", name=name)
                    for key, name in names.items()}


def test_pythons_default_utilities_and_transitions_are_what_the_default_patterns_declare(
    java, monitor_jar: Path, tmp_path: Path
) -> None:
    """The VEPL declarations are the source of signals; Python's defaults (used where a run has no declarations,
    e.g. hand-written rules) must say the same, value for value."""
    declared = tmp_path / "utilities.json"
    result = subprocess.run([java.executable, "-jar", str(monitor_jar), "--compile-only", "--utilities-out",
                             str(declared)], capture_output=True, text=True, timeout=120, check=False)
    assert result.returncode == 0, result.stderr
    utilities = load_declared_utilities(declared)
    for signal, utility in utilities.items():
        assert DEFAULT_UTILITIES[signal] == (utility if utility is not None else 0.0), signal
    assert set(DEFAULT_UTILITIES) - set(utilities) == {"SIG_MONITOR_DATA_GAP"}  # the monitor's own, no pattern's
    assert load_declared_transitions(declared) == dict(DEFAULT_TRANSITIONS)
    assert set(json.loads(declared.read_text())) >= set(DEFAULT_TRANSITIONS)  # every default is declared


# -- the threshold rules, by behaviour ------------------------------------------------------------------------

BAD_THRESHOLDS = {
    "collision zero": ({"close": 0.25, "collision": 0.0}, "collision"),
    "close not above collision": ({"close": 0.1, "collision": 0.1}, "close" ),
    "missing": ({"close": 0.25}, "collision"),
}


def _case_with(thresholds: dict, generated: Path, into: Path) -> Path:
    """A copy of a generated case whose monitor.json has ``thresholds``."""
    into.mkdir(parents=True)
    for path in generated.iterdir():
        if path.is_file():
            (into / path.name).write_bytes(path.read_bytes())
    monitor = json.loads((into / "monitor.json").read_text())
    monitor["thresholds"] = thresholds
    (into / "monitor.json").write_text(json.dumps(monitor))
    return into


@pytest.fixture(scope="module")
def generated(run_cli, repo_root: Path, tmp_path_factory) -> Path:
    out = tmp_path_factory.mktemp("gen") / "case"
    result = run_cli("generate", repo_root / "examples" / "simple_navigation.rei", "-o", out)
    assert result.returncode == 0, result.stderr
    return out


@pytest.mark.parametrize("problem", list(BAD_THRESHOLDS))
def test_python_and_java_refuse_the_thresholds_the_dsl_refuses(problem: str, generated: Path, java,
                                                              monitor_jar: Path, write_rei, run_cli,
                                                              tmp_path: Path) -> None:
    thresholds, field = BAD_THRESHOLDS[problem]
    case = _case_with(thresholds, generated, tmp_path / "case")
    with pytest.raises(ArtifactError, match=field):
        read_monitor(case / "monitor.json")
    replay = subprocess.run([java.executable, "-jar", str(monitor_jar), "--replay", str(tmp_path / "none.msgpack"),
                             "--case", str(case)], capture_output=True, text=True, timeout=120, check=False)
    assert replay.returncode != 0 and f"thresholds.{field}" in replay.stderr, replay.stderr
    if "missing" not in problem:  # the DSL has defaults; it refuses the values
        source = write_rei("bad.rei", f"""testcase T {{
  room R size 3 x 3 {{ robot r : Waffle on F_0_0 }}
  mission M {{ goto F_2_2 }}
  monitor {{ close {thresholds['close']} collision {thresholds['collision']} }}
}}
""")
        validated = run_cli("validate", source)
        assert validated.returncode != 0 and "threshold" in validated.stdout + validated.stderr


def test_the_monitor_page_describes_every_class_and_feature_of_the_runtime_model(repo_root: Path) -> None:
    """Users write queries against these names: the page's table is a copy of runtime.ecore, checked here."""
    import xml.etree.ElementTree as ET

    page = (repo_root / "docs" / "monitor.md").read_text(encoding="utf-8")
    section = page.split("## Queries over the runtime model", 1)[1].split("\n## ", 1)[0]
    rows = {m[1]: m[2] for m in re.finditer(r"^\| `(\w+)` \| (.*)$", section, re.MULTILINE)}
    model = ET.parse(repo_root / "metamodels" / "model" / "runtime.ecore").getroot()
    xsi = "{http://www.w3.org/2001/XMLSchema-instance}type"
    for classifier in model.findall("eClassifiers"):
        name = classifier.get("name")
        if classifier.get(xsi) == "ecore:EEnum":
            literals = [literal.get("name") for literal in classifier.findall("eLiterals")]
            assert f"{name}: {', '.join(literals)}" in section, name
            continue
        assert name in rows, f"docs/monitor.md has no row for {name}"
        for feature in classifier.findall("eStructuralFeatures"):
            assert f"`{feature.get('name')}`" in rows[name], f"{name}.{feature.get('name')} is not on its row"


def test_the_footprint_types_are_one_fact_of_the_reader_and_both_world_readers(contract: dict,
                                                                                java_facts: dict) -> None:
    """A robot's footprint in world.json: written by the description reader, read by Python and the monitor."""
    types = contract["footprints"]["types"]
    assert list(FOOTPRINT_TYPES) == types
    assert java_facts["footprint_types"] == types
    written = [Polygon(((0.0, 0.0), (1.0, 0.0), (0.0, 1.0))).to_json()["type"], Circle(0.0, 0.0, 1.0).to_json()["type"]]
    assert written == types
    # hello's robot.outline: written by the simulation, read by the Java kit
    from rei.artifacts.world import CircleFootprint, PolygonFootprint
    sent = [protocol.outline(PolygonFootprint(((0.0, 0.0), (1.0, 0.0), (0.0, 1.0))))["type"],
            protocol.outline(CircleFootprint(0.0, 0.0, 1.0))["type"]]
    assert sent == types == java_facts["sut_outline_types"]
