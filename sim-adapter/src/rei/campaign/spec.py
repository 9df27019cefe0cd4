# SPDX-License-Identifier: EPL-2.0
"""The campaign spec (``rei campaign SPEC.yaml``): which test cases, in which variants, how often.

Checked completely at the door, every mistake at once, each with its line and column and its key path, so a typo
does not surface as an error in run 17 of 23 an hour later. Format (docs/campaigns.md)::

    name: thesis-7.4            # optional, default: the file's stem
    seed: 1                     # run seed = seed + repetition (default 0)
    repetitions: 1              # per case and variant (groups may override)
    timeout: 300                # wall seconds per run before it is stopped and recorded as ERROR
    mode: replay                # replay (default) or pipeline (`rei run`: router, live monitor)
    controller: nav             # default controller of the variants
    sut: {command: "rei nav-sut", map: true}  # or an external SUT (docs/sut.md): command, clock, deadline,
                                #   map, join_timeout; a variant's own sut: or controller: wins
    report: false               # write each run's report.html too
    patterns: my-patterns       # the user's *.vepl every run's monitor runs besides the defaults (docs/vepl.md)
    utilities: utilities.yaml   # utility per signal; both as `rei run --patterns DIR --utilities YAML`
    variants: [{name: base}]    # default variants: name, humans (true), fault (null), controller, sut
    groups:
      - name: small
        rooms: {size: small, density: dense, humans: 0, count: 7, seed: 1}  # catalogue: FILE, robot: NAME,
                                                                            #   people: reactive, behaviour: B
        variants: [{name: base}, {name: fault1, fault: "laser:1%"}]
      - name: examples
        cases: [../simple_navigation.rei]      # relative to the spec file
        repetitions: 2
"""

from __future__ import annotations

import dataclasses
import functools
import re
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

from rei import located_yaml
from rei.rooms.model import DEFAULT_TYPES, Room, RoomTypes
from rei.sut.external.options import DEFAULT_DEADLINE, DEFAULT_JOIN_TIMEOUT

MODES = ("replay", "pipeline")
_NAME = re.compile(r"[A-Za-z0-9][A-Za-z0-9_-]*")


class SpecError(located_yaml.Problems):
    """A spec that can not be run: each of its mistakes names the file, the line and column where known, and the
    key."""


@dataclass(frozen=True, slots=True)
class ExternalSut:
    """A variant's external system under test (``rei run --sut COMMAND`` and its options)."""

    command: str
    clock: str = "lockstep"
    deadline: float = DEFAULT_DEADLINE
    map: bool = False
    join_timeout: float = DEFAULT_JOIN_TIMEOUT
    cwd: str | None = None  # the spec file's folder: relative paths in the command are relative to it

    def to_dict(self) -> dict[str, Any]:
        return dataclasses.asdict(self)

    def argv(self) -> list[str]:
        """As `rei run` options (run in ``cwd``)."""
        return ["--sut", self.command, "--sut-clock", self.clock, "--sut-deadline", str(self.deadline),
                "--sut-join-timeout", str(self.join_timeout), *(["--sut-map"] if self.map else [])]


@dataclass(frozen=True, slots=True)
class Variant:
    name: str
    humans: bool = True
    fault: str | None = None
    controller: str = "nav"
    sut: ExternalSut | None = None
    #: the behaviour towards the robot of every person who sees it (avoids, ignores, curious, scared, blocks; mixed
    #: in generated rooms): the same rooms and cases, their people behaving so (rei.campaign.plan); None: as written
    behaviour: str | None = None


