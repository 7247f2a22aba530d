"""``exact`` for ranged spins with a normal flight time (issue 12, first item).

The Gauss product rule over the spins (closed form in T, split at ψ = 45°) is checked against
the adaptive QUADPACK quadrature it replaces where both apply (to 1e-9), against Monte Carlo
(10⁸ tosses, within 4 standard errors) where the old method refused (three ranged spins), on
the heads/tails symmetry, and on the ``human`` preset's value before this change.
"""

from __future__ import annotations

import numpy as np
import pytest

from coinflight.model.distributions import Normal, Uniform
from coinflight.model.ensemble import TossDistribution
from coinflight.probability import estimate
from coinflight.probability.exact import closed_form, common, gauss, omega_psi, quadrature
from coinflight.studies.presets import human

GAUSS = "closed form in T, Gauss product rule over the spins split at ψ = 45°"


def _old(dist: TossDistribution) -> float:
    """The adaptive quadrature (QUADPACK) that ran before, called directly."""
    ranged = [n for n in common._SPINS if not getattr(dist, n).is_fixed]
    return quadrature._closed_form_in_t_quadrature(dist, ranged, {})[0]


def test_human_preset_keeps_its_value():
    # 0.508009: `coinflight probability --preset human` before this change (QUADPACK, 1e-9).
    result = estimate(human(), "exact")
    assert result.details["how"] == GAUSS
    assert result.p_heads == pytest.approx(0.508009, abs=1e-6)
    assert result.error_estimate <= 1e-9


@pytest.mark.parametrize(
    "spins",
    [
        # one ranged spin, ω_z fixed: the kink in ωx at ±√(((I3/I1) ω_z)² − ωy²)
        {"omega_x": Normal(60.0, 6.0), "omega_z": 28.0},
        {"omega_x": Uniform(20.0, 70.0), "omega_y": 10.0, "omega_z": 30.0},
        # ω_z ranged: the kink in ω_z at ±(I1/I3) Ω⊥
        {"omega_x": 60.0, "omega_z": Uniform(-80.0, 80.0)},
        # ω_z = 0 (no kink), both diameter spins ranged, one across 0
        {"omega_x": Normal(60.0, 6.0), "omega_y": Uniform(-20.0, 30.0)},
    ],
)
def test_agrees_with_the_old_quadrature(spins):
    dist = TossDistribution(**spins, flight_time=Normal(0.4, 0.04))
    result = estimate(dist, "exact")
    assert result.details["how"] == GAUSS
    assert result.p_heads == pytest.approx(_old(dist), abs=1e-9)


def test_a_tail_that_the_old_quadrature_missed():
    # (I3/I1) ω_z ≈ 79.4 rad/s: only ωx beyond 3.2 sd turns the coin over. QUADPACK over the
    # quantile saw 1 everywhere and returned 1.0; the reference here is scipy's quad in ωx split
    # at the kink, 1e-13 each part.
    from scipy.integrate import quad

    dist = TossDistribution(omega_x=Normal(60.0, 6.0), omega_z=40.0, flight_time=Normal(0.4, 0.04))
    i1, i3 = dist.moments
    k = i3 / i1 * 40.0

    def f(x: float) -> float:
        density = np.exp(-0.5 * ((x - 60.0) / 6.0) ** 2) / (6.0 * np.sqrt(2.0 * np.pi))
        return closed_form._p_same_fixed_spins(x, 0.0, 40.0, dist.flight_time, i1, i3) * density

    reference = sum(
        quad(f, lo, hi, epsabs=1e-13, limit=500)[0] for lo, hi in ((0.0, k), (k, 200.0))
    )
    assert 1.0 - reference > 4e-5  # the tail is there
    assert estimate(dist, "exact").p_heads == pytest.approx(reference, abs=1e-9)


def _random_box(rng: np.random.Generator) -> dict[str, object]:
    """Three ranged spins (uniform or normal) and a normal flight time."""
    spins: dict[str, object] = {}
    for name in ("omega_x", "omega_y", "omega_z"):
        mean = rng.uniform(-60.0, 60.0)
        width = rng.uniform(5.0, 40.0)
        spins[name] = (
            Uniform(mean - width, mean + width) if rng.random() < 0.5 else Normal(mean, width / 2)
        )
    t = rng.uniform(0.3, 0.6)
    return {**spins, "flight_time": Normal(t, t * rng.uniform(0.02, 0.15))}


