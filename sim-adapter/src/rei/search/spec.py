# SPDX-License-Identifier: EPL-2.0
"""The search spec (``rei search SPEC.yaml``): a base case, the SUT, what may change, what counts as worse.

Checked completely at the door; every mistake is reported at once, each as ``FILE:LINE:COLUMN: message`` at the
YAML value (or key) it is about and in the order of the file, as ``rei validate`` reports a test case's (the names
of elements the base case does not have with them: rei.search.base.with_base_case_problems). Format
(docs/search.md)::

    name: crossing              # optional, default: the file's stem
    case: crossing.rei          # the base case, relative to the spec file, or instead:
    # rooms: {size: small, density: sparse, humans: 1, seed: 4}  # one generated room, as in campaign specs
    controller: nav             # or sut: {command: ..., map: true, ...} as in campaign specs
    seed: 0                     # the sampler's seed
    budget: 20                  # simulated evaluations (--budget overrides)
    sampler: tpe                # tpe, cmaes, nsga2, qmc or random (--sampler overrides)
    timeout: 120                # wall seconds per run before it is stopped and recorded as ERROR
    humans: true
    patterns: my-patterns       # optional: a folder of *.vepl every run's monitor runs besides the defaults
    utilities: utilities.yaml   # optional: utility per signal, as `rei run --patterns DIR --utilities YAML`
    parameters:
      - {object: bin1, floor: any}              # any floor free in the base case, or a list of floors
      - {object: bin1, yaw: [0, 180]}           # degrees
      - {human: walker, points: [[F_2_0, F_2_2], any]}  # per control point: its floors (or 'any')
      - {human: walker, start: [0, 20], speed: [0.4, 1.5], loop: [true, false]}
      - {human: ann, behaviour: [avoids, curious, blocks]}   # a person on a route (start, speed, loop too)
      - {human: ann, stop: 1, floor: [F_3_0, F_4_0]}          # a stop of its route: its floors, or any
      - {robot: tb3, floor: [F_0_1, F_1_1]}
      - {goal: 1, floor: any}
      - {seed: [0, 1000]}
      - {fault: "laser:1%", rate: [0.0, 0.05]}  # and gain, width: the run-long impulse noise around a preset
      - {fault: laser, kind: [blackout, freeze], start: [2, 20], duration: [0.2, 5]}  # a fault on a timeline
      #   and a kind's own values (impulse: rate, gain, width; noise: sigma), a pulse train's period, pulse or duty
      - {fault: commands, kind: loss, probability: [0.5, 1], start: [4, 6]}           # the motion's faults alike
      - {furniture: [Chair, Box], count: [0, 3], floor: any}  # extra pieces from the catalogues
      - {crowd: shoppers, count: [2, 12], rate: [0.2, 2], behaviour: [avoids, ignores, blocks]}  # a crowd's line
      - {group: family, count: [2, 4], behaviour: [avoids, curious]}  # a group's line
    objectives:                 # one, or several (a Pareto search)
      - utility                 # or {utility: minimize}
      - {metric: clearance_humans_min}          # summary.json's metrics, default: towards the worse side
      - {verdict: MISSION_WITH_HUMAN_TRAJECTORY}  # 0 when it fails, 1 when it holds: minimized
      - {signal: SIG_OBJECT_COLLISION_BEGIN, of: count}  # or of: first (its first time); or a signal 'patterns' declare
    shrink: {budget: 8}         # simulations per distinct failure to shrink it; budget 0 turns it off
    diversity: true             # an evaluation that only repeats failures found before scores as uninteresting
    refine: true                # follow a near miss's encounter shift (rei.search.refine; with that objective)
"""

from __future__ import annotations

import dataclasses
import difflib
import math
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml

from rei import located_yaml
from rei.artifacts.animation import Behaviour
from rei.campaign.spec import (
    ExternalSut,
    RoomSettings,
    SpecError,
    _Reader,
    _rooms,
    _sut,
    anchored,
    check_user_patterns,
)
from rei.evaluation.metrics import BY_NAME, NAMES, Better
from rei.search import SAMPLERS
from rei.sim.faults import SENSOR_KIND_KEYS, SENSORS, fault_from_fields
from rei.sim.faults.motion import WHEELS

DIRECTIONS = ("minimize", "maximize")
#: Samplers that search one objective only (Optuna's CmaEsSampler refuses a multi-objective study at its first ask).
SINGLE_OBJECTIVE = ("cmaes",)
#: The direction in which each kind of objective is worse for the robot (what a falsification looks for).
_WORSE = {"utility": "minimize", "time": "maximize", "verdict": "minimize"}


@dataclass(frozen=True, slots=True)
class Range:
    low: float
    high: float
    integer: bool = False


@dataclass(frozen=True, slots=True)
class Parameter:
    """One searched property of one element. ``target``: object, human, robot, goal, seed, fault, furniture
    (extra pieces: ``domain`` is (types, count Range, floors or None)), crowd or group (``count``, ``rate``,
    ``behaviour`` of its line);
    ``name``: the element (a goal's index as text; empty for seed and a preset's fault, the sensor for a fault on
    a timeline); ``prop``: floor, yaw, points, start, speed, loop, behaviour, stop (a route's stop ``index``: its
    floor), value (seed), rate, gain, width, and a fault on a timeline's kind, start, duration, sigma, period,
    pulse, duty;
    ``domain``: a Range, a tuple of choices, or for ``points`` a tuple with one tuple of floors (or None: any
    floor) per control point; None for 'any'."""

    target: str
    name: str
    prop: str
    domain: Any
    where: str  # FILE:LINE:COLUMN of its value, for later messages
    base: str | None = None  # fault: the preset the searched values are added to
    name_at: str = ""  # FILE:LINE:COLUMN of the element's name (messages about the element)
    prop_at: str = ""  # FILE:LINE:COLUMN of its key (a key the element's kind does not have: stop for a stop)
    index: int | None = None  # a route's stop (prop 'stop')

    @property
    def key(self) -> str:
        """Its name in the study and in search.json: ``bin1.floor``, ``goal1.floor``, ``ann.stops.1``, ``seed``."""
        if self.target == "seed":
            return "seed"
        if self.target in ("fault", "furniture"):
            return f"{self.target}.{self.prop}"
        if self.prop == "stop":
            return f"{self.name}.stops.{self.index}"
        owner = f"goal{self.name}" if self.target == "goal" else self.name
        return f"{owner}.{self.prop}"


@dataclass(frozen=True, slots=True)
class Objective:
    """``kind``: utility, time, metric, verdict or signal; ``key``: the metric, requirement or signal
    (``any`` for every verdict); ``of``: count or first (signals)."""

    kind: str
    key: str
    direction: str
    of: str = ""

    @property
    def label(self) -> str:
        if self.kind in ("utility", "time"):
            return self.kind
        return f"{self.kind}:{self.key}" + (f":{self.of}" if self.of else "")