@dataclass(frozen=True, slots=True)
class RoomSettings:
    """``rei gen-rooms`` settings of a group: a room class (``size``), or an occupancy map to furnish (``map``,
    with ``floor_size`` and ``unknown_free``: ``rei gen-rooms --map``)."""

    size: str | None
    density: str | None = None
    humans: int | None = None
    count: int = 1
    seed: int = 0
    types: RoomTypes = DEFAULT_TYPES  # a user catalogue's furniture and robot (``catalogue``, ``robot``)
    map: Path | None = None
    floor_size: float = 1.0
    unknown_free: bool = False
    #: the humans are people who see the robot with this behaviour (or mixed: ``people: reactive``, ``behaviour``);
    #: None: humans on lanes
    reactive: str | None = None

    def generate(self, count: int | None = None) -> list[Room]:
        """The first ``count`` rooms of these settings (default: ``count`` of the settings)."""
        from rei.rooms import generate_map_rooms, generate_rooms, load_site

        count = self.count if count is None else count
        if self.map is None:
            return generate_rooms(str(self.size), self.density, self.humans, self.seed, count, self.types,
                                  self.reactive)
        site = load_site(self.map, self.floor_size, self.unknown_free)
        return generate_map_rooms(site, self.density, self.humans, self.seed, count, self.types,
                                  reactive=self.reactive)


@dataclass(frozen=True, slots=True)
class Group:
    name: str
    cases: tuple[Path, ...]
    rooms: RoomSettings | None
    variants: tuple[Variant, ...]
    repetitions: int


@dataclass(frozen=True, slots=True)
class Spec:
    name: str
    seed: int
    timeout: float
    mode: str
    report: bool
    groups: tuple[Group, ...]
    source: Path | None = None
    #: the user's VEPL patterns (``rei run --patterns``) and utility file (``--utilities``) of every run, absolute
    patterns: Path | None = None
    utilities: Path | None = None


def load_spec(path: Path) -> Spec:
    try:
        text = path.read_text(encoding="utf-8")
        data = yaml.safe_load(text)
    except OSError as error:
        raise SpecError(f"{path}: cannot read: {error.strerror or error}") from None
    except yaml.YAMLError as error:
        raise SpecError(f"{path}: not YAML: {error}") from None
    spec = parse_spec(data, base=path.resolve().parent, where=str(path), default_name=path.stem,
                      node=located_yaml.compose(text))
    return dataclasses.replace(spec, source=path)


def parse_spec(data: Any, *, base: Path, where: str = "spec", default_name: str = "campaign",
               node: yaml.Node | None = None) -> Spec:
    """A checked ``Spec`` from parsed YAML; relative case paths are resolved against ``base``. ``node``: the same
    document composed (rei.located_yaml), so that a mistake can be placed at its line and column. Every mistake
    is reported at once (a ``SpecError`` of them all, in the order of the file); a check that depends on a failed
    one is skipped."""
    top = _Reader(data, where, node)
    problems = located_yaml.Collector()
    problems.add(*_given_twice(node, where))
    with problems.check():
        top.only("name", "seed", "repetitions", "timeout", "mode", "controller", "sut", "report", "variants",
                 "groups", "patterns", "utilities")
    name = problems.read(lambda: top.str("name", default_name), default_name)
    seed = problems.read(lambda: top.int("seed", 0, minimum=0), 0)
    repetitions = problems.read(lambda: top.int("repetitions", 1, minimum=1), 1)
    timeout = problems.read(lambda: top.number("timeout", 600.0), 600.0)
    mode = problems.read(lambda: top.choice("mode", MODES, "replay"), "replay")
    controller = problems.read(lambda: anchored(top.controller("controller", "nav", base), base), "nav")
    report = problems.read(lambda: top.bool("report", False), False)
    if top.get("controller") is not None and top.get("sut") is not None:
        problems.add(f"{top.key_at('sut')}: give either 'controller' (in-process) or 'sut' (external), not both")
    sut = problems.read(lambda: _sut(top, base), None)
    default = (Variant("base", controller=controller, sut=sut),)
    variants = problems.read(lambda: _variants(top, "variants", controller, default, base, sut), default)
    groups_raw = top.get("groups")
    groups = []
    if not isinstance(groups_raw, list) or not groups_raw:
        problems.add(f"{top.at('groups')}: 'groups' must be a non-empty list")
    else:
        for i, raw in enumerate(groups_raw):
            with problems.check():
                group = _Reader(raw, f"{where}: groups[{i}]", _item(top.node_of("groups"), i), where)
                groups.append(_group(group, base, controller, sut, variants, repetitions))
    names = [g.name for g in groups]
    duplicate = next((n for n in names if names.count(n) > 1), None)
    if duplicate:
        problems.add(f"{top.at('groups')}: two groups are named {duplicate!r}")
    paths = located_yaml.Collector()
    patterns = paths.read(lambda: _path(top, "patterns", base, "a folder of .vepl files"), None)
    utilities = paths.read(lambda: _path(top, "utilities", base, "a YAML file 'SIGNAL: utility'"), None)
    if not paths:  # the patterns' check needs both paths
        try:
            check_user_patterns(patterns, utilities)
        except SpecError as error:
            key = "patterns" if error.args[1:] == ("patterns",) else "utilities"
            paths.add(*(f"{top.at(key)}: {line}" for line in str(error.args[0]).splitlines()))  # a mistake each
    problems.add(*paths.problems)
    problems.raise_if_any(SpecError)
    return Spec(name, seed, timeout, mode, report, tuple(groups), patterns=patterns, utilities=utilities)


