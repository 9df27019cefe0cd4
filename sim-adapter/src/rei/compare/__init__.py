# SPDX-License-Identifier: EPL-2.0
"""``rei compare BASELINE CANDIDATE``: is the candidate better or worse than the baseline, and is it real?

Two campaign folders (or two run folders) of the same spec, run with different systems under test, settings or
versions: runs pair by group, case, variant and seed (rei.compare.runs); per metric of docs/metrics.md the
paired difference with its interval and a paired test (rei.compare.analysis), a regression verdict from the
thresholds (rei.compare.thresholds), and ``compare.json``, ``verdicts.xml`` and ``compare.html``
(rei.compare.outputs)::

    comparison = compare(baseline, candidate, load_thresholds(path))
    write_comparison(comparison, out)
    sys.exit(comparison.exit_code)
"""

from rei.compare.analysis import Comparison, MetricComparison, compare
from rei.compare.outputs import write_comparison
from rei.compare.runs import CompareError, Pairing, Run, load_side, pair
from rei.compare.thresholds import Threshold, Thresholds, ThresholdsError, default_thresholds, load_thresholds

__all__ = ["CompareError", "Comparison", "MetricComparison", "Pairing", "Run", "Threshold", "Thresholds",
           "ThresholdsError", "compare", "default_thresholds", "load_side", "load_thresholds", "pair",
           "write_comparison"]