@dataclass(frozen=True, slots=True)
class SearchSpec:
    """``case``: the base case; None when ``rooms`` generates it (rei.search.base writes it into the search's
    folder and sets ``case``)."""

    name: str
    case: Path | None
    controller: str
    sut: ExternalSut | None
    seed: int
    budget: int
    sampler: str
    timeout: float
    humans: bool
    parameters: tuple[Parameter, ...]
    objectives: tuple[Objective, ...]
    shrink_budget: int
    diversity: bool = True
    refine: bool = True
    source: Path | None = None
    rooms: RoomSettings | None = None
    #: the user's VEPL patterns (``rei run --patterns``) and utility file (``--utilities``), absolute
    patterns: Path | None = None
    utilities: Path | None = None
    #: FILE:LINE:COLUMN of each top-level key's value, for messages about a setting after parsing
    positions: Mapping[str, str] = field(default_factory=dict, compare=False, repr=False)

    def with_options(self, **changes: Any) -> SearchSpec:
        """The spec with the command line's overrides (``budget``, ``sampler``; None: the spec's), checked as the
        spec's own values are."""
        spec = dataclasses.replace(self, **{k: v for k, v in changes.items() if v is not None})
        if changes.get("sampler") is not None:
            _check_sampler(spec.sampler, spec.objectives, self.positions.get("objectives", str(self.source or "spec")),
                           "--sampler ")
        return spec


class _Located:
    """A YAML document's nodes with their marks (rei.located_yaml) in ``file``: every value comes with where it
    was written, every mistake is a ``SpecError``."""

    def __init__(self, file: str) -> None:
        self.file = file

    def at(self, node: yaml.Node) -> str:
        line, column = located_yaml.position(node)
        return f"{self.file}:{line}:{column}"

    def value(self, node: yaml.Node) -> Any:
        try:
            return located_yaml.value(node)
        except located_yaml.LocatedError as error:
            raise SpecError(error.at(self.file)) from None

    def mapping(self, node: yaml.Node, what: str,
                problems: located_yaml.Collector | None = None) -> located_yaml.Entries:
        """A mapping's entries; with ``problems``, a key given twice is one of them (its first entry is read)."""
        twice: list[located_yaml.LocatedError] | None = None if problems is None else []
        try:
            entries = located_yaml.mapping(node, what, twice)
        except located_yaml.LocatedError as error:
            raise SpecError(error.at(self.file)) from None
        if problems is not None:
            problems.add(*(error.at(self.file) for error in twice or ()))
        return entries


#: The domain of a parameter whose values did not read: the spec has that mistake already; its element is still
#: checked against the base case (rei.search.space), with the spec's other mistakes.
class _Unread:
    def __repr__(self) -> str:
        return "UNREAD"


UNREAD: Any = _Unread()


@dataclass(frozen=True, slots=True)
class Unchecked:
    """What of a spec with mistakes can still be checked against its base case, so that a name the base case does
    not have is reported with the spec's own mistakes: the base case (``case``, or the ``rooms`` that generate it),
    whether the runs have humans, and the parameters (those whose values did not read with domain ``UNREAD``)."""

    case: Path | None
    rooms: RoomSettings | None
    humans: bool
    parameters: tuple[Parameter, ...]


class SearchSpecError(SpecError):
    """The mistakes of a search spec, every one, in the order of the file; ``unchecked``: what of the spec can
    still be checked against its base case (rei.search.base.with_base_case_problems), None when nothing can."""

    unchecked: Unchecked | None = None


def load_search_spec(path: Path) -> SearchSpec:
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as error:
        raise SpecError(f"{path}: cannot read: {error.strerror or error}") from None
    spec = parse_search_spec(text, base=path.resolve().parent, file=str(path), default_name=path.stem)
    return dataclasses.replace(spec, source=path)


_KNOWN = ("name", "case", "rooms", "controller", "sut", "seed", "budget", "sampler", "timeout", "humans", "parameters",
          "objectives", "shrink", "diversity", "refine", "patterns", "utilities")


def parse_search_spec(text: str, *, base: Path, file: str = "spec", default_name: str = "search") -> SearchSpec:
    """A checked ``SearchSpec`` from YAML text; the case path is resolved against ``base``. Every mistake is
    reported at once, a ``SearchSpecError`` of them all in the order of the file; a check that depends on one that
    failed (a fault's values on the fault, a signal on the patterns that declare it) is skipped."""
    loc = _Located(file)
    try:
        root = located_yaml.compose(text)
    except located_yaml.LocatedError as error:
        raise SearchSpecError(error.at(file)) from None
    if root is None:
        raise SearchSpecError(f"{file}:1:1: the spec is empty: expected 'case', 'parameters' and 'objectives'")
    problems = located_yaml.Collector()
    try:
        top = loc.mapping(root, "the spec", problems)
    except SpecError as error:
        raise SearchSpecError(*error.args) from None
    for name, (key, _) in top.items():
        if name not in _KNOWN:
            problems.add(f"{loc.at(key)}: unknown key '{name}'; known: {', '.join(_KNOWN)}")
    plain = {}
    for name, (_, value) in top.items():
        if name not in ("parameters", "objectives", "sut"):
            with problems.check():
                plain[name] = loc.value(value)
    reader = _PositionedReader(plain, top, loc)
    for required in ("parameters", "objectives"):
        if required not in top:
            problems.add(f"{loc.at(root)}: '{required}' is required")
    case, rooms = None, None
    if ("case" in top) == ("rooms" in top):
        where = loc.at(top["rooms"][0]) if "rooms" in top else loc.at(root)
        problems.add(f"{where}: give either 'case' (a .rei file) or 'rooms' (generated-room settings as in "
                     f"campaign specs){', not both' if 'rooms' in top else ''}")
    elif "case" in top:
        case = problems.read(lambda: _case(top["case"][1], base, loc), None)
    else:
        rooms = problems.read(lambda: _room_settings(top["rooms"][1], base, loc), None)
    if "controller" in top and "sut" in top:
        problems.add(f"{loc.at(top['sut'][0])}: give either 'controller' (in-process) or 'sut' (external), not both")
    controller = problems.read(lambda: anchored(reader.call("controller", lambda r: r.str("controller", "nav")), base),
                               "nav")
    with problems.check():
        _check_controller(controller, loc.at(top["controller"][1]) if "controller" in top else file)
    sut = None
    if "sut" in top:
        sut_node = top["sut"][1]
        sut = problems.read(lambda: _at(loc.at(sut_node), lambda: _sut(_Reader({"sut": loc.value(sut_node)}, ""),
                                                                         base)), None)
    shrink_budget = problems.read(lambda: _shrink_budget(top, loc, problems), 8)
    # with those whose values did not read (UNREAD), when the spec has that mistake: their elements are still
    # checked against the base case
    every_parameter = _parameters(top["parameters"][1], loc, problems) if "parameters" in top else ()
    patterns, utilities, declared = problems.read(lambda: _patterns(top, base, loc), (None, None, None))
    objectives: tuple[Objective, ...] = ()
    read_objectives = located_yaml.Collector()
    if "objectives" in top:
        objectives = _objectives(top["objectives"][1], loc, declared, read_objectives)
        problems.add(*read_objectives.problems)
    name = problems.read(lambda: reader.call("name", lambda r: r.name("name", default_name)), default_name)
    seed = problems.read(lambda: reader.call("seed", lambda r: r.int("seed", 0, minimum=0)), 0)
    budget = problems.read(lambda: reader.call("budget", lambda r: r.int("budget", 20, minimum=1)), 20)
    sampler = problems.read(lambda: reader.call("sampler", lambda r: r.choice("sampler", SAMPLERS, "tpe")), None)
    timeout = problems.read(lambda: reader.call("timeout", lambda r: r.number("timeout", 300.0)), 300.0)
    humans = problems.read(lambda: reader.call("humans", lambda r: r.bool("humans", True)), True)
    diversity = problems.read(lambda: reader.call("diversity", lambda r: r.bool("diversity", True)), True)
    refine = problems.read(lambda: reader.call("refine", lambda r: r.bool("refine", True)), True)
    positions = {name: loc.at(value) for name, (_, value) in top.items()}
    if sampler is not None and "objectives" in top and not read_objectives:  # it counts the objectives
        with problems.check():
            _check_sampler(sampler, objectives, positions.get("sampler", file))
    if problems:
        error = SearchSpecError.of(problems.problems)
        if case is not None or rooms is not None:
            error.unchecked = Unchecked(case, rooms, humans, every_parameter)
        raise error
    parameters = every_parameter
    assert all(p.domain is not UNREAD for p in parameters)
    return SearchSpec(
        name=name, case=case, controller=controller, sut=sut, seed=seed, budget=budget, sampler=sampler,
        timeout=timeout, humans=humans, parameters=parameters, objectives=objectives, shrink_budget=shrink_budget,
        diversity=diversity, refine=refine, rooms=rooms, patterns=patterns, utilities=utilities, positions=positions)


