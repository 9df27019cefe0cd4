# SPDX-License-Identifier: EPL-2.0
"""The `rei` console script: parsing, delegation to the Java CLI, exit codes, errors without tracebacks."""

from __future__ import annotations

import argparse
import importlib
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import pytest

from rei import __version__
from rei.cli import COMMANDS, build_parser, main
from rei.cli.errors import EXIT_TOOLCHAIN, CommandError
from rei.toolchain import JARS

MakeJdk = Callable[..., Path]
LastArgs = Callable[[Path], list[str]]


@pytest.fixture
def fake_java_env(make_jdk: MakeJdk, fake_checkout: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """Point the CLI at a fake JDK and a fake checkout; returns the JDK home (for `last_args`)."""
    home = make_jdk()
    monkeypatch.setenv("JAVA_HOME", str(home))
    monkeypatch.setenv("REI_HOME", str(fake_checkout))
    return home


def test_every_registered_command_adds_a_parser_with_a_handler() -> None:
    parser = build_parser()
    subparsers = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    # modules are Python names; a command is its module's name with dashes (gen_rooms -> gen-rooms), a Python
    # keyword with a trailing underscore (import_ -> import)
    assert list(subparsers.choices) == [name.rstrip("_").replace("_", "-") for name in COMMANDS]
    for name in COMMANDS:
        module = importlib.import_module(f"rei.cli.{name}")
        assert module.__doc__, f"rei.cli.{name} needs a docstring"
        assert callable(subparsers.choices[name.rstrip("_").replace("_", "-")].get_default("handler"))


def test_version(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as exit_info:
        main(["--version"])
    assert exit_info.value.code == 0
    assert capsys.readouterr().out.strip() == f"rei {__version__}"


@pytest.mark.parametrize("argv", [[], ["validate"], ["generate", "a.rei"], ["frobnicate"]])
def test_usage_errors_exit_2(argv: list[str], capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as exit_info:
        main(argv)
    assert exit_info.value.code == 2
    assert "usage: rei" in capsys.readouterr().err


@pytest.mark.parametrize("code", [0, 1, 2])
def test_validate_passes_files_and_exit_code_through(
    last_args: LastArgs, fake_java_env: Path, fake_checkout: Path, monkeypatch: pytest.MonkeyPatch, code: int
) -> None:
    monkeypatch.setenv("FAKE_JAVA_EXIT", str(code))
    assert main(["validate", "a.rei", "dir/b.rei"]) == code
    assert last_args(fake_java_env) == [
        "-jar",
        str(fake_checkout / JARS["cli"]),
        "validate",
        "a.rei",
        "dir/b.rei",
    ]


def test_generate_passes_output_templates_and_quiet(
    last_args: LastArgs, fake_java_env: Path, fake_checkout: Path
) -> None:
    assert main(["generate", "case.rei", "-o", "out dir", "--templates", "tpl", "--quiet"]) == 0
    assert last_args(fake_java_env)[2:] == [
        "generate",
        "case.rei",
        "-o",
        "out dir",
        "--templates",
        "tpl",
        "--quiet",
    ]


def test_generate_without_options_passes_only_file_and_output(
    last_args: LastArgs, fake_java_env: Path
) -> None:
    assert main(["generate", "case.rei", "--output", "out"]) == 0
    assert last_args(fake_java_env)[2:] == ["generate", "case.rei", "-o", "out"]


def test_missing_jar_is_one_line_without_traceback(
    fake_java_env: Path, fake_checkout: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (fake_checkout / JARS["cli"]).unlink()
    assert main(["validate", "a.rei"]) == EXIT_TOOLCHAIN
    err = capsys.readouterr().err
    assert err.startswith("rei: error: ") and "run ./rei once to build the Java parts" in err
    assert "Traceback" not in err and err.count("\n") == 1


def test_old_java_is_reported_before_the_jar(
    make_jdk: MakeJdk,
    fake_checkout: Path,
    monkeypatch: pytest.MonkeyPatch,
    capsys: pytest.CaptureFixture[str],
) -> None:
    monkeypatch.setenv("JAVA_HOME", str(make_jdk("11.0.2", name="jdk11")))
    monkeypatch.setenv("REI_HOME", str(fake_checkout))
    (fake_checkout / JARS["cli"]).unlink()
    assert main(["generate", "a.rei", "-o", "out"]) == EXIT_TOOLCHAIN
    assert "is Java 11; REI needs Java 17 or newer" in capsys.readouterr().err


def test_command_error_carries_its_exit_code(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    def fail(_: argparse.Namespace) -> int:
        raise CommandError("no such run", exit_code=1)

    monkeypatch.setattr("rei.cli.validate.run", fail)
    assert main(["validate", "x.rei"]) == 1
    assert capsys.readouterr().err == "rei: error: no such run\n"


def test_console_script_is_installed_and_reports_errors_without_traceback(
    fake_java_env: Path, fake_checkout: Path
) -> None:
    (fake_checkout / JARS["cli"]).unlink()
    script = Path(sys.executable).parent / "rei"
    assert script.is_file(), "pip install -e 'sim-adapter[dev]' installs the rei console script"
    version = subprocess.run([script, "--version"], capture_output=True, text=True, timeout=60, check=False)
    assert (version.returncode, version.stdout.strip()) == (0, f"rei {__version__}")
    failed = subprocess.run(
        [script, "validate", "x.rei"], capture_output=True, text=True, timeout=60, check=False
    )
    assert failed.returncode == EXIT_TOOLCHAIN
    assert "Traceback" not in failed.stderr and "run ./rei once" in failed.stderr
