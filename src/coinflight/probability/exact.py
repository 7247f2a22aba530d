"""Exact P(heads): integrate the measure of the heads bands instead of sampling.

Which integral is used (``details["how"]``):

* ``closed form``: ω_z = 0 (the paper's cases a and b), the flight time uniform or fixed, at
  most one of ωx, ωy a uniform range and the other fixed. A finite sum over the band pieces
  (:func:`coinflight.core.bands.diameter_spin_integral`); error at rounding level (~1e-14).
* ``closed form in T``: every spin fixed (precession allowed), any flight-time distribution
  with a CDF: Σ over bands of CDF(hi) − CDF(lo).
* ``quadrature``: otherwise, with at most two ranged spin components and a continuous flight
  time: adaptive quadrature (``scipy.integrate.quad``) over the ranged spins, in probability
  space (u = CDF(ω)), of the closed form in T or, with ω_z = 0 and a uniform spin range, of the
  closed form in that spin. The error estimate is reported.
* A fixed flight time with ranged spins and precession, or three ranged spin components: a
  ValueError naming the methods to use instead.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from typing import Any

import numpy as np

from coinflight import _validation as v
from coinflight.core import bands
from coinflight.model.distributions import Distribution, Fixed, Uniform
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