def _case(node: yaml.Node, base: Path, loc: _Located) -> Path:
    case = (base / str(loc.value(node))).resolve()
    if case.suffix != ".rei" or not case.is_file():
        raise SpecError(f"{loc.at(node)}: the base case {case} is not a .rei file")
    return case


def _shrink_budget(top: located_yaml.Entries, loc: _Located, problems: located_yaml.Collector) -> int:
    if "shrink" not in top:
        return 8
    shrink = loc.mapping(top["shrink"][1], "'shrink'", problems)
    for name, (key, _) in shrink.items():
        if name != "budget":
            problems.add(f"{loc.at(key)}: unknown key '{name}'; known: budget")
    if "budget" not in shrink:
        return 8
    budget: int = _PositionedReader({"budget": loc.value(shrink["budget"][1])}, shrink, loc).call(
        "budget", lambda r: r.int("budget", 8, minimum=0))
    return budget


def _check_sampler(sampler: str, objectives: tuple[Objective, ...], where: str, given: str = "") -> None:
    """A sampler that searches one objective is refused for several (``given``: how it was chosen, when on the
    command line)."""
    if sampler in SINGLE_OBJECTIVE and len(objectives) > 1:
        raise SpecError(f"{where}: {given}{sampler} searches a single objective, the spec gives "
                        f"{len(objectives)} ({', '.join(o.label for o in objectives)}): use nsga2 (or tpe) "
                        f"for several, or keep one objective")


def _room_settings(node: yaml.Node, base: Path, loc: _Located) -> RoomSettings:
    """``rooms:`` read and checked by the campaign spec's reader (the same keys but ``count``: a search starts
    from one room), each mistake placed at the setting it is about (rei.campaign.spec)."""
    entries = loc.mapping(node, "'rooms'")
    problems = located_yaml.Collector()
    if "count" in entries:
        problems.add(f"{loc.at(entries['count'][0])}: a search starts from one generated room: leave out "
                     "'count' (another room of these settings: change 'seed')")
    settings = problems.read(lambda: _rooms(_Reader(loc.value(node), loc.file, node, loc.file), base), None)
    problems.raise_if_any(SpecError)
    assert settings is not None
    return settings


class _PositionedReader:
    """The campaign spec's typed reader, its messages placed at the value they are about."""

    def __init__(self, plain: dict[str, Any], nodes: Mapping[str, tuple[yaml.Node, yaml.Node]], loc: _Located) -> None:
        self._plain, self._nodes, self._loc = plain, nodes, loc

    def call(self, key: str, read: Any) -> Any:
        where = self._loc.at(self._nodes[key][1]) if key in self._nodes else self._loc.file
        return _at(where, lambda: read(_Reader(self._plain, "")))


#: What the campaign reader puts before its messages when its own position is empty.
_OWN_PREFIX = re.compile(r"^:\s*(sut:\s*)?")


def _at(where: str, read: Any) -> Any:
    """``read()``, each problem of a SpecError from it placed at ``where`` (the campaign reader's own prefix
    dropped)."""
    try:
        return read()
    except SpecError as error:
        raise SpecError.of(f"{where}: {_OWN_PREFIX.sub('', problem)}" for problem in error.problems) from None


def _check_controller(controller: str, where: str) -> None:
    from rei.sut.registry import controller_problem

    problem = controller_problem(controller)
    if problem is not None:
        raise SpecError(f"{where}: {problem}")


#: A human's keys: a trajectory's (points) and a route's (behaviour, a stop's floor) alike; which apply to which
#: person is known from the base case (rei.search.space).
_PROPS = {"object": ("floor", "yaw"), "robot": ("floor",),
          "human": ("points", "start", "speed", "loop", "behaviour", "stop", "floor"),
          "goal": ("floor",), "seed": (), "fault": ("rate", "gain", "width", "kind", "start", "duration", "sigma",
                                                   "fraction", "probability", "scale", "bias", "dx", "dy", "dyaw", "wheel", "delay",
                                                   "period", "pulse", "duty"), "furniture": ("count", "floor"),
          "crowd": ("count", "rate", "behaviour"), "group": ("count", "behaviour")}
#: The fewest people of a crowd and of a group (the language's tooFewPeople: a group's leader and one more).
LEAST_PEOPLE = {"crowd": 1, "group": 2}
#: The slowest crowd rate a case's text can hold (rei.edit.gatherings.number writes three decimals).
LEAST_RATE = 0.001


