"""Flippers differ: a population of precession angles fitted to per-person same-side counts.

One precession angle ψ for every flip of every person explains the pooled same-side rate of
Bartoš et al.'s 350,757 flips (REFERENCES §6), but not the spread of the 48 people's rates
(:func:`coinflight.studies.data.heterogeneity`). This module fits the hierarchical model

    ψ_i ~ F(θ)   (one angle for each person i, drawn from a population F),
    k_i | ψ_i ~ Binomial(n_i, p(ψ_i)),

with p(ψ) = 1/2 + (1/π) arcsin(cot²ψ) the same-side probability of Diaconis, Holmes &
Montgomery 2007 (:func:`coinflight.core.precession.same_side_probability`), k_i the same-side
flips of n_i. The population parameters θ are fitted by the marginal likelihood
∏_i ∫ Binomial(k_i; n_i, p(ψ)) dF(ψ; θ); the integral over ψ is a quadrature (below), not a
simulation. The model is then checked on people it has not seen (:func:`held_out`) and on two
predictions it makes without being fitted to them (:func:`start_face_test`,
:func:`below_half_test`). :func:`analyse` does all of it.

Populations (:data:`FAMILIES`)
    ``normal``: ψ normal with mean μ ≤ 90° and standard deviation σ, *folded at 90°*. p(ψ)
    depends on ψ only through cos²ψ (a spin about the normal in one sense or the other gives the
    same coin), so only the distance d = |90° − ψ| from a spin about a diameter matters; a normal
    ψ whose tail crosses 90° is the same population as its mirror image. The normal is the
    two-parameter family that assumes least beyond a typical angle and a spread (maximum entropy
    for a given mean and variance), and the one a person's angle made of many small habits of the
    hand would follow. σ = 0 is one ψ for everybody, so the two models are nested.
    ``lognormal``: the distance d = 90° − ψ log-normal (median ψ and the s.d. of log d): a
    right-skewed alternative in which nobody spins exactly about a diameter.

Quadrature
    The population is integrated cell by cell on d ∈ [0°, 45°] in :data:`CELLS` cells of
    :data:`CELL_DEG` (p at each cell's midpoint, weighted by the population's exact mass in the
    cell from its distribution function), plus one cell d ≥ 45° where the coin never turns over
    (p = 1). The mass weights are exact for any spread, so one ψ for all (σ → 0) is the limit of
    the rule, not a singularity; the midpoint error is below 10⁻³ in a person's log-likelihood for
    n ≤ 10⁵ flips (tested against adaptive quadrature). Work: people × cells, a matrix computed
    once per table (:data:`MAX_FIT_PEOPLE`).

Every interval is 95 %. Angles are in radians in the library, degrees in the JSON and text.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from coinflight import _validation as v
from coinflight.core.precession import angle_for_same_side, same_side_probability
from coinflight.probability import streams

if TYPE_CHECKING:
    from coinflight.model.distributions import Normal
    from coinflight.studies.data import CountsTable, Heterogeneity

FloatArray = NDArray[np.float64]

FAMILIES = ("normal", "lognormal")
"""Population families of ψ: ``normal`` (folded at 90°, the model) and ``lognormal`` (of
90° − ψ, the alternative it is compared with)."""

CELL_DEG = 0.02
"""Width of a quadrature cell in d = 90° − ψ, degrees."""
CELLS = round(45.0 / CELL_DEG)
"""Quadrature cells on d ∈ [0°, 45°] (one more cell holds d ≥ 45°, p = 1)."""

MAX_FIT_PEOPLE = 5000
"""Most people whose ψ population is fitted: the likelihood keeps people × (CELLS + 1) numbers
three times (about 270 MB at 5,000 people), and the fit's time grows with it (about 1 s per
1,000 people on a 2-core machine)."""

PROFILE_DROP = 0.5 * 3.841458820694124
"""Drop of the log-likelihood at the ends of a 95 % profile-likelihood interval: half the 0.95
quantile of χ²(1)."""

DEFAULT_FOLDS = 2
"""Folds of the held-out check: each split fits on half the people and predicts the other half."""
DEFAULT_REPEATS = 20
"""Random splits of the people in the held-out check."""
MAX_REPEATS = 1000
"""Most random splits (each split fits the model once per fold)."""

_EDGES = np.radians(np.linspace(0.0, 45.0, CELLS + 1))
_MIDPOINTS = 0.5 * (_EDGES[:-1] + _EDGES[1:])
_P_CELLS = np.append(same_side_probability(0.5 * math.pi - _MIDPOINTS), 1.0)
"""p at each cell's midpoint, and p = 1 in the last cell (d ≥ 45°)."""


@dataclass(frozen=True)
class PsiPopulation:
    """A population of precession angles.

    Attributes
    ----------
    family : {"normal", "lognormal"}
        ``normal``: ψ ~ Normal(location, scale) folded at 90°; ``lognormal``: 90° − ψ ~
        LogNormal with median 90° − location and log-s.d. ``scale``.
    location : float
        The normal's mean ψ, or the lognormal's median ψ, rad, in [0, π/2].
    scale : float
        The normal's standard deviation of ψ, rad (0: one ψ for all), or the standard deviation
        of log(90° − ψ) (dimensionless), ≥ 0.
    """

    family: str
    location: float
    scale: float

    def __post_init__(self) -> None:
        v.choice("population family", self.family, FAMILIES)
        object.__setattr__(
            self, "location", float(v.in_range("psi location", self.location, 0.0, math.pi / 2))
        )
        object.__setattr__(self, "scale", float(v.non_negative("psi spread", self.scale)))

    def distance_cdf(self, d: FloatArray) -> FloatArray:
        """P(|90° − ψ| ≤ d) for distances d ≥ 0, rad."""
        return _distance_cdf(self.family, self.location, self.scale, np.asarray(d, dtype=float))

    def cell_masses(self) -> FloatArray:
        """The population's mass in each quadrature cell of d and in d ≥ 45° (sums to 1)."""
        return _cell_masses(self.family, self.location, self.scale)

    def distribution(self) -> Normal:
        """The normal population as a :class:`~coinflight.model.distributions.Normal` of ψ in
        degrees (unfolded: p(ψ) is the same for ψ and 180° − ψ), for
        :func:`coinflight.studies.bias.mean_same_side_probability`."""
        from coinflight.model.distributions import Normal

        if self.family != "normal":
            raise ValueError(f"only a normal population is a Normal, got {self.family}")
        return Normal(math.degrees(self.location), math.degrees(self.scale))

    def describe(self) -> str:
        """One line: the family and its parameters in degrees."""
        if self.family == "normal":
            return (
                f"ψ normal, mean {math.degrees(self.location):.2f}°, "
                f"sd {math.degrees(self.scale):.2f}°, folded at 90°"
            )
        return (
            f"90° − ψ log-normal, median ψ {math.degrees(self.location):.2f}°, "
            f"log-sd {self.scale:.3f}"
        )


