"""Flight through air, compiled: quadratic drag on the projected area and linear spin damping.

One integrator (numba) carries a toss from launch to a hand catch at launch height
(:func:`catch`) or to rest on a table (:func:`land`, with the impacts of
:func:`coinflight.core.impact.impact` and the ending rules of :mod:`coinflight.core.bounce`).

Equations of motion (lab frame, SI; heads normal n, angular momentum L about the centre of mass,
symmetric top with moments I1 about a diameter and I3 about the axis):

    dv/dt = −g Z − (ρ C_d A(n·v̂) / 2m) |v| v
    A(c) = π r² |c| + 2 r h sqrt(1 − c²)                    (c = n·v̂)
    dL/dt = −K ω,   ω = I⁻¹ L = L/I1 + (1/I3 − 1/I1)(L·n) n,   dn/dt = ω × n

Drag. A(c) is the area of the coin's silhouette seen along the flow: a right circular cylinder
of radius r and thickness h viewed at an angle θ from its axis (cos θ = c) shows its face as an
ellipse of area π r² |cos θ| and its side as a 2r × h sin θ rectangle, which do not overlap.
One drag coefficient C_d is applied to that area for every attitude: an assumption (quasi-steady
drag with the coefficient of a disc broadside on, 1.17, Hoerner, *Fluid-Dynamic Drag*, 1965,
ch. 3; a thin disc edge-on has its own coefficient, not modelled separately), which replaces the
fixed face area of the previous model (quadratic drag on a fixed area, as Strzałko et al. 2008
are reported to use: not checked in their paper; ``projected=False`` keeps it, for comparison).
The drag acts at the centre of mass: the aerodynamic torques of a tumbling disc (lift, a centre
of pressure off the centre) are not modelled.

Spin damping. The torque is −K ω (K in N m s, ``Drag.spin_damping``). It is not isotropic in I
(the torque −k I ω would be, and reduces to the torque-free motion in the rescaled time
(1 − e^{−kt})/k), so the motion is solved as follows. Writing L = a n + b with a = L·n and b ⊥
n, the equations give ȧ = −(K/I3) a and d|b|/dt = −(K/I1) |b| exactly (the torque-free
coupling only turns b), so

    a(t) = a0 e^{−K t / I3},   |b|(t) = |b0| e^{−K t / I1}

in closed form, and the triad (n, u = b/|b|, n × u) turns with the angular velocity L/I1,
which has the components (a, |b|, 0)/I1 in that triad. Its rotation is integrated by the
fourth-order Magnus method with two Gauss-Legendre points (Blanes, Casas, Oteo & Ros,
*Phys. Rep.* 470:151, 2009):
over a step h the triad turns by the rotation vector

    θ = ∫ (a n + |b| u)/I1 dt + (√3/12) h² ω1 × ω2

(ω1, ω2 the triad's angular velocity at the two Gauss points), the first term integrated
exactly. Without damping the first term is the whole rotation: the torque-free precession of
n about the fixed L at the rate |L|/I1 (Diaconis, Holmes & Montgomery 2007 §2, as
:func:`coinflight.core.flight.precess`) to rounding error, so K = 0 reproduces the closed form
whatever the step. The damping's only time scale limits a step to ``DECAY_STEP`` · min(I1, I3)/K
until the spin that remains could turn the coin by less than 1e-12 rad; after that the attitude is
frozen, so any K ≥ 0 (1e3 N m s on a 1 mm coin) ends in a bounded number of steps.

Translation: Runge-Kutta in t on (z, v), with n at the stages t0, t0 + h/2, t0 + h from the
Magnus half steps. Where the drag barely depends on the velocity within a step (its relaxation
rate times the step, c |v| h with c = ρ C_d A_max / 2m, below ``KUTTA_DRAG`` = 2e-3: every
step of a US nickel spinning at 150 rad/s or more below 8 m/s) the step is Kutta's third-order
rule, three evaluations of the acceleration with Simpson's weights on those stages (Hairer,
Nørsett & Wanner, *Solving Ordinary Differential Equations I*, 2nd ed., 1993, §II.1, Table
1.1); elsewhere (a slow spin's longer steps, a light coin near its terminal speed) it is
classical RK4, four evaluations. For a toss the two differ only through the velocity
dependence of the drag, of relative size (c |v| h)^k, k ≥ 1, per step. Both are exact for the
vacuum parabola, so C_d = K = 0 reproduces :mod:`coinflight.core.ballistics` too. The face
drag's share of each step, −c π r² ∫ |n·v| v dt, is not left to the rule's Simpson weights
(which integrate the kink of |n·v| twice a turn to first order, and the turning attitude with a
relative error (θ/2)⁴/180 of one sign for a turn θ a step): :func:`kink_integrals` interpolates
n·v and (n·v) v on the three stages in the basis 1, cos, sin of the turn (exact for a frozen v
and a uniform turn, Rodrigues' formula), locates the kinks in closed form and integrates piece
by piece; the step's velocity and height are corrected by the difference. The side's share
(2 r h |n × v|, 12 % of the face's on a nickel) keeps the rule's weights.
A step turns the coin by at most ``TURN_STEP`` rad without damping, ``DAMPED_TURN_STEP`` with
it (the projected area changes with the attitude), lasts at most ``MAX_STEP`` s and at most
``DRAG_STEP``/(c |v|). In the landing, a step that cannot bring any point of the coin to the
surface (its centre stays higher than the coin's reach, falling at most −min(v_z, 0) h + g h²/2:
falling, the drag only slows it) skips the contact search.

Accuracy. Against SciPy's DOP853 at rtol 1e-12 (:func:`coinflight.core.numerical.air_catch`)
the catch time of vigorous tosses of a US nickel (ωx 150-300 rad/s, v0 1.5-3 m/s) is off by
about 3e-7 s (median) and under 1e-6 s (worst), n_z by at most 2e-4, and the first contact with
a table 0.8 m below launch by about 1e-6 s (median) and a few 1e-6 s (worst)
(``python benchmarks/bench_air.py --accuracy 40``). For scale, the drag itself moves the catch
by ~4e-3 s and a 10 % change of C_d by ~4e-4 s; tests/test_drag.py checks 1e-5 s.
``TURN_STEP`` = 2π/(2 + (√5 − 1)/2) ≈ 2.40 rad keeps the step incommensurate with the half turn
(the kinks fall at spread phases of the steps); without the kink integrals the same step would
be an order of magnitude less accurate.

Events. The catch is the centre of mass coming back down to launch height; the table contact
is the coin's lowest point reaching the surface (:func:`next_contact`). Far from it the steps
are the longest above. Near it, without spin damping, the attitude is the vacuum's torque-free
precession (the steps compute exactly that) and the centre of mass falls at most D τ²/2 below
the vacuum parabola, D bounding the drag's deceleration: conservative advancement (Mirtich
1996, §3.4) on that lower bound of the gap (:func:`lower_gap`, :func:`bound_search`; closed-form
evaluations, not steps of the integrator) gives the step's length, and the coin leaves the
surface after an impact when the bound says it has (:func:`lift`, no step taken). With damping
the bound on the gap comes from the current state alone and each advancement is a step. A step
that ends below the surface brackets the contact, and one that the search stopped while the
coin approaches starts a safeguarded Newton iteration on the length of one step from that
step's start (a step of any length from a state is a smooth function of its length), to
GAP_TOLERANCE.

Cost: about 35 µs of one core a toss carried to rest on a table (``python
benchmarks/bench_air.py --profile 20000`` times the phases), roughly a third each in the first
flight (~70 steps of ~2.4 rad), the bounce flights and the impacts
(:func:`coinflight.core.impact.impact`). The steps are allocation-free (tuples of scalars) and
run on numba's threads, one toss per iteration; a toss carried to rest through air costs the
flights' ~100 steps on top of the vacuum landing's impacts.

Accuracy of a bounce flight (``python benchmarks/bench_air.py --accuracy 40``): from the state
after DOP853's own first impact to the next contact, 1.7e-10 s (median) and 4.7e-6 s (largest)
off DOP853 at rtol 1e-12; the second contact from launch (the first flight's error carried
through the impact) 1.9e-6 s (median) and 3e-4 s (largest).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, NamedTuple

import numpy as np
from numpy.typing import NDArray

from coinflight.core._jit import njit, prange
from coinflight.core.bounce import (
    MAX_IMPACTS,
    after_impact,
    batch_inputs,
    run_batch,
    with_surface,
)
from coinflight.core.contact import Contact
from coinflight.core.flight import (
    CA_TOLERANCE,
    GAP_TOLERANCE,
    GRAZE_SKIP,
    precess,
)
from coinflight.core.impact import (
    angular_velocity,
    contact_point,
    cross,
    dot,
    impact,
    lowest_depth,
    resting_face,
)
from coinflight.core.outcome import Status

if TYPE_CHECKING:
    from coinflight.core.bounce import Landed

FloatArray = NDArray[np.float64]

TURN_STEP = 2.0 * math.pi / (2.0 + 0.5 * (math.sqrt(5.0) - 1.0))
"""Largest rotation of the coin in one step without spin damping, rad (see the notes on
accuracy)."""
DAMPED_TURN_STEP = 2.0 * math.pi / (6.0 + 0.5 * (math.sqrt(5.0) - 1.0))
"""Largest rotation in one step with spin damping, rad: the Magnus steps' error grows with
the turn (at TURN_STEP, n off DOP853 by 7e-5 in the strong-damping test, 7e-6 at this)."""
MAX_STEP = 1.0 / 64.0
"""Longest step, s."""
DRAG_STEP = 0.02
"""Largest step in units of the velocity's relaxation time 1/(c |v|)."""
KUTTA_DRAG = 2e-3
"""Steps in which the drag's relaxation rate times the step, c A_max |v| h, is below this take
Kutta's third-order rule (three evaluations of the acceleration), the others RK4."""
DECAY_STEP = 0.5
"""Largest step in units of the spin damping's time min(I1, I3)/K while the spin still turns
the coin."""
FROZEN_TURN = 1e-12
"""Once the spin that remains can turn the coin by less than this (rad), its attitude is frozen."""
SEARCH_STEPS = 100_000
"""Steps of :func:`bound_search` at most (it then hands back the length it has reached)."""
FAR_MARGIN = 1e-6
"""A flight step skips the contact search when the coin stays this far above the surface, m."""
MAX_STEPS = 1_000_000
"""Steps per toss at most: a toss that needs more ends with status UNSETTLED (table) or a
negative catch time (hand); :func:`coinflight.outcomes.air.check_air` refuses, before any
work, the air in which a toss would need more (:func:`steps_needed`)."""
SQRT3_12 = math.sqrt(3.0) / 12.0
GAUSS = math.sqrt(3.0) / 6.0
"""The Gauss-Legendre points of a step h from t0 are t0 + (½ ∓ GAUSS) h."""
# Status codes as plain ints for the compiled loops (core.outcome.Status).
_LIMIT = int(Status.BOUNCE_LIMIT)
_UNSETTLED = int(Status.UNSETTLED)


