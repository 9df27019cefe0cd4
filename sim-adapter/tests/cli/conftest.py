# SPDX-License-Identifier: EPL-2.0
"""A fake JDK and a fake REI checkout, so the CLI plumbing is tested without building the Java parts."""

from __future__ import annotations

import stat
from collections.abc import Callable
from pathlib import Path

import pytest

from rei.toolchain import JARS

FAKE_JAVA = """#!/bin/sh
# Answers -version like a JDK; otherwise records its arguments, echoes them and exits with $FAKE_JAVA_EXIT.
if [ "$1" = "-version" ]; then
    echo 'openjdk version "{version}" 2024-01-16' >&2
    exit 0
fi
printf '%s\\n' "$@" > "$(dirname "$0")/../last-args"
echo "fake-java: $*"
echo "fake-java-stderr" >&2
exit "${{FAKE_JAVA_EXIT:-0}}"
"""

MakeJdk = Callable[..., Path]


@pytest.fixture
def make_jdk(tmp_path: Path) -> MakeJdk:
    """Create a fake JDK home whose `bin/java` is a shell script; `release=False` leaves out the release
    file so the version must come from `java -version`."""

    def make(version: str = "17.0.2", release: bool = True, name: str = "jdk") -> Path:
        home = tmp_path / name
        (home / "bin").mkdir(parents=True)
        java = home / "bin" / "java"
        java.write_text(FAKE_JAVA.format(version=version))
        java.chmod(java.stat().st_mode | stat.S_IXUSR | stat.S_IXGRP | stat.S_IXOTH)
        if release:
            (home / "release").write_text(f'IMPLEMENTOR="Test"\nJAVA_VERSION="{version}"\n')
        return home

    return make


@pytest.fixture
def fake_checkout(tmp_path: Path) -> Path:
    """An REI checkout with empty stand-ins for every jar."""
    root = tmp_path / "checkout"
    (root / "sim-adapter").mkdir(parents=True)
    (root / "pom.xml").write_text("<project/>\n")
    for relative in JARS.values():
        (root / relative).parent.mkdir(parents=True, exist_ok=True)
        (root / relative).write_bytes(b"PK")
    return root


@pytest.fixture
def last_args() -> Callable[[Path], list[str]]:
    """Reads the arguments the fake java of a JDK home was last started with."""

    def read(jdk: Path) -> list[str]:
        return (jdk / "last-args").read_text().splitlines()

    return read