def _distance_cdf(family: str, location: float, scale: float, d: FloatArray) -> FloatArray:
    """P(|90° − ψ| ≤ d) of a population (:class:`PsiPopulation`'s fields, unchecked)."""
    from scipy.special import ndtr

    centre = 0.5 * math.pi - location  # the normal's mean distance, the log-normal's median
    if scale == 0.0:  # a point mass: P(D < d), so that it falls in the cell (a, b] holding it,
        return np.where(d > centre, 1.0, 0.0)  # the first cell when at d = 0
    if family == "normal":
        return np.asarray(ndtr((d - centre) / scale) - ndtr((-d - centre) / scale))
    if centre <= 0.0:
        return np.ones_like(d)
    with np.errstate(divide="ignore"):
        return np.asarray(ndtr((np.log(d) - math.log(centre)) / scale))


def _cell_masses(family: str, location: float, scale: float) -> FloatArray:
    """Mass of each quadrature cell of d and of d ≥ 45° (fields unchecked: the optimizers'
    inner loop)."""
    cdf = _distance_cdf(family, location, scale, _EDGES)
    masses = np.empty(CELLS + 1)
    np.subtract(cdf[1:], cdf[:-1], out=masses[:-1])
    masses[-1] = 1.0 - cdf[-1]
    return np.clip(masses, 0.0, None, out=masses)


@dataclass(frozen=True, eq=False)
class Likelihood:
    """Each person's binomial likelihood on the quadrature cells, computed once per table.

    ``log_peak[i] + log(scaled[i] @ masses)`` is person i's log marginal likelihood
    log ∫ Binomial(k_i; n_i, p(ψ)) dF(ψ) for the cell masses of any population F. The
    distribution functions ``cdf`` (at k_i) and ``cdf_below`` (at k_i − 1) give the predictive
    check of :func:`held_out` the same way.
    """

    same: NDArray[np.int64]
    flips: NDArray[np.int64]
    log_peak: FloatArray
    scaled: FloatArray
    cdf: FloatArray
    cdf_below: FloatArray

    @classmethod
    def of(cls, same: NDArray[np.int64], flips: NDArray[np.int64]) -> Likelihood:
        """The matrices for same-side counts ``same`` of ``flips`` (one entry per person)."""
        from scipy.stats import binom

        people = len(flips)
        v.work_bound(
            f"fitting a ψ population to {v.quantity(people)} people",
            people,
            MAX_FIT_PEOPLE,
            "people",
            "fit a sample of the people, or split the table",
        )
        k = np.asarray(same, dtype=np.int64)[:, None]
        n = np.asarray(flips, dtype=np.int64)[:, None]
        with np.errstate(divide="ignore"):
            log_b = binom.logpmf(k, n, _P_CELLS[None, :])
        peak = log_b.max(axis=1)
        scaled = np.exp(log_b - peak[:, None])
        cdf = binom.cdf(k, n, _P_CELLS[None, :])
        below = binom.cdf(k - 1, n, _P_CELLS[None, :])
        return cls(k[:, 0], n[:, 0], peak, scaled, cdf, below)

    def subset(self, people: NDArray[np.intp]) -> Likelihood:
        """The rows of ``people`` only."""
        return Likelihood(
            self.same[people],
            self.flips[people],
            self.log_peak[people],
            self.scaled[people],
            self.cdf[people],
            self.cdf_below[people],
        )

    def per_person(self, pop: PsiPopulation) -> FloatArray:
        """Each person's log marginal likelihood under ``pop``."""
        with np.errstate(divide="ignore"):
            return np.asarray(self.log_peak + np.log(self.scaled @ pop.cell_masses()))

    def total(self, pop: PsiPopulation) -> float:
        """The log marginal likelihood of all people under ``pop``."""
        return self.total_at(pop.family, pop.location, pop.scale)

    def total_at(self, family: str, location: float, scale: float) -> float:
        """:meth:`total` of the population with these fields, taken as valid (no checks: the
        optimizers' inner loop)."""
        with np.errstate(divide="ignore"):
            inner = np.log(self.scaled @ _cell_masses(family, location, scale))
        return float(self.log_peak.sum() + inner.sum())


def one_psi_loglik(same: NDArray[np.int64], flips: NDArray[np.int64], psi: float) -> FloatArray:
    """Each person's binomial log-likelihood when every flip has the precession angle ψ."""
    from scipy.stats import binom

    return np.asarray(binom.logpmf(same, flips, same_side_probability(psi)))


def one_psi_angle(same: NDArray[np.int64], flips: NDArray[np.int64]) -> float:
    """The maximum-likelihood single ψ (rad): p(ψ) equal to the pooled rate, π/2 when that rate
    is at or below 1/2 (p(ψ) ≥ 1/2 for every ψ)."""
    rate = float(np.sum(same)) / float(np.sum(flips))
    return float(angle_for_same_side(max(rate, 0.5)))


