"""Exact P(heads): integrate the measure of the heads bands instead of sampling.

Which integral is used (``details["how"]``):

* ``closed form``: ω_z = 0 (the paper's cases a and b), the flight time uniform or fixed, at
  most one of ωx, ωy a uniform range and the other fixed. A finite sum over the band pieces
  (:func:`coinflight.core.bands.diameter_spin_integral`); error at rounding level (~1e-14).
* ``closed form in T``: every spin fixed (precession allowed), any flight-time distribution
  with a CDF: Σ over bands of CDF(hi) − CDF(lo).
* ``closed form in T, Gauss product rule over the spins split at ψ = 45°``: a normal flight
  time (or launch speed) with one or two ranged spins (uniform or normal; where this rule
  refuses, the (Ω, ψ) rule below runs instead and ``details["fallback"]`` says why):
  P(same side | spins) over T as the wrapped-normal series
  (:func:`coinflight.core.bands.same_side_normal_time`), then
  Gauss–Legendre panels over the spins with the kink at ψ = 45° put on a coordinate (ω_z
  inner, or the radius of polar coordinates in (ωx, ωy) when ω_z is fixed ≠ 0 or the cone's
  apex or a uniform ω_z's rims lie in the box) and smoothed by a change of variable; node
  counts raised until two agree within 1e-9 (their difference is the error estimate), else a
  ValueError. The work of the first two orders is bounded before anything is computed.
* ``closed form in T, Gauss–Legendre over the spins in (Ω, ψ)``: a fixed or uniform flight
  time (or launch speed) with any ranged spins (uniform or normal, up to all three), e.g.
  precession with a fixed T, or all four parameters ranged; and a normal flight time with
  three ranged spins (the wrapped-normal series as the inner function, 2-100x faster than
  the product rule there, and equal to it within 1e-10). P(same side | spins) depends on
  Ω = √(Ω⊥² + ((I3/I1) ω_z)²) and ψ only; the azimuth of (ωx, ωy) is integrated out in closed
  form (a uniform box's arc length, a fixed component's Jacobian) or by an interpolant (a
  normal component), ω_z's sign folded, and the rest integrated over Ω (inner, cut at every
  band edge, box corner and range end, all explicit in Ω) and ψ ∈ (45°, 90°] (outer, cut
  where those curves cross) by Gauss–Legendre through a smoothstep; node counts raised until
  two agree within 1e-9 (:func:`_omega_psi`). ``details["spin integral"]`` says which form
  ran ("2-D", "axial fixed", "plane fixed" or "diameter").
* ``quadrature``: otherwise (spins of another kind, e.g. a truncated normal), with at most two
  ranged spin components and a ranged flight time: adaptive quadrature
  (``scipy.integrate.quad``) over the ranged spins, in probability space (u = CDF(ω)), of the
  closed form in T. The error estimate is reported.
* Anything else (distributions other than fixed, uniform and normal beyond those): a
  ValueError naming the methods to use instead.
"""

from __future__ import annotations

import itertools
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
"""Budget of integrand evaluations for the adaptive quadrature, so that ``exact`` always ends
in bounded time: about 25-30 s on the reference 2-core machine. Only distributions beyond
fixed, uniform and normal spins reach that quadrature now (e.g. a truncated normal spin); past
the budget a ValueError names the sampling methods instead."""
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
MAX_SPIN_POINTS = 6e7
"""Most spin points (each a few wrapped-normal terms) the Gauss product rule may evaluate over
all its orders, bounded before anything is allocated (about a minute on the 2-core machine)."""
SPIN_POINTS_PER_SECOND = 1.5e6
"""Spin points the Gauss product rule evaluates a second (2-core machine, about ten terms each)."""
MAX_PANELS = 24
"""Most panels per spin variable (or per angular sector) the resolution may ask for."""
_CHUNK = 1 << 16
"""Spins evaluated at once by the Gauss product rule (memory ~ _CHUNK × 6 terms × 8 bytes × 4)."""
_NORMAL_SPAN = 9.0
"""A normal spin is integrated over mean ± 9 sd (all but 2e-19 of its mass)."""


def _pdf(d: Distribution, x: np.ndarray) -> np.ndarray:
    """Density of a uniform or normal spin distribution at ``x``."""
    if isinstance(d, Uniform):
        return np.where((x >= d.low) & (x <= d.high), 1.0 / (d.high - d.low), 0.0)
    assert isinstance(d, Normal)
    z = (x - d.mean) / d.sd
    return np.exp(-0.5 * z * z) / (d.sd * math.sqrt(2.0 * math.pi))


def _support(d: Distribution) -> tuple[float, float]:
    """Where a spin's mass lies: a uniform's range, a normal's mean ± 9 sd."""
    if isinstance(d, Uniform):
        return d.low, d.high
    assert isinstance(d, Normal)
    return d.mean - _NORMAL_SPAN * d.sd, d.mean + _NORMAL_SPAN * d.sd


def _scale(d: Distribution) -> float:
    """Widest panel a spin's density allows: 3 sd for a normal, half the range for a uniform."""
    if isinstance(d, Normal):
        return 3.0 * d.sd
    lo, hi = d.bounds
    return 0.5 * (hi - lo)


def _breaks(d: Distribution, h: float) -> np.ndarray:
    """Panel ends of the composite rule for one spin: its support cut at the mean, ±3 sd and
    at 0 (where the spin's sign flips), then each panel halved until it is at most ``h`` wide
    (at most :data:`MAX_PANELS` panels in all)."""
    lo, hi = _support(d)
    h = min(h, _scale(d))
    if isinstance(d, Normal):
        pts = d.mean + d.sd * np.array([-9.0, -3.0, 0.0, 3.0, 9.0])
    else:
        pts = np.linspace(lo, hi, 3)
    if pts[0] < 0.0 < pts[-1]:
        pts = np.unique(np.append(pts, 0.0))
    return _refine(pts, h)


