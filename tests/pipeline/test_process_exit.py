# SPDX-License-Identifier: EPL-2.0
"""`rei run` and the simulation it starts skip the interpreter's last garbage collection at exit (rei.lifetime
.skip_exit_collection): `rei run` waits for the simulation's exit, the user for the run's. Measured on the example:
0.12-0.33 s from the simulation's last file to its exit with that collection, 0.01-0.05 s without."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

#: Loaded by every Python process of the run (PYTHONPATH): at its exit it notes its command and how many objects
#: were frozen, i.e. left out of the interpreter's last collections. Registered first, so it runs last.
PROBE = """\
import atexit, gc, json, os, sys

def _note():
    with open(os.environ["REI_EXIT_PROBE"], "a", encoding="utf-8") as notes:
        notes.write(json.dumps({"argv": sys.argv[1:3], "frozen": gc.get_freeze_count()}) + "\\n")

atexit.register(_note)
"""


def test_the_run_and_its_simulation_leave_the_last_collection_out(run_cli: Any, repo_root: Path,
                                                                 tmp_path: Path) -> None:
    probe = tmp_path / "probe"
    probe.mkdir()
    (probe / "sitecustomize.py").write_text(PROBE, encoding="utf-8")
    notes = tmp_path / "exits.jsonl"
    out = tmp_path / "out"
    result = run_cli("run", repo_root / "examples" / "simple_navigation.rei", "-o", out, "--no-service",
                     timeout=240.0, env={"PYTHONPATH": str(probe), "REI_EXIT_PROBE": str(notes)})
    assert result.returncode == 0, result.stdout + result.stderr
    exits = [json.loads(line) for line in notes.read_text(encoding="utf-8").splitlines()]
    commands = {tuple(e["argv"]): e["frozen"] for e in exits}
    run = [frozen for argv, frozen in commands.items() if argv[:1] == ("run",)]
    sim = [frozen for argv, frozen in commands.items() if argv[:1] == ("sim",)]
    assert run and sim, exits
    assert run[0] > 0 and sim[0] > 0, exits
    # nothing the run writes is lost to the skipped collection: the files of a whole run are there and complete
    assert json.loads((out / "summary.json").read_text())["verdicts"]
    assert "processed 665 state" in (out / "monitor.log").read_text()
    assert (out / "report.html").read_text().rstrip().endswith("</html>")
