# SPDX-License-Identifier: EPL-2.0
"""TPE's initial design (rei.search.design): Sobol points inside every parameter's domain, spread over it."""

from __future__ import annotations

from optuna.distributions import CategoricalDistribution, FloatDistribution, IntDistribution

from rei.search.design import sobol_design, startup_trials

SPACE = {"walker.start": FloatDistribution(0.0, 60.0), "seed": IntDistribution(0, 3),
         "bin1.floor": CategoricalDistribution(["F_0_0", "F_1_0", "F_2_0", "F_3_0"]),
         "fault.rate": FloatDistribution(0.001, 0.1, log=True)}


def test_the_design_size_is_a_power_of_two_within_a_quarter_of_the_budget() -> None:
    assert [startup_trials(b) for b in (1, 8, 16, 30, 32, 200)] == [2, 2, 4, 4, 8, 8]


def test_every_point_is_inside_its_domain_and_the_design_spreads_over_each_range() -> None:
    design = sobol_design(SPACE, 8, seed=3)
    assert design == sobol_design(SPACE, 8, seed=3) and design != sobol_design(SPACE, 8, seed=4)
    for point in design:
        assert 0.0 <= point["walker.start"] <= 60.0 and 0.001 <= point["fault.rate"] <= 0.1
    # Sobol's balance: 8 points put 2 in each quarter of a range, each integer and each choice twice
    assert sorted(int(p["walker.start"] // 15) for p in design) == [0, 0, 1, 1, 2, 2, 3, 3]
    assert sorted(p["seed"] for p in design) == [0, 0, 1, 1, 2, 2, 3, 3]
    assert sorted(p["bin1.floor"] for p in design) == ["F_0_0", "F_0_0", "F_1_0", "F_1_0", "F_2_0", "F_2_0",
                                                      "F_3_0", "F_3_0"]


def test_an_empty_space_has_no_design() -> None:
    assert sobol_design({}, 8, seed=0) == []
