"""Numerical reference: Euler's equations and quaternion kinematics integrated by SciPy.

One toss per call, slow and independent of the closed form: the tests use it to check
:mod:`coinflight.core.torque_free`, and the drag model reuses its right-hand side.
"""

from __future__ import annotations

from collections.abc import Callable
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


def air_rhs(
    mass: float,
    radius: float,
    thickness: float,
    moments: ArrayLike,
    g: float,
    drag_factor: float,
    spin_damping: float,
    projected: bool = True,
) -> Callable[[float, FloatArray], FloatArray]:
    """f(t, y) of a flight through air on y = (x, y, z, vx, vy, vz, ω (body), q (scalar last)).

    The equations of :mod:`coinflight.core.drag` written in the body frame, independently of
    its closed-form decays and Magnus steps: dv/dt = −g Z − c A(n·v̂) |v| v with c = ρ C_d / 2m
    (``drag_factor``) and A the projected area π r² |n·v̂| + 2 r h sqrt(1 − (n·v̂)²) (or π r²
    when not ``projected``); I ω̇ = −ω × I ω − K ω (Euler's equations, Stefan & Cheche eq 5, with
    the damping torque); dq/dt = ½ q ⊗ (ω, 0).
    """
    moments = np.asarray(moments, dtype=float)

    def f(_t: float, y: FloatArray) -> FloatArray:
        v = y[3:6]
        w = y[6:9]
        x, yy, z, s = y[9:13] / np.linalg.norm(y[9:13])
        n = np.array([2 * (x * z + s * yy), 2 * (yy * z - s * x), 1 - 2 * (x * x + yy * yy)])
        speed = float(np.sqrt(v @ v))
        acc = np.zeros(3)
        if speed > 0.0:
            if projected:
                c = float(n @ v) / speed
                area = np.pi * radius**2 * abs(c) + 2 * radius * thickness * np.sqrt(
                    max(0.0, 1 - c * c)
                )
            else:
                area = np.pi * radius**2
            acc = -drag_factor * area * speed * v
        acc[2] -= g
        dw = euler_rhs(w, moments) - spin_damping * w / moments
        return np.concatenate([v, acc, dw, quaternion_rate(y[9:13], w)])

    return f


def air_catch(
    f: Callable[[float, FloatArray], FloatArray],
    omega0: ArrayLike,
    launch_speed: float,
    start_sign: float = 1.0,
    rtol: float = 1e-12,
    atol: float = 1e-13,
) -> tuple[float, FloatArray]:
    """(catch time, state then) of a flight through air (``f`` from :func:`air_rhs`): DOP853
    from launch until the centre of mass comes back down to launch height."""
    from scipy.integrate import solve_ivp

    def back_down(t: float, y: FloatArray) -> float:
        return float(y[2]) if t > 0 else 1.0

    back_down.terminal = True  # type: ignore[attr-defined]
    back_down.direction = -1  # type: ignore[attr-defined]
    q0 = [0.0, 0.0, 0.0, 1.0] if start_sign > 0 else [1.0, 0.0, 0.0, 0.0]
    y0 = np.concatenate([[0.0, 0.0, 0.0, 0.0, 0.0, float(launch_speed)], omega0, q0])
    sol = solve_ivp(f, (0.0, 60.0), y0, method="DOP853", rtol=rtol, atol=atol, events=back_down)
    if sol.t_events[0].size == 0:  # pragma: no cover - gravity brings it down
        raise RuntimeError("the numerical reference did not come back down")
    return float(sol.t_events[0][0]), np.asarray(sol.y_events[0][0])


def quaternion_normal(q: ArrayLike) -> FloatArray:
    """Heads normal in the lab, the third column of R(q), for scalar-last q (..., 4)."""
    x, y, z, w = np.moveaxis(np.asarray(q, dtype=float), -1, 0)
    s = 1.0 / (x * x + y * y + z * z + w * w)
    return np.stack(
        [2 * s * (x * z + w * y), 2 * s * (y * z - w * x), 1 - 2 * s * (x * x + y * y)], axis=-1
    )
