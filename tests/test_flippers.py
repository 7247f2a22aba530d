"""The people's ψ population (coinflight.studies.flippers): likelihood, fit, held-out people and
the two predictions the model is not fitted to."""

from __future__ import annotations

import itertools
import json
import math

import numpy as np
import pytest
from scipy import integrate, special, stats
from tests._cli import one_line_error
from typer.testing import CliRunner

from coinflight.cli import app
from coinflight.studies import flippers as f
from coinflight.studies.data import CountsTable, load_dataset

BARTOS = load_dataset("bartos2023")


def run(*args: object):
    return CliRunner().invoke(app, [str(a) for a in args])


def p_dhm(psi: float) -> float:
    """Diaconis, Holmes & Montgomery 2007, section 2, written out here as the test's own
    reference: p(ψ) = 1/2 + (1/π) arcsin(cot²ψ), 1 where cot²ψ ≥ 1."""
    c2 = math.cos(psi) ** 2 / max(math.sin(psi) ** 2, 1e-300)
    return 0.5 + math.asin(min(c2, 1.0)) / math.pi


def brute_loglik(k: int, n: int, mean: float, sd: float, points: int = 200_001) -> float:
    """log ∫ C(n, k) p^k (1 − p)^(n − k) φ(ψ; mean, sd) dψ as a plain Riemann sum over the
    *unfolded* normal on mean ± 10 sd: the fold at 90° comes from p(ψ) = p(180° − ψ) alone."""
    psi = np.linspace(mean - 10 * sd, mean + 10 * sd, points)
    dpsi = psi[1] - psi[0]
    p = np.array([p_dhm(x) for x in psi])
    log_b = (
        math.lgamma(n + 1) - math.lgamma(k + 1) - math.lgamma(n - k + 1)
        + special.xlogy(k, p) + special.xlog1py(n - k, -p)
    )  # fmt: skip
    dens = np.exp(-0.5 * ((psi - mean) / sd) ** 2) / (sd * math.sqrt(2 * math.pi))
    return float(np.log(np.sum(np.exp(log_b) * dens) * dpsi))


def table_of(same, flips) -> CountsTable:
    """People whose flips all started heads up (hsame = same, tdiff = the rest)."""
    same, flips = np.asarray(same), np.asarray(flips)
    counts = np.column_stack([same, 0 * same, 0 * same, flips - same]).astype(np.int64)
    return CountsTable(tuple(f"P{i}" for i in range(len(same))), counts)


# --- the likelihood -------------------------------------------------------------------------


SMALL = ([12, 9, 30, 20], [20, 20, 40, 20])
"""A small table: four people, 20-40 flips each, one of them always on the same side."""


@pytest.mark.parametrize("mean_deg, sd_deg", [(75.0, 8.0), (88.0, 5.0), (60.0, 3.0)])
def test_likelihood_equals_a_brute_force_sum_on_a_small_table(mean_deg, sd_deg):
    # (88°, 5°) puts a third of the population beyond 90°: wrong without the fold.
    k, n = SMALL
    lik = f.Likelihood.of(np.array(k), np.array(n))
    pop = f.PsiPopulation("normal", math.radians(mean_deg), math.radians(sd_deg))
    got = lik.per_person(pop)
    want = [
        brute_loglik(ki, ni, math.radians(mean_deg), math.radians(sd_deg))
        for ki, ni in zip(k, n, strict=True)
    ]
    assert got == pytest.approx(want, abs=2e-4)


def test_lognormal_likelihood_equals_adaptive_quadrature():
    k, n = 30, 50
    median, s = math.radians(80.0), 0.6
    lik = f.Likelihood.of(np.array([k]), np.array([n]))
    got = float(lik.per_person(f.PsiPopulation("lognormal", median, s))[0])
    dist = stats.lognorm(s, scale=0.5 * math.pi - median)  # of d = 90° − ψ

    def integrand(d: float) -> float:
        return stats.binom.pmf(k, n, p_dhm(0.5 * math.pi - d)) * dist.pdf(d)

    value = integrate.quad(integrand, 0.0, math.pi / 4, limit=200, points=[0.17])[0]
    value += stats.binom.pmf(k, n, 1.0) * dist.sf(math.pi / 4)
    assert got == pytest.approx(math.log(value), abs=2e-4)


