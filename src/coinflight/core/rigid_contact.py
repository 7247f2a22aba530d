"""A rigid coin rolling or sliding on one rim point: the constrained contact (numba).

The coin and the table are rigid: while the coin touches at one rim point the gap there stays
0, the contact force is whatever keeps it so (and, rolling, keeps the point from slipping), and
the steps are set by the motion's own time scales, not by a stiffness (a compliant contact's
springs and regularised friction would hold its steps to ~0.4 ms whatever the motion, and its
answers would depend on that stiffness: the physics page, "Why the 3-D ending is rigid").

This module is the one-rim contact: the modes ROLLING and SLIDING, their transitions located as
events, lift-off, Painlevé's paradox detected, and the stops where the other rim or the face
comes down. :func:`advance_rigid` stops and says why at each of them;
:mod:`coinflight.core.rigid_ending` builds the end of a landing on these modes (every table
landing whose bounces die out) and carries the coin through the stops (hops, rim and face
impacts, the band).

The state is y = (z, v, n, L): the height of the centre of mass, its velocity, the heads
normal and the angular momentum about the centre of mass (lab frame, SI), as the bounces of
:mod:`coinflight.core.bounce` hand it over.

The contact point and its kinematics
------------------------------------
The coin touches with ρ(n), the lowest point of its rim relative to the centre of mass
(:func:`coinflight.core.impact.contact_point`): ρ = R ŵ − sgn(n_z) H n − a Z, with
ŵ = (n_z n − Z)/s, s = sqrt(1 − n_z²), R = r − a, H = h/2 − a (a the corner radius; the rim
circle of a rounded rim is the core cylinder's, moved down by a). The gap is g = z + ρ_z(n).
The material point of the coin at ρ moves at u = v + ω × ρ. The geometric point ρ(n(t)) moves
at ρ̇_g = R ŵ̇ − sgn(n_z) H ṅ (ṅ = ω × n, ŵ̇ = (ṅ_z n + n_z ṅ)/s + ŵ n_z ṅ_z / s²), which
differs from ω × ρ by a motion along the rim circle (or, rounded, over the corner's ball)
whose tangent at the lowest point is horizontal; so ġ = v_z + ρ̇_g,z = u_z (the identity of a
rolling body's contact, O'Reilly 1996, §2; Le Saux, Leine & Glocker 2005, §2).

Differentiating u (the velocity of the material point *now* at the contact; the point that is
there changes, so ρ's rate is ρ̇_g, not ω × ρ):

    u̇ = a + α × ρ + ω × ρ̇_g.

With the contact force F at ρ, gravity, and the resistance torques T (below),
a = F/m − g Z, L̇ = ρ × F + T, and ω = I⁻¹(n) L with I⁻¹ = 1/I1 + (1/I3 − 1/I1) n nᵀ, so
α = I⁻¹ L̇ + γ with the gyroscopic term γ = (1/I3 − 1/I1) [(ṅ·L) n + (n·L) ṅ]. Then

    u̇ = W F + b,   W = 1/m − [ρ×] I⁻¹ [ρ×],   b = −g Z + γ × ρ + ω × ρ̇_g + (I⁻¹ T) × ρ.

W is the collision matrix K of :func:`coinflight.core.impact.collision_matrix` (Stronge 2000,
eq 5.7; Batlle 1996), used here as is. The resistance torques are proportional to the normal
force, T = F_z τ, so their part of b is moved into W's third column: W' = W + ((I⁻¹ τ) × ρ) Zᵀ
and u̇ = W' F + b₀, b₀ = −g Z + γ × ρ + ω × ρ̇_g (linear in F, not symmetric).

Modes and their transitions
---------------------------
* **ROLLING** (u = 0 held): W' F = −b₀, solved for the three components of F. Valid while
  F_z ≥ 0 and |F_h| ≤ μ F_z (Coulomb's cone).
* **SLIDING** (u_h ≠ 0, u_z = 0): F = N (Z − μ ŝ), ŝ = u_h/|u_h| (exact Coulomb friction, not
  regularised); N from u̇_z = 0: N = −b₀_z / c_N, c_N = W'_zz − μ W_zh·ŝ. Valid while N ≥ 0.
  c_N ≤ 0 is Painlevé's paradox (no N, or two, make the motion consistent; Painlevé 1895,
  Stewart 2000, SIAM Rev. 42:3): reported (:data:`PAINLEVE`), not integrated through.
* **FREE**: the normal force needed would be negative: the coin lifts off. The run stops and
  hands the state back (:mod:`coinflight.core.rigid_ending` flies it).

Events, each located in the step to :data:`EVENT_TIME` (regula falsi on the event function that
crossed, Illinois-modified, safeguarded by bisection: ~8 trial steps an event where bisection
took ~35; the bracket is decided as bisection decides it): in ROLLING, F_z falling
to 0 (lift-off) or |F_h| reaching μ F_z (slip starts); in SLIDING, N falling to 0 (lift-off),
c_N to 0 (Painlevé) or the slip stopping (its component along the slip at the step's start
reaching 0, or |u_h| below :data:`SLIP_FLOOR`). At a slip's stop the stick test: ROLLING if
the rolling force lies in the cone, else SLIDING again. A slide starts from u_h = 0 along the
direction in which the slip grows on a ray, u̇_h = λ ŝ with λ > 0 (Batlle 1996 for impacts; Le
Saux, Leine & Glocker 2005, §4 for the rolling disk's stick-slip): with N fixed this is the
impact law's ray, (λ/N + μ K_hh) ŝ = W'_hz + b₀_h/N, solved by
:func:`coinflight.core.impact._ray_direction` (reused), and iterated on N(ŝ).
In both modes the run stops when n_z crosses 0 (the other rim touches: the band contact; only
for a rim with a flat band, H > 0) or s falls below :data:`FACE_SINE` (the face comes down to
the table). A run keeps the rim it starts on: past n_z = 0 that rim's point carries on smoothly
to the event, where the lower rim's point would jump by 2H n and a trial step whose stages
straddle n_z = 0 would see a jump in the force (its error rejected step after step down to the
crossing: ~30 rejected steps at each of the thousands of rim changes of a coin rocking across
its band).

Rolling and pivoting resistance at the point contact are torques −ℓ_r F_z ω_h / sqrt(|ω_h|² + ω_ε²)
and −ℓ_p F_z ω_z / sqrt(ω_z² + ω_ε²) Z, ω_ε = SLIP_SPEED / r, with the regularisation ω_ε.
**Regularised, not set-valued**: set-valued rolling and drilling stick adds two more stick
conditions and their events (a coin that stops rolling but keeps sliding, and the reverse), not
built. Below ω_ε (0.47 rad/s for a nickel: its rim moving at 5 mm/s) the torque is a viscous one,
time scale I1 ω_ε/(ℓ F_z) (~14 ms for a nickel at ℓ = 1e-4 m and F_z = m g); it matters only to a
coin already nearly at rest, which the energy test of the ending has settled first in the landings
measured.

Integration
-----------
Dormand-Prince 5(4) with adaptive steps (Hairer, Nørsett & Wanner, *Solving ODEs I*, II.5; the
coefficients of :mod:`coinflight.core.dormand_prince`), its stages written out for this
module's rates (passing the rates as a first-class function would keep it out of numba's
on-disk cache, ``cache=True``, on which a fast start relies). It stops at events, and projects
after every step. The projection keeps the flow on its constraints: n
renormalised; z set so the gap is 0; u_z (SLIDING) or u (ROLLING) set to 0 by the impulse at the
contact point that does it with least kinetic energy (P = −u_z/K_zz Z or P = −K⁻¹ u: Gauss's
principle). The largest gap and constraint speed removed are reported (the drift; tests bound
it). Then the energy: the work of the contact over the step, the quadrature of its power
P = F·u + F_z τ·ω on the constraints (friction while sliding, the resistances) by the pair's
fifth-order weights (an extra component dW/dt = P), is added to the energy the flow should
have, and the velocities v and L are scaled by the one factor that puts the step on it: the
projection onto an invariant of Hairer, Lubich & Wanner, *Geometric Numerical Integration*
(2nd ed.), IV.4, orthogonal in the kinetic-energy metric, in which the energy's gradient in the
velocities is the velocity itself; it keeps u = 0 or u_z = 0 (u is linear in v and L), and it
neither adds nor removes the physical dissipation, which is the quadrature's. A rolling coin
without resistances keeps its energy to rounding, whatever the tolerance. Without friction it
is not applied: the flow then keeps the horizontal momentum and L_z, linear invariants that
the steps keep to rounding and a scaling would not. A stick's impulse (the slip's remainder
removed, dissipative) starts the energy afresh. In a slide the steps' error estimate in the
slip is held below :data:`SLIP_ERROR` besides the tolerance.

The ending: with ``settle``, the run stops when the coin's energy (no springs here: kinetic
plus m g z) is below its well's barrier (:func:`below_barrier`).

Speed
-----
A landing's contact takes about 1,000 accepted steps a simulated second at the ending's tolerance
(1e-7), a few μs each (six rate evaluations; the stages written out): the coins the bounces hand
over spin (one precessing at ~100 rad/s takes steps of ~0.5 ms), switch between sticking and
slipping at the cone's boundary (steps of ~15 μs while a small slip turns: near its stop the slip's
direction turns at ~|u̇_h|/|u_h|, so that the steps shrink with the slip down to :data:`SLIP_FLOOR`,
~20 of them a stop), and lift off within milliseconds (events located in ~8 trial steps).
``benchmarks/bench_bounce.py`` measures the landings a second.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, NamedTuple

import numpy as np

from coinflight.core import dormand_prince as dp
from coinflight.core._jit import njit
from coinflight.core.flight import (
    SLIP_SPEED,
    _barrier,
    _motion_energy,
    _motion_free_energy,
)
from coinflight.core.impact import (
    _ray_direction,
    angular_velocity,
    contact_point,
    cross,
    dot,
    inverse_inertia_apply,
)

if TYPE_CHECKING:
    from coinflight.core.contact import Contact

FREE = 0
"""Mode: off the table (the run stops: lift-off)."""
ROLLING = 1
"""Mode: rolling (and pivoting) on one rim point without slip."""
SLIDING = 2
"""Mode: sliding on one rim point (Coulomb friction against the slip)."""
MODE_NAMES = ("free", "rolling", "sliding")

DURATION = 0
"""Why a run stopped: the duration asked for has passed."""
LIFT_OFF = 1
"""The normal force would be negative: the coin leaves the table (mode FREE)."""
SECOND_RIM = 2
"""n_z crossed 0: the other rim touches (the band contact; not built)."""
FACE = 3
"""The face comes down to the table (s < :data:`FACE_SINE`; not built)."""
PAINLEVE = 4
"""Painlevé's paradox: sliding with c_N ≤ 0 (no consistent normal force)."""
BELOW_BARRIER = 5
"""The coin's energy is below its well's barrier (``settle``)."""
MAX_STEPS_REACHED = 6
"""The step budget ran out."""
NOT_IN_CONTACT = 7
"""The start state approaches the table faster than ``approach``: an impact is needed first."""
STEP_FAILED = 8
"""60 trial steps in a row were rejected (the step size fell by 0.2⁶⁰), or
:data:`STALL_EVENTS` events in a row made no progress: the state is left at the last accepted
step."""
REASON_NAMES = (
    "duration",
    "lift-off",
    "second rim",
    "face",
    "Painlevé",
    "below barrier",
    "max steps",
    "not in contact",
    "step failed",
)

