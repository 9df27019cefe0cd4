# SPDX-License-Identifier: EPL-2.0
"""The statistics of campaigns and comparisons, from SciPy's ``stats`` (docs/metrics.md, "Campaign aggregation"
and "Comparing two versions").

Why SciPy and not hand-written formulas: the bootstrap, the Wilcoxon signed-rank test and the exact binomial
test have edge cases (ties, zeros, tiny samples, exact versus normal approximation) that a well-kept library
already decides and documents. What is decided here is only what SciPy leaves open: a sample of one has no
interval, a sample without spread has the interval of its one value, and a paired sample without a non-zero
difference has p = 1 (nothing differs). SciPy is imported on first use: ``scipy.stats`` takes about a second
to import, which a campaign's workers and ``rei run`` never need.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

CONFIDENCE = 0.95
#: Bootstrap resamples: enough for a stable 95 % percentile interval (its ends move by well under 1 % of the
#: spread between seeds at this count), few enough that a comparison of many metrics stays fast.
RESAMPLES = 2000
#: The bootstrap's random numbers are seeded, so a report made twice from the same runs is the same.
SEED = 29


@dataclass(frozen=True, slots=True)
class Estimate:
    """A sample's mean with its 95 % bootstrap interval (None for fewer than two values), and its median."""

    n: int
    mean: float | None
    median: float | None
    low: float | None
    high: float | None


@dataclass(frozen=True, slots=True)
class Rate:
    """``k`` of ``n``, with the 95 % Wilson score interval."""

    n: int
    k: int
    rate: float | None
    low: float | None
    high: float | None


@dataclass(frozen=True, slots=True)
class Paired:
    """Paired differences (candidate - baseline): their mean with its bootstrap interval, and a test's p."""

    n: int
    mean: float | None
    low: float | None
    high: float | None
    p: float | None
    test: str


def _scipy() -> Any:
    from scipy import stats

    return stats


def estimate(values: Sequence[float]) -> Estimate:
    x = np.asarray([v for v in values if v is not None and math.isfinite(v)], dtype=float)
    if len(x) == 0:
        return Estimate(0, None, None, None, None)
    low, high = mean_interval(x)
    return Estimate(len(x), float(x.mean()), float(np.median(x)), low, high)


def mean_interval(x: np.ndarray) -> tuple[float | None, float | None]:
    """The 95 % percentile-bootstrap interval of the mean (scipy.stats.bootstrap)."""
    if len(x) < 2:
        return None, None
    if float(np.ptp(x)) == 0.0:
        return float(x[0]), float(x[0])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # a sample of a few distinct values warns of its own degeneracy
        result = _scipy().bootstrap((x,), np.mean, n_resamples=RESAMPLES, confidence_level=CONFIDENCE,
                                 method="percentile", vectorized=True, rng=np.random.default_rng(SEED))
    return float(result.confidence_interval.low), float(result.confidence_interval.high)


def rate(flags: Sequence[bool | None]) -> Rate:
    known = [bool(f) for f in flags if f is not None]
    n, k = len(known), sum(known)
    if n == 0:
        return Rate(0, 0, None, None, None)
    interval = _scipy().binomtest(k, n).proportion_ci(CONFIDENCE, method="wilson")
    return Rate(n, k, k / n, float(interval.low), float(interval.high))


def paired_continuous(differences: Sequence[float]) -> Paired:
    """Mean difference with its bootstrap interval; Wilcoxon signed-rank test (zero differences dropped)."""
    d = np.asarray([v for v in differences if v is not None and math.isfinite(v)], dtype=float)
    if len(d) == 0:
        return Paired(0, None, None, None, None, "wilcoxon")
    low, high = mean_interval(d)
    if not np.any(d != 0):
        p = 1.0
    else:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            p = float(_scipy().wilcoxon(d, zero_method="wilcox").pvalue)
    return Paired(len(d), float(d.mean()), low, high, p, "wilcoxon")


def paired_success(pairs: Sequence[tuple[bool, bool]]) -> Paired:
    """Change of the success rate (candidate - baseline) with its bootstrap interval; McNemar's exact test: a
    two-sided binomial test of the discordant pairs (success lost against success gained) at 1/2."""
    if not pairs:
        return Paired(0, None, None, None, None, "mcnemar-exact")
    d = np.array([int(c) - int(b) for b, c in pairs], dtype=float)
    lost, gained = int(np.sum(d < 0)), int(np.sum(d > 0))
    p = 1.0 if lost + gained == 0 else float(_scipy().binomtest(gained, lost + gained, 0.5).pvalue)
    low, high = mean_interval(d)
    return Paired(len(d), float(d.mean()), low, high, p, "mcnemar-exact")
