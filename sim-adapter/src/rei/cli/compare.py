# SPDX-License-Identifier: EPL-2.0
"""`rei compare BASELINE CANDIDATE -o OUT [--thresholds FILE.yaml]`: is the candidate worse, and is it real?

BASELINE and CANDIDATE are two campaign folders (or two run folders) of the same spec, run with different
systems under test, settings or versions. Runs pair by group, case, variant, seed and fault; runs without a
partner or in ERROR are listed, not dropped. Per navigation metric (docs/metrics.md) the paired difference with its 95 %
bootstrap interval and a paired test (Wilcoxon signed-rank; success: McNemar's exact test), and a regression
verdict from the thresholds (default: success, SPL and collisions worse at p < 0.05, minimum clearances 5 cm
lower, any more robot-at-fault collisions with people, 2 % more of the mission in people's intimate space, people
delayed 1 s more); when the runs carry several faults, also per fault over its pairs. Writes OUT/compare.html,
OUT/compare.json and OUT/verdicts.xml (JUnit). Exit 0: no regression; 1: a metric regressed (overall or under a
fault); 2: bad arguments or thresholds, or no run pairs.
"""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import Any

from rei.cli._case import prepare_output
from rei.cli.errors import EXIT_OK, CommandError


def register(subparsers: argparse._SubParsersAction[Any]) -> None:
    """Add the `compare` subcommand."""
    parser = subparsers.add_parser("compare", help="compare two campaigns (or runs) metric by metric",
                                   description=__doc__.split("\n\n", 1)[1] if __doc__ else None)
    parser.add_argument("baseline", type=Path, metavar="BASELINE", help="campaign or run folder of the baseline")
    parser.add_argument("candidate", type=Path, metavar="CANDIDATE", help="campaign or run folder of the candidate")
    add_compare_options(parser)
    parser.set_defaults(handler=run)


def add_compare_options(parser: argparse.ArgumentParser, output: bool = True) -> None:
    if output:
        parser.add_argument("-o", "--output", required=True, type=Path, metavar="OUT", help="output folder")
    parser.add_argument("--thresholds", type=Path, metavar="FILE.yaml",
                        help="when a difference is a regression (docs/metrics.md); default: built-in thresholds")


def load_thresholds_option(path: Path | None) -> Any:
    """The thresholds of ``--thresholds`` (checked before anything runs), or the defaults."""
    from rei.compare import ThresholdsError, default_thresholds, load_thresholds

    if path is None:
        return default_thresholds()
    try:
        return load_thresholds(path)
    except ThresholdsError as error:
        raise CommandError(error.problems) from None


def compare_and_report(baseline: Path, candidate: Path, out: Path, thresholds: Any) -> int:
    """Compare, write the files, print the verdicts; the exit code (0 or 1)."""
    from rei.compare import CompareError, compare, write_comparison

    try:
        comparison = compare(baseline.resolve(), candidate.resolve(), thresholds)
    except CompareError as error:
        raise CommandError(str(error)) from None
    prepare_output(out)  # -o naming a file was a traceback, after the comparison
    files = write_comparison(comparison, out.resolve())
    p = comparison.pairing
    print(f"compare: {len(p.pairs)} pair(s); {len(p.only_baseline)} run(s) only in the baseline, "
          f"{len(p.only_candidate)} only in the candidate, {len(p.errors)} pair(s) with a side in ERROR")
    for run in p.only_baseline:
        print(f"  not compared: {run.key}: only in the baseline")
    for run in p.only_candidate:
        print(f"  not compared: {run.key}: only in the candidate")
    for b, c in p.errors:
        print(f"  not compared: {b.key} (baseline {b.status}) and {c.key} (candidate {c.status})"
              f"{f': {b.error or c.error}' if b.error or c.error else ''}")
    for m in comparison.metrics:
        if m.status is not None:
            print(f"  {str(m.status).upper() if m.regressed else str(m.status):<14} {m.message}")
    for fault, metrics in comparison.by_fault:
        for m in metrics:
            if m.status is not None:
                print(f"  {str(m.status).upper() if m.regressed else str(m.status):<14} under {fault}: {m.message}")
    print(f"regressions: {', '.join(m.metric.name for m in comparison.regressions) or 'none'}")
    if comparison.by_fault:
        under = comparison.fault_regressions
        print(f"regressions under a fault: {', '.join(f'{m.metric.name} under {f}' for f, m in under) or 'none'}")
    print(f"report:   {files['html']}")
    print(f"verdicts: {files['junit']}")
    return comparison.exit_code


def run(args: argparse.Namespace) -> int:
    thresholds = load_thresholds_option(args.thresholds)
    code = compare_and_report(args.baseline, args.candidate, args.output, thresholds)
    return code if code else EXIT_OK
