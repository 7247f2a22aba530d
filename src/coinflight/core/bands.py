"""Exact measure of the "same side" bands of a coin caught at launch height (pure NumPy).

A torque-free coin caught after time T shows the face it started with iff
n(T)·n0 = cos²ψ + sin²ψ cos(ωp T) > 0 (Diaconis, Holmes & Montgomery 2007), i.e. iff the phase
u = ωp T lies in a band (2πm − a, 2πm + a) with a = arccos(−cot²ψ) ∈ [π/2, π]. For a spin about
a diameter (ψ = 90°) a = π/2 and ωp = Ω: heads iff cos(ΩT) > 0 (Stefan & Cheche eqs 11, 14;
Keller 1986). These kernels integrate the band indicator exactly.
"""

from __future__ import annotations

import itertools
import math
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

FloatArray = NDArray[np.float64]

TWO_PI = 2.0 * np.pi


def never_turns_over(axial2: Any, transverse2: Any) -> Any:
    """True where the coin only wobbles: ψ ≤ 45° or ψ ≥ 135°, or no tumbling at all.

    ``axial2`` and ``transverse2`` are cos²ψ and sin²ψ times any common positive factor, e.g.
    ((I3/I1) ω_z)² and Ω⊥² = ωx² + ωy² (cos ψ = I3 ω_z / |M|, sin ψ = I1 Ω⊥ / |M|), so that
    no division is needed. Arrays or scalars; compiled as-is by numba in
    :mod:`coinflight.core.sampling`.

    Notes
    -----
    n(T)·n0 = cos²ψ + sin²ψ cos(ωp T) ≥ cos²ψ − sin²ψ ≥ 0 when cot²ψ ≥ 1 (Diaconis, Holmes &
    Montgomery 2007, section 2): the normal never passes the horizontal, and the coin shows
    its starting face at every T (at ψ = 45° exactly it touches the horizontal at the phases
    ωp T = π (2m + 1), a null set of times). With Ω⊥ = 0 the normal does not move.
    """
    return (transverse2 == 0.0) | (axial2 >= transverse2)


def half_width(cot2_psi: Any) -> Any:
    """Half-width a = arccos(−cot²ψ) of each band in phase; π when ψ ≤ 45° (never turns).

    Arrays or scalars (a float in, a float out); compiled as-is by numba in
    :mod:`coinflight.core.sampling`.

    Notes
    -----
    n(T)·n0 > 0 ⇔ cos(ωp T) > −cot²ψ (Diaconis, Holmes & Montgomery 2007, section 2).
    """
    return np.arccos(-np.minimum(cot2_psi, 1.0))


def precession_bands(
    perp2: ArrayLike, axial2: ArrayLike
) -> tuple[NDArray[np.bool_], FloatArray, FloatArray]:
    """Where each spin turns the coin over, and its band's rate ωp and half-width a.

    Spins given as Ω⊥² = ωx² + ωy² (``perp2``) and ((I3/I1) ω_z)² (``axial2``): ``turns`` is
    False where the coin never turns over (:func:`never_turns_over`), ωp = √(Ω⊥² + axial²) the
    rate of n(T)·n0 = cos²ψ + sin²ψ cos(ωp T), a = :func:`half_width` (cot²ψ = axial²/Ω⊥²)
    (Diaconis, Holmes & Montgomery 2007, section 2). Where the coin never turns over ωp and a
    are finite placeholders (those of Ω⊥ = 1, no axial spin), for the caller to replace.
    """
    perp2 = np.asarray(perp2, dtype=float)
    axial2 = np.asarray(axial2, dtype=float)
    turns = ~never_turns_over(axial2, perp2)
    p2 = np.where(turns, perp2, 1.0)
    x2 = np.where(turns, axial2, 0.0)
    return turns, np.sqrt(p2 + x2), half_width(x2 / p2)


