# SPDX-License-Identifier: EPL-2.0
"""The `rei run` line at the top of each case `rei search` saves reproduces the run as the search made it, also
when the spec changes what the run depends on besides the case and seed: a search with a weakened controller
(``nav:moving_horizon=0``), without the humans and with a laser fault saves a case whose line, run as written in
the case's folder with the real `rei run` (router, live monitor, simulation, evaluator), records the search's
streams byte for byte. Without a simulation: an external SUT's line runs its command in the spec's folder, and a
command with a line break stays on the comment's one line; a real shell reads each line back into the same
arguments."""

from __future__ import annotations

import json
import shlex
import shutil
import subprocess
from pathlib import Path
from typing import Any

from rei.campaign.spec import ExternalSut
from rei.search.failures import DistinctFailure, Failure, failure_verdicts
from rei.search.reproduce import HEADER_PREFIX, RunOptions, header

REPO_ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = REPO_ROOT / "examples" / "search"
TIMEOUT = 300.0
CONTROLLER = "nav:moving_horizon=0"
SPEC = f"""\
case: crossing.rei
controller: "{CONTROLLER}"
humans: false
seed: 3
budget: 1
timeout: 120
parameters:
  - {{seed: [0, 1000]}}
  - {{fault: "laser:1%", rate: [0.0, 0.05]}}
objectives: [utility]
shrink: {{budget: 0}}
"""


def test_a_saved_case_reruns_byte_for_byte_with_the_specs_controller_and_no_humans(tmp_path: Path,
                                                                                   run_cli: Any) -> None:
    shutil.copy(EXAMPLE / "crossing.rei", tmp_path / "crossing.rei")
    spec = tmp_path / "weak.yaml"
    spec.write_text(SPEC, encoding="utf-8")
    out = tmp_path / "out"
    searched = run_cli("search", spec, "-o", out, "--workers", "1", timeout=TIMEOUT)
    assert searched.returncode in (0, 1), searched.stdout + searched.stderr
    [record] = [r for r in json.loads((out / "search.json").read_text(encoding="utf-8"))["evaluations"]
                if r["status"] == "COMPLETED"]
    case = Path(record["case"])
    first = case.read_text(encoding="utf-8").splitlines()[0]
    fault = record["fault"]
    assert fault and fault.startswith("laser:1%,rate="), record
    assert first == (f"{HEADER_PREFIX}{record['key']}: rei run {case.name} --seed {record['seed']} --fault {fault} "
                     f"--controller {CONTROLLER} --no-humans")
    argv = shlex.split(first.split(": ", 1)[1])
    assert argv[:2] == ["rei", "run"], argv
    again = tmp_path / "again"
    result = run_cli(*argv[1:], "-o", again, cwd=case.parent, timeout=TIMEOUT)  # as written, in its folder
    assert result.returncode in (0, 1), result.stdout + result.stderr
    recorded = Path(record["run"]) / "streams"
    streams = sorted(p.name for p in recorded.iterdir())
    assert streams == ["mission.msgpack", "signal.msgpack", "state.msgpack"]
    for name in streams:
        assert (again / "streams" / name).read_bytes() == (recorded / name).read_bytes(), name
    summary = json.loads((again / "summary.json").read_text(encoding="utf-8"))
    assert summary["metrics"].get("clearance_humans_min") is None, summary["metrics"]  # no humans in the world


def _as_the_shell_reads_it(line: str, tmp_path: Path) -> tuple[str, list[str]]:
    """The folder and arguments `rei` gets when bash runs ``line`` (`rei` a function printing them)."""
    script = 'rei() { pwd; printf "%s\\0" "$@"; }\n' + line + "\n"
    done = subprocess.run(["bash", "-c", script], capture_output=True, text=True, cwd=tmp_path, timeout=30,
                          check=True)
    folder, _, args = done.stdout.partition("\n")
    return folder, args.split("\0")[:-1]


def test_an_external_suts_line_runs_its_command_in_the_specs_folder(tmp_path: Path) -> None:
    spec_folder = tmp_path / "spec folder"
    spec_folder.mkdir()
    case = tmp_path / "out" / "candidates" / "tpe-0004.rei"
    command = "python3 'my nav.py' --gain \"it's\"\n  --verbose\n"  # as a YAML block scalar gives it
    sut = ExternalSut(command=command, map=True, cwd=str(spec_folder))
    first = header("tpe-0004", case, 7, "laser:rate=0.02", RunOptions(humans=False, sut=sut))
    assert "\n" not in first and first.startswith(f"{HEADER_PREFIX}tpe-0004: cd ")
    folder, args = _as_the_shell_reads_it(first.split(": ", 1)[1], tmp_path)
    assert folder == str(spec_folder)
    assert args == ["run", str(case), "--seed", "7", "--fault", "laser:rate=0.02", *sut.argv(), "--no-humans"]
    assert "--sut-map" in args and "--controller" not in args


def test_verdicts_reproduce_a_failure_with_its_cases_own_line(tmp_path: Path) -> None:
    case = tmp_path / "out folder" / "candidates" / "tpe-0002.rei"
    case.parent.mkdir(parents=True)
    case.write_text(header("tpe-0002", case, 11, None, RunOptions(controller=CONTROLLER, humans=False)) +
                    "\ntestcase T {}\n", encoding="utf-8")
    failure = Failure("COLLISION", "-", "F_1_1", 3.0, ("MISSION_SIMPLE",), "collision at t=3.000",
                      "MISSION_SIMPLE: the mission failed")
    [verdict] = failure_verdicts([DistinctFailure(failure, ["tpe-0002"], 10.0, "tpe-0002")],
                                 {failure.signature: str(case)}, simulated=1)
    line = verdict.evidence[-1].text.removeprefix("reproduce: ")
    assert verdict.message.endswith(f"(reproduce: {line})")
    folder, args = _as_the_shell_reads_it(line, tmp_path)  # from any folder: it goes to the case's
    assert folder == str(case.parent)
    assert args == ["run", case.name, "--seed", "11", "--controller", CONTROLLER, "--no-humans"]