def test_quadrature_is_accurate_for_the_largest_person():
    # 20,100 flips (Bartoš et al.'s most): the likelihood in ψ is narrowest.
    k, n = 10_300, 20_100
    lik = f.Likelihood.of(np.array([k]), np.array([n]))
    mean, sd = math.radians(84.0), math.radians(4.0)
    got = float(lik.per_person(f.PsiPopulation("normal", mean, sd))[0])

    def integrand(psi: float) -> float:
        return stats.binom.pmf(k, n, p_dhm(psi)) * stats.norm.pdf(psi, mean, sd)

    value = integrate.quad(
        integrand, mean - 10 * sd, mean + 10 * sd, points=[0.5 * math.pi], limit=400
    )[0]
    assert got == pytest.approx(math.log(value), abs=1e-3)


def test_zero_spread_is_one_psi_for_all():
    k, n = np.array(SMALL[0]), np.array(SMALL[1])
    lik = f.Likelihood.of(k, n)
    psi = math.radians(70.0)
    want = f.one_psi_loglik(k, n, psi)
    assert want == pytest.approx(
        [stats.binom.logpmf(a, b, p_dhm(psi)) for a, b in zip(k, n, strict=True)], rel=1e-12
    )
    # σ → 0: the mass falls in one cell of 0.02°, p at its midpoint (d = 19.99°: ψ = 70.01°).
    mid = math.radians(70.01)
    got = lik.per_person(f.PsiPopulation("normal", mid, 1e-9))
    assert got == pytest.approx(f.one_psi_loglik(k, n, mid), abs=1e-9)
    assert got == pytest.approx(want, abs=3e-3)  # 0.01° from 70°


def test_one_psi_angle_is_the_pooled_rate_inverted():
    k, n = BARTOS.same_by_person, BARTOS.flips_by_person
    psi = f.one_psi_angle(k, n)
    assert p_dhm(psi) == pytest.approx(BARTOS.same / BARTOS.flips, rel=1e-12)
    # the pooled rate is the binomial maximum likelihood: a nudge either way lowers it
    best = f.one_psi_loglik(k, n, psi).sum()
    for step in (-1e-3, 1e-3):
        assert f.one_psi_loglik(k, n, psi + step).sum() < best
    assert f.one_psi_angle(np.array([4]), np.array([10])) == pytest.approx(0.5 * math.pi)


# --- the fit on simulated people -------------------------------------------------------------


def simulate(mean_deg: float, sd_deg: float, seed: int):
    """Bartoš et al.'s numbers of flips, each person's ψ from Normal(mean, sd), binomial counts."""
    rng = np.random.default_rng(seed)
    n = BARTOS.flips_by_person
    psi = rng.normal(math.radians(mean_deg), math.radians(sd_deg), len(n))
    p = np.array([p_dhm(x) for x in psi])
    return rng.binomial(n, p), n


@pytest.mark.parametrize("seed", [11, 12])
def test_a_known_spread_is_recovered_within_its_interval(seed):
    mean, sd = 84.0, 5.0
    k, n = simulate(mean, sd, seed)
    fit = f.fit_population(f.Likelihood.of(k, n))
    lo, hi = (math.degrees(x) for x in fit.scale_ci95)
    assert lo < sd < hi and lo > 0.0
    lo, hi = (math.degrees(x) for x in fit.location_ci95)
    assert lo < mean <= hi
    assert fit.lr_p_value < 1e-6  # heterogeneous, and said so


@pytest.mark.parametrize("seed", [21, 22])
def test_one_psi_for_all_is_not_reported_heterogeneous(seed):
    # Negative case: every person at ψ = 80°: the spread's interval reaches 0 and the test of
    # one ψ against the population does not reject.
    k, n = simulate(80.0, 0.0, seed)
    fit = f.fit_population(f.Likelihood.of(k, n))
    assert fit.scale_ci95[0] == 0.0
    assert fit.lr_p_value > 0.05
    assert math.degrees(fit.location_ci95[0]) < 80.0 < math.degrees(fit.location_ci95[1])


