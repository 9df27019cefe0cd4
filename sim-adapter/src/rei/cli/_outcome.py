# SPDX-License-Identifier: EPL-2.0
"""How `rei run` and `rei evaluate` end: the verdicts on stdout, then the report and the Foxglove recording."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any


def print_verdicts(summary: Any) -> None:
    """One line per verdict, the run's error if any, the total utility (``summary``: rei.evaluation.Summary)."""
    for verdict in summary.verdicts:
        print(f"{verdict.status.upper():<15} {verdict.requirement}  {verdict.message}")
    if summary.status != "COMPLETED":
        print(f"run {summary.run_id} ended in ERROR: {summary.error}")
    print(f"total utility {summary.total_utility:+g}")


def write_views(out: Path) -> None:
    """report.html and run.mcap; a failure here must not hide the verdicts printed before."""
    from rei.report import write_views as write_both

    try:
        report, mcap = write_both(out)
        print(f"report: {report}")
        print(f"mcap:   {mcap} (open in Foxglove Studio)")
    except Exception as error:  # noqa: BLE001 - the run's results are already written
        print(f"rei: no report: {type(error).__name__}: {error}", file=sys.stderr)