RTOL = 1e-8
"""Relative tolerance of the step-size control."""
MAX_STEP = 5e-3
"""Longest step, s."""
MAX_STEPS = 200_000
"""Accepted steps at most in one run."""
EVENT_TIME = 1e-12
"""Events are located to within this time, s (the bracket of the event's search)."""
STICK_SPEED = 1e-9
"""A slip below this speed, m/s, has stopped (the stick test follows)."""
FACE_SINE = 1e-2
"""s = sqrt(1 − n_z²) below which the face is taken to reach the table (the run stops): a
nickel's far rim point is then 2 r s ≈ 0.21 mm above the table, and the contact point runs round
the rim at ~ω/s (the end of Euler's disk), which steps cannot follow cheaply
(:mod:`coinflight.core.rigid_ending` ends a coin lying flat there)."""
SLIP_FLOOR = 1e-5
"""A small slip, m/s. Below it a slip that the cone could not stop (the rolling force is
outside it) slides along the ray of :func:`slip_start` instead of its own direction: a slide
starting at the cone's boundary grows from 0 with a direction the step control would follow
with very short steps. Friction keeps its size μ N; only its direction, over a slip below
10 μm/s, is the ray's, except when the slip points against the ray: friction then opposes the
slip itself (along the ray it would do positive work, up to μ N SLIP_FLOOR). And a slip
falling below it has stopped (the event; then the stick test, and if it holds the projection
removes the rest of the slip, at most this, by an impulse): a stopping slip's direction turns
at ~(u̇_h)/|u_h| as it vanishes, which the step control would follow with steps shrinking with
it."""
STALL_TIME = 1e-9
"""An event located less than this after the one before, s, makes no progress (with
:data:`STALL_EVENTS`)."""
STALL_EVENTS = 100
"""Events in a row that make no progress after which a run stops (:data:`STEP_FAILED`):
a slide starting on the friction cone's boundary that the stop event ends as it starts,
again and again (a rounding-level loop, seen once in 84 hand-off landings)."""
APPROACH = 1e-6
"""Default ``approach`` of :func:`advance_rigid`, m/s."""
SLIP_ERROR = 0.1 * SLIP_FLOOR
"""The largest error estimate of a sliding step in the slip u_h, m/s (besides the tolerance):
a stopping slip is followed down to :data:`SLIP_FLOOR` only if the steps' error in it is
well below it. Without it, at tolerances from about 1e-6, a slip that friction has stopped
hovers above the floor at the size of the steps' error, its direction u_h/|u_h| (and the
friction's) swinging from step to step, on thousands of short steps."""
ENERGY_MOVE = 1e-4
"""The largest relative change of the velocities by which a step is put back on its energy
(:func:`_keep_energy`); a step's energy error is ~RTOL of it, far below."""


