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


def estimate(dist: TossDistribution, *, model: OutcomeModel | None = None) -> ProbabilityResult:
    """Exact P(heads) for the hand catch; see the module notes for what is supported.

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
    i1, i3 = dist.moments
    t = dist.flight_time
    ranged_spins = [name for name in _SPINS if not getattr(dist, name).is_fixed]
    error = 0.0
    how: str
    details: dict[str, Any] = {}
    if (
        dist.spin_about_diameter
        and isinstance(t, Fixed | Uniform)
        and (
            len(ranged_spins) == 0
            or (len(ranged_spins) == 1 and isinstance(getattr(dist, ranged_spins[0]), Uniform))
        )
    ):
        x_name = ranged_spins[0] if ranged_spins else "omega_x"
        c_name = "omega_y" if x_name == "omega_x" else "omega_x"
        p_same = _closed_form_diameter(getattr(dist, x_name), getattr(dist, c_name).mean, t)
        how = "closed form"
    elif not ranged_spins:
        p_same = _p_same_fixed_spins(
            dist.omega_x.mean, dist.omega_y.mean, dist.omega_z.mean, t, i1, i3
        )
        how = "closed form in T"
    elif (
        dist.spin_about_diameter
        and isinstance(t, Uniform | Fixed)
        and len(ranged_spins) == 2
        and any(isinstance(getattr(dist, n), Uniform) for n in ranged_spins)
    ):
        # One uniform spin in closed form, the other by quadrature over its quantiles.
        x_name = next(n for n in ranged_spins if isinstance(getattr(dist, n), Uniform))
        c_name = "omega_y" if x_name == "omega_x" else "omega_x"
        x_dist, c_dist = getattr(dist, x_name), getattr(dist, c_name)
        t_high = t.value if isinstance(t, Fixed) else t.high
        _check_pieces(x_dist, 0.0, t_high, MAX_PIECES / 1000)

        def inner(u: float) -> float:
            return _closed_form_diameter(x_dist, float(c_dist.ppf(u)), t, MAX_PIECES / 1000)

        p_same, error = _quad(inner, 1, details)
        how = "closed form in one spin, quadrature in the other"
    elif isinstance(t, Fixed):
        raise ValueError(
            "the exact method cannot integrate over ranged spins with a fixed flight time unless "
            f"ω_z = 0 and one spin component is a uniform range; {_USE_INSTEAD}"
        )
    elif len(ranged_spins) > 2:
        raise ValueError(
            f"the exact method integrates over at most two ranged spin components, got "
            f"{len(ranged_spins)} ({', '.join(ranged_spins)}); {_USE_INSTEAD}"
        )
    else:
        spins = {name: getattr(dist, name) for name in _SPINS}

        def integrand(*u: float) -> float:
            w = {n: spins[n].mean for n in _SPINS}
            for name, ui in zip(ranged_spins, u, strict=True):
                w[name] = float(spins[name].ppf(ui))
            return _p_same_fixed_spins(w["omega_x"], w["omega_y"], w["omega_z"], t, i1, i3)

        p_same, error = _quad(integrand, len(ranged_spins), details)
        how = "closed form in T, quadrature over the spins"
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
