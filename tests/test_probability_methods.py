"""P(heads) over ranges of tosses: exact, grid (method A), Monte Carlo (B) and QMC agree.

Reference values: the founding paper prints no probabilities for its Figs 2a-b and 3a-b, only
that both methods "tend to the unbiased value of 50 %". The paper-reproduction tests therefore
compare every method with coinflight's exact band integral and check |p − ½| < 0.005 (the
estimates round to 50 % at the whole-percent resolution the figures are read at).
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from coinflight.core import bands, sampling
from coinflight.core.torque_free import normal_alignment
from coinflight.model.distributions import Fixed, Normal, TruncatedNormal, Uniform
from coinflight.model.ensemble import TossDistribution
from coinflight.outcomes.base import OutcomeModel
from coinflight.probability import PAPER_B_CELLS, ProbabilityResult, estimate, wilson_interval

T_RANGE = Uniform(0.6, 0.9)  # Stefan & Cheche §3: T ∈ [0.6, 0.9] s in Figs 2-3
PAPER = {
    # Stefan & Cheche §3 / REFERENCES §1
    "fig2a": TossDistribution(Uniform(60, 90), 0, 0, T_RANGE),
    "fig2b": TossDistribution(Uniform(90, 120), 0, 0, T_RANGE),
    "fig3a": TossDistribution(Uniform(60, 90), 10, 0, T_RANGE),
    "fig3b": TossDistribution(Uniform(60, 90), 60, 0, T_RANGE),
}
OTHER = {
    "negative-spins": TossDistribution(Uniform(-30, 90), 10, 0, T_RANGE),
    "two-spins": TossDistribution(Uniform(60, 90), Uniform(-10, 20), 0, T_RANGE),
    "precessing": TossDistribution(Uniform(60, 90), 10, 40, T_RANGE),
    "normal-time": TossDistribution(Uniform(60, 90), 0, 0, Normal(0.75, 0.05)),
    "tails-up": TossDistribution(Uniform(30, 50), 0, 0, Uniform(0.3, 0.4), start="tails"),
}
BOXES = {**PAPER, **OTHER}


class Generic(OutcomeModel):
    """The hand catch by the NumPy closed form, no compiled kernel: a brute-force reference."""

    def count(self, dist, u):
        wx, wy, wz, t = dist.values(u)
        i1, i3 = dist.moments
        same = int(np.count_nonzero(normal_alignment(wx, wy, wz, t, i1, i3) > 0.0))
        n = u.shape[1]
        heads = same if dist.start == "heads" else n - same
        return np.array([n - heads, heads, 0], dtype=np.int64)


@pytest.mark.parametrize("name", list(PAPER))
def test_paper_figures_approach_one_half(name):
    dist = PAPER[name]
    exact = estimate(dist, "exact")
    assert exact.details["how"] == "closed form"
    assert abs(exact.p_heads - 0.5) < 0.005
    # Method A at the paper's 5000 × 5000; its count differs from the integral by O(1e-5).
    a = estimate(dist, "grid", n=5000)
    assert a.samples == 5000**2
    assert abs(a.p_heads - exact.p_heads) < 1e-4
    # Method B: 100 cells per parameter, 2²⁰ events: within 4 standard errors of that grid.
    coarse = estimate(dist, "grid", n=PAPER_B_CELLS)
    b = estimate(dist, "monte-carlo", n=1 << 20, seed=2, grid_cells=PAPER_B_CELLS)
    assert abs(b.p_heads - coarse.p_heads) < 4 * b.stderr
    assert abs(b.p_heads - 0.5) < 0.005


@pytest.mark.parametrize("name", [*PAPER, "negative-spins", "tails-up"])
def test_exact_agrees_with_fine_grid(name):
    # Grid error measured at ~3e-7 for N = 20000 on these boxes; the issue asks for 1e-6.
    dist = BOXES[name]
    assert estimate(dist, "grid", n=20000).p_heads == pytest.approx(
        estimate(dist, "exact").p_heads, abs=1e-6
    )


@pytest.mark.parametrize("name", list(BOXES))
def test_grid_converges_to_exact(name):
    dist = BOXES[name]
    exact = estimate(dist, "exact").p_heads
    # Band counting needs a uniform flight time; otherwise every configuration is evaluated.
    big = 400 if len(dist.ranged) > 2 else 8000
    errors = [abs(estimate(dist, "grid", n=n).p_heads - exact) for n in (big // 20, big)]
    assert errors[1] < 2e-5 if len(dist.ranged) <= 2 else errors[1] < 5e-4
    assert errors[1] < errors[0] or errors[0] < 1e-6


@pytest.mark.parametrize("name", list(BOXES))
def test_monte_carlo_and_qmc_agree_with_exact(name):
    dist = BOXES[name]
    exact = estimate(dist, "exact")
    for result in (
        estimate(dist, "monte-carlo", n=1 << 20, seed=11),
        estimate(dist, "qmc", n=16 << 12, seed=11),
    ):
        assert result.stderr is not None and result.stderr > 0
        assert abs(result.p_heads - exact.p_heads) < 4 * result.stderr, result.method
        lo, hi = result.ci95
        assert lo < result.p_heads < hi


def test_grid_band_counting_equals_brute_force():
    cases = [
        *BOXES.values(),
        TossDistribution(Uniform(5, 20), 0, Uniform(-400, 400), Uniform(0.3, 0.9), start="tails"),
        TossDistribution(0.0, 0.0, 30.0, Uniform(0.3, 0.9)),  # no transverse spin
    ]
    for dist in cases:
        for n in (7, 60):
            fast = estimate(dist, "grid", n=n)
            slow = estimate(dist, "grid", n=n, model=Generic())
            assert fast.counts == slow.counts
            assert fast.details["how"] == "band counting along the flight time"
            assert slow.details["how"] == "every configuration evaluated"


def test_exact_precession_matches_diaconis_formula():
    # REFERENCES §2: over many turns, P(same side) = 1/2 + arcsin(cot²ψ)/π; ψ = 60° → 0.608.
    coin = TossDistribution(0, 0, 0, 1.0).coin
    i1, i3 = coin.moments
    w_perp = 100.0
    wz = i1 * w_perp / (i3 * math.tan(math.radians(60.0)))
    dist = TossDistribution(w_perp, 0, wz, Uniform(1.0, 50.0))
    p = estimate(dist, "exact").p_same_side
    expected = 0.5 + math.asin(1.0 / math.tan(math.radians(60.0)) ** 2) / math.pi
    assert p == pytest.approx(expected, abs=1e-3)  # averaging over ~900 turns: error < 1e-3
    assert round(p, 3) == 0.608


def test_small_psi_is_detected_as_biased():
    # The negative test: spin mostly about the normal (ψ < 45°): the coin only wobbles.
    dist = TossDistribution(Uniform(5, 10), 0, Uniform(300, 400), Uniform(0.5, 0.7))
    for result in (
        estimate(dist, "monte-carlo", n=100_000, seed=5),
        estimate(dist, "qmc", n=16 << 10, seed=5),
        estimate(dist, "grid", n=200),
    ):
        assert result.p_same_side == 1.0
    mc = estimate(dist, "monte-carlo", n=100_000, seed=5)
    assert abs(mc.p_heads - 0.5) > 4 * max(mc.stderr, 1 / math.sqrt(mc.n))
    assert mc.ci95[0] > 0.5
    # And a box partly in the wobble regime: clearly above ½, by every method.
    mixed = TossDistribution(Uniform(20, 80), 0, Uniform(100, 200), T_RANGE)
    mc = estimate(mixed, "monte-carlo", n=1 << 18, seed=5)
    assert mc.p_same_side - 0.5 > 10 * mc.stderr


def test_seed_reproducible_whatever_chunks_and_threads():
    dist = TossDistribution(Uniform(60, 90), Uniform(-10, 10), Uniform(-5, 5), T_RANGE)
    n = 3 * (1 << 20) + 12345
    results = [
        estimate(dist, "monte-carlo", n=n, seed=42, threads=1, chunk_size=1 << 30),
        estimate(dist, "monte-carlo", n=n, seed=42, threads=2, chunk_size=1),
        estimate(dist, "monte-carlo", n=n, seed=42, executor=_MapExecutor(), chunk_size=2 << 20),
    ]
    assert len({r.counts for r in results}) == 1
    assert results[0].seed == 42
    other = estimate(dist, "monte-carlo", n=n, seed=43)
    assert other.counts != results[0].counts
    q = [estimate(dist, "qmc", n=16 << 10, seed=3, threads=t) for t in (1, 2)]
    assert q[0].counts == q[1].counts
    q.append(estimate(dist, "qmc", n=16 << 10, seed=3, executor=_MapExecutor()))
    assert q[2].counts == q[0].counts


def test_compiled_and_numpy_outcomes_agree_on_the_same_draws():
    # Monte Carlo hands every outcome model the same unit-cube points: the compiled kernel and
    # the NumPy closed form must count the same faces, for plain draws and for method B.
    dist = TossDistribution(Uniform(60, 90), 10, 0, T_RANGE)
    fast = estimate(dist, "monte-carlo", n=50_000, seed=9)
    slow = estimate(dist, "monte-carlo", n=50_000, seed=9, model=Generic())
    assert fast.counts == slow.counts
    b_fast = estimate(dist, "monte-carlo", n=50_000, seed=9, grid_cells=100)
    b_slow = estimate(dist, "monte-carlo", n=50_000, seed=9, grid_cells=100, model=Generic())
    assert b_fast.counts == b_slow.counts


def test_progress_reports_all_work():
    dist = PAPER["fig2a"]
    done = []
    estimate(dist, "monte-carlo", n=(1 << 20) + 7, seed=1, chunk_size=1, progress=done.append)
    assert sum(done) == (1 << 20) + 7 and len(done) == 2
    # By default too, the progress moves once per block of 2²⁰ tosses (a bar that moves).
    done.clear()
    estimate(dist, "monte-carlo", n=3 << 20, seed=1, progress=done.append)
    assert done == [1 << 20] * 3
    done.clear()
    estimate(dist, "grid", n=300, progress=done.append)
    assert sum(done) == 300**2


class _MapExecutor:
    """The smallest executor: anything with ``map``."""

    def map(self, fn, *iterables):
        return map(fn, *iterables)


def test_result_is_consistent():
    for method, n in (("exact", None), ("grid", 50), ("monte-carlo", 1000), ("qmc", 16 << 4)):
        seed = 1 if method in ("monte-carlo", "qmc") else None
        r = estimate(PAPER["fig3a"], method, n=n, seed=seed)
        assert r.seed == seed
        assert isinstance(r, ProbabilityResult)
        assert r.p_heads + r.p_tails + r.p_edge == pytest.approx(1.0, abs=1e-15)
        assert r.p_same_side == r.p_heads  # started heads up
        assert r.method == method and r.n == n
        d = r.to_dict()
        assert {"p_heads", "p_tails", "method", "n", "stderr", "ci95"} <= set(d)


def test_wilson_interval():
    # Wilson (1927): 0 of 10 → [0, z²/(n + z²)] = [0, 0.2775]; 5 of 10 → 0.5 ± 0.2634.
    assert wilson_interval(0, 10) == pytest.approx((0.0, 0.27754), abs=1e-5)
    lo, hi = wilson_interval(5, 10)
    assert (lo, hi) == pytest.approx((0.23659, 0.76341), abs=1e-5)
    # The same numbers as SciPy's implementation.
    from scipy.stats import binomtest

    for k, n in ((0, 10), (3, 10), (10, 10), (178_078, 350_757), (1, 10**9)):
        ci = binomtest(k, n).proportion_ci(method="wilson")
        assert wilson_interval(k, n) == pytest.approx((ci.low, ci.high), rel=1e-12, abs=1e-15)


@pytest.mark.parametrize(
    ("kwargs", "error", "words"),
    [
        ({"method": "magic"}, ValueError, "unknown method 'magic'"),
        ({"method": "grid", "n": 0}, ValueError, "n must be at least 1"),
        ({"method": "monte-carlo", "n": -5}, ValueError, "n must be at least 1"),
        ({"method": "qmc", "n": 1000}, ValueError, "power of two"),
        ({"method": "exact", "n": 10}, ValueError, "takes no n"),
        ({"method": "grid", "n": 2.5}, TypeError, "n must be an integer"),
        ({"method": "grid", "grid_cells": 5}, TypeError, "no option grid_cells"),
        ({"method": "monte-carlo", "seed": -1}, ValueError, "seed"),
        # Options a method cannot use are refused, not dropped.
        ({"method": "exact", "seed": 5}, TypeError, "'exact' takes no seed"),
        ({"method": "grid", "n": 10, "seed": 5}, TypeError, "'grid' takes no seed"),
        ({"method": "exact", "threads": 2}, TypeError, "'exact' takes no option threads"),
        ({"method": "exact", "executor": map}, TypeError, "'exact' takes no option executor"),
        ({"method": "exact", "progress": print}, TypeError, "'exact' takes no option progress"),
    ],
)
def test_bad_requests(kwargs, error, words):
    with pytest.raises(error, match=words):
        estimate(PAPER["fig2a"], **kwargs)


@pytest.mark.parametrize(
    "dist",
    [
        # refused before issue 12: precession with a fixed flight time, three ranged spins
        TossDistribution(Uniform(60, 90), 0, Uniform(1, 2), 0.7),
        TossDistribution(Uniform(60, 90), Uniform(0, 1), Uniform(1, 2), T_RANGE),
    ],
)
def test_exact_integrates_what_it_refused_before(dist):
    result = estimate(dist, "exact")
    assert result.details["how"] == "closed form in T, Gauss–Legendre over the spins in (Ω, ψ)"
    assert result.error_estimate <= 1e-9


def test_exact_refuses_what_it_cannot_integrate():
    # A truncated normal spin (a library-only distribution), precession, a fixed flight time.
    dist = TossDistribution(
        Uniform(60, 90), TruncatedNormal(0.0, 1.0, -2.0, 2.0), Uniform(-5, 5), 0.7
    )
    with pytest.raises(ValueError, match="fixed, uniform and normal distributions only") as info:
        estimate(dist, "exact")
    assert "grid, monte-carlo or qmc" in str(info.value)


@pytest.mark.parametrize(
    ("t", "face"),
    # Stefan & Cheche Figs 3c-f (ωx0 = 90, ωy0 = 30 rad/s): faces by their eq 14, as in
    # tests/test_paper_rotations.py.
    [(0.6, "heads"), (0.65, "heads"), (0.7, "tails"), (0.75, "tails")],
)
def test_exact_single_toss_is_its_face(t, face):
    d = TossDistribution(90.0, 30.0, 0, Fixed(t))
    for method in ("exact", "grid"):
        assert estimate(d, method).p_heads == (1.0 if face == "heads" else 0.0)


def test_band_measure_kernel():
    u = np.linspace(0.0, 60.0, 200_001)
    for a in (np.pi / 2, 2.0, 3.0):
        inside = bands.in_band(u, a).astype(float)
        # Cumulative trapezoid of the indicator ≈ F(u) to the grid spacing.
        numeric = np.concatenate([[0.0], np.cumsum(0.5 * (inside[1:] + inside[:-1]) * np.diff(u))])
        assert np.max(np.abs(numeric - bands.phase_measure(u, a))) < 1e-3


def test_fast_sin_is_accurate():
    # The docstring's claim: absolute error ≤ 3.4e-16 for |x| ≤ 1e7 (libm's sin as reference).
    special = np.array([0.0, -0.0, 1e-300, -1e-300, np.pi, -np.pi, np.pi / 2, 3e6, -3e6, 1e7])
    assert [sampling.sin(v) for v in special[:4]] == [0.0, -0.0, 1e-300, -1e-300]
    for v in special:
        assert abs(sampling.sin(v) - np.sin(v)) <= 3.4e-16, v
    rng = np.random.default_rng(10)
    x = np.concatenate([np.linspace(-1e3, 1e3, 20_001), rng.uniform(-1e7, 1e7, 20_000)])
    got = np.array([sampling.sin(v) for v in x])
    assert np.max(np.abs(got - np.sin(x))) <= 3.4e-16
    # Beyond, the reduction loses bits, but the error stays below the spacing of the
    # argument itself (the phase is not known better than that).
    for v in (1e8, -1e8, 3e8, 1e9):
        assert abs(sampling.sin(v) - np.sin(v)) < abs(np.spacing(v)), v
    assert sampling.sinc(0.0) == 1.0


def test_compiled_kernels_match_numpy_closed_form():
    # Guards the numba cache too: a kernel compiled from an older normal_alignment would differ.

    rng = np.random.default_rng(8)
    n = 200_000
    wx, wy = rng.uniform(-100, 100, n), rng.uniform(-30, 30, n)
    wz, t = rng.uniform(-200, 200, n), rng.uniform(0.2, 1.5, n)
    i1, i3 = TossDistribution(0, 0, 0, 1.0).moments
    expected = int(np.count_nonzero(normal_alignment(wx, wy, wz, t, i1, i3) > 0))
    assert sampling.count_same_side(wx, wy, wz, t, i1, i3) == expected
    u = np.stack([(wx + 100) / 200, (wy + 30) / 60, (wz + 200) / 400, (t - 0.2) / 1.3])
    offset = np.array([-100.0, -30.0, -200.0, 0.2])
    scale = np.array([200.0, 60.0, 400.0, 1.3])
    values = offset[:, None] + scale[:, None] * u
    expected = int(np.count_nonzero(normal_alignment(*values, i1, i3) > 0))
    assert sampling.count_same_side_affine(u, offset, scale, i1, i3) == expected


@settings(deadline=None, max_examples=25)
@given(
    lo=st.floats(-50.0, 150.0),
    width=st.floats(1.0, 60.0),
    wy=st.floats(-40.0, 40.0),
    t_lo=st.floats(0.2, 1.0),
    t_width=st.one_of(st.just(0.0), st.floats(0.01, 0.5)),
)
def test_heads_tails_symmetry_and_sum(lo, width, wy, t_lo, t_width):
    t = Uniform(t_lo, t_lo + t_width) if t_width > 0 else Fixed(t_lo)
    heads_up = TossDistribution(Uniform(lo, lo + width), wy, 0, t)
    tails_up = TossDistribution(Uniform(lo, lo + width), wy, 0, t, start="tails")
    for method, n in (("exact", None), ("grid", 64)):
        a, b = estimate(heads_up, method, n=n), estimate(tails_up, method, n=n)
        assert a.p_heads + a.p_tails + a.p_edge == pytest.approx(1.0, abs=1e-12)
        # Started tails up, the coin shows heads exactly when, started heads up, it shows tails.
        assert b.p_heads == pytest.approx(a.p_tails, abs=1e-12)
        assert b.p_same_side == pytest.approx(a.p_same_side, abs=1e-12)
    # The closed form agrees with a fine grid for any such box.
    fine = estimate(heads_up, "grid", n=4000).p_heads
    assert estimate(heads_up, "exact").p_heads == pytest.approx(fine, abs=2e-3)


def test_exact_fixed_time_two_spins():
    # Closed form in ωx, quadrature over ωy (the inner measure is continuous in ωy).
    dist = TossDistribution(Uniform(60, 90), Uniform(0, 20), 0, Fixed(0.7))
    exact = estimate(dist, "exact")
    assert exact.details["how"] == "closed form in one spin, quadrature in the other"
    assert 0 < exact.error_estimate < 1e-9
    # The error estimate is a bound on a deterministic result, not a 95 % interval.
    assert exact.ci95 is None and exact.stderr is None
    assert exact.to_dict()["ci95"] is None
    assert exact.describe().endswith("(quadrature error bound)")
    # A 2000² grid over (ωx, ωy) evaluated configuration by configuration.
    assert estimate(dist, "grid", n=2000).p_heads == pytest.approx(exact.p_heads, abs=1e-4)
    mc = estimate(dist, "monte-carlo", n=1 << 20, seed=4)
    assert abs(mc.p_heads - exact.p_heads) < 4 * mc.stderr


def _heads_time_measure(omega: float, t1: float, t2: float) -> float:
    """Length of {T ∈ [t1, t2] : cos(Ω T) > 0}, summed band by band (independent of core)."""
    total = 0.0
    m = math.floor((omega * t1 + math.pi / 2) / (2 * math.pi))
    while (2 * math.pi * m - math.pi / 2) / omega < t2:
        lo = max(t1, (2 * math.pi * m - math.pi / 2) / omega)
        hi = min(t2, (2 * math.pi * m + math.pi / 2) / omega)
        total += max(0.0, hi - lo)
        m += 1
    return total


@pytest.mark.parametrize("name", ["fig2a", "fig3b"])
def test_exact_to_1e9_against_independent_quadrature(name):
    # REFERENCES §3 (Keller): P = (1/ΔxΔT) ∫ dx |{T : cos(√(x² + c²) T) > 0}|; the inner
    # measure summed band by band, the outer by QUADPACK with the kinks as break points.
    from scipy.integrate import quad

    dist = PAPER[name]
    a, b = dist.omega_x.low, dist.omega_x.high
    c = dist.omega_y.value
    t1, t2 = dist.flight_time.low, dist.flight_time.high
    kinks = []
    for t in (t1, t2):
        for k in range(200):
            w = (math.pi / 2 + math.pi * k) / t
            if w * w > c * c:
                x = math.sqrt(w * w - c * c)
                if a < x < b:
                    kinks.append(x)
    kinks.sort()
    edges = [a, *kinks, b]
    total = 0.0
    for lo, hi in itertools.pairwise(edges):
        val, err = quad(
            lambda x: _heads_time_measure(math.hypot(x, c), t1, t2), lo, hi, epsabs=1e-14
        )
        assert err < 1e-12
        total += val
    reference = total / ((b - a) * (t2 - t1))
    assert estimate(dist, "exact").p_heads == pytest.approx(reference, abs=1e-9)


def test_monte_carlo_runs_are_prefixes_of_longer_runs():
    """Same seed: the first n tosses of a longer run are the tosses of the run of n."""
    from coinflight.probability.streams import DRAW, block_generators, draw_block, seed_sequence

    root = seed_sequence(5)
    short = np.concatenate(list(draw_block(block_generators(root, 0, 3), DRAW + 77, 0)), axis=1)
    long = np.concatenate(list(draw_block(block_generators(root, 0, 3), 3 * DRAW, 0)), axis=1)
    np.testing.assert_array_equal(short, long[:, : DRAW + 77])
    dist = PAPER["fig3a"]
    n = 1 << 20
    counts = [estimate(dist, "monte-carlo", n=m, seed=5).counts for m in (n - 1, n)]
    assert counts[1][1] - counts[0][1] in (0, 1)


def test_exact_quadrature_has_an_evaluation_budget(monkeypatch):
    # The reviewer's case (ω_z ranged, 2-D quadrature on a kinked integrand) ran for minutes;
    # with the budget it stops with a ValueError naming the sampling methods. A small budget
    # keeps the test fast; the default one is sized on the human preset (~300,000 evaluations).
    from coinflight.probability.exact import quadrature

    monkeypatch.setattr(quadrature, "MAX_EVALUATIONS", 1000)
    # (The reviewer's uniform ω_z now goes to the (Ω, ψ) rule; a truncated normal one, which
    # only the quadrature takes, keeps the kinked 2-D integrand.)
    slow = TossDistribution(Uniform(60, 90), 0, TruncatedNormal(2.5, 2.0, 0.0, 5.0), T_RANGE)
    with pytest.raises(ValueError, match=r"did not reach .*1e-09.* 1,000") as info:
        estimate(slow, "exact")
    for name in ("qmc", "monte-carlo", "grid"):
        assert name in str(info.value)
    # A 1-D quadrature well within the budget still succeeds and reports its evaluations.
    ok = estimate(TossDistribution(Uniform(60, 90), Uniform(0, 20), 0, Fixed(0.7)), "exact")
    assert 0 < ok.details["evaluations"] <= 1000  # 903


def test_grid_default_size_and_work_limit():
    from coinflight.probability.grid import MAX_WORK, default_cells

    # Default n: 5000 up to two ranged parameters, else the largest n with n^k ≤ 1e8.
    assert [default_cells(k) for k in range(1, 5)] == [5000, 5000, 464, 100]
    four = TossDistribution(Uniform(60, 90), Uniform(0, 20), Uniform(0, 5), T_RANGE)
    assert estimate(four, "grid").n == 100
    three = TossDistribution(Uniform(60, 90), Uniform(0, 20), 0, T_RANGE)
    assert estimate(three, "grid", n=2000).samples == 2000**3  # 4e6 nodes × ~6 bands: allowed
    # Band counting: 1000³ spin nodes × ~5.7 bands each is over the limit (hours before).
    with pytest.raises(ValueError, match=r"1,000,000,000 spin nodes × ~5\.\d+ bands") as info:
        estimate(four, "grid", n=1000)
    assert "monte-carlo or qmc" in str(info.value)
    # Brute force (fixed flight time): 1000³ = 1e9 configurations one by one.
    fixed_t = TossDistribution(Uniform(60, 90), Uniform(0, 20), Uniform(0, 5), 0.7)
    assert MAX_WORK < 1000**3
    with pytest.raises(
        ValueError, match=r"1,000,000,000 configurations, each evaluated one by one"
    ):
        estimate(fixed_t, "grid", n=1000)


def test_band_counting_wobbling_and_45_degree_spins():
    # ψ < 45° (|I3 ωz / I1| > Ω⊥) shows the starting face at every node; ψ = 45° exactly is
    # settled node by node. With I1 = 1, I3 = 2: ωx = 2, ωz = 1 is exactly 45°.
    wx = np.array([2.0, 2.0, 0.0, 1.0, 3.0, 2.0])
    wz = np.array([1.0, 5.0, 0.0, 0.4, 1.0, -1.0])
    wy = np.zeros_like(wx)
    t_nodes = np.linspace(0.01, 40.0, 5001)
    for j in range(len(wx)):
        one = slice(j, j + 1)
        fast = sampling.count_same_side_time_bands(wx[one], wy[one], wz[one], t_nodes, 1.0, 2.0)
        full = np.full_like(t_nodes, 1.0)
        slow = sampling.count_same_side(wx[j] * full, 0 * full, wz[j] * full, t_nodes, 1.0, 2.0)
        assert fast == slow, j


class _Unsettling(Generic):
    """The hand catch, plus a tally: tosses with T > 0.8 s flagged as never settled."""

    tallies = ("unsettled",)

    def count(self, dist, u):
        _, _, _, t = dist.values(u)
        return np.append(super().count(dist, u), np.count_nonzero(t > 0.8))


def test_model_tallies_are_reported():
    # A landing model's extra counts (unsettled tosses) reach the result's details.
    dist = PAPER["fig2a"]
    grid = estimate(dist, "grid", n=100, model=_Unsettling())
    # Grid midpoints 0.6 + 0.3 (i + ½)/100 > 0.8 for i ≥ 67: 33 of 100 time nodes.
    assert grid.details["unsettled"] == 33 * 100
    assert grid.details["unsettled_fraction"] == pytest.approx(0.33, abs=1e-15)
    assert grid.p_heads == estimate(dist, "grid", n=100).p_heads
    for method, n in (("monte-carlo", 20_000), ("qmc", 16 << 10)):
        r = estimate(dist, method, n=n, seed=3, model=_Unsettling())
        # T uniform on 0.6-0.9 s: P(T > 0.8) = 1/3; within 5 binomial standard errors.
        assert abs(r.details["unsettled_fraction"] - 1 / 3) < 5 * math.sqrt(2 / 9 / n), method
    assert "unsettled" not in estimate(dist, "monte-carlo", n=1000, seed=3).details


@pytest.mark.parametrize(
    ("method", "options", "line"),
    [
        ("exact", {}, "closed form"),
        ("grid", {"n": 50}, "50 cells per ranged parameter, 2,500 configurations"),
        ("monte-carlo", {"n": 1000, "seed": 3}, "1,000 tosses, seed 3"),
        (
            "monte-carlo",
            {"n": 1000, "seed": 3, "grid_cells": 100},
            "1,000 tosses drawn from 100 cells (method B), seed 3",
        ),
        (
            "monte-carlo",
            {"n": 1000, "seed": 3, "variance_reduction": "conditional-on-spin"},
            "1,000 spins, conditional-on-spin (closed form over T), seed 3",
        ),
        ("qmc", {"n": 1024, "seed": 3}, "1,024 Sobol points in 16 scramblings, seed 3"),
        (
            "qmc",
            {"n": 1024, "seed": 3, "variance_reduction": "conditional-on-spin"},
            "1,024 Sobol points in 16 scramblings, conditional-on-spin, seed 3",
        ),
    ],
)
def test_describe_run_says_how_the_result_was_made(method, options, line):
    assert estimate(PAPER["fig2a"], method, **options).describe_run() == line


def test_describe_run_of_a_quadrature_warning_and_of_another_method():
    warned = ProbabilityResult(0.5, 0.5, 0.0, 0.5, "exact", details={"how": "q", "warning": "w"})
    assert warned.describe_run() == "q; quadrature warning: w"
    other = ProbabilityResult(0.5, 0.5, 0.0, 0.5, "toy", n=10, samples=20, seed=1)
    assert other.describe_run() == "n = 10, 20 samples, seed 1"
    assert ProbabilityResult(0.5, 0.5, 0.0, 0.5, "toy").describe_run() == ""