@njit(cache=True, inline="always")
def _side(nz):
    """The rim below for the heads normal's z component nz: +1 the tails-side rim (n_z ≥ 0)."""
    return 1.0 if nz >= 0.0 else -1.0


@njit(cache=True)
def _basis(n, c, side):
    """(ρ, ŵ, s, side, R, H) of the contact point on the rim ``side`` (module notes; ±1, the
    sign of n_z for which it is the lower rim: :func:`coinflight.core.impact.contact_point`
    with the rim given, to the bit the same for side = sgn(n_z)). A run keeps its rim: past
    n_z = 0 the same rim's point carries on smoothly (the second-rim event stops the run
    there), where the lower rim's would jump by 2H n and a step's stages straddling n_z = 0
    would see a discontinuous force (their error rejecting step after step down to the
    crossing)."""
    corner = c.corner_radius
    nz = n[2]
    hh = c.half_thickness - corner
    s2 = 1.0 - nz * nz
    if s2 <= 1e-24:
        rho = (-side * hh * n[0], -side * hh * n[1], -side * hh * n[2] - corner)
    else:
        k = (c.radius - corner) / math.sqrt(s2)
        rho = (
            k * nz * n[0] - side * hh * n[0],
            k * nz * n[1] - side * hh * n[1],
            k * (nz * nz - 1.0) - side * hh * n[2] - corner,
        )
    # s ≥ FACE_SINE on the flow (the face event); a trial stage may overshoot: kept finite so
    # that its error rejects the step.
    s = max(math.sqrt(max(0.0, s2)), 1e-9)
    w = ((nz * n[0]) / s, (nz * n[1]) / s, (nz * nz - 1.0) / s)
    return rho, w, s, side, c.radius - corner, hh


@njit(cache=True)
def geometric_rate(n, omega, c):
    """ρ̇_g, the rate of the contact point ρ(n(t)) as n turns at ω, m/s (module notes)."""
    return _rate(n, omega, c, _side(n[2]))


@njit(cache=True)
def _rate(n, omega, c, side):
    """:func:`geometric_rate` on the rim ``side`` (:func:`_basis`)."""
    _, w, s, sign, big_r, big_h = _basis(n, c, side)
    return _rate_of(n, omega, w, s, sign, big_r, big_h)


@njit(cache=True, inline="always")
def _rate_of(n, omega, w, s, sign, big_r, big_h):
    """:func:`_rate` from the basis of :func:`_basis` (ŵ, s, side, R, H)."""
    nd = cross(omega, n)
    nz, ndz = n[2], nd[2]
    k = nz * ndz / (s * s)
    wd = (
        (ndz * n[0] + nz * nd[0]) / s + k * w[0],
        (ndz * n[1] + nz * nd[1]) / s + k * w[1],
        (ndz * n[2] + nz * nd[2]) / s + k * w[2],
    )
    return (
        big_r * wd[0] - sign * big_h * nd[0],
        big_r * wd[1] - sign * big_h * nd[1],
        big_r * wd[2] - sign * big_h * nd[2],
    )


@njit(cache=True)
def _resistance(omega, c):
    """τ: the resistance torques per newton of normal force (T = F_z τ), m."""
    eps = SLIP_SPEED / c.radius
    tx, ty, tz = 0.0, 0.0, 0.0
    if c.rolling_resistance > 0.0:
        k = -c.rolling_resistance / math.sqrt(omega[0] * omega[0] + omega[1] * omega[1] + eps * eps)
        tx, ty = k * omega[0], k * omega[1]
    if c.pivoting_resistance > 0.0:
        tz = -c.pivoting_resistance * omega[2] / math.sqrt(omega[2] * omega[2] + eps * eps)
    return (tx, ty, tz)


@njit(cache=True)
def constraint_terms(y, c):
    """(W', b₀, ρ, ω, τ, u) of the state y: u̇ = W' F + b₀ (module notes). W' as a 9-tuple,
    row-major."""
    return _terms(y, c, _side(y[6]))


@njit(cache=True)
def _terms(y, c, side):
    """:func:`constraint_terms` on the rim ``side`` (:func:`_basis`)."""
    v = (y[1], y[2], y[3])
    n = (y[4], y[5], y[6])
    lm = (y[7], y[8], y[9])
    i1, i3 = c.i1, c.i3
    omega = angular_velocity(lm, n, i1, i3)
    rho, wh, s, sign, big_r, big_h = _basis(n, c, side)
    k = _collision(rho, n, c)
    tau = _resistance(omega, c)
    col = cross(inverse_inertia_apply(tau, n, i1, i3), rho)
    w = (k[0], k[1], k[2] + col[0], k[1], k[3], k[4] + col[1], k[2], k[4], k[5] + col[2])
    nd = cross(omega, n)
    q = (1.0 / i3 - 1.0 / i1) * dot(nd, lm)
    p = (1.0 / i3 - 1.0 / i1) * dot(n, lm)
    gamma = (q * n[0] + p * nd[0], q * n[1] + p * nd[1], q * n[2] + p * nd[2])
    rd = _rate_of(n, omega, wh, s, sign, big_r, big_h)
    t1 = cross(gamma, rho)
    t2 = cross(omega, rd)
    b = (t1[0] + t2[0], t1[1] + t2[1], t1[2] + t2[2] - c.g)
    wr = cross(omega, rho)
    u = (v[0] + wr[0], v[1] + wr[1], v[2] + wr[2])
    return w, b, rho, omega, tau, u


@njit(cache=True, inline="always")
def _collision(rho, n, c):
    """The collision matrix K of the contact point ρ as
    :func:`coinflight.core.impact.collision_matrix` gives it (Stronge 2000, eq 5.7), in closed
    form: K = E/m + (|ρ|² E − ρ ρᵀ)/I1 + (1/I3 − 1/I1) q qᵀ, q = ρ × n (I⁻¹ = E/I1 +
    (1/I3 − 1/I1) n nᵀ and (ρ × a)·(ρ × b) = |ρ|² a·b − (ρ·a)(ρ·b)). The same six entries,
    to rounding."""
    a = 1.0 / c.i1
    d = 1.0 / c.i3 - a
    mi = 1.0 / c.mass
    rr = rho[0] * rho[0] + rho[1] * rho[1] + rho[2] * rho[2]
    q = cross(rho, n)
    diag = mi + a * rr
    return (
        diag - a * rho[0] * rho[0] + d * q[0] * q[0],
        -a * rho[0] * rho[1] + d * q[0] * q[1],
        -a * rho[0] * rho[2] + d * q[0] * q[2],
        diag - a * rho[1] * rho[1] + d * q[1] * q[1],
        -a * rho[1] * rho[2] + d * q[1] * q[2],
        diag - a * rho[2] * rho[2] + d * q[2] * q[2],
    )


