"""Exact P(heads): integrate the measure of the heads bands instead of sampling.

Which integral is used (``details["how"]``):

* ``closed form``: ω_z = 0 (the paper's cases a and b), the flight time uniform or fixed, at
  most one of ωx, ωy a uniform range and the other fixed. A finite sum over the band pieces
  (:func:`coinflight.core.bands.diameter_spin_integral`); error at rounding level (~1e-14).
* ``closed form in T``: every spin fixed (precession allowed), any flight-time distribution
  with a CDF: Σ over bands of CDF(hi) − CDF(lo).
* ``closed form in T, Gauss product rule over the spins split at ψ = 45°``: a normal flight
  time (or launch speed) with any ranged spins when ω_z is ranged or ω_z = 0, or one ranged spin
  with ω_z fixed: the closed form over T for arrays of spins
  (:func:`coinflight.core.bands.same_side_over_times`), then Gauss–Legendre panels over the
  spins with the kink at ψ = 45° put on one spin and smoothed by a change of variable; node
  counts raised until two agree within 1e-9 (their difference is the error estimate), else a
  ValueError.
* ``quadrature``: otherwise, with at most two ranged spin components and a continuous flight
  time: adaptive quadrature (``scipy.integrate.quad``) over the ranged spins, in probability
  space (u = CDF(ω)), of the closed form in T or, with ω_z = 0 and a uniform spin range, of the
  closed form in that spin. The error estimate is reported.
* A fixed flight time with ranged spins and precession, or three ranged spin components with a
  uniform or fixed flight time: a ValueError naming the methods to use instead.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from typing import Any

import numpy as np

from coinflight import _validation as v
from coinflight.core import bands
from coinflight.model.distributions import Distribution, Fixed, Normal, Uniform
from coinflight.model.ensemble import TossDistribution
from coinflight.outcomes.base import OutcomeModel
from coinflight.probability.registry import Estimator
from coinflight.probability.result import ProbabilityResult

TOLERANCE = 1e-9
"""Absolute and relative tolerance asked of the quadrature: 1e-9, the accuracy the exact method
promises. (1e-10 is beyond what round-off in the band sums allows for normal distributions:
QUADPACK then warns and takes twice as long.)"""
MAX_EVALUATIONS = 500_000
"""Budget of integrand evaluations for the quadrature, so that ``exact`` always ends in bounded
time: about 25-30 s on the reference 2-core machine. The slowest supported case, the ``human``
preset (normal flight time, two normal spins), needs about 300,000 (~16 s). Past the budget a
ValueError names the sampling methods instead."""
MAX_PIECES = 50_000_000
"""Most band pieces the closed form may sum (about 25 s on the reference 2-core machine, memory
bounded by :data:`coinflight.core.bands.PIECES_PER_CHUNK`). A spin range of width Δω and flight
times up to T hold about 2 Δω T / π pieces; when the closed form is the integrand of a
quadrature, each evaluation may hold at most MAX_PIECES / 1000 of them."""
PIECES_PER_SECOND = 2e6
"""Band pieces the closed form sums a second (measured: ~470 ns each, 2-core machine)."""
_SPINS = ("omega_x", "omega_y", "omega_z")
_USE_INSTEAD = "use --method grid, monte-carlo or qmc instead"

NAME = "exact"
"""The method's name (its registry entry, results, messages)."""


def _p_same_fixed_spins(
    wx: float, wy: float, wz: float, t: Distribution, i1: float, i3: float
) -> float:
    """P(same side) for fixed spins, flight time ``t`` (any distribution with a CDF)."""
    perp2 = wx * wx + wy * wy
    axial = i3 / i1 * wz
    if perp2 == 0.0 or axial * axial >= perp2:
        # ψ ≤ 45°: cos²ψ + sin²ψ cos(ωp T) ≥ 0 with equality on a null set: always same side.
        return 1.0
    wp = math.sqrt(perp2 + axial * axial)
    a = float(bands.half_width(axial * axial / perp2))
    if isinstance(t, Fixed):
        return 1.0 if bool(bands.in_band(wp * t.value, a)) else 0.0
    if isinstance(t, Uniform):
        return float(bands.time_average_uniform(wp, a, t.low, t.high))
    lo_t, hi_t = t.bounds
    # Unbounded tails (normal): the mass beyond these quantiles is 2⁻⁵³ ≈ 1e-16 each.
    if not math.isfinite(lo_t):
        lo_t = max(0.0, float(t.ppf(2.0**-53)))
    if not math.isfinite(hi_t):
        hi_t = float(t.ppf(1.0 - 2.0**-53))
    lo, hi = bands.band_edges(wp, a, lo_t, hi_t)
    return float(np.sum(t.cdf(hi) - t.cdf(lo)))