def _parameters(node: yaml.Node, loc: _Located, problems: located_yaml.Collector) -> tuple[Parameter, ...]:
    """The parameters, each mistake one of ``problems``; a parameter of an element whose values did not read is
    one with the domain ``UNREAD`` (its element can still be checked against the base case)."""
    if not isinstance(node, yaml.SequenceNode) or not node.value:
        problems.add(f"{loc.at(node)}: 'parameters' must be a non-empty list")
        return ()
    parameters: list[Parameter] = []
    for item in node.value:
        with problems.check():
            parameters += _parameter(item, loc, problems)
    keys = [p.key for p in parameters if p.domain is not UNREAD]
    for i, parameter in enumerate(p for p in parameters if p.domain is not UNREAD):
        if parameter.key in keys[:i]:
            problems.add(f"{parameter.where}: {parameter.key} is searched twice")
    return tuple(parameters)


def _parameter(item: yaml.Node, loc: _Located, problems: located_yaml.Collector) -> list[Parameter]:
    """The parameters of one item of ``parameters`` (one per property it searches)."""
    entry = loc.mapping(item, "a parameter", problems)
    targets = [name for name in entry if name in _PROPS]
    if len(targets) != 1:
        raise SpecError(f"{loc.at(item)}: a parameter names exactly one of {', '.join(_PROPS)}, "
                        f"got {', '.join(targets) or 'none'}")
    target = targets[0]
    key_node, name_node = entry[target]
    name_value = loc.value(name_node)
    props = [name for name in entry if name != target]
    for prop in props:
        if prop not in _PROPS[target]:
            problems.add(f"{loc.at(entry[prop][0])}: '{prop}' is not a property of {_article(target)} {target}; "
                         f"expected {', '.join(_PROPS[target]) or 'no other key'}")
    known = [prop for prop in props if prop in _PROPS[target]]
    if target == "furniture":
        return [_furniture(name_value, name_node, entry, item, loc)]
    if target == "seed":
        seeds = _range(name_value, name_node, loc, integer=True)
        if seeds.low < 0:  # the run's random generators take none below 0: every run would crash
            raise SpecError(f"{loc.at(name_node)}: a run's seed is 0 or more, got [{seeds.low:g}, {seeds.high:g}]")
        return [Parameter("seed", "", "value", seeds, loc.at(item))]
    if target == "fault":
        return _fault(name_value, name_node, known, entry, item, loc, problems, any_key=bool(props))
    named = True
    if target == "goal":
        if isinstance(name_value, bool) or not isinstance(name_value, int) or name_value < 0:
            problems.add(f"{loc.at(name_node)}: 'goal' is the goal's index in the mission (0 is the first), "
                         f"got {name_value!r}")
            named = False
    elif not isinstance(name_value, str) or not name_value:
        problems.add(f"{loc.at(name_node)}: '{target}' must name an element of the base case")
        named = False
    if not props:
        problems.add(f"{loc.at(key_node)}: give what to change of {name_value}: {', '.join(_PROPS[target])}")
    parameters = []
    if target == "human" and ("stop" in entry or "floor" in entry):
        stop = _stop(entry, loc, problems)
        if named and stop is not None:
            parameters.append(Parameter(target, str(name_value), "stop", stop[1], loc.at(entry["floor"][1]),
                                        name_at=loc.at(name_node), prop_at=loc.at(entry["stop"][0]), index=stop[0]))
        props = [prop for prop in props if prop not in ("stop", "floor")]
    for prop in props:
        value_node = entry[prop][1] if prop in known else entry[prop][0]
        domain = problems.read(lambda prop=prop: _domain(prop, entry[prop][1], loc, target), UNREAD) if prop in known \
            else UNREAD
        if named:
            parameters.append(Parameter(target, str(name_value), prop, domain, loc.at(value_node),
                                        name_at=loc.at(name_node), prop_at=loc.at(entry[prop][0])))
    return parameters


def _stop(entry: dict[str, tuple[yaml.Node, yaml.Node]], loc: _Located,
          problems: located_yaml.Collector) -> tuple[int, Any] | None:
    """``stop: INDEX, floor: [...]`` of a person on a route: (the stop's index, its floors or None for any; UNREAD
    when they did not read), None when one of the two keys is missing."""
    if "stop" not in entry:
        problems.add(f"{loc.at(entry['floor'][0])}: a person's 'floor' is a floor of its route's stops: give 'stop' "
                     "too, the stop's index in the route (0 is the first)")
        return None
    if "floor" not in entry:
        problems.add(f"{loc.at(entry['stop'][0])}: give 'floor' with 'stop': the floors the stop may be on, a list "
                     "or 'any'")
        return None
    index_node, floor_node = entry["stop"][1], entry["floor"][1]
    index = problems.read(lambda: loc.value(index_node), None)
    if isinstance(index, bool) or not isinstance(index, int) or index < 0:
        problems.add(f"{loc.at(index_node)}: 'stop' is the stop's index in the person's route (0 is the first), "
                     f"got {index!r}")
        return None
    return index, problems.read(lambda: _floors(loc.value(floor_node), floor_node, loc), UNREAD)


def _furniture(types: Any, node: yaml.Node, entry: dict[str, tuple[yaml.Node, yaml.Node]], item: yaml.Node,
               loc: _Located) -> Parameter:
    """``{furniture: [Chair, Box], count: [0, 3], floor: any}``: up to ``count`` extra pieces of the listed
    catalogue types (checked against the base case's catalogues later), each on a floor of ``floor``."""
    problems = located_yaml.Collector()
    if not isinstance(types, list) or not types or not all(isinstance(t, str) and t for t in types):
        problems.add(f"{loc.at(node)}: 'furniture' lists the catalogue types to add, such as [Chair, Box]")
    count = None
    if "count" not in entry:
        problems.add(f"{loc.at(item)}: give 'count': how many pieces at least and at most, such as [0, 3]")
    else:
        count_node = entry["count"][1]
        count = problems.read(lambda: _range(loc.value(count_node), count_node, loc, integer=True), None)
        if count is not None and (count.low < 0 or count.high > 10):
            problems.add(f"{loc.at(count_node)}: 'count' is between 0 and 10 pieces, got [{count.low:g}, "
                         f"{count.high:g}]")
    floors = None
    if "floor" in entry:
        floors = problems.read(lambda: _floors(loc.value(entry["floor"][1]), entry["floor"][1], loc), None)
    problems.raise_if_any(SpecError)
    return Parameter("furniture", "", "count", (tuple(dict.fromkeys(types)), count, floors), loc.at(item),
                     name_at=loc.at(node))