@njit(cache=True)
def _solve3(w, b):
    """x with W x = b (Cramer's rule; W a row-major 9-tuple)."""
    a, bb, cc, d, e, f, g, h, i = w
    det = a * (e * i - f * h) - bb * (d * i - f * g) + cc * (d * h - e * g)
    x0 = (b[0] * (e * i - f * h) - bb * (b[1] * i - f * b[2]) + cc * (b[1] * h - e * b[2])) / det
    x1 = (a * (b[1] * i - f * b[2]) - b[0] * (d * i - f * g) + cc * (d * b[2] - b[1] * g)) / det
    x2 = (a * (e * b[2] - b[1] * h) - bb * (d * b[2] - b[1] * g) + b[0] * (d * h - e * g)) / det
    return (x0, x1, x2)


@njit(cache=True)
def rolling_force(y, c):
    """F keeping the contact point at rest (u̇ = 0): W' F = −b₀, N."""
    return _rolling(y, c, _side(y[6]))


@njit(cache=True)
def _rolling(y, c, side):
    """:func:`rolling_force` on the rim ``side``."""
    w, b, _, _, _, _ = _terms(y, c, side)
    return _solve3(w, (-b[0], -b[1], -b[2]))


@njit(cache=True)
def sliding_force(y, c, dx, dy):
    """(F, c_N) of a contact sliding along (dx, dy) (unit; the slip's direction): F = N (Z − μ ŝ)
    with N = −b₀_z / c_N, c_N = W'_zz − μ (W_zx ŝ_x + W_zy ŝ_y); F = 0 when c_N ≤ 0
    (Painlevé)."""
    w, b, _, _, _, _ = constraint_terms(y, c)
    mu = c.friction
    coef = w[8] - mu * (w[6] * dx + w[7] * dy)
    if coef <= 0.0:
        return (0.0, 0.0, 0.0), coef
    normal = -b[2] / coef
    return (-mu * normal * dx, -mu * normal * dy, normal), coef


@njit(cache=True)
def slip_start(y, c):
    """(ŝ_x, ŝ_y): the direction in which a stuck contact that the cone cannot hold starts to
    slide: the ray u̇_h = λ ŝ, λ > 0 (module notes; :func:`coinflight.core.impact._ray_direction`
    at the normal force N(ŝ), iterated)."""
    return _slip_start(y, c, _side(y[6]))


@njit(cache=True)
def _slip_start(y, c, side):
    """:func:`slip_start` on the rim ``side``."""
    w, b, _, _, _, _ = _terms(y, c, side)
    return _ray(w, b, c.friction)


@njit(cache=True)
def _ray(w, b, mu):
    """:func:`slip_start` from the terms of :func:`constraint_terms`."""
    f = _solve3(w, (-b[0], -b[1], -b[2]))
    size = math.sqrt(f[0] * f[0] + f[1] * f[1])
    if size == 0.0:
        return 1.0, 0.0
    dx, dy = -f[0] / size, -f[1] / size  # the stick force's opposite: the first guess
    if mu <= 0.0:
        return dx, dy
    for _ in range(20):
        coef = w[8] - mu * (w[6] * dx + w[7] * dy)
        if coef <= 0.0:
            break
        normal = -b[2] / coef
        if normal <= 0.0:
            break
        ex, ey = _ray_direction(w[0], w[1], w[4], w[2] + b[0] / normal, w[5] + b[1] / normal, mu)
        if not (math.isfinite(ex) and math.isfinite(ey)):
            break
        change = abs(ex - dx) + abs(ey - dy)
        dx, dy = ex, ey
        if change < 1e-14:
            break
    return dx, dy


@njit(cache=True)
def _force(y, c, mode, dx, dy, side):
    """(F, c_N, ŝ): the contact force of the mode (ŝ the slip direction used; (dx, dy) below
    :data:`STICK_SPEED`), on the rim ``side`` (:func:`_basis`)."""
    w, b, _, _, _, u = _terms(y, c, side)
    return _contact_force(w, b, u, c.friction, mode, dx, dy)


@njit(cache=True)
def _contact_force(w, b, u, mu, mode, dx, dy):
    """:func:`_force` from the terms of :func:`constraint_terms`."""
    if mode == ROLLING:
        return _solve3(w, (-b[0], -b[1], -b[2])), 1.0, 0.0, 0.0
    slip = math.sqrt(u[0] * u[0] + u[1] * u[1])
    if slip > SLIP_FLOOR:
        dx, dy = u[0] / slip, u[1] / slip
    else:
        # A slip this small that the cone could not stop grows along the ray (the notes).
        f = _solve3(w, (-b[0], -b[1], -b[2]))
        if f[2] < 0.0 or math.sqrt(f[0] * f[0] + f[1] * f[1]) > mu * f[2]:
            dx, dy = _ray(w, b, mu)
            if slip > 0.0 and u[0] * dx + u[1] * dy < 0.0:
                # Never along the slip's opposite: friction on a slip against the ray would do
                # positive work; it opposes the slip itself there.
                dx, dy = u[0] / slip, u[1] / slip
        elif slip > STICK_SPEED:
            dx, dy = u[0] / slip, u[1] / slip
    coef = w[8] - mu * (w[6] * dx + w[7] * dy)
    if coef <= 0.0:
        return (0.0, 0.0, 0.0), coef, dx, dy
    normal = -b[2] / coef
    return (-mu * normal * dx, -mu * normal * dy, normal), coef, dx, dy


@njit(cache=True)
def _derivative(y, out, c, mode, dx, dy):
    """dy/dt of y = (z, v, n, L) in ``mode`` (ROLLING or SLIDING along the slip, or (dx, dy) at a
    slip below :data:`STICK_SPEED`), on the lower rim."""
    _flow(y, out, c, mode, dx, dy, _side(y[6]), np.empty(6))


@njit(cache=True)
def _flow(y, out, c, mode, dx, dy, side, seen):
    """:func:`_derivative` on the rim ``side`` (:func:`_basis`); returns the power of the
    contact (the rate of the mechanical energy, W: ≤ 0, Coulomb friction and the
    resistances). ``seen`` receives (F, c_N, u_x, u_y) at y, from which
    :func:`_event_values` finds the events there without evaluating the terms again."""
    w, b, rho, omega, tau, u = _terms(y, c, side)
    f, coef, _, _ = _contact_force(w, b, u, c.friction, mode, dx, dy)
    seen[0], seen[1], seen[2] = f
    seen[3] = coef
    seen[4], seen[5] = u[0], u[1]
    n = (y[4], y[5], y[6])
    torque = cross(rho, f)
    nd = cross(omega, n)
    m = c.mass
    out[0] = y[3]
    out[1] = f[0] / m
    out[2] = f[1] / m
    out[3] = f[2] / m - c.g
    out[4] = nd[0]
    out[5] = nd[1]
    out[6] = nd[2]
    out[7] = torque[0] + f[2] * tau[0]
    out[8] = torque[1] + f[2] * tau[1]
    out[9] = torque[2] + f[2] * tau[2]
    if y.shape[0] > 10:  # the horizontal position, carried along (not in the error control)
        out[10] = y[1]
        out[11] = y[2]
    # The power of the contact force and the resistance torques: F·u + F_z τ·ω (the rate of
    # the energy ½ m v² + ½ L·ω + m g z: m v·a + ω·L̇ + m g v_z with L̇ = ρ × F + F_z τ), on the
    # constraints: u = 0 rolling, u_z = 0 sliding (a stage point's drift off them does no
    # physical work).
    power = f[2] * (tau[0] * omega[0] + tau[1] * omega[1] + tau[2] * omega[2])
    if mode == SLIDING:
        power += f[0] * u[0] + f[1] * u[1]
    return power