@dataclass(frozen=True)
class PersonPsi:
    """One person's ψ given their counts and the fitted population (empirical Bayes).

    Attributes
    ----------
    person : str
        The name.
    psi, ci95 : float, (float, float)
        Posterior median of ψ and its 2.5 % and 97.5 % quantiles, rad, on the branch
        [45°, 90°] (ψ < 45°: the coin never turns over). The population parameters are taken
        as known, so the interval leaves out their own uncertainty.
    p_same_side : float
        Posterior mean of the person's same-side probability: their rate, shrunken toward the
        population.
    """

    person: str
    psi: float
    ci95: tuple[float, float]
    p_same_side: float


def shrunken(lik: Likelihood, pop: PsiPopulation, people: Sequence[str]) -> tuple[PersonPsi, ...]:
    """Each person's posterior ψ under the population ``pop`` (:class:`PersonPsi`)."""
    post = lik.scaled * pop.cell_masses()[None, :]
    post /= post.sum(axis=1, keepdims=True)
    cum = np.cumsum(post[:, :-1], axis=1)  # P(d ≤ right edge of each cell)
    out = []
    for name, row, c in zip(people, post, cum, strict=True):
        q = [_quantile_d(c, level) for level in (0.5, 0.975, 0.025)]
        psi = [0.5 * math.pi - x for x in q]
        out.append(PersonPsi(name, psi[0], (psi[1], psi[2]), float(row @ _P_CELLS)))
    return tuple(out)


def _quantile_d(cum: FloatArray, level: float) -> float:
    """The distance d at which the cell-wise cumulative mass ``cum`` reaches ``level``
    (linear within a cell); 45° when it is reached only in the last cell."""
    i = int(np.searchsorted(cum, level))
    if i >= len(cum):
        return float(_EDGES[-1])
    below = cum[i - 1] if i else 0.0
    share = (level - below) / (cum[i] - below) if cum[i] > below else 0.5
    return float(_EDGES[i] + share * (_EDGES[i + 1] - _EDGES[i]))


# --- the fit ------------------------------------------------------------------------------


@dataclass(frozen=True)
class PopulationFit:
    """The maximum marginal likelihood population of ψ, against one ψ for all.

    Attributes
    ----------
    population : PsiPopulation
        The fitted population.
    loglik : float
        Its log marginal likelihood.
    location_ci95, scale_ci95 : (float, float) or None
        95 % profile-likelihood intervals of ``location`` and ``scale`` (rad for the normal);
        None when not computed (the alternative family, the held-out fits).
    limited : tuple of str
        ``("scale high",)`` when the spread's interval stops at its bound 45° instead of at the
        likelihood's drop. (A location interval reaching 90° is complete: it continues into its
        mirror image, ψ and 180° − ψ being the same population; a spread's reaching 0 includes
        one ψ for all.)
    one_psi : float
        The single ψ that fits all flips, rad.
    loglik_one_psi : float
        The log-likelihood of one ψ for all.
    """

    population: PsiPopulation
    loglik: float
    one_psi: float
    loglik_one_psi: float
    location_ci95: tuple[float, float] | None = None
    scale_ci95: tuple[float, float] | None = None
    limited: tuple[str, ...] = ()

    @property
    def loglik_ratio(self) -> float:
        """log L(population) − log L(one ψ), ≥ 0 (one ψ is the population with σ = 0)."""
        return self.loglik - self.loglik_one_psi

    @property
    def lr_statistic(self) -> float:
        """The likelihood-ratio statistic 2 (log L(population) − log L(one ψ))."""
        return 2.0 * max(self.loglik_ratio, 0.0)

    @property
    def lr_p_value(self) -> float:
        """Likelihood-ratio test of one ψ (σ = 0, on the boundary) against the normal
        population: P = ½ P(χ²₁ > 2 LLR) (Self & Liang 1987, JASA 82, 605, case 5)."""
        from scipy.stats import chi2

        return float(0.5 * chi2.sf(self.lr_statistic, 1))


def _bounds(family: str) -> tuple[tuple[float, float], tuple[float, float]]:
    if family == "normal":
        return (0.0, 0.5 * math.pi), (0.0, 0.25 * math.pi)
    return (0.0, 0.5 * math.pi - 1e-6), (1e-3, 5.0)


def _maximize(
    lik: Likelihood, family: str, starts: Sequence[tuple[float, float]], tolerance: float
) -> tuple[PsiPopulation, float]:
    """The population of ``family`` of largest marginal likelihood, by bounded Nelder-Mead
    (``scipy.optimize.minimize``, parameters to ``tolerance`` rad, log L to ``tolerance / 10``)
    from each start, the best kept."""
    from scipy.optimize import minimize

    bounds = _bounds(family)

    def cost(x: FloatArray) -> float:
        a = min(max(float(x[0]), bounds[0][0]), bounds[0][1])
        b = min(max(float(x[1]), bounds[1][0]), bounds[1][1])
        return _negative(lik.total_at(family, a, b))

    best: tuple[float, FloatArray] | None = None
    for raw in starts:
        start = [min(max(x, lo), hi) for x, (lo, hi) in zip(raw, bounds, strict=True)]
        res = minimize(
            cost,
            np.array(start),
            method="Nelder-Mead",
            bounds=bounds,
            options={"xatol": tolerance, "fatol": tolerance / 10, "maxfev": 2000},
        )
        if best is None or res.fun < best[0]:
            best = (float(res.fun), np.asarray(res.x))
    assert best is not None
    a, b = (min(max(float(x), lo), hi) for x, (lo, hi) in zip(best[1], bounds, strict=True))
    return PsiPopulation(family, a, b), -best[0]