def _given_twice(node: yaml.Node | None, file: str) -> list[str]:
    """Every key given twice in a mapping under ``node``, at its second place: YAML keeps the last silently (a
    pasted ``seed: 2`` below ``seed: 1`` ran seed 2), and the other mistakes would be placed at the first."""
    problems: list[str] = []
    if isinstance(node, yaml.MappingNode):
        seen: set[str] = set()
        for key, value in node.value:
            name = str(located_yaml.scalar(key))
            if name in seen:
                line, column = located_yaml.position(key)
                problems.append(f"{file}:{line}:{column}: '{name}' is given twice")
            seen.add(name)
            problems += _given_twice(value, file)
    elif isinstance(node, yaml.SequenceNode):
        for item in node.value:
            problems += _given_twice(item, file)
    return problems


def anchored(controller: str, base: Path) -> str:
    """``controller`` with a ``script:FILE`` made absolute against ``base`` (the spec's folder, as its cases,
    patterns and SUT command are): the runs build it in their own folders, where a relative file is not found."""
    name, sep, file = controller.partition(":")
    if name != "script" or not sep or not file or Path(file).is_absolute():
        return controller
    return f"script:{(base / file).resolve()}"


def _path(r: _Reader, key: str, base: Path, what: str) -> Path | None:
    value = r.get(key)
    if value is None:
        return None
    if not isinstance(value, str) or not value:
        raise SpecError(f"{r.at(key)}: '{key}' names {what}, relative to the spec file")
    return (base / value).resolve()


def check_user_patterns(patterns: Path | None, utilities: Path | None) -> frozenset[str]:
    """Check a spec's ``patterns:`` folder and ``utilities:`` file as `rei run` checks ``--patterns`` and
    ``--utilities`` (the monitor jar compiles the patterns; the file is read against what they declare); returns
    the signals the patterns declare (empty without them). SpecError with the compiler's ``file:line:column``
    lines; its second argument names the key at fault (``patterns`` or ``utilities``)."""
    from rei.evaluation import UtilityError, load_utilities
    from rei.run.patterns import PatternError

    declared = None
    if patterns is not None:
        try:
            declared = dict(_compiled(patterns, _stamp(patterns)))
        except PatternError as error:
            raise SpecError(str(error), "patterns") from None
    if utilities is not None:
        try:
            load_utilities(utilities, declared)  # it may name the signals of the user's patterns
        except UtilityError as error:
            raise SpecError(str(error), "utilities") from None
    return frozenset(declared or ())


def _stamp(folder: Path) -> tuple[tuple[str, int, int], ...]:
    """What the monitor reads of ``folder`` (its *.vepl), by name, size and change time: the cache key of
    ``_compiled``, so a spec read twice (a search's resume check parses OUT/spec.yaml too) compiles once."""
    try:
        return tuple(sorted((p.name, p.stat().st_size, p.stat().st_mtime_ns) for p in folder.glob("*.vepl")))
    except OSError:
        return ()


