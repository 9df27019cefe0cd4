# SPDX-License-Identifier: EPL-2.0
"""What a person looks at after a run: `OUT/report.html` (map, utility, signals, verdicts) and `OUT/run.mcap`
(the run for Foxglove Studio). Both are written from the run folder alone, so they can be made again later, for
old runs, or for runs whose evaluator never finished."""

from __future__ import annotations

from rei.report.html import write_report
from rei.report.mcap import write_mcap

__all__ = ["write_mcap", "write_report"]