def phase_measure(u: ArrayLike, a: ArrayLike = np.pi / 2) -> FloatArray:
    """Measure F(u) of {s ∈ [0, u] : s mod 2π within a of 0} (u ≥ 0), rad.

    F is continuous, piecewise linear with slope 1 in the bands and 0 between them:
    F(u) = 2a ⌊u/2π⌋ + min(r, a) + max(0, r − (2π − a)), r = u mod 2π. For a = π/2 this is the
    heads measure of Keller (1986) for θ = Ω t (Stefan & Cheche eq 11, heads iff cos θ > 0).
    """
    uu = np.asarray(u, dtype=float)
    aa = np.asarray(a, dtype=float)
    turns = np.floor(uu / TWO_PI)
    r = uu - TWO_PI * turns
    return 2.0 * aa * turns + np.minimum(r, aa) + np.maximum(0.0, r - (TWO_PI - aa))


def in_band(u: ArrayLike, a: ArrayLike = np.pi / 2) -> NDArray[np.bool_]:
    """True where phase u lies strictly inside a band (cos u > cos a)."""
    r = np.mod(np.asarray(u, dtype=float), TWO_PI)
    aa = np.asarray(a, dtype=float)
    return (r < aa) | (r > TWO_PI - aa)


def band_measure(u: ArrayLike, length: ArrayLike, a: ArrayLike = np.pi / 2) -> FloatArray:
    """Measure of the bands in [u, u + length] (u ≥ 0, length ≥ 0), rad: F(u + length) − F(u).

    Written so that a short interval does not lose its digits: F(u + L) − F(u) subtracts two
    numbers of size u, which leaves nothing of an L below u·2⁻⁵² (which once gave
    P(heads) = 1 for T in 0.7:0.7000000000000002). Here the whole turns of L count 2a each and
    the rest, an interval [r, r + ρ] with r = u mod 2π and ρ = L mod 2π, is intersected with the
    bands around 0, 2π and 4π as ρ minus what lies outside each, so an interval inside a band
    measures exactly ρ. F as in :func:`phase_measure`.
    """
    uu = np.asarray(u, dtype=float)
    ll = np.asarray(length, dtype=float)
    aa = np.asarray(a, dtype=float)
    r = uu - TWO_PI * np.floor(uu / TWO_PI)
    turns = np.floor(ll / TWO_PI)
    rho = ll - TWO_PI * turns
    local = np.zeros(np.broadcast(r, rho, aa).shape)
    for centre in (0.0, TWO_PI, 2.0 * TWO_PI):
        below = np.maximum(0.0, (centre - aa) - r)  # part of [r, r + ρ] before the band
        above = np.maximum(0.0, (r + rho) - (centre + aa))  # and after it
        local = local + np.maximum(0.0, rho - below - above)
    return 2.0 * aa * turns + local


def time_average_uniform(wp: ArrayLike, a: ArrayLike, t1: float, t2: float) -> FloatArray:
    """Fraction of flight times T uniform in [t1, t2] for which ωp T is in a band.

    (F(ωp t2) − F(ωp t1)) / (ωp (t2 − t1)), the difference taken by :func:`band_measure` so that
    it tends to the band indicator at t1 as t2 → t1; 1 where ωp = 0 (the coin does not turn).
    """
    wp = np.asarray(wp, dtype=float)
    safe = np.where(wp > 0, wp, 1.0)
    length = safe * (t2 - t1)
    val = band_measure(safe * t1, length, a) / length
    return np.where(wp > 0, np.clip(val, 0.0, 1.0), 1.0)


def band_edges(wp: float, a: float, t_low: float, t_high: float) -> tuple[FloatArray, FloatArray]:
    """Times (lo_m, hi_m) of the bands that meet [t_low, t_high], for ωp > 0, a < π."""
    m = np.arange(np.floor((wp * t_low - a) / TWO_PI), np.ceil((wp * t_high + a) / TWO_PI) + 1)
    return (TWO_PI * m - a) / wp, (TWO_PI * m + a) / wp