@functools.lru_cache(maxsize=8)
def _compiled(folder: Path, stamp: tuple[tuple[str, int, int], ...]) -> tuple[tuple[str, float | None], ...]:
    """What ``folder``'s patterns declare beside the defaults' (rei.run.patterns.check: a JVM start and the VEPL
    compiler, 1-3 s)."""
    from rei.run.patterns import PatternSelection, check

    del stamp  # only the cache key
    return tuple(check(PatternSelection(folder)).items())


def _group(r: _Reader, base: Path, controller: str, sut: ExternalSut | None, variants: tuple[Variant, ...],
           repetitions: int) -> Group:
    problems = located_yaml.Collector()
    with problems.check():
        r.only("name", "cases", "rooms", "variants", "repetitions")
    name = problems.read(lambda: r.name("name", None), "")
    cases_raw, rooms_raw = r.get("cases"), r.get("rooms")
    cases: tuple[Path, ...] = ()
    rooms = None
    if (cases_raw is None) == (rooms_raw is None):
        problems.add(f"{r.here()}: give exactly one of 'cases' (test case files) and 'rooms' (generator settings)")
    elif cases_raw is not None:
        cases = problems.read(lambda: _cases(r, cases_raw, base), ())
    else:
        rooms = problems.read(lambda: _rooms(_Reader(rooms_raw, f"{r.where}: rooms", r.node_of("rooms"), r.file),
                                             base), None)
    own = problems.read(lambda: _variants(r, "variants", controller, variants, base, sut), variants)
    repeated = problems.read(lambda: r.int("repetitions", repetitions, minimum=1), repetitions)
    if not problems:
        with problems.check():
            _check_behaviours(r, own, cases, rooms)
    problems.raise_if_any(SpecError)
    return Group(name, cases, rooms, own, repeated)


def _cases(r: _Reader, raw: Any, base: Path) -> tuple[Path, ...]:
    """A group's ``cases``: .rei files or generated case folders, relative to ``base``, each a name of its own."""
    if not isinstance(raw, list) or not raw:
        raise SpecError(f"{r.at('cases')}: 'cases' must be a non-empty list of paths")
    problems = located_yaml.Collector()
    for i, case in enumerate(raw):  # at the item (a number, a mapping), not the list
        if not isinstance(case, str) or not case:
            problems.add(f"{r.item_at('cases', i)}: a case is a path to a .rei file or a generated case folder, "
                         f"got {case!r}")
    problems.raise_if_any(SpecError)
    cases = tuple((base / c).resolve() for c in raw)
    for i, case in enumerate(cases):
        if not (case.is_file() and case.suffix == ".rei") and not (case / "world.json").is_file():
            problems.add(f"{r.item_at('cases', i)}: {case} is neither a .rei file nor a generated case folder")
    stems = [_case_stem(c) for c in cases]
    if len(set(stems)) != len(stems):
        problems.add(f"{r.at('cases')}: two cases have the same name; give each file its own name")
    problems.raise_if_any(SpecError)
    return cases