class Air(NamedTuple):
    """A coin in air, as the kernels read it (SI units): built by :meth:`Air.build`.

    Attributes
    ----------
    mass, radius, thickness, i1, i3, g : float
        The coin (kg, m, m, kg m², kg m²) and gravity (m/s²).
    drag_factor : float
        ρ C_d / 2m, 1/m³: times an area A and |v| v, the drag deceleration.
    spin_damping : float
        K of the damping torque −K ω, N m s.
    projected : float
        1.0: A is the projected area of the coin seen along its velocity; 0.0: the face area
        π r² whatever the attitude (the previous model).
    max_area : float
        Largest projected area, sqrt((π r²)² + (2 r h)²) (1.0) or π r² (0.0), m².
    """

    mass: float
    radius: float
    thickness: float
    i1: float
    i3: float
    g: float
    drag_factor: float
    spin_damping: float
    projected: float
    max_area: float

    @classmethod
    def build(
        cls,
        *,
        mass: float,
        radius: float,
        thickness: float,
        i1: float,
        i3: float,
        g: float,
        drag_coefficient: float,
        spin_damping: float,
        air_density: float,
        projected: bool = True,
    ) -> Air:
        """The record; no validation (the value layer has checked every value)."""
        face = math.pi * radius * radius
        side = 2.0 * radius * thickness
        return cls(
            mass=float(mass),
            radius=float(radius),
            thickness=float(thickness),
            i1=float(i1),
            i3=float(i3),
            g=float(g),
            drag_factor=0.5 * float(air_density) * float(drag_coefficient) / float(mass),
            spin_damping=float(spin_damping),
            projected=1.0 if projected else 0.0,
            max_area=math.hypot(face, side) if projected else face,
        )


@njit(cache=True)
def projected_area(c: float, radius: float, thickness: float) -> float:
    """Area of a cylinder's silhouette seen along a direction at cos θ = c from its axis, m².

    π r² |c| (the face, an ellipse) + 2 r h sqrt(1 − c²) (the side, a rectangle).
    """
    s2 = 1.0 - c * c
    return math.pi * radius * radius * abs(c) + 2.0 * radius * thickness * math.sqrt(
        s2 if s2 > 0.0 else 0.0
    )


@njit(cache=True, error_model="numpy")
def _acceleration(v: tuple, n: tuple, air: Air) -> tuple:
    """dv/dt: gravity and the quadratic drag c A |v| v, c = ρ C_d / 2m, on the projected area
    A = π r² |n·v̂| + 2 r h sqrt(1 − (n·v̂)²) (or the face area): A |v| = π r² |n·v| + 2 r h
    |n × v|, one square root."""
    if air.projected > 0.0:
        # |v| sqrt(1 − (n·v̂)²) = |n × v|, accurate when broadside on (unlike |v|² − (n·v)²).
        nxv = cross(n, v)
        area_speed = math.pi * air.radius * air.radius * abs(dot(n, v)) + 2.0 * air.radius * (
            air.thickness * math.sqrt(dot(nxv, nxv))
        )
    else:
        area_speed = math.pi * air.radius * air.radius * math.sqrt(dot(v, v))
    k = air.drag_factor * area_speed
    return (-k * v[0], -k * v[1], -air.g - k * v[2])


@njit(cache=True, error_model="numpy")
def _decay(rate: float, t0: float, h: float) -> tuple:
    """(e^{−rate t0}, ∫_{t0}^{t0+h} e^{−rate t} dt)."""
    e0 = math.exp(-rate * t0)
    if rate == 0.0:
        return e0, h
    x = rate * h
    if x < 1e-8:
        return e0, e0 * h * (1.0 - 0.5 * x)
    return e0, -e0 * math.expm1(-x) / rate


@njit(cache=True, error_model="numpy")
def _rotate(x: tuple, axis: tuple, c: float, s: float) -> tuple:
    """x turned about the unit vector ``axis`` by the angle of cosine c and sine s (Rodrigues)."""
    d = dot(axis, x) * (1.0 - c)
    w = cross(axis, x)
    return (
        x[0] * c + w[0] * s + axis[0] * d,
        x[1] * c + w[1] * s + axis[1] * d,
        x[2] * c + w[2] * s + axis[2] * d,
    )


@njit(cache=True, error_model="numpy")
def rotation(n: tuple, u: tuple, t0: float, h: float, a0: float, b0: float, air: Air) -> tuple:
    """(axis, cos, sin, angle) of the triad's turn over a step h from t0 (times since a0, b0
    were set): fourth-order Magnus (see the module notes), exact when K = 0."""
    k = air.spin_damping
    if k == 0.0:
        ta = a0 * h / air.i1  # ∫ a/I1 dt, along n
        tb = b0 * h / air.i1  # ∫ |b|/I1 dt, along u
        tw = 0.0
    else:
        _, int3 = _decay(k / air.i3, t0, h)
        _, int1 = _decay(k / air.i1, t0, h)
        ta = a0 * int3 / air.i1
        tb = b0 * int1 / air.i1
        # (√3/12) h² (ω1 × ω2)·w with ω = (a, |b|, 0)/I1 at the Gauss points t0 + (½ ∓ √3/6) h.
        s1 = t0 + (0.5 - GAUSS) * h
        s2 = t0 + (0.5 + GAUSS) * h
        al1 = a0 * math.exp(-k * s1 / air.i3)
        al2 = a0 * math.exp(-k * s2 / air.i3)
        be1 = b0 * math.exp(-k * s1 / air.i1)
        be2 = b0 * math.exp(-k * s2 / air.i1)
        tw = SQRT3_12 * h * h * (al1 * be2 - be1 * al2) / (air.i1 * air.i1)
    w = cross(n, u)
    theta = (
        ta * n[0] + tb * u[0] + tw * w[0],
        ta * n[1] + tb * u[1] + tw * w[1],
        ta * n[2] + tb * u[2] + tw * w[2],
    )
    angle = math.sqrt(dot(theta, theta))
    if angle == 0.0:
        return (0.0, 0.0, 1.0), 1.0, 0.0, 0.0
    inv = 1.0 / angle
    axis = (theta[0] * inv, theta[1] * inv, theta[2] * inv)
    return axis, math.cos(angle), math.sin(angle), angle


