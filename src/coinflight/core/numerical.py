"""Numerical reference: Euler's equations and quaternion kinematics integrated by SciPy.

One toss per call, slow and independent of the closed form: the tests use it to check
:mod:`coinflight.core.torque_free`, and the drag model reuses its right-hand side.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

FloatArray = NDArray[np.float64]


def euler_rhs(omega: FloatArray, moments: FloatArray) -> FloatArray:
    """dω/dt for a torque-free rigid body, body frame.

    Notes
    -----
    Euler's equations, Stefan & Cheche eq 5: I1 ω̇x + (I3 − I2) ωy ωz = 0 and cyclic.
    """
    i1, i2, i3 = moments
    wx, wy, wz = omega
    return np.array([(i2 - i3) * wy * wz / i1, (i3 - i1) * wz * wx / i2, (i1 - i2) * wx * wy / i3])


def quaternion_rate(q: FloatArray, omega: FloatArray) -> FloatArray:
    """dq/dt = ½ q ⊗ (ω, 0) for a scalar-last unit quaternion q (body → lab), body-frame ω."""
    x, y, z, w = q
    wx, wy, wz = omega
    return 0.5 * np.array(
        [
            w * wx + y * wz - z * wy,
            w * wy + z * wx - x * wz,
            w * wz + x * wy - y * wx,
            -x * wx - y * wy - z * wz,
        ]
    )


@dataclass(frozen=True)
class Trajectory:
    """Sampled numerical trajectory: times (n,), quaternions (n, 4) scalar-last, ω (n, 3)."""

    t: FloatArray
    quaternion: FloatArray
    omega: FloatArray

    def normal(self) -> FloatArray:
        """Heads normal in the lab frame, shape (n, 3): the third column of R(q)."""
        from scipy.spatial.transform import Rotation

        return Rotation.from_quat(self.quaternion).apply([0.0, 0.0, 1.0])


def integrate(
    omega0: ArrayLike,
    moments: ArrayLike,
    t_eval: ArrayLike,
    start_sign: float = 1.0,
    rtol: float = 1e-12,
    atol: float = 1e-12,
) -> Trajectory:
    """Integrate one torque-free flight from launch (t = 0) to the times ``t_eval``.

    Parameters
    ----------
    omega0 : array_like, shape (3,)
        Body-frame angular velocity at launch, rad/s.
    moments : array_like, shape (3,)
        Principal moments (I1, I2, I3), kg m²; need not be symmetric.
    t_eval : array_like, shape (n,)
        Increasing times ≥ 0 at which to report the state, s.
    start_sign : float
        +1 heads up at launch, −1 tails up (a half turn about lab X).

    Notes
    -----
    DOP853 (``scipy.integrate.solve_ivp``) on the 7-dimensional state (ω, q); the quaternion is
    renormalised only when read out.
    """
    from scipy.integrate import solve_ivp

    moments = np.asarray(moments, dtype=float)
    t_eval = np.atleast_1d(np.asarray(t_eval, dtype=float))
    q0 = np.array([0.0, 0.0, 0.0, 1.0]) if start_sign > 0 else np.array([1.0, 0.0, 0.0, 0.0])

    def rhs(_t: float, y: FloatArray) -> FloatArray:
        return np.concatenate([euler_rhs(y[:3], moments), quaternion_rate(y[3:], y[:3])])

    y0 = np.concatenate([np.asarray(omega0, dtype=float), q0])
    t_end = float(t_eval[-1]) if t_eval[-1] > 0 else 1e-12
    sol = solve_ivp(rhs, (0.0, t_end), y0, method="DOP853", t_eval=t_eval, rtol=rtol, atol=atol)
    if not sol.success:  # pragma: no cover - DOP853 on a smooth bounded problem
        raise RuntimeError(f"numerical reference failed: {sol.message}")
    q = sol.y[3:].T
    q = q / np.linalg.norm(q, axis=1, keepdims=True)
    return Trajectory(t=sol.t, quaternion=q, omega=sol.y[:3].T)