def _rooms(r: _Reader, base: Path) -> RoomSettings:
    """A group's ``rooms`` settings, checked by generating their first room; a mistake the generator finds is
    placed at the setting its message names (else at the mapping)."""
    from rei.maps import MapError
    from rei.rooms import BEHAVIOURS, MIXED, GenerationError
    from rei.rooms.catalogue import room_types

    problems = located_yaml.Collector()
    with problems.check():
        r.only("size", "map", "floor_size", "unknown_free", "density", "humans", "people", "behaviour", "count", "seed",
               "catalogue", "robot")
    catalogue, robot = r.get("catalogue"), r.get("robot")
    if robot is not None and catalogue is None:
        problems.add(f"{r.key_at('robot')}: 'robot' picks a robot type of 'catalogue': give the catalogue too")
    on_map = r.get("map") is not None
    size, map_file = None, None
    if (r.get("size") is None) == on_map:  # exactly one of them
        size = problems.read(lambda: None if on_map else r.str("size", None), None)
        map_file = problems.read(lambda: (base / r.str("map", None)).resolve() if on_map else None, None)
    else:
        problems.add(f"{r.here()}: give exactly one of 'size' (a room class) and 'map' (an occupancy map's YAML "
                     "file to furnish)")
    if not on_map and (r.get("floor_size") is not None or r.get("unknown_free") is not None):
        problems.add(f"{r.here()}: 'floor_size' and 'unknown_free' describe the floors of 'map': give the map too")
    # density and humans are checked here, not only by the generator: it stops at its first mistake and takes
    # a bool for a count (humans: true was one human) or names a Python comparison for a word
    density = problems.read(lambda: _density(r), None)
    humans = problems.read(lambda: _humans(r, size), None)
    count = problems.read(lambda: r.int("count", 1, minimum=1), 1)
    seed = problems.read(lambda: r.int("seed", 0, minimum=0), 0)
    floor_size = problems.read(lambda: r.number("floor_size", 1.0), 1.0)
    unknown_free = problems.read(lambda: r.bool("unknown_free", False), False)
    people = problems.read(lambda: r.choice("people", ("rails", "reactive"), "rails"), "rails")
    behaviour = problems.read(lambda: r.choice("behaviour", (*BEHAVIOURS, MIXED), "avoids"), "avoids")
    if r.get("behaviour") is not None and people != "reactive":
        problems.add(f"{r.key_at('behaviour')}: 'behaviour' is the behaviour of people who see the robot: give "
                     "'people: reactive' too")
    problems.raise_if_any(SpecError)  # the generator's check needs every setting
    try:
        types = DEFAULT_TYPES if catalogue is None else room_types((base / str(catalogue)).resolve(),
                                                                    None if robot is None else str(robot))
        settings = RoomSettings(size=size, density=density, humans=humans, count=count, seed=seed,
                                types=types, map=map_file, floor_size=floor_size, unknown_free=unknown_free,
                                reactive=behaviour if people == "reactive" else None)
        settings.generate(1)  # checks them
    except (ValueError, TypeError, GenerationError, MapError) as error:
        raise SpecError(f"{r.named_in(str(error))}: {error}") from None
    return settings


def _density(r: _Reader) -> str | None:
    from rei.rooms import DENSITIES

    if r.get("density") is None:
        return None
    density: str = r.str("density", None)
    if density not in DENSITIES:
        raise SpecError(f"{r.at('density')}: density must be one of {', '.join(DENSITIES)}, got {density!r}")
    return density


def _humans(r: _Reader, size: str | None) -> int | None:
    """``humans``: a whole number from 0, at most what a room of ``size`` holds (a map room: any)."""
    from rei.rooms import MAX_HUMANS

    if r.get("humans") is None:
        return None
    humans = r.int("humans", 0, minimum=0)
    if size in MAX_HUMANS and humans > MAX_HUMANS[size]:
        raise SpecError(f"{r.at('humans')}: a {size} room holds 0 to {MAX_HUMANS[size]} humans, got {humans}")
    return humans


def _sut(r: _Reader, base: Path) -> ExternalSut | None:
    """The ``sut:`` mapping of a spec or variant, checked as `rei run --sut` checks its options."""
    from rei.sut.external.options import SutOptions
    from rei.sut.external.process import SutLaunchError, check_command

    if r.get("sut") is None:
        return None
    s = _Reader(r.get("sut"), f"{r.where}: sut", r.node_of("sut"), r.file)
    problems = located_yaml.Collector()
    with problems.check():
        s.only("command", "clock", "deadline", "map", "join_timeout")
    command = problems.read(lambda: s.str("command", None), "")
    clock = problems.read(lambda: s.choice("clock", ("lockstep", "realtime"), "lockstep"), "lockstep")
    deadline = problems.read(lambda: s.number("deadline", DEFAULT_DEADLINE), DEFAULT_DEADLINE)
    on_map = problems.read(lambda: s.bool("map", False), False)
    join_timeout = problems.read(lambda: s.number("join_timeout", DEFAULT_JOIN_TIMEOUT), DEFAULT_JOIN_TIMEOUT)
    problems.raise_if_any(SpecError)
    sut = ExternalSut(command=command, clock=clock, deadline=deadline, map=on_map, join_timeout=join_timeout,
                      cwd=str(base))
    try:
        SutOptions(command=sut.command, clock=sut.clock, deadline=sut.deadline)  # type: ignore[arg-type]
        check_command(sut.command, base)
    except (ValueError, SutLaunchError) as error:
        raise SpecError(f"{s.at('command')}: {error}") from None
    return sut


