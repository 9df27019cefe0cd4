# SPDX-License-Identifier: EPL-2.0
"""Controller lookup: built-ins, entry-point plug-ins and the error for an unknown name."""

from __future__ import annotations

from importlib import metadata

import pytest

from rei.sut.api import NavStatus
from rei.sut.nav import NavController
from rei.sut.registry import ENTRY_POINT_GROUP, ControllerRegistry, UnknownControllerError
from rei.sut.script import ScriptController, ScriptError

# A plug-in factory, found through a real EntryPoint object pointing at this module.
made: list[str] = []


def make_plugin(arg: str) -> ScriptController:
    made.append(arg)
    from rei.sut.script import Segment

    return ScriptController([Segment(1.0, 0.0, 0.1)])


def not_a_controller(arg: str) -> object:
    return object()


def entry(name: str, attr: str) -> metadata.EntryPoint:
    return metadata.EntryPoint(name=name, value=f"{__name__}:{attr}", group=ENTRY_POINT_GROUP)


def test_builtin_nav_with_parameters():
    nav = ControllerRegistry([]).create("nav:max_linear=0.2,no_progress_timeout=12")
    assert isinstance(nav, NavController)
    assert nav.config.max_linear == 0.2 and nav.config.no_progress_timeout == 12.0
    assert nav.status is NavStatus.IDLE
    assert ControllerRegistry([]).create("nav").config.max_linear == 0.26


def test_builtin_script_reads_its_file(tmp_path):
    path = tmp_path / "square.txt"
    path.write_text("1.0 0.2 0.0\n")
    script = ControllerRegistry([]).create(f"script:{path}")
    assert isinstance(script, ScriptController) and script.duration == 1.0
    with pytest.raises(ScriptError, match="needs a file"):
        ControllerRegistry([]).create("script")


def test_plugins_from_entry_points():
    registry = ControllerRegistry([entry("mine", "make_plugin"), entry("broken", "not_a_controller")])
    assert registry.names() == ["nav", "script", "broken", "mine"]
    made.clear()
    assert isinstance(registry.create("mine:fast=1"), ScriptController)
    assert made == ["fast=1"]
    with pytest.raises(TypeError, match="'broken': factory returned object"):
        registry.create("broken")


def test_builtins_win_over_plugins_of_the_same_name():
    registry = ControllerRegistry([entry("nav", "make_plugin")])
    assert isinstance(registry.create("nav"), NavController)


def test_unknown_name_lists_the_available_ones():
    registry = ControllerRegistry([entry("mine", "make_plugin")])
    with pytest.raises(UnknownControllerError) as info:
        registry.create("turtle:fast")
    message = str(info.value)
    assert "'turtle'" in message and "nav, script, mine" in message and ENTRY_POINT_GROUP in message


def test_unloadable_plugin_is_reported():
    registry = ControllerRegistry([metadata.EntryPoint("ghost", "no_such_module_xyz:make", ENTRY_POINT_GROUP)])
    with pytest.raises(UnknownControllerError, match="cannot load entry point 'no_such_module_xyz:make'"):
        registry.create("ghost")


def test_default_registry_reads_the_installed_entry_points():
    assert ControllerRegistry().names()[:2] == ["nav", "script"]