def _segment(u: FloatArray, a: float) -> tuple[FloatArray, FloatArray]:
    """(s, b) with F(u) = s·u + b on the piece of F holding u: s = 1 inside band k, where
    b = −(2π − 2a)k; s = 0 in the gap after band k, where b = 2ak + a (F of :func:`phase_measure`).

    From the integer k rather than as F(u) − s·u, which would round at the size of u.
    """
    k = np.floor((u + a) / TWO_PI)
    inside = (u + a) - TWO_PI * k < 2.0 * a
    s = inside.astype(float)
    b = np.where(inside, -(TWO_PI - 2.0 * a) * k, 2.0 * a * k + a)
    return s, b


def _diameter_spin_pieces(x1: float, x2: float, c: float, t1: float, t2: float) -> float:
    """∫ over x ∈ [x1, x2] (0 ≤ x1 ≤ x2) of P(same side | Ω = √(x² + c²)), T uniform on [t1, t2].

    For a spin about a diameter (ω_z = 0), one spin component x uniform and the other fixed at
    c, the same-side probability at Ω averaged over T uniform is
    G(Ω) = (F(Ω t2) − F(Ω t1)) / (Ω (t2 − t1)). F is piecewise linear, so between the Ω where
    Ω t1 or Ω t2 crosses a band edge, G(Ω) = α + β/Ω with constant α, β; and
    ∫ dx / √(x² + c²) = ln(x + √(x² + c²)). The integral is thus a finite sum in closed form
    (Keller 1986; Stefan & Cheche eq 15). With t1 = t2 (fixed T) G is the band indicator and the
    integral the total length of the bands in x.

    Notes
    -----
    Every difference is taken where it is small, so that narrow ranges keep their digits and a
    range of width → 0 tends to the fixed value: pieces are cut in x (the range's ends
    exact), dΩ and the logarithms' differences (log1p) follow from dx, the offsets β come from
    integer band indices (:func:`_segment`), and pieces where Ω t1 and Ω t2 lie in one band
    count dx exactly.
    """
    c = abs(float(c))
    if x2 <= x1:
        return 0.0
    w1, w2 = np.hypot(x1, c), np.hypot(x2, c)
    half = np.pi / 2
    times = (t1,) if t1 == t2 else (t1, t2)
    # Ω where Ω t crosses π/2 + jπ, for each t, inside (w1, w2).
    breaks: list[float] = []
    for t in times:
        j = np.arange(np.floor((w1 * t - half) / np.pi), np.ceil((w2 * t - half) / np.pi) + 1)
        w = (half + np.pi * j) / t
        breaks.extend(w[(w > w1) & (w < w2)])
    inner = np.asarray(breaks, dtype=float)
    # Pieces in x: the ends exactly as given, the breaks inside mapped by x = √(Ω² − c²).
    xs = np.unique(np.concatenate(([x1, x2], np.sqrt(np.maximum(inner * inner - c * c, 0.0)))))
    xs = xs[(xs >= x1) & (xs <= x2)]
    dx = np.diff(xs)
    omega = np.hypot(xs, c)
    mid = np.hypot(0.5 * (xs[:-1] + xs[1:]), c)
    # dΩ = dx (x_a + x_b) / (Ω_a + Ω_b), from x² = Ω² − c², consistent with dx: where a piece's
    # α dx and β Δln nearly cancel, an error in dx then cancels with them.
    o_sum = omega[:-1] + omega[1:]
    with np.errstate(divide="ignore", invalid="ignore"):
        d_omega = np.where(o_sum > 0, dx * (xs[:-1] + xs[1:]) / o_sum, 0.0)
    if t1 == t2:
        return float(np.sum(dx[in_band(mid * t1)]))
    s1, b1 = _segment(mid * t1, half)
    s2, b2 = _segment(mid * t2, half)
    width = t2 - t1
    # On a piece, measure(Ω) = (s2 t2 − s1 t1) Ω + (b2 − b1); divided by Ω (t2 − t1) and
    # integrated over x: α dx + β Δln(x + Ω), Δln = log1p((dx + dΩ) / (x_a + Ω_a)).
    alpha = np.where((s1 == 1.0) & (s2 == 1.0), 1.0, (s2 * t2 - s1 * t1) / width)
    beta = (b2 - b1) / width
    base = xs[:-1] + omega[:-1]
    # From x = 0 with c = 0 the logarithm is infinite, but there Ω t1 and Ω t2 lie in the first
    # band (β = 0): the term is not used.
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        dlog = np.where(beta == 0.0, 0.0, np.log1p((dx + d_omega) / base))
    return float(np.sum(alpha * dx) + np.sum(beta * dlog))