def _variants(r: _Reader, key: str, controller: str, default: tuple[Variant, ...], base: Path,
              sut: ExternalSut | None = None) -> tuple[Variant, ...]:
    raw = r.get(key)
    if raw is None:
        return default
    if not isinstance(raw, list) or not raw:
        raise SpecError(f"{r.at(key)}: '{key}' must be a non-empty list")
    problems = located_yaml.Collector()
    variants = []
    for i, item in enumerate(raw):
        with problems.check():
            v = _Reader(item, f"{r.where}: {key}[{i}]", _item(r.node_of(key), i), r.file)
            variants.append(_variant(v, controller, base, sut))
    names = [x.name for x in variants]
    if len(set(names)) != len(names):
        problems.add(f"{r.at(key)}: two variants have the same name")
    problems.raise_if_any(SpecError)
    return tuple(variants)


def _variant(v: _Reader, controller: str, base: Path, sut: ExternalSut | None) -> Variant:
    from rei.sim.faults import parse_faults

    problems = located_yaml.Collector()
    with problems.check():
        v.only("name", "humans", "fault", "controller", "sut", "behaviour")
    name = problems.read(lambda: v.name("name", None), "")
    humans = problems.read(lambda: v.bool("humans", True), True)
    fault = v.get("fault")
    if fault is not None and not isinstance(fault, str):
        problems.add(f"{v.at('fault')}: 'fault' must be text such as \"laser:1%\"")
    elif fault is not None:
        try:
            parse_faults(fault)
        except ValueError as error:
            problems.add(f"{v.at('fault')}: fault: {error}")
    spec = problems.read(lambda: anchored(v.controller("controller", controller, base), base), controller)
    behaviour = problems.read(lambda: _behaviour(v), None)
    if behaviour is not None and humans is False:  # its runs have no people to behave so: a mistake, not a no-op
        problems.add(f"{v.at('behaviour')}: 'behaviour' sets how the people behave and 'humans: false' leaves them "
                     f"out of the runs; remove one of the two")
    own_sut = problems.read(lambda: _sut(v, base), None)
    if v.get("sut") is not None and v.get("controller") is not None:
        problems.add(f"{v.key_at('sut')}: give either 'controller' (in-process) or 'sut' (external), not both")
    problems.raise_if_any(SpecError)
    variant_sut = own_sut if own_sut is not None else (None if v.get("controller") is not None else sut)
    return Variant(name, humans, fault, spec, variant_sut, behaviour)


def _behaviour(v: _Reader) -> str | None:
    from rei.rooms import BEHAVIOURS, MIXED

    if v.get("behaviour") is None:
        return None
    behaviour: str = v.choice("behaviour", (*BEHAVIOURS, MIXED), None)
    return behaviour