def _fault(name_value: Any, name_node: yaml.Node, props: list[str], entry: dict[str, tuple[yaml.Node, yaml.Node]],
           item: yaml.Node, loc: _Located, problems: located_yaml.Collector, any_key: bool) -> list[Parameter]:
    """``{fault: "laser:1%", rate: [0.0, 0.05]}``: the fault's values searched around the preset. A value's
    range is checked against the fault only when the fault reads."""
    from rei.sim.faults import parse_fault

    if isinstance(name_value, str) and name_value in SENSORS:
        return _scheduled_fault(name_value, name_node, props, entry, item, loc, problems)
    base_fault = None
    if not isinstance(name_value, str):
        problems.add(f"{loc.at(name_node)}: 'fault' is the fault the values change, such as \"laser:1%\"")
    else:
        try:
            base_fault = parse_fault(name_value)
        except ValueError as error:
            problems.add(f"{loc.at(name_node)}: {error}")
        else:
            if base_fault is None:
                problems.add(f"{loc.at(name_node)}: 'fault' is the fault the values change, such as \"laser:1%\", "
                             f"got {name_value!r} (no fault)")
    if not any_key:
        problems.add(f"{loc.at(item)}: give at least one of rate, gain, width")
    parameters = []
    for prop in [p for p in props if p not in PRESET_KEYS]:
        problems.add(f"{loc.at(entry[prop][0])}: '{prop}' is a key of a fault on a timeline ({{fault: laser, kind: "
                     f"[...], {prop}: ...}}); a preset's values are {', '.join(PRESET_KEYS)}")
    for prop in [p for p in props if p in PRESET_KEYS]:
        with problems.check():
            value_node = entry[prop][1]
            domain = _range(loc.value(value_node), value_node, loc, integer=prop == "width")
            if base_fault is not None:
                _check_fault_range(base_fault, prop, domain, loc.at(value_node))
                parameters.append(Parameter("fault", "", prop, domain, loc.at(value_node), base=name_value))
    return parameters


#: The values of the run-long impulse noise searched around a preset (``{fault: "laser:1%", rate: [...]}``).
PRESET_KEYS = ("rate", "gain", "width")
#: The keys of a fault on a timeline the search varies besides its kind: ``start`` and ``duration`` (seconds) make
#: its ``from`` and ``to``; the others are the fault's own keys (rei.sim.faults.spec), a kind's (``KIND_KEYS``) or
#: the pulse train's (``period`` with ``pulse`` or ``duty``).
SCHEDULE_KEYS = ("start", "duration", "period", "pulse", "duty")
#: Each sensor's kinds whose every key is a number searched in a range, the first two the example of a list.
SEARCHABLE_KINDS: dict[str, tuple[str, ...]] = {
    "laser": ("blackout", "freeze", "impulse", "noise"), "odometry": ("drift", "jump"), "drive": ("slip", "stuck"),
    "commands": ("loss", "latency"), "pose": ("kidnap",)}
#: Why the other kinds are not searched yet.
UNSEARCHED = {"occlusion": "an occlusion's sector is not searched yet"}
#: What a kind cannot do without: a range of at least one key of each (a drift's scale or bias, an offset's dx, dy
#: or dyaw).
NEEDED_KEYS = {"noise": ("sigma",), "slip": ("fraction",), "stuck": ("wheel",), "latency": ("delay",), "loss": ("probability",), "drift": ("scale", "bias"),
               "jump": ("dx", "dy", "dyaw"), "kidnap": ("dx", "dy", "dyaw")}
#: A value of each needed key that its kinds accept whatever the others are: it stands in for the keys other than
#: the one whose range's ends are checked.
STAND_INS = {"delay": "1", "sigma": "1", "fraction": "1", "probability": "1", "scale": "2", "bias": "1", "dx": "1", "dy": "1",
             "dyaw": "1"}


def _scheduled_fault(sensor: str, name_node: yaml.Node, props: list[str],
                     entry: dict[str, tuple[yaml.Node, yaml.Node]], item: yaml.Node, loc: _Located,
                     problems: located_yaml.Collector) -> list[Parameter]:
    """``{fault: laser, kind: [blackout, freeze], start: [2, 20], duration: [0.2, 5]}``: a fault on a timeline,
    its kind one of a list and each other key a range; every key must be one a listed kind has, every range's ends
    values the fault model accepts (its own checks, rei.sim.faults, say why not)."""
    name_at = loc.at(name_node)
    kinds: tuple[str, ...] = ()
    keys, searchable = SENSOR_KIND_KEYS[sensor], SEARCHABLE_KINDS[sensor]
    if "kind" not in entry:
        problems.add(f"{loc.at(item)}: give 'kind': the {sensor} fault's kinds to choose from, such as "
                     f"[{', '.join(searchable[:2])}] (of {', '.join(_in_order(sensor))})")
    else:
        kinds = problems.read(lambda: _fault_kinds(sensor, entry["kind"][1], loc), ())
    domains: dict[str, Any] = {}
    for prop in props:
        if prop == "kind":
            continue
        value_node = entry[prop][1]
        with problems.check():
            domains[prop] = (_wheels(loc.value(value_node), value_node, loc) if prop == "wheel"
                             else _range(loc.value(value_node), value_node, loc, integer=prop == "width"))
            owners = [k for k in kinds if prop in keys[k]]
            if prop not in SCHEDULE_KEYS and kinds and not owners:
                listed = " or ".join(f"{sensor} {k}" for k in kinds)
                raise SpecError(f"{loc.at(entry[prop][0])}: {_article(listed)} {listed} fault has no '{prop}' "
                                f"(its keys: {', '.join(_kind_keys(sensor, kinds))})")
            if prop != "wheel":  # a choice of wheels, each one a stuck wheel can be
                _check_schedule_range(sensor, prop, domains[prop], owners, loc.at(value_node))
    for kind in kinds:
        needed = NEEDED_KEYS.get(kind, ())
        if needed and not any(key in entry for key in needed):
            listed = " or ".join(f"'{key}'" for key in needed)
            problems.add(f"{loc.at(entry['kind'][1])}: {_article(sensor)} {sensor} {kind} fault needs {listed}: give "
                         f"{'its range' if len(needed) == 1 else 'a range of one'}")
    if "pulse" in entry and "duty" in entry:
        problems.add(f"{loc.at(entry['duty'][0])}: give the pulse width as 'pulse' (seconds) or 'duty' (a share of "
                     "the period), not both")
    elif ("pulse" in entry or "duty" in entry) != ("period" in entry):
        what = "period" if "period" in entry else "pulse" if "pulse" in entry else "duty"
        problems.add(f"{loc.at(entry[what][0])}: a pulse train needs 'period' and 'pulse' (or 'duty')")
    if not kinds:
        return []
    parameters = [Parameter("fault", sensor, "kind", kinds, loc.at(entry["kind"][1]), name_at=name_at,
                            prop_at=loc.at(entry["kind"][0]))]
    parameters += [Parameter("fault", sensor, prop, domain, loc.at(entry[prop][1]), name_at=name_at,
                             prop_at=loc.at(entry[prop][0])) for prop, domain in domains.items()]
    return parameters