def _negative(loglik: float) -> float:
    """The cost the optimizers minimize: −log L, and 10³⁰⁰ where log L is −∞ (a population
    with no mass where a person's counts can happen)."""
    return -loglik if math.isfinite(loglik) else 1e300


def _starts(family: str, psi_one: float, spread: float) -> list[tuple[float, float]]:
    """Starting points: the one-ψ angle with a small and a moderate spread."""
    if family == "normal":
        return [(min(psi_one, 1.55), max(spread, 0.01)), (min(psi_one, 1.5), 0.15)]
    d = max(0.5 * math.pi - psi_one, 0.02)
    return [(0.5 * math.pi - d, 0.5), (0.5 * math.pi - d, 1.5)]


def _moment_spread(same: NDArray[np.int64], flips: NDArray[np.int64], psi_one: float) -> float:
    """A rough spread of ψ to start from: the excess spread of the rates over binomial
    sampling, through the slope of p(ψ) at the one-ψ angle."""
    rates = same / flips
    pooled = float(np.sum(same) / np.sum(flips))
    excess = float(np.var(rates) - np.mean(pooled * (1.0 - pooled) / flips))
    slope = abs(float(same_side_probability(psi_one - 0.01) - same_side_probability(psi_one)))
    return math.sqrt(max(excess, 0.0)) / max(slope / 0.01, 1e-3)


def fit_population(
    lik: Likelihood, family: str = "normal", *, intervals: bool = True, thorough: bool = True
) -> PopulationFit:
    """Fit a ψ population to the people of ``lik`` by maximum marginal likelihood.

    Parameters
    ----------
    lik : Likelihood
        :meth:`Likelihood.of` the table.
    family : {"normal", "lognormal"}
        The population family (:data:`FAMILIES`).
    intervals : bool
        Compute the 95 % profile-likelihood intervals of the normal's mean and spread.
    thorough : bool
        Start the optimizer from two points and converge to 10⁻⁵ rad (True), or from one to
        10⁻⁴ rad (False: the held-out fits, about twice as fast).

    Notes
    -----
    The one-ψ model is the normal family at σ = 0, fitted exactly (:func:`one_psi_angle`); the
    population's likelihood is never reported below it (the better of the two is kept). Profile
    intervals: the parameter where max over the other parameter of log L falls
    :data:`PROFILE_DROP` below the maximum (Brent's root finder, ``scipy.optimize.brentq``).
    They rest on the χ² approximation, which with as few people as Bartoš et al.'s 48 makes
    the spread's interval somewhat narrow (in simulated tables it holds the true spread a little
    less often than 95 % of the time; the mean's interval keeps its 95 %).
    """
    v.choice("population family", family, FAMILIES)
    psi_one = one_psi_angle(lik.same, lik.flips)
    ll_one = float(one_psi_loglik(lik.same, lik.flips, psi_one).sum())
    spread = _moment_spread(lik.same, lik.flips, psi_one)
    starts = _starts(family, psi_one, spread)
    if thorough:
        pop, ll = _maximize(lik, family, starts, 1e-5)
    else:
        pop, ll = _maximize(lik, family, starts[:1], 1e-4)
    if family == "normal" and ll < ll_one:
        pop, ll = PsiPopulation("normal", psi_one, 0.0), ll_one
    fit = PopulationFit(pop, ll, psi_one, ll_one)
    if not (intervals and family == "normal"):
        return fit
    loc_ci, loc_limited = _profile_interval(lik, fit, "location")
    scale_ci, scale_limited = _profile_interval(lik, fit, "scale")
    return PopulationFit(pop, ll, psi_one, ll_one, loc_ci, scale_ci, (*loc_limited, *scale_limited))


def _profile(lik: Likelihood, fit: PopulationFit, which: str, value: float) -> float:
    """max over the other parameter of log L with ``which`` held at ``value``."""
    from scipy.optimize import minimize_scalar

    (loc_lo, loc_hi), (sc_lo, sc_hi) = _bounds("normal")
    pop = fit.population
    if which == "location":

        def cost(s: float) -> float:
            return _negative(lik.total_at("normal", value, s))

        lo, hi = sc_lo, min(sc_hi, max(4.0 * pop.scale, 0.05))
    else:

        def cost(s: float) -> float:
            return _negative(lik.total_at("normal", s, value))

        lo, hi = max(loc_lo, pop.location - 0.5), loc_hi
    res = minimize_scalar(cost, bounds=(lo, hi), method="bounded", options={"xatol": 1e-6})
    best = -float(res.fun)
    if which == "scale" or pop.scale == 0.0:
        return best
    # The spread may sit on its bound 0 at this location: the one-ψ value there, exactly.
    return max(best, float(one_psi_loglik(lik.same, lik.flips, value).sum()))


def _profile_interval(
    lik: Likelihood, fit: PopulationFit, which: str
) -> tuple[tuple[float, float], tuple[str, ...]]:
    """The 95 % profile-likelihood interval of ``which`` (location or scale)."""
    from scipy.optimize import brentq

    (loc_lo, loc_hi), (sc_lo, sc_hi) = _bounds("normal")
    pop = fit.population
    best = pop.location if which == "location" else pop.scale
    lo_bound, hi_bound = (loc_lo, loc_hi) if which == "location" else (sc_lo, sc_hi)
    target = fit.loglik - PROFILE_DROP

    def gap(x: float) -> float:
        return _profile(lik, fit, which, x) - target

    ends = []
    limited = []
    for side, bound in (("low", lo_bound), ("high", hi_bound)):
        if best == bound:
            ends.append(bound)
            continue
        if gap(bound) >= 0.0:
            ends.append(bound)
            if which == "scale" and side == "high":  # 90°, 0 for location: the fold, 0 spread
                limited.append(f"{which} {side}")
            continue
        ends.append(
            float(
                brentq(gap, bound, best, xtol=1e-6)
                if side == "low"
                else brentq(gap, best, bound, xtol=1e-6)
            )
        )
    return (ends[0], ends[1]), tuple(limited)


