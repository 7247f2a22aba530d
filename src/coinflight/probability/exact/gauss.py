"""Exact P(same side) for a normal flight time (or launch speed) with one or two ranged spins:
the wrapped-normal series in T (:func:`coinflight.core.bands.same_side_normal_time`) inside
a Gauss–Legendre product rule over the spins, split where the coin stops turning over
(ψ = 45°) (:func:`_gauss_spins`); chosen by :mod:`coinflight.probability.exact`, which falls
back to :mod:`coinflight.probability.exact.omega_psi` where this rule refuses."""

from __future__ import annotations

import itertools
import math

import numpy as np

from coinflight.core import bands
from coinflight.model.distributions import Distribution, Normal, Uniform
from coinflight.model.ensemble import TossDistribution
from coinflight.probability.exact import common

GAUSS_ORDERS = (12, 16, 24, 32, 48, 64)
"""Gauss–Legendre nodes per panel tried in turn by the Gauss product rule over the spins; the
result is the first whose change from the previous order is within :data:`~.common.TOLERANCE`."""
MAX_SPIN_POINTS = 6e7
"""Most spin points (each a few wrapped-normal terms) the Gauss product rule may evaluate over
all its orders, bounded before anything is allocated (about a minute on the 2-core machine)."""
SPIN_POINTS_PER_SECOND = 1.5e6
"""Spin points the Gauss product rule evaluates a second (2-core machine, about ten terms each)."""
MAX_PANELS = 24
"""Most panels per spin variable (or per angular sector) the resolution may ask for."""
NARROWEST_BLUR = 0.05
"""Least blur Ω sd of a band edge (rad of phase, at the smallest Ω where a band edge can be)
this rule takes: below it P(same side | spins) steps across each edge in less than its
panels' nodes resolve, and two orders can agree on a wrong value (T ~ normal(0.3, 3e-5) with
ωx in 5:6 once gave 0.25, the answer 0.235988). Below it the rule refuses and the (Ω, ψ) rule,
which cuts at each blurred edge (:func:`coinflight.probability.exact.omega_psi._edge_times`),
runs instead."""
_CHUNK = 1 << 16
"""Spins evaluated at once by the Gauss product rule (memory ~ _CHUNK × 6 terms × 8 bytes × 4)."""


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
    lo, hi = common._support(d)
    h = min(h, _scale(d))
    pts = common._normal_marks(d) if isinstance(d, Normal) else np.linspace(lo, hi, 3)
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
    (three go to the (Ω, ψ) rule, much faster there)."""
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
    for name in common._SPINS:
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
    (x1, x2), (y1, y2) = common._support(dx), common._support(dy)
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
    (x1, x2), (y1, y2) = common._support(dx), common._support(dy)
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
        ws.append((wphi[:, None] * ws_ * r * common._pdf(dx, x) * common._pdf(dy, y)).ravel())
    return np.concatenate(xs), np.concatenate(ys), np.concatenate(ws)


def _use_polar(dist: TossDistribution, ranged: list[str]) -> bool:
    """Two ranged ωx, ωy go to polar coordinates when ω_z is fixed ≠ 0 (the circle where the
    coin stops turning over is a radius) or when a uniform ω_z's rims (:func:`_rims`) are
    circles in a box that does not hold the origin (the case that did not converge in a tensor
    product); else a tensor product (with the origin in the box the tensor product is faster,
    and the polar rule converges poorly there)."""
    if "omega_z" not in ranged:
        return dist.omega_z.mean != 0.0
    (x1, x2), (y1, y2) = common._support(dist.omega_x), common._support(dist.omega_y)
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
    spins = {d: getattr(dist, d) for d in common._SPINS}
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


def _check_blur(dist: TossDistribution, ranged: list[str]) -> None:
    """ValueError when the normal flight time blurs the band edges less than
    :data:`NARROWEST_BLUR`: at the smallest Ω a band edge can have (the first edge π / 2T,
    or the spins' nearest approach to 0 if larger), Ω sd below it."""
    t = dist.flight_time
    assert isinstance(t, Normal)
    i1, i3 = dist.moments
    nearest = []
    for name in common._SPINS:
        d = getattr(dist, name)
        lo, hi = common._support(d) if name in ranged else (d.mean, d.mean)
        near = 0.0 if lo <= 0.0 <= hi else min(abs(lo), abs(hi))
        nearest.append(near * (i3 / i1 if name == "omega_z" else 1.0))
    first_edge = max(math.hypot(*nearest), 0.5 * math.pi / (t.mean + 9.0 * t.sd))
    if first_edge * t.sd < NARROWEST_BLUR:
        raise ValueError(
            f"the exact Gauss rule cannot resolve a flight time of sd {t.sd:g} s: it blurs "
            f"each band edge over {first_edge * t.sd:.2g} rad of phase, less than "
            f"{NARROWEST_BLUR:g}; {common._USE_INSTEAD}"
        )


def _gauss_spins(
    dist: TossDistribution, ranged: list[str], details: common._Details
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
    within :data:`~.common.TOLERANCE`, their difference being the error estimate.
    """
    i1, i3 = dist.moments
    ratio = i3 / i1
    t = dist.flight_time
    assert isinstance(t, Normal)
    _check_blur(dist, ranged)
    spins: dict[str, Distribution] = {n: getattr(dist, n) for n in common._SPINS}
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
            wx_, wy_ = wx_ * common._pdf(spins[plane[0]], x), wy_ * common._pdf(spins[plane[1]], y)
            return np.repeat(x, y.size), np.tile(y, x.size), np.outer(wx_, wy_).ravel()
        if not plane:
            return (np.array([spins["omega_x"].mean]), np.array([spins["omega_y"].mean]),
                    np.ones(1))  # fmt: skip
        d = spins[plane[0]]
        x, w = _composite(_breaks(d, h), n)
        w = w * common._pdf(d, x)
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
            w = w * safe * np.cos(theta) * common._pdf(d, z)
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
            w = w * np.where(x > 0.0, s / np.where(x > 0.0, x, 1.0), 1.0) * common._pdf(d, sign * x)
            total += math.fsum(w * same(x * x + c * c, np.full_like(x, axial0**2)))
        return total

    return common._by_orders(
        "the exact Gauss quadrature",
        len(ranged),
        GAUSS_ORDERS,
        lambda n: _gauss_points(dist, ranged, h, n),
        integral,
        (MAX_SPIN_POINTS, MAX_SPIN_POINTS),
        "spin points",
        SPIN_POINTS_PER_SECOND,
        details,
    )