def test_the_fit_is_the_best_point_of_a_brute_grid():
    lik = f.Likelihood.of(BARTOS.same_by_person, BARTOS.flips_by_person)
    fit = f.fit_population(lik)
    grid = max(
        lik.total(f.PsiPopulation("normal", math.radians(a), math.radians(b)))
        for a in np.arange(70.0, 90.01, 1.0)
        for b in np.arange(0.5, 20.0, 0.5)
    )
    assert fit.loglik >= grid - 1e-6
    # The profile interval's ends lie PROFILE_DROP below the maximum (χ²₁ 0.95 / 2).
    lo = fit.scale_ci95[0]
    prof = max(
        lik.total(f.PsiPopulation("normal", m, lo)) for m in np.radians(np.arange(75, 90.01, 0.05))
    )
    assert prof == pytest.approx(fit.loglik - stats.chi2.ppf(0.95, 1) / 2, abs=0.02)


# --- Bartoš et al.'s 48 people ----------------------------------------------------------------


@pytest.fixture(scope="module")
def bartos():
    return f.analyse(BARTOS, seed=1)


def test_bartos_population_against_the_issues_orientation(bartos):
    # Orientation, not a target (an independent fit quoted in the issue that asked for this):
    # a log-likelihood ratio of "about 157" between the population and one ψ: that number is
    # 2 ΔlogL, the test statistic; coverage ~70 % (one ψ) and ~94 % (population), 2-fold.
    fit = bartos.fit
    assert fit.lr_statistic == pytest.approx(157.0, rel=0.05)
    assert fit.loglik_ratio == pytest.approx(fit.lr_statistic / 2)
    ho = bartos.held_out
    assert ho.coverage_one_psi == pytest.approx(0.70, abs=0.05)
    assert ho.coverage == pytest.approx(0.94, abs=0.03)
    assert ho.log_score > ho.log_score_one_psi
    # One ψ is rejected; the spread of ψ is well away from 0.
    assert fit.scale_ci95[0] > math.radians(3.0)
    het = bartos.heterogeneity
    assert (het.dof, round(het.chi2)) == (47, 265)  # the issue's χ²
    assert het.i2 == pytest.approx(0.82, abs=0.01) and het.tau == pytest.approx(0.013, abs=1e-3)


def test_heldout_coverage_matches_the_predictive_interval(bartos):
    # The coverage test F(k) ≥ 2.5 %, F(k − 1) < 97.5 % against the interval found by bisection.
    lik = f.Likelihood.of(BARTOS.same_by_person, BARTOS.flips_by_person)
    pop = bartos.fit.population
    masses = pop.cell_masses()
    inside = (lik.cdf @ masses >= 0.025) & (lik.cdf_below @ masses < 0.975)
    interval = f.predictive_interval(lik.flips, pop)
    count = lik.same / lik.flips
    assert inside.tolist() == ((count >= interval[:, 0]) & (count <= interval[:, 1])).tolist()


def test_heldout_splits_are_seeded():
    lik = f.Likelihood.of(BARTOS.same_by_person, BARTOS.flips_by_person)
    a = f.held_out(lik, repeats=3, seed=5)
    assert a == f.held_out(lik, repeats=3, seed=5)
    assert a.seed == 5 and a.predictions == 3 * 48
    fresh = f.held_out(lik, repeats=1)
    assert isinstance(fresh.seed, int)
    assert f.held_out(lik, repeats=1, seed=fresh.seed) == fresh
    with pytest.raises(ValueError, match="folds must be between 2 and 48, got 49"):
        f.held_out(lik, folds=49)


def test_heldout_work_is_bounded_before_it_starts():
    assert f.held_out_seconds(48, 2, 20) == pytest.approx(40 * f.FIT_SECONDS)
    words = r"a held-out check of 5000 people in 5000 folds × 1000 splits is .* s of estimated work"
    with pytest.raises(ValueError, match=words + r", more than the limit of 3,600"):
        f.check_splits(5000, 5000, 1000)


def test_heldout_coverage_of_a_homogeneous_population_is_nominal():
    # Every person at ψ = 80°: both models are right, and both cover about 95 %.
    k, n = simulate(80.0, 0.0, 3)
    ho = f.held_out(f.Likelihood.of(k, n), repeats=10, seed=2)
    assert ho.coverage_one_psi >= 0.88 and ho.coverage >= 0.88