@njit(cache=True)
def turn(n: tuple, u: tuple, t0: float, h: float, a0: float, b0: float, air: Air) -> tuple:
    """The triad (n, u) after a step h from t0 (:func:`rotation`)."""
    axis, c, s, _ = rotation(n, u, t0, h, a0, b0, air)
    return _rotate(n, axis, c, s), _rotate(u, axis, c, s)


@njit(cache=True)
def angular_momentum(n: tuple, u: tuple, t: float, a0: float, b0: float, air: Air) -> tuple:
    """L = a(t) n + |b|(t) u at time t since a0, b0 were set (the closed-form decays)."""
    a = a0
    b = b0
    if air.spin_damping > 0.0:
        a *= math.exp(-air.spin_damping * t / air.i3)
        b *= math.exp(-air.spin_damping * t / air.i1)
    return (a * n[0] + b * u[0], a * n[1] + b * u[1], a * n[2] + b * u[2])


@njit(cache=True)
def split(lm: tuple, n: tuple) -> tuple:
    """(a, |b|, u): L = a n + |b| u with u ⊥ n a unit vector (any, when b = 0)."""
    a = dot(lm, n)
    b = (lm[0] - a * n[0], lm[1] - a * n[1], lm[2] - a * n[2])
    bm = math.sqrt(dot(b, b))
    if bm > 0.0:
        return a, bm, (b[0] / bm, b[1] / bm, b[2] / bm)
    # Any unit vector perpendicular to n.
    p = (1.0, 0.0, 0.0) if abs(n[0]) < 0.9 else (0.0, 1.0, 0.0)
    q = cross(n, p)
    qm = math.sqrt(dot(q, q))
    return a, 0.0, (q[0] / qm, q[1] / qm, q[2] / qm)


@njit(cache=True)
def step(z, v, n, u, t0, h, a0, b0, air):
    """One step of length h of the centre of mass (height z, velocity v: Kutta's third-order
    rule or RK4, see the module notes) and the Magnus half steps of the attitude (n, u); t0
    counts from the setting of a0, b0."""
    axis, c, s, angle = rotation(n, u, t0, 0.5 * h, a0, b0, air)
    return step_turning(z, v, n, u, t0, h, a0, b0, air, axis, c, s, 2.0 * angle)


NO_TURN = (-1.0, (0.0, 0.0, 1.0), 1.0, 0.0, 0.0)
"""The ``turned`` of :func:`cached_step` before a first step: none to reuse."""


@njit(cache=True, inline="always")
def cached_step(z, v, n, u, t0, h, a0, b0, air, turned):
    """:func:`step`, reusing the first half step's turn of the step before: (z, v, n, u, turned).

    ``turned`` is (h, axis, cos, sin, θ) of the previous step (:data:`NO_TURN` at first): without
    spin damping a half step's turn depends on its length only (the triad turns about the fixed
    L at the rate |L|/I1), so it is computed again (:func:`rotation`) only for a new length or
    with damping, and returned for the next step."""
    if h != turned[0] or air.spin_damping > 0.0:
        axis, c, s, angle = rotation(n, u, t0, 0.5 * h, a0, b0, air)
        turned = (h, axis, c, s, 2.0 * angle)
    z1, v1, n1, u1 = step_turning(
        z, v, n, u, t0, h, a0, b0, air, turned[1], turned[2], turned[3], turned[4]
    )
    return z1, v1, n1, u1, turned


@njit(cache=True, error_model="numpy", inline="always")
def _lagrange_primitives(y: float) -> tuple:
    """Primitives at y of the three quadratic Lagrange basis functions on the nodes 0, 1/2, 1
    and of the same times (1 − x)."""
    y2 = y * y
    y3 = y2 * y
    y4 = y3 * y
    return (
        2.0 * y3 / 3.0 - 1.5 * y2 + y,
        2.0 * y2 - 4.0 * y3 / 3.0,
        2.0 * y3 / 3.0 - 0.5 * y2,
        -0.5 * y4 + 5.0 * y3 / 3.0 - 2.0 * y2 + y,
        2.0 * y2 - 8.0 * y3 / 3.0 + y4,
        -0.5 * y4 + y3 - 0.5 * y2,
    )


@njit(cache=True, error_model="numpy", inline="always")
def _piece(x0: float, x1: float, sign: float, w: tuple) -> tuple:
    """sign times the integrals over [x0, x1] of the three quadratic Lagrange basis functions
    on the nodes 0, 1/2, 1 (first three) and of the same times (1 − x) (last three); ``w`` adds.
    (Scalars only: no array or list is allocated.)"""
    f0 = _lagrange_primitives(x0)
    f1 = _lagrange_primitives(x1)
    return (
        w[0] + sign * (f1[0] - f0[0]),
        w[1] + sign * (f1[1] - f0[1]),
        w[2] + sign * (f1[2] - f0[2]),
        w[3] + sign * (f1[3] - f0[3]),
        w[4] + sign * (f1[4] - f0[4]),
        w[5] + sign * (f1[5] - f0[5]),
    )


@njit(cache=True, error_model="numpy", inline="always")
def unit_scaled(g0: float, g1: float, g2: float) -> tuple:
    """``g0, g1, g2`` times the power of two that brings the largest in size into [1/2, 1)
    (unchanged if all are 0 or one is not finite): their roots and signs are the same, and the
    scaling is exact (Goldberg, "What every computer scientist should know about floating-point
    arithmetic", ACM Computing Surveys 23, 1991, §1.2: a power of two changes the exponent only),
    so that b² − 4ac formed from them neither underflows nor overflows (nodes of 1e-300 once
    made it 0 and lost a root). Where the products of the unscaled nodes stay normal numbers
    (every ordinary step) the roots found from the scaled ones are the same bit for bit."""
    big = max(abs(g0), abs(g1), abs(g2))
    if big == 0.0 or not big < math.inf:
        return g0, g1, g2
    e = -math.frexp(big)[1]
    return math.ldexp(g0, e), math.ldexp(g1, e), math.ldexp(g2, e)


@njit(cache=True, error_model="numpy", inline="always")
def one_sign(g0: float, gm: float, g2: float) -> float:
    """The sign of g = n·v over a step in which no root of its interpolant was found, from its
    values at the stages x = 0, 1/2, 1: that of the one largest in size. If g has no root in
    the step, all three share it; a root may also have been missed by rounding, but, with the
    nodes scaled to order 1 first (:func:`unit_scaled`, so that the discriminant neither
    underflows nor overflows), only within rounding of an end (where g is then tiny) or as two
    roots within rounding of each other (a discriminant rounded below 0: g tiny between
    them), and then g keeps the sign of its largest node on all but a rounding-sized part of
    the step. (Taking g1's sign there, or an end's, once gave the whole step the wrong sign:
    an O(1) error in its drag integral. Unscaled nodes of 1e-300 made the discriminant 0
    where it is not, and missed two roots far apart.)"""
    if abs(g0) >= abs(gm) and abs(g0) >= abs(g2):
        big = g0
    elif abs(gm) >= abs(g2):
        big = gm
    else:
        big = g2
    return 1.0 if big >= 0.0 else -1.0