def _kind_keys(sensor: str, kinds: tuple[str, ...]) -> list[str]:
    return list(dict.fromkeys([*(key for k in kinds for key in SENSOR_KIND_KEYS[sensor][k]), *SCHEDULE_KEYS]))


def _wheels(value: Any, node: yaml.Node, loc: _Located) -> tuple[str, ...]:
    listed = [value] if isinstance(value, str) else value
    if not isinstance(listed, list) or not listed or not all(wheel in WHEELS for wheel in listed):
        raise SpecError(f"{loc.at(node)}: 'wheel' is the stuck wheel or a list to choose from: "
                        f"{' or '.join(WHEELS)}, got {value!r}")
    return tuple(dict.fromkeys(listed))


def _in_order(sensor: str) -> list[str]:
    """The sensor's searched kinds in the fault model's order (contract/vocabulary.json's)."""
    return [kind for kind in SENSOR_KIND_KEYS[sensor] if kind in SEARCHABLE_KINDS[sensor]]


def _fault_kinds(sensor: str, node: yaml.Node, loc: _Located) -> tuple[str, ...]:
    value = loc.value(node)
    listed = [value] if isinstance(value, str) else value
    keys, searchable = SENSOR_KIND_KEYS[sensor], SEARCHABLE_KINDS[sensor]
    if not isinstance(listed, list) or not listed or not all(isinstance(k, str) for k in listed):
        raise SpecError(f"{loc.at(node)}: 'kind' is {_article(sensor)} {sensor} fault's kind or a list of them, such "
                        f"as [{', '.join(searchable[:2])}] (of {', '.join(_in_order(sensor))})")
    for kind in listed:
        if kind in keys and kind not in searchable:
            raise SpecError(f"{loc.at(node)}: {UNSEARCHED[kind]}: search {', '.join(_in_order(sensor))}, or give "
                            f"the {kind} in the base case's faults block")
        if kind not in keys:
            close = difflib.get_close_matches(kind, list(keys), n=1)
            hint = f" (did you mean {close[0]}?)" if close else ""
            raise SpecError(f"{loc.at(node)}: unknown {sensor} fault kind {kind!r}{hint}; known: "
                            f"{', '.join(_in_order(sensor))}")
    return tuple(dict.fromkeys(listed))


def _check_schedule_range(sensor: str, prop: str, domain: Range, kinds: list[str], where: str) -> None:
    """Both ends of a searched key are values the fault model accepts (its own checks, rei.sim.faults, say the
    allowed interval; they are intervals, so every value between the ends is one too)."""
    if prop == "start" and domain.low < 0:
        raise SpecError(f"{where}: a fault's start must be a time >= 0 s, got [{domain.low:g}, {domain.high:g}]")
    if prop == "duration" and domain.low <= 0:
        raise SpecError(f"{where}: a fault's duration must be > 0 s, got [{domain.low:g}, {domain.high:g}]")
    if prop in ("start", "duration"):
        return
    for end in (domain.low, domain.high):
        text = str(int(end)) if domain.integer else repr(end)
        fields = {"period": text, "pulse": text} if prop == "period" else \
            {"period": "1", "duty": text} if prop == "duty" else \
            {"period": repr(max(end, 1.0)), "pulse": text} if prop == "pulse" else {prop: text}
        for kind in kinds or SEARCHABLE_KINDS[sensor][:1]:
            stand_ins = {key: STAND_INS[key] for key in NEEDED_KEYS.get(kind, ()) if key != prop}
            try:
                fault_from_fields(sensor, kind, {**stand_ins, **fields})
            except ValueError as error:
                raise SpecError(f"{where}: {prop} [{domain.low:g}, {domain.high:g}] reaches outside what a {sensor} "
                                f"{kind} fault accepts: {error}") from None


def _check_fault_range(fault: Any, prop: str, domain: Range, where: str) -> None:
    """Both ends of a searched fault value are values the fault accepts (its own check, rei.sim.faults.LaserFault,
    says the allowed interval); the accepted values are intervals, so every value between the ends is one too."""
    for end in (domain.low, domain.high):
        try:
            dataclasses.replace(fault, **{prop: int(end) if domain.integer else end})
        except ValueError as error:
            raise SpecError(f"{where}: {prop} [{domain.low:g}, {domain.high:g}] reaches outside what the fault "
                            f"accepts: {error}") from None


def _domain(prop: str, node: yaml.Node, loc: _Located, target: str = "") -> Any:
    value = loc.value(node)
    if prop == "count":  # a crowd's or a group's number of people
        domain = _range(value, node, loc, integer=True)
        if domain.low < LEAST_PEOPLE[target]:
            least = LEAST_PEOPLE[target]
            raise SpecError(f"{loc.at(node)}: a {target} has {least} {'person' if least == 1 else 'people'} or more "
                            f"(the language's least), got [{domain.low:g}, {domain.high:g}]")
        return domain
    if prop == "rate":  # a crowd's people a second
        domain = _range(value, node, loc)
        if domain.low <= 0:
            raise SpecError(f"{loc.at(node)}: a crowd's rate (people a second) must be positive, got "
                            f"[{domain.low:g}, {domain.high:g}]")
        if domain.low < LEAST_RATE:  # a smaller one is written 0 in the case's text, which the language refuses
            raise SpecError(f"{loc.at(node)}: a crowd's rate is written with three decimals: {LEAST_RATE:g} "
                            f"people a second at least, got [{domain.low:g}, {domain.high:g}]")
        return domain
    if prop == "floor":
        return _floors(value, node, loc)
    if prop == "points":
        if not isinstance(node, yaml.SequenceNode) or len(node.value) < 2:
            raise SpecError(f"{loc.at(node)}: 'points' lists each control point's floors (or 'any'), "
                            "at least two points")
        problems = located_yaml.Collector()
        points = tuple(problems.read(lambda point=point: _floors(loc.value(point), point, loc), None)
                       for point in node.value)
        problems.raise_if_any(SpecError)
        return points
    if prop == "loop":
        if not isinstance(value, list) or not value or not all(isinstance(v, bool) for v in value):
            raise SpecError(f"{loc.at(node)}: 'loop' lists the choices, such as [true, false]")
        return tuple(dict.fromkeys(value))
    if prop == "behaviour":
        known = [b.value for b in Behaviour]
        if not isinstance(value, list) or not value or not all(isinstance(v, str) for v in value):
            raise SpecError(f"{loc.at(node)}: 'behaviour' lists the choices, such as [{', '.join(known)}]")
        unknown = [v for v in value if v not in known]
        if unknown:
            raise SpecError(f"{loc.at(node)}: {unknown[0]!r} is not a behaviour; expected {', '.join(known)}")
        return tuple(dict.fromkeys(value))
    if prop == "yaw":
        return _range(value, node, loc)
    if prop in ("start", "speed"):
        domain = _range(value, node, loc)
        if prop == "speed" and domain.low <= 0:
            raise SpecError(f"{loc.at(node)}: a speed (m/s) must be positive, got {domain.low:g}")
        if prop == "start" and domain.low < 0:
            raise SpecError(f"{loc.at(node)}: a start time must not be negative, got {domain.low:g}")
        return domain
    raise AssertionError(prop)