# --- held-out people ---------------------------------------------------------------------


@dataclass(frozen=True)
class HeldOut:
    """How well each model predicts people it was not fitted to.

    The people are split at random into ``folds`` groups, ``repeats`` times; each group is
    predicted by the models fitted to the others.

    Attributes
    ----------
    folds, repeats, seed : int
        The splits and the seed that draws them (:mod:`coinflight.probability.streams`).
    coverage, coverage_one_psi : float
        Share of held-out people whose same-side count lies within the model's central 95 %
        predictive interval for a person with that many flips (the ψ population's mixture of
        binomials; one ψ's binomial).
    coverage_range, coverage_range_one_psi : (float, float)
        The least and the greatest coverage of one split.
    log_score, log_score_one_psi : float
        Mean log predictive probability of a held-out person's count (higher is better).
    predictions : int
        Held-out predictions made: people × repeats.
    """

    folds: int
    repeats: int
    seed: int
    coverage: float
    coverage_one_psi: float
    coverage_range: tuple[float, float]
    coverage_range_one_psi: tuple[float, float]
    log_score: float
    log_score_one_psi: float
    predictions: int


FIT_SECONDS = 0.02
"""Seconds of one held-out fit of 48 people on the reference 2-core machine, taken as growing
with the number of people."""


def held_out_seconds(people: int, folds: int, repeats: int) -> float:
    """Estimated seconds of :func:`held_out`: folds × repeats fits of :data:`FIT_SECONDS`, each
    scaled by people / 48."""
    return FIT_SECONDS * folds * repeats * max(people, 1) / 48.0


def check_splits(people: int, folds: int, repeats: int) -> tuple[int, int]:
    """``folds`` and ``repeats`` checked: 2 ≤ folds ≤ people, 1 ≤ repeats ≤ MAX_REPEATS, the
    estimated work (:func:`held_out_seconds`) within the run limit."""
    if people < 2:
        raise ValueError(f"held-out people need at least 2 people, got {people}")
    folds = v.count("folds", folds, 2, people)
    repeats = v.count("repeats", repeats, 1, MAX_REPEATS)
    v.work_bound(
        f"a held-out check of {people} people in {folds} folds × {repeats} splits",
        held_out_seconds(people, folds, repeats),
        v.MAX_RUN_SECONDS,
        "s of estimated work",
        "use fewer folds or repeats",
    )
    return folds, repeats


def held_out(
    lik: Likelihood,
    folds: int = DEFAULT_FOLDS,
    repeats: int = DEFAULT_REPEATS,
    seed: streams.SeedLike = None,
) -> HeldOut:
    """Coverage and log score of both models on held-out people (:class:`HeldOut`).

    Split r permutes the people with :func:`coinflight.probability.streams.generator` (root,
    r) and cuts the permutation into ``folds`` near-equal groups (``numpy.array_split``); the
    same seed gives the same splits. A count k is inside the central 95 % interval
    [q(0.025), q(0.975)] of a discrete predictive distribution F iff F(k) ≥ 0.025 and
    F(k − 1) < 0.975.
    """
    from scipy.stats import binom

    folds, repeats = check_splits(len(lik.flips), folds, repeats)
    root = streams.seed_sequence(seed)
    covered: list[float] = []
    covered_one: list[float] = []
    score = score_one = 0.0
    for r in range(repeats):
        order = streams.generator(root, r).permutation(len(lik.flips))
        hit = hit_one = 0
        for test in np.array_split(order, folds):
            train = np.setdiff1d(order, test)
            fit = fit_population(lik.subset(train), intervals=False, thorough=False)
            held = lik.subset(test)
            masses = fit.population.cell_masses()
            low, high = held.cdf @ masses, held.cdf_below @ masses
            hit += int(np.count_nonzero((low >= 0.025) & (high < 0.975)))
            score += float(held.per_person(fit.population).sum())
            p_one = float(same_side_probability(fit.one_psi))
            low1 = binom.cdf(held.same, held.flips, p_one)
            high1 = binom.cdf(held.same - 1, held.flips, p_one)
            hit_one += int(np.count_nonzero((low1 >= 0.025) & (high1 < 0.975)))
            score_one += float(one_psi_loglik(held.same, held.flips, fit.one_psi).sum())
        covered.append(hit / len(order))
        covered_one.append(hit_one / len(order))
    total = repeats * len(lik.flips)
    return HeldOut(
        folds=folds,
        repeats=repeats,
        seed=streams.reported_seed(root),
        coverage=float(np.mean(covered)),
        coverage_one_psi=float(np.mean(covered_one)),
        coverage_range=(min(covered), max(covered)),
        coverage_range_one_psi=(min(covered_one), max(covered_one)),
        log_score=score / total,
        log_score_one_psi=score_one / total,
        predictions=total,
    )


def predictive_interval(flips: NDArray[np.int64], pop: PsiPopulation) -> FloatArray:
    """The central 95 % predictive interval of the same-side *rate* of a person with ``flips``
    flips under the population ``pop``: shape (people, 2), the 2.5 % and 97.5 % quantiles of
    the count (a mixture of binomials over the cells) divided by ``flips``.

    For drawing: the mixture is taken over :data:`COARSE` cells merged into one (p their
    mass-weighted mean), ten times fewer binomials; a quantile moves by at most a count or two
    (tested against the fine cells).
    """
    from scipy.special import bdtr

    n = np.asarray(flips, dtype=np.int64)
    p, w = _coarse_cells(pop.cell_masses())
    out = np.empty((len(n), 2))
    for col, level in enumerate((0.025, 0.975)):
        lo = np.full(len(n), -1, dtype=np.int64)  # F(lo) < level
        hi = n.copy()  # F(hi) ≥ level
        while np.any(hi - lo > 1):
            mid = (lo + hi) // 2
            f = bdtr(mid[:, None], n[:, None], p[None, :]) @ w
            ok = f >= level
            hi = np.where(ok, mid, hi)
            lo = np.where(ok, lo, mid)
        out[:, col] = hi / n
    return out