@njit(cache=True, error_model="numpy")
def kink_weights(g0: float, g1: float, g2: float) -> tuple:
    """Quadrature weights for the face drag's |n·v| v over a step whose n·v changes sign.

    The step's stages sample g = n·v at x = 0, 1/2, 1 (in units of the step) and the smooth
    product Q = (n·v) v there. With g and Q replaced by their quadratic interpolants g_q, Q_q on
    those nodes, ∫₀¹ sign(g_q) Q_q dx = Σ W_i Q_i and ∫₀¹ (1 − x) sign(g_q) Q_q dx = Σ M_i Q_i
    exactly: the integrals of the Lagrange basis between the roots of g_q (a quadratic), with
    the sign of g_q on each piece. Without a root in (0, 1) they are Simpson's weights (1/6,
    2/3, 1/6) and (1/6, 1/3, 0) times the sign, i.e. the Runge-Kutta step's own quadrature of
    the velocity and (through ∫ (1 − x) a dx) of the position (Hairer, Nørsett & Wanner, *Solving
    Ordinary Differential Equations I*, 2nd ed., 1993, §II.1); with a root the step's stage
    values sample a kink, which Simpson's rule integrates to first order only (an error ∝ h²
    a step, the dominant error of the flight), while this quadrature is exact for piecewise
    quadratics with the kink at the interpolant's root. The idea is the one of quadrature for
    piecewise-smooth integrands with located breakpoints (Davis & Rabinowitz, *Methods of
    Numerical Integration*, 2nd ed., 1984, §2.12).

    Returns (W0, W1, W2, M0, M1, M2, found): found is False (and the weights Simpson's times
    the sign of :func:`one_sign`) when no root of g_q is found in (0, 1). Each piece between the
    roots found takes g_q's sign at its middle, so that a root within rounding of an end, put
    on either side of it, changes the weights by rounding only (as in :func:`kink_integrals`).
    """
    g0, g1, g2 = unit_scaled(g0, g1, g2)
    c = g0
    a = 2.0 * g0 - 4.0 * g1 + 2.0 * g2
    b = -3.0 * g0 + 4.0 * g1 - g2
    r1 = 2.0
    r2 = 2.0
    if a == 0.0:
        if b != 0.0:
            r1 = -c / b
    else:
        disc = b * b - 4.0 * a * c
        if disc >= 0.0:
            q = -0.5 * (b + math.copysign(math.sqrt(disc), b))
            if q != 0.0:
                r1 = q / a
                r2 = c / q
            else:  # b = 0 and a c = 0 with a ≠ 0: c = 0, a double root at 0
                r1 = 0.0
    if not 0.0 < r1 < 1.0:
        r1 = 2.0
    if not 0.0 < r2 < 1.0:
        r2 = 2.0
    if r2 < r1:
        r1, r2 = r2, r1
    if r1 > 1.0:
        s = one_sign(g0, g1, g2)
        return s / 6.0, 2.0 * s / 3.0, s / 6.0, s / 6.0, s / 3.0, 0.0, False
    w = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    x0 = 0.0
    for x1 in (r1, r2, 1.0):
        if x1 > 1.0:
            continue
        if x1 > x0:
            xm = 0.5 * (x0 + x1)
            w = _piece(x0, x1, 1.0 if (a * xm + b) * xm + c >= 0.0 else -1.0, w)
            x0 = x1
    return w[0], w[1], w[2], w[3], w[4], w[5], True


TRIG_KINK = 0.3
"""Steps turning the coin by more than this (rad) interpolate n·v in the basis 1, cos, sin of
the turn (:func:`kink_integrals`), shorter ones by a quadratic (:func:`kink_weights`)."""
TRIG_COS = math.cos(0.5 * TRIG_KINK)


@njit(cache=True, error_model="numpy", inline="always")
def _primitives(x: float, cx: float, sx: float, it: float) -> tuple:
    """Primitives at x of (1, cos θx, sin θx) and of (1 − x) times them, given cos θx, sin θx
    and it = 1/θ: x, sin θx / θ, −cos θx / θ and, with ∫ x cos θx = x sin θx / θ + cos θx / θ²
    and ∫ x sin θx = −x cos θx / θ + sin θx / θ², those minus the x-weighted ones."""
    pc = sx * it
    ps = -cx * it
    return (
        x,
        pc,
        ps,
        x - 0.5 * x * x,
        pc - x * pc - cx * it * it,
        ps - x * ps - sx * it * it,
    )


@njit(cache=True, error_model="numpy", inline="always")
def _add_root(tot: tuple, t: float, it: float, d: float) -> tuple:
    """``tot`` + ``d`` times :func:`_primitives` at the root x = 2 arctan(t)/θ of g
    (t = tan(θx/2), it = 1/θ), ``d`` the sign of g before it minus the sign after it."""
    t2 = t * t
    inv = 1.0 / (1.0 + t2)
    fr = _primitives(2.0 * math.atan(t) * it, (1.0 - t2) * inv, 2.0 * t * inv, it)
    return (
        tot[0] + d * fr[0],
        tot[1] + d * fr[1],
        tot[2] + d * fr[2],
        tot[3] + d * fr[3],
        tot[4] + d * fr[4],
        tot[5] + d * fr[5],
    )


@njit(cache=True, error_model="numpy")
def kink_integrals(g0, gm, g2, q0, qm, q2, c, s, theta):
    """(∫₀¹ sign(g) Q dx, ∫₀¹ (1 − x) sign(g) Q_z dx): the face drag's share of a step.

    x is the time in units of the step; g = n·v and the vector Q = (n·v) v are known at the
    stages x = 0, 1/2, 1 (``g0, gm, g2``; ``q0, qm, q2``); ``c, s`` are the cosine and sine of
    the coin's turn θ/2 over half the step, ``theta`` is θ. While the coin turns uniformly about
    a fixed axis (no damping) and v is frozen, n·v = p + q cos θx + r sin θx exactly (Rodrigues'
    formula), and so is each component of Q: both are interpolated on the three nodes in the
    basis 1, cos θx, sin θx, the roots of g found in closed form (with t = tan(θx/2), p + q cos
    θx + r sin θx = 0 is a quadratic in t) and sign(g) Q integrated exactly piece by piece. Only
    the change of v within the step (gravity, the drag) and, with damping, the turn's
    non-uniformity are left to the interpolation. This is quadrature of a piecewise-smooth
    integrand with its breakpoints located (Davis & Rabinowitz, *Methods of Numerical
    Integration*, 2nd ed., 1984, §2.12) with trigonometric interpolation for the rotation, in
    place of the Runge-Kutta rule's own Simpson weights (Hairer, Nørsett & Wanner, *Solving
    Ordinary Differential Equations I*, 2nd ed., 1993, §II.1), which integrate the kink of |n·v|
    to first order only and the turning attitude with a relative error (θ/2)⁴/180 of one sign.
    Below a turn of ``TRIG_KINK`` the basis is ill-conditioned: the quadratic interpolant is
    used (:func:`kink_weights`). Each piece between the roots found takes g's sign at its middle
    (in t), and a step without a root found the sign of :func:`one_sign`: a root within rounding
    of an end, put on either side of it, or two roots within rounding of each other, change
    the integral by rounding only, not by twice a piece's weight. (The previous rule, the
    roots counted made to agree in parity with the signs of g just inside the ends and the root
    nearest an end moved across it, moved the wrong root where both lie within rounding of
    the ends.)
    """
    if c > TRIG_COS or c <= 0.0 or s <= 0.0:
        w0, w1, w2, m0, m1, m2, _ = kink_weights(g0, gm, g2)
        return (
            (
                w0 * q0[0] + w1 * qm[0] + w2 * q2[0],
                w0 * q0[1] + w1 * qm[1] + w2 * q2[1],
                w0 * q0[2] + w1 * qm[2] + w2 * q2[2],
            ),
            m0 * q0[2] + m1 * qm[2] + m2 * q2[2],
        )
    g0, gm, g2 = unit_scaled(g0, gm, g2)  # the roots' b² − ac of order 1, and the same roots
    cc = c * c - s * s  # cos θ
    ss = 2.0 * c * s  # sin θ
    # Nodes 0, 1/2, 1: f = p + q, p + q c + r s, p + q C + r S; solved for (p, q, r).
    den = 1.0 / (2.0 * (c - 1.0))
    rs = 1.0 / s
    gq = ((g2 - g0) - 2.0 * c * (gm - g0)) * den
    gr = ((gm - g0) - gq * (c - 1.0)) * rs
    gp = g0 - gq
    it = 1.0 / theta
    f0 = _primitives(0.0, 1.0, 0.0, it)
    f1 = _primitives(1.0, cc, ss, it)
    # Σ over the pieces of sign × (F(end) − F(start)) = σ_last F(1) − σ_first F(0)
    # + Σ (σ before x_r − σ after x_r) F(x_r) over the roots x_r in (0, 1) found.
    # Roots: with t = tan(θx/2), p + q cos + r sin = 0 is (p − q) t² + 2 r t + (p + q) = 0
    # (the half-angle substitution: (1 + t²) g), and 0 < θx < θ < π is 0 < t < tan(θ/2) = s/c.
    qa = gp - gq
    qb = gr
    qc = gp + gq
    disc = qb * qb - qa * qc
    # The roots na/da and nb/db (0/0: none); 0 < t < s/c (c, s > 0) tested without dividing.
    na = 0.0
    da = 0.0
    nb = 0.0
    db = 0.0
    if disc > 0.0:
        qq = -(qb + math.copysign(math.sqrt(disc), qb))
        na = qq
        da = qa
        nb = qc
        db = qq
    in_a = na * da > 0.0 and abs(na) * c < abs(da) * s
    in_b = nb * db > 0.0 and abs(nb) * c < abs(db) * s
    ta = tb = 0.0
    if in_a or in_b:
        # The roots found in order, each piece's sign that of (1 + t²) g at its middle in t.
        if in_a and in_b:
            ta = min(na / da, nb / db)
            tb = max(na / da, nb / db)
        else:
            ta = na / da if in_a else nb / db
            tb = ta
        t_end = s / c
        m = 0.5 * ta
        first = 1.0 if (qa * m + 2.0 * qb) * m + qc >= 0.0 else -1.0
        m = 0.5 * (tb + t_end)
        last = 1.0 if (qa * m + 2.0 * qb) * m + qc >= 0.0 else -1.0
    else:  # no root found: one piece, one sign
        first = last = one_sign(g0, gm, g2)
    tot = (
        last * f1[0] - first * f0[0],
        last * f1[1] - first * f0[1],
        last * f1[2] - first * f0[2],
        last * f1[3] - first * f0[3],
        last * f1[4] - first * f0[4],
        last * f1[5] - first * f0[5],
    )
    if in_a and in_b:
        m = 0.5 * (ta + tb)
        middle = 1.0 if (qa * m + 2.0 * qb) * m + qc >= 0.0 else -1.0
        tot = _add_root(tot, ta, it, first - middle)
        tot = _add_root(tot, tb, it, middle - last)
    elif in_a or in_b:
        tot = _add_root(tot, ta, it, first - last)
    # Each component f (nodes f0, fm, f2) has q = den ((f2 − f0) − 2c (fm − f0)),
    # r = rs ((fm − f0) − (c − 1) q), p = f0 − q, and its integral p T0 + q T1 + r T2 is linear
    # in the node values: weights on the nodes, once for the three components.
    two_c = 2.0 * c
    ca = (tot[1] - tot[0] - (c - 1.0) * rs * tot[2]) * den
    cb = rs * tot[2]
    w0 = tot[0] - cb + ca * (two_c - 1.0)
    wm = cb - two_c * ca
    w2 = ca
    ma = (tot[4] - tot[3] - (c - 1.0) * rs * tot[5]) * den
    mb = rs * tot[5]
    m0 = tot[3] - mb + ma * (two_c - 1.0)
    mm = mb - two_c * ma
    m2 = ma
    return (
        (
            w0 * q0[0] + wm * qm[0] + w2 * q2[0],
            w0 * q0[1] + wm * qm[1] + w2 * q2[1],
            w0 * q0[2] + wm * qm[2] + w2 * q2[2],
        ),
        m0 * q0[2] + mm * qm[2] + m2 * q2[2],
    )


