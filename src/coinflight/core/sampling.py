"""Compiled kernels that count the faces of many tosses (numba, cached on disk).

Imported only by the probability estimators: importing it imports numba.

Design
------
* The face of a toss is decided by :func:`coinflight.core.torque_free.normal_alignment`, the
  same function the rest of coinflight uses, compiled here by numba. Only its ``np.sinc`` is
  swapped for :func:`sinc`, a branch-free polynomial version accurate to 2 ulp: libm's ``sin``
  is not vectorised by LLVM and costs ~30 ns a call on the reference machine, which alone
  would exceed the Monte Carlo budget (see ``benchmarks/bench_probability.py``).
* Random numbers for Monte Carlo come from a counter-based generator, SplitMix64 (Steele, Lea
  & Flood, OOPSLA 2014): output i of a stream with key k is mix64(k + (i + 1) γ), exactly the
  SplitMix64 sequence started at k. A block of tosses is therefore a pure function of its key
  (drawn from a NumPy ``SeedSequence`` child) and of the toss index: results cannot depend on
  chunking or threads, and the loop vectorises. Each toss uses two 64-bit outputs, split into
  four 32-bit uniforms (i + ½)/2³².
* Parameters are mapped from the unit interval by a per-parameter affine map
  x = offset + scale · u (Uniform and Fixed distributions); other distributions are mapped by
  their ``ppf`` in NumPy and passed in with offset 0, scale 1.
"""

from __future__ import annotations

import types
from collections.abc import Callable
from typing import Any

import numba
import numpy as np

from coinflight.core import torque_free

# Cody & Waite reduction: π split into three parts whose first two have 33 significant bits,
# so that k·_PI_A and k·_PI_B are exact for |k| < 2²⁰.
_PI_A = 3.1415926534682512
_PI_B = 1.2154201012607932e-10
_PI_C = 4.044532497591901e-21
_INV_PI = 0.3183098861837907
# Taylor coefficients (−1)ⁿ/(2n+1)! of sin on [−π/2, π/2]; the first omitted term is < 2e-18.
_S0 = 1.0
_S1 = -0.16666666666666666
_S2 = 0.008333333333333333
_S3 = -0.0001984126984126984
_S4 = 2.7557319223985893e-06
_S5 = -2.505210838544172e-08
_S6 = 1.6059043836821613e-10
_S7 = -7.647163731819816e-13
_S8 = 2.8114572543455206e-15
_S9 = -8.22063524662433e-18
_S10 = 1.9572941063391263e-20

_GAMMA = np.uint64(0x9E3779B97F4A7C15)
_MIX1 = np.uint64(0xBF58476D1CE4E5B9)
_MIX2 = np.uint64(0x94D049BB133111EB)
_LOW32 = np.uint64(0xFFFFFFFF)
_TWO_M32 = 2.0**-32


@numba.njit(inline="always", cache=True, error_model="numpy")
def sin(x: float) -> float:
    """sin x, branch-free so that LLVM vectorises loops that call it.

    Reduction x = kπ + r, |r| ≤ π/2 (Cody & Waite 1980) and a degree-21 Taylor polynomial;
    absolute error ≤ 2.3e-16 for |x| < 3e6 (checked against ``numpy.sin`` in the tests).
    """
    k = np.floor(x * _INV_PI + 0.5)
    r = ((x - k * _PI_A) - k * _PI_B) - k * _PI_C
    r2 = r * r
    p = _S10
    p = p * r2 + _S9
    p = p * r2 + _S8
    p = p * r2 + _S7
    p = p * r2 + _S6
    p = p * r2 + _S5
    p = p * r2 + _S4
    p = p * r2 + _S3
    p = p * r2 + _S2
    p = p * r2 + _S1
    p = p * r2 + _S0
    parity = k - 2.0 * np.floor(0.5 * k)
    return (1.0 - 2.0 * parity) * r * p


@numba.njit(inline="always", cache=True, error_model="numpy")
def sinc(x: float) -> float:
    """Normalised sinc, sin(πx)/(πx), as ``numpy.sinc`` (1 at x = 0)."""
    y = np.pi * x
    return sin(y) / y if y != 0.0 else 1.0


def _with_fast_sinc(func: Callable[..., Any], name: str) -> types.FunctionType:
    """``func`` itself (same bytecode), with its ``np`` resolving ``sinc`` to :func:`sinc`."""
    fast_np = types.ModuleType(f"coinflight_fast_np_{name}")
    # Everything else resolves to NumPy itself (PEP 562 module __getattr__), so the swap keeps
    # working if the closed form starts using other NumPy functions.
    fast_np.__getattr__ = lambda attr: getattr(np, attr)  # type: ignore[method-assign]
    fast_np.sinc = sinc  # type: ignore[attr-defined]
    namespace = dict(func.__globals__)
    namespace["np"] = fast_np
    out = types.FunctionType(func.__code__, namespace, name, func.__defaults__)
    out.__qualname__ = name
    out.__module__ = func.__module__
    out.__doc__ = func.__doc__
    return out