def _check_pieces(x: Uniform, c: float, t2: float, limit: float) -> None:
    """Refuse, before any allocation, a closed form that would sum more than ``limit`` pieces."""
    lo, hi = x.low, x.high
    pieces = bands.diameter_spin_pieces(0.0, max(abs(lo), abs(hi)), 0.0, t2) + (
        bands.diameter_spin_pieces(0.0, min(abs(lo), abs(hi)), 0.0, t2) if lo < 0 < hi else 0.0
    )
    v.work_bound(
        f"the exact closed form for a spin range {lo:g}:{hi:g} rad/s with flight times up to "
        f"{t2:g} s",
        pieces,
        limit,
        "band pieces",
        _USE_INSTEAD,
        rate=PIECES_PER_SECOND,
    )


def _closed_form_diameter(
    x: Distribution, c: float, t: Distribution, limit: float = MAX_PIECES
) -> float:
    """P(same) for ω_z = 0, one spin ``x`` uniform (or fixed), the other fixed at c."""
    t1, t2 = (t.value, t.value) if isinstance(t, Fixed) else (t.low, t.high)  # type: ignore[attr-defined]
    if isinstance(x, Fixed):
        w = math.hypot(x.value, c)
        if w == 0.0:
            return 1.0
        if t1 == t2:
            return 1.0 if bool(bands.in_band(w * t1)) else 0.0
        return float(bands.time_average_uniform(w, np.pi / 2, t1, t2))
    assert isinstance(x, Uniform)
    lo, hi = x.low, x.high
    _check_pieces(x, c, t2, limit)
    total = 0.0
    # The integrand depends on |x| only: fold the negative part onto [0, ∞).
    if hi > 0:
        total += bands.diameter_spin_integral(max(lo, 0.0), hi, c, t1, t2)
    if lo < 0:
        total += bands.diameter_spin_integral(max(-hi, 0.0), -lo, c, t1, t2)
    return total / (hi - lo)


class _OverBudget(Exception):
    """Raised inside the integrand when the quadrature has used its evaluation budget."""


def _quad(f: Callable[..., float], dims: int, details: dict[str, Any]) -> tuple[float, float]:
    """∫ f over [0, 1]^dims by adaptive Gauss–Kronrod (QUADPACK), with its error estimate.

    At most :data:`MAX_EVALUATIONS` evaluations of ``f``; past them a ValueError (the
    tolerance is never loosened). QUADPACK's warnings (round-off prevents the tolerance) are
    kept in ``details["warning"]`` rather than printed: the error estimate is reported either
    way.
    """
    import warnings

    from scipy.integrate import IntegrationWarning, nquad, quad

    budget = MAX_EVALUATIONS
    used = 0

    def counted(*u: float) -> float:
        nonlocal used
        used += 1
        if used > budget:
            raise _OverBudget
        return f(*u)

    opts = {"epsabs": TOLERANCE, "epsrel": TOLERANCE, "limit": 2000}
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", IntegrationWarning)
        try:
            if dims == 1:
                val, err = quad(counted, 0.0, 1.0, **opts)
            else:
                val, err = nquad(counted, [(0.0, 1.0)] * dims, opts=opts)
        except _OverBudget:
            raise ValueError(
                f"the exact quadrature did not reach its tolerance {TOLERANCE:g} within its "
                f"budget of {budget:,} integrand evaluations (a kinked integrand in {dims} "
                "dimensions); use --method qmc, monte-carlo or grid instead"
            ) from None
    details["evaluations"] = used
    messages = [" ".join(str(w.message).split()) for w in caught]
    if messages:
        details["warning"] = messages[0]
    return float(val), float(err)


