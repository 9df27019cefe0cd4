# SPDX-License-Identifier: EPL-2.0
"""Locating Java and the jars: every failure is a ToolchainError whose message says what to do."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

from rei import toolchain
from rei.toolchain import JARS, ToolchainError

MakeJdk = Callable[..., Path]
LastArgs = Callable[[Path], list[str]]


def test_repo_root_of_this_checkout_is_found_from_the_package() -> None:
    root = toolchain.find_repo_root(env={})
    assert (root / "pom.xml").is_file()
    assert (root / "sim-adapter" / "src" / "rei" / "toolchain.py").is_file()


def test_repo_root_walks_up_from_a_nested_start(fake_checkout: Path) -> None:
    nested = fake_checkout / "sim-adapter" / "src" / "rei" / "cli"
    nested.mkdir(parents=True)
    assert toolchain.find_repo_root(nested / "__init__.py", env={}) == fake_checkout.resolve()


def test_rei_home_wins_over_the_package_location(fake_checkout: Path) -> None:
    assert toolchain.find_repo_root(env={"REI_HOME": str(fake_checkout)}) == fake_checkout.resolve()


def test_rei_home_that_is_no_checkout_is_an_error(tmp_path: Path) -> None:
    with pytest.raises(ToolchainError, match="REI_HOME=.* is not an REI checkout"):
        toolchain.find_repo_root(env={"REI_HOME": str(tmp_path)})


def test_no_checkout_above_the_start_is_an_error(tmp_path: Path) -> None:
    with pytest.raises(ToolchainError, match="set REI_HOME"):
        toolchain.find_repo_root(tmp_path / "a" / "b.py", env={})


@pytest.mark.parametrize(
    ("version", "feature"), [("17.0.2", 17), ("21", 21), ("11.0.22", 11), ("1.8.0_402", 8)]
)
@pytest.mark.parametrize("release", [True, False], ids=["release-file", "java-version"])
def test_java_version_is_read(make_jdk: MakeJdk, version: str, feature: int, release: bool) -> None:
    home = make_jdk(version, release=release)
    assert toolchain.java_version(home / "bin" / "java") == feature


def test_java_home_is_preferred_and_checked(make_jdk: MakeJdk) -> None:
    home = make_jdk("21.0.1")
    java = toolchain.find_java(env={"JAVA_HOME": str(home), "PATH": ""})
    assert java.executable == home / "bin" / "java"
    assert java.version == 21


def test_java_home_without_java_is_an_error(tmp_path: Path) -> None:
    with pytest.raises(ToolchainError, match="has no bin/java"):
        toolchain.find_java(env={"JAVA_HOME": str(tmp_path)})


def test_java_on_path_is_used_without_java_home(make_jdk: MakeJdk) -> None:
    home = make_jdk("17.0.9")
    java = toolchain.find_java(env={"PATH": str(home / "bin")})
    assert java.executable == home / "bin" / "java"
    assert java.version == 17


def test_missing_java_is_an_error(tmp_path: Path) -> None:
    with pytest.raises(ToolchainError, match="java not found on PATH"):
        toolchain.find_java(env={"PATH": str(tmp_path)})


@pytest.mark.parametrize("version", ["11.0.22", "1.8.0_402"])
def test_old_java_is_an_error(make_jdk: MakeJdk, version: str) -> None:
    home = make_jdk(version)
    with pytest.raises(ToolchainError, match="REI needs Java 17 or newer"):
        toolchain.find_java(env={"JAVA_HOME": str(home)})


def test_present_jar_is_found(fake_checkout: Path) -> None:
    assert toolchain.find_jar("cli", fake_checkout) == fake_checkout / JARS["cli"]


def test_missing_jar_tells_the_user_to_build(fake_checkout: Path) -> None:
    (fake_checkout / JARS["language-server"]).unlink()
    with pytest.raises(ToolchainError, match=r"rei-language-server\.jar is missing: run \./rei once"):
        toolchain.find_jar("language-server", fake_checkout)


def test_unknown_jar_role_is_a_programming_error(fake_checkout: Path) -> None:
    with pytest.raises(ValueError, match="unknown jar role"):
        toolchain.find_jar("nope", fake_checkout)


def test_run_jar_streams_output_and_returns_the_exit_code(
    last_args: LastArgs,
    make_jdk: MakeJdk,
    fake_checkout: Path,
    capfd: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    home = make_jdk()
    java = toolchain.find_java(env={"JAVA_HOME": str(home)})
    jar = fake_checkout / JARS["cli"]
    monkeypatch.setenv("FAKE_JAVA_EXIT", "5")
    assert toolchain.run_jar(jar, ["validate", "a b.rei"], java=java) == 5
    assert last_args(home) == ["-jar", str(jar), "validate", "a b.rei"]
    out, err = capfd.readouterr()
    assert f"fake-java: -jar {jar} validate a b.rei" in out
    assert "fake-java-stderr" in err
