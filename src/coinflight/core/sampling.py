"""Compiled kernels that count the faces of many tosses (numba, cached on disk).

Imported only by the probability estimators: importing it imports numba.

Design
------
* The face of a toss is decided by :func:`coinflight.core.torque_free.normal_alignment`, the
  same function the rest of coinflight uses, compiled here by numba. Only its ``np.sinc`` is
  swapped for :func:`sinc`, a branch-free polynomial version accurate to 2 ulp: libm's ``sin``
  is not vectorised by LLVM and costs ~30 ns a call on the reference machine, which alone
  would exceed the Monte Carlo budget (see ``benchmarks/bench_probability.py``).
* Random numbers are not drawn here: the estimators fill arrays of uniforms with NumPy
  generators (which release the GIL) and pass them in, so the kernels are pure functions of
  their arrays and the loops vectorise.
* Parameters are mapped from the unit interval by a per-parameter affine map
  x = offset + scale · u (Uniform and Fixed distributions); other distributions are mapped by
  their ``ppf`` in NumPy and passed in as values.
"""

from __future__ import annotations

import types
from collections.abc import Callable
from typing import Any

import numpy as np

from coinflight.core import bands, torque_free
from coinflight.core._jit import numba

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


@numba.njit(inline="always", cache=True, error_model="numpy")
def sin(x: float) -> float:
    """sin x, branch-free so that LLVM vectorises loops that call it.

    Reduction x = kπ + r, |r| ≤ π/2 (Cody & Waite 1980) and a degree-21 Taylor polynomial;
    absolute error ≤ 3.4e-16 for |x| ≤ 1e7 (measured maximum 3.3e-16 against ``numpy.sin``;
    checked in the tests). Beyond, k·π_A is no longer exact and the error grows (2e-9 at
    1e8, 6e-8 at 1e9), staying below the spacing of doubles at x (1.5e-8, 1.2e-7).
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

never_turns_over = numba.njit(inline="always", cache=True, error_model="numpy")(
    bands.never_turns_over
)
""":func:`coinflight.core.bands.never_turns_over`, compiled."""

half_width = numba.njit(inline="always", cache=True, error_model="numpy")(bands.half_width)
""":func:`coinflight.core.bands.half_width`, compiled."""


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
    u: np.ndarray, offset: np.ndarray, scale: np.ndarray, i1: float, i3: float
) -> int:
    """Same-side count for unit-cube points mapped affinely to initial conditions.

    Parameters
    ----------
    u : ndarray, shape (4, n)
        Points of the unit cube; row p drives parameter p of (ωx, ωy, ωz, T). Rows must be
        contiguous for the loop to vectorise (a toss-major layout is about 4 times slower).
    offset, scale : ndarray, shape (4,)
        Parameter p is ``offset[p] + scale[p] * u[p]`` (rad/s, s); a fixed parameter has
        scale 0, so its row does not change its value.
    i1, i3 : float
        Principal moments, kg m².
    """
    same = 0
    for j in range(u.shape[1]):
        a = normal_alignment(
            offset[0] + scale[0] * u[0, j],
            offset[1] + scale[1] * u[1, j],
            offset[2] + scale[2] * u[2, j],
            offset[3] + scale[3] * u[3, j],
            i1,
            i3,
        )
        same += a > 0.0
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
    search, O(bands · log n_t) per spin instead of O(n_t); a wobbling spin (ψ < 45°) shows the
    starting face at every node, O(1). Nodes within rounding distance of a
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
        if never_turns_over(ax2, perp2):
            if perp2 == 0.0 or ax2 > perp2:
                # ψ < 45° (or no tumbling at all): n(t)·n0 ≥ cos²ψ − sin²ψ > 0, every node
                # shows the starting face.
                total += n_t
                continue
            # ψ = 45° exactly: the normal touches the horizontal at ωp t = π (2m + 1); the
            # sign there is rounding's, so settled node by node as the brute force does.
            for i in range(n_t):
                total += normal_alignment(wx[j], wy[j], wz[j], t_nodes[i], i1, i3) > 0.0
            continue
        wp = np.sqrt(perp2 + ax2)
        a = half_width(ax2 / perp2)
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
    z = np.zeros(2)
    count_same_side(z, z, z, z + 1.0, 1.0, 1.0)
    count_same_side_affine(np.zeros((4, 2)), np.zeros(4), np.ones(4), 1.0, 1.0)
    count_same_side_time_bands(z, z, z, np.array([0.5, 0.6]), 1.0, 1.0)
