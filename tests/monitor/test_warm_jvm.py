# SPDX-License-Identifier: EPL-2.0
"""The warm monitor JVM (``--serve``, rei.run.jvm.JarServer): many replays in one JVM, the same signals as a JVM
of their own, a hung command cancelled, and a gone server replaced by a JVM of the command's own."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from rei.run.jvm import JarServer, run_jar, run_served

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "simple_navigation.rei"


@pytest.fixture(scope="module")
def recorded(tmp_path_factory: pytest.TempPathFactory, run_cli: Any) -> Path:
    """The example's mission, simulated without a router: OUT/streams/*.msgpack and OUT/case."""
    out = tmp_path_factory.mktemp("recorded")
    generated = run_cli("generate", EXAMPLE, "-o", out / "case")
    assert generated.returncode == 0, generated.stderr
    simulated = run_cli("sim", out / "case", "-o", out, "--no-router")
    assert simulated.returncode in (0, 1), simulated.stderr
    return out


def _replay(out: Path, signals: Path) -> list[str]:
    return ["--replay", str(out), "--case", str(out / "case"), "--signals-out", str(signals), "--quiet"]


def test_replays_in_one_warm_jvm_give_the_signals_of_a_jvm_of_their_own(recorded: Path, tmp_path: Path) -> None:
    alone = run_jar("monitor", _replay(recorded, tmp_path / "alone.jsonl"), tmp_path / "alone.log")
    assert alone.code == 0 and not alone.served, alone.log_tail
    expected = (tmp_path / "alone.jsonl").read_bytes()
    assert expected.count(b"\n") >= 3  # the example's run has signals to compare
    with JarServer("monitor", tmp_path / "server.log") as server:
        for i in range(3):  # the second and later reuse the rule base the first built
            served = run_jar("monitor", _replay(recorded, tmp_path / f"served{i}.jsonl"), tmp_path / f"served{i}.log",
                             server=server.socket)
            assert served.code == 0 and served.served, served.log_tail
            assert (tmp_path / f"served{i}.jsonl").read_bytes() == expected
            assert "replayed 665 state" in (tmp_path / f"served{i}.log").read_text()
    assert server.cpu > 0 and not server.alive()


def test_a_hung_command_is_cancelled_and_the_server_goes_on(recorded: Path, tmp_path: Path) -> None:
    with JarServer("monitor", tmp_path / "server.log") as server:
        # a live monitor on a port nobody listens on keeps trying to connect, and would until --timeout
        hung = run_served(server.socket, ["--router", "ws://127.0.0.1:9/ws", "--run", "hung", "--until-end"],
                          tmp_path / "hung.log", timeout=3.0)
        assert hung is not None and hung.code == -1 and "cancelled after 3 s" in hung.log_tail
        after = run_served(server.socket, _replay(recorded, tmp_path / "after.jsonl"), tmp_path / "after.log")
        assert after is not None and after.code == 0, after.log_tail


def test_a_command_for_a_server_that_is_gone_runs_in_its_own_jvm(recorded: Path, tmp_path: Path) -> None:
    server = JarServer("monitor", tmp_path / "server.log").start()
    socket = server.socket
    server.stop()
    assert run_served(socket, ["--compile-only"], tmp_path / "nobody.log") is None
    result = run_jar("monitor", _replay(recorded, tmp_path / "own.jsonl"), tmp_path / "own.log", server=socket)
    assert result.code == 0 and not result.served, result.log_tail


def test_a_line_break_in_an_argument_is_refused_not_split(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match="line break"):
        run_served(tmp_path / "none.sock", ["--case", "a\nrun"], tmp_path / "x.log")
