"""Stefan & Cheche's own construction of the coin's orientation, kept as published.

Used to check, in the tests and in the reproduction report, that the general closed form of
:mod:`coinflight.core.torque_free` contains the paper's cases a) and b) exactly.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

FloatArray = NDArray[np.float64]


def euler_angles(
    omega_x0: ArrayLike, omega_y0: ArrayLike, t: ArrayLike
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Euler angles (α, β, γ) of case b) at time t.

    Notes
    -----
    Stefan & Cheche eq 12 with ω_z0 = 0 is solved by α = α0 = 0, β = Ω t (β0 = 0) and
    γ = γ0 = −arctan(ω_y0 / ω_x0), Ω = sqrt(ω_x0² + ω_y0²) (eq 9). We use arctan2 so that
    ω_x0 = 0 is allowed; the paper's arctan is the same for ω_x0 > 0.
    """
    wx = np.asarray(omega_x0, dtype=float)
    wy = np.asarray(omega_y0, dtype=float)
    t = np.asarray(t, dtype=float)
    big_omega = np.hypot(wx, wy)
    alpha = np.zeros(np.broadcast_shapes(wx.shape, wy.shape, t.shape))
    beta = big_omega * t + alpha
    gamma = -np.arctan2(wy, wx) + alpha
    return alpha, beta, gamma


def euler_matrix(alpha: ArrayLike, beta: ArrayLike, gamma: ArrayLike) -> FloatArray:
    """Stefan & Cheche's Euler rotation matrix A (Goldstein's x-convention), shape (..., 3, 3)."""
    a = np.asarray(alpha, dtype=float)
    b = np.asarray(beta, dtype=float)
    g = np.asarray(gamma, dtype=float)
    ca, sa, cb, sb, cg, sg = np.cos(a), np.sin(a), np.cos(b), np.sin(b), np.cos(g), np.sin(g)
    rows = [
        [cg * ca - cb * sa * sg, cg * sa + cb * ca * sg, sb * sg],
        [-sg * ca - cb * sa * cg, -sg * sa + cb * ca * cg, sb * cg],
        [sb * sa, -sb * ca, cb],
    ]
    shape = np.broadcast_shapes(a.shape, b.shape, g.shape)
    return np.stack(
        [np.stack([np.broadcast_to(x, shape) for x in row], axis=-1) for row in rows], axis=-2
    )


def plane_normal(r_a: ArrayLike, r_b: ArrayLike) -> FloatArray:
    """Unit normal n(r_A, r_B) = r_A × r_B / |r_A × r_B| of the plane of two radii (eq 13)."""
    n = np.cross(np.asarray(r_a, dtype=float), np.asarray(r_b, dtype=float))
    return n / np.linalg.norm(n, axis=-1, keepdims=True)


def dihedral_cosine(
    omega_x0: ArrayLike, omega_y0: ArrayLike, t: ArrayLike, radius: float = 1.0
) -> FloatArray:
    """cos θ between the coin's plane at launch and at t, by the paper's construction.

    Notes
    -----
    Stefan & Cheche eqs 12-14: r_A0 = (R, 0, 0) and r_B0 = (0, R, 0) are turned by A to
    r_A = A r_A0 and r_B = A r_B0, and cos θ = n(r_A0, r_B0) · n(r_A, r_B). The paper finds
    cos θ = cos(Ω t) (eq 14), independent of α0, β0.
    """
    alpha, beta, gamma = euler_angles(omega_x0, omega_y0, t)
    a = euler_matrix(alpha, beta, gamma)
    r_a0 = np.array([radius, 0.0, 0.0])
    r_b0 = np.array([0.0, radius, 0.0])
    n0 = plane_normal(r_a0, r_b0)
    n = plane_normal(a @ r_a0, a @ r_b0)
    return np.asarray(n @ n0)


def rotation_angle(omega_x0: ArrayLike, omega_y0: ArrayLike, flight_time: ArrayLike) -> FloatArray:
    """Total rotation angle θ(T) = T sqrt(ω_x0² + ω_y0²) (Stefan & Cheche eqs 11, 15), rad."""
    return np.asarray(flight_time, dtype=float) * np.hypot(
        np.asarray(omega_x0, dtype=float), np.asarray(omega_y0, dtype=float)
    )