def predictive_interval_one_psi(flips: NDArray[np.int64], psi: float) -> FloatArray:
    """The central 95 % interval of the same-side rate of a person with ``flips`` flips when
    every flip has the angle ψ: the 2.5 % and 97.5 % quantiles of Binomial(flips, p(ψ))
    (``scipy.stats.binom.ppf``) divided by ``flips``; shape (people, 2)."""
    from scipy.stats import binom

    n = np.asarray(flips, dtype=np.int64)
    p = float(same_side_probability(psi))
    return np.column_stack([binom.ppf(0.025, n, p), binom.ppf(0.975, n, p)]) / n[:, None]


COARSE = 10
"""Quadrature cells merged into one by :func:`predictive_interval`."""


def _coarse_cells(masses: FloatArray) -> tuple[FloatArray, FloatArray]:
    """p and mass of the cells merged :data:`COARSE` at a time (the last cell, p = 1, alone);
    groups without mass left out."""
    body, last = masses[:-1].reshape(-1, COARSE), masses[-1]
    mass = body.sum(axis=1)
    p_body = _P_CELLS[:-1].reshape(-1, COARSE)
    with np.errstate(invalid="ignore"):
        p = np.where(mass > 0, (p_body * body).sum(axis=1) / mass, p_body.mean(axis=1))
    p, mass = np.append(p, 1.0), np.append(mass, last)
    keep = mass > 1e-12 * mass.max()
    return p[keep], mass[keep] / mass[keep].sum()


# --- the predictions the model was not fitted to ------------------------------------------


@dataclass(frozen=True)
class StartFaceTest:
    """Does the same-side rate depend on the face the flip started from?

    The precession model says no: heads and tails are the same to the physics. Pooled: Pearson's
    χ² on the 2 × 2 table (start face × same / different side, ``scipy.stats.chi2_contingency``
    without continuity correction). Per person: the sum of each person's 1-degree χ² (people with
    both faces started and both outcomes seen), on as many degrees of freedom.

    Attributes
    ----------
    rate_heads, rate_tails : float
        Same-side rate of the flips started heads up, and tails up.
    chi2, p_value : float
        The pooled test.
    chi2_people, p_value_people : float
        The per-person test.
    df_people : int
        People in the per-person test.
    people_below_005 : int
        People whose own test gives p < 0.05 (about 5 % of ``df_people`` when the model is right).
    """

    rate_heads: float
    rate_tails: float
    chi2: float
    p_value: float
    chi2_people: float
    df_people: int
    p_value_people: float
    people_below_005: int


def start_face_test(counts: NDArray[np.int64]) -> StartFaceTest:
    """:class:`StartFaceTest` of a (people, 4) table hsame, hdiff, tsame, tdiff.

    Started heads up: hsame same, tdiff different; started tails up: tsame same, hdiff
    different (Bartoš et al.'s columns, :mod:`coinflight.studies.data`).
    """
    from scipy.stats import chi2 as chi2_dist

    c = np.asarray(counts, dtype=np.int64)
    tables = np.stack([c[:, [0, 3]], c[:, [2, 1]]], axis=1)  # person × start × (same, diff)
    pooled = tables.sum(axis=0)
    stat, p = _chi2_2x2(pooled)
    per = [_chi2_2x2(t) for t in tables if _testable(t)]
    stats = np.array([s for s, _ in per])
    total = float(stats.sum()) if per else 0.0
    with np.errstate(invalid="ignore", divide="ignore"):
        rates = pooled[:, 0] / pooled.sum(axis=1)
    return StartFaceTest(
        rate_heads=float(rates[0]),
        rate_tails=float(rates[1]),
        chi2=stat,
        p_value=p,
        chi2_people=total,
        df_people=len(per),
        p_value_people=float(chi2_dist.sf(total, len(per))) if per else 1.0,
        people_below_005=sum(1 for _, q in per if q < 0.05),
    )


def _testable(t: NDArray[np.int64]) -> bool:
    return bool((t.sum(axis=0) > 0).all() and (t.sum(axis=1) > 0).all())


def _chi2_2x2(t: NDArray[np.int64]) -> tuple[float, float]:
    from scipy.stats import chi2_contingency

    if not _testable(t):
        return 0.0, 1.0
    res = chi2_contingency(t, correction=False)
    return float(res.statistic), float(res.pvalue)


@dataclass(frozen=True)
class BelowHalfTest:
    """Is any person's true same-side rate below 1/2?

    The model says no: p(ψ) ≥ 1/2 for every ψ. People are observed below 1/2 by sampling alone;
    the question is whether more are than sampling explains.

    Attributes
    ----------
    observed : int
        People whose same-side rate is below 1/2.
    expected_at_half : float
        Expected number if every person's true rate were exactly 1/2, the most any set of true
        rates ≥ 1/2 can give: Σ P(Binomial(n_i, ½) < n_i / 2).
    p_value_at_half : float
        P(at least ``observed``) under that bound (the count is a Poisson-binomial variable):
        a test of "no true rate below 1/2" that holds for any true rates ≥ 1/2.
    expected_model : float
        Expected number under the fitted population: Σ_i P(k < n_i / 2) of each person's
        predictive distribution (the population was fitted to these counts; its p ≥ 1/2 was not).
    p_value_model : float
        P(at least ``observed``) under the fitted population.
    lowest_person : str
        The person whose one-sided binomial test of "rate ≥ 1/2" gives the least p.
    lowest_p_value : float
        That test's p, and ``lowest_p_holm`` = min(1, people × p) (Holm's first step).
    """

    observed: int
    expected_at_half: float
    p_value_at_half: float
    expected_model: float
    p_value_model: float
    lowest_person: str
    lowest_p_value: float
    lowest_p_holm: float