_Details = dict[str, Any]


def _one_uniform_diameter_spin(dist: TossDistribution, ranged: list[str]) -> bool:
    """Spin about a diameter, T fixed or uniform, at most one ranged spin and that uniform."""
    return (
        dist.spin_about_diameter
        and isinstance(dist.flight_time, Fixed | Uniform)
        and (
            len(ranged) == 0 or (len(ranged) == 1 and isinstance(getattr(dist, ranged[0]), Uniform))
        )
    )


def _closed_form(
    dist: TossDistribution, ranged: list[str], details: _Details
) -> tuple[float, float]:
    """The band integral over the one uniform spin (or none), in closed form."""
    x_name = ranged[0] if ranged else "omega_x"
    c_name = "omega_y" if x_name == "omega_x" else "omega_x"
    return _closed_form_diameter(
        getattr(dist, x_name), getattr(dist, c_name).mean, dist.flight_time
    ), 0.0


def _closed_form_in_t(
    dist: TossDistribution, ranged: list[str], details: _Details
) -> tuple[float, float]:
    """Fixed spins: the band integral over T in closed form."""
    i1, i3 = dist.moments
    p = _p_same_fixed_spins(
        dist.omega_x.mean, dist.omega_y.mean, dist.omega_z.mean, dist.flight_time, i1, i3
    )
    return p, 0.0


def _two_diameter_spins_one_uniform(dist: TossDistribution, ranged: list[str]) -> bool:
    """Spin about a diameter, T fixed or uniform, both spins ranged, one of them uniform."""
    return (
        dist.spin_about_diameter
        and isinstance(dist.flight_time, Uniform | Fixed)
        and len(ranged) == 2
        and any(isinstance(getattr(dist, n), Uniform) for n in ranged)
    )


def _closed_form_and_quadrature(
    dist: TossDistribution, ranged: list[str], details: _Details
) -> tuple[float, float]:
    """One uniform spin in closed form, the other by quadrature over its quantiles."""
    t = dist.flight_time
    assert isinstance(t, Fixed | Uniform)  # _two_diameter_spins_one_uniform
    x_name = next(n for n in ranged if isinstance(getattr(dist, n), Uniform))
    c_name = "omega_y" if x_name == "omega_x" else "omega_x"
    x_dist, c_dist = getattr(dist, x_name), getattr(dist, c_name)
    _check_pieces(x_dist, 0.0, t.value if isinstance(t, Fixed) else t.high, MAX_PIECES / 1000)

    def inner(u: float) -> float:
        return _closed_form_diameter(x_dist, float(c_dist.ppf(u)), t, MAX_PIECES / 1000)

    return _quad(inner, 1, details)


def _spins_by_quadrature(dist: TossDistribution, ranged: list[str]) -> bool:
    """T ranged and at most two ranged spins."""
    return not isinstance(dist.flight_time, Fixed) and len(ranged) <= 2


def _closed_form_in_t_quadrature(
    dist: TossDistribution, ranged: list[str], details: _Details
) -> tuple[float, float]:
    """The band integral over T in closed form, quadrature over the ranged spins' quantiles."""
    i1, i3 = dist.moments
    spins = {name: getattr(dist, name) for name in _SPINS}

    def integrand(*u: float) -> float:
        w = {n: spins[n].mean for n in _SPINS}
        for name, ui in zip(ranged, u, strict=True):
            w[name] = float(spins[name].ppf(ui))
        return _p_same_fixed_spins(
            w["omega_x"], w["omega_y"], w["omega_z"], dist.flight_time, i1, i3
        )

    return _quad(integrand, len(ranged), details)


