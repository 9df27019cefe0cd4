# SPDX-License-Identifier: EPL-2.0
"""External systems under test (docs/sut.md) with the real router, monitor, simulation and SUT processes."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time
from pathlib import Path

import pytest

from rei.wamp.recording import read_recording

PROGRAMS = Path(__file__).resolve().parent / "programs"
EXAMPLE = "examples/simple_navigation.rei"


def _summary(out: Path) -> dict:
    return json.loads((out / "summary.json").read_text())


def _sim(out: Path) -> dict:
    return json.loads((out / "sim.json").read_text())


def _program(name: str, marker: Path) -> str:
    """The command of a test SUT; ``marker`` (the run folder) on its command line lets the test find it later."""
    return f"{sys.executable} {PROGRAMS / name} {marker}"


def test_the_reference_navigation_as_an_external_sut_records_the_same_streams_as_in_process(
    run_cli, repo_root: Path, tmp_path: Path, processes_mentioning
) -> None:
    inproc, external = tmp_path / "inproc", tmp_path / "external"
    first = run_cli("run", repo_root / EXAMPLE, "-o", inproc, "--seed", "7", timeout=300)
    second = run_cli("run", repo_root / EXAMPLE, "-o", external, "--seed", "7", "--sut", "rei nav-sut",
                     "--sut-map", timeout=300)
    assert first.returncode == 0, first.stdout + first.stderr
    assert second.returncode == 0, second.stdout + second.stderr
    for stream in ("state", "mission"):
        assert (inproc / "streams" / f"{stream}.msgpack").read_bytes() == \
            (external / "streams" / f"{stream}.msgpack").read_bytes(), stream
    verdicts = {out: [(v["requirement"], v["status"]) for v in _summary(out)["verdicts"]] for out in (inproc, external)}
    assert verdicts[inproc] == verdicts[external]
    sut = _sim(external)["sut"]
    assert sut["exit_code"] == 0 and sut["rejected"] == 0 and sut["commands"] == _sim(inproc)["steps"] // 24 + 1
    assert (external / "sut.log").is_file()
    assert processes_mentioning(tmp_path) == []


def test_a_sut_that_never_answers_ends_the_run_in_error_within_its_deadline(
    run_cli, repo_root: Path, tmp_path: Path, processes_mentioning
) -> None:
    out = tmp_path / "out"
    started = time.monotonic()
    result = run_cli("run", repo_root / EXAMPLE, "-o", out, "--sut", _program("silent_sut.py", out),
                     "--sut-deadline", "2", "--sut-join-timeout", "3", timeout=300)
    assert result.returncode == 2, result.stdout + result.stderr
    summary = _summary(out)
    assert summary["status"] == "ERROR"
    assert "no command for tick 0 at t=0.000 s within 3 s (--sut-join-timeout for tick 0)" in summary["error"]
    assert "joined; not answering" in summary["error"]  # the tail of sut.log is the evidence
    assert {v["status"] for v in summary["verdicts"]} <= {"error", "not-applicable"}
    # what was published is kept: the mission had begun
    assert [m["event"] for m in read_recording(out / "streams" / "mission.msgpack")] == ["BEGIN", "TASK_START"]
    assert time.monotonic() - started < 120
    assert processes_mentioning(tmp_path) == []  # the silent SUT ignored `end` and was stopped


def test_a_sut_that_subscribes_after_hello_is_told_why_tick_0_never_came(
    run_cli, repo_root: Path, tmp_path: Path, processes_mentioning
) -> None:
    """Calling hello before subscribing (the router drops tick 0) ended in "no command for tick 0 ... within 3 s"
    and nothing else: the same words as a SUT that hangs."""
    out = tmp_path / "out"
    result = run_cli("run", repo_root / EXAMPLE, "-o", out, "--sut", _program("late_subscriber_sut.py", out),
                     "--sut-deadline", "2", "--sut-join-timeout", "3", timeout=300)
    assert result.returncode == 2, result.stdout + result.stderr
    error = _summary(out)["error"]
    assert "no command for tick 0 at t=0.000 s within 3 s" in error
    assert "nothing at all came from it since it called hello" in error
    assert "subscribed to tick only after calling hello" in error and "subscribed after hello" in error
    assert processes_mentioning(tmp_path) == []


def test_a_sut_that_dies_ends_the_run_in_error_with_its_exit_code_and_log(
    run_cli, repo_root: Path, tmp_path: Path, processes_mentioning
) -> None:
    out = tmp_path / "out"
    result = run_cli("run", repo_root / EXAMPLE, "-o", out, "--sut", _program("crashing_sut.py", out), timeout=300)
    assert result.returncode == 2, result.stdout + result.stderr
    error = _summary(out)["error"]
    assert "exited with code 3" in error and "segmentation fault in the planner" in error
    assert _sim(out)["sut"]["exit_code"] == 3 and _sim(out)["sut"]["commands"] == 20
    assert processes_mentioning(tmp_path) == []


def test_garbage_from_the_sut_is_rejected_counted_and_the_run_goes_on(
    run_cli, repo_root: Path, tmp_path: Path
) -> None:
    out = tmp_path / "out"
    result = run_cli("run", repo_root / EXAMPLE, "-o", out, "--sut", _program("garbage_sut.py", out), "--sut-map",
                     timeout=300)
    assert result.returncode in (0, 1), result.stdout + result.stderr
    assert _summary(out)["status"] == "COMPLETED"
    sut = _sim(out)["sut"]
    ticks = sut["commands"]
    assert ticks > 100
    assert sut["rejected"] == 6 * ticks  # five malformed commands and one malformed status per tick
    assert sut["clamped"] == 5 and sut["stale"] == ticks - 1
    assert len(sut["first_rejections"]) == 10 and "v must be finite" in " ".join(sut["first_rejections"])
    log = (out / "simulation.log").read_text()
    assert "sut: tick 0 (t=0.000 s): command rejected: a command must be a map" in log
    notes = " ".join(p["text"] for p in _summary(out)["problems"])
    assert f"{6 * ticks} messages were rejected" in notes


def test_a_sut_the_user_starts_attaches_with_the_run_s_environment(
    rei_script: Path, repo_root: Path, tmp_path: Path, processes_mentioning
) -> None:
    out = tmp_path / "out"
    env = {**os.environ, "REI_HOME": str(repo_root)}
    run = subprocess.Popen([str(rei_script), "run", str(repo_root / EXAMPLE), "-o", str(out), "--sut-attach",
                            "--sut-map"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, env=env,
                           start_new_session=True)
    sut = None
    try:
        env_file = out / "sut.env"
        deadline = time.monotonic() + 120
        while not env_file.is_file() and time.monotonic() < deadline and run.poll() is None:
            time.sleep(0.2)
        assert env_file.is_file(), "rei run did not write OUT/sut.env"
        variables = dict(line.split("=", 1) for line in env_file.read_text().splitlines())
        assert set(variables) == {"REI_ROUTER_URL", "REI_ROUTER_RAWSOCKET_URL", "REI_REALM", "REI_RUN_ID", "REI_AUTH_FILE",
                                  "REI_CASE_DIR"}
        assert "secret" not in env_file.read_text()
        sut = subprocess.Popen([str(rei_script), "nav-sut"], env={**env, **variables}, stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, text=True)
        output, _ = run.communicate(timeout=300)
        assert sut.wait(timeout=30) == 0
    finally:
        for process in (run, sut):
            if process is not None and process.poll() is None:
                process.kill()
    assert run.returncode == 0, output
    assert "waiting up to 60 s for your system under test" in output and "joined" in output
    assert processes_mentioning(tmp_path) == []


def test_ctrl_c_during_a_run_with_an_external_sut_says_when_and_keeps_the_streams(
    rei_script: Path, repo_root: Path, tmp_path: Path, processes_mentioning
) -> None:
    """Ctrl-C said only "ended in ERROR: interrupted": not where the simulation was, which is where the recorded
    streams end."""
    import signal

    out = tmp_path / "out"
    run = subprocess.Popen([str(rei_script), "run", str(repo_root / EXAMPLE), "-o", str(out), "--no-humans", "--sut",
                            _program("silent_sut.py", out), "--sut-clock", "realtime", "--sut-deadline", "60"],
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                           env={**os.environ, "REI_HOME": str(repo_root)})
    try:
        deadline = time.monotonic() + 120
        while "joined" not in (out / "simulation.log").read_text(errors="replace") if (
                out / "simulation.log").is_file() else True:
            assert run.poll() is None and time.monotonic() < deadline, run.communicate()
            time.sleep(0.2)
        time.sleep(3.0)  # the realtime clock: about 3 s simulated
        run.send_signal(signal.SIGINT)
        output, _ = run.communicate(timeout=120)
    finally:
        if run.poll() is None:
            run.kill()
    assert run.returncode == 2, output
    assert "ended in ERROR: interrupted (Ctrl-C) at about t=" in output, output
    stated = float(output.split("interrupted (Ctrl-C) at about t=")[1].split(" s")[0])
    recorded = [m["t"] for m in read_recording(out / "streams" / "state.msgpack")]
    assert 1.0 <= stated and abs(recorded[-1] - stated) < 2.0, (stated, recorded[-1])
    # the simulation, stopped by rei run's SIGTERM, still writes its summary: how far it got, the SUT's exit code
    sim = _sim(out)
    assert sim["error"].startswith("stopped by SIGTERM at t=") and abs(sim["sim_time"] - recorded[-1]) < 0.5, sim
    assert sim["sut"]["exit_code"] is not None, sim["sut"]
    assert processes_mentioning(tmp_path) == []


def test_what_a_sut_leaves_in_its_process_group_is_stopped_too(
    run_cli, repo_root: Path, tmp_path: Path, processes_mentioning
) -> None:
    out = tmp_path / "out"
    result = run_cli("run", repo_root / EXAMPLE, "-o", out, "--sut", f"{PROGRAMS / 'leaky_sut.sh'} {out}",
                     "--sut-map", timeout=300)
    assert result.returncode == 0, result.stdout + result.stderr
    assert processes_mentioning(tmp_path) == []  # the helper ignored SIGTERM: it got SIGKILL


def test_an_external_sut_in_a_campaign_is_judged_and_a_broken_one_is_an_error_with_verdicts(
    run_cli, repo_root: Path, tmp_path: Path, processes_mentioning
) -> None:
    (tmp_path / "silent_sut.py").write_text((PROGRAMS / "silent_sut.py").read_text())
    spec = tmp_path / "spec.yaml"
    spec.write_text(f"""