def _check_behaviours(r: _Reader, variants: tuple[Variant, ...], cases: tuple[Path, ...],
                      rooms: RoomSettings | None) -> None:
    """A variant that sets the people's behaviour needs people who see the robot in every case of the group: rooms
    generated with ``people: reactive``, or .rei files with a person on a route, a crowd or a group (``mixed`` is
    drawn per person by the room generator: generated rooms only). Placed at the group's rooms or cases."""
    from rei.edit.gatherings import gatherings

    varied = [v for v in variants if v.behaviour is not None]
    if not varied:
        return
    first = varied[0]
    what = f"variant {first.name!r} sets the people's behaviour ({first.behaviour})"
    problems = located_yaml.Collector()
    if rooms is not None:
        if rooms.reactive is None:
            problems.add(f"{r.at('rooms')}: {what}: these rooms' humans walk lanes; give 'people: reactive'")
        problems.raise_if_any(SpecError)
        return
    mixed = next((v for v in varied if v.behaviour == "mixed"), None)
    if mixed is not None:
        problems.add(f"{r.at('cases')}: variant {mixed.name!r}: 'mixed' draws each person's behaviour in generated "
                     f"rooms ('rooms' with 'people: reactive'); for test cases give one behaviour")
    for i, case in enumerate(cases):
        if case.suffix != ".rei":
            problems.add(f"{r.item_at('cases', i)}: {what}: {case.name} is a generated folder; give its .rei file")
            continue
        try:
            text = case.read_text(encoding="utf-8")
        except OSError as error:
            problems.add(f"{r.item_at('cases', i)}: cannot read {case}: {error.strerror or error}")
            continue
        if not gatherings(text, routes=True):
            problems.add(f"{r.item_at('cases', i)}: {what}: {case.name} has no person who sees the robot (a human "
                         f"on a route, a crowd or a group)")
    problems.raise_if_any(SpecError)


def _case_stem(case: Path) -> str:
    return case.stem if case.suffix == ".rei" else case.name


def _item(node: yaml.Node | None, index: int) -> yaml.Node | None:
    """Item ``index`` of a composed list (None when there is no node or it is no list that long)."""
    if isinstance(node, yaml.SequenceNode) and index < len(node.value):
        item: yaml.Node = node.value[index]
        return item
    return None