@njit(cache=True)
def _events(y, c, mode, dx, dy, sx, sy, floor, band, side):
    """Event functions at y, each positive while nothing happens: (lift-off, slip start or
    stop, Painlevé, second rim, face). (sx, sy): the slip direction at the step's start;
    ``floor``: the slip below which it has stopped (:data:`SLIP_FLOOR`; 0 for a step starting
    below it, a slide starting from rest, whose stop is its reversal); ``band``: n_z's sign at
    the start (0: no band, no second-rim event); ``side``: the run's rim (:func:`_basis`)."""
    w, b, _, _, _, u = _terms(y, c, side)
    f, coef, _, _ = _contact_force(w, b, u, c.friction, mode, dx, dy)
    return _event_values(f, coef, u[0], u[1], y[6], c.friction, mode, sx, sy, floor, band)


@njit(cache=True)
def _event_values(f, coef, ux, uy, nz, mu, mode, sx, sy, floor, band):
    """:func:`_events` from the contact force F, c_N and the slip (u_x, u_y) at the point and
    its n_z (as :func:`_flow` leaves them in ``seen``)."""
    second = nz * band if band != 0.0 else 1.0
    face = math.sqrt(max(0.0, 1.0 - nz * nz)) - FACE_SINE
    if mode == ROLLING:
        cone = mu * f[2] - math.sqrt(f[0] * f[0] + f[1] * f[1])
        return f[2], cone, 1.0, second, face
    along = ux * sx + uy * sy
    slip = math.sqrt(ux * ux + uy * uy)
    stop = min(along, slip - floor)
    return (f[2] if coef > 0.0 else 1.0), stop, coef, second, face


@njit(cache=True)
def _seen_events(seen, nz, mu, mode, sx, sy, floor, band):
    """:func:`_event_values` from what the last rate evaluation left in ``seen`` (F, c_N,
    u_x, u_y) and the state's n_z."""
    return _event_values(
        (seen[0], seen[1], seen[2]), seen[3], seen[4], seen[5], nz, mu, mode, sx, sy, floor, band
    )


@njit(cache=True)
def _crossed(e):
    return e[0] < 0.0 or e[1] < 0.0 or e[2] <= 0.0 or e[3] < 0.0 or e[4] < 0.0


@njit(cache=True)
def _first_crossed(e):
    """The index of the first event function of e that has crossed (:func:`_crossed`)."""
    if e[0] < 0.0:
        return 0
    if e[1] < 0.0:
        return 1
    if e[2] <= 0.0:
        return 2
    if e[3] < 0.0:
        return 3
    return 4


@njit(cache=True)
def _step(y, h, c, mode, dx, dy, side, k1, k2, k3, k4, k5, k6, k7, tmp, new, power, seen):
    """One Dormand-Prince step of h from y (k1 = f(y) given, its power in power[1]) on the rim
    ``side``: ``new`` and the error estimate (k7 = f(new)); the stages' powers in power[2:8],
    and ``seen`` at ``new`` (:func:`_flow`).
    Returns the work of the contact over the step, J: the power's quadrature by the pair's
    fifth-order weights (the energy's change on the exact flow; the quadrature of an extra
    component dW/dt = P, Hairer, Lubich & Wanner, *Geometric Numerical Integration*, IV.4)."""
    # The stages written out: a loop over them, picking each one's arrays at run time, takes
    # about as long again as the six rate evaluations themselves.
    dp.stage(2, y, h, k1, k2, k3, k4, k5, k6, tmp)
    power[2] = _flow(tmp, k2, c, mode, dx, dy, side, seen)
    dp.stage(3, y, h, k1, k2, k3, k4, k5, k6, tmp)
    power[3] = _flow(tmp, k3, c, mode, dx, dy, side, seen)
    dp.stage(4, y, h, k1, k2, k3, k4, k5, k6, tmp)
    power[4] = _flow(tmp, k4, c, mode, dx, dy, side, seen)
    dp.stage(5, y, h, k1, k2, k3, k4, k5, k6, tmp)
    power[5] = _flow(tmp, k5, c, mode, dx, dy, side, seen)
    dp.stage(6, y, h, k1, k2, k3, k4, k5, k6, tmp)
    power[6] = _flow(tmp, k6, c, mode, dx, dy, side, seen)
    dp.stage(7, y, h, k1, k2, k3, k4, k5, k6, new)
    power[7] = _flow(new, k7, c, mode, dx, dy, side, seen)
    return h * (
        dp.B1 * power[1] + dp.B3 * power[3] + dp.B4 * power[4] + dp.B5 * power[5] + dp.B6 * power[6]
    )


@njit(cache=True)
def _keep_energy(y, c, target):
    """Put y on its energy, ``target`` (J): the velocities v and L scaled by one factor λ so
    that ½ m v² + ½ L·ω + m g z = target (Hairer, Lubich & Wanner, *Geometric Numerical
    Integration*, IV.4, projection onto an invariant; here the energy at the run's start less
    the work of friction and the resistances since, :func:`_step`). Scaling is the orthogonal
    projection onto the energy's level set in the kinetic-energy metric (the energy's gradient
    in the velocities is the velocity itself there), and it keeps the contact's constraints
    on the velocity (u = 0 rolling, u_z = 0 sliding: u is linear in (v, L)). Applied only for a
    change below :data:`ENERGY_MOVE` (the drift of the steps); else y is left as it is. Not
    applied without friction: the contact force is then vertical, at a point in the plane of n
    and Z, so that the horizontal momentum, L_z and L·n are conserved, linear invariants that
    the Runge–Kutta steps keep to rounding (Hairer, Lubich & Wanner, IV.1) and a scaling would
    not. Returns the energy of y after."""
    m = c.mass
    n = (y[4], y[5], y[6])
    lm = (y[7], y[8], y[9])
    omega = angular_velocity(lm, n, c.i1, c.i3)
    kinetic = 0.5 * m * (y[1] * y[1] + y[2] * y[2] + y[3] * y[3]) + 0.5 * dot(lm, omega)
    potential = m * c.g * y[0]
    want = target - potential
    if kinetic > 0.0 and want > 0.0 and c.friction > 0.0:
        scale = math.sqrt(want / kinetic)
        if abs(scale - 1.0) < ENERGY_MOVE:
            y[1] *= scale
            y[2] *= scale
            y[3] *= scale
            y[7] *= scale
            y[8] *= scale
            y[9] *= scale
            return target
    return kinetic + potential


@njit(cache=True)
def _project(y, c, mode):
    """Put y back on its constraints (module notes): |n| = 1, gap 0, u_z = 0 (and u_h = 0
    rolling) by the least-energy impulse at the contact on the lower rim. Returns (gap removed,
    speed removed)."""
    return _project_on(y, c, mode, _side(y[6]))


