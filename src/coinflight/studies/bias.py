"""Same-side bias of precessing coins: closed form, averages over ψ, inverse, Monte Carlo check.

A real toss does not spin about a diameter: the normal precesses about the angular momentum on a
cone of half-angle ψ, and a coin caught in the hand then lands on the side it started with
probability p(ψ) ≥ 1/2 (Diaconis, Holmes & Montgomery 2007; REFERENCES §2). This module is the
value layer over :mod:`coinflight.core.precession`: it validates angles, averages p over a
distribution of ψ, inverts p, and checks the closed form by simulating the full torque-free
flight (:func:`coinflight.core.torque_free.normal_alignment`) for random flight times and spins.

Angles are in radians unless ``degrees=True`` is passed, as in
``scipy.spatial.transform.Rotation``.

Examples
--------
>>> round(float(same_side_probability(60.0, degrees=True)), 3)
0.608
>>> round(float(psi_for_probability(0.508, degrees=True)), 2)
80.99
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING, Any, Protocol, runtime_checkable

import numpy as np
from numpy.typing import ArrayLike, NDArray

from coinflight import _validation as v
from coinflight.core import precession
from coinflight.core.torque_free import normal_alignment
from coinflight.model.coin import DEFAULT_COIN, Coin
from coinflight.model.distributions import Normal
from coinflight.probability import streams
from coinflight.probability.result import BinomialEstimate

if TYPE_CHECKING:
    from coinflight.model.ensemble import TossDistribution

FloatArray = NDArray[np.float64]

TAIL_MASS = 1e-6
"""Largest probability a ψ distribution may put outside [0°, 180°], see
:func:`check_psi_distribution`."""

DEFAULT_FLIGHT_TIME = (0.3, 0.7)
"""Flight times T of the Monte Carlo check, s: uniform on this range (hand tosses, REFERENCES
§2: v0 ≈ 2.4 m/s gives T ≈ 0.49 s)."""

DEFAULT_PRECESSION_RATE = (150.0, 330.0)
"""Precession rates ωp of the Monte Carlo check, rad/s: uniform on this range (≈ 24-53 rev/s
around the 38 rev/s of a typical toss, REFERENCES §2). With T this spreads ωp T over ≈ 30
turns, which is what makes the phase effectively uniform and the closed form apply."""

QUADRATURE_TOLERANCE = 1e-8
"""Largest accepted error estimate of :func:`mean_same_side_probability`."""


@runtime_checkable
class QuantileDistribution(Protocol):
    """Anything with a quantile function: ``ppf(u)`` maps u ∈ (0, 1) to values, vectorised."""

    def ppf(self, u: ArrayLike) -> ArrayLike: ...


def _angle_scale(degrees: bool) -> tuple[float, float, str]:
    """(factor to radians, upper limit π in the user's unit, unit name)."""
    return (math.pi / 180.0, 180.0, "degrees") if degrees else (1.0, math.pi, "rad")


def check_psi(psi: ArrayLike, *, degrees: bool = False) -> FloatArray:
    """ψ in radians, or ValueError if any value is outside [0, π] (or [0°, 180°]).

    ψ is the angle between two directions (the heads normal and the angular momentum), so it
    lies in [0, π].
    """
    factor, top, unit = _angle_scale(degrees)
    arr = v.in_range("precession angle psi", psi, 0.0, top, unit)
    return arr * factor


def same_side_probability(psi: ArrayLike, *, degrees: bool = False) -> FloatArray:
    """Probability p(ψ) that a coin precessing at cone angle ψ lands on its starting side.

    Parameters
    ----------
    psi : array_like
        Angle ψ between the heads normal and the angular momentum, in [0, π] rad (or [0°, 180°]
        with ``degrees=True``).
    degrees : bool
        Whether ``psi`` is in degrees.

    Returns
    -------
    ndarray
        p(ψ) in [1/2, 1], same shape as ``psi``.

    Notes
    -----
    p(ψ) = 1/2 + (1/π) arcsin(cot²ψ) for π/4 ≤ ψ ≤ 3π/4, else 1 (Diaconis, Holmes & Montgomery
    2007, section 2; REFERENCES §2), valid when the phase ωp T spreads over many turns.

    Examples
    --------
    Diaconis, Holmes & Montgomery's values: ψ = 60° → 0.608, 80° → 0.510, 90° → 1/2, and a
    coin that only wobbles (ψ < 45°) always lands as it started:

    >>> same_side_probability([60.0, 80.0, 90.0, 30.0], degrees=True).round(3)
    array([0.608, 0.51 , 0.5  , 1.   ])
    """
    return precession.same_side_probability(check_psi(psi, degrees=degrees))


def psi_for_probability(p: ArrayLike, *, degrees: bool = False) -> FloatArray:
    """The fixed precession angle ψ ∈ [π/4, π/2] for which p(ψ) = p.

    Parameters
    ----------
    p : array_like
        Same-side probability in [1/2, 1].
    degrees : bool
        Return degrees instead of radians.

    Returns
    -------
    ndarray
        ψ on the branch [π/4, π/2] (its mirror π − ψ gives the same p). p = 1 gives π/4, the
        largest angle at which the coin never turns over.

    Notes
    -----
    Closed-form inverse of Diaconis, Holmes & Montgomery's p(ψ), see
    :func:`coinflight.core.precession.angle_for_same_side`.
    """
    arr = v.in_range("same-side probability", p, 0.5, 1.0)
    psi = precession.angle_for_same_side(arr)
    return np.degrees(psi) if degrees else psi


def check_psi_distribution(dist: QuantileDistribution, *, degrees: bool = False) -> None:
    """ValueError if ``dist`` puts more than :data:`TAIL_MASS` of its mass outside [0, π].

    A distribution whose tails reach a hair beyond (a normal, say) is accepted: the tiny mass
    outside is folded back (ψ → −ψ, 2π − ψ), which p(ψ) does by itself since it depends on ψ
    only through cos²ψ and sin²ψ.
    """
    _, top, unit = _angle_scale(degrees)
    lo, hi = (float(x) for x in np.asarray(dist.ppf(np.array([TAIL_MASS, 1.0 - TAIL_MASS]))))
    if not (np.isfinite(lo) and np.isfinite(hi)) or lo < 0.0 or hi > top:
        raise ValueError(
            f"the precession angle distribution must lie within [0, {top:g}] {unit} "
            f"(up to {TAIL_MASS:g} of its probability); its {TAIL_MASS:g} and "
            f"{1 - TAIL_MASS:g} quantiles are {lo:.4g} and {hi:.4g} {unit}"
        )


def mean_same_side_probability(dist: QuantileDistribution, *, degrees: bool = False) -> float:
    """Same-side probability averaged over a distribution of precession angles.

    Parameters
    ----------
    dist : object with ``ppf``
        Distribution of ψ given by its quantile function (e.g. the distributions of
        :mod:`coinflight.model.distributions`), in radians or, with ``degrees=True``, degrees.
    degrees : bool
        Whether ``dist`` is a distribution of degrees.

    Returns
    -------
    float
        E[p(ψ)] = ∫₀¹ p(ψ(u)) du, with ψ(u) the quantile function.

    Notes
    -----
    p(ψ) from Diaconis, Holmes & Montgomery 2007. The integral is taken in probability space by
    adaptive Gauss-Kronrod quadrature (``scipy.integrate.quad``, split where ψ crosses π/4 and
    3π/4), so any distribution with a quantile function works, point masses included;
    requested absolute error 1e-10, and an error estimate above
    :data:`QUADRATURE_TOLERANCE` raises ``ArithmeticError``.
    """
    from scipy.integrate import quad
    from scipy.optimize import brentq

    check_psi_distribution(dist, degrees=degrees)
    factor, _, _ = _angle_scale(degrees)

    def psi_at(u: float) -> float:
        return float(np.asarray(dist.ppf(np.array([u])), dtype=float)[0]) * factor

    def integrand(u: float) -> float:
        return float(precession.same_side_probability(psi_at(u)))

    # p(ψ) has a square-root corner where ψ crosses π/4 and 3π/4 (the coin starts or stops
    # turning over): give quad those points, found on the quantile function.
    lo, hi = psi_at(TAIL_MASS), psi_at(1.0 - TAIL_MASS)
    points = [
        brentq(lambda u, c=corner: psi_at(u) - c, TAIL_MASS, 1.0 - TAIL_MASS, xtol=1e-14)
        for corner in (0.25 * math.pi, 0.75 * math.pi)
        if lo < corner < hi
    ]
    # full_output: quad reports trouble in its return value instead of warning; the error
    # estimate is checked here instead.
    value, err, *_ = quad(
        integrand,
        0.0,
        1.0,
        points=points or None,
        epsabs=1e-10,
        epsrel=0.0,
        limit=400,
        full_output=1,
    )
    if not err <= QUADRATURE_TOLERANCE:
        raise ArithmeticError(
            f"averaging p(psi) over the distribution did not converge (error estimate {err:.2g})"
        )
    return float(value)


def psi_mean_for_probability(p: float, sd: float = 0.0, *, degrees: bool = False) -> float:
    """Mean of a normal ψ distribution of spread ``sd`` whose average p(ψ) equals ``p``.

    Parameters
    ----------
    p : float
        Same-side probability, in [1/2, 1].
    sd : float
        Standard deviation of ψ (0: a fixed angle, the closed-form inverse).
    degrees : bool
        Whether ``sd`` and the result are in degrees.

    Returns
    -------
    float
        The mean ψ on the branch below π/2 (the mirrored mean π − ψ works as well).

    Raises
    ------
    ValueError
        If no mean ≤ π/2 gives ``p``: a spread makes the average exceed 1/2 even at ψ = π/2,
        so small p can then not be reached.

    Notes
    -----
    E[p(ψ)] (Diaconis, Holmes & Montgomery 2007) decreases as the mean moves up to π/2; the
    mean is found by Brent's method (``scipy.optimize.brentq``) to 1e-9 (in the unit of
    ``sd``).
    """
    from scipy.optimize import brentq

    target = float(v.in_range("same-side probability", p, 0.5, 1.0))
    _, top, unit = _angle_scale(degrees)
    spread = float(v.non_negative("spread of psi", sd, unit))
    if spread == 0.0:
        return float(psi_for_probability(target, degrees=degrees))
    right = top / 2.0
    # Lowest mean whose distribution still lies in [0, π] (see check_psi_distribution).
    from scipy.special import ndtri

    left = -spread * float(ndtri(TAIL_MASS))
    if left >= right:
        raise ValueError(
            f"a spread of {spread:g} {unit} in psi is too wide: a normal distribution of psi "
            f"must stay within [0, {top:g}] {unit}"
        )

    def excess(mean: float) -> float:
        return mean_same_side_probability(Normal(mean, spread), degrees=degrees) - target

    at_right = excess(right)
    if at_right > 0.0:
        raise ValueError(
            f"with a spread of {spread:g} {unit} in psi the same-side probability is at least "
            f"{target + at_right:.6f} (mean psi = {right:g} {unit}); {target:g} cannot be reached"
        )
    if excess(left) < 0.0:
        raise ValueError(
            f"with a spread of {spread:g} {unit} in psi no mean within the allowed range "
            f"[{left:.4g}, {right:g}] {unit} gives a same-side probability of {target:g}"
        )
    return float(brentq(excess, left, right, xtol=1e-9))


GRID_POINTS = 1_000_000
"""Points of the midpoint grid of :func:`expected_same_side` (split evenly over the varying
spin components)."""


def expected_same_side(dist: TossDistribution) -> float:
    """Closed-form same-side probability of a distribution of tosses, averaged over its spins.

    Each toss's spin (ωx, ωy, ωz) fixes its cone angle ψ and so its same-side probability p(ψ);
    this averages p(ψ) over the spin distribution. The flight time does not enter: the closed
    form assumes the phase ωp T is spread over many turns, which :func:`simulate_same_side` and
    :func:`coinflight.probability.estimate` check.

    Parameters
    ----------
    dist : coinflight.model.ensemble.TossDistribution
        The tosses (e.g. a preset of :mod:`coinflight.studies.presets`).

    Returns
    -------
    float
        E[p(ψ(ω))].

    Notes
    -----
    p(ψ) of Diaconis, Holmes & Montgomery 2007, ψ = cone angle of ω
    (:func:`~coinflight.core.torque_free.cone_angle`). The expectation is a midpoint rule in
    probability space, each varying component through its quantile function, with
    :data:`GRID_POINTS` points in all: 10⁶ points over one or two components, error below
    1e-6 for smooth (e.g. normal) distributions away from ψ = 45°, 135°.
    """
    from coinflight.core.torque_free import cone_angle

    i1, i3 = dist.moments
    comps = [dist.omega_x, dist.omega_y, dist.omega_z]
    varying = [k for k, c in enumerate(comps) if not c.is_fixed]
    cells = max(1, round(GRID_POINTS ** (1.0 / max(1, len(varying)))))
    u = (np.arange(cells) + 0.5) / cells
    axes = [
        np.asarray(c.ppf(u), dtype=float) if k in varying else np.array([c.mean])
        for k, c in enumerate(comps)
    ]
    wx, wy, wz = np.meshgrid(*axes, indexing="ij", sparse=True)
    omega = np.stack(np.broadcast_arrays(wx, wy, wz), axis=-1)
    return float(np.mean(precession.same_side_probability(cone_angle(omega, i1, i3))))


TOSSES_PER_SECOND = 4e6
"""Same-side tosses a second (:func:`simulate_same_side`): 10⁷ in 3.7 s on the busy 2-core
machine, start-up included."""
MIN_TOSSES = 100
"""Fewest simulated tosses for a same-side fraction with a standard error. The binomial s.e.
sqrt(p (1 − p) / n) is estimated from the sample's p; from one toss it is always 0 and from a
handful it is often 0 (every toss the same side), which would report an exact agreement with the
closed form. The normal approximation behind "z s.e. from the closed form" wants n p (1 − p)
≳ 10, i.e. n ≳ 40 at p ≈ 1/2 (the usual textbook rule); 100 leaves room."""


def check_tosses(n: object) -> int:
    """``n`` as the number of tosses of a Monte Carlo check: a whole number ≥ :data:`MIN_TOSSES`,
    at most an hour's work (:data:`TOSSES_PER_SECOND`)."""
    try:
        count = v.count("number of tosses", n, MIN_TOSSES)
    except ValueError:
        raise ValueError(
            f"number of tosses must be at least {MIN_TOSSES} (from fewer the standard error is "
            f"not meaningful), got {n}"
        ) from None
    v.work_bound(
        f"a same-side Monte Carlo check of {count} tosses",
        count,
        TOSSES_PER_SECOND * v.MAX_RUN_SECONDS,
        "tosses",
        "use fewer tosses (the standard error is at most 0.5/√n)",
        TOSSES_PER_SECOND,
    )
    return count


def simulate_same_side(
    psi: ArrayLike | QuantileDistribution,
    n: int,
    seed: streams.SeedLike = None,
    *,
    coin: Coin | None = None,
    flight_time: tuple[float, float] = DEFAULT_FLIGHT_TIME,
    precession_rate: tuple[float, float] = DEFAULT_PRECESSION_RATE,
    degrees: bool = False,
    progress: Callable[[int], object] | None = None,
) -> BinomialEstimate:
    """Same-side frequency of simulated tosses with precession angle ψ (fixed or distributed).

    Each toss draws a flight time T ~ U(flight_time), a precession rate ωp ~ U(precession_rate),
    a random direction of the transverse spin, and (for a distribution) ψ from its quantile
    function; it sets the body spin on the cone of angle ψ (:func:`~coinflight.core.precession.
    spin_on_cone`) and decides the face with the exact torque-free flight,
    :func:`~coinflight.core.torque_free.normal_alignment` (n(T)·n0 > 0: same side).

    Parameters
    ----------
    psi : float or object with ``ppf``
        A fixed precession angle, or a distribution of it.
    n : int
        Number of tosses (≥ :data:`MIN_TOSSES`).
    seed : int or SeedSequence, optional
        Seed of the tosses (None: a fresh one from the OS); the result reports it. The tosses
        come from :func:`coinflight.probability.streams.unit_cube` (T, ωp, azimuth and the
        quantile of ψ each from its own stream per block), so a run of n tosses is the first n
        tosses of any longer run with the same seed.
    coin : Coin, optional
        Default the US quarter; enters only through I1 / I3.
    flight_time : (float, float)
        Range of T, s.
    precession_rate : (float, float)
        Range of ωp, rad/s.
    degrees : bool
        Whether ``psi`` is in degrees.
    progress : callable, optional
        Called with the number of tosses done after each draw of them (a progress bar).

    Returns
    -------
    BinomialEstimate
        Same-side tosses (``successes``) of ``n``.
    """
    n = check_tosses(n)
    streams.check_seed(seed)
    for name, rng_, unit in (
        ("flight time range", flight_time, "s"),
        ("precession rate range", precession_rate, "rad/s"),
    ):
        lo, hi = v.positive(name, rng_, unit)
        if lo > hi:
            raise ValueError(f"{name} must be (low, high) with low ≤ high, got {tuple(rng_)}")
    the_coin = coin if coin is not None else Coin.preset(DEFAULT_COIN)
    i1, i3 = the_coin.moments
    factor, _, _ = _angle_scale(degrees)
    fixed_psi: float | None = None
    dist: QuantileDistribution | None = None
    if isinstance(psi, QuantileDistribution):
        dist = psi
        check_psi_distribution(dist, degrees=degrees)
    else:
        value = check_psi(psi, degrees=degrees)
        if value.ndim:
            raise TypeError("psi must be a single angle or a distribution, not an array")
        fixed_psi = float(value)

    root = streams.seed_sequence(seed)
    same = 0
    for u in streams.unit_cube(root, n, 3 if dist is None else 4):
        t = flight_time[0] + (flight_time[1] - flight_time[0]) * u[0]
        wp = precession_rate[0] + (precession_rate[1] - precession_rate[0]) * u[1]
        azimuth = 2.0 * np.pi * u[2]
        if dist is not None:
            psi_k = np.asarray(dist.ppf(u[3]), dtype=float) * factor
        else:
            psi_k = np.full(u.shape[1], fixed_psi)
        w_perp, wz = precession.spin_on_cone(wp, psi_k, i1, i3)
        wx, wy = w_perp * np.cos(azimuth), w_perp * np.sin(azimuth)
        same += int(np.count_nonzero(normal_alignment(wx, wy, wz, t, i1, i3) > 0.0))
        if progress is not None:
            progress(u.shape[1])
    return BinomialEstimate(successes=same, n=n, seed=streams.reported_seed(root))


def simulate_same_side_at(
    angles: ArrayLike, n: int, seed: streams.SeedLike = None, **options: Any
) -> list[tuple[float, BinomialEstimate]]:
    """:func:`simulate_same_side` at each fixed angle of ``angles``: (angle, estimate) pairs.

    Angle i draws from child i of the seed's ``SeedSequence``
    (:func:`coinflight.probability.streams.child`), so the points are independent and each
    reports the one seed; the whole run is refused before any work beyond the run limit.
    ``options`` are those of :func:`simulate_same_side` (``coin``, ``degrees``, …).
    """
    psi = check_psi(angles, degrees=bool(options.get("degrees", False)))
    count = check_tosses(n)
    v.work_bound(
        f"{v.quantity(psi.size)} angles × {v.quantity(count)} tosses",
        psi.size * count,
        TOSSES_PER_SECOND * v.MAX_RUN_SECONDS,
        "tosses",
        "use fewer angles or tosses",
        TOSSES_PER_SECOND,
    )
    root = streams.seed_sequence(seed)
    angle_list = [float(a) for a in np.atleast_1d(np.asarray(angles, dtype=float))]
    out = []
    for i, a in enumerate(angle_list):
        out.append((a, simulate_same_side(a, count, streams.child(root, i), **options)))
    return out


__all__ = [
    "DEFAULT_FLIGHT_TIME",
    "DEFAULT_PRECESSION_RATE",
    "MIN_TOSSES",
    "QuantileDistribution",
    "check_psi",
    "check_psi_distribution",
    "check_tosses",
    "expected_same_side",
    "mean_same_side_probability",
    "psi_for_probability",
    "psi_mean_for_probability",
    "same_side_probability",
    "simulate_same_side",
    "simulate_same_side_at",
]
