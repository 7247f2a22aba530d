"""A coin hitting a horizontal surface: contact geometry and the impact impulse.

Scalar kernels on 3-tuples of floats (lab frame, SI units, the surface normal is +Z), written
so that numba compiles the same functions for the event-driven simulation of
:mod:`coinflight.core.bounce`. The coin is a uniform cylinder of radius r and half-thickness
hh = h/2 whose state is its heads normal n, the velocity v of its centre of mass and its
angular momentum L about the centre of mass (all lab frame). Its rim's corners may be rounded
with a radius a (0 ≤ a ≤ min(h/2, r)): the coin is then the cylinder (r − a, h/2 − a) swept
by a ball of radius a; :func:`lowest_depth`,
:func:`contact_point` take a (0 by default: the sharp cylinder, bit for bit) and
:func:`impact` reads it, with the coin, e, μ and the contact duration, from the landing's
contact record (:class:`coinflight.core.contact.Contact`).

The impact law
--------------
A rigid body hitting a plane at one point with Coulomb friction, solved over the impact in
impulse space (Stronge, *Rigid body collisions with friction*, Proc. R. Soc. Lond. A 431:169,
1990; Stronge, *Impact Mechanics*, 2000, ch. 4-5; the 3-D slip flow: Batlle, *The sliding
velocity flow of rough collisions in multibody systems*, J. Appl. Mech. 63:804, 1996; Bhatt &
Koechling, *Three-dimensional frictional rigid-body impact*, J. Appl. Mech. 62:893, 1995).
The configuration does not change during the impact, so the velocity u of the contact point is
linear in the impulse P applied there, u = u0 + K P, with the collision matrix
K = 1/m + [r×]ᵀ I⁻¹ [r×] (symmetric, positive definite; Stronge 2000, eq 5.7). The normal
impulse p = P_z grows monotonically and is the independent variable:

* sliding (slip u_t = (u_x, u_y) ≠ 0): dP/dp = (−μ û_t, 1), so du/dp = K (−μ û_t + ẑ), with
  û_t the current slip direction, which turns as the impact proceeds (the 3-D "swerve");
* sticking (u_t = 0): the tangential impulse that keeps the contact stuck grows at the rate
  r = −K_tt⁻¹ K_tz; the contact stays stuck, for the rest of the impact (K is constant), if
  |r| ≤ μ; otherwise it slides again along the one direction û that keeps its slip on a ray,
  (λ I + μ K_tt) û = K_tz with λ > 0 (Batlle 1996);
* compression ends when u_z = 0, after the normal work W_c = ∫ u_z dp < 0; restitution then
  runs until the normal work done in it equals −e² W_c: Stronge's energetic coefficient of
  restitution e (Stronge 1990), which, unlike Newton's, never makes energy when friction acts.
  With e = 0 the impact ends at the end of compression: the contact point leaves with
  u_z = 0. If the slip turns so that the contact point comes back to the surface during
  restitution (u_z = 0 again), the impact ends there.

Simultaneous impacts
--------------------
A coin that meets the table nearly flat (or nearly upright) strikes it with a second rim
point within the duration of the first contact (:data:`CONTACT_DURATION`): the two are one
impact, not two in sequence, which would set a flat coin spinning (the falling-rod paradox;
Stoianovici & Hurmuzlu 1996). The impulse then acts at the centre of the normal impulses of the
two-point Newton impact and the impact there is Stronge's, weighted continuously by how far the
two contacts overlap in time (:func:`simultaneous_point`): a coin dropped flat bounces flat, no
impact jumps with the tilt, and, being a single Stronge impact at a point of the coin (then, if
the lowest point is left approaching, one more at it), it never makes energy.

Integration. Frictionless impacts, sticking and sliding along a fixed direction (every planar
impact) are linear in p and are solved in closed form, segment by segment to the next event. A
slide whose direction turns is integrated with classical Runge-Kutta (RK4) steps in p: a step
ends before the next normal event as u_z would reach it at its present rate, lets the slip
direction turn by at most TURN_STEP (more, up to a radian, for a slip much slower than the
impact speed |u0|, whose errors are in proportion) and, while the slip shrinks, changes it by at
most STOP_FRACTION of itself (so it cannot reverse within a step). A slip below
SLIP_TOLERANCE |u0| is ended by one straight segment in impulse space with friction on the cone
in a fixed direction that brings it exactly to rest, if the cone can hold the stick; otherwise
the contact takes its ray, carrying along that remaining slip. An impact takes at most
MAX_STEPS segments; a slide still going by then sticks or takes its ray. Against the same law
integrated 20 times finer (tests/test_impact.py) the impulse agrees to ~1e-4 (median) and
~1e-2 in the worst percent of random impacts, those whose slip swerves close to rest.

Exactness by construction. Between steps the impulse follows a straight segment (a chord) in
impulse space, on which u is linear, so the normal work (trapezoid rule), the end of
compression and the end of restitution are exact on that path, and so is the kinetic energy,
T0 + ∫ u·dP. Friction opposes the slip and the normal work totals (1 − e²) W_c ≤ 0, so the
kinetic energy does not grow; as a guard against the O(SLIP_TOLERANCE) approximations above,
restitution also ends if the kinetic energy gets back to its value before the impact. Every
increment of tangential impulse is at most μ times its normal increment, so |P_t| ≤ μ P_z. The
impulse acts at the contact point, so the angular momentum about that point is conserved; with
μ = 0 it is vertical, so the horizontal momentum and L_z are unchanged, and so is L·n (the
contact point, n and ẑ lie in one plane, so the torque r × ẑ is perpendicular to n); with e = 1
and μ = 0 the kinetic energy is conserved.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from coinflight.core._jit import njit

if TYPE_CHECKING:
    from coinflight.core.contact import Contact

Vec = tuple[float, float, float]
_Matrix = tuple[float, float, float, float, float, float]
"""The collision matrix K as (K_xx, K_xy, K_xz, K_yy, K_yz, K_zz), 1/kg."""
TURN_STEP = 0.2
"""A turning slide is integrated in RK4 steps over which its direction turns by at most this
angle, rad (up to a radian for a slip much slower than |u0|)."""
MAX_STEPS = 400
"""Steps per impact at most (a slide that has not stopped by then sticks, or takes its ray)."""
STOP_FRACTION = 0.5
"""An RK4 step changes the slip by at most this fraction of its size."""
SLIP_TOLERANCE = 1e-3
"""Below this times the impact speed |u0|, a slip is stopped by one straight segment (or, if the
cone cannot hold a stick, the contact takes its ray)."""
ROUNDING = 1e-14
"""Slip below this times |u0| is rounding error: the contact sticks."""
END_TOLERANCE = 1e-14
"""Compression ends at u_z ≥ −END_TOLERANCE |u0|; restitution within this fraction of W_c."""
CONTACT_DURATION = 1e-4
"""t_c, how long one impact of the coin's rim on a table lasts, s: a physical parameter, not a
step size. Hertz's contact time, t_c = 2.87 (m*² / (R E*² v))^(1/5) (Johnson, *Contact
Mechanics*, 1985, §11.4), for a coin's rim (corner radius R ≈ 0.3 mm, effective mass m* ≈ m/5
at the rim of a disc, m = 2.3-11 g) striking at v ≈ 1-3 m/s a table whose surface modulus
E* is 0.5-10 GPa (wood across and along the grain) gives 5e-5 to 3e-4 s; a stone or glass top
(E* ≈ 50-70 GPa) 2e-5 to 4e-5 s. Two contacts of the coin that would meet the table less than
t_c apart overlap in time: one simultaneous impact (:func:`simultaneous_point`). Not measured
for coins; it decides only landings that meet the table within about
v t_c / 2r (≈ 0.7° for a nickel at 2.6 m/s) of flat or of upright. The default of a table's
``contact_duration`` (:class:`coinflight.model.surface.Surface`, 1 μs to 10 ms) and of the
contact record's (:class:`coinflight.core.contact.Contact`), from which every landing's impacts
take it, so that an answer is quoted as a band over it, as over the restitution and friction."""


@njit(cache=True)
def dot(a: Vec, b: Vec) -> float:
    """a · b."""
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


@njit(cache=True)
def cross(a: Vec, b: Vec) -> Vec:
    """a × b."""
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


@njit(cache=True)
def lowest_depth(nz: float, radius: float, half_thickness: float, corner: float = 0.0) -> float:
    """Depth of the coin's lowest point below its centre of mass, m.

    Notes
    -----
    The support function of a cylinder along −Z: r sqrt(1 − n_z²) + (h/2)|n_z| (the lowest
    point is on the rim of the lower face; a face when n_z = ±1, the edge when n_z = 0).
    Yong & Mahadevan 2011, §III; REFERENCES §5.

    With rounded rim corners of radius a = ``corner`` (0 ≤ a ≤ min(h/2, r)), the coin is the
    cylinder (r − a, h/2 − a) swept by a ball of radius a; the support function of a Minkowski
    sum is the sum of the support functions, so the depth is
    (r − a) sqrt(1 − n_z²) + (h/2 − a)|n_z| + a. With a = 0 it is the sharp cylinder's, to the
    last bit (subtracting and adding 0.0 is exact).
    """
    s2 = 1.0 - nz * nz
    return (
        (radius - corner) * math.sqrt(s2 if s2 > 0.0 else 0.0)
        + (half_thickness - corner) * abs(nz)
        + corner
    )


@njit(cache=True)
def contact_point(n: Vec, radius: float, half_thickness: float, corner: float = 0.0) -> Vec:
    """Lowest point of the coin relative to its centre of mass, lab frame, m.

    r ŵ − sign(n_z) (h/2) n, where ŵ is the unit vector of the coin's plane pointing most
    downwards, (−Z + n_z n)/sqrt(1 − n_z²). A coin lying flat touches with the centre of its
    lower face.

    With rounded rim corners of radius a = ``corner``, the lowest point of the cylinder
    (r − a, h/2 − a) swept by a ball of radius a: the core cylinder's lowest rim point,
    (r − a) ŵ − sign(n_z)(h/2 − a) n, moved down by a, − a Z (the ball's lowest point).
    Exactly the sharp coin's point for a = 0.
    """
    nz = n[2]
    s2 = 1.0 - nz * nz
    sign = 1.0 if nz >= 0.0 else -1.0
    hh = half_thickness - corner
    if s2 <= 1e-24:
        return (
            -sign * hh * n[0],
            -sign * hh * n[1],
            -sign * hh * n[2] - corner,
        )
    k = (radius - corner) / math.sqrt(s2)
    return (
        k * nz * n[0] - sign * hh * n[0],
        k * nz * n[1] - sign * hh * n[1],
        k * (nz * nz - 1.0) - sign * hh * n[2] - corner,
    )


@njit(cache=True)
def inverse_inertia_apply(x: Vec, n: Vec, i1: float, i3: float) -> Vec:
    """I⁻¹ x for the coin's inertia tensor in the lab, I⁻¹ = 1/I1 + (1/I3 − 1/I1) n nᵀ."""
    c = (1.0 / i3 - 1.0 / i1) * dot(n, x)
    return (x[0] / i1 + c * n[0], x[1] / i1 + c * n[1], x[2] / i1 + c * n[2])


@njit(cache=True)
def angular_velocity(angular_momentum: Vec, n: Vec, i1: float, i3: float) -> Vec:
    """ω = I⁻¹ L in the lab frame, rad/s (symmetric top: L/I1 + (1/I3 − 1/I1)(L·n) n)."""
    return inverse_inertia_apply(angular_momentum, n, i1, i3)


@njit(cache=True)
def contact_velocity(v: Vec, omega: Vec, rc: Vec) -> Vec:
    """Velocity of the material point at rc: u = v + ω × rc, m/s."""
    w = cross(omega, rc)
    return (v[0] + w[0], v[1] + w[1], v[2] + w[2])


@njit(cache=True)
def kinetic_energy(
    v: Vec, angular_momentum: Vec, n: Vec, mass: float, i1: float, i3: float
) -> float:
    """½ m |v|² + ½ L · I⁻¹ L, J."""
    omega = angular_velocity(angular_momentum, n, i1, i3)
    return 0.5 * mass * dot(v, v) + 0.5 * dot(angular_momentum, omega)


@njit(cache=True)
def _coupling(rc: Vec, a: Vec, b: Vec, n: Vec, mass: float, i1: float, i3: float) -> float:
    """a · K b for the collision matrix K b = b/m + (I⁻¹(rc × b)) × rc (Stronge 2000, eq 5.7)."""
    return dot(a, b) / mass + dot(cross(rc, a), inverse_inertia_apply(cross(rc, b), n, i1, i3))


@njit(cache=True)
def _apply(p: Vec, v: Vec, angular_momentum: Vec, rc: Vec, mass: float) -> tuple[Vec, Vec]:
    """Velocity and angular momentum after the impulse p at rc."""
    t = cross(rc, p)
    return (
        (v[0] + p[0] / mass, v[1] + p[1] / mass, v[2] + p[2] / mass),
        (angular_momentum[0] + t[0], angular_momentum[1] + t[1], angular_momentum[2] + t[2]),
    )


@njit(cache=True, error_model="numpy")
def _friction_rate(ux: float, uy: float, friction: float) -> tuple[float, float]:
    """dP_t/dp of a sliding contact: −μ û_t, opposite to the slip (Coulomb)."""
    k = -friction / math.sqrt(ux * ux + uy * uy)
    return k * ux, k * uy


@njit(cache=True, error_model="numpy")
def _ray_direction(
    kxx: float, kxy: float, kyy: float, bx: float, by: float, friction: float
) -> tuple[float, float]:
    """Direction û in which a stuck contact that the cone cannot hold starts to slide.

    The slip stays on the ray s û when du_t/dp = −μ K_tt û + b = λ û with λ > 0, i.e.
    û = (λ I + μ K_tt)⁻¹ b with |û| = 1 (Batlle 1996). |(λ I + μ K_tt)⁻¹ b| is convex and
    decreasing in λ ≥ 0, above 1 at λ = 0 (|K_tt⁻¹ b| > μ: the cone cannot hold the stick), so
    Newton's iteration from λ = 0 climbs monotonically to the one root.
    """
    # |M⁻¹ b| ≥ |b| / (λ + μ λmax(K_tt)): the root is not left of |b| − μ λmax.
    lam_max = 0.5 * (kxx + kyy + math.sqrt((kxx - kyy) ** 2 + 4.0 * kxy * kxy))
    lam = max(0.0, math.sqrt(bx * bx + by * by) - friction * lam_max)
    x0 = 0.0
    x1 = 0.0
    for _ in range(100):
        m00 = lam + friction * kxx
        m01 = friction * kxy
        m11 = lam + friction * kyy
        det = m00 * m11 - m01 * m01
        x0 = (m11 * bx - m01 * by) / det
        x1 = (m00 * by - m01 * bx) / det
        size = math.sqrt(x0 * x0 + x1 * x1)
        # d|x|/dλ = −x·M⁻¹x / |x|.
        y0 = (m11 * x0 - m01 * x1) / det
        y1 = (m00 * x1 - m01 * x0) / det
        step = (size - 1.0) * size / (x0 * y0 + x1 * y1)
        lam += step
        if not step > 1e-15 * lam:
            break
    size = math.sqrt(x0 * x0 + x1 * x1)
    return x0 / size, x1 / size


@njit(cache=True, error_model="numpy")
def contact_impulse(
    u0: Vec,
    k: tuple[float, float, float, float, float, float],
    restitution: float,
    friction: float,
    turn_step: float,
    slip_tolerance: float,
    max_steps: int,
) -> tuple[Vec, int]:
    """Impulse P at the contact over a whole impact (see the module notes for the law).

    Parameters
    ----------
    u0 : tuple of 3 floats
        Velocity of the contact point before the impact, m/s (u0_z < 0: approaching).
    k : tuple of 6 floats
        Collision matrix (K_xx, K_xy, K_xz, K_yy, K_yz, K_zz), 1/kg.
    restitution, friction : float
        Stronge's energetic coefficient e in [0, 1] and Coulomb's μ ≥ 0 (the law's properties
        tested for μ up to 3, :data:`coinflight.model.surface.MAX_FRICTION`).
    turn_step : float
        Largest turn of the slip direction in one RK4 step, rad (:data:`TURN_STEP`; a parameter
        for tests).
    slip_tolerance : float
        :data:`SLIP_TOLERANCE` (a parameter for tests).
    max_steps : int
        Segments at most (:data:`MAX_STEPS`; a parameter for tests).

    Returns
    -------
    impulse : tuple of 3 floats
        P, N s.
    steps : int
        Integration segments used (≤ :data:`MAX_STEPS`).

    Notes
    -----
    Each step is a straight segment (sticking, a ray, the stop of a small slip:
    :func:`_stop_segment`, a nearly straight slide) or an RK4 step of a turning slide
    (:func:`_slide_step`), cut at the end of compression or restitution (:func:`_cut`).
    """
    if u0[2] >= 0.0:
        return (0.0, 0.0, 0.0), 0
    if friction == 0.0:
        return (0.0, 0.0, -(1.0 + restitution) * u0[2] / k[5]), 1
    scale = math.sqrt(u0[0] * u0[0] + u0[1] * u0[1] + u0[2] * u0[2])
    z_tol = END_TOLERANCE * scale
    slip_tol = slip_tolerance * scale
    rx, ry, det = _stick_rate(k)
    holds = math.sqrt(rx * rx + ry * ry) <= friction  # the cone holds a stick for good
    p, px, py = 0.0, 0.0, 0.0  # the impulse so far
    w, energy = 0.0, 0.0  # normal work ∫ u_z dp and change of kinetic energy ∫ u · dP
    w_tol, target = 0.0, 0.0  # the normal work done by the end of restitution
    compression, linear = True, False
    qx, qy = 0.0, 0.0  # sticking or sliding on a ray (linear): dP_t/dp to the end
    steps = 0
    for steps in range(1, max_steps + 1):
        ux, uy, uz = _velocity_at(u0, k, px, py, p)
        if compression and uz >= -z_tol:
            compression = False
            target, w_tol = (1.0 - restitution * restitution) * w, -END_TOLERANCE * w
        if not compression and (restitution == 0.0 or w >= target - w_tol):
            break
        s = math.sqrt(ux * ux + uy * uy)
        seg = True
        small = s <= slip_tol or steps >= max_steps - 6  # late: then finish in closed form
        if not linear and small:
            linear, qx, qy = _settle(holds, s <= ROUNDING * scale, rx, ry, k, friction)
        if not linear and small:
            stops, h, fx, fy = _stop_segment(ux, uy, k, det, rx, ry, friction)
            if not stops:
                linear = True
                qx, qy = rx, ry
        elif not linear:
            fx, fy = _friction_rate(ux, uy, friction)
            h, seg = _slide_step(
                ux, uy, uz, s, fx, fy, k, compression, target - w, turn_step, scale, slip_tol
            )
        if linear:
            fx, fy = qx, qy
            h = _linear_event(compression, uz, _normal_rate(k, fx, fy), target - w)
        # Ends if the slip has turned the contact point back onto the surface; h = ∞ cannot
        # happen for a positive definite K (a guard: never loop forever).
        if (not compression and uz <= 0.0 and _normal_rate(k, fx, fy) <= 0.0) or not h < math.inf:
            break
        nx, ny = (px + fx * h, py + fy * h) if seg else _rk4(u0, k, p, px, py, h, friction)
        while not seg and _turns_back(u0, k, nx, ny, p + h, ux, uy):
            h *= 0.25  # the slip would have turned by 90° or more in one step
            nx, ny = _rk4(u0, k, p, px, py, h, friction)
        uz_new = _velocity_at(u0, k, nx, ny, p + h)[2]
        theta, done = _cut(compression, uz, uz_new, h, target - w)
        theta, done, gain = _chord_energy(
            (ux, uy, uz), k, nx - px, ny - py, h, uz_new - uz, compression, energy, theta, done
        )
        energy += gain
        w += h * theta * (uz + 0.5 * theta * (uz_new - uz))
        px += theta * (nx - px)
        py += theta * (ny - py)
        p += theta * h
        if done:
            break
    return (px, py, p), steps


@njit(cache=True, error_model="numpy")
def _velocity_at(u0: Vec, k: _Matrix, px: float, py: float, p: float) -> Vec:
    """Velocity of the contact point after the impulse (px, py, p): u = u0 + K P (Stronge 2000,
    eq 5.7)."""
    kxx, kxy, kxz, kyy, kyz, kzz = k
    return (
        u0[0] + kxx * px + kxy * py + kxz * p,
        u0[1] + kxy * px + kyy * py + kyz * p,
        u0[2] + kxz * px + kyz * py + kzz * p,
    )


@njit(cache=True, error_model="numpy")
def _normal_rate(k: _Matrix, fx: float, fy: float) -> float:
    """du_z/dp while the tangential impulse grows at dP_t/dp = (fx, fy)."""
    return k[5] + k[2] * fx + k[4] * fy


@njit(cache=True, error_model="numpy")
def _stick_rate(k: _Matrix) -> tuple[float, float, float]:
    """(r_x, r_y, det K_tt): the rate r = −K_tt⁻¹ K_tz at which a stuck contact takes tangential
    impulse (the stick test is |r| ≤ μ; Stronge 2000, §5.2)."""
    kxx, kxy, kxz, kyy, kyz, _ = k
    det = kxx * kyy - kxy * kxy
    return -(kyy * kxz - kxy * kyz) / det, -(kxx * kyz - kxy * kxz) / det, det


@njit(cache=True, error_model="numpy")
def _settle(
    holds: bool, rounding: bool, rx: float, ry: float, k: _Matrix, friction: float
) -> tuple[bool, float, float]:
    """What a slip below SLIP_TOLERANCE (or a slide out of steps) does to the end of the impact:
    (whether it takes a constant rate dP_t/dp, that rate).

    If the cone cannot hold a stick (not ``holds``), it slides on, on the ray the cone lets it
    take (what is left of the slip is carried along); if the slip is rounding error, it sticks;
    otherwise it is stopped by one straight segment (:func:`_stop_segment`).
    """
    if not holds:
        dx, dy = _ray_direction(k[0], k[1], k[3], k[2], k[4], friction)
        qx, qy = _friction_rate(dx, dy, friction)
        return True, qx, qy
    if rounding:
        return True, rx, ry
    return False, 0.0, 0.0


@njit(cache=True, error_model="numpy")
def _stop_segment(
    ux: float, uy: float, k: _Matrix, det: float, rx: float, ry: float, friction: float
) -> tuple[bool, float, float, float]:
    """The one straight segment, friction on the cone in a fixed direction, that brings the
    slip u_t to 0: (whether there is one, its normal impulse h, dP_t/dp on it).

    With a = K_tt⁻¹ u_t it takes the normal impulse h of |a − r h| = μ h,
    (μ² − |r|²) h² + 2 (a·r) h − |a|² = 0, h > 0. There is none when |r| = μ to rounding: the
    cone holds the stick but cannot stop the slip.
    """
    kxx, kxy, _, kyy, _, _ = k
    ax = (kyy * ux - kxy * uy) / det
    ay = (kxx * uy - kxy * ux) / det
    a2 = ax * ax + ay * ay
    b1 = ax * rx + ay * ry
    c2 = friction * friction - rx * rx - ry * ry
    denominator = b1 + math.sqrt(max(b1 * b1 + c2 * a2, 0.0))
    if denominator > 0.0:
        h = 2.0 * a2 / denominator
        return True, h, rx - ax / h, ry - ay / h
    return False, 0.0, 0.0, 0.0


@njit(cache=True, error_model="numpy")
def _slide_step(
    ux: float,
    uy: float,
    uz: float,
    s: float,
    fx: float,
    fy: float,
    k: _Matrix,
    compression: bool,
    dw: float,
    turn_step: float,
    scale: float,
    slip_tol: float,
) -> tuple[float, bool]:
    """Normal impulse h of the next step of a slide (slip (ux, uy) of size s, friction rate
    (fx, fy)) and whether it is a straight segment (else an RK4 step)."""
    kxx, kxy, kxz, kyy, kyz, _ = k
    gx = kxx * fx + kxy * fy + kxz  # du_t/dp
    gy = kxy * fx + kyy * fy + kyz
    sigma = (ux * gx + uy * gy) / s  # d|u_t|/dp
    turn = abs(ux * gy - uy * gx) / s  # |u_t| |dû/dp|
    event = _linear_event(compression, uz, _normal_rate(k, fx, fy), dw)
    if turn == 0.0 or (sigma < 0.0 and s * turn <= slip_tol * -sigma):
        # Straight, or so nearly that what it misses of a stop is below SLIP_TOLERANCE: a
        # segment to the stop or to the next normal event.
        if sigma < 0.0 and s / -sigma < event:
            return s / -sigma, True
        return event, True
    # The slip changes by at most STOP_FRACTION of itself in one step (so it cannot reverse
    # within it), and its direction turns by at most turn_step: at the rate turn / |u_t(p)|
    # with |u_t| ≈ s + σ p, the turn over h is (turn/σ) ln(1 + σ h / s).
    h = STOP_FRACTION * s / math.sqrt(sigma * sigma + turn * turn)
    if sigma > 0.0:
        h = math.inf  # a growing slip cannot reverse: the turn sets the step
    # A slower slip matters less (what a step misses scales with it): it may turn further in
    # one step, up to a radian.
    angle = min(turn_step * math.sqrt(math.sqrt(scale / s)), 1.0)
    x = min(angle * sigma / turn, 30.0)
    limit = s / sigma * math.expm1(x) if sigma != 0.0 else angle * s / turn
    if limit < h:
        h = limit
    # Not past the next normal event as u_z would reach it at its present rate (so the chord
    # is cut close to its end).
    return (event if event < h else h), False


@njit(cache=True, error_model="numpy")
def _turns_back(u0: Vec, k: _Matrix, nx: float, ny: float, p: float, ux: float, uy: float) -> bool:
    """Whether the slip at the impulse (nx, ny, p) points against the slip (ux, uy)."""
    vx, vy, _ = _velocity_at(u0, k, nx, ny, p)
    return vx * ux + vy * uy <= 0.0


@njit(cache=True, error_model="numpy")
def _chord_energy(
    u: Vec,
    k: _Matrix,
    dpx: float,
    dpy: float,
    h: float,
    duz: float,
    compression: bool,
    energy: float,
    theta: float,
    done: bool,
) -> tuple[float, bool, float]:
    """The cut θ of the chord ΔP = (dpx, dpy, h) (and whether the impact ends there) kept or
    shortened so that the kinetic energy does not grow, and the change of kinetic energy to it.

    Along the chord E(θ) = E + θ u·ΔP + ½ θ² ΔP·K ΔP (duz = (K ΔP)_z, already known); energy is
    E − E(before the impact) at its start.
    """
    kxx, kxy, kxz, kyy, kyz, _ = k
    dux = kxx * dpx + kxy * dpy + kxz * h
    duy = kxy * dpx + kyy * dpy + kyz * h
    lin = u[0] * dpx + u[1] * dpy + u[2] * h
    quad = 0.5 * (dpx * dux + dpy * duy + h * duz)
    if not compression and energy + theta * lin + theta * theta * quad > 0.0:
        theta = _energy_guard(energy, lin, quad, theta)
        done = True
    return theta, done, theta * lin + theta * theta * quad


@njit(cache=True, error_model="numpy")
def _energy_guard(energy: float, lin: float, quad: float, theta: float) -> float:
    """The fraction of a restitution chord (≤ θ) where the kinetic energy is back to its value
    before the impact: it never grows. Only the O(SLIP_TOLERANCE) approximations at the end of a
    slide could make it; the impact then ends there."""
    denominator = lin + math.sqrt(max(lin * lin - 4.0 * quad * energy, 0.0))
    if denominator > 0.0:
        return min(theta, 2.0 * -energy / denominator)
    return min(theta, -lin / quad) if quad > 0.0 else 0.0


@njit(cache=True, error_model="numpy")
def _cut(compression: bool, uz: float, uz_new: float, h: float, dw: float) -> tuple[float, bool]:
    """Where on a straight segment of impulse (u_z linear from uz to uz_new over the normal
    impulse h) compression ends (u_z = 0), or restitution ends (the normal work dw still to do
    is done, or u_z is back to 0): (fraction θ in [0, 1], whether the impact ends there)."""
    theta = 1.0
    done = False
    if compression:
        if uz_new > 0.0:
            theta = -uz / (uz_new - uz)
    else:
        du = uz_new - uz
        if uz_new <= 0.0 < uz:
            theta = -uz / du
            done = True
        if h * theta * (uz + 0.5 * theta * du) >= dw:
            # ½ h du θ² + h uz θ − dw = 0, the root where the work reaches the target.
            root = (h * uz) ** 2 + 2.0 * h * du * dw
            theta = 2.0 * dw / (h * uz + math.sqrt(root if root > 0.0 else 0.0))
            done = True
    return min(max(theta, 0.0), 1.0), done


@njit(cache=True, error_model="numpy")
def _linear_event(compression: bool, uz: float, c: float, dw: float) -> float:
    """Normal impulse to the next normal event while u_z grows at the constant rate c = du_z/dp.

    In compression, to u_z = 0; in restitution, to the normal work dw still to do (or to u_z = 0
    again if c < 0 brings the contact point back first); ∞ if there is no such event.
    """
    if compression:
        return -uz / c if c > 0.0 else math.inf
    disc = uz * uz + 2.0 * c * dw
    if disc >= 0.0 and uz + math.sqrt(disc) > 0.0:
        return 2.0 * dw / (uz + math.sqrt(disc))
    return uz / -c if c < 0.0 else math.inf


@njit(cache=True, error_model="numpy")
def _rk4(
    u0: Vec, k: _Matrix, p: float, px: float, py: float, h: float, friction: float
) -> tuple[float, float]:
    """Tangential impulse after a classical Runge-Kutta step h of dP_t/dp = −μ û_t(P_t, p)."""
    u = _velocity_at(u0, k, px, py, p)
    ax, ay = _friction_rate(u[0], u[1], friction)
    u = _velocity_at(u0, k, px + 0.5 * h * ax, py + 0.5 * h * ay, p + 0.5 * h)
    bx, by = _friction_rate(u[0], u[1], friction)
    u = _velocity_at(u0, k, px + 0.5 * h * bx, py + 0.5 * h * by, p + 0.5 * h)
    cx, cy = _friction_rate(u[0], u[1], friction)
    u = _velocity_at(u0, k, px + h * cx, py + h * cy, p + h)
    dx, dy = _friction_rate(u[0], u[1], friction)
    return (
        px + h * (ax + 2.0 * bx + 2.0 * cx + dx) / 6.0,
        py + h * (ay + 2.0 * by + 2.0 * cy + dy) / 6.0,
    )


@njit(cache=True)
def collision_matrix(
    rc: Vec, n: Vec, mass: float, i1: float, i3: float
) -> tuple[float, float, float, float, float, float]:
    """(K_xx, K_xy, K_xz, K_yy, K_yz, K_zz) of the contact point rc, 1/kg (Stronge 2000, eq 5.7)."""
    ex = (1.0, 0.0, 0.0)
    ey = (0.0, 1.0, 0.0)
    ez = (0.0, 0.0, 1.0)
    return (
        _coupling(rc, ex, ex, n, mass, i1, i3),
        _coupling(rc, ex, ey, n, mass, i1, i3),
        _coupling(rc, ex, ez, n, mass, i1, i3),
        _coupling(rc, ey, ey, n, mass, i1, i3),
        _coupling(rc, ey, ez, n, mass, i1, i3),
        _coupling(rc, ez, ez, n, mass, i1, i3),
    )


@njit(cache=True)
def _normal_coupling(ra: Vec, rb: Vec, n: Vec, mass: float, i1: float, i3: float) -> float:
    """ẑ · K_ab ẑ = 1/m + (r_a × ẑ) · I⁻¹ (r_b × ẑ): the normal velocity at r_a per unit normal
    impulse at r_b, 1/kg (the Delassus matrix of two contacts; Stronge 2000, eq 5.7)."""
    za = (ra[1], -ra[0], 0.0)  # r_a × ẑ
    zb = (rb[1], -rb[0], 0.0)
    return 1.0 / mass + dot(za, inverse_inertia_apply(zb, n, i1, i3))


@njit(cache=True)
def newton_share(
    ra: Vec, rb: Vec, ua: float, ub: float, n: Vec, mass: float, i1: float, i3: float, e: float
) -> float:
    """λ = p_b / (p_a + p_b), the share of the normal impulse that the point rb takes when the
    coin strikes the table at ra and rb at once (frictionless), in [0, 1].

    The simultaneous impact of two contacts with Newton's law for each, as a linear
    complementarity problem (Glocker & Pfeiffer's set-valued impact law: Pfeiffer & Glocker,
    *Multibody Dynamics with Unilateral Contacts*, Wiley 1996, ch. 7; Glocker, *Energetic
    consistency conditions for standard impacts, part I*, Multibody Syst. Dyn. 29:77, 2013):
    normal impulses p ≥ 0 and ξ = u⁺ + e min(u⁻, 0) ≥ 0 with p·ξ = 0, where the normal
    velocities after are u⁺ = u⁻ + G p, G the 2×2 Delassus matrix (:func:`_normal_coupling`,
    positive definite: the LCP has exactly one solution, found here by trying its four
    active sets). ``ua`` < 0 (ra is the point that touched). A point whose impulse would pull
    takes none and the other strikes alone: as the approach of rb vanishes the share goes to 0
    continuously, the single impact at ra.
    """
    gaa = _normal_coupling(ra, ra, n, mass, i1, i3)
    gbb = _normal_coupling(rb, rb, n, mass, i1, i3)
    gab = _normal_coupling(ra, rb, n, mass, i1, i3)
    ta = ua + e * min(ua, 0.0)
    tb = ub + e * min(ub, 0.0)
    det = gaa * gbb - gab * gab
    if not det > 0.0:
        return 0.0  # the two points act as one (G singular to rounding)
    pa = -(gbb * ta - gab * tb) / det
    pb = -(gaa * tb - gab * ta) / det
    if pa >= 0.0 and pb >= 0.0 and pa + pb > 0.0:
        return pb / (pa + pb)
    if tb - gab * ta / gaa >= 0.0:  # ra alone: rb is left not approaching
        return 0.0
    return 1.0  # rb alone (ra then left not approaching)


@njit(cache=True)
def simultaneity(delay: float) -> float:
    """w in [0, 1]: how far two contacts, the second beginning ``delay`` contact durations
    (τ / t_c ≥ 0) after the first, make one simultaneous impact.

    1 while the second contact begins within the first half of the first (during its
    compression, when the two compressions overlap), 0 once the first is over (τ ≥ t_c: two
    impacts in sequence), and (1 + cos(π (2τ/t_c − 1))) / 2 between (the second beginning
    during the first's restitution): continuous with a continuous slope, so the impact does
    not jump at either end.
    """
    if delay <= 0.5:
        return 1.0
    if delay >= 1.0:
        return 0.0
    return 0.5 * (1.0 + math.cos(math.pi * (2.0 * delay - 1.0)))


@njit(cache=True)
def _flat_point(rc: Vec, v: Vec, omega: Vec, n: Vec, c: Contact, offset: float) -> Vec:
    """:func:`simultaneous_point` of a coin flat to rounding (|n_z| = 1, ``rc`` the centre of
    its lower face): its whole face touches at once (w = 1). The face is represented by the
    diameter along which its points approach at the most different speeds (any one without a
    tilt rate), whose ends take the impulse as the two-point Newton impact shares it
    (:func:`newton_share`): straight below the centre of mass for a coin without a tilt
    rate, as for the nearly flat coin whose lowest diameter is used."""
    # The normal velocity over the face, v_z + (ω × r)_z, grows along (−ω_y, ω_x).
    dx, dy = -omega[1], omega[0]
    size = math.sqrt(dx * dx + dy * dy)
    if size > 0.0:
        dx, dy = dx / size, dy / size
    else:
        dx, dy = 1.0, 0.0
    # In the face plane (n is vertical to rounding): d − (d·n) n, of length r − a.
    along = dx * n[0] + dy * n[1]
    ex, ey, ez = dx - along * n[0], dy - along * n[1], -along * n[2]
    corner = c.corner_radius
    scale = (c.radius - corner) / math.sqrt(ex * ex + ey * ey + ez * ez)
    ex, ey, ez = scale * ex, scale * ey, scale * ez
    base = (-offset * n[0], -offset * n[1], -offset * n[2] - corner)
    ra = (base[0] - ex, base[1] - ey, base[2] - ez)  # the end approaching faster
    rb = (base[0] + ex, base[1] + ey, base[2] + ez)
    ua = contact_velocity(v, omega, ra)[2]
    ub = contact_velocity(v, omega, rb)[2]
    if ua >= 0.0 or (ra[0] - rb[0]) ** 2 + (ra[1] - rb[1]) ** 2 <= 1e-24 * c.radius * c.radius:
        return rc
    lam = newton_share(ra, rb, ua, ub, n, c.mass, c.i1, c.i3, c.restitution)
    return (
        ra[0] + lam * (rb[0] - ra[0]),
        ra[1] + lam * (rb[1] - ra[1]),
        ra[2] + lam * (rb[2] - ra[2]),
    )


@njit(cache=True)
def simultaneous_point(
    rc: Vec, v: Vec, omega: Vec, v_after: Vec, omega_after: Vec, n: Vec, c: Contact
) -> Vec:
    """Where the impulse of an impact that starts at the lowest point ``rc`` acts, m (relative
    to the centre of mass): ``rc`` itself, or, when a second point of the rim would meet the
    table within a contact duration, a point between the two (a simultaneous impact).

    Parameters
    ----------
    rc : tuple of 3 floats
        The lowest point (:func:`contact_point`), approaching the table.
    v, omega : tuple of 3 floats
        Velocity of the centre of mass and angular velocity before the impact (lab).
    v_after, omega_after : tuple of 3 floats
        The same after the impact at ``rc`` alone (:func:`_strike`): the sequential law's.
    n : tuple of 3 floats
        Heads normal (lab).
    c : Contact
        The coin, e, the corner radius a and the contact duration t_c, s (0: every impact at
        the lowest point alone), as :func:`impact` reads them.

    Notes
    -----
    *Which second point, and when.* The candidates are the rim points that land next when the
    coin is nearly flat or nearly upright: the other end of the lowest diameter of the lower
    face, and the lowest point of the other face's rim (the two ends of the edge band). A
    candidate b at height gap_b above the table, which the impact at rc alone (the sequential
    law) leaves approaching at u_b⁺ < 0, would strike τ_b = gap_b / (−u_b⁺) later. That is the
    time to compare with the contact's duration: the impact at one end of a flat coin drives
    the other end down (the falling rod), so the sequential law's own next contact comes
    within t_c of the first for tilts up to about (−u_b⁺) t_c / 2r, not just the approach
    speed's. The two contacts make one impact as far as w = :func:`simultaneity` (τ_b / t_c)
    says: fully if b would strike within the first half of the first contact (during its
    compression), not at all if after its end; the candidate with the larger w is taken.
    (Gravity and the rotation of the gap over τ_b, both of order τ_b² ≤ t_c², are left out.)

    *The law.* The impulse acts at the centre of the normal impulses that the two points take
    in the simultaneous frictionless Newton impact (:func:`newton_share`, the share λ of b),
    and the impact there is Stronge's, with friction (:func:`contact_impulse`). Without
    friction, at full simultaneity (w = 1) and with both points approaching, this is exactly
    the two-contact Newton impact (Glocker & Pfeiffer's set-valued law; tested against an
    independent solution): two parallel normal impulses are one impulse at their centre, and
    both points leave with u⁺ = −e u⁻ (Stronge's and Newton's laws agree without friction).
    (With b receding before the impact, the LCP gives it no restitution, u_b⁺ = 0 where it
    pushes, and the single impact at the centre only approximates that.) A flat (or
    upright) coin landing without spin takes its impulse straight below its centre of mass:
    it bounces flat, at e times its approach speed, and no spin is made, where the sequential
    rigid impacts at its two ends set it spinning (the falling-rod paradox: Stoianovici &
    Hurmuzlu, *A critical study of the applicability of rigid-body collision theory*, J. Appl.
    Mech. 63:307, 1996, measure that the sequential rigid law fails there).

    Why this law: it is the set-valued Newton impact of the two contacts where that law is
    sound (without friction, and with one e for both contacts, it never makes energy: Glocker
    2013), it keeps Stronge's law for friction (a single impact at a material point of the
    coin never makes energy, with any friction: the module notes), and it has the sequential
    law as its limit. Liu, Zhao & Brogliato's energetic multiple-impact law (Proc. R. Soc. A
    464:3193, 2008) resolves the impact's time course but has no friction; a two-contact
    Newton law with Coulomb friction at each contact can make energy.

    *Continuity.* The impulse acts at rc + w λ (b − rc), and w, λ and u_b⁺ are continuous in
    the state: no threshold, the impact (and so the landing, up to later events) is a
    continuous function of the tilt. At w = 0 it is the impact at ``rc`` alone, bit for bit;
    as b's approach after it vanishes, τ_b → ∞ and w → 0. The weighting w is this model's
    interpolation between the two rigid limits (a compliant contact would resolve the time
    course), not a law from the literature; it acts only within about
    (−u_b⁺) t_c / 2r of flat or upright.

    Limits: the face is represented by its lowest diameter (a spin about that diameter is not
    restituted), and friction acts at the one point (a flat coin sliding into a flat impact
    feels its friction there, h/2 below its centre of mass, where a face in full contact
    would shift its pressure to cancel that torque).
    """
    nz = n[2]
    s2 = 1.0 - nz * nz
    duration = c.contact_duration
    if not duration > 0.0:
        return rc
    corner = c.corner_radius
    sign = 1.0 if nz >= 0.0 else -1.0
    offset = sign * (c.half_thickness - corner)
    fx, fy, fz = offset * n[0], offset * n[1], offset * n[2]
    if s2 <= 1e-24:
        return _flat_point(rc, v, omega, n, c, offset)
    k = (c.radius - corner) / math.sqrt(s2)
    # (r − a) ŵ, the core rim's radius towards the lowest point, and the core face's offset.
    wx, wy, wz = k * nz * n[0], k * nz * n[1], k * (nz * nz - 1.0)
    best = 0.0
    bx, by, bz = rc
    for which in range(2):
        if which == 0:  # the other end of the lower face's lowest diameter
            cx, cy, cz = -wx - fx, -wy - fy, -wz - fz - corner
        else:  # the lowest point of the other face's rim
            cx, cy, cz = wx + fx, wy + fy, wz + fz - corner
        apart = (cx - rc[0]) ** 2 + (cy - rc[1]) ** 2 + (cz - rc[2]) ** 2
        closing = contact_velocity(v_after, omega_after, (cx, cy, cz))[2]
        if closing >= 0.0 or apart <= 1e-24 * c.radius * c.radius:
            continue  # not approaching, or no second point (a rim rounded to a = h/2 or r)
        reach = -closing * duration  # how far it closes in one contact duration
        gap = cz - rc[2]
        if not gap < reach:
            continue  # not within a contact duration (also a closing speed of rounding size)
        overlap = simultaneity(gap / reach)
        if overlap > best:
            best, bx, by, bz = overlap, cx, cy, cz
    if best <= 0.0:
        return rc
    ua = contact_velocity(v, omega, rc)[2]
    ub = contact_velocity(v, omega, (bx, by, bz))[2]
    lam = best * newton_share(rc, (bx, by, bz), ua, ub, n, c.mass, c.i1, c.i3, c.restitution)
    if lam <= 0.0:
        return rc
    return (rc[0] + lam * (bx - rc[0]), rc[1] + lam * (by - rc[1]), rc[2] + lam * (bz - rc[2]))


@njit(cache=True)
def impact(v: Vec, angular_momentum: Vec, n: Vec, c: Contact) -> tuple[Vec, Vec, float]:
    """State just after the coin hits the surface z = const with its lowest point.

    Parameters
    ----------
    v : tuple of 3 floats
        Velocity of the centre of mass before the impact, m/s.
    angular_momentum : tuple of 3 floats
        Angular momentum about the centre of mass before the impact, kg m²/s.
    n : tuple of 3 floats
        Heads normal (unit), lab frame.
    c : Contact
        The record (:class:`coinflight.core.contact.Contact`) of the coin (r, h/2, m, I1, I3)
        and the surface, of which the impact reads: Stronge's energetic coefficient of
        restitution e in [0, 1] and Coulomb's μ ≥ 0 (its properties tested for μ up to 3,
        :data:`coinflight.model.surface.MAX_FRICTION`); the corner radius a, m
        (0 ≤ a ≤ min(h/2, r); 0: sharp), the impulse acting at the lowest point of the cylinder
        (r − a, h/2 − a) swept by a ball of radius a (:func:`contact_point`); and the contact
        duration t_c, s (:data:`CONTACT_DURATION`): a second rim point that meets the table
        within it makes the impact a simultaneous one (:func:`simultaneous_point`); 0: always
        the lowest point alone.

    Returns
    -------
    v, angular_momentum : tuple of 3 floats
        After the impact.
    rebound : float
        Normal velocity after the impact of the lowest point, m/s, or, after a simultaneous
        impact, the smaller of it and that of the point where the impulse acted (the coin
        leaves the table no faster): ≥ 0, and 0 when e = 0 (to rounding: 3e-12 of the
        approach speed in 200,000 random impacts near flat and upright).

    Notes
    -----
    Stronge's impact in impulse space (:func:`contact_impulse`) at the lowest point, or, for a
    coin meeting the table nearly flat or nearly upright, at the centre of the normal impulses
    of the simultaneous impact (:func:`simultaneous_point`); see the module notes for the law
    and why the kinetic energy never grows.
    """
    rc = contact_point(n, c.radius, c.half_thickness, c.corner_radius)
    omega = angular_velocity(angular_momentum, n, c.i1, c.i3)
    u = contact_velocity(v, omega, rc)
    if u[2] >= 0.0:
        return v, angular_momentum, u[2]
    after = _strike(v, angular_momentum, n, rc, u, c)
    if not c.contact_duration > 0.0:
        return after
    omega_after = angular_velocity(after[1], n, c.i1, c.i3)
    both = simultaneous_point(rc, v, omega, after[0], omega_after, n, c)
    if both == rc:
        return after  # the impact at the lowest point alone
    v, angular_momentum, leaving = _strike(
        v, angular_momentum, n, both, contact_velocity(v, omega, both), c
    )
    # The lowest point must not be left moving into the table (the impulse acted beside it,
    # and friction or a partial share may leave it so): if it is, it strikes in turn.
    u = contact_velocity(v, angular_velocity(angular_momentum, n, c.i1, c.i3), rc)
    lowest = u[2]
    if lowest < 0.0:
        v, angular_momentum, lowest = _strike(v, angular_momentum, n, rc, u, c)
        omega = angular_velocity(angular_momentum, n, c.i1, c.i3)
        leaving = contact_velocity(v, omega, both)[2]
    # The coin leaves the table as fast as the slower of the two points where it struck.
    return v, angular_momentum, min(lowest, leaving)


@njit(cache=True)
def _strike(
    v: Vec, angular_momentum: Vec, n: Vec, rc: Vec, u: Vec, c: Contact
) -> tuple[Vec, Vec, float]:
    """Stronge's impact at the point rc of the coin, approaching at u (:func:`contact_impulse`):
    (v, angular momentum, normal velocity of rc) after it."""
    k = collision_matrix(rc, n, c.mass, c.i1, c.i3)
    impulse, _ = contact_impulse(
        u, k, c.restitution, c.friction, TURN_STEP, SLIP_TOLERANCE, MAX_STEPS
    )
    v, angular_momentum = _apply(impulse, v, angular_momentum, rc, c.mass)
    omega = angular_velocity(angular_momentum, n, c.i1, c.i3)
    return v, angular_momentum, contact_velocity(v, omega, rc)[2]


@njit(cache=True)
def resting_face(nz: float, edge_sine: float) -> int:
    """Face code of the well the coin is in: EDGE if |n_z| < sin(arctan(h/d)), else heads/tails.

    Notes
    -----
    Resting on a rim point, the centre of mass lies above the edge (the cylinder's side) iff the
    normal is within arctan(h/d) of the horizontal (Yong & Mahadevan 2011, eq 1; REFERENCES §5);
    the corner between is the top of the potential barrier, at height sqrt(r² + h²/4).
    ``edge_sine`` = h / sqrt(h² + d²). Codes of :mod:`coinflight.core.outcome`.
    """
    if abs(nz) < edge_sine:
        return 2
    return 1 if nz > 0.0 else 0
