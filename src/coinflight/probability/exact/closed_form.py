"""Exact P(same side) as a finite sum over the heads bands: ω_z = 0 with at most one
uniform spin and T fixed or uniform (``closed form``, the band pieces of
:func:`coinflight.core.bands.diameter_spin_integral`, Keller 1986), and fixed spins with any
flight-time distribution that has a CDF (``closed form in T``); chosen by
:mod:`coinflight.probability.exact`."""

from __future__ import annotations

import math

import numpy as np

from coinflight import _validation as v
from coinflight.core import bands
from coinflight.model.distributions import Distribution, Fixed, Uniform
from coinflight.model.ensemble import TossDistribution
from coinflight.probability.exact.common import (
    _USE_INSTEAD,
    _Details,
)

MAX_PIECES = 50_000_000
"""Most band pieces the closed form may sum (about 25 s on the reference 2-core machine, memory
bounded by :data:`coinflight.core.bands.PIECES_PER_CHUNK`). A spin range of width Δω and flight
times up to T hold about 2 Δω T / π pieces; when the closed form is the integrand of a
quadrature, each evaluation may hold at most MAX_PIECES / 1000 of them."""
PIECES_PER_SECOND = 2e6
"""Band pieces the closed form sums a second (about half a microsecond each, reference 2-core
machine)."""


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