name: external
timeout: 200
variants:
  - {{name: nav, sut: {{command: "rei nav-sut", map: true}}}}
  - {{name: silent, sut: {{command: "python3 silent_sut.py {tmp_path}", deadline: 2, join_timeout: 3}}}}
groups:
  - {{name: example, cases: ["{repo_root / EXAMPLE}"]}}
""")
    result = run_cli("campaign", spec, "-o", tmp_path / "campaign", "--workers", "1", timeout=400)
    runs = tmp_path / "campaign" / "runs"
    nav = _summary(runs / "example__simple_navigation__nav__r0")
    silent = _summary(runs / "example__simple_navigation__silent__r0")
    assert nav["status"] == "COMPLETED", result.stdout + result.stderr
    assert {v["status"] for v in nav["verdicts"]} <= {"pass", "not-applicable"}
    assert silent["status"] == "ERROR" and "no command for tick 0" in silent["error"]
    assert silent["verdicts"], "a broken run is still judged (as errors)"
    assert processes_mentioning(tmp_path) == []


@pytest.mark.parametrize("arguments, message", [
    (["--sut", "no-such-program --flag"], "program 'no-such-program' not found"),
    (["--sut", "rei nav-sut", "--controller", "script:x.txt"], "--sut/--sut-attach replace it"),
    (["--sut-map"], "apply with --sut COMMAND or --sut-attach only"),
    (["--sut", "rei nav-sut", "--sut-deadline", "0"], "--sut-deadline must be a number of seconds > 0"),
    (["--sut-deadline", "5"], "apply with --sut COMMAND or --sut-attach only"),
])
def test_bad_sut_options_fail_before_anything_starts(run_cli, repo_root: Path, tmp_path: Path,
                                                     arguments: list[str], message: str) -> None:
    result = run_cli("run", repo_root / EXAMPLE, "-o", tmp_path / "out", *arguments, timeout=60)
    assert result.returncode == 2
    assert message in result.stderr
    assert not (tmp_path / "out").exists()


def test_a_free_running_sut_drives_a_wall_clock_paced_simulation(run_cli, repo_root: Path, tmp_path: Path) -> None:
    script = tmp_path / "forward.txt"
    script.write_text("3.0 0.2 0.0\n")  # 3 s forward, then SUCCEEDED (a false success: the goal is 4 m away)
    out = tmp_path / "out"
    started = time.monotonic()
    result = run_cli("sim", repo_root / EXAMPLE, "-o", out, "--progress", "none", "--sut",
                     f"rei nav-sut script:{script}", "--sut-clock", "realtime", timeout=120)
    wall = time.monotonic() - started
    assert result.returncode == 1, result.stdout + result.stderr  # both tasks fail, the run does not
    summary = _sim(out)
    assert summary["sut"]["clock"] == "realtime" and summary["sut"]["commands"] > 20
    assert summary["wall_time"] >= 0.9 * summary["sim_time"] >= 2.7 and wall >= summary["sim_time"]
    reasons = [task["reason"] for task in summary["tasks"]]
    assert "false success" in reasons[0]
    moved = [m for m in read_recording(out / "streams" / "state.msgpack") if m["robot"]["twist"][0] > 0.15]
    assert moved, "the commands that arrived while the simulation ran were applied"
