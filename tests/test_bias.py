"""Same-side bias p(ψ) of a precessing coin: closed form, inverse, averages, Monte Carlo."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from coinflight import Coin
from coinflight.core import precession, torque_free
from coinflight.model.distributions import Fixed, Normal, Uniform
from coinflight.studies import bias as b

# REFERENCES §2 (Diaconis, Holmes & Montgomery 2007): p(ψ) printed to 3 decimals, so the
# tolerance is half a unit of the last digit.
REFERENCE_P = [(60.0, 0.608), (70.0, 0.542), (80.0, 0.510), (90.0, 0.5)]


@pytest.mark.parametrize(("psi_deg", "printed"), REFERENCE_P)
def test_closed_form_matches_references(psi_deg, printed):
    assert float(b.same_side_probability(psi_deg, degrees=True)) == pytest.approx(printed, abs=5e-4)
    assert float(b.same_side_probability(math.radians(psi_deg))) == pytest.approx(printed, abs=5e-4)


def test_p_0508_needs_about_81_degrees():
    # REFERENCES §2: "p = 0.508 needs ψ ≈ 81°" (printed to the degree).
    assert float(b.psi_for_probability(0.508, degrees=True)) == pytest.approx(81.0, abs=0.5)


@pytest.mark.parametrize("psi_deg", [0.0, 10.0, 30.0, 44.9, 45.0, 135.0, 150.0, 180.0])
def test_coin_that_never_turns_over_always_lands_same_side(psi_deg):
    # ψ ≤ π/4 or ≥ 3π/4: cos²ψ ≥ sin²ψ, n(T)·n0 ≥ 0 for every phase (REFERENCES §2). At exactly
    # 45° and 135° the rounding of π/4 in binary moves p by at most ~1e-8 (square-root corner).
    assert float(b.same_side_probability(psi_deg, degrees=True)) == pytest.approx(1.0, abs=1e-7)


def test_closed_form_is_the_fraction_of_phases_that_land_same_side():
    # Independent of the arcsin formula: n·n0 = cos²ψ + sin²ψ cos φ over a fine uniform grid
    # of phases φ (midpoints of 10⁶ cells; grid error ≤ 2 cells = 2e-6).
    phi = (np.arange(1_000_000) + 0.5) * (2 * np.pi / 1_000_000)
    for psi in np.radians([50.0, 62.5, 75.0, 85.0, 95.0, 120.0]):
        frac = np.mean(np.cos(psi) ** 2 + np.sin(psi) ** 2 * np.cos(phi) > 0)
        assert float(precession.same_side_probability(psi)) == pytest.approx(frac, abs=2e-6)


@settings(max_examples=200, deadline=None)
@given(st.floats(min_value=0.0, max_value=180.0))
def test_symmetric_about_90_degrees_and_between_half_and_one(psi):
    p = float(b.same_side_probability(psi, degrees=True))
    assert 0.5 <= p <= 1.0
    assert p == pytest.approx(float(b.same_side_probability(180.0 - psi, degrees=True)), abs=1e-7)


@settings(max_examples=200, deadline=None)
@given(st.floats(min_value=45.5, max_value=89.9), st.floats(min_value=0.01, max_value=0.4))
def test_bias_falls_as_psi_approaches_90(psi, step):
    lower = float(b.same_side_probability(psi, degrees=True))
    higher = float(b.same_side_probability(min(psi + step, 90.0), degrees=True))
    assert lower > higher


@settings(max_examples=200, deadline=None)
@given(st.floats(min_value=46.0, max_value=90.0))
def test_inverse_round_trip(psi):
    p = b.same_side_probability(psi, degrees=True)
    assert float(b.psi_for_probability(p, degrees=True)) == pytest.approx(psi, abs=1e-7)


def test_inverse_edges():
    assert float(b.psi_for_probability(0.5)) == pytest.approx(math.pi / 2, abs=1e-12)
    assert float(b.psi_for_probability(1.0)) == pytest.approx(math.pi / 4, abs=1e-12)


@pytest.mark.parametrize("bad", [-0.1, 180.5, 400.0, math.nan, math.inf])
def test_psi_outside_0_180_degrees_is_a_clear_error(bad):
    with pytest.raises(ValueError, match=r"psi must be between 0 and 180 \(in degrees\)"):
        b.same_side_probability(bad, degrees=True)


def test_psi_in_radians_checked_against_pi():
    with pytest.raises(ValueError, match=r"between 0 and 3.14159 \(in rad\)"):
        b.same_side_probability(3.2)


@pytest.mark.parametrize("bad", [0.49, 1.01, -1.0])
def test_inverse_rejects_probabilities_outside_half_one(bad):
    with pytest.raises(ValueError, match=r"same-side probability must be between 0\.5 and 1"):
        b.psi_for_probability(bad)


@settings(max_examples=100, deadline=None)
@given(
    st.floats(min_value=0.0, max_value=math.pi),
    st.floats(min_value=1.0, max_value=500.0),
    st.sampled_from(["us-cent", "us-quarter", "gbp-1"]),
)
def test_spin_on_cone_has_the_asked_cone_angle_and_rate(psi, rate, coin_name):
    i1, i3 = Coin.preset(coin_name).moments
    w_perp, wz = precession.spin_on_cone(rate, psi, i1, i3)
    omega = np.array([w_perp, 0.0, wz])
    assert float(torque_free.cone_angle(omega, i1, i3)) == pytest.approx(psi, abs=1e-9)
    assert float(torque_free.precession_rate(omega, i1, i3)) == pytest.approx(rate, rel=1e-12)
    if 1e-3 < psi < math.pi - 1e-3:
        assert float(precession.axial_spin(w_perp, psi, i1, i3)) == pytest.approx(
            wz, rel=1e-9, abs=1e-9
        )


# Monte Carlo over the full torque-free flight. The tolerance has two parts: 4 binomial
# standard errors, and the departure of the finite ensemble (T ~ U[0.3, 0.7] s,
# ωp ~ U[150, 330] rad/s) from a uniform phase, for which the closed form is exact; a
# 4000 × 4000 midpoint grid over (T, ωp) at ψ = 90° gives 0.49985, i.e. 1.5e-4 (bound: 5e-4).
PHASE_BIAS = 5e-4
N_MC = 200_000


@pytest.mark.parametrize("psi_deg", [50.0, 60.0, 70.0, 80.0, 90.0, 115.0])
def test_monte_carlo_over_full_dynamics_matches_closed_form(psi_deg):
    est = b.simulate_same_side(psi_deg, N_MC, seed=20070, degrees=True)
    p = float(b.same_side_probability(psi_deg, degrees=True))
    assert est.n == N_MC
    assert est.stderr == pytest.approx(math.sqrt(est.p * (1 - est.p) / N_MC))
    assert abs(est.p - p) < 4 * est.stderr + PHASE_BIAS


def test_monte_carlo_independent_of_the_coin():
    # p depends on ψ alone; a thick £1 coin (I3/I1 furthest from 2) at ψ = 70°.
    est = b.simulate_same_side(70.0, N_MC, seed=5, degrees=True, coin=Coin.preset("gbp-1"))
    p = float(b.same_side_probability(70.0, degrees=True))
    assert abs(est.p - p) < 4 * est.stderr + PHASE_BIAS


def test_monte_carlo_detects_the_bias():
    # Negative test: at ψ = 70° the same-side excess (0.042) is far outside the noise of 1/2.
    est = b.simulate_same_side(70.0, N_MC, seed=11, degrees=True)
    assert est.p - 0.5 > 20 * est.stderr


def test_monte_carlo_is_reproducible_and_seeded():
    one = b.simulate_same_side(80.0, 150_000, seed=3, degrees=True)
    two = b.simulate_same_side(80.0, 150_000, seed=3, degrees=True)
    other = b.simulate_same_side(80.0, 150_000, seed=4, degrees=True)
    assert one == two
    assert one.seed == 3
    assert other.successes != one.successes


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"n": 0, "seed": 1}, "number of tosses must be at least 100"),
        ({"n": 100, "seed": -1}, "seed must be a non-negative integer"),
        ({"n": 100, "seed": 1, "flight_time": (0.7, 0.3)}, "low ≤ high"),
        ({"n": 100, "seed": 1, "precession_rate": (-1.0, 3.0)}, "precession rate range must be"),
    ],
)
def test_monte_carlo_bad_input(kwargs, message):
    with pytest.raises(ValueError, match=message):
        b.simulate_same_side(80.0, degrees=True, **kwargs)


def _psi_space_average(pdf, lo, hi):
    """Independent check: ∫ p(ψ) pdf(ψ) dψ in ψ-space (degrees), split at 45°, 90°, 135°."""
    from scipy.integrate import quad

    cuts = [x for x in (lo, 45.0, 90.0, 135.0, hi) if lo <= x <= hi]
    total = 0.0
    for a, c in itertools.pairwise(cuts):
        val, _ = quad(
            lambda x: float(b.same_side_probability(x, degrees=True)) * pdf(x),
            a,
            c,
            epsabs=1e-13,
            limit=200,
        )
        total += val
    return total


@pytest.mark.parametrize(("mean", "sd"), [(81.0, 5.0), (60.0, 8.0), (47.0, 3.0), (100.0, 12.0)])
def test_average_over_normal_psi_matches_psi_space_quadrature(mean, sd):
    from scipy.stats import norm

    expected = _psi_space_average(lambda x: norm.pdf(x, mean, sd), 0.0, 180.0)
    assert b.mean_same_side_probability(Normal(mean, sd), degrees=True) == pytest.approx(
        expected, abs=1e-8
    )
    assert b.mean_same_side_probability(Normal(mean, sd), degrees=True) == pytest.approx(
        expected, abs=1e-8
    )


def test_average_over_uniform_psi_matches_psi_space_quadrature():
    expected = _psi_space_average(lambda x: 1.0 / 40.0, 40.0, 80.0)
    got = b.mean_same_side_probability(Uniform(40.0, 80.0), degrees=True)
    assert got == pytest.approx(expected, abs=1e-8)


def test_average_over_a_fixed_angle_is_the_closed_form():
    assert b.mean_same_side_probability(Fixed(1.2)) == pytest.approx(
        float(b.same_side_probability(1.2)), abs=1e-12
    )


def test_monte_carlo_over_a_psi_distribution_matches_the_average():
    dist = Normal(75.0, 6.0)
    est = b.simulate_same_side(dist, N_MC, seed=9, degrees=True)
    p = b.mean_same_side_probability(dist, degrees=True)
    assert abs(est.p - p) < 4 * est.stderr + PHASE_BIAS


def test_distribution_reaching_outside_0_180_is_rejected():
    with pytest.raises(ValueError, match=r"must lie within \[0, 180\] degrees"):
        b.mean_same_side_probability(Normal(170.0, 5.0), degrees=True)
    with pytest.raises(ValueError, match=r"must lie within \[0, 3.14159\] rad"):
        b.mean_same_side_probability(Uniform(0.5, 3.5))


@pytest.mark.parametrize("sd", [0.0, 1.0, 4.0, 7.0])
def test_mean_psi_for_probability_round_trip(sd):
    target = 0.5077
    mean = b.psi_mean_for_probability(target, sd, degrees=True)
    assert mean < 90.0
    p = (
        float(b.same_side_probability(mean, degrees=True))
        if sd == 0
        else b.mean_same_side_probability(Normal(mean, sd), degrees=True)
    )
    assert p == pytest.approx(target, abs=1e-9)


def test_mean_psi_unreachable_with_wide_spread():
    # A spread of 10° alone gives 0.5104 > 0.5077 even with the mean at 90°.
    with pytest.raises(ValueError, match="cannot be reached"):
        b.psi_mean_for_probability(0.5077, 10.0, degrees=True)
