"""Flight through air: quadratic drag on the centre of mass and damping of the spin (SciPy).

One toss per call, integrated by ``scipy.integrate.solve_ivp`` (DOP853) on the 13-dimensional
state (position, velocity, body angular velocity ω, scalar-last quaternion q body → lab):

    dv/dt = −g Z − (ρ C_d A / 2m) |v| v,          A = π r² (a face, broadside on)
    I ω̇ = −ω × I ω − k ω                          (Euler's equations with a damping torque)
    dq/dt = ½ q ⊗ (ω, 0)

The torque-free part reuses :func:`coinflight.core.numerical.euler_rhs` and
:func:`coinflight.core.numerical.quaternion_rate` (Stefan & Cheche eq 5). Quadratic drag with a
fixed area is the model of Strzałko et al. 2008 (§5, REFERENCES §4); the coin's changing
attitude to the wind is not followed. With C_d = k = 0 the flight is the closed form of
:mod:`coinflight.core.torque_free` and :mod:`coinflight.core.ballistics` (tested to 1e-9).
Contacts with a table are located by ``solve_ivp``'s event root finding on the gap under the
coin's lowest point, and resolved by :func:`coinflight.core.impact.impact`.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from coinflight.core.numerical import euler_rhs, quaternion_rate

FloatArray = NDArray[np.float64]
RTOL = 1e-12
ATOL = 1e-13


@dataclass(frozen=True)
class DragModel:
    """Parameters of the drag flight (SI units)."""

    mass: float
    radius: float
    moments: tuple[float, float, float]
    g: float
    drag_coefficient: float = 0.0
    spin_damping: float = 0.0
    air_density: float = 1.2

    @property
    def drag_factor(self) -> float:
        """ρ C_d A / 2m, 1/m: the deceleration per (m/s)² of speed."""
        area = math.pi * self.radius**2
        return 0.5 * self.air_density * self.drag_coefficient * area / self.mass


def rhs(model: DragModel) -> Callable[[float, FloatArray], FloatArray]:
    """Right-hand side f(t, y) for y = (x, y, z, vx, vy, vz, ωx, ωy, ωz, qx, qy, qz, qw)."""
    moments = np.asarray(model.moments, dtype=float)
    k = model.drag_factor
    damping = model.spin_damping / moments
    g = model.g

    def f(_t: float, y: FloatArray) -> FloatArray:
        v = y[3:6]
        w = y[6:9]
        acc = -k * math.sqrt(v @ v) * v
        acc[2] -= g
        dw = euler_rhs(w, moments) - damping * w
        return np.concatenate([v, acc, dw, quaternion_rate(y[9:13], w)])

    return f


def initial_state(omega0: ArrayLike, launch_speed: float, start_sign: float) -> FloatArray:
    """State at launch: centre of mass at the origin moving up at v0; heads or tails up."""
    q0 = [0.0, 0.0, 0.0, 1.0] if start_sign > 0 else [1.0, 0.0, 0.0, 0.0]
    return np.concatenate([[0.0, 0.0, 0.0, 0.0, 0.0, float(launch_speed)], omega0, q0])


def normal(q: FloatArray) -> FloatArray:
    """Heads normal in the lab, the third column of R(q), for scalar-last q (..., 4)."""
    x, y, z, w = np.moveaxis(np.asarray(q, dtype=float), -1, 0)
    s = 1.0 / (x * x + y * y + z * z + w * w)
    return np.stack(
        [2 * s * (x * z + w * y), 2 * s * (y * z - w * x), 1 - 2 * s * (x * x + y * y)], axis=-1
    )


def fly(
    model: DragModel,
    omega0: ArrayLike,
    launch_speed: float,
    t_eval: ArrayLike,
    start_sign: float = 1.0,
) -> FloatArray:
    """States (n, 13) at the times ``t_eval`` (increasing, ≥ 0) of a flight with drag."""
    from scipy.integrate import solve_ivp

    t_eval = np.atleast_1d(np.asarray(t_eval, dtype=float))
    y0 = initial_state(np.asarray(omega0, dtype=float), launch_speed, start_sign)
    t_end = max(float(t_eval[-1]), 1e-12)
    sol = solve_ivp(
        rhs(model), (0.0, t_end), y0, method="DOP853", t_eval=t_eval, rtol=RTOL, atol=ATOL
    )
    if not sol.success:  # pragma: no cover - DOP853 on a smooth bounded problem
        raise RuntimeError(f"drag flight failed: {sol.message}")
    return np.asarray(sol.y.T)


def catch(
    model: DragModel, omega0: ArrayLike, launch_speed: float, start_sign: float = 1.0
) -> tuple[float, FloatArray]:
    """Time and state when the centre of mass comes back down to launch height (a catch)."""
    from scipy.integrate import solve_ivp

    def back_down(t: float, y: FloatArray) -> float:
        return float(y[2]) if t > 0 else 1.0

    back_down.terminal = True  # type: ignore[attr-defined]
    back_down.direction = -1  # type: ignore[attr-defined]
    y0 = initial_state(np.asarray(omega0, dtype=float), launch_speed, start_sign)
    t_max = 2.0 * launch_speed / model.g * 1.5 + 1.0
    sol = solve_ivp(
        rhs(model), (0.0, t_max), y0, method="DOP853", events=back_down, rtol=RTOL, atol=ATOL
    )
    if sol.t_events[0].size == 0:  # pragma: no cover - gravity always brings it down
        raise RuntimeError("the coin did not come back down")
    return float(sol.t_events[0][0]), np.asarray(sol.y_events[0][0])


def land(
    omega0: ArrayLike,
    launch_speed: float,
    start_sign: float,
    *,
    drop_height: float,
    g: float,
    radius: float,
    thickness: float,
    mass: float,
    i1: float,
    i3: float,
    restitution: float,
    friction: float,
    drag_coefficient: float,
    spin_damping: float,
    air_density: float,
    max_bounces: int = -1,
    rest_speed: float | None = None,
) -> tuple[int, int, float, float, int]:
    """One toss with drag onto a table: (face, bounces, first contact, settle time, status).

    The same rules as :func:`coinflight.core.bounce.land` (impact law, settling, rocking,
    status codes); only the flights between impacts are integrated numerically.
    ``max_bounces`` < 0 means until the coin settles.
    """
    from scipy.integrate import solve_ivp
    from scipy.spatial.transform import Rotation

    from coinflight.core import bounce, impact

    rest = bounce.REST_SPEED if rest_speed is None else rest_speed
    hh = 0.5 * thickness
    model = DragModel(mass, radius, (i1, i1, i3), g, drag_coefficient, spin_damping, air_density)
    f = rhs(model)
    rho = math.hypot(radius, hh)
    edge_sine = hh / rho
    barrier = mass * g * rho

    def gap(_t: float, y: FloatArray) -> float:
        n = normal(y[9:13])
        return float(y[2] + drop_height - impact.lowest_depth(float(n[2]), radius, hh))

    gap.terminal = True  # type: ignore[attr-defined]
    gap.direction = -1  # type: ignore[attr-defined]
    y = initial_state(np.asarray(omega0, dtype=float), launch_speed, start_sign)
    # As in the drag-free kernel, look for the contact from the apex on.
    t = 0.0
    apex = solve_ivp(f, (0.0, launch_speed / g), y, method="DOP853", rtol=RTOL, atol=ATOL)
    y = apex.y[:, -1]
    t = float(apex.t[-1])
    bounces = 0
    first = -1.0
    for _ in range(bounce.MAX_IMPACTS):
        # Steps of at most 1/64 of a turn: a rim that dips below the surface and out again
        # between two solver steps would be missed (no sign change to locate); such dips last
        # a small fraction of a turn (one of 0.5 ms at ~200 rad/s in test_bounce).
        spin = float(np.linalg.norm(y[6:9]))
        turn = 0.03125 * math.pi / spin if spin > 0.0 else math.inf
        sol = solve_ivp(
            f, (t, t + 60.0), y, method="DOP853", events=gap, rtol=RTOL, atol=ATOL, max_step=turn
        )
        if sol.t_events[0].size == 0:  # pragma: no cover
            break
        t = float(sol.t_events[0][0])
        y = np.array(sol.y_events[0][0])
        q = y[9:13] / np.linalg.norm(y[9:13])
        rot = Rotation.from_quat(q)
        nx, ny, nz = (float(c) for c in rot.apply([0.0, 0.0, 1.0]))
        n = (nx, ny, nz)
        if first < 0.0:
            first = t
        if 0 <= max_bounces <= bounces:
            return impact.resting_face(n[2], edge_sine), bounces, first, t, bounce.BOUNCE_LIMIT
        lm_body = np.array([i1, i1, i3]) * y[6:9]
        lx, ly, lz = (float(c) for c in rot.apply(lm_body))
        lm = (lx, ly, lz)
        v = (float(y[3]), float(y[4]), float(y[5]))
        v, lm, rebound = impact.impact(v, lm, n, radius, hh, mass, i1, i3, restitution, friction)
        z = impact.lowest_depth(n[2], radius, hh)
        omega = impact.angular_velocity(lm, n, i1, i3)
        if bounce.tumbling_energy(v, lm, n, mass, i1, g, z) < barrier:
            return impact.resting_face(n[2], edge_sine), bounces, first, t, bounce.SETTLED_ENERGY
        if rebound < rest:
            if restitution == 0.0:
                face = impact.resting_face(n[2], edge_sine)
                return face, bounces, first, t, bounce.SETTLED_DEAD
            face = bounce.rock(n, omega, radius, hh, mass, i1, g)
            return face, bounces, first, t, bounce.SETTLED_ROCKING
        bounces += 1
        y = y.copy()
        y[3:6] = v
        y[6:9] = rot.inv().apply(np.asarray(omega))
        y[9:13] = q
        # Leave the surface before looking for the next contact (as in the drag-free kernel).
        accel = g + 2.0 * float(np.dot(omega, omega)) * rho
        dt = rebound / accel
        for _ in range(60):
            step = solve_ivp(f, (t, t + dt), y, method="DOP853", rtol=RTOL, atol=ATOL)
            if gap(0.0, step.y[:, -1]) > 0.0:
                break
            dt *= 0.5
        y = step.y[:, -1]
        t = float(step.t[-1])
    n_z = float(normal(y[9:13])[2])
    return impact.resting_face(n_z, edge_sine), bounces, first, t, bounce.UNSETTLED