OMEGA_PSI = "closed form in T, Gauss–Legendre over the spins in (Ω, ψ)"


@pytest.mark.slow
@pytest.mark.parametrize("case", [0, 1, 2, 3])
def test_three_ranged_spins_agree_with_monte_carlo(case):
    # Refused before (three ranged spin components); now the (Ω, ψ) rule with the
    # wrapped-normal series inside. 10⁸ tosses (issue 12's criterion), within 4 standard
    # errors.
    dist = TossDistribution(**_random_box(np.random.default_rng(1200 + case)))
    result = estimate(dist, "exact")
    assert result.details["how"] == OMEGA_PSI
    assert result.error_estimate <= 1e-9
    mc = estimate(dist, "monte-carlo", n=10**8, seed=12 + case)
    se = max(mc.stderr, 1e-9)
    assert abs(result.p_heads - mc.p_heads) <= 4 * se


@pytest.mark.parametrize("case", [0, 2])
def test_three_ranged_spins_two_rules_agree(case):
    # The Gauss product rule over (ωx, ωy, ω_z) (split at ψ = 45° on a coordinate) and the
    # (Ω, ψ) rule (azimuth integrated out, cuts at the box's curves) share only the
    # wrapped-normal series: they agree within their tolerances (1e-9 each).
    dist = TossDistribution(**_random_box(np.random.default_rng(1200 + case)))
    ranged = list(common._SPINS)
    product = gauss._gauss_spins(dist, ranged, {})[0]
    assert estimate(dist, "exact").p_same_side == pytest.approx(product, abs=2e-9)


@pytest.mark.parametrize(
    "spins",
    [
        # ω_z fixed ≠ 0 with the azimuth integrated out (a 1-D rule along A = const)
        {"omega_x": Normal(60.0, 6.0), "omega_y": Uniform(-20.0, 30.0), "omega_z": 25.0},
        {"omega_x": Uniform(-40.0, 50.0), "omega_y": Normal(5.0, 10.0), "omega_z": -15.0},
        # one spin fixed: the density of Ω⊥ with its inverse square root
        {"omega_x": Normal(60.0, 6.0), "omega_y": Uniform(-20.0, 30.0)},
        {"omega_x": 60.0, "omega_z": Uniform(-80.0, 80.0)},
    ],
)
def test_two_ranged_spins_two_rules_agree(spins):
    # As above, where the Gauss rule runs by default (one or two ranged spins).
    dist = TossDistribution(**spins, flight_time=Normal(0.4, 0.04))
    ranged = [n for n in common._SPINS if not getattr(dist, n).is_fixed]
    result = estimate(dist, "exact")
    assert result.details["how"] == GAUSS
    assert omega_psi._omega_psi(dist, ranged, {})[0] == pytest.approx(result.p_same_side, abs=2e-9)


def test_where_the_gauss_rule_refuses_the_omega_psi_rule_answers():
    # ωx and ω_z across 0 with a narrow normal T: the Gauss rule does not converge by 64 nodes
    # a panel (5e-8 apart); the (Ω, ψ) rule does, and the result says so.
    dist = TossDistribution(
        omega_x=Uniform(-85.0, 85.0), omega_z=Uniform(-85.0, 85.0), flight_time=Normal(0.6, 0.03)
    )
    result = estimate(dist, "exact")
    assert result.details["how"] == OMEGA_PSI
    assert "did not reach its tolerance" in result.details["fallback"]
    assert result.error_estimate <= 1e-9
    mc = estimate(dist, "monte-carlo", n=10**7, seed=5)
    assert abs(result.p_heads - mc.p_heads) <= 4 * mc.stderr


def test_heads_and_tails_are_symmetric():
    kw = {
        "omega_x": Normal(240.0, 24.0),
        "omega_y": 0.0,
        "omega_z": Normal(0.0, 40.0),
        "launch_speed": Normal(2.4, 0.24),
    }
    heads = estimate(TossDistribution.from_launch_speed(**kw, start="heads"), "exact")
    tails = estimate(TossDistribution.from_launch_speed(**kw, start="tails"), "exact")
    assert heads.p_heads == pytest.approx(tails.p_tails, abs=1e-15)
    assert heads.p_heads + heads.p_tails == pytest.approx(1.0, abs=1e-15)