def below_half_test(lik: Likelihood, pop: PsiPopulation, people: Sequence[str]) -> BelowHalfTest:
    """:class:`BelowHalfTest` of the people of ``lik`` under the population ``pop``."""
    from scipy.stats import binom

    k, n = lik.same, lik.flips
    below = 2 * k < n
    cut = (n - 1) // 2  # largest count below n / 2
    at_half = binom.cdf(cut, n, 0.5)
    masses = pop.cell_masses()
    model = binom.cdf(cut[:, None], n[:, None], _P_CELLS[None, :]) @ masses
    one_sided = binom.cdf(k, n, 0.5)  # P(count ≤ k | rate ½): the least-favourable rate ≥ ½
    i = int(np.argmin(one_sided))
    observed = int(np.count_nonzero(below))
    return BelowHalfTest(
        observed=observed,
        expected_at_half=float(at_half.sum()),
        p_value_at_half=_poisson_binomial_tail(at_half, observed),
        expected_model=float(model.sum()),
        p_value_model=_poisson_binomial_tail(model, observed),
        lowest_person=people[i],
        lowest_p_value=float(one_sided[i]),
        lowest_p_holm=float(min(1.0, len(n) * one_sided[i])),
    )


def _poisson_binomial_tail(probabilities: FloatArray, at_least: int) -> float:
    """P(Σ Bernoulli(p_i) ≥ ``at_least``): the distribution of the sum as the product of the
    generating polynomials ∏ (1 − p_i + p_i z), by repeated convolution."""
    pmf = np.array([1.0])
    for q in np.asarray(probabilities, dtype=float):
        pmf = np.convolve(pmf, [1.0 - q, q])
    return float(min(1.0, pmf[at_least:].sum()))


# --- all of it ----------------------------------------------------------------------------


@dataclass(frozen=True)
class FlipperAnalysis:
    """:func:`analyse`'s answer: how people's flips differ, by the precession model.

    Attributes
    ----------
    heterogeneity : Heterogeneity
        χ², I² and τ of the people's rates (:func:`coinflight.studies.data.heterogeneity`).
    fit : PopulationFit
        The normal ψ population (folded at 90°) against one ψ.
    alternative : PopulationFit
        The log-normal population of 90° − ψ, for comparison.
    people : tuple of PersonPsi
        Each person's shrunken ψ.
    held_out : HeldOut or None
        The check on held-out people (None with fewer than 2 people).
    start_face : StartFaceTest
        Same-side rate by starting face.
    below_half : BelowHalfTest
        People below 1/2.
    seed : int
        The seed of the held-out splits.
    """

    heterogeneity: Heterogeneity
    fit: PopulationFit
    alternative: PopulationFit
    people: tuple[PersonPsi, ...]
    held_out: HeldOut | None
    start_face: StartFaceTest
    below_half: BelowHalfTest
    seed: int

    def to_dict(self) -> dict[str, Any]:
        """The JSON-ready ``heterogeneity`` object (angles in degrees)."""
        het, fit, alt = self.heterogeneity, self.fit, self.alternative
        pop = fit.population
        ho = self.held_out

        def deg(pair: tuple[float, float] | None) -> list[float] | None:
            return None if pair is None else [math.degrees(x) for x in pair]

        return {
            "chi2": het.chi2,
            "df": het.dof,
            "dof": het.dof,
            "p_value": het.p_value,
            "i2": het.i2,
            "tau": het.tau,
            "model": "psi ~ normal(psi_mean, psi_sd) folded at 90 deg; p(psi) of DHM 2007",
            "psi_mean": math.degrees(pop.location),
            "psi_mean_ci95": deg(fit.location_ci95),
            "psi_sd": math.degrees(pop.scale),
            "psi_sd_ci95": deg(fit.scale_ci95),
            "ci95_limited": list(fit.limited),
            "psi_one": math.degrees(fit.one_psi),
            "loglik": fit.loglik,
            "loglik_one_psi": fit.loglik_one_psi,
            "loglik_ratio": fit.loglik_ratio,
            "lr_statistic": fit.lr_statistic,
            "lr_p_value": fit.lr_p_value,
            "alternative": {
                "model": "90 deg - psi lognormal",
                "psi_median": math.degrees(alt.population.location),
                "log_sd": alt.population.scale,
                "loglik": alt.loglik,
                "loglik_vs_normal": alt.loglik - fit.loglik,
            },
            "heldout_coverage": None if ho is None else ho.coverage,
            "heldout_coverage_one_psi": None if ho is None else ho.coverage_one_psi,
            "heldout_coverage_range": None if ho is None else list(ho.coverage_range),
            "heldout_coverage_range_one_psi": None
            if ho is None
            else list(ho.coverage_range_one_psi),
            "heldout_log_score": None if ho is None else _finite(ho.log_score),
            "heldout_log_score_one_psi": None if ho is None else _finite(ho.log_score_one_psi),
            "folds": None if ho is None else ho.folds,
            "repeats": None if ho is None else ho.repeats,
            "seed": self.seed,
            "start_face": {
                "p_same_side_heads_start": self.start_face.rate_heads,
                "p_same_side_tails_start": self.start_face.rate_tails,
                "chi2": self.start_face.chi2,
                "p_value": self.start_face.p_value,
                "chi2_people": self.start_face.chi2_people,
                "df_people": self.start_face.df_people,
                "p_value_people": self.start_face.p_value_people,
                "people_p_below_0_05": self.start_face.people_below_005,
            },
            "below_half": {
                "observed": self.below_half.observed,
                "expected_at_half": self.below_half.expected_at_half,
                "p_value_at_half": self.below_half.p_value_at_half,
                "expected_model": self.below_half.expected_model,
                "p_value_model": self.below_half.p_value_model,
                "lowest_person": self.below_half.lowest_person,
                "lowest_p_value": self.below_half.lowest_p_value,
                "lowest_p_holm": self.below_half.lowest_p_holm,
            },
            "per_person": [
                {
                    "person": p.person,
                    "psi": math.degrees(p.psi),
                    "psi_ci95": deg(p.ci95),
                    "p_same_side": p.p_same_side,
                }
                for p in self.people
            ],
        }

    def report(self) -> list[str]:
        """The short text block of ``coinflight data``."""
        het, fit, alt, sf, bh = (
            self.heterogeneity,
            self.fit,
            self.alternative,
            self.start_face,
            self.below_half,
        )
        pop = fit.population

        def ci(pair: tuple[float, float] | None) -> str:
            if pair is None:
                return ""
            return f" [{math.degrees(pair[0]):.1f}°, {math.degrees(pair[1]):.1f}°]"

        lines = [
            "people differ: a ψ for each person from one population (p(ψ): Diaconis et al. 2007)",
            f"  I² = {het.i2:.2f}, s.d. of the true same-side rates τ = {het.tau:.4f}",
            f"  ψ normal, folded at 90°: mean {math.degrees(pop.location):.1f}°"
            f"{ci(fit.location_ci95)}, sd {math.degrees(pop.scale):.1f}°{ci(fit.scale_ci95)} "
            f"(95 % profile likelihood)",
            f"  one ψ = {math.degrees(fit.one_psi):.2f}° for all: log-likelihood "
            f"{fit.loglik_ratio:.1f} lower (LR {fit.lr_statistic:.1f}, p = {fit.lr_p_value:.2g})",
            f"  log-normal 90° − ψ instead: log-likelihood {alt.loglik - fit.loglik:+.1f}",
        ]
        ho = self.held_out
        if ho is not None:
            lines += [
                f"  held-out people, {ho.folds}-fold × {ho.repeats} splits (seed {ho.seed}): "
                f"95 % predictive intervals cover",
                f"    {100 * ho.coverage:.0f} % (ψ population), {100 * ho.coverage_one_psi:.0f} % "
                f"(one ψ); log score a person {ho.log_score:.2f} vs {ho.log_score_one_psi:.2f}",
            ]
        lines += [
            f"  starting face (predicted: no effect): same side {sf.rate_heads:.5f} heads-up, "
            f"{sf.rate_tails:.5f} tails-up,",
            f"    χ² = {sf.chi2:.2f} (p = {sf.p_value:.2g}); per person χ² = "
            f"{sf.chi2_people:.1f} on {sf.df_people} (p = {sf.p_value_people:.2g})",
            f"  below ½ (predicted: no true rate is): {bh.observed} people observed, "
            f"{bh.expected_model:.1f} expected by sampling under",
            f"    the fitted population (p = {bh.p_value_model:.2g}), at most "
            f"{bh.expected_at_half:.1f} if all were at ½ (p = {bh.p_value_at_half:.2g})",
        ]
        return lines