def _refine(pts: np.ndarray, h: float) -> np.ndarray:
    """``pts`` with each gap cut into equal pieces at most ``h`` wide (≤ MAX_PANELS pieces)."""
    out = [pts[:1]]
    budget = max(1, MAX_PANELS // max(1, len(pts) - 1))
    for a, b in itertools.pairwise(pts):
        pieces = min(budget, max(1, math.ceil((b - a) / h))) if h > 0 else 1
        out.append(np.linspace(a, b, pieces + 1)[1:])
    return np.concatenate(out)


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
    """A normal flight time (or launch speed) and one or two ranged spins, uniform or normal
    (three go to the (Ω, ψ) rule, measured 2-100x faster there)."""
    if not isinstance(dist.flight_time, Normal) or not ranged or len(ranged) == 3:
        return False
    return all(isinstance(getattr(dist, n), Uniform | Normal) for n in ranged)


def _resolution(dist: TossDistribution, ranged: list[str]) -> float:
    """Widest panel over the spins (besides each density's own scale, :func:`_scale`): where
    the flight-time spread leaves the phase's wrapped-normal terms alive for typical spins
    (ωp · sd < 5.3, a term above 1e-6, with the spins within their central 1 − 1e-4), one
    phase period
    2π / mean T over which P(same side | spins) then oscillates. The comparison of successive
    orders judges what remains."""
    t = dist.flight_time
    assert isinstance(t, Normal)
    h = math.inf
    i1, i3 = dist.moments
    nearest = {}
    for name in _SPINS:
        d = getattr(dist, name)
        lo, hi = (float(d.ppf(5e-5)), float(d.ppf(1 - 5e-5))) if name in ranged else (d.mean,) * 2
        nearest[name] = 0.0 if lo <= 0.0 <= hi else min(abs(lo), abs(hi))
    typical = math.hypot(nearest["omega_x"], nearest["omega_y"], i3 / i1 * nearest["omega_z"])
    if typical * t.sd < 5.3:
        h = min(h, 2.0 * math.pi / t.mean)
    return h


def _polar_plan(
    dx: Distribution, dy: Distribution, h: float, kink: float | None, rims: tuple[float, ...] = ()
) -> tuple[np.ndarray, int]:
    """The angular panel ends and the radial pieces per segment of :func:`_polar`."""
    (x1, x2), (y1, y2) = _support(dx), _support(dy)
    h = min(h, _scale(dx), _scale(dy))
    corners = [(x, y) for x in (x1, x2) for y in (y1, y2)]
    if x1 <= 0.0 <= x2 and y1 <= 0.0 <= y2:
        start, stop = -math.pi, math.pi
    else:
        centre = math.atan2(0.5 * (y1 + y2), 0.5 * (x1 + x2))
        rel = [(math.atan2(y, x) - centre + math.pi) % (2 * math.pi) - math.pi for x, y in corners]
        start, stop = centre + min(rel), centre + max(rel)
    cuts = [math.atan2(y, x) for x, y in corners] + [-math.pi / 2, 0.0, math.pi / 2]
    for radius in (kink, *rims) if kink else rims:
        for edge in (x1, x2):
            if abs(edge) < radius:
                c = math.acos(edge / radius)
                cuts += [c, -c]
        for edge in (y1, y2):
            if abs(edge) < radius:
                s = math.asin(edge / radius)
                cuts += [s, math.pi - s]
    wrapped = [start + (c - start) % (2 * math.pi) for c in cuts]
    ends = np.unique(np.clip([start, stop, *wrapped], start, stop))
    far = max(math.hypot(x, y) for x, y in corners)
    ends = _refine(ends, h / far)
    chord = math.hypot(x2 - x1, y2 - y1)
    return ends, min(MAX_PANELS, max(1, math.ceil(chord / h)))


def _edge_angles(
    ends: np.ndarray, n: int, xs: tuple[float, float], ys: tuple[float, float]
) -> tuple[np.ndarray, np.ndarray]:
    """Angles and weights of a Gauss–Legendre rule on each angular panel between ``ends``,
    with the nodes placed in the coordinate e along the side of the box the panel's rays leave
    through, not in the angle: the distance out, √(X² + e²) on the side x = X, is then
    smooth in e, where as a function of the angle (X / cos φ) it has a pole just beyond a
    panel's end for an elongated box, which slows Gauss–Legendre down. The angle is
    φ = atan2(e, X) (side x = X) or atan2(Y, e) (side y = Y), dφ = |X| de / (X² + e²)."""
    g, gw = np.polynomial.legendre.leggauss(n)
    phis, weights = [], []
    for a, b in itertools.pairwise(ends):
        if b <= a:
            continue
        mid = 0.5 * (a + b)
        c, s = math.cos(mid), math.sin(mid)
        # The side the middle ray leaves through: the smallest positive exit distance.
        exits = []
        for edge, comp, axis in ((xs[0], c, 0), (xs[1], c, 0), (ys[0], s, 1), (ys[1], s, 1)):
            if comp != 0.0 and edge / comp > 0.0:
                exits.append((edge / comp, edge, axis))
        if not exits:  # no side ahead (cannot happen for a ray through the box): the angle
            half = 0.5 * (b - a)
            phis.append(mid + half * g)
            weights.append(half * gw)
            continue
        _, edge, axis = min(exits)
        if axis == 0:  # side x = X: e = X tan φ
            ea, eb = edge * math.tan(a), edge * math.tan(b)
        else:  # side y = Y: e = Y cot φ
            ea, eb = edge / math.tan(a), edge / math.tan(b)
        half, centre = 0.5 * (eb - ea), 0.5 * (ea + eb)
        e = centre + half * g
        phi = np.arctan2(e, edge) if axis == 0 else np.arctan2(edge, e)
        phi = a + np.mod(phi - a, 2.0 * np.pi)  # on the panel's branch
        dphi = abs(edge) / (edge * edge + e * e)
        phis.append(phi)
        weights.append(abs(half) * gw * dphi)
    return np.concatenate(phis), np.concatenate(weights)


def _polar(
    dx: Distribution,
    dy: Distribution,
    n: int,
    h: float,
    kink: float | None,
    rims: tuple[float, ...] = (),
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Nodes (x, y) and density-weighted weights of a product rule over two ranged spins in
    polar coordinates about the origin, where P(same side | spins) depends on the radius
    Ω⊥ smoothly except at the origin (a cone's apex when ω_z is ranged) and at ``kink``
    (the circle Ω⊥ = (I3/I1) |ω_z| where the coin stops turning over, ω_z fixed).

    The angle is cut at the corners of the support box (where the ray leaves through another
    side), at the axes, and where a side meets the circle; the radius runs from where the ray
    enters the box to where it leaves it, cut at the circle, beyond which r = √(k² + s²) makes
    the square-root kink smooth in s. ``rims`` are radii where the integrand has a
    half-integer power (a uniform ω_z's range ends meet the cone): the radius is cut there too and
    each radial piece mapped by the smoothstep r = a + (b − a)(3u² − 2u³), whose vanishing
    slope at both ends makes such powers smooth in u. Each piece then carries a smooth
    integrand: Gauss–Legendre with ``n`` nodes a panel, panels at most ``h`` wide (arc length
    at the far corner).
    """
    (x1, x2), (y1, y2) = _support(dx), _support(dy)
    ends, pieces = _polar_plan(dx, dy, h, kink, rims)
    phi, wphi = _edge_angles(ends, n, (x1, x2), (y1, y2))
    cos, sin = np.cos(phi), np.sin(phi)
    # Where each ray enters and leaves the box (slab method).
    r_in = np.zeros_like(phi)
    r_out = np.full_like(phi, np.inf)
    for c, lo, hi in ((cos, x1, x2), (sin, y1, y2)):
        safe = np.where(c != 0.0, c, 1.0)
        a, b = lo / safe, hi / safe
        near, far_ = np.minimum(a, b), np.maximum(a, b)
        inside = (lo <= 0.0) & (hi >= 0.0)
        near = np.where(c != 0.0, near, -np.inf if inside else np.inf)
        far_ = np.where(c != 0.0, far_, np.inf if inside else -np.inf)
        r_in, r_out = np.maximum(r_in, near), np.minimum(r_out, far_)
    r_out = np.maximum(r_out, r_in)
    frac = np.linspace(0.0, 1.0, pieces + 1)
    segments = []
    k = kink or 0.0
    # Inside the circle (P = 1 when ω_z is fixed), then outside it in s = √(r² − k²).
    if k:
        segments.append((np.minimum(r_in, k), np.minimum(r_out, k), False))
        s_lo = np.sqrt(np.maximum(np.maximum(r_in, k) ** 2 - k * k, 0.0))
        s_hi = np.sqrt(np.maximum(np.maximum(r_out, k) ** 2 - k * k, 0.0))
        segments.append((s_lo, s_hi, True))
    else:
        bounds = [r_in, *(np.clip(rim, r_in, r_out) for rim in sorted(rims)), r_out]
        segments += [(a, b, False) for a, b in itertools.pairwise(bounds)]
    graded = bool(rims) and not k
    xs, ys, ws = [], [], []
    for lo, hi, substituted in segments:
        u, ws_ = _composite(np.broadcast_to(frac, (lo.size, frac.size)), n)
        if graded:  # smoothstep: slope 0 at both ends of the piece
            ws_ = ws_ * 6.0 * u * (1.0 - u)
            u = u * u * (3.0 - 2.0 * u)
        s = lo[:, None] + (hi - lo)[:, None] * u
        ws_ = ws_ * (hi - lo)[:, None]
        if substituted:
            r = np.sqrt(k * k + s * s)
            ws_ = ws_ * np.where(r > 0.0, s / np.where(r > 0.0, r, 1.0), 1.0)
        else:
            r = s
        x, y = r * cos[:, None], r * sin[:, None]
        xs.append(x.ravel())
        ys.append(y.ravel())
        ws.append((wphi[:, None] * ws_ * r * _pdf(dx, x) * _pdf(dy, y)).ravel())
    return np.concatenate(xs), np.concatenate(ys), np.concatenate(ws)


def _use_polar(dist: TossDistribution, ranged: list[str]) -> bool:
    """Two ranged ωx, ωy go to polar coordinates when ω_z is fixed ≠ 0 (the circle where the
    coin stops turning over is a radius) or when a uniform ω_z's rims (:func:`_rims`) are
    circles in a box that does not hold the origin (the case that did not converge in a tensor
    product); else a tensor product. (With the origin in the box the tensor product measured
    faster: there the polar rule did not converge by 24 nodes a panel on the test box with
    three spins across 0.)"""
    if "omega_z" not in ranged:
        return dist.omega_z.mean != 0.0
    (x1, x2), (y1, y2) = _support(dist.omega_x), _support(dist.omega_y)
    return not (x1 <= 0.0 <= x2 and y1 <= 0.0 <= y2) and bool(_rims(dist, ranged))


def _rims(dist: TossDistribution, ranged: list[str]) -> tuple[float, ...]:
    """Radii Ω⊥ = (I3/I1) |ω_z| at the ends of a uniform ω_z range: there the cone where the
    coin stops turning over meets the range's end, and the integral over ω_z has a
    half-integer power of the distance (:func:`_polar` grades its pieces there)."""
    d = dist.omega_z
    if "omega_z" not in ranged or not isinstance(d, Uniform):
        return ()
    i1, i3 = dist.moments
    return tuple(sorted({i3 / i1 * abs(e) for e in (d.low, d.high) if e != 0.0}))


def _gauss_points(dist: TossDistribution, ranged: list[str], h: float, n: int) -> int:
    """The spin points of one order of :func:`_gauss_spins`, counted before any allocation."""
    spins = {d: getattr(dist, d) for d in _SPINS}
    plane = [d for d in ("omega_x", "omega_y") if d in ranged]
    if len(plane) == 2 and _use_polar(dist, ranged):
        kink = None if "omega_z" in ranged else abs(spins["omega_z"].mean) or None
        rims = _rims(dist, ranged)
        ends, pieces = _polar_plan(spins["omega_x"], spins["omega_y"], h, kink, rims)
        outer = (len(ends) - 1) * n * pieces * n * (2 if kink else 1 + len(rims))
    else:
        outer = math.prod(n * (len(_breaks(spins[d], h)) - 1) for d in plane)
        outer *= 2 if plane and "omega_z" not in ranged else 1
    inner = n * (len(_breaks(spins["omega_z"], h)) - 1) if "omega_z" in ranged else 1
    return outer * inner


def _gauss_spins(
    dist: TossDistribution, ranged: list[str], details: _Details
) -> tuple[float, float]:
    """Wrapped-normal closed form in T, Gauss–Legendre product rule over the spins, split at
    ψ = 45°.

    Conditional on the spins, P(same side) over the normal flight time is a short series
    (:func:`coinflight.core.bands.same_side_normal_time`), smooth in the spins except where the
    coin stops turning over, ((I3/I1) ω_z)² = Ω⊥²: beyond it the measure is 1, and at it the
    band half-width a = arccos(−cot²ψ) reaches π like a square root. The kink is put on a
    coordinate and smoothed by a change of variable:

    * ω_z ranged: ω_z is the inner variable, the kink at ±k, k = (I1/I3) Ω⊥, with the
      measure 1 outside and ω_z = k sin θ inside; the mass outside comes from ω_z's CDF. The
      ranged ωx, ωy are outer variables: one by composite Gauss–Legendre, two in polar
      coordinates (:func:`_polar`; Ω⊥ has a cone's apex at the origin).
    * ω_z fixed ≠ 0: the kink is the circle Ω⊥ = (I3/I1) |ω_z|; one ranged spin x (the other
      fixed at c) is cut at x = ±√(k² − c²) and x = ±√(k² + s²) outside; two ranged spins go
      to polar coordinates with the radius cut at the circle.
    * ω_z = 0: no kink; a tensor product over the ranged ωx, ωy.

    Each variable takes a composite Gauss–Legendre rule (panels from :func:`_breaks`, at most
    :func:`_resolution` wide); orders :data:`GAUSS_ORDERS` are tried until two in a row agree
    within :data:`TOLERANCE`, their difference being the error estimate.
    """
    i1, i3 = dist.moments
    ratio = i3 / i1
    t = dist.flight_time
    assert isinstance(t, Normal)
    spins: dict[str, Distribution] = {n: getattr(dist, n) for n in _SPINS}
    plane = [n for n in ("omega_x", "omega_y") if n in ranged]
    z_ranged = "omega_z" in ranged
    axial0 = ratio * spins["omega_z"].mean
    h = _resolution(dist, ranged)

    def same(perp2: np.ndarray, axial2: np.ndarray) -> np.ndarray:
        out = np.empty(perp2.size)
        for start in range(0, perp2.size, _CHUNK):
            sl = slice(start, start + _CHUNK)
            out[sl] = bands.same_side_normal_time(perp2[sl], axial2[sl], t.mean, t.sd)
        return out

    def plane_nodes(n: int, kink: float | None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Nodes (ωx, ωy) and weights over the ranged plane spins (fixed ones at their value)."""
        if len(plane) == 2 and _use_polar(dist, ranged):
            rims = _rims(dist, ranged) if kink is None else ()
            return _polar(spins["omega_x"], spins["omega_y"], n, h, kink, rims)
        if len(plane) == 2:  # the apex outside the box: a tensor product of the two
            (x, wx_), (y, wy_) = (_composite(_breaks(spins[d], h), n) for d in plane)
            wx_, wy_ = wx_ * _pdf(spins[plane[0]], x), wy_ * _pdf(spins[plane[1]], y)
            return np.repeat(x, y.size), np.tile(y, x.size), np.outer(wx_, wy_).ravel()
        if not plane:
            return (np.array([spins["omega_x"].mean]), np.array([spins["omega_y"].mean]),
                    np.ones(1))  # fmt: skip
        d = spins[plane[0]]
        x, w = _composite(_breaks(d, h), n)
        w = w * _pdf(d, x)
        fixed = np.full_like(x, spins["omega_y" if plane[0] == "omega_x" else "omega_x"].mean)
        return (x, fixed, w) if plane[0] == "omega_x" else (fixed, x, w)

    def integral(n: int) -> float:
        if z_ranged:
            wx, wy, weight = plane_nodes(n, None)
            d = spins["omega_z"]
            cuts = _breaks(d, h)
            k = np.sqrt(wx * wx + wy * wy) / ratio
            sure = 1.0 - (d.cdf(k) - d.cdf(-k))  # |ω_z| ≥ k: never turns over
            safe = np.where(k > 0.0, k, 1.0)[:, None]
            ends = np.where(k[:, None] > 0.0, np.arcsin(np.clip(cuts, -safe, safe) / safe), 0.0)
            theta, w = _composite(ends, n)
            z = safe * np.sin(theta)
            w = w * safe * np.cos(theta) * _pdf(d, z)
            perp2 = np.broadcast_to((wx * wx + wy * wy)[:, None], z.shape)
            p = same(perp2.ravel(), ((ratio * z) ** 2).ravel()).reshape(z.shape)
            return math.fsum(weight * sure) + math.fsum((weight[:, None] * w * p).ravel())
        if axial0 == 0.0 or len(plane) == 2:
            wx, wy, weight = plane_nodes(n, abs(axial0) or None)
            return math.fsum(weight * same(wx * wx + wy * wy, np.full(wx.size, axial0**2)))
        # ω_z fixed ≠ 0, one ranged spin x, the other fixed at c: the kink at x = ±k.
        inner = plane[0]
        d = spins[inner]
        c = spins["omega_y" if inner == "omega_x" else "omega_x"].mean
        k = math.sqrt(max(axial0 * axial0 - c * c, 0.0))
        total = float(d.cdf(k) - d.cdf(-k))  # |x| < k: never turns over
        cuts = _breaks(d, h)
        for sign in (1.0, -1.0):
            side = np.clip(sign * cuts, k, None)
            ends = np.sort(np.sqrt(np.maximum(side * side - k * k, 0.0)))
            s, w = _composite(ends, n)
            x = np.sqrt(k * k + s * s)
            w = w * np.where(x > 0.0, s / np.where(x > 0.0, x, 1.0), 1.0) * _pdf(d, sign * x)
            total += math.fsum(w * same(x * x + c * c, np.full_like(x, axial0**2)))
        return total

    previous, previous_n, change = math.nan, 0, math.nan
    # No answer without two orders (their difference is the error estimate): both bounded
    # before anything is computed, each later order before its nodes are allocated.
    v.work_bound(
        f"the exact Gauss quadrature over {len(ranged)} ranged spins",
        sum(_gauss_points(dist, ranged, h, n) for n in GAUSS_ORDERS[:2]),
        MAX_SPIN_POINTS,
        "spin points",
        _USE_INSTEAD,
        rate=SPIN_POINTS_PER_SECOND,
    )
    used = 0
    for n in GAUSS_ORDERS:
        points = _gauss_points(dist, ranged, h, n)
        where = f"the exact Gauss quadrature over {len(ranged)} ranged spins" + (
            f" (at {previous_n} nodes a panel {change:.2g} from the order before), "
            f"to {n} nodes a panel,"
            if math.isfinite(change)
            else ""
        )
        # Bounded before the order's nodes are allocated: refused rather than loosened.
        v.work_bound(
            where, used + points, MAX_SPIN_POINTS, "spin points", _USE_INSTEAD,
            rate=SPIN_POINTS_PER_SECOND,
        )  # fmt: skip
        used += points
        value = integral(n)
        change = abs(value - previous)
        if change <= TOLERANCE:
            details["nodes per panel"] = n
            details["spin points"] = used
            # The difference of the last two orders, not below the rounding of the sums.
            return value, max(change, 4e-16 * math.sqrt(points))
        previous, previous_n = value, n
    raise ValueError(
        f"the exact Gauss quadrature did not reach its tolerance {TOLERANCE:g} with "
        f"{GAUSS_ORDERS[-1]} nodes per panel (last change {change:.2g}); {_USE_INSTEAD}"
    )


# --- T fixed or uniform, any spins: the spins in (Ω, ψ) coordinates -------------------------

POLAR_ORDERS = (8, 12, 16, 24, 32)
"""Gauss–Legendre nodes per panel tried in turn by the (Ω, ψ) rule (:func:`_omega_psi`); the
result is the first whose change from the previous order is within :data:`TOLERANCE`."""
MAX_POLAR_POINTS = 4e7
"""Most integrand points the (Ω, ψ) rule may evaluate over its first two orders and each later
one, bounded before its nodes are allocated (about half a minute on the 2-core machine)."""
POLAR_POINTS_PER_SECOND = 3e6
"""Integrand points the (Ω, ψ) rule evaluates a second (2-core machine)."""
MAX_CROSSING_SAMPLES = 5e7
"""Most curve-pair samples the search for the outer cuts of the (Ω, ψ) rule may take."""
_CROSSING_SAMPLES = 257
"""Samples along ψ (equal steps in √(ψ − 45°)) on which each pair of curves is searched for a
crossing (a sign change, then bisection)."""
_PSI_PANEL = 0.05
"""Widest outer panel in ψ, rad."""
_POLAR_CHUNK = 1 << 18
"""Integrand points evaluated at once by the (Ω, ψ) rule."""
_QUARTER = math.pi / 4


class _Radial:
    """The distribution of Ω⊥ = √(ωx² + ωy²) (the plane) or of A = (I3/I1) |ω_z| (axial):
    an atom at ``value`` (``density`` None), or a density on [lo, hi], smooth between
    consecutive ``breaks`` (where it may have a square-root onset, an inverse square root or
    a jump: the outer rule cuts where a band edge crosses them) and ``soft`` points (where it
    is smooth or negligible, a normal's mean ± 3 sd or ± 9 sd: only inner cuts, so that no
    piece is much wider than the density's scale); ``graded`` holds all of them with the
    points of :func:`_graded` (so that two breaks close together, a narrow range, do not
    spoil the pieces beside them)."""

    def __init__(
        self,
        density: Callable[[np.ndarray], np.ndarray] | None,
        breaks: list[float] | None = None,
        soft: list[float] | None = None,
        value: float = math.nan,
    ) -> None:
        self.density = density
        self.value = value
        hard = np.asarray(breaks if breaks is not None else [], dtype=float)
        both = np.unique(np.concatenate((hard, np.asarray(soft or [], dtype=float))))
        if density is None:
            both = np.array([value])
        self.breaks = np.unique(hard)
        self.points = both
        self.lo, self.hi = float(both[0]), float(both[-1])
        self.graded = _graded(both)


def _graded(pts: np.ndarray, factor: float = 4.0) -> np.ndarray:
    """``pts`` (sorted, unique) with, on each side of each point, points at distances
    h·4, h·16, … out to half the gap on that side, h being the distance to its nearest
    neighbour: a mesh graded towards clusters of breaks, so that each piece is about as long
    as its distance from the nearest break. A singularity just beyond a piece's end (the next
    break of a narrow range) then slows Gauss–Legendre down on no piece (hp-graded meshes:
    Schwab 1998, p-and hp-Finite Element Methods, §4.4)."""
    p = np.unique(pts)
    if p.size < 3:
        return p
    gaps = np.diff(p)
    near = np.minimum(np.r_[np.inf, gaps], np.r_[gaps, np.inf])
    extra: list[float] = []
    for k, x in enumerate(p):
        for side, gap in (
            (-1.0, gaps[k - 1] if k else 0.0),
            (1.0, gaps[k] if k < gaps.size else 0.0),
        ):
            d = factor * near[k]
            while d < 0.5 * gap:
                extra.append(x + side * d)
                d *= factor
    return np.unique(np.concatenate((p, extra)))


def _folded(d: Distribution) -> tuple[list[float], list[float]]:
    """Breaks and soft points (as :class:`_Radial` has them) of |X| for a ranged spin X, its
    support folded onto [0, ∞): a uniform's ends and 0 inside its range are breaks; a
    normal's 0 inside its support is a break (the fold), its mean, ±3 sd and its support's
    ends (±9 sd, density below 1e-17) soft points."""
    s1, s2 = _support(d)
    zero = [0.0] if s1 < 0.0 < s2 else []
    lo = [0.0 if s1 <= 0.0 <= s2 else min(abs(s1), abs(s2)), max(abs(s1), abs(s2))]
    if isinstance(d, Normal):
        pts = d.mean + d.sd * np.array([-_NORMAL_SPAN, -3.0, 0.0, 3.0, _NORMAL_SPAN])
        return zero, [*lo, *(abs(float(p)) for p in pts)]
    return [*zero, *lo, abs(s1), abs(s2)], []


def _axial(dz: Distribution, ratio: float) -> _Radial:
    """A = (I3/I1) |ω_z|: its density on A ≥ 0 is (p(A/ratio) + p(−A/ratio)) / ratio."""
    if dz.is_fixed:
        return _Radial(None, value=ratio * abs(dz.mean))
    hard, soft = _folded(dz)

    def density(a: np.ndarray) -> np.ndarray:
        z = a / ratio
        return (_pdf(dz, z) + _pdf(dz, -z)) / ratio

    return _Radial(density, [ratio * f for f in hard], [ratio * f for f in soft])


def _plane(dx: Distribution, dy: Distribution) -> _Radial:
    """Ω⊥ = √(ωx² + ωy²): an atom when both are fixed; for one fixed at c and the other y
    ranged, the density (p(s) + p(−s)) ρ / s, s = √(ρ² − c²) (an inverse square root at
    ρ = |c|); for two uniform ranges, ρ times the circle's angle in the box over its area
    (:func:`coinflight.core.bands.circle_in_box_angle`); for two ranged components of which
    one is normal, an interpolant (:class:`_PlaneInterpolant`). Breaks: the support's ends,
    the box's corner radii and the sides' distances (a circle's tangent)."""
    if dx.is_fixed and dy.is_fixed:
        return _Radial(None, value=math.hypot(dx.mean, dy.mean))
    if dx.is_fixed or dy.is_fixed:
        c, d = (dx.mean, dy) if dx.is_fixed else (dy.mean, dx)
        hard, soft = _folded(d)

        def one(rho: np.ndarray) -> np.ndarray:
            s = np.sqrt(np.maximum(rho * rho - c * c, 0.0))
            safe = np.where(s > 0.0, s, 1.0)
            return np.where(s > 0.0, (_pdf(d, s) + _pdf(d, -s)) * rho / safe, 0.0)

        # ρ = |c| (s = 0) holds the inverse square root: a break whatever y's kind.
        hard = [*hard, 0.0] if _support(d)[0] <= 0.0 <= _support(d)[1] else hard
        return _Radial(one, [math.hypot(c, f) for f in hard], [math.hypot(c, f) for f in soft])
    (x1, x2), (y1, y2) = _support(dx), _support(dy)
    near = math.hypot(
        0.0 if x1 <= 0.0 <= x2 else min(abs(x1), abs(x2)),
        0.0 if y1 <= 0.0 <= y2 else min(abs(y1), abs(y2)),
    )
    far = max(math.hypot(x, y) for x in (x1, x2) for y in (y1, y2))
    pts = [near, far, *(math.hypot(x, y) for x in (x1, x2) for y in (y1, y2))]
    pts += [abs(e) for e in (x1, x2, y1, y2)]
    pts = sorted({p for p in pts if near <= p <= far})
    if isinstance(dx, Uniform) and isinstance(dy, Uniform):
        area = (x2 - x1) * (y2 - y1)

        def box(rho: np.ndarray) -> np.ndarray:
            return rho * bands.circle_in_box_angle(rho, x1, x2, y1, y2) / area

        return _Radial(box, pts)
    # A normal component: its side lines (±9 sd) are negligible; a uniform one's are breaks.
    sides = [
        abs(e) for d, es in ((dx, (x1, x2)), (dy, (y1, y2))) if isinstance(d, Uniform) for e in es
    ]
    hard = [p for p in sides if near <= p <= far]
    return _Radial(_PlaneInterpolant(dx, dy, pts), hard, pts)


class _PlaneInterpolant:
    """Density of Ω⊥ = √(ωx² + ωy²) for two ranged spins of which one is normal:
    W(ρ) = ρ ∫ p_x(ρ cos φ) p_y(ρ sin φ) dφ over the circle's arcs in the support box
    (:func:`coinflight.core.bands.circle_in_box_arcs`), by composite Gauss–Legendre in φ at
    Chebyshev points, and then a Chebyshev interpolant on each piece between consecutive
    ``breaks`` (cut to at most 1.5 sd wide), in the smoothstep variable u of
    ρ = a + (b − a)(3u² − 2u³) that makes the square-root onsets at a tangent side smooth.
    Each piece is halved until its interpolant's last coefficients are below 1e-13 of W's
    largest value (:func:`numpy.polynomial.chebyshev.chebinterpolate`)."""

    DEGREE = 24
    MAX_PIECES = 4000

    def __init__(self, dx: Distribution, dy: Distribution, breaks: list[float]) -> None:
        self.dx, self.dy = dx, dy
        self.box = (*_support(dx), *_support(dy))
        self.sd = min(d.sd for d in (dx, dy) if isinstance(d, Normal))
        self.breaks = np.asarray(breaks, dtype=float)
        self.coefs = np.empty((0, 0))  # built on first use (:meth:`_build`)

    def _build(self) -> None:
        ends = _refine_width(self.breaks, 1.5 * self.sd)
        pieces = list(itertools.pairwise(ends))
        coefs = [self._fit(a, b) for a, b in pieces]
        scale = max(np.max(np.abs(c)) for c in coefs)
        done: list[tuple[float, float, np.ndarray]] = []
        while pieces:
            (a, b), c = pieces.pop(), coefs.pop()
            small = np.max(np.abs(c[-4:])) <= 1e-13 * scale
            if small or len(done) + len(pieces) > self.MAX_PIECES:
                done.append((a, b, c))
                continue
            m = 0.5 * (a + b)
            pieces += [(a, m), (m, b)]
            coefs += [self._fit(a, m), self._fit(m, b)]
        done.sort(key=lambda piece: piece[0])
        self.starts = np.array([d[0] for d in done])
        self.widths = np.array([d[1] - d[0] for d in done])
        self.coefs = np.array([d[2] for d in done]).T.copy()  # (degree + 1, pieces)
        self.lo, self.hi = float(ends[0]), float(ends[-1])

    def _exact(self, rho: np.ndarray) -> np.ndarray:
        """W at a few radii by Gauss–Legendre over each arc, panels at most sd / 4 long."""
        out = np.zeros_like(rho)
        g, gw = np.polynomial.legendre.leggauss(16)
        for sx, sy, lo, hi in bands.circle_in_box_arcs(rho, *self.box):
            panels = max(1, math.ceil(float(np.max(rho * (hi - lo))) / (0.25 * self.sd)))
            k = np.arange(panels)
            width = (hi - lo)[:, None] / panels
            phi = lo[:, None] + width * (k[:, None] + 0.5 * (g + 1.0)).ravel()[None, :]
            w = (0.5 * width) * np.tile(gw, panels)[None, :]
            r = rho[:, None]
            val = _pdf(self.dx, sx * r * np.cos(phi)) * _pdf(self.dy, sy * r * np.sin(phi))
            out += rho * np.sum(w * val, axis=1)
        return out

    def _fit(self, a: float, b: float) -> np.ndarray:
        def f(t: np.ndarray) -> np.ndarray:
            u = 0.5 * (t + 1.0)
            return self._exact(a + (b - a) * u * u * (3.0 - 2.0 * u))

        return np.polynomial.chebyshev.chebinterpolate(f, self.DEGREE)

    def __call__(self, rho: np.ndarray) -> np.ndarray:
        if not self.coefs.size:
            self._build()
        r = np.asarray(rho, dtype=float)
        inside = (r > self.lo) & (r < self.hi)
        i = np.clip(np.searchsorted(self.starts, r, side="right") - 1, 0, self.starts.size - 1)
        y = np.clip((r - self.starts[i]) / self.widths[i], 0.0, 1.0)
        u = 0.5 - np.sin(np.arcsin(1.0 - 2.0 * y) / 3.0)  # the smoothstep's inverse
        t = 2.0 * u - 1.0
        c = self.coefs
        # Clenshaw's recurrence, each point with its piece's coefficients.
        b1 = np.zeros_like(t)
        b2 = np.zeros_like(t)
        t2 = 2.0 * t
        for k in range(c.shape[0] - 1, 0, -1):
            b1, b2 = t2 * b1 - b2 + c[k][i], b1
        return np.where(inside, t * b1 - b2 + c[0][i], 0.0)


def _refine_width(pts: np.ndarray, width: float) -> np.ndarray:
    """``pts`` (sorted) with each gap cut into equal pieces at most ``width`` wide."""
    out = [pts[:1]]
    for a, b in itertools.pairwise(pts):
        out.append(np.linspace(a, b, max(1, math.ceil((b - a) / width)) + 1)[1:])
    return np.concatenate(out)


def _times(t: Distribution) -> tuple[float, float, float]:
    """(T1, T2, 0) of a uniform flight time, (T, T, 0) of a fixed one, (mean, mean, sd) of a
    normal one."""
    if isinstance(t, Normal):
        return t.mean, t.mean, t.sd
    return (t.value, t.value, 0.0) if isinstance(t, Fixed) else (t.low, t.high, 0.0)  # type: ignore[attr-defined]


def _curves(table: tuple[np.ndarray, ...], psi: Any) -> Any:
    """Ω along the curves of the (Ω, ψ) plane where the integrand changes form, at ψ:
    kind 0, a band edge Ω = ((2j + 1)π ± b(ψ)) / T (p = (2j + 1)π, sgn = ±1, b from
    :func:`coinflight.core.bands.gap_half_width`); kind 1, a circle Ω⊥ = p, Ω = p / sin ψ;
    kind 2, a plane A = p, Ω = p / cos ψ. ``table`` = (kind, p, sgn, T). Broadcasts."""
    kind, p, sgn, t = table
    s, c = np.sin(psi), np.cos(psi)
    b = bands.gap_half_width((c / s) ** 2)
    with np.errstate(divide="ignore"):
        axial = p / c
    return np.where(kind == 0, (p + sgn * b) / t, np.where(kind == 1, p / s, axial))


def _edges(times: tuple[float, ...], om_lo: float, om_hi: float) -> tuple[np.ndarray, ...]:
    """The band-edge curves (kind, p, sgn, T) that may meet Ω in [om_lo, om_hi]."""
    cols: list[list[float]] = [[], [], [], []]
    for t in sorted(set(times[:2])):
        j = np.arange(
            max(0, math.ceil((om_lo * t - 1.5 * math.pi) / (2 * math.pi))),
            max(0, math.floor((om_hi * t - 0.5 * math.pi) / (2 * math.pi))) + 1,
        )
        for sgn in (-1.0, 1.0):
            cols[0] += [0.0] * j.size
            cols[1] += list((2 * j + 1) * math.pi)
            cols[2] += [sgn] * j.size
            cols[3] += [t] * j.size
    return tuple(np.asarray(c, dtype=float) for c in cols)


def _stack(*curves: tuple[np.ndarray, ...]) -> tuple[np.ndarray, ...]:
    """Curve tables (kind, p, sgn, T) joined."""
    return tuple(np.concatenate([c[i] for c in curves]) for i in range(4))


def _box(kind: int, values: np.ndarray) -> tuple[np.ndarray, ...]:
    """Curve table of circles (kind 1) or planes (kind 2) at ``values``."""
    vals = np.asarray(values, dtype=float)
    return (np.full(vals.size, float(kind)), vals, np.zeros(vals.size), np.ones(vals.size))


def _crossings(
    first: tuple[np.ndarray, ...], second: tuple[np.ndarray, ...], psi_lo: float, psi_hi: float
) -> np.ndarray:
    """ψ in (psi_lo, psi_hi) where a curve of ``first`` crosses one of ``second``.

    Each pair is sampled at :data:`_CROSSING_SAMPLES` points equally spaced in √(ψ − 45°)
    (the band edges move like that square root near 45°); every sign change is bisected to
    rounding. Pairs that cross twice between two samples are missed; the comparison of
    successive Gauss orders judges what that leaves.
    """
    na, nb = first[0].size, second[0].size
    if na == 0 or nb == 0 or psi_hi <= psi_lo:
        return np.empty(0)
    s = np.linspace(
        math.sqrt(max(psi_lo - _QUARTER, 0.0)),
        math.sqrt(max(psi_hi - _QUARTER, 0.0)),
        _CROSSING_SAMPLES,
    )
    psi = _QUARTER + s * s
    fb = _curves(tuple(c[:, None] for c in second), psi)
    roots = []
    step = max(1, int(4e6 // (nb * s.size)))
    for start in range(0, na, step):
        part = tuple(c[start : start + step] for c in first)
        fa = _curves(tuple(c[:, None] for c in part), psi)
        with np.errstate(invalid="ignore"):
            d = fa[:, None, :] - fb[None, :, :]
        pos = d > 0.0
        ok = np.isfinite(d)
        change = (pos[..., :-1] != pos[..., 1:]) & ok[..., :-1] & ok[..., 1:]
        ia, ib, m = np.nonzero(change)
        if ia.size == 0:
            continue
        lo, hi = s[m], s[m + 1]
        sign_lo = pos[ia, ib, m]
        ca = tuple(c[ia] for c in part)
        cb = tuple(c[ib] for c in second)
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            pm = _QUARTER + mid * mid
            with np.errstate(invalid="ignore"):
                same = (_curves(ca, pm) - _curves(cb, pm) > 0.0) == sign_lo
            lo, hi = np.where(same, mid, lo), np.where(same, hi, mid)
        roots.append(_QUARTER + (0.5 * (lo + hi)) ** 2)
    return np.concatenate(roots) if roots else np.empty(0)


def _smooth_rule(ends: np.ndarray, n: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss–Legendre with ``n`` nodes on each panel between consecutive ``ends`` (last axis),
    through the smoothstep x = a + (b − a)(3u² − 2u³): its slope vanishes at both ends, so
    that a square root or inverse square root at a panel's end (the gap's width at ψ = 45°, a
    circle touching a side of the box, a fixed ωx) becomes smooth in u."""
    g, gw = np.polynomial.legendre.leggauss(n)
    u, wu = 0.5 * (g + 1.0), 0.5 * gw
    lo, hi = ends[..., :-1, None], ends[..., 1:, None]
    width = hi - lo
    x = lo + width * (u * u * (3.0 - 2.0 * u))
    w = width * (6.0 * u * (1.0 - u) * wu)
    shape = (*ends.shape[:-1], -1)
    return x.reshape(shape), w.reshape(shape)


def _panels(cuts: np.ndarray, lo: float, hi: float, width: float = _PSI_PANEL) -> np.ndarray:
    """Panel ends: ``cuts`` inside (lo, hi) with lo and hi, each gap cut to at most ``width``."""
    pts = np.unique(np.concatenate(([lo, hi], cuts[(cuts > lo) & (cuts < hi)])))
    out = [pts[:1]]
    for a, b in itertools.pairwise(pts):
        out.append(np.linspace(a, b, max(1, math.ceil((b - a) / width)) + 1)[1:])
    return np.concatenate(out)


def _turning(om: np.ndarray, a: np.ndarray, times: tuple[float, float, float]) -> np.ndarray:
    """1 − P(same side) at rate Ω and band half-width a over the flight times: the fraction of
    T uniform on [T1, T2] (:func:`coinflight.core.bands.time_average_uniform`), whether the
    one T puts Ω T in a gap, or the wrapped-normal series of a normal T
    (:func:`coinflight.core.bands.same_side_normal_time`, with cot²ψ = −cos a)."""
    t1, t2, sd = times
    if sd > 0.0:
        om, a = np.broadcast_arrays(om, a)
        cot2 = -np.cos(a)
        perp2 = om * om / (1.0 + cot2)
        same = bands.same_side_normal_time(perp2.ravel(), (perp2 * cot2).ravel(), t1, sd)
        return 1.0 - same.reshape(om.shape)
    if t1 == t2:
        return (~bands.in_band(om * t1, a)).astype(float)
    return 1.0 - bands.time_average_uniform(om, a, t1, t2)


class _PolarPlan:
    """The (Ω, ψ) integral of a case: its outer panel ends, and per order its points."""

    def __init__(self, dist: TossDistribution) -> None:
        i1, i3 = dist.moments
        self.ratio = i3 / i1
        self.times = _times(dist.flight_time)
        self.plane = _plane(dist.omega_x, dist.omega_y)
        self.axial = _axial(dist.omega_z, self.ratio)
        p, ax = self.plane, self.axial
        self.empty = False
        if p.density is None and ax.density is None:  # pragma: no cover - closed form in T
            raise AssertionError("both atoms: the closed form in T")
        if p.density is None:
            self.kind = "plane fixed"
            # Along Ω⊥ = p: ψ from where A reaches the top of its range (or Ω⊥) to its bottom.
            psi_a = math.atan2(p.value, min(ax.hi, p.value))
            psi_b = math.atan2(p.value, ax.lo)
            curve = _box(1, np.array([p.value]))
            om_hi = p.value / math.sin(psi_a)
            fixed_cuts = np.arctan2(p.value, ax.points[ax.points > 0.0])
        elif ax.density is None and ax.value > 0.0:
            self.kind = "axial fixed"
            # Along A = value: ψ from where Ω⊥ reaches A (or its range's bottom) to its top.
            psi_a = math.atan2(max(p.lo, ax.value), ax.value)
            psi_b = math.atan2(p.hi, ax.value)
            curve = _box(2, np.array([ax.value]))
            om_hi = math.hypot(p.hi, ax.value)
            fixed_cuts = np.arctan2(p.graded, ax.value)
        elif ax.density is None:
            self.kind = "diameter"  # ω_z = 0: ψ = 90°, Ω = Ω⊥, the gaps' half-width π/2
            edges = _edges(self.times, p.lo, p.hi)
            cuts = (edges[1] + edges[2] * 0.5 * math.pi) / edges[3]
            self.ends = _panels(_graded(np.concatenate((cuts, p.graded))), p.lo, p.hi, math.inf)
            return
        else:
            self.kind = "2-D"
            psi_a, psi_b = _QUARTER, 0.5 * math.pi
            om_hi = min(math.hypot(p.hi, ax.hi), math.sqrt(2.0) * p.hi)
            self.edges = _edges(self.times, p.lo, om_hi)
            circles, planes = _box(1, p.breaks), _box(2, ax.breaks[ax.breaks > 0.0])
            self.box_curves = _stack(circles, planes)
            # The inner cuts: the box's curves with the soft points and the graded radii.
            self.inner_curves = _stack(_box(1, p.graded), _box(2, ax.points[ax.points > 0.0]))
            self._bound_crossings(self.edges[0].size * self.box_curves[0].size)
            cuts = np.concatenate(
                (
                    _crossings(self.edges, self.box_curves, psi_a, psi_b),
                    _crossings(circles, planes, psi_a, psi_b),
                )
            )
            self.ends = _panels(_graded(np.r_[psi_a, psi_b, cuts]), psi_a, psi_b)
            self.inner = self.edges[0].size + self.inner_curves[0].size + 1
            return
        if psi_b <= psi_a:
            self.empty = True
            return
        edges = _edges(self.times, 0.0, om_hi)
        self._bound_crossings(edges[0].size)
        cuts = np.concatenate((_crossings(edges, curve, psi_a, psi_b), fixed_cuts))
        self.ends = _panels(_graded(np.r_[psi_a, psi_b, cuts]), psi_a, psi_b)

    def _bound_crossings(self, pairs: int) -> None:
        v.work_bound(
            "the exact (Ω, ψ) rule's search for where band edges cross the spin box",
            float(pairs) * _CROSSING_SAMPLES,
            MAX_CROSSING_SAMPLES,
            "curve samples",
            _USE_INSTEAD,
            rate=POLAR_POINTS_PER_SECOND * 10,
        )

    def points(self, n: int) -> int:
        """Integrand points of order ``n``, counted before any allocation."""
        if self.empty:
            return 0
        outer = (self.ends.size - 1) * n
        return outer * self.inner * n if self.kind == "2-D" else outer

    def integral(self, n: int) -> float:
        """∫ of the density times 1 − P(same side | spins) over the spins, order ``n``."""
        if self.empty:
            return 0.0
        p, ax, times = self.plane, self.axial, self.times
        x, w = _smooth_rule(self.ends, n)
        if self.kind == "diameter":
            assert p.density is not None
            return math.fsum(w * p.density(x) * _turning(x, np.full_like(x, 0.5 * math.pi), times))
        s, c = np.sin(x), np.cos(x)
        a = bands.half_width((c / s) ** 2)
        if self.kind == "plane fixed":
            assert ax.density is not None
            r0 = p.value
            om, axial = r0 / s, r0 * c / s
            g = ax.density(axial) * _turning(om, a, times) * r0 / (s * s)
            return math.fsum(w * g)
        if self.kind == "axial fixed":
            assert p.density is not None
            a0 = ax.value
            om, rho = a0 / c, a0 * s / c
            g = p.density(rho) * _turning(om, a, times) * a0 / (c * c)
            return math.fsum(w * g)
        assert p.density is not None and ax.density is not None
        total = []
        rows = max(1, _POLAR_CHUNK // (self.inner * n))
        for start in range(0, x.size, rows):
            sl = slice(start, start + rows)
            ss, cc, aa = s[sl, None], c[sl, None], a[sl, None]
            with np.errstate(divide="ignore", invalid="ignore"):
                lo = np.maximum(p.lo / ss, np.where(ax.lo > 0.0, ax.lo / cc, 0.0))
                hi = np.minimum(p.hi / ss, ax.hi / cc)
            hi = np.maximum(hi, lo)
            brk = _curves(tuple(q[None, :] for q in self.inner_curves), x[sl, None])
            edge = _curves(tuple(q[None, :] for q in self.edges), x[sl, None])
            ends = np.sort(np.clip(np.concatenate((lo, edge, brk, hi), axis=1), lo, hi), axis=1)
            # Only the pieces of positive width (most curves lie outside a row's range).
            keep = ends[:, 1:] > ends[:, :-1]
            row = np.nonzero(keep)[0]
            if row.size == 0:
                continue
            pieces = np.stack((ends[:, :-1][keep], ends[:, 1:][keep]), axis=-1)
            om, wo = _smooth_rule(pieces, n)
            ss, cc, aa = ss[row], cc[row], aa[row]
            val = p.density(om * ss) * ax.density(om * cc) * om * _turning(om, aa, times)
            total.append(float(np.sum(w[sl][row, None] * wo * val)))
        return math.fsum(total)


_OMEGA_PSI = "closed form in T, Gauss–Legendre over the spins in (Ω, ψ)"


def _gauss_or_omega_psi(
    dist: TossDistribution, ranged: list[str], details: _Details
) -> tuple[float, float]:
    """The Gauss product rule over the spins (:func:`_gauss_spins`, fastest with a normal T and
    one or two ranged spins); where it refuses (not converged, or over its budget), the
    (Ω, ψ) rule (:func:`_omega_psi`), e.g. ωx and ω_z ranged across 0 with a narrow T. If
    both refuse, the Gauss rule's reason is given."""
    try:
        return _gauss_spins(dist, ranged, details)
    except ValueError as gauss_error:
        fallback: _Details = {}
        try:
            result = _omega_psi(dist, ranged, fallback)
        except ValueError:
            raise gauss_error from None
        details.clear()
        details.update(fallback, how=_OMEGA_PSI, fallback=f"the Gauss rule refused: {gauss_error}")
        return result


def _polar_seconds(dist: TossDistribution) -> float:
    """An upper estimate of the seconds of :func:`_omega_psi`'s first two orders, without its
    search for crossings: at most about one outer cut per pair of a band edge and a box curve
    (measured 0.2-1.2 of that on the test boxes) plus the panels' width limit, and the inner
    pieces counted as the plan counts them; 0.2 s more to build a normal plane's interpolant."""
    i1, i3 = dist.moments
    times = _times(dist.flight_time)
    p, ax = _plane(dist.omega_x, dist.omega_y), _axial(dist.omega_z, i3 / i1)
    setup = 0.2 if isinstance(p.density, _PlaneInterpolant) else 0.0
    orders = sum(n * n for n in POLAR_ORDERS[:2])
    if p.density is None or ax.density is None:
        om_hi = math.hypot(p.hi, ax.hi)
        edges = _edges(times, 0.0, om_hi)[0].size
        return 1e-3 + setup + (edges + p.graded.size + 64) * orders / POLAR_POINTS_PER_SECOND
    om_hi = min(math.hypot(p.hi, ax.hi), math.sqrt(2.0) * p.hi)
    edges = _edges(times, p.lo, om_hi)[0].size
    curves = p.breaks.size + ax.breaks.size
    panels = edges * curves + edges + 32
    inner = edges + p.graded.size + ax.points.size + 1
    return 1e-3 + setup + panels * inner * orders / POLAR_POINTS_PER_SECOND


def _omega_psi_applies(dist: TossDistribution, ranged: list[str]) -> bool:
    """T fixed or uniform with some spin ranged, or T normal with three ranged spins; every
    ranged spin uniform or normal."""
    t = dist.flight_time
    return (
        (isinstance(t, Fixed | Uniform) or (isinstance(t, Normal) and len(ranged) == 3))
        and bool(ranged)
        and all(isinstance(getattr(dist, n), Uniform | Normal) for n in ranged)
    )


def _omega_psi(dist: TossDistribution, ranged: list[str], details: _Details) -> tuple[float, float]:
    """Band measure over T in closed form, Gauss–Legendre over the spins in (Ω, ψ).

    P(same side | spins) depends on the spins through Ω = √(Ω⊥² + A²) and ψ with
    cot ψ = A / Ω⊥, A = (I3/I1) ω_z, Ω⊥ = √(ωx² + ωy²) (Diaconis, Holmes & Montgomery 2007,
    section 2): the coin shows the other face iff Ω T lies in a gap (2j + 1)π ± b(ψ),
    b = arccos(cot²ψ), only for ψ > 45°. With the density of Ω⊥ (:func:`_plane`, the azimuth
    integrated out) and of A (:func:`_axial`, ω_z's sign folded), 1 − P(same side) is

        ∫ dψ ∫ dΩ  (Ω / ratio)·p⊥(Ω sin ψ)·p_A(Ω cos ψ)·(1 − P(same | Ω, ψ))

    over ψ ∈ (45°, 90°], the Jacobian of (Ω⊥, ω_z) → (Ω, ψ) being Ω / ratio (the ratio's
    1/ratio is in p_A). For fixed ψ every place where the integrand changes form is explicit
    in Ω: the band edges ((2j + 1)π ± b(ψ)) / T1,2 (1 − P is linear in Ω T between them,
    for T uniform: Keller 1986), the radii where p⊥ has a kink (corners of a uniform box, a
    side's tangent circle) over sin ψ, and the ends of ω_z's range over cos ψ. The inner
    integral over Ω is cut at all of them; the outer one over ψ at 45°, 90° and where two of
    these curves cross (:func:`_crossings`). Each panel takes Gauss–Legendre through a
    smoothstep (:func:`_smooth_rule`), which makes the square roots at ψ = 45° and at a
    tangent circle smooth. With one of Ω⊥, A fixed the integral is over ψ along one curve.
    Orders :data:`POLAR_ORDERS` are tried until two in a row agree within :data:`TOLERANCE`.
    """
    plan = _PolarPlan(dist)
    details["spin integral"] = plan.kind
    previous, previous_n, change, used = math.nan, 0, math.nan, 0
    v.work_bound(
        f"the exact (Ω, ψ) rule over {len(ranged)} ranged spins",
        sum(plan.points(n) for n in POLAR_ORDERS[:2]),
        MAX_POLAR_POINTS,
        "integrand points",
        _USE_INSTEAD,
        rate=POLAR_POINTS_PER_SECOND,
    )
    for n in POLAR_ORDERS:
        points = plan.points(n)
        where = f"the exact (Ω, ψ) rule over {len(ranged)} ranged spins" + (
            f" (at {previous_n} nodes a panel {change:.2g} from the order before), "
            f"to {n} nodes a panel,"
            if math.isfinite(change)
            else ""
        )
        v.work_bound(
            where, used + points, 2 * MAX_POLAR_POINTS, "integrand points", _USE_INSTEAD,
            rate=POLAR_POINTS_PER_SECOND,
        )  # fmt: skip
        used += points
        value = 1.0 - plan.integral(n)
        change = abs(value - previous)
        if change <= TOLERANCE:
            details["nodes per panel"] = n
            details["integrand points"] = used
            return value, max(change, 4e-16 * math.sqrt(max(points, 1)))
        previous, previous_n = value, n
    raise ValueError(
        f"the exact (Ω, ψ) rule did not reach its tolerance {TOLERANCE:g} with "
        f"{POLAR_ORDERS[-1]} nodes per panel (last change {change:.2g}); {_USE_INSTEAD}"
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
        _gauss_or_omega_psi,
    ),
    (_OMEGA_PSI, _omega_psi_applies, _omega_psi),
    (
        "closed form in T, quadrature over the spins",
        _spins_by_quadrature,
        _closed_form_in_t_quadrature,
    ),
)
"""The integrals this method does, in order of preference: (how, whether it applies, run)."""


def _refusal(dist: TossDistribution, ranged: list[str]) -> str:
    """Why no exact integral here handles the distribution, and what to use instead."""
    odd = [
        f"{name} ({type(d).__name__})"
        for name in (*_SPINS, "flight_time")
        if not isinstance(d := getattr(dist, name), Fixed | Uniform | Normal)
    ]
    return (
        "the exact method integrates fixed, uniform and normal distributions only, not "
        f"{', '.join(odd) or 'this one'}; {_USE_INSTEAD}"
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
    details.setdefault("how", how)  # a runner that fell back to another integral says so
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


def estimated_seconds(dist: TossDistribution, model: OutcomeModel | None = None) -> float | None:
    """Seconds the exact method will take on ``dist`` (2-core reference machine), from the
    work of the integral that would run, counted before it runs: its band pieces, spin points
    or integrand points (the first two orders, the least that gives an error estimate) at
    the measured rates. None where no estimate is made (the adaptive quadrature, a model
    other than the hand catch, a distribution refused or over budget: those end early or
    within their own bound). For a sweep's work bound
    (:func:`coinflight.probability.sweep.check_sweep_work`)."""
    if model is not None and not model.closed_form_bands:
        return None
    ranged = [name for name in _SPINS if not getattr(dist, name).is_fixed]
    case = next((case for case in _CASES if case[1](dist, ranged)), None)
    if case is None:
        return None
    run = case[2]
    try:
        if run is _closed_form_in_t:
            return 1e-4
        if run is _closed_form:
            x = getattr(dist, ranged[0]) if ranged else None
            if not isinstance(x, Uniform):
                return 1e-4
            t2 = _times(dist.flight_time)[1]
            pieces = bands.diameter_spin_pieces(0.0, max(abs(x.low), abs(x.high)), 0.0, t2)
            return 1e-4 + 2.0 * pieces / PIECES_PER_SECOND
        if run is _gauss_or_omega_psi:
            h = _resolution(dist, ranged)
            points = sum(_gauss_points(dist, ranged, h, n) for n in GAUSS_ORDERS[:2])
            return points / SPIN_POINTS_PER_SECOND
        if run is _omega_psi:
            return _polar_seconds(dist)
    except ValueError:
        return None
    return None


def _summary(result: ProbabilityResult) -> str:
    extra = str(result.details["how"])
    if "warning" in result.details:
        extra += f"; quadrature warning: {result.details['warning']}"
    return extra


ESTIMATOR = Estimator(
    NAME, estimate, "exact value", "band integral (Keller 1986)", parallel=False, summary=_summary
)
