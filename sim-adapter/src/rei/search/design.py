# SPDX-License-Identifier: EPL-2.0
"""TPE's start: a low-discrepancy initial design instead of random start-up trials.

TPE needs a few evaluated points before its model can steer. Optuna draws them with its RandomSampler, seeded as the
random baseline is: with the same seed, TPE's first trials were the random search's first trials, so it could only
find the first failure where random sampling did. Here they are the first points of a scrambled Sobol sequence
(SciPy's ``qmc.Sobol``, seeded by the search's seed): they spread over every parameter's range without the gaps and
clumps of independent draws, and they are fewer (``startup_trials``), so the model takes over sooner. They are
enqueued in the study before its first trial (Optuna's ``enqueue_trial``), so they live in the journal and a
resumed search neither draws nor repeats them.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np
from optuna.distributions import BaseDistribution, CategoricalDistribution, FloatDistribution, IntDistribution
from scipy.stats import qmc


def startup_trials(budget: int) -> int:
    """How many points the initial design has: a power of two (Sobol's balance), at most 8 and a quarter of the
    budget, at least 2."""
    return max(2, min(8, 2 ** int(math.log2(max(1, budget // 4)))))


def sobol_design(distributions: Mapping[str, BaseDistribution], count: int, seed: int) -> list[dict[str, Any]]:
    """``count`` points of a scrambled Sobol sequence over ``distributions``, as trial parameters (the keys in a
    fixed order, so a spec and seed always give the same design)."""
    names = sorted(distributions)
    if not names or count < 1:
        return []
    engine = qmc.Sobol(d=len(names), scramble=True, seed=seed)
    units = engine.random_base2(max(0, math.ceil(math.log2(count))))[:count]
    return [{name: _value(distributions[name], float(u)) for name, u in zip(names, row, strict=True)}
            for row in units]


def _value(distribution: BaseDistribution, u: float) -> Any:
    """The value at ``u`` in [0, 1) of ``distribution``'s range (a uniform cell per choice or integer)."""
    if isinstance(distribution, CategoricalDistribution):
        choices = distribution.choices
        return choices[min(int(u * len(choices)), len(choices) - 1)]
    if isinstance(distribution, IntDistribution):
        cells = (distribution.high - distribution.low) // distribution.step + 1
        return distribution.low + min(int(u * cells), cells - 1) * distribution.step
    if isinstance(distribution, FloatDistribution):
        low, high = distribution.low, distribution.high
        if distribution.log:
            return float(np.exp(np.log(low) + u * (np.log(high) - np.log(low))))
        value = low + u * (high - low)
        if distribution.step is not None:
            value = low + round((value - low) / distribution.step) * distribution.step
        return float(min(max(value, low), high))
    raise TypeError(f"no initial design for {distribution!r}")