PIECES_PER_CHUNK = 1_000_000
"""Band pieces summed at once by :func:`diameter_spin_integral` (memory ~100 MB at most)."""


def diameter_spin_pieces(x1: float, x2: float, c: float, t2: float) -> float:
    """Upper estimate of the number of band pieces in :func:`diameter_spin_integral`.

    Ω t crosses a band edge every π of phase, for t1 and t2: at most 2 (Ω2 − Ω1) t2 / π + 3.
    """
    w1, w2 = math.hypot(x1, c), math.hypot(x2, c)
    return 2.0 * (w2 - w1) * t2 / math.pi + 3.0


def diameter_spin_integral(x1: float, x2: float, c: float, t1: float, t2: float) -> float:
    """∫ over x ∈ [x1, x2] (0 ≤ x1 ≤ x2) of P(same side | Ω = √(x² + c²)), T uniform on [t1, t2].

    The closed form of :func:`_diameter_spin_pieces`, summed over sub-ranges of x holding at
    most :data:`PIECES_PER_CHUNK` pieces each, so that memory stays bounded for any range (the
    integral is additive in x). The caller bounds the total work with
    :func:`diameter_spin_pieces`.
    """
    pieces = diameter_spin_pieces(x1, x2, c, t2)
    chunks = max(1, math.ceil(pieces / PIECES_PER_CHUNK))
    if chunks == 1 or x2 <= x1:
        return _diameter_spin_pieces(x1, x2, c, t1, t2)
    # Equal steps in Ω hold equal numbers of pieces; map them back to x.
    w = np.linspace(math.hypot(x1, c), math.hypot(x2, c), chunks + 1)
    xs = np.sqrt(np.maximum(w * w - c * c, 0.0))
    xs[0], xs[-1] = x1, x2
    return math.fsum(
        _diameter_spin_pieces(float(a), float(b), c, t1, t2) for a, b in itertools.pairwise(xs)
    )


def same_side_over_times(
    perp2: FloatArray,
    axial2: FloatArray,
    cdf: Any,
    t_low: float,
    t_high: float,
) -> FloatArray:
    """P(same side) at each spin, the flight time T with CDF ``cdf`` on about [t_low, t_high].

    Vectorized over spins given as Ω⊥² = ωx² + ωy² (``perp2``) and ((I3/I1) ω_z)² (``axial2``):
    the band measure Σ_m CDF((2πm + a)/ωp) − CDF((2πm − a)/ωp) over every band that meets
    [t_low, t_high] (ωp = √(Ω⊥² + axial²), a from :func:`half_width`; Diaconis, Holmes &
    Montgomery 2007, section 2); 1 where the coin never turns over (:func:`never_turns_over`).
    The same sum as the fixed-spin closed form in T, for arrays of spins at once; the caller
    bounds its work (about ωp (t_high − t_low) / 2π + 3 terms a spin).
    """
    turns, wp, a = precession_bands(perp2, axial2)
    m0 = np.floor((wp * t_low - a) / TWO_PI)
    count = int(np.max(np.ceil((wp * t_high + a) / TWO_PI) - m0, initial=0.0)) + 1
    m = m0[..., None] + np.arange(count)
    inv = 1.0 / wp[..., None]
    total = np.sum(
        cdf((TWO_PI * m + a[..., None]) * inv) - cdf((TWO_PI * m - a[..., None]) * inv), axis=-1
    )
    return np.where(turns, total, 1.0)