def test_work_is_bounded_before_it_starts(monkeypatch):
    # A flight time so narrow that P(same | spins) oscillates with the spins (period 2π/T)
    # over three wide spin ranges: the first two orders (the least that gives an error
    # estimate) already pass the bound (thousands of band edges to cross with the box's
    # curves), refused before anything is computed: the integrand is never evaluated (checked
    # by an integral that fails if called, not by a clock: the machine is shared).
    from coinflight.probability.exact import omega_psi

    def never(self, n):
        raise AssertionError(f"the integral ran ({n} nodes a panel) before the work bound")

    monkeypatch.setattr(omega_psi._PolarPlan, "integral", never)
    dist = TossDistribution(
        omega_x=Uniform(100.0, 6100.0),
        omega_y=Uniform(100.0, 6100.0),
        omega_z=Uniform(100.0, 6100.0),
        flight_time=Normal(1.0, 1e-4),
    )
    with pytest.raises(ValueError, match="use --method grid, monte-carlo or qmc instead"):
        estimate(dist, "exact")


def _monte_carlo_check(dist: TossDistribution, seed: int) -> None:
    """exact within 4 s.e. of 10⁸ plain Monte Carlo tosses (issue 12); the exact error ≤ 1e-9."""
    result = estimate(dist, "exact")
    assert result.error_estimate <= 1e-9
    mc = estimate(dist, "monte-carlo", n=10**8, seed=seed)
    assert abs(result.p_heads - mc.p_heads) <= 4 * mc.stderr


def test_the_issues_examples_agree_with_monte_carlo():
    # `coinflight probability --preset human` and the normal-spin example of issue 12.
    _monte_carlo_check(human(), 121)
    example = TossDistribution.from_launch_speed(
        Normal(240.0, 24.0), 0.0, Normal(0.0, 40.0), Normal(2.4, 0.24)
    )
    _monte_carlo_check(example, 122)


@pytest.mark.parametrize(
    "spins",
    [
        # ω_z fixed ≠ 0 with both ωx and ωy ranged: the circle Ω⊥ = (I3/I1)|ω_z| in polar
        # coordinates (an nquad fallback before)
        {"omega_x": Normal(60.0, 6.0), "omega_y": Uniform(-20.0, 30.0), "omega_z": 25.0},
        {"omega_x": Uniform(-40.0, 50.0), "omega_y": Normal(5.0, 10.0), "omega_z": -15.0},
    ],
)
def test_fixed_axial_spin_with_two_ranged_spins(spins):
    dist = TossDistribution(**spins, flight_time=Normal(0.4, 0.04))
    assert estimate(dist, "exact").details["how"] == GAUSS
    _monte_carlo_check(dist, 123)


@pytest.mark.parametrize("sd", [0.002, 0.02, 0.06])
def test_wrapped_normal_series_equals_the_band_sum(sd):
    # The Fourier series of the wrapped normal (Mardia & Jupp §3.5.7) against the direct sum
    # of normal-CDF differences over every band (Diaconis, Holmes & Montgomery 2007), at
    # phase spreads σ = ωp·sd on both sides of the switch at 1.5, to rounding. (sd ≤ mean/8,
    # as TossDistribution requires: the series also counts T < 0.)
    from scipy.special import ndtr

    from coinflight.core import bands

    rng = np.random.default_rng(7)
    perp2 = rng.uniform(0.0, 400.0, 5000) ** 2
    axial2 = rng.uniform(0.0, 300.0, 5000) ** 2 * rng.random(5000)
    mean = 0.5
    direct = bands.same_side_over_times(
        perp2, axial2, lambda t: ndtr((t - mean) / sd), max(0.0, mean - 9 * sd), mean + 9 * sd
    )
    series = bands.same_side_normal_time(perp2, axial2, mean, sd)
    sigma = np.sqrt(perp2 + axial2) * sd
    if sd == 0.02:
        assert np.any(sigma < bands.WRAPPED_SIGMA) and np.any(sigma >= bands.WRAPPED_SIGMA)
    np.testing.assert_allclose(series, direct, rtol=0, atol=1e-13)