@njit(cache=True)
def _project_on(y, c, mode, side):
    """:func:`_project` on the rim ``side`` (:func:`_basis`)."""
    size = math.sqrt(y[4] * y[4] + y[5] * y[5] + y[6] * y[6])
    y[4] /= size
    y[5] /= size
    y[6] /= size
    n = (y[4], y[5], y[6])
    rho, _, _, _, _, _ = _basis(n, c, side)
    gap = y[0] + rho[2]
    y[0] = -rho[2]
    lm = (y[7], y[8], y[9])
    omega = angular_velocity(lm, n, c.i1, c.i3)
    wr = cross(omega, rho)
    u = (y[1] + wr[0], y[2] + wr[1], y[3] + wr[2])
    k = _collision(rho, n, c)
    if mode == ROLLING:
        kk = (k[0], k[1], k[2], k[1], k[3], k[4], k[2], k[4], k[5])
        p = _solve3(kk, (-u[0], -u[1], -u[2]))
        speed = math.sqrt(dot(u, u))
    else:
        p = (0.0, 0.0, -u[2] / k[5])
        speed = abs(u[2])
    t = cross(rho, p)
    m = c.mass
    y[1] += p[0] / m
    y[2] += p[1] / m
    y[3] += p[2] / m
    y[7] += t[0]
    y[8] += t[1]
    y[9] += t[2]
    return abs(gap), speed


@njit(cache=True)
def energy(y, c):
    """Mechanical energy of y with a rigid table: ½ m v² + ½ L·ω + m g z, J."""
    return _motion_energy(y, c)


@njit(cache=True)
def below_barrier(y, c):
    """Whether the coin's energy is below its well's barrier: the test of
    the well's barrier (frictionless and
    without resistances, the horizontal kinetic energy is not free and the barrier is the least
    corner energy at the conserved L·n, L_z)."""
    _, free = _motion_free_energy(y, c)
    return free < _barrier(y, c)


@njit(cache=True)
def _classify(y, c):
    """The mode of a state on the constraints with u_z = 0: ROLLING if its slip is below
    :data:`SLIP_FLOOR` and the rolling force lies in the cone, else SLIDING; FREE if the normal
    force would be negative; with the slide's start direction (dx, dy) and PAINLEVE's flag."""
    return _classify_on(y, c, _side(y[6]))


@njit(cache=True)
def _classify_on(y, c, side):
    """:func:`_classify` on the rim ``side`` (:func:`_basis`)."""
    _, _, _, _, _, u = _terms(y, c, side)
    slip = math.sqrt(u[0] * u[0] + u[1] * u[1])
    if slip <= SLIP_FLOOR:
        f = _rolling(y, c, side)
        if f[2] < 0.0:
            return FREE, 0.0, 0.0, False
        if math.sqrt(f[0] * f[0] + f[1] * f[1]) <= c.friction * f[2]:
            return ROLLING, 0.0, 0.0, False
        dx, dy = _slip_start(y, c, side)
    else:
        dx, dy = u[0] / slip, u[1] / slip
    f, coef, _, _ = _force(y, c, SLIDING, dx, dy, side)
    if coef <= 0.0:
        return SLIDING, dx, dy, True
    if f[2] < 0.0:
        return FREE, dx, dy, False
    return SLIDING, dx, dy, False


@njit(cache=True)
def _slip_error(y, h, c, side, k1, k3, k4, k5, k6, k7):
    """The error estimate of a step of h from y in the slip u_h (m/s): δu = δv + (I⁻¹ δL) × ρ
    from the estimates δv, δL (:func:`coinflight.core.dormand_prince.estimate`)."""
    ex = dp.estimate(1, h, k1, k3, k4, k5, k6, k7)
    ey = dp.estimate(2, h, k1, k3, k4, k5, k6, k7)
    dl = (
        dp.estimate(7, h, k1, k3, k4, k5, k6, k7),
        dp.estimate(8, h, k1, k3, k4, k5, k6, k7),
        dp.estimate(9, h, k1, k3, k4, k5, k6, k7),
    )
    n = (y[4], y[5], y[6])
    rho, _, _, _, _, _ = _basis(n, c, side)
    wr = cross(angular_velocity(dl, n, c.i1, c.i3), rho)
    return math.sqrt((ex + wr[0]) ** 2 + (ey + wr[1]) ** 2)


@njit(cache=True)
def _slip_velocity(y, c, side):
    """u = v + ω × ρ, the velocity of the material point at the contact on the rim ``side``,
    m/s (as :func:`_terms` finds it)."""
    n = (y[4], y[5], y[6])
    omega = angular_velocity((y[7], y[8], y[9]), n, c.i1, c.i3)
    rho, _, _, _, _, _ = _basis(n, c, side)
    wr = cross(omega, rho)
    return (y[1] + wr[0], y[2] + wr[1], y[3] + wr[2])


@njit(cache=True)
def _sticks(y, c, side):
    """Whether a sliding contact on the rim ``side`` has stopped: its slip below
    :data:`SLIP_FLOOR` and the rolling force inside the friction cone (and pressing)."""
    w, b, _, _, _, u = _terms(y, c, side)
    if u[0] * u[0] + u[1] * u[1] > SLIP_FLOOR * SLIP_FLOOR:
        return False
    f = _solve3(w, (-b[0], -b[1], -b[2]))
    return f[2] >= 0.0 and math.sqrt(f[0] * f[0] + f[1] * f[1]) <= c.friction * f[2]