WRAPPED_SIGMA = 1.5
"""Phase spread σ = ωp·sd above which :func:`same_side_normal_time` sums the wrapped-normal
Fourier series (at most ⌈8.9/σ⌉ ≤ 6 terms) instead of the normal-CDF differences (about
16.6 σ / 2π + 3 terms): both cost a handful of terms a spin."""
_FOURIER_CUT = 8.9
"""Terms k of the Fourier series with k σ ≤ 8.9 are kept: the first dropped one is
below exp(−8.9²/2) < 6e-18."""
_TAIL_SIGMAS = 8.3
"""The CDF sum spans T within ±8.3 sd of the mean (mass outside 1e-16)."""


def same_side_normal_time(
    perp2: ArrayLike, axial2: ArrayLike, mean: float, sd: float
) -> FloatArray:
    """P(same side) at each spin for a normal flight time T ~ N(mean, sd²).

    Spins given as Ω⊥² (``perp2``) and ((I3/I1) ω_z)² (``axial2``), as in
    :func:`same_side_over_times`. The phase u = ωp T is normal with mean m = ωp·mean and sd
    σ = ωp·sd, and the coin shows its starting face iff u mod 2π lies within a of 0, so

        P = a/π + (2/π) Σ_{k≥1} exp(−k²σ²/2) sin(k a) cos(k m) / k,

    the integral of the wrapped normal density over (−a, a) (Mardia & Jupp 2000, Directional
    Statistics, §3.5.7: the wrapped normal's Fourier series). For σ ≥ :data:`WRAPPED_SIGMA` the
    series needs at most six terms to reach 1e-17; below it the band sum
    Σ_m Φ((2πm + a)/ωp) − Φ((2πm − a)/ωp) (Diaconis, Holmes & Montgomery 2007, section 2) over
    T within ±8.3 sd holds a few bands. The series counts the mass at T < 0 (below 6e-16 for
    the flight times coinflight accepts, mean > 8 sd). Smooth in the spins except where the
    coin stops turning over (a → π like a square root at ψ = 45°); 1 where it never turns over.
    """
    from scipy.special import ndtr

    turns, wp, a = precession_bands(perp2, axial2)
    sigma = wp * sd
    out = np.ones(turns.shape)
    series = turns & (sigma >= WRAPPED_SIGMA)
    if np.any(series):
        where = np.flatnonzero(series)
        kmax = np.ceil(_FOURIER_CUT / sigma[where]).astype(np.int64)
        for terms_k in np.unique(kmax):  # one pass per number of terms (at most six)
            idx = where[kmax == terms_k]
            s, aa, m = sigma[idx], a[idx], np.mod(wp[idx] * mean, TWO_PI)
            k = np.arange(1, terms_k + 1, dtype=float)
            terms = np.exp(-0.5 * (k * s[:, None]) ** 2) * np.sin(k * aa[:, None])
            terms *= np.cos(k * m[:, None]) / k
            out[idx] = aa / np.pi + (2.0 / np.pi) * np.sum(terms, axis=-1)
    direct = turns & ~series
    if np.any(direct):
        w, aa = wp[direct], a[direct]
        t_low = max(0.0, mean - _TAIL_SIGMAS * sd)
        t_high = mean + _TAIL_SIGMAS * sd
        m0 = np.floor((w * t_low - aa) / TWO_PI)
        count = int(np.max(np.ceil((w * t_high + aa) / TWO_PI) - m0)) + 1
        mm = m0[:, None] + np.arange(count)
        # (t − mean)/sd at the band ends t = (2πm ± a)/ω: a subnormal sd overflows to ±inf,
        # the step function that is the limit sd → 0 of Φ, so the overflow is silenced.
        with np.errstate(over="ignore"):
            hi = ((TWO_PI * mm + aa[:, None]) / w[:, None] - mean) / sd
            lo = ((TWO_PI * mm - aa[:, None]) / w[:, None] - mean) / sd
        out[direct] = np.sum(ndtr(hi) - ndtr(lo), axis=-1)
    return out


