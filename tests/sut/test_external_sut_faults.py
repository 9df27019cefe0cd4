# SPDX-License-Identifier: EPL-2.0
"""The commands' faults (docs/faults.md) act on an external SUT's commands as on an in-process controller's: they
sit between the controller and the simulation, where both (and the ROS bridges, external SUTs too) hand over their
commands. The reference navigation in process and as an external SUT, with the same latency and loss, record the
same streams byte for byte (test_motion_fault_streams checks the in-process run against the faults' definitions)."""

from __future__ import annotations

from pathlib import Path

from rei.wamp.recording import read_recording

EXAMPLE = "examples/simple_navigation.rei"
FAULTS = "commands:latency,delay=0.3,from=3,to=8;commands:loss,probability=0.3,from=10,to=14"


def test_an_external_sut_s_commands_are_delayed_and_lost_as_an_in_process_controller_s(
    run_cli, repo_root: Path, tmp_path: Path
) -> None:
    inproc, external = tmp_path / "inproc", tmp_path / "external"
    first = run_cli("run", repo_root / EXAMPLE, "-o", inproc, "--seed", "7", "--fault", FAULTS, timeout=300)
    second = run_cli("run", repo_root / EXAMPLE, "-o", external, "--seed", "7", "--fault", FAULTS,
                     "--sut", "rei nav-sut", "--sut-map", timeout=300)
    assert first.returncode in (0, 1), first.stdout + first.stderr
    assert second.returncode == first.returncode, second.stdout + second.stderr
    for stream in ("state", "mission"):
        assert (inproc / "streams" / f"{stream}.msgpack").read_bytes() == \
            (external / "streams" / f"{stream}.msgpack").read_bytes(), stream
    events = [(m["t"], m["event"]) for m in read_recording(external / "streams" / "mission.msgpack")
              if m["event"].startswith("FAULT_")]
    assert events == [(3.0, "FAULT_COMMANDS_LATENCY_BEGIN"), (8.0, "FAULT_COMMANDS_LATENCY_END"),
                      (10.0, "FAULT_COMMANDS_LOSS_BEGIN"), (14.0, "FAULT_COMMANDS_LOSS_END")]