@njit(cache=True)
def _run(y, c, duration, settle, max_steps, rtol, approach, counts):
    """The integrator of :func:`advance_rigid` (y in place). ``counts`` (7 floats) receives
    (accepted steps, rejected steps, event steps, mode changes, largest gap removed, largest
    constraint speed removed, time rolling). Returns (time, mode, reason)."""
    for i in range(7):
        counts[i] = 0.0
    n = (y[4], y[5], y[6])
    if 1.0 - n[2] * n[2] < FACE_SINE * FACE_SINE:
        return 0.0, FREE, FACE  # lying on its face: not a one-rim contact
    if c.half_thickness - c.corner_radius > 0.0 and n[2] == 0.0:
        return 0.0, FREE, SECOND_RIM  # upright on its band: both rims touch
    side = _side(n[2])  # the rim the run keeps (_basis)
    rho, _, _, _, _, _ = _basis(n, c, side)
    y[0] = -rho[2]
    lm = (y[7], y[8], y[9])
    omega = angular_velocity(lm, n, c.i1, c.i3)
    uz = y[3] + cross(omega, rho)[2]
    if uz < -approach:
        return 0.0, FREE, NOT_IN_CONTACT
    if uz > approach:
        return 0.0, FREE, LIFT_OFF
    _project_on(y, c, SLIDING, side)  # u_z = 0 by a frictionless normal impulse
    mode, dx, dy, jam = _classify_on(y, c, side)
    if jam:
        return 0.0, mode, PAINLEVE
    if mode == FREE:
        return 0.0, FREE, LIFT_OFF
    if mode == ROLLING:
        _project_on(y, c, ROLLING, side)
    band = 0.0
    if c.half_thickness - c.corner_radius > 0.0:
        band = side
    size = y.shape[0]  # 10, or 12 with the horizontal position (x, y) carried along
    k1, k2, k3, k4, k5, k6, k7, tmp, new = dp.workspace(size)
    trial = np.empty(size)
    scale = np.empty(10)
    reach = c.reach
    speed = max(math.sqrt(c.g * reach), 0.01)
    scale[0] = reach
    for i in range(1, 4):
        scale[i] = speed
        scale[i + 3] = 1.0
        scale[i + 6] = c.i1 * speed / reach
    t = 0.0
    h = 1e-4
    power = np.empty(8)
    seen = np.empty(6)
    power[1] = _flow(y, k1, c, mode, dx, dy, side, seen)
    # The energy the flow should have: the start's, less the work of the contact since
    # (:func:`_step`); each accepted step is put back on it (:func:`_keep_energy`).
    target = _motion_energy(y, c)
    accepted = 0
    stalled = 0
    while True:
        if settle and below_barrier(y, c):
            return t, mode, BELOW_BARRIER
        if t >= duration:
            return t, mode, DURATION
        if accepted >= max_steps:
            return t, mode, MAX_STEPS_REACHED
        # No limit by the turn: the state has no body-fixed angle to resolve
        # (an axisymmetric coin), and the tumbling is the step control's.
        h = min(h, MAX_STEP, duration - t)
        # The slip's direction at the step's start (SLIDING), for its stop event.
        sx, sy, floor = dx, dy, 0.0
        if mode == SLIDING:
            u = _slip_velocity(y, c, side)
            slip = math.sqrt(u[0] * u[0] + u[1] * u[1])
            if slip > STICK_SPEED:
                sx, sy = u[0] / slip, u[1] / slip
            if slip > SLIP_FLOOR:
                floor = SLIP_FLOOR
        err = math.inf
        for _ in range(60):
            work = _step(
                y, h, c, mode, dx, dy, side, k1, k2, k3, k4, k5, k6, k7, tmp, new, power, seen
            )
            err = dp.error_ratio(y, new, h, k1, k3, k4, k5, k6, k7, rtol, scale, 10)
            if mode == SLIDING:
                slip_err = _slip_error(y, h, c, side, k1, k3, k4, k5, k6, k7) / SLIP_ERROR
                if not slip_err <= err:
                    err = slip_err
            if err <= 1.0:
                break
            counts[1] += 1.0
            h *= max(0.2, 0.9 * err**-0.2) if err < math.inf else 0.2  # NaN or ∞: 0.2
        if not err <= 1.0:
            return t, mode, STEP_FAILED
        accepted += 1
        counts[0] += 1.0
        mu = c.friction
        ev = _seen_events(seen, new[6], mu, mode, sx, sy, floor, band)
        if _crossed(ev):
            # Locate the first time an event function crosses: regula falsi on the function
            # that has crossed, Illinois-modified (Dowell & Jarratt 1971, BIT 11:168: the end
            # kept twice has its value halved, so both ends converge), safeguarded by bisection
            # (an iteration that leaves more than half the bracket is followed by a bisection);
            # the bracket, decided by _crossed as before, closes to EVENT_TIME.
            lo, hi = 0.0, h
            e_lo = _events(y, c, mode, dx, dy, sx, sy, floor, band, side)
            e_hi = ev
            f_lo, f_hi = 0.0, 0.0
            which = -1
            kept = 0
            bisect = False
            for i in range(size):
                trial[i] = new[i]
            trial_work = work
            while hi - lo > EVENT_TIME and hi - lo > 1e-15 * hi:
                width = hi - lo
                j = _first_crossed(e_hi)
                if j != which:
                    which = j
                    f_lo, f_hi = e_lo[j], e_hi[j]
                    kept = 0
                if bisect or not (f_lo > 0.0 and f_hi <= 0.0 and f_lo - f_hi > 0.0):
                    mid = 0.5 * (lo + hi)
                else:
                    margin = 0.25 * EVENT_TIME
                    mid = lo + width * (f_lo / (f_lo - f_hi))
                    mid = min(max(mid, lo + margin), hi - margin)
                mid_work = _step(
                    y, mid, c, mode, dx, dy, side, k1, k2, k3, k4, k5, k6, k7, tmp, new, power, seen
                )
                counts[2] += 1.0
                e_mid = _seen_events(seen, new[6], mu, mode, sx, sy, floor, band)
                if _crossed(e_mid):
                    hi = mid
                    e_hi = e_mid
                    f_hi = e_mid[which]
                    for i in range(size):
                        trial[i] = new[i]
                    trial_work = mid_work
                    f_lo = 0.5 * f_lo if kept == 1 else f_lo
                    kept = 1
                else:
                    lo = mid
                    e_lo = e_mid
                    f_lo = e_mid[which]
                    f_hi = 0.5 * f_hi if kept == -1 else f_hi
                    kept = -1
                bisect = hi - lo > 0.5 * width and not bisect
            for i in range(size):
                y[i] = trial[i]
            t += hi
            # Events in a row that each advance less than STALL_TIME: the run has stalled (a
            # slide on the cone's boundary stopping as it starts); the caller restarts it.
            stalled = stalled + 1 if hi < STALL_TIME else 0
            if stalled > STALL_EVENTS:
                return t, mode, STEP_FAILED
            if mode == ROLLING:
                counts[6] += hi
            ev = _events(y, c, mode, dx, dy, sx, sy, floor, band, side)
            if ev[3] < 0.0:
                # Just past n_z = 0 (within EVENT_TIME), on the run's rim to within the step's
                # drift: the caller takes the other rim's arrival from here.
                return t, mode, SECOND_RIM
            gap, drift = _project_on(y, c, SLIDING, side)
            counts[4] = max(counts[4], gap)
            counts[5] = max(counts[5], drift)
            target = _keep_energy(y, c, target + trial_work)
            if ev[4] < 0.0:
                return t, mode, FACE
            if ev[2] <= 0.0:
                return t, mode, PAINLEVE
            if ev[0] < 0.0:
                return t, FREE, LIFT_OFF
            # The slip starts (ROLLING) or stops (SLIDING): the stick test.
            if mode == SLIDING:
                # Its stop: the slip left is below the event's tolerance; test the stick.
                _, _, _, _, _, u = _terms(y, c, side)
                f = _rolling(y, c, side)
                if f[2] >= 0.0 and math.sqrt(f[0] * f[0] + f[1] * f[1]) <= c.friction * f[2]:
                    mode = ROLLING
                else:
                    slip = math.sqrt(u[0] * u[0] + u[1] * u[1])
                    # Reversing or swerving: the slip that is left sets the direction, or, if it
                    # is below the stick speed, the ray.
                    if slip <= STICK_SPEED:
                        dx, dy = _slip_start(y, c, side)
                    else:
                        dx, dy = u[0] / slip, u[1] / slip
            else:
                mode = SLIDING
                dx, dy = _slip_start(y, c, side)
            _, _, _, _, _, u = _terms(y, c, side)
            if mode == ROLLING or u[0] * u[0] + u[1] * u[1] <= STICK_SPEED * STICK_SPEED:
                # Rolling, or a slide starting from rest of the contact point: u_h = 0.
                _project_on(y, c, ROLLING, side)
            if mode == SLIDING:
                f, coef, _, _ = _force(y, c, SLIDING, dx, dy, side)
                if coef <= 0.0:
                    return t, mode, PAINLEVE
                if f[2] < 0.0:
                    return t, FREE, LIFT_OFF
            counts[3] += 1.0
            power[1] = _flow(y, k1, c, mode, dx, dy, side, seen)
            target = _motion_energy(y, c)  # after the stick's impulse, if any
            h = max(h, 1e-7)
            continue
        t += h
        if mode == ROLLING:
            counts[6] += h
        for i in range(size):
            y[i] = new[i]
        gap, drift = _project_on(y, c, mode, side)
        counts[4] = max(counts[4], gap)
        counts[5] = max(counts[5], drift)
        target = _keep_energy(y, c, target + work)
        # First same as last: k7, the derivative at the step's end before the projection (which
        # moves the state by the drift reported, ≲1e-11 m and 1e-9 m/s, measured: far below the
        # step's tolerance), kept across n's renormalisation.
        for i in range(size):
            k1[i] = k7[i]
        power[1] = power[7]
        h *= min(5.0, 0.9 * err**-0.2) if err > 0.0 else 5.0
        if mode == SLIDING and _sticks(y, c, side):
            # A slide below SLIP_FLOOR whose rolling force is back inside the cone has stopped
            # (the stick test of a slip's stop, for a slide that started below the floor and
            # never crossed it: one hovering on the cone's boundary would otherwise be followed
            # with steps shrinking as its slip turns).
            mode = ROLLING
            _project_on(y, c, ROLLING, side)
            counts[3] += 1.0
            power[1] = _flow(y, k1, c, mode, dx, dy, side, seen)
            target = _motion_energy(y, c)