@njit(cache=True, error_model="numpy")
def step_turning(z, v, n, u, t0, h, a0, b0, air, axis, c, s, theta):
    """:func:`step` given the first half step's turn (axis, cos, sin) of :func:`rotation` and
    twice its angle ``theta``: without damping the same for every step of the same length, so
    computed once for them.

    Where n·v changes sign within the step (the face's projected area π r² |n·v̂| has its kink
    there), the face drag's share of the step is integrated exactly over the kinks
    (:func:`kink_integrals`; for turns too short or too long for its basis, :func:`kink_weights`)
    instead of the Runge-Kutta rule's own weights."""
    c_half = c
    s_half = s
    n1 = _rotate(n, axis, c, s)
    if air.spin_damping > 0.0:
        u1 = _rotate(u, axis, c, s)
        axis, c, s, _ = rotation(n1, u1, t0 + 0.5 * h, 0.5 * h, a0, b0, air)
        n2 = _rotate(n1, axis, c, s)
        u2 = _rotate(u1, axis, c, s)
    else:  # the second half turn is the first again: u turns by twice its angle at once
        n2 = _rotate(n1, axis, c, s)
        u2 = _rotate(u, axis, c * c - s * s, 2.0 * c * s)
    k1 = _acceleration(v, n, air)
    va = (v[0] + 0.5 * h * k1[0], v[1] + 0.5 * h * k1[1], v[2] + 0.5 * h * k1[2])
    k2 = _acceleration(va, n1, air)
    relax = air.drag_factor * air.max_area * h
    if relax * relax * dot(v, v) <= KUTTA_DRAG * KUTTA_DRAG:
        # Kutta's third-order rule (Simpson's weights on the stages t0, t0 + h/2, t0 + h):
        # the drag changes by less than KUTTA_DRAG of itself with the velocity in a step.
        vb = (
            v[0] + h * (2.0 * k2[0] - k1[0]),
            v[1] + h * (2.0 * k2[1] - k1[1]),
            v[2] + h * (2.0 * k2[2] - k1[2]),
        )
        k4 = _acceleration(vb, n2, air)
        z1 = z + h / 6.0 * (v[2] + 4.0 * va[2] + vb[2])
        v1 = (
            v[0] + h / 6.0 * (k1[0] + 4.0 * k2[0] + k4[0]),
            v[1] + h / 6.0 * (k1[1] + 4.0 * k2[1] + k4[1]),
            v[2] + h / 6.0 * (k1[2] + 4.0 * k2[2] + k4[2]),
        )
        gm = dot(n1, va)
        qm = (gm * va[0], gm * va[1], gm * va[2])
        am = abs(gm)
        vm_applied = (am * va[0], am * va[1], am * va[2])
    else:
        vb = (v[0] + 0.5 * h * k2[0], v[1] + 0.5 * h * k2[1], v[2] + 0.5 * h * k2[2])
        k3 = _acceleration(vb, n1, air)
        vc = (v[0] + h * k3[0], v[1] + h * k3[1], v[2] + h * k3[2])
        k4 = _acceleration(vc, n2, air)
        z1 = z + h / 6.0 * (v[2] + 2.0 * va[2] + 2.0 * vb[2] + vc[2])
        v1 = (
            v[0] + h / 6.0 * (k1[0] + 2.0 * k2[0] + 2.0 * k3[0] + k4[0]),
            v[1] + h / 6.0 * (k1[1] + 2.0 * k2[1] + 2.0 * k3[1] + k4[1]),
            v[2] + h / 6.0 * (k1[2] + 2.0 * k2[2] + 2.0 * k3[2] + k4[2]),
        )
        # The midpoint's two stages, averaged: Q and g there, and what the rule applied.
        ga = dot(n1, va)
        gb = dot(n1, vb)
        gm = 0.5 * (ga + gb)
        qm = (
            0.5 * (ga * va[0] + gb * vb[0]),
            0.5 * (ga * va[1] + gb * vb[1]),
            0.5 * (ga * va[2] + gb * vb[2]),
        )
        aa = abs(ga)
        ab = abs(gb)
        vm_applied = (
            0.5 * (aa * va[0] + ab * vb[0]),
            0.5 * (aa * va[1] + ab * vb[1]),
            0.5 * (aa * va[2] + ab * vb[2]),
        )
        vb = vc
    g0 = dot(n, v)
    g2 = dot(n2, vb)
    # The face drag's share of the step by kink_integrals in place of the rule's own; not for a
    # short turn (below TRIG_KINK: the quadratic interpolant) in which n·v keeps its sign at the
    # stages, where both are Simpson's rule.
    same = (g0 > 0.0) == (gm > 0.0) and (gm > 0.0) == (g2 > 0.0)
    if air.projected > 0.0 and (c_half <= TRIG_COS or not same):
        q0 = (g0 * v[0], g0 * v[1], g0 * v[2])
        q2 = (g2 * vb[0], g2 * vb[1], g2 * vb[2])
        corrected, corrected_z = kink_integrals(g0, gm, g2, q0, qm, q2, c_half, s_half, theta)
        # Corrected minus applied face drag (both times −c π r²): velocity and height.
        fd = -air.drag_factor * math.pi * air.radius * air.radius
        a0_ = abs(g0)
        a2_ = abs(g2)
        fv = fd * h
        v1 = (
            v1[0] + fv * (corrected[0] - (a0_ * v[0] + 4.0 * vm_applied[0] + a2_ * vb[0]) / 6.0),
            v1[1] + fv * (corrected[1] - (a0_ * v[1] + 4.0 * vm_applied[1] + a2_ * vb[1]) / 6.0),
            v1[2] + fv * (corrected[2] - (a0_ * v[2] + 4.0 * vm_applied[2] + a2_ * vb[2]) / 6.0),
        )
        z1 = z1 + fv * h * (corrected_z - (a0_ * v[2] + 2.0 * vm_applied[2]) / 6.0)
    return z1, v1, n2, u2