normal_alignment = numba.njit(inline="always", cache=True, error_model="numpy")(
    _with_fast_sinc(torque_free.normal_alignment, "normal_alignment_sampling")
)
""":func:`coinflight.core.torque_free.normal_alignment`, compiled (fast sinc, see module)."""


@numba.njit(inline="always", cache=True, error_model="numpy")
def _mix64(z: np.uint64) -> np.uint64:
    """SplitMix64 finaliser (Steele, Lea & Flood 2014; constants from Vigna's splitmix64.c)."""
    z = (z ^ (z >> np.uint64(30))) * _MIX1
    z = (z ^ (z >> np.uint64(27))) * _MIX2
    return z ^ (z >> np.uint64(31))


@numba.njit(nogil=True, cache=True, error_model="numpy")
def uniforms(key: np.uint64, start: int, n: int) -> np.ndarray:
    """The four uniforms of tosses ``start … start + n − 1`` of stream ``key``, shape (4, n).

    The values :func:`count_same_side_random` uses; for tests and for non-affine distributions.
    """
    out = np.empty((4, n))
    for j in range(n):
        c = key + np.uint64(2 * (start + j) + 1) * _GAMMA
        w1 = _mix64(c)
        w2 = _mix64(c + _GAMMA)
        out[0, j] = (np.float64(w1 & _LOW32) + 0.5) * _TWO_M32
        out[1, j] = (np.float64(w1 >> np.uint64(32)) + 0.5) * _TWO_M32
        out[2, j] = (np.float64(w2 & _LOW32) + 0.5) * _TWO_M32
        out[3, j] = (np.float64(w2 >> np.uint64(32)) + 0.5) * _TWO_M32
    return out


@numba.njit(nogil=True, cache=True, error_model="numpy")
def count_same_side_random(
    key: np.uint64,
    start: int,
    n: int,
    offset: np.ndarray,
    scale: np.ndarray,
    cells: int,
    i1: float,
    i3: float,
) -> int:
    """Number of same-side tosses among tosses ``start … start + n − 1`` of stream ``key``.

    Parameters
    ----------
    key : uint64
        Stream key (from a ``SeedSequence`` child).
    start, n : int
        First toss index in the stream and number of tosses.
    offset, scale : ndarray, shape (4,)
        Affine maps u ↦ offset + scale · u for (ωx, ωy, ωz, T); rad/s and s.
    cells : int
        0 for continuous draws; otherwise the paper's method B: u is replaced by the midpoint
        of its cell among ``cells`` equal cells, (⌊u · cells⌋ + ½) / cells.
    i1, i3 : float
        Principal moments, kg m².
    """
    same = 0
    fc = float(cells)
    for j in range(n):
        c = key + np.uint64(2 * (start + j) + 1) * _GAMMA
        w1 = _mix64(c)
        w2 = _mix64(c + _GAMMA)
        u0 = (np.float64(w1 & _LOW32) + 0.5) * _TWO_M32
        u1 = (np.float64(w1 >> np.uint64(32)) + 0.5) * _TWO_M32
        u2 = (np.float64(w2 & _LOW32) + 0.5) * _TWO_M32
        u3 = (np.float64(w2 >> np.uint64(32)) + 0.5) * _TWO_M32
        if cells > 0:
            u0 = (np.floor(u0 * fc) + 0.5) / fc
            u1 = (np.floor(u1 * fc) + 0.5) / fc
            u2 = (np.floor(u2 * fc) + 0.5) / fc
            u3 = (np.floor(u3 * fc) + 0.5) / fc
        a = normal_alignment(
            offset[0] + scale[0] * u0,
            offset[1] + scale[1] * u1,
            offset[2] + scale[2] * u2,
            offset[3] + scale[3] * u3,
            i1,
            i3,
        )
        same += a > 0.0
    return same


@numba.njit(nogil=True, cache=True, error_model="numpy")
def count_same_side(
    wx: np.ndarray, wy: np.ndarray, wz: np.ndarray, t: np.ndarray, i1: float, i3: float
) -> int:
    """Number of same-side tosses among given initial conditions, each of shape (n,)."""
    same = 0
    for j in range(t.shape[0]):
        same += normal_alignment(wx[j], wy[j], wz[j], t[j], i1, i3) > 0.0
    return same


@numba.njit(nogil=True, cache=True, error_model="numpy")
def count_same_side_affine(
    u: np.ndarray, rows: np.ndarray, offset: np.ndarray, scale: np.ndarray, i1: float, i3: float
) -> int:
    """Same-side count for unit-cube points ``u`` (k, n) mapped affinely.

    ``rows[p]`` is the row of ``u`` holding parameter p of (ωx, ωy, ωz, T), or −1 when p is
    fixed at ``offset[p]``.
    """
    same = 0
    n = u.shape[1]
    x = np.empty(4)
    for j in range(n):
        for p in range(4):
            r = rows[p]
            x[p] = offset[p] + scale[p] * u[r, j] if r >= 0 else offset[p]
        same += normal_alignment(x[0], x[1], x[2], x[3], i1, i3) > 0.0
    return same