def _finite(x: float) -> float | None:
    """``x``, or None for −∞ (a model that gave a held-out count probability 0): JSON has no
    infinities."""
    return x if math.isfinite(x) else None


def analyse(
    table: CountsTable,
    seed: streams.SeedLike = None,
    *,
    folds: int = DEFAULT_FOLDS,
    repeats: int = DEFAULT_REPEATS,
) -> FlipperAnalysis:
    """Fit, check on held-out people and test the unfitted predictions (:class:`FlipperAnalysis`).

    Parameters
    ----------
    table : CountsTable
        Per-person counts (:func:`coinflight.studies.data.load_dataset`, ``read_counts``).
    seed : int, optional
        Seed of the held-out splits (None: a fresh one from the operating system); reported.
    folds, repeats : int
        Held-out splits (:func:`held_out`).

    Cost: about 1 s for Bartoš et al.'s 48 people with the default splits.
    """
    from coinflight.studies.data import heterogeneity

    streams.check_seed(seed)
    people = len(table.people)
    if people >= 2:
        folds, repeats = check_splits(people, folds, repeats)
    root = streams.seed_sequence(seed)
    lik = Likelihood.of(table.same_by_person, table.flips_by_person)
    fit = fit_population(lik)
    alternative = fit_population(lik, "lognormal", intervals=False)
    return FlipperAnalysis(
        heterogeneity=heterogeneity(table),
        fit=fit,
        alternative=alternative,
        people=shrunken(lik, fit.population, table.people),
        held_out=held_out(lik, folds, repeats, root) if people >= 2 else None,
        start_face=start_face_test(table.counts),
        below_half=below_half_test(lik, fit.population, table.people),
        seed=streams.reported_seed(root),
    )


def fitted_population(dataset: str) -> PsiPopulation:
    """The normal ψ population fitted to a shipped dataset (``coinflight bias --psi-dist
    bartos2023``): deterministic, no splits drawn."""
    from coinflight.studies.data import load_dataset

    table = load_dataset(dataset)
    lik = Likelihood.of(table.same_by_person, table.flips_by_person)
    return fit_population(lik, intervals=False).population


__all__ = [
    "CELLS",
    "CELL_DEG",
    "COARSE",
    "DEFAULT_FOLDS",
    "DEFAULT_REPEATS",
    "FAMILIES",
    "FIT_SECONDS",
    "MAX_FIT_PEOPLE",
    "BelowHalfTest",
    "FlipperAnalysis",
    "HeldOut",
    "Likelihood",
    "PersonPsi",
    "PopulationFit",
    "PsiPopulation",
    "StartFaceTest",
    "analyse",
    "below_half_test",
    "fit_population",
    "fitted_population",
    "held_out",
    "held_out_seconds",
    "one_psi_angle",
    "one_psi_loglik",
    "predictive_interval",
    "predictive_interval_one_psi",
    "shrunken",
    "start_face_test",
]