@njit(cache=True, error_model="numpy")
def step_size(v, t0, a0, b0, air):
    """Longest step allowed from this state (TURN_STEP, MAX_STEP, DRAG_STEP, DECAY_STEP)."""
    k = air.spin_damping
    a = abs(a0)
    b = b0
    if k > 0.0:
        a *= math.exp(-k * t0 / air.i3)
        b *= math.exp(-k * t0 / air.i1)
    # Compared squared: the square roots are taken only for a limit that applies.
    h = MAX_STEP
    spin2 = a * a + b * b  # (I1 times how fast the triad turns, rad/s) squared
    turn = TURN_STEP if k == 0.0 else DAMPED_TURN_STEP
    if spin2 * h * h > (turn * air.i1) ** 2:
        h = turn * air.i1 / math.sqrt(spin2)
    relax2 = (air.drag_factor * air.max_area) ** 2 * dot(v, v)  # (c A_max |v|)²
    if relax2 * h * h > DRAG_STEP * DRAG_STEP:
        h = DRAG_STEP / math.sqrt(relax2)
    # The spin that remains turns the coin by at most ∫ rate dt ≤ (a I3 + b I1)/(K I1).
    if k > 0.0 and (a * air.i3 + b * air.i1) / (k * air.i1) > FROZEN_TURN:
        decay = DECAY_STEP * min(air.i1, air.i3) / k
        if decay < h:
            h = decay
    return h


@njit(cache=True)
def launch_state(omega_body, start_sign, air):
    """(n, u, a0, b0) at launch: heads up (identity) or tails up (a half turn about lab X)."""
    s = 1.0 if start_sign > 0 else -1.0
    n = (0.0, 0.0, s)
    lm = (air.i1 * omega_body[0], s * air.i1 * omega_body[1], s * air.i3 * omega_body[2])
    a0, b0, u = split(lm, n)
    return n, u, a0, b0


@njit(cache=True)
def catch_one(omega_body, start_sign, launch_speed, air):
    """(face, catch time, n_z then): the centre of mass back at launch height on the way down.

    The catch time is −1 if the toss needed more than MAX_STEPS steps.
    """
    n, u, a0, b0 = launch_state(omega_body, start_sign, air)
    z = 0.0
    v = (0.0, 0.0, launch_speed)
    t = 0.0
    turned = NO_TURN
    for _ in range(MAX_STEPS):
        h = step_size(v, t, a0, b0, air)
        z1, v1, n1, u1, turned = cached_step(z, v, n, u, t, h, a0, b0, air, turned)
        if v1[2] < 0.0 and z1 <= 0.0:
            # Newton on the length of one step from (z, v, n, u) at t: z(τ) = 0, z'(τ) = v_z.
            lo = 0.0
            hi = h
            tau = h * z / (z - z1) if z > z1 else h
            for _ in range(60):
                zt, vt, _, _ = step(z, v, n, u, t, tau, a0, b0, air)
                if zt > 0.0:
                    lo = tau
                else:
                    hi = tau
                trial = tau - zt / vt[2] if vt[2] < 0.0 else 0.5 * (lo + hi)
                if not (lo <= trial <= hi):
                    trial = 0.5 * (lo + hi)
                if abs(trial - tau) <= 1e-15 * (t + tau) or zt == 0.0:
                    tau = trial
                    break
                tau = trial
            _, _, nt, _ = step(z, v, n, u, t, tau, a0, b0, air)
            face = 1 if nt[2] > 0.0 else 0
            return face, t + tau, nt[2]
        z, v, n, u = z1, v1, n1, u1
        t += h
    return (1 if n[2] > 0.0 else 0), -1.0, n[2]


@njit(cache=True)
def trajectory(omega_body, start_sign, launch_speed, air, times, out):
    """States at the increasing ``times`` (≥ 0) from launch: out[k] = (z, vx, vy, vz, nx, ny,
    nz, Lx, Ly, Lz); z counts from launch height. For the tests and the figures."""
    n, u, a0, b0 = launch_state(omega_body, start_sign, air)
    z = 0.0
    v = (0.0, 0.0, launch_speed)
    t = 0.0
    for k in range(times.shape[0]):
        for _ in range(MAX_STEPS):
            if t >= times[k]:
                break
            h = step_size(v, t, a0, b0, air)
            last = t + h >= times[k]
            if last:
                h = times[k] - t
            z, v, n, u = step(z, v, n, u, t, h, a0, b0, air)
            t = times[k] if last else t + h
        lm = angular_momentum(n, u, t, a0, b0, air)
        out[k, 0] = z
        out[k, 1], out[k, 2], out[k, 3] = v
        out[k, 4], out[k, 5], out[k, 6] = n
        out[k, 7], out[k, 8], out[k, 9] = lm


@njit(cache=True)
def drag_slack(v, h, air):
    """Bound D on the drag's deceleration over a step h from the velocity v: c A_max (|v| + g h)²
    (the speed grows at most at g, the drag only slows it), m/s²."""
    vmax = math.sqrt(dot(v, v)) + air.g * h
    return air.drag_factor * air.max_area * vmax * vmax


@njit(cache=True)
def precession(lm, air):
    """(L̂, |L|/I1): the axis and rate of the undamped coin's torque-free precession."""
    lmag = math.sqrt(dot(lm, lm))
    if lmag == 0.0:
        return (0.0, 0.0, 1.0), 0.0
    return (lm[0] / lmag, lm[1] / lmag, lm[2] / lmag), lmag / air.i1


@njit(cache=True, error_model="numpy")
def lower_gap(z, v, n, lm, axis, rate, tau, fall, air, c):
    """(a lower bound of the gap under the undamped coin τ after the state (z, v, n, L), its
    rate): ``axis`` and ``rate`` its precession (:func:`precession`), ``fall`` = g + D with D
    bounding the drag's deceleration (:func:`drag_slack`).

    Without spin damping the attitude is the torque-free precession of the vacuum
    (:func:`coinflight.core.flight.precess`, what the steps compute to rounding), and the centre
    of mass falls at most D τ²/2 below the vacuum parabola: the gap is at least
    z + v_z τ − (g + D) τ²/2 − depth(n_z(τ)) (:func:`coinflight.core.impact.lowest_depth`, the
    rounded rim); its rate is v_z − (g + D) τ plus the lowest point's (envelope theorem)."""
    m = precess(n, axis, rate, tau)
    gap = (
        z
        + (v[2] - 0.5 * fall * tau) * tau
        - lowest_depth(m[2], air.radius, c.half_thickness, c.corner_radius)
    )
    omega = angular_velocity(lm, m, air.i1, air.i3)
    rc = contact_point(m, air.radius, c.half_thickness, c.corner_radius)
    return gap, v[2] - fall * tau + cross(omega, rc)[2]


@njit(cache=True, error_model="numpy")
def bound_search(z, v, n, lm, tmin, h, air, c):
    """Longest step from ``tmin`` up to h over which the undamped coin provably stays above
    CA_TOLERANCE: the first τ at which :func:`lower_gap` falls to it, else h.

    Conservative advancement (Mirtich 1996, §3.4) on the lower bound: each step at least the
    one that provably cannot close it (the bound falls at most at its downward speed plus
    |ω| ρ, accelerating at g + D), and as far as its Taylor bound (downward acceleration at most
    g + D + 2 |ω|² ρ) stays positive, as the search with damping in :func:`next_contact`. The
    bound costs a closed-form precession, not a step of the integrator."""
    axis, rate = precession(lm, air)
    fall = air.g + drag_slack(v, h, air)
    omega = angular_velocity(lm, n, air.i1, air.i3)
    w2 = dot(omega, omega)  # constant in torque-free motion
    spin = math.sqrt(w2) * c.reach
    accel = fall + 2.0 * w2 * c.reach
    tau = tmin
    for _ in range(SEARCH_STEPS):
        gap, speed = lower_gap(z, v, n, lm, axis, rate, tau, fall, air, c)
        if gap <= CA_TOLERANCE:
            return tau
        vz = v[2] - fall * tau
        a = (-vz if vz < 0.0 else 0.0) + spin
        safe = 2.0 * gap / (a + math.sqrt(a * a + 2.0 * fall * gap))
        taylor = (speed + math.sqrt(speed * speed + 2.0 * accel * gap)) / accel
        tau += taylor if taylor > safe else safe
        if tau >= h:
            return h
    return tau