@numba.njit(nogil=True, cache=True, error_model="numpy")
def count_same_side_time_bands(
    wx: np.ndarray,
    wy: np.ndarray,
    wz: np.ndarray,
    t_nodes: np.ndarray,
    i1: float,
    i3: float,
) -> int:
    """Exact count of same-side configurations on a grid, with no loop over the time nodes.

    Parameters
    ----------
    wx, wy, wz : ndarray, shape (m,)
        Spin nodes, rad/s (one configuration of spins per entry).
    t_nodes : ndarray, shape (n_t,)
        Increasing flight-time nodes, s.
    i1, i3 : float
        Principal moments, kg m².

    Notes
    -----
    For each spin the coin shows its starting face iff cos(ωp t) > −cot²ψ (Diaconis, Holmes &
    Montgomery 2007; Stefan & Cheche eq 14 when ψ = 90°), i.e. for ωp t in bands
    (2πm − a, 2πm + a), a = arccos(−cot²ψ). The nodes inside each band are found by binary
    search, O(bands · log n_t) per spin instead of O(n_t). Nodes within rounding distance of a
    band edge are settled by evaluating :func:`normal_alignment` itself, so that the count
    equals the brute-force count exactly.
    """
    total = 0
    n_t = t_nodes.shape[0]
    t_first = t_nodes[0]
    t_last = t_nodes[n_t - 1]
    for j in range(wx.shape[0]):
        perp2 = wx[j] * wx[j] + wy[j] * wy[j]
        axial = i3 / i1 * wz[j]
        ax2 = axial * axial
        if perp2 == 0.0 or ax2 >= perp2:
            # ψ ≤ 45°: the normal never passes the horizontal (only touches it when ψ = 45°);
            # settled node by node (rare: wobbling coins only).
            for i in range(n_t):
                total += normal_alignment(wx[j], wy[j], wz[j], t_nodes[i], i1, i3) > 0.0
            continue
        wp = np.sqrt(perp2 + ax2)
        a = np.arccos(-ax2 / perp2)
        m_first = int(np.floor((wp * t_first - a) / (2.0 * np.pi)))
        m_last = int(np.ceil((wp * t_last + a) / (2.0 * np.pi)))
        for m in range(m_first, m_last + 1):
            lo = (2.0 * np.pi * m - a) / wp
            hi = (2.0 * np.pi * m + a) / wp
            i_lo = _settle(
                np.searchsorted(t_nodes, lo), lo, True, wx[j], wy[j], wz[j], t_nodes, i1, i3
            )
            i_hi = _settle(
                np.searchsorted(t_nodes, hi), hi, False, wx[j], wy[j], wz[j], t_nodes, i1, i3
            )
            if i_hi > i_lo:
                total += i_hi - i_lo
    return total


@numba.njit(inline="always", cache=True, error_model="numpy")
def _settle(
    i: int,
    edge: float,
    entering: bool,
    wx: float,
    wy: float,
    wz: float,
    t_nodes: np.ndarray,
    i1: float,
    i3: float,
) -> int:
    """First node index on the far side of a band edge, as the predicate itself decides.

    ``i`` is the first node with t ≥ ``edge``. Nodes within 1e-9 (relative) of the edge are
    tested with :func:`normal_alignment`: at an entering edge the first node inside the band is
    wanted, at a leaving edge the first node outside.
    """
    n_t = t_nodes.shape[0]
    tol = 1e-9 * abs(edge)
    if i < n_t and abs(t_nodes[i] - edge) <= tol:
        inside = normal_alignment(wx, wy, wz, t_nodes[i], i1, i3) > 0.0
        if inside != entering:
            i += 1
    if i > 0 and abs(t_nodes[i - 1] - edge) <= tol:
        inside = normal_alignment(wx, wy, wz, t_nodes[i - 1], i1, i3) > 0.0
        if inside == entering:
            i -= 1
    return i


def warm_up() -> None:
    """Compile (or load from the on-disk cache) every kernel once, for timing runs."""
    off = np.zeros(4)
    sc = np.ones(4)
    count_same_side_random(np.uint64(1), 0, 4, off, sc, 0, 1.0, 1.0)
    uniforms(np.uint64(1), 0, 2)
    z = np.zeros(2)
    count_same_side(z, z, z, z + 1.0, 1.0, 1.0)
    count_same_side_affine(np.zeros((1, 2)), np.array([0, -1, -1, -1]), off, sc, 1.0, 1.0)
    count_same_side_time_bands(z, z, z, np.array([0.5, 0.6]), 1.0, 1.0)