def circle_in_box_arcs(
    rho: ArrayLike, x1: float, x2: float, y1: float, y2: float
) -> list[tuple[float, float, FloatArray, FloatArray]]:
    """Arcs of the circle of radius ``rho`` about the origin inside the box [x1, x2] × [y1, y2],
    one per quadrant the box reaches: (sx, sy, lo, hi), the points (sx ρ cos φ, sy ρ sin φ)
    for φ in [lo, hi] ⊂ [0, π/2] (hi = lo where the circle misses that part).

    The box's part in a quadrant, reflected into the first one, is [p1, p2] × [q1, q2] with
    0 ≤ p1, 0 ≤ q1; there the circle's angles with p1 ≤ ρ cos φ ≤ p2 form
    [arccos(p2/ρ), arccos(p1/ρ)] and those with q1 ≤ ρ sin φ ≤ q2 form
    [arcsin(q1/ρ), arcsin(q2/ρ)] (ratios capped at 1, each angle from atan2 of the legs
    √((ρ − p)(ρ + p)) and p so that it keeps its digits near a tangent); the arc is their
    overlap. Its ends are
    smooth in ρ except at the radii of the box's corners and where the circle touches a side's
    line (ρ = p or q, a square-root onset).
    """
    r = np.asarray(rho, dtype=float)

    legs: dict[float, FloatArray] = {}

    def leg(p: float) -> FloatArray:  # √(ρ² − p²), 0 inside; each distance once
        if p not in legs:
            legs[p] = np.sqrt(np.maximum((r - p) * (r + p), 0.0))
        return legs[p]

    def acos(p: float) -> FloatArray:  # arccos(min(p/ρ, 1)), accurate where p/ρ → 1
        return np.arctan2(leg(p), p)

    def asin(q: float) -> FloatArray:  # arcsin(min(q/ρ, 1)), likewise
        return np.arctan2(q, leg(q))

    xs = [(1.0, max(x1, 0.0), x2)] if x2 > 0.0 else []
    xs += [(-1.0, max(-x2, 0.0), -x1)] if x1 < 0.0 else []
    ys = [(1.0, max(y1, 0.0), y2)] if y2 > 0.0 else []
    ys += [(-1.0, max(-y2, 0.0), -y1)] if y1 < 0.0 else []
    arcs = []
    for sx, p1, p2 in xs:
        for sy, q1, q2 in ys:
            if p2 <= p1 or q2 <= q1:
                continue
            lo = np.maximum(acos(p2), asin(q1))
            hi = np.minimum(acos(p1), asin(q2))
            hi = np.where(r > 0.0, np.maximum(hi, lo), lo)
            arcs.append((sx, sy, lo, hi))
    return arcs


def circle_in_box_angle(rho: ArrayLike, x1: float, x2: float, y1: float, y2: float) -> FloatArray:
    """Angle (rad) of the circle of radius ``rho`` about the origin that lies in the box
    [x1, x2] × [y1, y2]: the total of :func:`circle_in_box_arcs`. Times ρ / area, it is the
    density of Ω⊥ = √(ωx² + ωy²) for uniform ωx, ωy (the polar-coordinates Jacobian).
    """
    total = np.zeros(np.shape(rho))
    for _sx, _sy, lo, hi in circle_in_box_arcs(rho, x1, x2, y1, y2):
        total = total + (hi - lo)
    return total


def gap_half_width(cot2_psi: Any) -> Any:
    """Half-width b = π − a = arccos(cot²ψ) of the phase gaps (2m + 1)π ± b in which the coin
    shows the other face (a from :func:`half_width`); 0 when ψ ≤ 45° (no gap).

    Notes
    -----
    n(T)·n0 < 0 ⇔ cos(ωp T) < −cot²ψ (Diaconis, Holmes & Montgomery 2007, section 2): the
    phases within arccos(cot²ψ) of an odd multiple of π. Near ψ = 45° it is a square root,
    b ≈ √(2 (1 − cot²ψ)).
    """
    return np.arccos(np.minimum(cot2_psi, 1.0))
