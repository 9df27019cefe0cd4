# SPDX-License-Identifier: EPL-2.0
"""What `rei run`'s own process imports to judge a run: no SciPy. Importing ``scipy.spatial`` took about 0.6 s
after every simulation (the encounter margin's k-d tree), which a warm run pays on its critical path (issue #37)."""

from __future__ import annotations

import subprocess
import sys


def test_judging_a_run_imports_no_scipy() -> None:
    code = ("import sys, rei.cli.run, rei.run.pipeline, rei.evaluation, rei.evaluation.metrics.compute, rei.report; "
            "print(sorted(m for m in sys.modules if m == 'scipy' or m.startswith('scipy.')))")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert done.stdout.strip() == "[]", done.stdout