class _Reader:
    """Typed access to one mapping of the spec, every error prefixed with where it is: its key path after ``file``
    (the spec file), and the line and column where the mapping's composed ``node`` is known (of the value a
    message is about, of an unknown key, or of the mapping itself)."""

    def __init__(self, data: Any, where: str, node: yaml.Node | None = None, file: str | None = None) -> None:
        self.where, self.file = where, where if file is None else file
        if not isinstance(data, Mapping):
            raise SpecError(f"{self._placed(node)}: expected a mapping, got {type(data).__name__}")
        self.data = data
        self.node = node if isinstance(node, yaml.MappingNode) else None

    def _placed(self, node: yaml.Node | None) -> str:
        """``FILE:LINE:COLUMN: key path`` of ``node`` (without a node: the key path after the file)."""
        if node is None:
            return self.where
        line, column = located_yaml.position(node)
        path = self.where[len(self.file):].lstrip(": ") if self.where.startswith(self.file) else self.where
        return f"{self.file}:{line}:{column}" + (f": {path}" if path else "")

    def _entry(self, key: str) -> tuple[yaml.Node, yaml.Node] | None:
        for key_node, value_node in self.node.value if self.node is not None else ():
            if isinstance(key_node, yaml.ScalarNode) and key_node.value == key:
                return key_node, value_node
        return None

    def node_of(self, key: str) -> yaml.Node | None:
        """The composed value of ``key`` (None without a node)."""
        entry = self._entry(key)
        return None if entry is None else entry[1]

    def here(self) -> str:
        """Where the mapping is (for a mistake of the mapping as a whole, such as a key it lacks)."""
        return self._placed(self.node)

    def at(self, key: str) -> str:
        """Where the value of ``key`` is (the mapping, when it does not have the key)."""
        node = self.node_of(key)
        return self._placed(node) if node is not None else self.here()

    def key_at(self, key: str) -> str:
        """Where ``key`` itself is written (the mapping, when it does not have the key)."""
        entry = self._entry(key)
        return self._placed(entry[0]) if entry is not None else self.here()

    def item_at(self, key: str, index: int) -> str:
        """Where item ``index`` of the list at ``key`` is (the list, without it)."""
        item = _item(self.node_of(key), index)
        return self._placed(item) if item is not None else self.at(key)

    def named_in(self, message: str) -> str:
        """Where the value of the key that ``message`` names first is (the mapping, when it names none)."""
        named = [(match.start(), str(key)) for key in self.data
                 if (match := re.search(rf"\b{re.escape(str(key))}\b", message))]
        return self.at(min(named)[1]) if named else self.here()

    def controller(self, key: str, default: str, base: Path) -> str:
        """An in-process controller (``nav``, ``nav:max_linear=0.2``, ...) checked as `--controller` is: the run
        would build the same, so a mistyped ``nav:`` parameter is refused here, with the known ones; a
        ``script:FILE`` relative to ``base``."""
        from rei.sut.registry import controller_problem

        value = self.str(key, default)
        problem = None if key not in self.data else controller_problem(anchored(value, base))
        if problem is not None:
            raise SpecError(f"{self.at(key)}: {problem}")
        return value

    def only(self, *keys: str) -> None:
        """Each key the mapping has that is not one of ``keys`` is a mistake, at the key."""
        unknown = [key for key in map(str, self.data) if key not in keys]
        if unknown:
            raise SpecError.of(f"{self.key_at(key)}: unknown key {key!r}; known: {', '.join(keys)}"
                               for key in unknown)

    def get(self, key: str) -> Any:
        return self.data.get(key)

    def _typed(self, key: str, default: Any, kinds: tuple[type, ...], what: str) -> Any:
        value = self.data.get(key, default)
        if value is None and default is None:
            raise SpecError(f"{self.here()}: '{key}' is required")
        if isinstance(value, bool) and bool not in kinds or not isinstance(value, kinds):
            raise SpecError(f"{self.at(key)}: '{key}' must be {what}, got {value!r}")
        return value

    def str(self, key: str, default: str | None) -> str:
        return self._typed(key, default, (str,), "text")

    def name(self, key: str, default: str | None) -> str:
        value = self.str(key, default)
        if not _NAME.fullmatch(value):
            raise SpecError(f"{self.at(key)}: '{key}' {value!r}: use letters, digits, '_' and '-' (it names folders)")
        return value

    def bool(self, key: str, default: bool) -> bool:
        return self._typed(key, default, (bool,), "true or false")

    def int(self, key: str, default: int, minimum: int) -> int:
        value = self._typed(key, default, (int,), "an integer")
        if value < minimum:
            raise SpecError(f"{self.at(key)}: '{key}' must be >= {minimum}, got {value}")
        return value

    def number(self, key: str, default: float) -> float:
        value = self._typed(key, default, (int, float), "a number")
        if not value > 0:
            raise SpecError(f"{self.at(key)}: '{key}' must be positive, got {value}")
        return float(value)

    def choice(self, key: str, choices: tuple[str, ...], default: str) -> str:
        value = self.str(key, default)
        if value not in choices:
            raise SpecError(f"{self.at(key)}: '{key}' must be one of {', '.join(choices)}, got {value!r}")
        return value


def moves_people(cases: tuple[Path, ...], rooms: RoomSettings | None) -> bool:
    """Whether some of these cases (or the rooms generated) have people who see the robot (a human on a route, a
    crowd, a group; rooms with ``people: reactive`` and humans), whom JuPedSim's people server moves: their runs'
    nodes need it (rei.campaign.nodes). A generated case folder says so in its ``animation.json``."""
    import json

    from rei.edit.gatherings import gatherings

    if rooms is not None and rooms.reactive is not None and (rooms.humans or 0) > 0:
        return True
    for case in cases:
        try:
            if case.suffix == ".rei":
                if gatherings(case.read_text(encoding="utf-8"), routes=True):
                    return True
            elif json.loads((case / "animation.json").read_text(encoding="utf-8")).get("people"):
                return True
        except (OSError, ValueError):  # unreadable: its own error comes with its runs
            continue
    return False


def spec_moves_people(spec: Spec) -> bool:
    """``moves_people`` for a campaign: some group has people who see the robot and a variant with humans."""
    return any(any(v.humans for v in group.variants) and moves_people(group.cases, group.rooms)
               for group in spec.groups)
