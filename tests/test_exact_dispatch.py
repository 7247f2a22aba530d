"""The exact method's one table of integrals: a distribution gets the first integral that
applies to it (``details["how"]``), and its cost is estimated, before anything runs, from the
work of that same integral (:func:`coinflight.probability.exact.estimated_seconds`)."""

from __future__ import annotations

import pytest

from coinflight.model.distributions import Normal, TruncatedNormal, Uniform
from coinflight.model.ensemble import TossDistribution
from coinflight.outcomes import outcome_model
from coinflight.probability import estimate, exact
from coinflight.probability.exact import gauss

T = Uniform(0.6, 0.9)  # Stefan & Cheche's flight times (Figs 2-3)
GAUSS = "closed form in T, Gauss product rule over the spins split at ψ = 45°"
CASES = {
    "closed form": TossDistribution(omega_x=Uniform(60, 90), flight_time=T),
    "closed form in T": TossDistribution(omega_x=80, omega_z=10, flight_time=Normal(0.7, 0.05)),
    "closed form in one spin, quadrature in the other": TossDistribution(
        omega_x=Uniform(60, 90), omega_y=Normal(0, 5), flight_time=T
    ),
    GAUSS: TossDistribution(omega_x=Uniform(60, 90), flight_time=Normal(0.75, 0.05)),
    "closed form in T, Gauss–Legendre over the spins in (Ω, ψ)": TossDistribution(
        omega_x=Uniform(60, 90), omega_y=10, omega_z=Uniform(0, 40), flight_time=T
    ),
    "closed form in T, quadrature over the spins": TossDistribution(
        omega_x=TruncatedNormal(80, 10, 60, 100), flight_time=T
    ),
}


@pytest.mark.parametrize("how", list(CASES))
def test_each_distribution_gets_its_integral_and_its_estimate(how):
    dist = CASES[how]
    result = estimate(dist, "exact")
    assert result.details["how"] == how
    seconds = exact.estimated_seconds(dist)
    if "quadrature" in how:  # adaptive: it ends within its own bound, not estimated
        assert seconds is None
    elif how == "closed form in T":  # a sum of a few band terms
        assert seconds == 1e-4
    else:
        assert seconds is not None and seconds > 1e-4


def test_the_gauss_rule_is_estimated_from_its_first_two_orders():
    # The estimate is the spin points of the first two orders at the measured rate: the run
    # uses at least those, exactly those when the second order already agrees.
    dist = CASES[GAUSS]
    seconds = exact.estimated_seconds(dist)
    result = estimate(dist, "exact")
    counted = seconds * gauss.SPIN_POINTS_PER_SECOND
    assert result.details["spin points"] >= counted * (1 - 1e-12)
    if result.details["nodes per panel"] == gauss.GAUSS_ORDERS[1]:
        assert result.details["spin points"] == pytest.approx(counted, rel=1e-12)


def test_a_model_without_closed_form_bands_is_refused_and_not_estimated():
    table = outcome_model("table")
    with pytest.raises(ValueError, match="the exact method handles the hand catch only"):
        estimate(CASES["closed form"], "exact", model=table)
    assert exact.estimated_seconds(CASES["closed form"], table) is None