GAUSS_ORDERS = (12, 16, 24, 32, 48, 64)
"""Gauss–Legendre nodes per panel tried in turn by the Gauss product rule over the spins; the
result is the first whose change from the previous order is within :data:`TOLERANCE`."""
MAX_BAND_TERMS = 3e9
"""Most normal-CDF differences the Gauss product rule may evaluate over all its orders (about
the time budget of :data:`MAX_EVALUATIONS`)."""
BAND_TERMS_PER_SECOND = 5e7
"""CDF differences the Gauss product rule evaluates a second (2-core machine)."""
_CHUNK = 1 << 15
"""Spins evaluated at once by the Gauss product rule (memory ~ _CHUNK × bands × 8 bytes × 4)."""


def _pdf(d: Distribution, x: np.ndarray) -> np.ndarray:
    """Density of a uniform or normal spin distribution at ``x``."""
    if isinstance(d, Uniform):
        return np.where((x >= d.low) & (x <= d.high), 1.0 / (d.high - d.low), 0.0)
    assert isinstance(d, Normal)
    z = (x - d.mean) / d.sd
    return np.exp(-0.5 * z * z) / (d.sd * math.sqrt(2.0 * math.pi))


def _breaks(d: Distribution) -> np.ndarray:
    """Panel ends of the composite rule for one spin: its support (normal: ±9 sd, which holds
    all but 2e-19 of the mass) cut at the mean, ±3 sd and at 0 (where the spin's sign flips)."""
    if isinstance(d, Uniform):
        pts = np.linspace(d.low, d.high, 3)
    else:
        assert isinstance(d, Normal)
        pts = d.mean + d.sd * np.array([-9.0, -3.0, 0.0, 3.0, 9.0])
    if pts[0] < 0.0 < pts[-1]:
        pts = np.sort(np.append(pts, 0.0))
    return pts