class RigidRun(NamedTuple):
    """What :func:`advance_rigid` did.

    Attributes
    ----------
    time : float
        Simulated time advanced, s.
    mode : int
        The mode at the end (:data:`FREE`, :data:`ROLLING`, :data:`SLIDING`).
    reason : int
        Why it stopped (:data:`DURATION`, :data:`LIFT_OFF`, :data:`SECOND_RIM`, :data:`FACE`,
        :data:`PAINLEVE`, :data:`BELOW_BARRIER`, :data:`MAX_STEPS_REACHED`,
        :data:`NOT_IN_CONTACT`, :data:`STEP_FAILED`; names in :data:`REASON_NAMES`).
    steps, rejected, event_steps : int
        Accepted steps, rejected trial steps, steps spent locating events.
    switches : int
        Mode changes (slip starts and stops).
    gap_drift, speed_drift : float
        The largest gap (m) and constraint speed (m/s) removed by a projection.
    rolling_time : float
        Time spent rolling, s.
    """

    time: float
    mode: int
    reason: int
    steps: int
    rejected: int
    event_steps: int
    switches: int
    gap_drift: float
    speed_drift: float
    rolling_time: float


def advance_rigid(
    y: np.ndarray,
    c: Contact,
    duration: float,
    *,
    settle: bool = False,
    max_steps: int = MAX_STEPS,
    rtol: float = RTOL,
    approach: float = APPROACH,
) -> RigidRun:
    """Advance the coin in state ``y`` = (z, vx, vy, vz, nx, ny, nz, Lx, Ly, Lz) (modified in
    place) touching the table at one
    rim point, rigid, for ``duration`` s or until an event it cannot carry on through.

    Parameters
    ----------
    y : ndarray, shape (10,) or (12,)
        The state; with 12 entries the last two are the horizontal position (x, y) of the
        centre of mass, m, carried along (integrated, outside the step's error control). z is
        first set so that the lowest rim point touches the table (gap 0), and a
        normal contact speed within ``approach`` is removed by a frictionless normal impulse.
    c : Contact
        The coin, the surface (μ, rolling and pivoting resistance; e is not used: no impact
        here) and g (:class:`coinflight.core.contact.Contact`). Any corner radius.
    duration : float
        Simulated time at most, s (math.inf: no limit).
    settle : bool
        Also stop when the energy is below the well's barrier (:func:`below_barrier`).
    max_steps : int
        Accepted steps at most.
    rtol : float
        Relative tolerance of the step control (positive and finite; not checked).
    approach : float
        Normal speed of the contact point, m/s, below which a start state counts as touching;
        approaching faster: :data:`NOT_IN_CONTACT` (an impact is needed first); leaving faster:
        :data:`LIFT_OFF`.

    Returns
    -------
    RigidRun
        Time, end mode, why it stopped, step counts and the projections' drift.
    """
    counts = np.zeros(7)
    t, mode, reason = _run(y, c, float(duration), settle, int(max_steps), rtol, approach, counts)
    return RigidRun(
        float(t),
        int(mode),
        int(reason),
        int(counts[0]),
        int(counts[1]),
        int(counts[2]),
        int(counts[3]),
        float(counts[4]),
        float(counts[5]),
        float(counts[6]),
    )


@njit(cache=True)
def steady_spin(tilt, precession, c):
    """ψ', the spin relative to the precessing frame, of a coin rolling steadily on its rim at
    the tilt ``tilt`` (of n from Z) and the precession rate Ω (no resistances), rad/s.

    Steady rolling (O'Reilly 1996, §5; Cushman, Hermans & Kemppainen 1995): n turns about Z at
    Ω, ω = Ω Z + ψ' n, the contact point at rest, v = −ω × ρ, so ma = m Ω Z × v and L̇ = Ω Z × L
    = ρ × (m Ω Z × v + m g Z). In the frame where n = (sin α, 0, cos α), ρ = (ρ_x, 0, ρ_z), the
    one component of that equation (along Z × n) is linear in ψ':

        ψ' = (m Ω² ρ_x ρ_z − m g ρ_x − Ω² (I3 − I1) s c) / (Ω (s I3 + m ρ_z (s ρ_z − c ρ_x))),

    s = sin α, c = cos α. A thin disc (ρ_x = r c, ρ_z = −r s): ψ' = −(m r Ω² r s c + m g r c +
    Ω² (I3 − I1) s c) / (Ω s (I3 + m r²)), the classical relation of the rolling disk.
    """
    n = (math.sin(tilt), 0.0, math.cos(tilt))
    rho = contact_point(n, c.radius, c.half_thickness, c.corner_radius)
    s, co = n[0], n[2]
    m = c.mass
    num = m * precession**2 * rho[0] * rho[2] - m * c.g * rho[0]
    num -= precession**2 * (c.i3 - c.i1) * s * co
    den = precession * (s * c.i3 + m * rho[2] * (s * rho[2] - co * rho[0]))
    return num / den


__all__ = [
    "BELOW_BARRIER",
    "DURATION",
    "FACE",
    "FREE",
    "LIFT_OFF",
    "MAX_STEPS_REACHED",
    "NOT_IN_CONTACT",
    "PAINLEVE",
    "ROLLING",
    "SECOND_RIM",
    "SLIDING",
    "STEP_FAILED",
    "RigidRun",
    "advance_rigid",
    "below_barrier",
    "energy",
    "steady_spin",
]