def test_shrunken_psi_is_the_posterior_by_brute_force(bartos):
    pop = bartos.fit.population
    for person in bartos.people:
        lo, hi = person.ci95
        assert math.radians(45) <= lo <= person.psi <= hi <= 0.5 * math.pi
    # Two people (the lowest rate and the highest) by a dense grid of the folded posterior:
    # density ∝ Binomial(k; n, p(ψ)) (φ(ψ) + φ(180° − ψ)) on [45°, 90°].
    psi = np.linspace(math.radians(45.0), 0.5 * math.pi, 400_001)
    p = np.array([p_dhm(x) for x in psi])
    prior = stats.norm.pdf(psi, pop.location, pop.scale) + stats.norm.pdf(
        math.pi - psi, pop.location, pop.scale
    )
    for i in (0, 47):  # 0.4875 and 0.6007
        k, n = int(BARTOS.same_by_person[i]), int(BARTOS.flips_by_person[i])
        post = stats.binom.pmf(k, n, p) * prior
        cdf = integrate.cumulative_trapezoid(post[::-1], dx=psi[1] - psi[0], initial=0.0)
        cdf /= cdf[-1]  # from 90° down
        want = [psi[::-1][np.searchsorted(cdf, q)] for q in (0.5, 0.025, 0.975)]
        got = bartos.people[i]
        assert [got.psi, got.ci95[1], got.ci95[0]] == pytest.approx(want, abs=math.radians(0.02))
        rate = float(np.sum(post * p) / np.sum(post))
        assert got.p_same_side == pytest.approx(rate, abs=1e-5)


# --- the predictions the model is not fitted to -----------------------------------------------


def test_start_face_pooled_test_is_the_two_proportion_test(bartos):
    c = BARTOS.counts.sum(axis=0)  # hsame, hdiff, tsame, tdiff
    n1, n2 = c[0] + c[3], c[2] + c[1]
    p1, p2 = c[0] / n1, c[2] / n2
    pooled = (c[0] + c[2]) / (n1 + n2)
    z = (p1 - p2) / math.sqrt(pooled * (1 - pooled) * (1 / n1 + 1 / n2))
    sf = bartos.start_face
    assert sf.chi2 == pytest.approx(z * z, rel=1e-9)
    assert sf.p_value == pytest.approx(2 * stats.norm.sf(abs(z)), rel=1e-9)
    assert (sf.rate_heads, sf.rate_tails) == pytest.approx((p1, p2), rel=1e-12)
    assert sf.p_value > 0.05 and sf.p_value_people > 0.05  # the prediction holds here
    assert sf.df_people == 48


def test_start_face_effect_is_detected_when_present():
    # A person whose heads-up starts land same side 60 % and tails-up 50 %: rejected.
    counts = np.array([[600, 500, 500, 400]] * 3, dtype=np.int64)
    sf = f.start_face_test(counts)
    assert sf.rate_heads == pytest.approx(0.6) and sf.rate_tails == pytest.approx(0.5)
    assert sf.p_value < 1e-10 and sf.p_value_people < 1e-10 and sf.people_below_005 == 3


def test_poisson_binomial_tail_by_enumeration():
    q = [0.1, 0.5, 0.7, 0.33]
    for at_least in range(6):
        want = sum(
            math.prod(p if x else 1 - p for p, x in zip(q, xs, strict=True))
            for xs in itertools.product((0, 1), repeat=4)
            if sum(xs) >= at_least
        )
        assert f._poisson_binomial_tail(np.array(q), at_least) == pytest.approx(want, abs=1e-14)


