# SPDX-License-Identifier: EPL-2.0
"""What a person looks at after a run: `OUT/report.html` (map, utility, signals, verdicts) and `OUT/run.mcap`
(the run for Foxglove Studio). Both are written from the run folder alone, so they can be made again later, for
old runs, or for runs whose evaluator never finished."""

from __future__ import annotations

from pathlib import Path

from rei.report.html import write_report
from rei.report.mcap import write_mcap
from rei.report.run_data import load_run
from rei.report.tracks import collect_tracks


def write_views(out_dir: Path, case_dir: Path | None = None) -> tuple[Path, Path]:
    """Both views of a run, `report.html` and `run.mcap`, from one reading of its folder and its states: what
    `rei run` and `rei evaluate` do last, on the run's critical path."""
    data = load_run(Path(out_dir), case_dir)
    tracks = collect_tracks(data.states())
    return (write_report(out_dir, case_dir, data=data, tracks=tracks),
            write_mcap(out_dir, case_dir, data=data, tracks=tracks))


__all__ = ["write_mcap", "write_report", "write_views"]