def _composite(ends: np.ndarray, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss–Legendre nodes and weights (``numpy.polynomial.legendre.leggauss``), ``n`` per
    panel, on the panels between consecutive ``ends`` (last axis; earlier axes broadcast)."""
    g, gw = np.polynomial.legendre.leggauss(n)
    lo, hi = ends[..., :-1, None], ends[..., 1:, None]
    half = 0.5 * (hi - lo)
    x = 0.5 * (hi + lo) + half * g
    w = half * gw
    shape = (*ends.shape[:-1], -1)
    return x.reshape(shape), w.reshape(shape)


def _gauss_applies(dist: TossDistribution, ranged: list[str]) -> bool:
    """A flight time with a smooth CDF (normal), ranged spins uniform or normal, and the ψ = 45°
    kink where it can be split: ω_z ranged, ω_z = 0, or one ranged spin."""
    if isinstance(dist.flight_time, Fixed | Uniform) or not ranged:
        return False
    if not all(isinstance(getattr(dist, n), Uniform | Normal) for n in ranged):
        return False
    return "omega_z" in ranged or dist.omega_z.mean == 0.0 or len(ranged) == 1


def _gauss_spins(
    dist: TossDistribution, ranged: list[str], details: _Details
) -> tuple[float, float]:
    """Closed form in T, Gauss–Legendre product rule over the spins, split at ψ = 45°.

    Conditional on the spins, P(same side) is the band measure over T
    (:func:`coinflight.core.bands.same_side_over_times`), smooth in the spins except where the
    coin stops turning over, ((I3/I1) ω_z)² = Ω⊥²: beyond it the measure is 1, and at it the
    band half-width a = arccos(−cot²ψ) reaches π like a square root. One spin carries the kink
    at ±k: ω_z (k = (I1/I3) Ω⊥, the measure 1 outside, ω_z = k sin θ inside) or, with ω_z fixed,
    the one ranged spin x (k² = ((I3/I1) ω_z)² − c², the measure 1 inside, x = ±√(k² + s²)
    outside); both substitutions make the integrand smooth in the new variable. The mass where
    the measure is 1 comes from the spin's CDF. The other spins are outer variables. Each
    variable takes a composite Gauss–Legendre rule (:func:`_breaks` panels); orders
    :data:`GAUSS_ORDERS` are tried until two in a row agree within :data:`TOLERANCE`, their
    difference being the error estimate.
    """
    i1, i3 = dist.moments
    ratio = i3 / i1
    t = dist.flight_time
    lo_t, hi_t = t.bounds
    if not math.isfinite(lo_t):
        lo_t = max(0.0, float(t.ppf(2.0**-53)))
    if not math.isfinite(hi_t):
        hi_t = float(t.ppf(1.0 - 2.0**-53))
    spins: dict[str, Distribution] = {n: getattr(dist, n) for n in _SPINS}
    inner = "omega_z" if "omega_z" in ranged else (ranged[0] if spins["omega_z"].mean else None)
    outer = [n for n in ranged if n != inner]
    # Work: points × bands a point, at the largest order, bounded before anything is allocated.
    largest = {
        n: float(np.max(np.abs(_breaks(spins[n])))) if n in ranged else abs(spins[n].mean)
        for n in _SPINS
    }
    wp_max = math.sqrt(
        largest["omega_x"] ** 2 + largest["omega_y"] ** 2 + (ratio * largest["omega_z"]) ** 2
    )
    per_point = wp_max * (hi_t - lo_t) / (2.0 * math.pi) + 3.0
    points = sum(math.prod(n * (len(_breaks(spins[d])) + 1) for d in ranged) for n in GAUSS_ORDERS)
    v.work_bound(
        f"the exact Gauss quadrature over {len(ranged)} ranged spins",
        points * per_point,
        MAX_BAND_TERMS,
        "band terms",
        _USE_INSTEAD,
        rate=BAND_TERMS_PER_SECOND,
    )

    def integral(n: int) -> float:
        # Outer spins: a tensor grid of nodes with their density-weighted weights.
        coords = {d: np.array([spins[d].mean]) for d in _SPINS}
        weight = np.ones(1)
        for name in outer:
            x, w = _composite(_breaks(spins[name]), n)
            w = w * _pdf(spins[name], x)
            coords = {k: np.repeat(c, x.size) for k, c in coords.items()}
            coords[name] = np.tile(x, weight.size)
            weight = np.repeat(weight, x.size) * np.tile(w, weight.size)
        wx, wy, wz = coords["omega_x"], coords["omega_y"], coords["omega_z"]
        if inner is None:
            same = _same(wx * wx + wy * wy, (ratio * wz) ** 2)
            return math.fsum(weight * same)
        d = spins[inner]
        cuts = _breaks(d)
        if inner == "omega_z":
            k = np.sqrt(wx * wx + wy * wy) / ratio
            sure = 1.0 - (d.cdf(k) - d.cdf(-k))  # |ω_z| ≥ k: never turns over
            safe = np.where(k > 0.0, k, 1.0)[:, None]
            ends = np.where(k[:, None] > 0.0, np.arcsin(np.clip(cuts, -safe, safe) / safe), 0.0)
            theta, w = _composite(ends, n)
            z = safe * np.sin(theta)
            w = w * safe * np.cos(theta) * _pdf(d, z)
            perp2 = np.broadcast_to((wx * wx + wy * wy)[:, None], z.shape)
            same = _same(perp2.ravel(), ((ratio * z) ** 2).ravel()).reshape(z.shape)
            return math.fsum(weight * sure) + math.fsum((weight[:, None] * w * same).ravel())
        # ω_z fixed, one ranged spin x, the other fixed at c: the kink at x = ±k.
        other = "omega_y" if inner == "omega_x" else "omega_x"
        c = spins[other].mean
        axial2 = (ratio * spins["omega_z"].mean) ** 2
        k = math.sqrt(max(axial2 - c * c, 0.0))
        total = float(d.cdf(k) - d.cdf(-k))  # |x| < k: never turns over
        for sign in (1.0, -1.0):
            side = np.clip(sign * cuts, k, None)
            ends = np.sort(np.sqrt(np.maximum(side * side - k * k, 0.0)))
            s, w = _composite(ends, n)
            x = np.sqrt(k * k + s * s)
            w = w * np.where(x > 0.0, s / np.where(x > 0.0, x, 1.0), 1.0) * _pdf(d, sign * x)
            same = _same(x * x + c * c, np.full_like(x, axial2))
            total += math.fsum(w * same)
        return total

    def _same(perp2: np.ndarray, axial2: np.ndarray) -> np.ndarray:
        out = np.empty(perp2.size)
        for start in range(0, perp2.size, _CHUNK):
            sl = slice(start, start + _CHUNK)
            out[sl] = bands.same_side_over_times(perp2[sl], axial2[sl], t.cdf, lo_t, hi_t)
        return out

    previous = math.nan
    for n in GAUSS_ORDERS:
        value = integral(n)
        change = abs(value - previous)
        if change <= TOLERANCE:
            details["nodes per panel"] = n
            return value, change
        previous = value
    raise ValueError(
        f"the exact Gauss quadrature did not reach its tolerance {TOLERANCE:g} with "
        f"{GAUSS_ORDERS[-1]} nodes per panel (last change {change:.2g}); {_USE_INSTEAD}"
    )


_CASES: tuple[
    tuple[
        str,
        Callable[[TossDistribution, list[str]], bool],
        Callable[[TossDistribution, list[str], _Details], tuple[float, float]],
    ],
    ...,
] = (
    ("closed form", _one_uniform_diameter_spin, _closed_form),
    ("closed form in T", lambda dist, ranged: not ranged, _closed_form_in_t),
    (
        "closed form in one spin, quadrature in the other",
        _two_diameter_spins_one_uniform,
        _closed_form_and_quadrature,
    ),
    (
        "closed form in T, Gauss product rule over the spins split at ψ = 45°",
        _gauss_applies,
        _gauss_spins,
    ),
    (
        "closed form in T, quadrature over the spins",
        _spins_by_quadrature,
        _closed_form_in_t_quadrature,
    ),
)
"""The integrals this method does, in order of preference: (how, whether it applies, run)."""


def _refusal(dist: TossDistribution, ranged: list[str]) -> str:
    """Why no exact integral here handles the distribution, and what to use instead."""
    if isinstance(dist.flight_time, Fixed):
        return (
            "the exact method cannot integrate over ranged spins with a fixed flight time unless "
            f"ω_z = 0 and one spin component is a uniform range; {_USE_INSTEAD}"
        )
    return (
        f"the exact method integrates over at most two ranged spin components, got "
        f"{len(ranged)} ({', '.join(ranged)}); {_USE_INSTEAD}"
    )


def estimate(dist: TossDistribution, *, model: OutcomeModel | None = None) -> ProbabilityResult:
    """Exact P(heads) for the hand catch; see the module notes for what is supported.

    The first of the integrals in ``_CASES`` that applies to the distribution is done.

    Raises
    ------
    ValueError
        For distributions that no exact integral here handles, naming the methods to use.
    """
    t0 = time.perf_counter()
    if model is not None and not model.closed_form_bands:
        raise ValueError(
            f"the exact method handles the hand catch only, not {model.name}; " + _USE_INSTEAD
        )
    ranged = [name for name in _SPINS if not getattr(dist, name).is_fixed]
    case = next((case for case in _CASES if case[1](dist, ranged)), None)
    if case is None:
        raise ValueError(_refusal(dist, ranged))
    how, _applies, run = case
    details: _Details = {}
    p_same, error = run(dist, ranged, details)
    p_same = min(1.0, max(0.0, p_same))
    p_heads = p_same if dist.start_sign > 0 else 1.0 - p_same
    details["how"] = how
    return ProbabilityResult(
        p_heads=p_heads,
        p_tails=1.0 - p_heads,
        p_edge=0.0,
        p_same_side=p_same,
        method=NAME,
        ci95=None,  # a deterministic result: error_estimate bounds it, no 95 % interval
        error_estimate=error,
        elapsed=time.perf_counter() - t0,
        details=details,
    )


def _summary(result: ProbabilityResult) -> str:
    extra = str(result.details["how"])
    if "warning" in result.details:
        extra += f"; quadrature warning: {result.details['warning']}"
    return extra


ESTIMATOR = Estimator(
    NAME, estimate, "exact value", "band integral (Keller 1986)", parallel=False, summary=_summary
)