def test_below_half_on_bartos(bartos):
    bh = bartos.below_half
    rates = BARTOS.same_by_person / BARTOS.flips_by_person
    assert bh.observed == int(np.sum(rates < 0.5)) == 10
    n = BARTOS.flips_by_person
    # P(Binomial(n, ½) < n / 2) = (1 − P(tie)) / 2, P(tie) = C(n, n/2) / 2ⁿ for even n
    tie = np.where(n % 2 == 0, stats.binom.pmf(n // 2, n, 0.5), 0.0)
    assert bh.expected_at_half == pytest.approx(float(np.sum((1 - tie) / 2)), rel=1e-10)
    assert bh.p_value_at_half > 0.5  # far fewer than at ½: the prediction holds
    assert bh.p_value_model > 0.05
    assert bh.lowest_p_holm > 0.05


def test_below_half_detects_people_below_half():
    # Ten people at a true rate of 0.45: more below ½ than any rates ≥ ½ can give.
    rng = np.random.default_rng(4)
    n = np.full(10, 2000)
    table = table_of(rng.binomial(n, 0.45), n)
    lik = f.Likelihood.of(table.same_by_person, table.flips_by_person)
    fit = f.fit_population(lik, intervals=False)
    bh = f.below_half_test(lik, fit.population, table.people)
    assert bh.observed == 10
    assert bh.p_value_at_half < 0.01 and bh.lowest_p_holm < 0.01


# --- the command line and the bias by name -----------------------------------------------------


def test_data_json_heterogeneity_object():
    result = run("data", "--json", "--seed", 3, "--repeats", 2)
    assert result.exit_code == 0, result.output
    het = json.loads(result.stdout)["heterogeneity"]
    for key in ("chi2", "df", "p_value", "i2", "tau", "psi_mean", "psi_sd", "loglik_ratio",
                "heldout_coverage", "heldout_coverage_one_psi", "seed"):  # fmt: skip
        assert key in het, key
    assert het["seed"] == 3 and het["repeats"] == 2
    assert het["psi_sd_ci95"][0] < het["psi_sd"] < het["psi_sd_ci95"][1]
    assert len(het["per_person"]) == 48
    fresh = json.loads(run("data", "--json", "--repeats", 1).stdout)["heterogeneity"]
    assert isinstance(fresh["seed"], int)  # none given: drawn and reported
    text = run("data", "--seed", 3, "--repeats", 2).stdout
    assert "held-out people, 2-fold × 2 splits (seed 3)" in text
    assert "starting face (predicted: no effect)" in text


def test_data_counts_file_and_limits(tmp_path, monkeypatch):
    path = tmp_path / "mine.txt"
    path.write_text(
        "person hsame hdiff tsame tdiff same flips\n"
        "A 60 40 55 45 115 200\nB 50 50 52 48 102 200\nC 70 30 66 34 136 200\n"
    )
    het = json.loads(run("data", "--counts", path, "--json", "--seed", 1).stdout)["heterogeneity"]
    assert het["folds"] == 2 and het["df"] == 2
    assert one_line_error("data", "--counts", path, "--folds", 4) == (
        "--folds must be at most the number of people (3), got 4"
    )
    monkeypatch.setattr(f, "MAX_FIT_PEOPLE", 2)
    het = json.loads(run("data", "--counts", path, "--json").stdout)["heterogeneity"]
    assert het["not_fitted"].startswith("not fitted: the ψ population is fitted to at most 2")


def test_bias_psi_dist_by_dataset_name(bartos):
    from coinflight.studies.bias import mean_same_side_probability

    result = run("bias", "--psi-dist", "bartos2023", "--json")
    assert result.exit_code == 0, result.output
    got = json.loads(result.stdout)
    pop = bartos.fit.population
    assert got["psi_deg"] == pytest.approx(math.degrees(pop.location), abs=1e-6)
    assert got["psi_sd_deg"] == pytest.approx(math.degrees(pop.scale), abs=1e-6)
    want = mean_same_side_probability(pop.distribution(), degrees=True)
    assert got["p_same_side"] == pytest.approx(want, abs=1e-9)
    # the model's own average p over the cells, the same number by another road
    assert float(f._P_CELLS @ pop.cell_masses()) == pytest.approx(want, abs=1e-5)
    assert one_line_error("bias", "--psi-dist", "bartos2024").endswith(
        "or a dataset's name: bartos2023"
    )


@pytest.mark.parametrize(
    "location_deg, cell", [(90.0, 0), (89.99, 0), (70.01, 999), (45.0, f.CELLS), (30.0, f.CELLS)]
)
def test_a_point_mass_population_keeps_all_its_mass(location_deg, cell):
    # Zero spread: all the mass in the one cell (a, b] holding d = |90° − ψ| (d = 0: the first
    # cell; d = 19.99° in cell 999 = [19.98°, 20°]; d ≥ 45°: the cell where the coin never
    # turns over), none lost at a cell's edge.
    masses = f.PsiPopulation("normal", math.radians(location_deg), 0.0).cell_masses()
    assert masses.sum() == pytest.approx(1.0, abs=1e-15)
    assert np.flatnonzero(masses).tolist() == [cell]