@njit(cache=True)
def _gap(z, v, n, lm, air, hh, corner):
    """(gap under the lowest point, its rate): z − depth(n_z), v_z + (ω × r_c)_z, for the rim
    rounded with corner radius ``corner`` (the cylinder (r − a, h/2 − a) swept by a ball of
    radius a: :func:`coinflight.core.impact.lowest_depth` and
    :func:`~coinflight.core.impact.contact_point`)."""
    gap = z - lowest_depth(n[2], air.radius, hh, corner)
    omega = angular_velocity(lm, n, air.i1, air.i3)
    rc = contact_point(n, air.radius, hh, corner)
    return gap, v[2] + cross(omega, rc)[2]


@njit(cache=True)
def ending(v, lm, n, rebound, c):
    """(face, status, duration of the 3-D ending) if the coin has settled after this impact,
    else (−1, −1, 0): :func:`coinflight.core.bounce.after_impact`, the one ending of every
    landing kernel (below the barrier; dead; the bounces died out: rocking or rigid ending)."""
    z = lowest_depth(n[2], c.radius, c.half_thickness, c.corner_radius)
    return after_impact(z, v, lm, n, rebound, c)


@njit(cache=True)
def lift(z, v, n, u, lm, a0, b0, rebound, air, c):
    """Leave the surface after an impact: (tmin, z, v, n, u, tr), the coin provably above it
    ``tmin`` after the state returned, tr after the impact.

    The gap first grows like rebound τ − A τ²/2 (A bounds the downward acceleration of any point
    of the coin): the peak of that, halved until the gap is positive, as
    :func:`coinflight.core.bounce.land_one`. Without spin damping the gap is judged by its
    lower bound (:func:`lower_gap`, no step taken: the state is the impact's, tmin > 0, and the
    next step starts the search there); with damping by steps of the integrator (tmin = 0)."""
    omega = angular_velocity(lm, n, c.i1, c.i3)
    tau = rebound / (c.g + 2.0 * dot(omega, omega) * c.reach)
    if air.spin_damping == 0.0:
        h = step_size(v, 0.0, a0, b0, air)
        tau = tau if tau < h else h
        fall = air.g + drag_slack(v, h, air)
        axis, rate = precession(lm, air)
        for _ in range(200):
            if lower_gap(z, v, n, lm, axis, rate, tau, fall, air, c)[0] > 0.0:
                break
            tau *= 0.5
        return tau, z, v, n, u, 0.0
    z1, v1, n1, u1 = z, v, n, u
    for _ in range(200):
        z1, v1, n1, u1 = step(z, v, n, u, 0.0, tau, a0, b0, air)
        if z1 - lowest_depth(n1[2], c.radius, c.half_thickness, c.corner_radius) > 0.0:
            break
        tau *= 0.5
    return 0.0, z1, v1, n1, u1, tau


@njit(cache=True)
def next_contact(z, v, n, u, tr, a0, b0, tmin, rising, air, c, budget):
    """Fly from (z, v, n, u), tr after a0, b0 were set, to the coin's next touch of the surface:
    (elapsed time, z, v, n, u, tr, L, the lowest point's vertical velocity, steps taken); the
    elapsed time is −1 after ``budget`` steps without a touch.

    ``rising``: from the launch, no contact is looked for before the apex (as without air).
    ``tmin`` > 0: the state is an impact's and the coin is above the surface from tmin on
    (:func:`lift`). Far from the surface (its centre higher than the coin's reach even after
    falling −min(v_z, 0) h + g h²/2 in the step: falling, the drag only slows it) the steps are
    the integrator's longest; near it, a step's length is also limited by the contact search:
    without damping the search on the gap's lower bound (:func:`bound_search`), with damping
    conservative advancement with the bound on the gap from this state alone (Mirtich 1996,
    §3.4). A step that ends below the surface brackets the contact, which a safeguarded Newton
    iteration on the length of one step from the bracket's start then polishes to
    GAP_TOLERANCE (a step of any length from a state is a smooth function of its length; Newton
    inside the bracket, else bisection, as :func:`coinflight.core.flight.next_contact`)."""
    hh = c.half_thickness
    corner = c.corner_radius
    rho = c.reach
    elapsed = 0.0
    turned = NO_TURN
    for steps in range(budget):
        h = step_size(v, tr, a0, b0, air)
        # Rising from the launch, or so high above the surface that no point of the coin can
        # reach it within the step, fly on without the contact search.
        if tmin == 0.0 and (
            rising or z - rho + h * (min(v[2], 0.0) - 0.5 * air.g * h) > FAR_MARGIN
        ):
            z, v, n, u, turned = cached_step(z, v, n, u, tr, h, a0, b0, air, turned)
            elapsed += h
            tr += h
            rising = rising and v[2] > 0.0
            continue
        lm = angular_momentum(n, u, tr, a0, b0, air)
        gap, speed = _gap(z, v, n, lm, air, hh, corner)
        # The state from which the contact is polished, and the bracket on the step from it.
        zb, vb, nb, ub = z, v, n, u
        z1, v1, n1, u1 = z, v, n, u
        tau, lo, hi, bracketed = 0.0, 0.0, 0.0, False
        g1, s1, lm1 = gap, speed, lm
        longest = h
        if gap > CA_TOLERANCE or tmin > 0.0:
            if air.spin_damping == 0.0:
                lo = tmin  # above the surface there (lift)
                h = bound_search(z, v, n, lm, tmin, h, air, c)
                tmin = 0.0
            else:
                # No point of the coin falls faster than |v_z| + |Ω| ρ nor accelerates
                # downwards faster than g + c v² + 2 |Ω|² ρ.
                spin = math.sqrt(dot(lm, lm)) / air.i1
                omega = angular_velocity(lm, n, air.i1, air.i3)
                w2 = dot(omega, omega)
                a = (-v[2] if v[2] < 0.0 else 0.0) + spin * rho
                accel = air.g + air.drag_factor * air.max_area * dot(v, v) + 2.0 * w2 * rho
                safe = 2.0 * gap / (a + math.sqrt(a * a + 2.0 * accel * gap))
                taylor = (speed + math.sqrt(speed * speed + 2.0 * accel * gap)) / accel
                trial = taylor if taylor > safe else safe
                if trial < h:
                    h = trial
            z1, v1, n1, u1, turned = cached_step(z, v, n, u, tr, h, a0, b0, air, turned)
            lm1 = angular_momentum(n1, u1, tr + h, a0, b0, air)
            g1, s1 = _gap(z1, v1, n1, lm1, air, hh, corner)
            if g1 < -CA_TOLERANCE:
                tau, hi, bracketed = h, h, True
            elif g1 > CA_TOLERANCE and s1 < 0.0 and h < longest:
                tau = h  # stopped by the search, approaching: Newton on from the step's start
            else:
                z, v, n, u = z1, v1, n1, u1
                elapsed += h
                tr += h
                if g1 > CA_TOLERANCE:
                    continue
                zb, vb, nb, ub = z, v, n, u  # within the band above the surface: polish
                lo = 0.0
        # Safeguarded Newton on the length τ of one step from (zb, vb, nb, ub): inside the
        # bracket once there is one; before it, while approaching and within the longest step
        # (beyond it, the state reached is taken and the flight goes on).
        tr0 = tr
        fly_on = False
        for _ in range(100):
            if abs(g1) <= GAP_TOLERANCE or (not bracketed and s1 >= 0.0):
                break
            if g1 > 0.0:
                lo = tau
            else:
                hi = tau
                bracketed = True
            trial = tau - g1 / s1 if s1 < 0.0 else 0.5 * (lo + hi)
            if bracketed and not (lo < trial < hi):
                trial = 0.5 * (lo + hi)
            if not bracketed and trial > longest:
                fly_on = True
                break
            if trial == tau:
                break
            tau = trial
            z1, v1, n1, u1 = step(zb, vb, nb, ub, tr0, tau, a0, b0, air)
            lm1 = angular_momentum(n1, u1, tr0 + tau, a0, b0, air)
            g1, s1 = _gap(z1, v1, n1, lm1, air, hh, corner)
        if fly_on or (g1 > CA_TOLERANCE and s1 >= 0.0):
            # Above the surface (not at a touch): fly on from there.
            z, v, n, u = z1, v1, n1, u1
            elapsed += tau
            tr = tr0 + tau
            continue
        return elapsed + tau, z1, v1, n1, u1, tr0 + tau, lm1, s1, steps + 1
    return -1.0, z, v, n, u, tr, angular_momentum(n, u, tr, a0, b0, air), 0.0, budget


