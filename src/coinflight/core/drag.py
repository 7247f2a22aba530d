"""Flight through air: quadratic drag on the centre of mass and damping of the spin (SciPy).

One toss per call, integrated by ``scipy.integrate.solve_ivp`` (DOP853; damping no faster
than :data:`MAX_RATE`, never more than :data:`MAX_EVALUATIONS` evaluations a toss) on the
13-dimensional state (position, velocity, body angular velocity ω, scalar-last quaternion q
body → lab):

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
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from coinflight.core.ballistics import flight_time
from coinflight.core.contact import Contact
from coinflight.core.numerical import euler_rhs, quaternion_rate
from coinflight.core.outcome import Status

FloatArray = NDArray[np.float64]
RTOL = 1e-12
ATOL = 1e-13
MAX_EVALUATIONS = 50_000
"""Most evaluations of the equations of motion for one toss (every flight and bounce of it):
about 5 s at the ~10⁴ a second measured on the 2-core machine. A toss at 80 rad/s takes
1,000-10,000; beyond the limit the toss ends in a ValueError instead of running on."""
EVALUATIONS_PER_SECOND = 1e4
MAX_RATE = 1e4
"""Fastest relaxation rate accepted, 1/s: the spin damping K/I (a tiny coin's spin dies in
attoseconds) or the drag 2 c |v| (a light, wide coin). DOP853, like any explicit method, is
stable only for steps below ~3/rate: at 1e4 1/s a second of flight is ~4e4 evaluations. Stiff
solvers (BDF, LSODA) were tried: they failed ('step size less than spacing') on the table."""


class IntegrationLimit(ValueError):
    """A toss with drag needed more than :data:`MAX_EVALUATIONS` evaluations."""


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


def stiffness(model: DragModel, launch_speed: float) -> float:
    """Fastest relaxation rate of the flight, 1/s: max(k/I1, k/I3, 2 c v) with c the drag factor
    and v the larger of the launch speed and the terminal speed sqrt(g/c)."""
    rates = [model.spin_damping / i for i in model.moments]
    c = model.drag_factor
    if c > 0:
        rates.append(2.0 * c * max(abs(float(launch_speed)), math.sqrt(model.g / c)))
    return max(rates)


def check_stiffness(model: DragModel, launch_speed: float) -> None:
    """ValueError unless the flight relaxes no faster than :data:`MAX_RATE` (before any work).

    Beyond it the spin damping stops the spin (or the drag the fall) faster than DOP853 can
    follow within :data:`MAX_EVALUATIONS` (its steps stay below ~3/rate); so short a time
    constant is no coin in air (a 1 mm coin with K = 1e-3 N m s would stop in a nanosecond).
    """
    rate = stiffness(model, launch_speed)
    if rate <= MAX_RATE:
        return
    i_min = min(model.moments)
    if model.spin_damping / i_min >= rate:
        raise ValueError(
            f"spin damping must be at most {i_min * MAX_RATE:.3g} N m s for this coin (it would "
            f"stop the spin in {i_min / model.spin_damping:.3g} s, faster than the "
            f"{1.0 / MAX_RATE:g} s the integrator can follow), got {model.spin_damping:g}"
        )
    raise ValueError(
        f"air drag C_d = {model.drag_coefficient:g} on this coin (radius {model.radius:g} m, mass "
        f"{model.mass:g} kg) would stop its fall in {1.0 / rate:.3g} s, faster than the "
        f"{1.0 / MAX_RATE:g} s the integrator can follow; use a smaller C_d or a heavier coin"
    )


def bounded(
    f: Callable[[float, FloatArray], FloatArray], what: str
) -> Callable[[float, FloatArray], FloatArray]:
    """``f`` that raises :class:`IntegrationLimit` at its :data:`MAX_EVALUATIONS` + 1-th call.

    One bounded function serves every integration of a toss, so the bound is per toss.
    """
    calls = 0

    def g(t: float, y: FloatArray) -> FloatArray:
        nonlocal calls
        calls += 1
        if calls > MAX_EVALUATIONS:
            raise IntegrationLimit(
                f"{what} needed more than {MAX_EVALUATIONS:,} evaluations of its equations of "
                f"motion (about {MAX_EVALUATIONS / EVALUATIONS_PER_SECOND:.0f} s) and was "
                "stopped; use a smaller spin, flight time, drag or spin damping"
            )
        return f(t, y)

    return g


def solve(
    f: Callable[[float, FloatArray], FloatArray],
    span: tuple[float, float],
    y0: FloatArray,
    what: str,
    **options: object,
) -> Any:
    """``solve_ivp`` at :data:`RTOL`/:data:`ATOL`; a ValueError naming the toss if it fails."""
    from scipy.integrate import solve_ivp

    sol = solve_ivp(f, span, y0, method="DOP853", rtol=RTOL, atol=ATOL, **options)
    if sol.status < 0:  # pragma: no cover - bounded rates and evaluations
        raise ValueError(f"{what} could not be integrated (DOP853: {sol.message})")
    return sol


def describe(model: DragModel, omega0: ArrayLike, launch_speed: float) -> str:
    """``'the toss with air drag (|ω0| = 80 rad/s, v0 = 3.43 m/s, C_d = 1.17, K = 0 N m s)'``."""
    w = float(np.linalg.norm(np.asarray(omega0, dtype=float)))
    return (
        f"the toss with air drag (|ω0| = {w:.3g} rad/s, v0 = {float(launch_speed):.3g} m/s, "
        f"C_d = {model.drag_coefficient:g}, K = {model.spin_damping:g} N m s)"
    )


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
    t_eval = np.atleast_1d(np.asarray(t_eval, dtype=float))
    y0 = initial_state(np.asarray(omega0, dtype=float), launch_speed, start_sign)
    t_end = max(float(t_eval[-1]), 1e-12)
    what = describe(model, omega0, launch_speed)
    check_stiffness(model, launch_speed)
    sol: Any = solve(bounded(rhs(model), what), (0.0, t_end), y0, what, t_eval=t_eval)
    return np.asarray(sol.y.T)


def catch(
    model: DragModel, omega0: ArrayLike, launch_speed: float, start_sign: float = 1.0
) -> tuple[float, FloatArray]:
    """Time and state when the centre of mass comes back down to launch height (a catch)."""

    def back_down(t: float, y: FloatArray) -> float:
        return float(y[2]) if t > 0 else 1.0

    back_down.terminal = True  # type: ignore[attr-defined]
    back_down.direction = -1  # type: ignore[attr-defined]
    y0 = initial_state(np.asarray(omega0, dtype=float), launch_speed, start_sign)
    t_max = float(flight_time(launch_speed, model.g)) * 1.5 + 1.0
    what = describe(model, omega0, launch_speed)
    check_stiffness(model, launch_speed)
    sol: Any = solve(bounded(rhs(model), what), (0.0, t_max), y0, what, events=back_down)
    if sol.t_events[0].size == 0:  # pragma: no cover - gravity always brings it down
        raise ValueError(f"{what} did not come back down within {t_max:.3g} s")
    return float(sol.t_events[0][0]), np.asarray(sol.y_events[0][0])


def land(
    omega0: ArrayLike,
    launch_speed: float,
    start_sign: float,
    *,
    drag_coefficient: float,
    spin_damping: float,
    air_density: float,
    max_bounces: int = -1,
    rest_speed: float | None = None,
    **contact: float,
) -> tuple[int, int, float, float, int]:
    """One toss with drag onto a table: (face, bounces, first contact, settle time, status).

    ``contact`` are the keywords of :meth:`coinflight.core.contact.Contact.build` but
    ``rest_speed`` (``drop_height``, ``g``, ``radius``, ``thickness``, ``mass``, ``i1``, ``i3``,
    ``restitution``, ``friction``), gathered into a :class:`~coinflight.core.contact.Contact`
    with the drag into a :class:`DragModel`, then :func:`land_contact`. ``rest_speed`` defaults
    to :data:`coinflight.core.bounce.REST_SPEED`.
    """
    from coinflight.core import bounce

    rest = bounce.REST_SPEED if rest_speed is None else rest_speed
    c = Contact.build(rest_speed=rest, **contact)
    moments = (c.i1, c.i1, c.i3)
    model = DragModel(c.mass, c.radius, moments, c.g, drag_coefficient, spin_damping, air_density)
    return land_contact(omega0, launch_speed, start_sign, c, model, max_bounces)


def _next_contact(
    f: Any, t: float, y: FloatArray, what: str, gap: Callable[[float, FloatArray], float]
) -> tuple[float, FloatArray]:
    """Time and state when the coin next touches the table (``gap`` reaches 0 going down).

    Steps of at most 1/64 of a turn: a rim that dips below the surface and out again between two
    solver steps would be missed (no sign change to locate); such dips last a small fraction of
    a turn (one of 0.5 ms at ~200 rad/s in test_bounce).
    """
    spin = float(np.linalg.norm(y[6:9]))
    turn = 0.03125 * math.pi / spin if spin > 0.0 else math.inf
    sol: Any = solve(f, (t, t + 60.0), y, what, events=gap, max_step=turn)
    if sol.t_events[0].size == 0:  # pragma: no cover - a minute of falling meets the table
        raise ValueError(f"{what} did not reach the table within 60 s of t = {t:.3g} s")
    return float(sol.t_events[0][0]), np.array(sol.y_events[0][0])


def _settles(
    n: tuple[float, float, float],
    v: tuple[float, float, float],
    lm: tuple[float, float, float],
    omega: tuple[float, float, float],
    rebound: float,
    contact: Contact,
) -> tuple[int, Status] | None:
    """(face, status) if the coin settles after this impact, else None (the rules of
    :func:`coinflight.core.bounce.land`: below the barrier, dead, or rocking to rest)."""
    from coinflight.core import bounce, impact

    radius, hh, mass, i1, g = (
        contact.radius,
        contact.half_thickness,
        contact.mass,
        contact.i1,
        contact.g,
    )
    z = impact.lowest_depth(n[2], radius, hh)
    if bounce.tumbling_energy(v, lm, n, mass, i1, g, z) < contact.barrier:
        return impact.resting_face(n[2], contact.edge_sine), Status.SETTLED_ENERGY
    if rebound >= contact.rest_speed:
        return None
    if contact.restitution == 0.0:
        return impact.resting_face(n[2], contact.edge_sine), Status.SETTLED_DEAD
    return bounce.rock(n, omega, radius, hh, mass, i1, g), Status.SETTLED_ROCKING


def _lift_off(
    f: Any, t: float, y: FloatArray, what: str, gap: Callable[[float, FloatArray], float], dt: float
) -> tuple[float, FloatArray]:
    """Time and state a little after an impact, once the coin is off the surface: the first of
    dt, dt/2, dt/4, … after which ``gap`` is positive."""
    for _ in range(60):
        step: Any = solve(f, (t, t + dt), y, what)
        if gap(0.0, step.y[:, -1]) > 0.0:
            break
        dt *= 0.5
    return float(step.t[-1]), step.y[:, -1]


def land_contact(
    omega0: ArrayLike,
    launch_speed: float,
    start_sign: float,
    contact: Contact,
    model: DragModel,
    max_bounces: int = -1,
) -> tuple[int, int, float, float, int]:
    """One toss with drag onto a table: (face, bounces, first contact, settle time, status).

    The same rules as :func:`coinflight.core.bounce.land` (impact law, settling, rocking,
    status codes :class:`~coinflight.core.outcome.Status`); only the flights between impacts are
    integrated numerically. ``model`` gives the flight (its coin and g those of ``contact``);
    ``max_bounces`` < 0 means until the coin settles.
    """
    from scipy.spatial.transform import Rotation

    from coinflight.core import bounce, impact

    radius, hh, mass = contact.radius, contact.half_thickness, contact.mass
    i1, i3, g = contact.i1, contact.i3, contact.g
    restitution, friction = contact.restitution, contact.friction
    drop_height, rho, edge_sine = contact.drop_height, contact.reach, contact.edge_sine
    what = describe(model, omega0, launch_speed)
    check_stiffness(model, launch_speed)
    f = bounded(rhs(model), what)

    def gap(_t: float, y: FloatArray) -> float:
        n = normal(y[9:13])
        return float(y[2] + drop_height - impact.lowest_depth(float(n[2]), radius, hh))

    gap.terminal = True  # type: ignore[attr-defined]
    gap.direction = -1  # type: ignore[attr-defined]
    y = initial_state(np.asarray(omega0, dtype=float), launch_speed, start_sign)
    # As in the drag-free kernel, look for the contact from the apex on.
    t = 0.0
    apex: Any = solve(f, (0.0, launch_speed / g), y, what)
    y = apex.y[:, -1]
    t = float(apex.t[-1])
    bounces = 0
    first = -1.0
    for _ in range(bounce.MAX_IMPACTS):
        t, y = _next_contact(f, t, y, what, gap)
        q = y[9:13] / np.linalg.norm(y[9:13])
        rot = Rotation.from_quat(q)
        nx, ny, nz = (float(c) for c in rot.apply([0.0, 0.0, 1.0]))
        n = (nx, ny, nz)
        if first < 0.0:
            first = t
        if 0 <= max_bounces <= bounces:
            return impact.resting_face(n[2], edge_sine), bounces, first, t, Status.BOUNCE_LIMIT
        lm_body = np.array([i1, i1, i3]) * y[6:9]
        lx, ly, lz = (float(c) for c in rot.apply(lm_body))
        lm = (lx, ly, lz)
        v = (float(y[3]), float(y[4]), float(y[5]))
        v, lm, rebound = impact.impact(v, lm, n, radius, hh, mass, i1, i3, restitution, friction)
        omega = impact.angular_velocity(lm, n, i1, i3)
        settled = _settles(n, v, lm, omega, rebound, contact)
        if settled is not None:
            return settled[0], bounces, first, t, settled[1]
        bounces += 1
        y = y.copy()
        y[3:6] = v
        y[6:9] = rot.inv().apply(np.asarray(omega))
        y[9:13] = q
        # Leave the surface before looking for the next contact (as in the drag-free kernel).
        t, y = _lift_off(
            f, t, y, what, gap, rebound / (g + 2.0 * float(np.dot(omega, omega)) * rho)
        )
    n_z = float(normal(y[9:13])[2])
    return impact.resting_face(n_z, edge_sine), bounces, first, t, Status.UNSETTLED
