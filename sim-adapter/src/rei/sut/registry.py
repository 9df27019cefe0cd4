# SPDX-License-Identifier: EPL-2.0
"""Controller lookup by name: ``nav``, ``script:FILE`` and third-party plug-ins.

A controller spec is ``name`` or ``name:argument``; the factory registered under ``name`` gets the argument text
(empty when there is none). Third-party controllers register a factory ``(arg: str) -> Controller`` under the
entry-point group ``rei.controllers`` in their own package, e.g. in its ``pyproject.toml``::

    [project.entry-points."rei.controllers"]
    mynav = "mypackage.controller:make"

Built-in names win over plug-ins of the same name, so a plug-in cannot silently replace the reference stack.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from importlib import metadata

from rei.sut.api import Controller

Factory = Callable[[str], Controller]
ENTRY_POINT_GROUP = "rei.controllers"


class UnknownControllerError(LookupError):
    """No controller of that name; the message lists the available ones."""


def _nav(arg: str) -> Controller:
    from rei.sut.nav import NavConfig, NavController

    config = NavConfig.parse(arg)
    # the robot's own footprint (the case's) unless the argument sets one: a Burger is not planned as a Waffle
    given = {part.partition("=")[0].strip() for part in arg.split(",")} & {"footprint_x", "footprint_y"}
    footprint = (config.footprint_x, config.footprint_y) if given else None
    return NavController(config.max_linear, config.max_angular, footprint, config)


def _script(arg: str) -> Controller:
    from rei.sut.script import ScriptController, ScriptError

    if not arg:
        raise ScriptError("script: needs a file, as in script:path/to/commands.txt")
    return ScriptController.from_file(arg)


BUILTINS: Mapping[str, Factory] = {"nav": _nav, "script": _script}


class ControllerRegistry:
    """Built-in factories plus those found in the ``rei.controllers`` entry points (loaded lazily)."""

    def __init__(self, entry_points: Iterable[metadata.EntryPoint] | None = None) -> None:
        if entry_points is None:
            entry_points = metadata.entry_points(group=ENTRY_POINT_GROUP)
        self._plugins = {ep.name: ep for ep in entry_points if ep.name not in BUILTINS}

    def names(self) -> list[str]:
        return sorted(BUILTINS) + sorted(self._plugins)

    def create(self, spec: str) -> Controller:
        """The controller for ``name`` or ``name:argument``."""
        name, _, arg = spec.partition(":")
        name = name.strip()
        if name in BUILTINS:
            factory = BUILTINS[name]
        elif name in self._plugins:
            entry = self._plugins[name]
            try:
                factory = entry.load()
            except Exception as exc:  # a broken plug-in must not look like a missing one
                raise UnknownControllerError(
                    f"controller {name!r}: cannot load entry point {entry.value!r}: {exc}"
                ) from exc
        else:
            raise UnknownControllerError(
                f"unknown controller {name!r}; available: {', '.join(self.names())} "
                f"(plug-ins register under the entry-point group {ENTRY_POINT_GROUP!r})"
            )
        controller = factory(arg)
        if not isinstance(controller, Controller):
            raise TypeError(f"controller {name!r}: factory returned {type(controller).__name__}, not a Controller")
        return controller


def create_controller(spec: str) -> Controller:
    """Shortcut for ``ControllerRegistry().create(spec)``."""
    return ControllerRegistry().create(spec)


def controller_problem(spec: str) -> str | None:
    """Why ``spec`` names no controller that can be built (an unknown name, a ``nav:`` parameter mistyped or out of
    range with the known ones listed, a missing script), or None: the check `rei campaign --controller` and the
    campaign and search specs make before any run, rather than each run failing on its own."""
    try:
        create_controller(spec)
    except (UnknownControllerError, ValueError) as error:
        return str(error)
    return None


def available_controllers() -> list[str]:
    return ControllerRegistry().names()