@njit(cache=True)
def bounce_flight(z, v, n, lm, rebound, air, c):
    """The flight after an impact that left the coin at (z, v, n, L) with the contact point
    rising at ``rebound``: (duration, z, v, n, L, the lowest point's vertical velocity) at its
    next touch of the surface (duration −1 after MAX_STEPS steps), as :func:`land_one` flies
    it (:func:`lift`, :func:`next_contact`)."""
    a0, b0, u = split(lm, n)
    tmin, z, v, n, u, tr = lift(z, v, n, u, lm, a0, b0, rebound, air, c)
    dt, z, v, n, u, tr, lm, speed, _ = next_contact(
        z, v, n, u, tr, a0, b0, tmin, False, air, c, MAX_STEPS
    )
    return (tr if dt >= 0.0 else -1.0), z, v, n, lm, speed


@njit(cache=True)
def land_one(omega_body, start_sign, launch_speed, air, c, max_bounces):
    """One toss from launch through air to rest on the table: (face, bounces, first contact,
    settle time, status), as :func:`coinflight.core.bounce.land_one` (the rounded rim's
    contacts and impacts, corner radius ``c.corner_radius``): flights by :func:`next_contact`,
    impacts by :func:`coinflight.core.impact.impact`, the ending by :func:`ending`, the coin
    leaving the surface by :func:`lift`."""
    n, u, a0, b0 = launch_state(omega_body, start_sign, air)
    z = c.drop_height  # height of the centre of mass above the surface
    v = (0.0, 0.0, launch_speed)
    t = 0.0  # since launch
    tr = 0.0  # since a0, b0 were set (launch or the last impact)
    tmin = 0.0
    bounces = 0
    first = -1.0
    rising = True  # the contact is looked for from the apex on, as without air
    budget = MAX_STEPS
    impacts = 0
    while impacts < MAX_IMPACTS:
        dt, z, v, n, u, tr, lm, speed, steps = next_contact(
            z, v, n, u, tr, a0, b0, tmin, rising, air, c, budget
        )
        budget -= steps
        if dt < 0.0:
            break
        t += dt
        rising = False
        tmin = 0.0
        if speed >= 0.0:
            # A graze: no impact, fly on from a little later.
            z, v, n, u = step(z, v, n, u, tr, GRAZE_SKIP, a0, b0, air)
            t += GRAZE_SKIP
            tr += GRAZE_SKIP
            continue
        impacts += 1
        if first < 0.0:
            first = t
        if bounces >= max_bounces:
            return resting_face(n[2], c.edge_sine), bounces, first, t, _LIMIT
        z = lowest_depth(n[2], c.radius, c.half_thickness, c.corner_radius)
        v, lm, rebound = impact(v, lm, n, c)
        face, status, duration = ending(v, lm, n, rebound, c)
        if status >= 0:
            return face, bounces, first, t + duration, status
        bounces += 1
        a0, b0, u = split(lm, n)
        tmin, z, v, n, u, tr = lift(z, v, n, u, lm, a0, b0, rebound, air, c)
        t += tr
    return resting_face(n[2], c.edge_sine), bounces, first, t, _UNSETTLED


def _batch_kernels(parallel: bool) -> tuple[Any, Any]:
    """The loops over a batch (catch and landing), for numba's threads or for the calling
    thread with the GIL released (as :func:`coinflight.core.bounce._batch_kernel`)."""
    loop = prange if parallel else range

    def catches(omega, start_sign, launch_speed, air, face, when, nz):
        for k in loop(omega.shape[0]):
            f, t, z = catch_one(
                (omega[k, 0], omega[k, 1], omega[k, 2]), start_sign[k], launch_speed[k], air
            )
            face[k] = f
            when[k] = t
            nz[k] = z

    def landings(
        omega,
        start_sign,
        launch_speed,
        air,
        contact,
        restitution,
        friction,
        rolling,
        pivoting,
        duration,
        max_bounces,
        face,
        bounces,
        first,
        settle,
        status,
    ):
        for k in loop(omega.shape[0]):
            face[k], bounces[k], first[k], settle[k], status[k] = land_one(
                (omega[k, 0], omega[k, 1], omega[k, 2]),
                start_sign[k],
                launch_speed[k],
                air,
                with_surface(
                    contact, restitution[k], friction[k], rolling[k], pivoting[k], duration[k]
                ),
                max_bounces,
            )

    jit = njit(cache=True, parallel=parallel, nogil=True)
    return jit(catches), jit(landings)


_catch_parallel, _land_parallel = _batch_kernels(parallel=True)
_catch_serial, _land_serial = _batch_kernels(parallel=False)


def catch(
    omega: Any, launch_speed: Any, start_sign: Any, air: Air, *, parallel: bool = True
) -> tuple[NDArray[np.int8], FloatArray, FloatArray]:
    """Hand catches of a batch: (face, catch time, n_z at the catch), shapes (n,).

    ``omega`` (n, 3) body-frame angular velocity at launch, rad/s; ``launch_speed`` (n,) m/s;
    ``start_sign`` (n,) +1 heads up, −1 tails up. A catch time of −1 marks a toss that needed
    more than :data:`MAX_STEPS` steps (refused beforehand by :func:`check_air`).
    """
    omega, speed, sign = batch_inputs(omega, launch_speed, start_sign)
    n = omega.shape[0]
    face = np.empty(n, dtype=np.int8)
    when = np.empty(n)
    nz = np.empty(n)
    kernel = _catch_parallel if parallel else _catch_serial
    kernel(omega, sign, speed, air, face, when, nz)
    return face, when, nz


def land(
    omega: Any,
    launch_speed: Any,
    start_sign: Any,
    air: Air,
    contact: Contact,
    *,
    max_bounces: int = MAX_IMPACTS,
    parallel: bool = True,
    **per_toss: Any,
) -> Landed:
    """Land a batch through air on a table: as :func:`coinflight.core.bounce.land` (face,
    bounces, first contact, settle time, status; each toss's own restitution, friction,
    resistances and contact duration when given), with the flights of this module."""
    kernel = _land_parallel if parallel else _land_serial
    return run_batch(
        kernel, (air,), omega, launch_speed, start_sign, contact, max_bounces, per_toss
    )


def states(omega: Any, launch_speed: float, start_sign: float, air: Air, times: Any) -> FloatArray:
    """States (len(times), 10) of one flight: z, v (3), n (3), L (3); see :func:`trajectory`."""
    times = np.ascontiguousarray(np.atleast_1d(np.asarray(times, dtype=float)))
    out = np.empty((times.shape[0], 10))
    w = np.asarray(omega, dtype=float)
    trajectory(
        (float(w[0]), float(w[1]), float(w[2])),
        float(start_sign),
        float(launch_speed),
        air,
        times,
        out,
    )
    return out


def steps_needed(
    air: Air, launch_speed: float, drop_height: float = 0.0, spin: float = 0.0
) -> float:
    """Upper estimate of the steps of one toss to its catch or first contact (for the work bound).

    With the largest drag factor c = ρ C_d A_max / 2m and v_t = sqrt(g/c) (the quadratic-drag
    motions, e.g. Taylor, *Classical Mechanics*, 2005, §2.4): the rise lasts (v_t/g) atan(v0/v_t)
    ≤ v0/g at speeds ≤ v0; the fall, down at most D = v0²/2g + drop height from rest, lasts at
    most acosh(e^{c D}) / sqrt(g c) at speeds ≤ v_t. Steps: each phase's time over its shortest
    step, DRAG_STEP / (c v), MAX_STEP or TURN_STEP at the spin ``spin`` (rad/s; the coin turns
    at most that fast times I3/I1).
    """
    g = air.g
    c = air.drag_factor * air.max_area
    v0 = abs(float(launch_speed))
    fall = v0 * v0 / (2.0 * g) + max(float(drop_height), 0.0)
    turn = TURN_STEP if air.spin_damping == 0.0 else DAMPED_TURN_STEP
    turning = max(spin * max(air.i3 / air.i1, 1.0) / turn, 1.0 / MAX_STEP)
    if c > 0.0:
        v_t = math.sqrt(g / c)
        up = v_t / g * math.atan(v0 / v_t)
        x = c * fall
        down = (x + math.log1p(math.sqrt(-math.expm1(-2.0 * x)))) / math.sqrt(g * c)
        return up * max(turning, c * v0 / DRAG_STEP) + down * max(turning, c * v_t / DRAG_STEP) + 10
    return (v0 / g + math.sqrt(2.0 * fall / g)) * turning + 10.0