def _floors(value: Any, node: yaml.Node, loc: _Located) -> tuple[str, ...] | None:
    if value == "any":
        return None
    if not isinstance(value, list) or not value or not all(isinstance(v, str) and v for v in value):
        raise SpecError(f"{loc.at(node)}: expected 'any' or a list of floor names, got {value!r}")
    return tuple(dict.fromkeys(value))


def _range(value: Any, node: yaml.Node, loc: _Located, integer: bool = False) -> Range:
    kinds = (int,) if integer else (int, float)
    if (not isinstance(value, list) or len(value) != 2
            or not all(isinstance(v, kinds) and not isinstance(v, bool) for v in value)):
        what = "integers" if integer else "numbers"
        raise SpecError(f"{loc.at(node)}: expected a range [low, high] of two {what}, got {value!r}")
    low, high = value
    if not all(math.isfinite(v) for v in value):  # an end at .inf reached the room editor's engine as no JSON
        raise SpecError(f"{loc.at(node)}: a range's ends must be finite numbers, got [{low}, {high}]")
    if not low < high:
        raise SpecError(f"{loc.at(node)}: the range's low end must be below its high end, got [{low}, {high}]")
    return Range(float(low), float(high), integer)


_KINDS = ("utility", "time", "metric", "verdict", "signal")


def _patterns(top: located_yaml.Entries, base: Path,
              loc: _Located) -> tuple[Path | None, Path | None, frozenset[str] | None]:
    """``patterns:`` and ``utilities:`` resolved against ``base`` and checked as `rei run` checks its
    ``--patterns``/``--utilities`` (rei.campaign.spec.check_user_patterns), a mistake placed at the key's value;
    with them, the signals the patterns declare."""
    paths: dict[str, Path] = {}
    problems = located_yaml.Collector()
    for key, what in (("patterns", "a folder of .vepl files"), ("utilities", "a YAML file 'SIGNAL: utility'")):
        if key in top:
            with problems.check():
                value = loc.value(top[key][1])
                if not isinstance(value, str) or not value:
                    raise SpecError(f"{loc.at(top[key][1])}: '{key}' names {what}, relative to the spec file")
                paths[key] = (base / value).resolve()
    problems.raise_if_any(SpecError)  # the check needs both
    try:
        declared = check_user_patterns(paths.get("patterns"), paths.get("utilities"))
    except SpecError as error:
        key = "patterns" if error.args[1:] == ("patterns",) else "utilities"
        raise SpecError.of([f"{loc.at(top[key][1])}: {line}" for line in str(error.args[0]).splitlines()]) from None
    return paths.get("patterns"), paths.get("utilities"), declared


def _objectives(node: yaml.Node, loc: _Located, declared: frozenset[str] | None,
                problems: located_yaml.Collector) -> tuple[Objective, ...]:
    """The objectives, each mistake one of ``problems``. ``declared``: the signals the spec's patterns declare
    (None when the patterns did not read: a signal is then not checked)."""
    if not isinstance(node, yaml.SequenceNode) or not node.value:
        problems.add(f"{loc.at(node)}: 'objectives' must be a non-empty list")
        return ()
    objectives: list[Objective] = []
    for item in node.value:
        with problems.check():
            objectives.append(_objective(item, loc, declared))
    labels = [o.label for o in objectives]
    if len(set(labels)) != len(labels):
        problems.add(f"{loc.at(node)}: an objective is given twice")
    return tuple(objectives)


def _objective(item: yaml.Node, loc: _Located, declared: frozenset[str] | None) -> Objective:
    if isinstance(item, yaml.ScalarNode):
        name = loc.value(item)
        if name not in ("utility", "time"):
            raise SpecError(f"{loc.at(item)}: unknown objective {name!r}: expected utility, time, or a mapping "
                            "{metric: KEY}, {verdict: REQUIREMENT}, {signal: NAME}")
        return Objective(name, name, _WORSE[name])
    problems = located_yaml.Collector()
    entry = loc.mapping(item, "an objective", problems)
    kinds = [k for k in entry if k in _KINDS]
    if len(kinds) != 1:
        raise SpecError(f"{loc.at(item)}: an objective names exactly one of {', '.join(_KINDS)}")
    kind = kinds[0]
    # utility and time carry their direction as their value; only a signal has 'of'
    known = (kind,) if kind in ("utility", "time") else (kind, "direction", "of") if kind == "signal" \
        else (kind, "direction")
    for extra, (key, _) in entry.items():
        if extra == "direction" and extra not in known:
            problems.add(f"{loc.at(key)}: '{kind}' takes its direction as its value: "
                         f"{{{kind}: minimize}} or {{{kind}: maximize}}")
        elif extra not in known:
            problems.add(f"{loc.at(key)}: unknown key '{extra}'; known: {', '.join(known)}")
    value_node = entry[kind][1]
    value = loc.value(value_node)
    direction_node = entry.get("direction", (None, None))[1]
    if kind in ("utility", "time"):
        if value not in DIRECTIONS:
            problems.add(f"{loc.at(value_node)}: expected minimize or maximize, got {value!r}")
        problems.raise_if_any(SpecError)
        return Objective(kind, kind, value)
    if not isinstance(value, str) or not value:
        problems.add(f"{loc.at(value_node)}: '{kind}' names a {'metric key' if kind == 'metric' else kind}")
    elif kind == "metric" and value not in NAMES:
        problems.add(f"{loc.at(value_node)}: unknown metric {value!r}; known: {', '.join(NAMES)}")
    elif kind == "verdict":
        from rei.evaluation.verdicts import REQUIREMENTS

        if value != "any" and value not in REQUIREMENTS:
            problems.add(f"{loc.at(value_node)}: unknown requirement {value!r}; known: any, {', '.join(REQUIREMENTS)}")
    elif kind == "signal" and declared is not None:
        with problems.check():
            _check_signal(value, loc.at(value_node), declared)
    of = ""
    if kind == "signal":
        of_node = entry.get("of", (None, None))[1]
        of = "count" if of_node is None else problems.read(lambda: loc.value(of_node), "count")
        if of not in ("count", "first"):
            problems.add(f"{loc.at(of_node)}: 'of' is count or first, got {of!r}")
    direction = None
    if direction_node is not None:
        direction = problems.read(lambda: loc.value(direction_node), None)
        if direction not in DIRECTIONS:
            problems.add(f"{loc.at(direction_node)}: expected minimize or maximize, got {direction!r}")
    elif kind == "metric" and value in NAMES and BY_NAME[value].better == Better.NEITHER:
        # no side is worse for the robot (a speed, time in social space): it was maximized without a word
        problems.add(f"{loc.at(value_node)}: {value} has no worse side of its own: give 'direction: minimize' or "
                     f"'direction: maximize'")
    problems.raise_if_any(SpecError)
    if direction is None and kind == "metric":  # worse for the robot: away from the metric's better side
        direction = "minimize" if BY_NAME[value].better == Better.HIGHER else "maximize"
    elif direction is None:
        direction = _WORSE.get(kind) or ("maximize" if of == "count" else "minimize")
    return Objective(kind, value, direction, of)


