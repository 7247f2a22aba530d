"""Exact measure of the "same side" bands of a coin caught at launch height (pure NumPy).

A torque-free coin caught after time T shows the face it started with iff
n(T)·n0 = cos²ψ + sin²ψ cos(ωp T) > 0 (Diaconis, Holmes & Montgomery 2007), i.e. iff the phase
u = ωp T lies in a band (2πm − a, 2πm + a) with a = arccos(−cot²ψ) ∈ [π/2, π]. For a spin about
a diameter (ψ = 90°) a = π/2 and ωp = Ω: heads iff cos(ΩT) > 0 (Stefan & Cheche eqs 11, 14;
Keller 1986). These kernels integrate the band indicator exactly.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

FloatArray = NDArray[np.float64]

TWO_PI = 2.0 * np.pi


def half_width(cot2_psi: ArrayLike) -> FloatArray:
    """Half-width a = arccos(−cot²ψ) of each band in phase; π when ψ ≤ 45° (never turns).

    Notes
    -----
    n(T)·n0 > 0 ⇔ cos(ωp T) > −cot²ψ (Diaconis, Holmes & Montgomery 2007, section 2).
    """
    c = np.asarray(cot2_psi, dtype=float)
    return np.arccos(-np.minimum(c, 1.0))


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


def time_average_uniform(wp: ArrayLike, a: ArrayLike, t1: float, t2: float) -> FloatArray:
    """Fraction of flight times T uniform in [t1, t2] for which ωp T is in a band.

    (F(ωp t2) − F(ωp t1)) / (ωp (t2 − t1)); 1 where ωp = 0 (the coin does not turn).
    """
    wp = np.asarray(wp, dtype=float)
    safe = np.where(wp > 0, wp, 1.0)
    val = (phase_measure(safe * t2, a) - phase_measure(safe * t1, a)) / (safe * (t2 - t1))
    return np.where(wp > 0, val, 1.0)


def band_edges(wp: float, a: float, t_low: float, t_high: float) -> tuple[FloatArray, FloatArray]:
    """Times (lo_m, hi_m) of the bands that meet [t_low, t_high], for ωp > 0, a < π."""
    m = np.arange(np.floor((wp * t_low - a) / TWO_PI), np.ceil((wp * t_high + a) / TWO_PI) + 1)
    return (TWO_PI * m - a) / wp, (TWO_PI * m + a) / wp


def diameter_spin_integral(x1: float, x2: float, c: float, t1: float, t2: float) -> float:
    """∫ over x ∈ [x1, x2] (0 ≤ x1 ≤ x2) of P(same side | Ω = √(x² + c²)), T uniform on [t1, t2].

    For a spin about a diameter (ω_z = 0), one spin component x uniform and the other fixed at
    c, the same-side probability at Ω averaged over T uniform is
    G(Ω) = (F(Ω t2) − F(Ω t1)) / (Ω (t2 − t1)). F is piecewise linear, so between the Ω where
    Ω t1 or Ω t2 crosses a band edge, G(Ω) = α + β/Ω with constant α, β; and
    ∫ dx / √(x² + c²) = asinh(x/|c|) (ln x when c = 0). The integral is thus a finite sum in
    closed form (Keller 1986; Stefan & Cheche eq 15). With t1 = t2 (fixed T) G is the band
    indicator and the integral the total length of the bands in x.
    """
    c = abs(float(c))
    if x2 <= x1:
        return 0.0
    w1, w2 = np.hypot(x1, c), np.hypot(x2, c)
    half = np.pi / 2
    times = (t1,) if t1 == t2 else (t1, t2)
    # Ω where Ω t crosses π/2 + jπ, for each t, inside (w1, w2).
    breaks = [w1, w2]
    for t in times:
        j = np.arange(np.floor((w1 * t - half) / np.pi), np.ceil((w2 * t - half) / np.pi) + 1)
        w = (half + np.pi * j) / t
        breaks.extend(w[(w > w1) & (w < w2)])
    omega = np.unique(np.asarray(breaks))
    xs = np.sqrt(np.maximum(omega * omega - c * c, 0.0))
    xs[0], xs[-1] = x1, x2
    mid = 0.5 * (omega[:-1] + omega[1:])
    dx = np.diff(xs)
    if t1 == t2:
        return float(np.sum(dx[in_band(mid * t1)]))
    # On each piece F(Ω t) = s Ω t + b with s = 1 inside a band, 0 outside.
    s1 = in_band(mid * t1).astype(float)
    s2 = in_band(mid * t2).astype(float)
    b1 = phase_measure(mid * t1) - s1 * mid * t1
    b2 = phase_measure(mid * t2) - s2 * mid * t2
    alpha = s2 * t2 - s1 * t1
    beta = b2 - b1
    # ∫ dx / √(x² + c²) = ln(x + √(x² + c²)) (= asinh(x/c) + ln c), which also holds for
    # c = 0 and does not overflow for tiny c. On the first piece from x = 0 with c = 0,
    # F(Ω t) = Ω t for both times, so β = 0 there and the infinite logarithm is not used.
    with np.errstate(divide="ignore"):
        prim = np.log(xs + np.hypot(xs, c))
    dlog = np.where(beta == 0.0, 0.0, np.diff(prim))
    total = np.sum(alpha * dx) + np.sum(np.where(beta == 0.0, 0.0, beta * dlog))
    return float(total / (t2 - t1))
