# SPDX-License-Identifier: EPL-2.0
"""`rei report OUT` (or `python -m rei.report OUT`): write report.html and run.mcap for a finished run.

Why a separate command: `rei run` writes both at its end, but a person also wants them for a run folder copied
from CI, for an old run after the report got better, or with the case in another folder (`--case`).
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from pathlib import Path

from rei.report.html import write_report
from rei.report.mcap import write_mcap


def main(out_dir: Path, case_dir: Path | None = None) -> int:
    """Write both files for the run in `out_dir`, print where they are; 2 when `out_dir` is not a run folder."""
    out_dir = Path(out_dir)
    if not out_dir.is_dir():
        print(f"rei report: {out_dir}: no such folder", file=sys.stderr)
        return 2
    if not (out_dir / "streams").is_dir() and not (out_dir / "summary.json").is_file():
        print(f"rei report: {out_dir}: not a run folder (no streams/ and no summary.json)", file=sys.stderr)
        return 2
    report = write_report(out_dir, case_dir)
    print(f"report: {report}")
    recording = write_mcap(out_dir, case_dir)
    print(f"mcap:   {recording} (open in Foxglove Studio)")
    return 0


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """The command's arguments, for `rei report` in rei.cli and for `python -m rei.report`."""
    parser.add_argument("out", metavar="OUT", type=Path, help="the run's output folder")
    parser.add_argument("--case", metavar="DIR", type=Path,
                        help="folder with world.json and mission.xml (default: OUT/case)")


def cli(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="rei report", description=__doc__.split("\n\n", 1)[0] if __doc__ else None)
    add_arguments(parser)
    args = parser.parse_args(argv)
    return main(args.out, args.case)


if __name__ == "__main__":
    sys.exit(cli())