def _check_signal(name: str, where: str, declared: frozenset[str] = frozenset()) -> None:
    """A signal of the default patterns (rei.evaluation.signals, checked against cep/patterns and the contract) or
    one the spec's own patterns declare (``declared``)."""
    from rei.evaluation.signals import KNOWN_SIGNALS

    known = sorted(set(KNOWN_SIGNALS) | declared)
    if name not in known:
        close = difflib.get_close_matches(name, known, n=1)
        hint = f" (did you mean {close[0]}?)" if close else ""
        mine = "" if declared else "; a signal of your own VEPL patterns: give their folder as 'patterns'"
        raise SpecError(f"{where}: unknown signal {name!r}{hint}; known: {', '.join(known)}{mine}")


def _article(word: str) -> str:
    return "an" if word[0] in "aeiou" else "a"


#: What a resumed search may change: how long it runs, which sampler's study it adds to (the journal holds one per
#: sampler: a random baseline in the same OUT is one), shrinking and the name. Anything else makes another search,
#: whose evaluations the journal's could not be compared with.
_RESUMABLE = ("name", "budget", "sampler", "shrink_budget", "source", "positions", "parameters", "objectives")
_KEYS = {"shrink_budget": "shrink"}


def check_resumable(given: SearchSpec, stored_text: str, stored_file: str) -> None:
    """SpecError, placed in ``given``'s file at what changed, when ``given`` is not the search whose spec is
    ``stored_text`` (OUT/spec.yaml, the spec the search in OUT started with): the same spec, reformatted, resumes."""
    file = str(given.source or "spec")
    base = given.source.resolve().parent if given.source is not None else Path.cwd()
    advice = (f"a changed spec is another search: give a new -o OUT, or restore the spec as {stored_file} has it to "
              f"resume (budget, sampler, shrink and name may change)")
    try:
        stored = parse_search_spec(stored_text, base=base, file=stored_file)
    except SpecError as error:
        raise SpecError(f"{file}:1:1: the search in this OUT started with a spec that no longer reads here "
                        f"({error}); {advice}") from None
    changes = _changes(stored, given, file)
    if changes:
        where, what = changes[0]
        more = f" (and {len(changes) - 1} more change(s))" if len(changes) > 1 else ""
        raise SpecError(f"{where}: this OUT holds a search started with another spec: {what}{more}; {advice}")


def check_patterns_kept(given: SearchSpec, runs: Path) -> None:
    """SpecError, placed at ``given``'s ``patterns:``, when the patterns in that folder are not the ones the search's
    runs so far ran (each run keeps a copy, ``runs/<key>/patterns/``, rei.run.patterns.record): the folder is the
    same, its patterns were edited since, so the resumed runs would be judged by other rules."""
    if given.patterns is None:
        return
    from rei.run.patterns import PATTERNS_DIR, SELECTION_FILE

    for selection in sorted(runs.glob(f"*/{SELECTION_FILE}")):
        kept = selection.parent / PATTERNS_DIR
        if not kept.is_dir():
            continue
        if _vepl(kept) != _vepl(given.patterns):
            file = str(given.source or "spec")
            raise SpecError(f"{given.positions.get('patterns', file + ':1:1')}: this OUT holds a search whose runs "
                            f"ran other patterns than {given.patterns} has now ({kept} has theirs); changed patterns "
                            f"are another search: give a new -o OUT, or restore the patterns to resume")
        return  # every run of the search ran the same patterns: one copy tells


def _vepl(folder: Path) -> dict[str, bytes]:
    """What the monitor reads of ``folder``: its ``*.vepl`` files, by name."""
    return {path.name: path.read_bytes() for path in folder.glob("*.vepl") if path.is_file()}


def _changes(stored: SearchSpec, given: SearchSpec, file: str) -> list[tuple[str, str]]:
    """(where in ``given``'s file, what) for each search-relevant difference; reformatting and the parameters'
    order are none (the study knows parameters by name), the objectives' order is (their values are a list)."""
    changes = []
    for f in dataclasses.fields(SearchSpec):
        if f.name in _RESUMABLE or getattr(stored, f.name) == getattr(given, f.name):
            continue
        key = _KEYS.get(f.name, f.name)
        here, there = _shown(getattr(given, f.name)), _shown(getattr(stored, f.name))
        changes.append((given.positions.get(key, f"{file}:1:1"),
                        f"{key} is {here} here, {there} there" if here and there else f"{key} is another here"))
    was = {p.key: _unplaced(p) for p in stored.parameters}
    now = {p.key: p for p in given.parameters}
    for key, p in now.items():
        if key not in was:
            changes.append((p.where, f"{key} is searched here, not there"))
        elif _unplaced(p) != was[key]:
            changes.append((p.where, f"{key} is {_shown(p.domain) or 'any'} here, {_shown(was[key].domain) or 'any'} there"
                            if p.domain != was[key].domain else f"{key} changed"))
    where = given.positions.get("parameters", f"{file}:1:1")
    changes += [(where, f"{key} is searched there, not here") for key in was if key not in now]
    labels = [(o.label, o.direction) for o in given.objectives]
    before = [(o.label, o.direction) for o in stored.objectives]
    if labels != before:
        def listed(objectives: list[tuple[str, str]]) -> str:
            return ", ".join(f"{label} ({direction})" for label, direction in objectives)
        changes.append((given.positions.get("objectives", f"{file}:1:1"),
                        f"the objectives are {listed(labels)} here, {listed(before)} there"))
    return changes


def _unplaced(parameter: Parameter) -> Parameter:
    return dataclasses.replace(parameter, where="", name_at="", prop_at="")


def _shown(value: Any) -> str:
    """A setting or a parameter's domain as the spec writes it; empty for one not worth showing (a mapping such as
    ``sut`` or ``rooms``, or no value at all)."""
    if isinstance(value, Range):
        return f"[{value.low:g}, {value.high:g}]"
    if isinstance(value, tuple):  # choices, floors (None: any), a human's points
        return "[" + ", ".join(_shown(v) or "any" for v in value) + "]"
    if isinstance(value, bool):
        return str(value).lower()
    if isinstance(value, float):
        return f"{value:g}"
    if isinstance(value, str | int | Path):
        return str(value)
    return ""
