"""The coin in persistent contact with the table, in 3-D, until it cannot leave its well (numba).

When the bounces of :mod:`coinflight.core.bounce` die out (a rebound slower than
``rest_speed``), the coin is not at rest: it rocks, rolls and slides on its rim, spins and
precesses like Euler's disk, touches with two rim points or slaps its face. This module carries
that motion on until the coin's energy can no longer take it over the barrier between its well
and the next one, and says which well that is.

**Experimental, opt-in** (``Surface(ending="contact")``; the default end of a landing is the
planar rocking of :func:`coinflight.core.bounce.rock`, and ``Surface(ending="rigid")`` is the
rigid, event-driven alternative of :mod:`coinflight.core.rigid_ending`). Its known limits:

* its answers depend on a numerical softness, the contact time t_c (:data:`CONTACT_TIME`), and
  its regularised friction drills: a rolling disc's spin about the vertical decays with no
  pivoting resistance, and Euler's disk without resistances still collapses;
* it holds coins rolling upright on the rim's flat band far more often than MuJoCo does on the
  same tosses (about ten times the edges): quote no edge rate from it;
* it costs about a third of a millisecond of one core per landing carried to rest (vigorous
  tosses of a US nickel), some thirty times the rocking ending.

The state is the height z of the centre of mass, its velocity v, the heads normal n and the
angular momentum L about the centre of mass (lab frame, SI); the spin angle about n does not
enter the contact of a cylinder with a plane, and neither does the horizontal position.

The contact model (compliant)
-----------------------------
A compliant (penalty) contact rather than a constrained one: rolling, sliding, pivoting,
rocking, two-point and face contact and short hops follow from one force law, with no list of
contact modes and no complementarity problem (the price: stiff equations, integrated with small
steps). The coin touches the plane with the two circles of its rims (with rounded corners, the
circles of the core cylinder, a lower). A rim circle σ = ±1 (heads, tails), centre σ (h/2) n
from the centre of mass, has at the angle φ from its lowest point the penetration

    d(φ) = A + B cos φ,   A = −z − σ (h/2) n_z,   B = r s,   s = sqrt(1 − n_z²),

positive on the arc |φ| < φ* (cos φ* = −A/B; the whole circle when A ≥ B, a face flat on the
table). Each point of the arc carries a vertical force per radian f(φ) = κ d(φ) + γ ḋ_s(φ): a
linear spring along the rim whose total is Hertz-like on a short arc (F ∝ d0^(3/2)) and linear
for a face, summed over the arc in closed form. The frictionless normal force of a rim acts on
the arc's plane of symmetry and exerts no torque about n or about the vertical, as in a rigid
frictionless contact (Stronge 2000, §5), so that L·n and L_z are conserved with μ = 0.

* **Stiffness.** κ = π m / (2 t_c²): a coin dropped flat sinks for t_c. A numerical softness,
  chosen short beside every time of the coin's motion (√(r/g) ≈ 30 ms).
* **Restitution.** A damper of ratio ζ sized for the arc's effective mass (the collision matrix
  of :mod:`coinflight.core.impact`; the damping ∝ d^(1/4) of Tsuji, Tanaka & Ishida, Powder
  Technol. 71:239, 1992) so that a rim contact restitutes with the surface's e; with friction,
  for the normal mass a sliding contact has; two rims pressed together are damped as one pair
  (:func:`joint_damping`).
* **Friction.** Coulomb friction regularised below :data:`SLIP_SPEED`, on the arc's centroid,
  with its drilling moment μ r_t F_n (r_t the arc's radius of gyration); rolling and pivoting
  resistance, torques of a length times the normal force (Le Saux, Leine & Glocker, J.
  Nonlinear Sci. 15:27, 2005), regularised alike.

Every force is a spring that stores energy or opposes a velocity, so the mechanical energy
(kinetic + m g z + the springs') never grows but by integration error.

Integration and ending
----------------------
Dormand-Prince 5(4) with adaptive steps (Hairer, Nørsett & Wanner, *Solving ODEs I*, II.5),
which take large steps through a hop (a lift-off is integrated here, not handed back to the
exact flight loop: the hops of the last phase are short and a step-size control resolves
them) and small ones through a slap. After each step the coin has *settled* when it cannot
leave its well any more:

* with friction or resistances, when the mechanical energy is below m g ρ, the height of the
  centre of mass balanced on the corner (ρ = sqrt(r² + h²/4); Vulović & Prange 1986, Yong &
  Mahadevan 2011): no force here adds energy, so the coin can never get over a corner again;
* frictionless (μ = 0, no resistances), the horizontal momentum, L_z and L·n are conserved, so
  only E − ½ m v_h² is free, and a corner at n_z = ±sin(edge) needs at least
  m g ρ + (L·n)²/2I3 + (L_z − (L·n) n_z)² / (2 I1 (1 − n_z²)) (the least rotational energy with
  those L_z and L·n there): the barrier of the well in 3-D.

The outcome is then the well the coin is in (:func:`coinflight.core.impact.resting_face`). A
coin at rest is below the barrier of its well, so it has settled too. After MAX_STEPS steps
(a coin rolling on its edge with no rolling resistance would roll for ever) the toss is
unsettled, with the well it was in; so is at once a coin with nothing to dissipate its
energy (e = 1, μ = 0, no resistances) above its barrier.

Upright rollers (the early decision)
------------------------------------
Most of this phase's steps go to coins rolling upright in the flat band of the rim, on both
rims, until the rolling resistance stops them; the energy test cannot end them early. With
:data:`UPRIGHT_DECISION`, :func:`settle` ends such a coin on edge (status DECIDED_UPRIGHT,
:class:`coinflight.core.outcome.Status`, counted apart from the coins carried to rest) as soon
as :func:`upright_decided` holds: its turn, held by the two rims and by friction (the steady
turning of a rolling disc at zero lean, O'Reilly, Nonlinear Dyn. 10:287, 1996), its lean and
its rolling speed are well inside the band's limits and can only fall. This is a rule adopted
on measurement (carried on to rest, the coins it decides end on edge), not a proof.
"""

from __future__ import annotations

import math
from enum import IntEnum

import numpy as np

from coinflight.core import dormand_prince as dp
from coinflight.core._jit import njit
from coinflight.core.impact import (
    angular_velocity,
    cross,
    dot,
    inverse_inertia_apply,
    resting_face,
)
from coinflight.core.outcome import Status

CONTACT_TIME = 1e-3
"""Default duration t_c of a flat contact of the compliant model, s (a numerical softness; see
the module notes)."""
SLIP_SPEED = 5e-3
"""v_ε of the regularised Coulomb friction, m/s: below it friction grows linearly with the slip.
It sets the stiffest time of the contact, m_eff v_ε / (μ F_n) (~0.1 ms at μ = 1), hence the
cost of a rolling coin (steps ∝ 1/v_ε); a contact that would stick creeps at v_ε F_t/(μ F_n),
a few mm/s."""
MAX_STEPS = 400_000
"""Integration steps at most in one contact phase; then the toss is unsettled."""
RTOL = 1e-7
"""Relative tolerance of the step-size control. At this default a landing's face is
reproducible to about 1 % of the tosses handed to this phase (tightened to 1e-9, 0.6-1.0 % of
faces change; about as many as a 1e-6 relative nudge of the handed state changes); no ensemble
fraction (heads, tails, edge) moves by more than a fraction of its standard error. The share of
faces a nudge δ changes grows as about δ^0.45, the signature of a fractal basin boundary
(Grebogi, McDonald, Ott & Yorke, Phys. Lett. A 99 (1983) 415)."""
MAX_STEP = 1e-3
"""Longest step, s (also at most a sixteenth of a turn)."""
SLIDING_MASS_FLOOR = 0.1
"""Least ratio ρ = 1 + K_zt·(F_t/F_n)/K_zz of a sliding rim's normal stiffness to its
frictionless one that :func:`_damper` sizes the damper for (ρ ≤ 0 would be a contact
whose friction drives it into the table, where no mass fits; the damper is then at most
sqrt(10) times its frictionless size). On random rim impacts of a spinning nickel ρ lies in
about 0.75-1.27 at μ = 0.3, 0.50-1.54 at μ = 0.6 and 0.17-1.89 at μ = 1. ρ ≤ 0
needs μ above μ* = K_zz / max K_zt·û, 1.12 for a nickel (near a tilt of 61°), and the floor
bites from μ ≈ 1.008; μ above 1 is not validated (:func:`_damper`)."""
UPRIGHT_DECISION = True
"""Whether :func:`settle` ends a coin rolling upright in its edge band as soon as
:func:`upright_decided` holds (the module notes, "Upright rollers"); False carries it on to
rest, to the bit the integration before this decision. A compile-time constant, not a run-time
switch: numba compiles :func:`settle` (cache=True) with the value this global had then, and its
on-disk cache ignores a later change, so setting it takes effect only after editing this source
and deleting ``src/coinflight/core/__pycache__`` (or in a process with a numba cache directory
of its own). At run time a coin is carried on
past the decision by :func:`advance` with ``decide=False`` (an argument, read at every call)."""


JOINT_DAMPING = True
"""Whether two rims pressed together are damped as one pair (:func:`_pair`: every mode of the
pair at the surface's ζ, so an upright coin restitutes with e; the module notes, "Two rims")
rather than each rim alone as if it carried the coin (False). A compile-time constant, as
:data:`UPRIGHT_DECISION` (its notes say how to change it)."""
JOINT_DEGENERATE = 1e-9
"""Least det W / (W₁₁ W₂₂) of the two rims' normal mobility for which :func:`joint_damping`
damps them together: 0 when both rim circles are one (a corner radius a = h/2) or their arcs'
centroids lie on one vertical line; a nickel with a = h/2 − 25 μm still has ~1e-4."""


class Ending(IntEnum):
    """How :func:`_integrate` (and :func:`advance`) stopped: false when the coin has not
    settled, true when it has, and which way (numba compiles the members as their integers)."""

    RUNNING = 0
    """Not settled: the duration or the step limit ran out first."""
    SETTLED = 1
    """Its energy can no longer take it out of its well (at rest or below its barrier):
    status SETTLED_CONTACT in :func:`settle`."""
    DECIDED = 2
    """Ended on edge by :func:`upright_decided` (a measured predictor, not a proof; the coin
    may still be rolling): status DECIDED_UPRIGHT in :func:`settle`."""


UPRIGHT_MARGIN = 0.5
"""Share of each bound of :func:`upright_decided` the coin may use: the band's restoring moment
m g h′ against the turn's overturning moment, μ N against the friction the turn and the
rolling resistance need, and the lean barrier against the energy of the tilt and bounce
oscillations. The rest is the margin for what the rigid wheel of the proof leaves out (the
contact's compliance, the regularised friction, the yaw driven by a lean rate)."""


@njit(cache=True)
def _tangent_basis(n):
    """(s, ŵ): ŵ the unit vector of the coin's plane pointing most downwards, s = sqrt(1 − n_z²);
    for a coin lying flat any unit vector of its plane."""
    nz = n[2]
    sw = (nz * n[0], nz * n[1], nz * nz - 1.0)  # s ŵ = −Z + n_z n
    s = math.sqrt(dot(sw, sw))
    if s > 1e-12:
        w = (sw[0] / s, sw[1] / s, sw[2] / s)
    else:
        a = (1.0, 0.0, 0.0) if abs(n[0]) < 0.9 else (0.0, 1.0, 0.0)
        t = cross(n, a)
        size = math.sqrt(dot(t, t))
        w = (t[0] / size, t[1] / size, t[2] / size)
    return s, w


@njit(cache=True)
def rim_contact(
    sigma, z, v, n, omega, radius, hh, mass, i1, i3, stiffness, zeta, corner=0.0, friction=0.0
):
    """Normal force of one rim circle on the table: (F_n, centre of pressure q, r_t, energy).

    Its damper is sized for this rim alone; when both rims' arcs are in the table the
    derivative damps them as one pair (:func:`_pair`; both rims' forces as applied:
    :func:`rims_contact`).

    Parameters
    ----------
    sigma : float
        +1 the rim of the heads face, −1 that of the tails face.
    z, v, n, omega
        Height and velocity of the centre of mass, heads normal, angular velocity (lab, SI).
    radius, hh, mass, i1, i3 : float
        The coin: r, h/2, m, I1, I3.
    stiffness, zeta : float
        κ (N/m per radian of rim) and the damping ratio ζ (see the module notes).
    corner : float
        a, the radius of the rim's rounded corners, m: the circle is then that of the core
        cylinder (``radius`` and ``hh`` less a) swept by a ball of radius a, which touches the
        table a below the circle (0: sharp corners).
    friction : float
        μ: with μ > 0 the damper is sized for the normal mass that friction leaves, ζ / sqrt(ρ)
        (:func:`_damper`, the module notes' "Restitution"), as :func:`_derivative` sizes it;
        0 (the default) the frictionless ζ.

    Returns
    -------
    force : float
        Total vertical force F_n ≥ 0 of the arc, N.
    q : tuple of 3 floats
        Centre of pressure relative to the centre of mass (the normal force's torque is
        q × F_n Z), m.
    pivot_radius : float
        r_t, the arc's radius of gyration about its centroid, m.
    energy : float
        Elastic energy of the arc, κ ∫ d²/2 dφ, J.
    """
    s, w = _tangent_basis(n)
    return _rim(
        sigma, z, v, n, omega, s, w, radius, hh, mass, i1, i3, stiffness, zeta, corner, friction
    )


@njit(cache=True)
def _arc(a, b):
    """(φ*, sin φ*, cos φ*) of the arc d(φ) = a + b cos φ > 0 (a + b > 0): φ* = arccos(−a/b),
    π for the whole circle (a ≥ b); the sine from the cosine, sqrt((1 − cos φ*)(1 + cos φ*)),
    exactly 0 at φ* = π."""
    if a >= b:
        return math.pi, 0.0, -1.0
    cp = -a / b
    return math.acos(cp), math.sqrt((1.0 - cp) * (1.0 + cp)), cp


@njit(cache=True)
def _arc_centroid(sigma, n, w, radius, hh, corner, phi, sp):
    """The centroid of rim σ's arc of half-angle φ* relative to the centre of mass, m: σ (h/2) n
    + r (sin φ*/φ*) ŵ − a Z (``radius``, ``hh`` those of the core cylinder, a = ``corner``); the
    face's centre less a Z for the whole circle."""
    k = radius * sp / phi
    return (
        sigma * hh * n[0] + k * w[0],
        sigma * hh * n[1] + k * w[1],
        sigma * hh * n[2] + k * w[2] - corner,
    )


@njit(cache=True, inline="always")
def _rim(
    sigma, z, v, n, omega, s, w, radius, hh, mass, i1, i3, stiffness, zeta, corner, friction=0.0
):
    """:func:`rim_contact` with the coin's tangent basis (s, ŵ) of :func:`_tangent_basis` given
    (it depends on n alone: :func:`_derivative` computes it once for both rims). The arc's
    half-angle φ* = arccos(−A/B), its sine from its cosine, sin φ* = sqrt((1 − cos φ*)(1 +
    cos φ*)): one sine and cosine fewer than from φ*, and exactly 0 at φ* = π. The arc's
    elastic energy is clamped at 0 (its closed form cancels on a short arc).

    With ``friction`` μ > 0 the damper is sized for the normal mass that friction leaves,
    ζ / sqrt(ρ) (:func:`_damper`), from the same arc and
    centroid and the same row of the collision matrix as the frictionless m_eff = 1/K_zz: one
    arccos, one centroid and one I⁻¹ product per rim and derivative, where the damper's own
    helper (``_sliding_damping``, gone) first computed them twice (results identical to the bit,
    ``tests/test_contact_friction.py``). ζ = 0 (the springs' energy alone, :func:`energy`)
    skips the damper."""
    radius -= corner
    hh -= corner
    a = corner - z - sigma * hh * n[2]
    b = radius * s
    if a + b <= 0.0:
        return 0.0, (0.0, 0.0, 0.0), 0.0, 0.0
    phi, sp, cp = _arc(a, b)
    i0 = 2.0 * phi  # ∫ dφ over the arc
    ic = 2.0 * sp  # ∫ cos φ dφ
    icc = phi + sp * cp  # ∫ cos² φ dφ
    elastic = stiffness * (a * i0 + b * ic)
    moment = stiffness * (a * ic + b * icc)  # ∫ κ d cos φ dφ
    # ≥ 0 as the integral of a square; the closed form cancels on a short arc (down to
    # −5e-20 J measured), clamped so that below_barrier's shortcut holds to the bit.
    energy = max(0.0, 0.5 * stiffness * (a * a * i0 + 2.0 * a * b * ic + b * b * icc))
    # Penetration rate, its even part: ḋ = a0 + a1 cos φ (+ a2 sin φ, left out).
    wn = cross(omega, n)
    ww = cross(omega, w)
    a0 = -(v[2] + sigma * hh * wn[2])
    a1 = -radius * ww[2]
    # Damping 2 ζ sqrt(K_t m_eff) ḋ, K_t = 2 φ κ, m_eff at the arc's centroid.
    gamma = 0.0
    if zeta > 0.0:
        centroid = _arc_centroid(sigma, n, w, radius, hh, corner, phi, sp)
        zeta, m_eff = _damper(centroid, v, n, omega, mass, i1, i3, friction, zeta)
        gamma = zeta * math.sqrt(2.0 * phi * stiffness * m_eff) / phi
    force = elastic + gamma * (a0 * i0 + a1 * ic)
    if force <= 0.0:
        return 0.0, (0.0, 0.0, 0.0), 0.0, energy
    moment += gamma * (a0 * ic + a1 * icc)
    # q = Σ f (p − c) / F: p − c = σ (h/2) n + r (cos φ ŵ + sin φ e2); the sin part sums to 0.
    kq = radius * moment / force
    q = (
        sigma * hh * n[0] + kq * w[0],
        sigma * hh * n[1] + kq * w[1],
        sigma * hh * n[2] + kq * w[2] - corner,
    )
    ratio = sp / phi
    pivot = radius * math.sqrt(max(0.0, 1.0 - ratio * ratio))
    return force, q, pivot, energy


@njit(cache=True)
def _damper(rc, v, n, omega, mass, i1, i3, friction, zeta):
    """(ζ / sqrt(ρ), 1/K_zz) of a rim whose arc's centroid is rc (relative to the centre of
    mass, m): the damping ratio for the normal mass its friction leaves (ζ itself for μ = 0) and
    the frictionless normal mass m_eff = 1/K_zz there that :func:`_rim` sizes the damper with,
    from one row of the collision matrix K b = b/m + (I⁻¹(rc × b)) × rc
    (Stronge 2000, eq 5.7; :func:`coinflight.core.impact.collision_matrix`): K b·Z = b·Z/m +
    (rc × b)·I⁻¹(rc × Z), the product I⁻¹(rc × Z) shared by b = Z, X, Y. K_zz so is the one of
    ``impact._coupling(rc, Z, Z, ...)`` to the bit (rc × Z = (rc_y, −rc_x, 0) there too).

    The module notes' "Restitution": ρ = 1 + K_zt·(F_t/F_n) / K_zz with the mobility K, the slip
    u_t and F_t/F_n = −μ u_t / sqrt(u_t² + v_ε²) (the regularised friction's share) all taken at
    the centroid of the rim's arc, the point whose normal mass 1/K_zz sizes the damper (friction
    acts at the centre of pressure q, which depends on the damper's own force; q and the
    centroid lie on one line, both tend to the lowest point for a short arc and to the face's
    centre as the arc closes, so ρ is continuous as the arc becomes the whole circle, near 1 for
    a coin flat on the table); ρ at least :data:`SLIDING_MASS_FLOOR`.

    ρ ≤ 0 where μ K_zt·u_t/sqrt(u_t² + v_ε²) ≥ K_zz: friction then drives the contact into the
    table faster than the normal force pushes it out, a Painlevé-type jam. This needs μ above
    μ* = K_zz / max over slip directions of K_zt·û (for a nickel μ* ≈ 1.12 at a tilt near 61°; the
    floor 0.1 already bites from μ ≈ 1.008). The range μ > 1 is not validated: the t_c → 0
    limit of random rim impacts is about 0.01 m/s from Stronge's law at μ 1.2-2 (largest 0.08
    m/s), against 0.0006 m/s at μ 0.3.

    Each rim's ρ uses that rim's own single-contact K. When both rims' arcs are in the table
    (an impact across the edge band, and every coin rolling upright in it) the pair is damped
    together by :func:`_pair`, from the two centroids' coupled 2×2 normal mobility, each rim's
    ρ scaling its own row and column (the module notes, "Two rims"); this rim's damper alone
    then serves only when the pair's damping would pull on a rim."""
    turn, kzz = _normal_row(rc, n, mass, i1, i3)
    if friction > 0.0:
        zeta = zeta / math.sqrt(_sliding_ratio(rc, turn, kzz, v, omega, friction))
    return zeta, 1.0 / kzz


@njit(cache=True, inline="always")
def _normal_row(rc, n, mass, i1, i3):
    """(I⁻¹(rc × Z), K_zz) of the point rc (relative to the centre of mass, m): the product
    the collision matrix's normal row is built from and its normal entry K_zz = 1/m +
    (rc × Z)·I⁻¹(rc × Z), 1/kg (Stronge 2000, eq 5.7; :func:`_damper`)."""
    arm = (rc[1], -rc[0], 0.0)  # rc × Z
    turn = inverse_inertia_apply(arm, n, i1, i3)
    return turn, 1.0 / mass + dot(arm, turn)


@njit(cache=True, inline="always")
def _sliding_ratio(rc, turn, kzz, v, omega, friction):
    """ρ of :func:`sliding_mass_ratio` at the point rc, from :func:`_normal_row`'s (turn, K_zz)
    and the material point's slip v + ω × rc (:func:`_damper`)."""
    u = cross(omega, rc)
    kzx = dot((0.0, rc[2], -rc[1]), turn)  # rc × X
    kzy = dot((-rc[2], 0.0, rc[0]), turn)  # rc × Y
    return sliding_mass_ratio(kzx, kzy, kzz, v[0] + u[0], v[1] + u[1], friction, SLIP_SPEED)


@njit(cache=True)
def sliding_mass_ratio(kzx, kzy, kzz, ux, uy, friction, slip_speed):
    """ρ = max(1 + K_zt·(F_t/F_n) / K_zz, :data:`SLIDING_MASS_FLOOR`) of a contact point
    whose collision matrix has the normal row (K_zx, K_zy, K_zz) (1/kg) and whose slip is
    (u_x, u_y) (m/s), F_t/F_n = −μ u_t / sqrt(u_t² + v_ε²) the regularised friction's share
    (v_ε = ``slip_speed``): the ratio of the normal effective mass's inverse with that friction,
    K_zz + K_zt·F_t/F_n, to the frictionless K_zz (Stronge 2000, eq 5.7 and ch. 4), as
    :func:`_damper` sizes a rim's damper with it."""
    share = friction / math.sqrt(ux * ux + uy * uy + slip_speed * slip_speed)
    return max(1.0 - share * (kzx * ux + kzy * uy) / kzz, SLIDING_MASS_FLOOR)


@njit(cache=True, inline="always")
def _rims(z, v, n, omega, s, w, lower, c, stiffness, zeta):
    """Both rims' (F_n, q, r_t) as :func:`_derivative` applies them, the lower rim (σ =
    ``lower``) first: when both arcs are non-empty (:data:`JOINT_DAMPING`), :func:`_pair`'s,
    the pair damped together if both its forces are positive, else each rim alone (the module
    notes, "Two rims"); otherwise each rim's :func:`_rim` (its damper sized alone, ζ/sqrt(ρ)),
    as before. Inlined into the derivative and into :func:`upright_decided`. Also returned:
    whether the pair was damped jointly, and its damping matrix (C₁₁, C₁₂, C₂₂) then (NaNs
    otherwise; :func:`rims_contact`)."""
    if JOINT_DAMPING and zeta > 0.0 and _both_arcs(z, n, s, lower, c):
        joint, g1, p1, t1, g2, p2, t2, c11, c12, c22 = _pair(
            lower, z, v, n, omega, s, w, c, stiffness, zeta
        )
        if joint:
            return g1, p1, t1, g2, p2, t2, True, c11, c12, c22
        return g1, p1, t1, g2, p2, t2, False, math.nan, math.nan, math.nan
    f1, q1, r1 = 0.0, (0.0, 0.0, 0.0), 0.0
    f2, q2, r2 = 0.0, (0.0, 0.0, 0.0), 0.0
    for sigma in (lower, -lower):
        # each rim's damper for the normal mass its friction leaves (_damper's), in _rim
        fn, q, rt, _ = _rim(
            sigma,
            z,
            v,
            n,
            omega,
            s,
            w,
            c.radius,
            c.half_thickness,
            c.mass,
            c.i1,
            c.i3,
            stiffness,
            zeta,
            c.corner_radius,
            c.friction,
        )
        if sigma == lower:
            f1, q1, r1 = fn, q, rt
        else:
            f2, q2, r2 = fn, q, rt
    return f1, q1, r1, f2, q2, r2, False, math.nan, math.nan, math.nan


@njit(cache=True, inline="always")
def _both_arcs(z, n, s, lower, c):
    """Whether both rims' arcs are non-empty (d(φ) > 0 somewhere), decided as :func:`_rim`
    decides it (a + b > 0, the same operations)."""
    radius = c.radius - c.corner_radius
    hh = c.half_thickness - c.corner_radius
    b = radius * s
    upper = -lower
    return c.corner_radius - z - lower * hh * n[2] + b > 0.0 and (
        c.corner_radius - z - upper * hh * n[2] + b > 0.0
    )


@njit(cache=True)
def rims_contact(y, c, stiffness, zeta):
    """Both rims' normal forces as :func:`_derivative` applies them, for tests and studies:
    (σ₁, F₁, q₁, F₂, q₂, joint, C₁₁, C₁₂, C₂₂), rim 1 the lower one (σ₁ = −1, the tails rim,
    when n_z ≥ 0), rim 2 = −σ₁; F ≥ 0 (N) and the centres of pressure q (m, relative to the
    centre of mass) of :func:`rim_contact`; ``joint`` whether the pair is damped together
    (:func:`_pair`), and then its damping matrix C (N s/m), else NaNs."""
    v = (y[1], y[2], y[3])
    n = (y[4], y[5], y[6])
    omega = angular_velocity((y[7], y[8], y[9]), n, c.i1, c.i3)
    lower = -1.0 if n[2] >= 0.0 else 1.0
    s, w = _tangent_basis(n)
    f1, q1, _, f2, q2, _, joint, c11, c12, c22 = _rims(
        y[0], v, n, omega, s, w, lower, c, stiffness, zeta
    )
    return lower, f1, q1, f2, q2, joint, c11, c12, c22


@njit(cache=True)
def joint_damping(w11, w12, w22, k1, k2, zeta):
    """(ok, C₁₁, C₁₂, C₂₂): the damping matrix C = 2 ζ M^½ (M^−½ K M^−½)^½ M^½ of two contacts
    with the normal mobility W (1/kg; M = W⁻¹ their mass matrix) and the tangent stiffnesses
    K = diag(k₁, k₂) (N/m), which damps every mode of M ẍ + C ẋ + K x = 0 at the ratio ζ
    (Caughey's modal damping; Caughey & O'Kelly, J. Appl. Mech. 32:583, 1965). It is 2 ζ
    times the geometric mean M # K of the two positive matrices, symmetric and positive
    definite (Bhatia, *Positive Definite Matrices*, 2007, §4.1), and for one contact
    (k₂ → 0) the single damper 2 ζ sqrt(k₁/W₁₁), which :func:`_rim` applies.

    In closed form, no matrix function evaluated: the square root of a 2 × 2 positive matrix,
    sqrt(A) = (A + sqrt(det A) I) / sqrt(tr A + 2 sqrt(det A)) (Cayley–Hamilton; Levinger,
    Math. Mag. 53:222, 1980), gives for det A = det B = 1 the geometric mean
    A # B = (A + B) / sqrt(det(A + B)) (the 2 × 2 case in Bhatia 2007, ch. 4: the positive
    solution of G A⁻¹ G = B, which ``tests/test_two_rim_damping.py`` checks against the
    definition with SciPy's sqrtm), and by its homogeneity
    M # K = sqrt(αβ) (M/α + K/β) / sqrt(det(M/α + K/β)), α = sqrt(det M) = 1/sqrt(det W),
    β = sqrt(k₁ k₂), M/α = adj(W)/sqrt(det W). det(M/α + K/β) ≥ 4 (two unit-determinant
    positive matrices), so nothing cancels but det W, which is the rims' separation: ok is
    False when det W ≤ :data:`JOINT_DEGENERATE` W₁₁ W₂₂ (two contacts on one vertical line, a
    rim without a flat band, a = h/2; the caller then damps each alone)."""
    det = w11 * w22 - w12 * w12
    if not det > JOINT_DEGENERATE * w11 * w22 or not k1 > 0.0 or not k2 > 0.0:
        return False, 0.0, 0.0, 0.0
    root = math.sqrt(det)
    ratio = math.sqrt(k1 / k2)
    s11 = w22 / root + ratio
    s22 = w11 / root + 1.0 / ratio
    s12 = -w12 / root
    scale = 2.0 * zeta * math.sqrt(math.sqrt(k1 * k2) / (root * (s11 * s22 - s12 * s12)))
    return True, scale * s11, scale * s12, scale * s22


@njit(cache=True, inline="always")
def _pair_rim(
    sigma, z, v, n, omega, s, w, wn, ww, radius, hh, mass, i1, i3, stiffness, corner, friction
):
    """What :func:`_pair` needs of rim σ (``radius``, ``hh`` those of the core cylinder):
    (K_t = 2 φ κ, elastic force, its moment ∫ κ d cos φ, ∫ ḋ_s, ∫ ḋ_s cos φ, 2 φ, 2 sin φ, ρ,
    K_zz, I⁻¹(rc × Z), rc, r_t, φ*), from :func:`_rim`'s arc sums, in its operations; K_t 0
    for an empty arc."""
    zero = (0.0, 0.0, 0.0)
    a = corner - z - sigma * hh * n[2]
    b = radius * s
    if a + b <= 0.0:
        return 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 0.0, zero, zero, 0.0, 1.0
    phi, sp, cp = _arc(a, b)
    i0 = 2.0 * phi
    ic = 2.0 * sp
    icc = phi + sp * cp
    a0 = -(v[2] + sigma * hh * wn[2])
    a1 = -radius * ww[2]
    rc = _arc_centroid(sigma, n, w, radius, hh, corner, phi, sp)
    turn, kzz = _normal_row(rc, n, mass, i1, i3)
    rho = _sliding_ratio(rc, turn, kzz, v, omega, friction) if friction > 0.0 else 1.0
    elastic = stiffness * (a * i0 + b * ic)
    moment = stiffness * (a * ic + b * icc)
    rate = a0 * i0 + a1 * ic
    turning = a0 * ic + a1 * icc
    ratio = sp / phi
    pivot = radius * math.sqrt(max(0.0, 1.0 - ratio * ratio))
    return i0 * stiffness, elastic, moment, rate, turning, i0, ic, rho, kzz, turn, rc, pivot, phi


@njit(cache=True, inline="always")
def _alone(sigma, rim, n, w, radius, hh, corner, friction, zeta):
    """(F_n, q, r_t) of rim σ damped alone from :func:`_pair_rim`'s sums ``rim``: :func:`_rim`'s
    force, in its operations (the damper ζ/sqrt(ρ) sqrt(K_t m_eff)/φ*, m_eff = 1/K_zz,
    :func:`_damper`), so the same to the bit. For :func:`_pair`'s fall-back, which so does not
    compute the rims' arcs twice."""
    k, elastic, moment, rate, turning, _, _, rho, kzz, _, _, pivot, phi = rim
    if friction > 0.0:
        zeta = zeta / math.sqrt(rho)
    gamma = zeta * math.sqrt(k * (1.0 / kzz)) / phi
    force = elastic + gamma * rate
    if force <= 0.0:
        return 0.0, (0.0, 0.0, 0.0), 0.0
    moment += gamma * turning
    kq = radius * moment / force
    q = (
        sigma * hh * n[0] + kq * w[0],
        sigma * hh * n[1] + kq * w[1],
        sigma * hh * n[2] + kq * w[2] - corner,
    )
    return force, q, pivot


@njit(cache=True)
def _pair(lower, z, v, n, omega, s, w, c, stiffness, zeta):
    """Both rims' (ok, F₁, q₁, r_t₁, F₂, q₂, r_t₂, C₁₁, C₁₂, C₂₂) damped together (the module
    notes, "Two rims"), rim 1 σ = ``lower``, rim 2 σ = −``lower``; ok False when a rim's
    joint force would not be positive or the pair is degenerate (:func:`joint_damping`), and
    then the forces are each rim's alone (:func:`_alone`: :func:`_rim`'s to the bit, from the
    same sums; zeros when an arc is empty). The pivot radii r_t are :func:`_rim`'s, computed
    here.

    Each rim's arc, its sums and its centroid rc_i are :func:`_rim`'s; the pair's normal
    mobility is W_ij = 1/m + (rc_i × Z)·I⁻¹(rc_j × Z) (the normal block of Stronge's collision
    matrix for two points, Stronge 2000, eq 5.7: :func:`_normal_row`), its tangent stiffnesses
    k_i = 2 φ_i κ. The sliding correction stays each rim's own (:func:`_damper`): ρ_i at the
    rim's centroid, entering as the congruence W̃ = P^½ W P^½, P = diag(ρ₁, ρ₂) (each rim's
    normal row and column scaled by sqrt(ρ_i), its K_zz by ρ_i as for one rim, the coupling by
    the geometric mean sqrt(ρ₁ ρ₂)), so that C stays symmetric positive and is :func:`_rim`'s
    damper 2 (ζ/sqrt(ρ_i)) sqrt(k_i/K_zz) when the other arc vanishes. The coupled friction
    terms between the rims (the collision matrix's K_zt of one rim's friction at the other's
    normal, not symmetric) are left out: a viscous damper needs a symmetric mass.

    The damping forces D = C ḋ act on the arcs' mean penetration rates ḋ_i = a0 + a1 sin φ/φ
    (the normal velocity of the centroid's material point): each rim's own part C_ii ḋ_i
    spread over its arc as :func:`_rim`'s, γ_i ḋ_s(φ) with γ_i = C_ii/(2 φ_i), the coupling
    C_ij ḋ_j spread evenly over the arc (acting at its centroid). Both act in the arc's plane
    of symmetry (no torque about n or the vertical: L·n and L_z conserved without friction),
    and the power they take, ḋᵀ C ḋ + Σ C_ii var_i(ḋ_s) ≥ 0 (var_i the spread of the even
    rate over arc i), is never negative: the pair still only dissipates."""
    mass, i1, i3, corner, friction = c.mass, c.i1, c.i3, c.corner_radius, c.friction
    radius = c.radius - corner
    hh = c.half_thickness - corner
    zero = (0.0, 0.0, 0.0)
    fail = (False, 0.0, zero, 0.0, 0.0, zero, 0.0, 0.0, 0.0, 0.0)
    wn = cross(omega, n)
    ww = cross(omega, w)
    one = _pair_rim(
        lower, z, v, n, omega, s, w, wn, ww, radius, hh, mass, i1, i3, stiffness, corner, friction
    )
    two = _pair_rim(
        -lower, z, v, n, omega, s, w, wn, ww, radius, hh, mass, i1, i3, stiffness, corner, friction
    )
    if one[0] <= 0.0 or two[0] <= 0.0:
        return fail
    k1, el1, mo1, d1, e1, i01, ic1, rho1, kz1, t1, _, r1, _ = one
    k2, el2, mo2, d2, e2, i02, ic2, rho2, kz2, _, c2, r2, _ = two
    w12 = (1.0 / mass + dot((c2[1], -c2[0], 0.0), t1)) * math.sqrt(rho1 * rho2)
    ok, c11, c12, c22 = joint_damping(rho1 * kz1, w12, rho2 * kz2, k1, k2, zeta)
    rate1 = d1 / i01  # the arcs' mean penetration rates
    rate2 = d2 / i02
    g1 = c11 / i01
    g2 = c22 / i02
    f1 = el1 + g1 * d1 + c12 * rate2
    f2 = el2 + g2 * d2 + c12 * rate1
    if not (ok and f1 > 0.0 and f2 > 0.0):
        # each rim alone, from the same sums (to the bit _rim's: the module notes, "Two rims")
        a1, b1, s1 = _alone(lower, one, n, w, radius, hh, corner, friction, zeta)
        a2, b2, s2 = _alone(-lower, two, n, w, radius, hh, corner, friction, zeta)
        return False, a1, b1, s1, a2, b2, s2, c11, c12, c22
    m1 = mo1 + g1 * e1 + c12 * rate2 * ic1 / i01
    m2 = mo2 + g2 * e2 + c12 * rate1 * ic2 / i02
    kq1 = radius * m1 / f1
    kq2 = radius * m2 / f2
    q1 = (
        lower * hh * n[0] + kq1 * w[0],
        lower * hh * n[1] + kq1 * w[1],
        lower * hh * n[2] + kq1 * w[2] - corner,
    )
    q2 = (
        -lower * hh * n[0] + kq2 * w[0],
        -lower * hh * n[1] + kq2 * w[1],
        -lower * hh * n[2] + kq2 * w[2] - corner,
    )
    return True, f1, q1, r1, f2, q2, r2, c11, c12, c22


@njit(cache=True)
def _derivative(y, out, c, stiffness, zeta):
    """dy/dt of the state y = (z, v, n, L) in contact (the forces of the module notes).

    About 0.1 µs a call on one core. :func:`_rim` is inlined into it (``inline="always"``);
    this one is not inlined into :func:`_integrate`'s seven calls, which would buy about 10 %
    more speed for twice the compile time."""
    mass, i1, i3, radius = c.mass, c.i1, c.i3, c.radius
    mu, rolling, pivoting = c.friction, c.rolling_resistance, c.pivoting_resistance
    v = (y[1], y[2], y[3])
    n = (y[4], y[5], y[6])
    lm = (y[7], y[8], y[9])
    omega = angular_velocity(lm, n, i1, i3)
    spin_eps = SLIP_SPEED / radius
    fx, fy, fz = 0.0, 0.0, -mass * c.g
    tx, ty, tz = 0.0, 0.0, 0.0
    # The lower rim first: the same sums, in the same order, for the mirror toss (n → −n).
    lower = -1.0 if n[2] >= 0.0 else 1.0
    s, w = _tangent_basis(n)
    f1, q1, r1, f2, q2, r2, _, _, _, _ = _rims(y[0], v, n, omega, s, w, lower, c, stiffness, zeta)
    for k in range(2):
        fn, q, rt = (f1, q1, r1) if k == 0 else (f2, q2, r2)
        if fn <= 0.0:
            continue
        fz += fn
        tx += q[1] * fn  # q × (0, 0, F_n)
        ty -= q[0] * fn
        if mu > 0.0:
            u = cross(omega, q)
            ux, uy = v[0] + u[0], v[1] + u[1]
            k = -mu * fn / math.sqrt(ux * ux + uy * uy + SLIP_SPEED * SLIP_SPEED)
            gx, gy = k * ux, k * uy
            fx += gx
            fy += gy
            tx -= q[2] * gy  # q × (gx, gy, 0)
            ty += q[2] * gx
            tz += q[0] * gy - q[1] * gx
        drill = mu * rt + pivoting
        if drill > 0.0:
            tz -= drill * fn * omega[2] / math.sqrt(omega[2] * omega[2] + spin_eps * spin_eps)
        if rolling > 0.0:
            k = (
                -rolling
                * fn
                / math.sqrt(omega[0] * omega[0] + omega[1] * omega[1] + spin_eps * spin_eps)
            )
            tx += k * omega[0]
            ty += k * omega[1]
    nd = cross(omega, n)
    out[0] = v[2]
    out[1] = fx / mass
    out[2] = fy / mass
    out[3] = fz / mass
    out[4] = nd[0]
    out[5] = nd[1]
    out[6] = nd[2]
    out[7] = tx
    out[8] = ty
    out[9] = tz


@njit(cache=True)
def energy(y, c, stiffness):
    """Mechanical energy of the state y = (z, v, n, L): ½ m v² + ½ L·ω + m g z + the springs', J."""
    return _with_springs(_motion_energy(y, c), y, c, stiffness)


@njit(cache=True, inline="always")
def _motion_energy(y, c):
    """½ m v² + ½ L·ω + m g z of the state y, J: :func:`energy` without the springs'."""
    v = (y[1], y[2], y[3])
    n = (y[4], y[5], y[6])
    lm = (y[7], y[8], y[9])
    omega = angular_velocity(lm, n, c.i1, c.i3)
    return 0.5 * c.mass * dot(v, v) + 0.5 * dot(lm, omega) + c.mass * c.g * y[0]


@njit(cache=True, inline="always")
def _motion_free_energy(y, c):
    """(e, f): :func:`_motion_energy` and its part that :func:`free_energy` sets against the
    barrier without springs: all of it with friction or resistances, else less the horizontal
    kinetic energy (conserved, not free). Shared with
    :func:`coinflight.core.rigid_contact.below_barrier`."""
    e = _motion_energy(y, c)
    if _dissipative(c):
        return e, e
    return e, e - 0.5 * c.mass * (y[1] * y[1] + y[2] * y[2])


@njit(cache=True)
def _with_springs(e, y, c, stiffness):
    """e plus the elastic energy of both rims' arcs (:func:`rim_contact`), added in the order of
    :func:`energy`, J."""
    v = (y[1], y[2], y[3])
    n = (y[4], y[5], y[6])
    lm = (y[7], y[8], y[9])
    omega = angular_velocity(lm, n, c.i1, c.i3)
    lower = -1.0 if n[2] >= 0.0 else 1.0
    s, w = _tangent_basis(n)
    for sigma in (lower, -lower):
        _, _, _, spring = _rim(
            sigma,
            y[0],
            v,
            n,
            omega,
            s,
            w,
            c.radius,
            c.half_thickness,
            c.mass,
            c.i1,
            c.i3,
            stiffness,
            0.0,
            c.corner_radius,
        )
        e += spring
    return e


@njit(cache=True)
def _corner_energy(ln, lz, nz, c):
    """Least energy of the coin balanced on a corner at n_z = nz with L·n = ln and L_z = lz."""
    return c.barrier + 0.5 * ln * ln / c.i3 + 0.5 * (lz - ln * nz) ** 2 / (c.i1 * (1.0 - nz * nz))


@njit(cache=True, inline="always")
def _dissipative(c):
    """Whether anything but the normal damping dissipates (friction or a resistance)."""
    return c.friction > 0.0 or c.rolling_resistance > 0.0 or c.pivoting_resistance > 0.0


@njit(cache=True, inline="always")
def _barrier(y, c):
    """The barrier of :func:`free_energy`, J: m g ρ with friction or resistances, else the least
    energy on the corners of the well at the conserved L·n, L_z."""
    if _dissipative(c):
        return c.barrier
    ln = y[4] * y[7] + y[5] * y[8] + y[6] * y[9]
    lz = y[9]
    nz = y[6]
    corner = c.edge_sine
    up = _corner_energy(ln, lz, corner, c)
    down = _corner_energy(ln, lz, -corner, c)
    if abs(nz) < corner:
        return min(up, down)
    return up if nz > 0.0 else down


@njit(cache=True)
def free_energy(y, c, stiffness):
    """(energy that can lift the coin, barrier of its well), J (module notes, "ending").

    With friction or resistances: the mechanical energy and m g ρ. Frictionless: the energy
    less ½ m v_h² and the least energy on the corners of the well at the conserved L·n, L_z.
    """
    e = energy(y, c, stiffness)
    if not _dissipative(c):
        e -= 0.5 * c.mass * (y[1] * y[1] + y[2] * y[2])
    return e, _barrier(y, c)


@njit(cache=True, inline="always")
def below_barrier(y, c, stiffness):
    """``free < barrier`` of :func:`free_energy`, decided alike to the bit, but without the
    springs' energy (two :func:`rim_contact` sums) when the rest of the energy already reaches
    the barrier: the springs' energies are ≥ 0 (:func:`rim_contact` clamps its energy at 0,
    where the closed form's cancellation on a short arc gives down to −5e-20 J) and rounded
    addition and subtraction are monotonic, so adding them cannot bring the sum below it. The
    test :func:`_integrate` makes after every step; inlined there (``inline="always"``, with
    the energy's pieces: ~3 % of a step)."""
    e, free = _motion_free_energy(y, c)
    barrier = _barrier(y, c)
    if free >= barrier:
        return False
    e = _with_springs(e, y, c, stiffness)
    if not _dissipative(c):
        e -= 0.5 * c.mass * (y[1] * y[1] + y[2] * y[2])
    return e < barrier


SINGLE_RIM_DEPTH = 2.0 ** (2.0 / 3.0)
"""How much deeper one rim sinks carrying the whole weight than each of two carrying half of it
(F ∝ d^(3/2) on a short arc): the depth on the lean's ridge is this times :func:`static_depth`."""


@njit(cache=True)
def static_depth(c, stiffness):
    """d_s, m: how deep an upright coin at rest sinks into the table (module notes, "Upright
    rollers"), both rims' arcs in the parabolic approximation of the rim, 1 − cos φ ≈ φ²/2:
    each carries F = (4√2/3) κ d^(3/2) / sqrt(r − a) = m g / 2 and stores (2/5) F d. The exact
    arc's penetration d − (r − a)(1 − cos φ) is the larger at every φ, so its springs store more
    at every depth, and the least potential energy (gravity and springs) of an upright coin is
    at least that of the approximation, m g (r − d_s) + (2/5) m g d_s = m g (r − (3/5) d_s);
    so is, with the depth d_1 = 2^(2/3) d_s of one rim carrying m g alone, that of a coin on one
    rim whose rigid centre height is H: m g (H − (3/5) d_1) (the other rim's springs, dropped,
    only add)."""
    radius = c.radius - c.corner_radius
    weight = c.mass * c.g
    return (3.0 * weight * math.sqrt(radius) / (8.0 * math.sqrt(2.0) * stiffness)) ** (2.0 / 3.0)


BUDGET_STEP = 1e-4
"""Seconds a step of :func:`_integrate` is taken to cover when :func:`upright_decided` asks
whether the steps left can carry a roller to rest: below the mean step measured in upright
rolling (~0.6 ms: ~1,600 steps a simulated second at t_c 1 ms), so that a roller
which would run out of :data:`MAX_STEPS` is not decided (the decision turns no UNSETTLED toss
into a settled one);
:data:`MAX_STEP` (1 ms) was too loose (rollers of 250–400 s decided). A contact time far below
1 ms shortens the steps below this."""


@njit(cache=True, inline="always")
def upright_decided(y, c, stiffness, zeta, budget):
    """True if the coin in state y = (z, v, n, L) rolls upright on both rims of its edge band
    and the rigid wheel's bounds hold with :data:`UPRIGHT_MARGIN` to spare (module notes,
    "Upright rollers"): a measured predictor of ending on edge (coins it decides, carried on
    to rest instead, end on edge), not a proof that it stays upright to rest.

    In this order (cheap tests first): a band (h′ = h/2 − a > 0) and friction (μ > 0); the
    turn's overturning moment M = (I3 |ω·n| + m r |v_h|) |ω_z| at most :data:`UPRIGHT_MARGIN`
    of the band's m g h′; the friction the turn and the rolling resistance need,
    sqrt((m |v_h| |ω_z|)² + F_r²), F_r = m ℓ_r m g r / (I3 + m r²), at most that share of μ m g;
    both rims pressed (their forces as :func:`_derivative` applies them, :func:`_rims`: each
    rim's damper sized alone, :func:`_damper`, or the pair's joint damping, :func:`_pair`:
    the force they exert now); the
    band's middle not slipping (the horizontal velocity of its lowest point below
    :data:`SLIP_SPEED`); the tilt below the lean's ridge θ*; and the energy that can lean the
    coin (the whole energy less the rolling and yawing kinetic energy ½ m (v·t̂)² + ½ I3 (ω·n)²
    + ½ I1 (ω·ŵ)², t̂ the horizontal unit vector across n) above the least potential energy
    upright, m g (r − (3/5) d_s) (:func:`static_depth`), by at most that share of the ridge's
    height above it (the notes).

    First of all, the coin must come to rest within ``budget`` s (the time the integration's
    remaining steps can cover, (steps left) × :data:`BUDGET_STEP` in :func:`_integrate`):
    with no rolling resistance (ℓ_r ≤ 0) it never stops rolling, and otherwise the resistance
    brakes ω = v/r at most at the rate ℓ_r m g / (I3 + m r²) (the torque ℓ_r F_n of
    :func:`_derivative`, N = m g on the two rims, weaker below its regularisation), so it rolls
    at least (v/r) (I3 + m r²) / (ℓ_r m g). A roller that carried on would end UNSETTLED after
    :data:`MAX_STEPS` is not decided, so that the decision turns no UNSETTLED toss into a
    decided one.
    """
    hb = c.half_thickness - c.corner_radius  # h′: half the flat band
    if hb <= 0.0 or c.friction <= 0.0 or c.rolling_resistance <= 0.0:
        return False
    mass, i1, i3, g, radius = c.mass, c.i1, c.i3, c.g, c.radius
    weight = mass * g
    v = (y[1], y[2], y[3])
    n = (y[4], y[5], y[6])
    lm = (y[7], y[8], y[9])
    across = math.sqrt(n[0] * n[0] + n[1] * n[1])
    if across < 0.5:
        return False  # not near upright (two rims touch only within the band's tilt)
    omega = angular_velocity(lm, n, i1, i3)
    spin = dot(omega, n)
    yaw = abs(omega[2])
    vh = math.sqrt(v[0] * v[0] + v[1] * v[1])
    brake = c.rolling_resistance * weight / (i3 + mass * radius * radius)  # dω/dt, rad/s²
    if vh / radius > brake * budget:
        return False  # rolls longer than the steps left can reach
    moment = (i3 * abs(spin) + mass * radius * vh) * yaw
    if moment > UPRIGHT_MARGIN * weight * hb:
        return False
    resist = mass * c.rolling_resistance * weight * radius / (i3 + mass * radius * radius)
    turn = mass * vh * yaw
    if math.sqrt(turn * turn + resist * resist) > UPRIGHT_MARGIN * c.friction * weight:
        return False
    s, w = _tangent_basis(n)
    lower = -1.0 if n[2] >= 0.0 else 1.0
    f1, _, _, f2, _, _, _, _, _, _ = _rims(y[0], v, n, omega, s, w, lower, c, stiffness, zeta)
    if f1 <= 0.0 or f2 <= 0.0:  # both rims pressed, as _derivative presses them
        return False
    core = radius - c.corner_radius  # r − a, the rim circle's radius
    low = (core * w[0], core * w[1], core * w[2] - c.corner_radius)  # the band middle's lowest
    u = cross(omega, low)
    ux, uy = v[0] + u[0], v[1] + u[1]
    if ux * ux + uy * uy > SLIP_SPEED * SLIP_SPEED:
        return False
    t = (-n[1] / across, n[0] / across, 0.0)
    vt = dot(v, t)
    ww = dot(omega, w)
    rolling = 0.5 * mass * vt * vt + 0.5 * i3 * spin * spin + 0.5 * i1 * ww * ww
    free = energy(y, c, stiffness) - rolling
    # The ridge of the lean: the coin on one rim at the tilt θ* where the restoring moment
    # m g (h′ cos θ − (r − a) sin θ) of the rigid pivot meets M, sunk to the depth at which that
    # rim alone carries m g, the turn's work M (θ* + θ_now) and the spin's (I3 − I1) ω_z²
    # sin²θ* / 2 taken off (the notes).
    depth = static_depth(c, stiffness)
    floor = weight * (radius - 0.6 * depth)  # least potential energy upright, at most
    reach = math.sqrt(core * core + hb * hb)
    tip = math.acos(moment / (weight * reach)) - math.acos(hb / reach)
    lean = math.asin(min(abs(n[2]), 1.0))
    if lean >= tip:
        return False
    ridge = weight * (core * math.cos(tip) + hb * math.sin(tip) + c.corner_radius)
    ridge -= 0.6 * weight * SINGLE_RIM_DEPTH * depth + moment * (tip + lean)
    ridge -= 0.5 * max(i3 - i1, 0.0) * yaw * yaw * math.sin(tip) ** 2
    return ridge > floor and free <= floor + UPRIGHT_MARGIN * (ridge - floor)


MODES = ("free", "one rim", "two rims", "face")
"""What the coin is doing, as :func:`contact_mode` classes it: off the table (a hop), on one
rim's arc with less than half the rim pressed (rolling, sliding, pivoting or rocking on a rim
point), on both rims (the edge band, or two points of a coin rocking across its edge), on its
face (one rim pressed along more than half its circle: lying flat, spinning or sliding)."""


@njit(cache=True)
def contact_mode(y, c):
    """The index in :data:`MODES` of what the coin in state y = (z, v, n, L) is doing."""
    n = (y[4], y[5], y[6])
    s = math.sqrt(max(0.0, 1.0 - n[2] * n[2]))
    radius = c.radius - c.corner_radius
    hh = c.half_thickness - c.corner_radius
    touching = 0
    face = False
    for sigma in (-1.0, 1.0):
        a = c.corner_radius - y[0] - sigma * hh * n[2]
        b = radius * s
        if a + b > 0.0:
            touching += 1
            if a >= 0.0:  # the arc covers more than half the rim (cos φ* = −a/b ≤ 0)
                face = True
    if touching == 0:
        return 0
    if touching == 2:
        return 2
    return 3 if face else 1


@njit(cache=True)
def _integrate(y, duration, c, stiffness, zeta, settle, decide, max_steps, stats, rtol):
    """Advance y in place for ``duration`` s (math.inf: no limit) or, if ``settle``, until the
    coin has settled, whichever comes first; with ``settle`` and ``decide``, a coin for which
    :func:`upright_decided` holds has settled too (on edge). ``stats`` (shape (len(MODES), 2),
    or (0, 2) for none) accumulates, per :func:`contact_mode` at the end of each step, the time
    and the steps taken (for the benchmark); with one more row (shape (len(MODES) + 1, 2),
    filled with −1 by the caller), that row receives (time, steps) when
    :func:`upright_decided` first holds, with or without ``decide`` (so a run carried to rest
    says where the decision would have ended it; the test runs at every step then). ``rtol``
    is the step control's relative tolerance (:data:`RTOL` but in tests).

    Returns (time advanced, accepted steps, :class:`Ending`): RUNNING (not settled), SETTLED
    (by the energy test) or DECIDED (by :func:`upright_decided`, with ``decide``).

    A step costs about 1 µs of one core: six derivatives (:func:`_derivative`), the tests after
    the step (:func:`below_barrier`, :func:`upright_decided`) and the stepper's arithmetic.
    """
    k1, k2, k3, k4, k5, k6, k7, tmp, new = dp.workspace(10)
    scale = np.empty(10)
    reach = c.reach
    speed = max(math.sqrt(c.g * reach), 0.01)  # velocity scale of the tolerances, m/s
    scale[0] = reach
    for i in range(1, 4):
        scale[i] = speed
        scale[i + 3] = 1.0
        scale[i + 6] = c.i1 * speed / reach
    contact_time = c.contact_time
    h = contact_time / 20.0
    t = 0.0
    _derivative(y, k1, c, stiffness, zeta)
    modes = len(MODES)
    probe = stats.shape[0] > modes
    for step in range(max_steps):
        if settle:
            if below_barrier(y, c, stiffness):
                return t, step, Ending.SETTLED
            if (decide or (probe and stats[modes, 1] < 0.0)) and upright_decided(
                y, c, stiffness, zeta, (max_steps - step) * BUDGET_STEP
            ):
                if probe and stats[modes, 1] < 0.0:
                    stats[modes, 0] = t
                    stats[modes, 1] = step
                if decide:
                    return t, step, Ending.DECIDED
        if t >= duration:
            return t, step, Ending.RUNNING
        lm = (y[7], y[8], y[9])
        n = (y[4], y[5], y[6])
        omega = angular_velocity(lm, n, c.i1, c.i3)
        turn = 0.125 * math.pi / (math.sqrt(dot(omega, omega)) + 1e-300)
        limit = min(MAX_STEP, turn, duration - t)
        if h > limit:
            h = limit
        for _ in range(60):
            for s in range(2, 8):
                point = dp.stage(s, y, h, k1, k2, k3, k4, k5, k6, new if s == 7 else tmp)
                _derivative(point, dp.rate(s, k2, k3, k4, k5, k6, k7), c, stiffness, zeta)
            err = dp.error_ratio(y, new, h, k1, k3, k4, k5, k6, k7, rtol, scale, 10)
            if err <= 1.0:
                break
            h *= max(0.2, 0.9 * err**-0.2)
        t += h
        if stats.shape[0] > 0:
            mode = contact_mode(new, c)
            stats[mode, 0] += h
            stats[mode, 1] += 1.0
        # Keep n a unit vector (the exact flow does).
        size = math.sqrt(new[4] * new[4] + new[5] * new[5] + new[6] * new[6])
        for i in range(10):
            y[i] = new[i]
        y[4] /= size
        y[5] /= size
        y[6] /= size
        # First same as last: k7, the derivative at the step's end before n's renormalisation
        # (a change of |n| by ≲1e-10 at RTOL 1e-7, measured, far below the step's tolerance
        # ~2e-7; re-evaluating it cost a seventh derivative in 96 % of the steps).
        for i in range(10):
            k1[i] = k7[i]
        h *= min(5.0, 0.9 * err**-0.2) if err > 0.0 else 5.0
    return t, max_steps, Ending.RUNNING


@njit(cache=True)
def stiffness_of(c):
    """κ = π m / (2 t_c²), N/m per radian of rim (module notes)."""
    return math.pi * c.mass / (2.0 * c.contact_time * c.contact_time)


@njit(cache=True)
def damping_of(c):
    """ζ of the contact record's restitution: the one :meth:`coinflight.core.contact.Contact.build`
    solved for, or, for another e (a toss's own, :func:`coinflight.core.bounce.with_surface`),
    :func:`tabulated_damping_ratio`."""
    if c.damping_restitution == c.restitution and c.damping_ratio >= 0.0:
        return c.damping_ratio
    return tabulated_damping_ratio(c.restitution)


@njit(cache=True)
def settle(z, v, n, lm, c):
    """Carry the coin on in contact until it cannot leave its well: (face, status, time).

    Parameters
    ----------
    z : float
        Height of the centre of mass above the table, m.
    v, n, lm : tuple of 3 floats
        Velocity of the centre of mass, heads normal (unit), angular momentum about the centre
        of mass (lab frame, SI).
    c : Contact
        The coin, the surface (e, μ, rolling and pivoting resistance, contact time) and g.

    Returns
    -------
    face : int
        TAILS 0, HEADS 1, EDGE 2: the well the coin cannot leave.
    status : Status
        SETTLED_CONTACT (the energy test: at rest or below its well's barrier),
        DECIDED_UPRIGHT (ended on edge by :func:`upright_decided`, :data:`UPRIGHT_DECISION`, a
        compile-time constant: a measured predictor, not a proof), or UNSETTLED after
        :data:`MAX_STEPS` steps.
    time : float
        Duration of the contact phase, s: until the energy test or, for a coin ended upright by
        :func:`upright_decided`, until that decision, not until it is at rest.
    """
    y = np.empty(10)
    y[0] = z
    y[1], y[2], y[3] = v
    y[4], y[5], y[6] = n
    y[7], y[8], y[9] = lm
    conservative = c.friction == 0.0 and c.rolling_resistance == 0.0
    if conservative and c.pivoting_resistance == 0.0 and c.restitution >= 1.0:
        # Nothing dissipates: the free energy stays where it is, above the barrier or below.
        y0 = (z, v[0], v[1], v[2], n[0], n[1], n[2], lm[0], lm[1], lm[2])
        y[:] = y0
        free, barrier = free_energy(y, c, stiffness_of(c))
        status = Status.SETTLED_CONTACT if free < barrier else Status.UNSETTLED
        return resting_face(n[2], c.edge_sine), status, 0.0
    t, _, ended = _integrate(
        y,
        math.inf,
        c,
        stiffness_of(c),
        damping_of(c),
        True,
        UPRIGHT_DECISION,
        MAX_STEPS,
        np.empty((0, 2)),
        RTOL,
    )
    face = resting_face(y[6], c.edge_sine)
    if ended == Ending.DECIDED:
        return face, Status.DECIDED_UPRIGHT, t
    if ended == Ending.SETTLED:
        return face, Status.SETTLED_CONTACT, t
    return face, Status.UNSETTLED, t


def advance(
    state: np.ndarray,
    duration: float,
    c,
    *,
    settle_check: bool = False,
    decide: bool = False,
    max_steps: int = MAX_STEPS,
    stats: np.ndarray | None = None,
    rtol: float = RTOL,
) -> tuple[float, int, Ending]:
    """Advance ``state`` = (z, vx, vy, vz, nx, ny, nz, Lx, Ly, Lz) in place (for tests and
    studies): (time, steps, ending), stopping after ``duration`` s or, with ``settle_check``,
    when the coin has settled by its energy (or, with ``decide`` too, when
    :func:`upright_decided` holds, as :func:`settle` with :data:`UPRIGHT_DECISION`), whichever
    comes first. ``decide`` is read at every call: ``decide=False`` is the run-time way to carry
    a coin on past the upright decision (:data:`UPRIGHT_DECISION` is fixed when numba
    compiles). ``ending`` (:class:`Ending`) is false when the coin has not settled, else
    SETTLED (the energy test) or DECIDED (the upright decision, the case :func:`settle`
    reports as DECIDED_UPRIGHT). ``stats``, an array of shape (len(:data:`MODES`), 2),
    accumulates the time and steps spent in each mode; with one more row filled with −1 (shape
    (len(:data:`MODES`) + 1, 2)) it also receives the (time, steps) at which
    :func:`upright_decided` first held, decided or not (with ``settle_check``). ``rtol``: the
    step control's relative tolerance (:data:`RTOL`; another for tests of the stepper; it must
    be positive and finite, not checked here: 0 or NaN rejects every step up to ``max_steps``)."""
    zeta = damping_of(c)
    if stats is None:
        stats = np.empty((0, 2))
    t, steps, ended = _integrate(
        state, duration, c, stiffness_of(c), zeta, settle_check, decide, max_steps, stats, rtol
    )
    return t, steps, Ending(ended)


@njit(cache=True)
def restitution_of(zeta, exponent):
    """Coefficient of restitution of the compliant normal law with damping ratio ζ.

    The dimensionless contact x'' = −x^p − 2 ζ sqrt(p x^(p−1)) x' (force K x^p, damping
    2 ζ sqrt(K_t m), K_t = dF/dx; m = K = v0 = 1, which the coefficient does not depend on), from
    x = 0, x' = 1 until the force vanishes (clipped at zero: the surface does not pull); e = −x'
    then. p = 3/2: a rim (Tsuji et al. 1992); p = 1: a face (Kelvin-Voigt; Schwager & Pöschel
    2007 give it in closed form).
    """
    x = 0.0
    u = 1.0
    dt = 2e-3
    for _ in range(1_000_000):
        # RK4 on (x, u).
        a1 = _law(x, u, zeta, exponent)
        x2, u2 = x + 0.5 * dt * u, u + 0.5 * dt * a1
        a2 = _law(x2, u2, zeta, exponent)
        x3, u3 = x + 0.5 * dt * u2, u + 0.5 * dt * a2
        a3 = _law(x3, u3, zeta, exponent)
        x4, u4 = x + dt * u3, u + dt * a3
        a4 = _law(x4, u4, zeta, exponent)
        xn = x + dt * (u + 2.0 * u2 + 2.0 * u3 + u4) / 6.0
        un = u + dt * (a1 + 2.0 * a2 + 2.0 * a3 + a4) / 6.0
        fn = -_law(xn, un, zeta, exponent)
        if xn <= 0.0 or (un < 0.0 and fn <= 0.0):
            # Interpolate the end (force or depth zero) linearly within the step.
            f0 = -a1
            if xn <= 0.0:
                frac = x / (x - xn)
            elif f0 > fn:
                frac = f0 / (f0 - fn)
            else:
                frac = 1.0
            return -(u + frac * (un - u))
        x, u = xn, un
    return 0.0


@njit(cache=True)
def _law(x, u, zeta, exponent):
    if x <= 0.0:
        return 0.0
    return -(x**exponent) - 2.0 * zeta * math.sqrt(exponent * x ** (exponent - 1.0)) * u


@njit(cache=True)
def damping_ratio(restitution):
    """ζ for which a rim contact (p = 3/2) restitutes with e (:func:`restitution_of`), by
    bisection; 0 for e = 1."""
    if restitution >= 1.0:
        return 0.0
    lo, hi = 0.0, 1.0
    for _ in range(60):
        if restitution_of(hi, 1.5) < restitution:
            break
        lo = hi
        hi *= 2.0
    for _ in range(50):
        mid = 0.5 * (lo + hi)
        if restitution_of(mid, 1.5) > restitution:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


ZETA_TABLE_LOWEST = 0.01
"""Smallest restitution of :data:`_ZETA_TABLE`; below it :func:`damping_ratio` is solved."""
_ZETA_TABLE = np.array(
    [
        4.388888727213681,
        4.221400079771877,
        4.059748558767703,
        3.9037248976689147,
        3.7531251643587344,
        3.6077541296044453,
        3.467421996847416,
        3.331947858843793,
        3.2011562187272924,
        3.074878061945392,
        2.952950611125499,
        2.8352170897952442,
        2.7215263228595985,
        2.6117318558318106,
        2.505694525918421,
        2.403277899752994,
        2.3043526785002895,
        2.208792172259913,
        2.116475880965738,
        2.0272872100500754,
        1.9411136638009094,
        1.8578469086279665,
        1.7773826158198394,
        1.6996203103280902,
        1.6244632254126299,
        1.5518174888938803,
        1.4815936742515041,
        1.4137053144368514,
        1.3480682581373595,
        1.2846028350681489,
        1.223231183087337,
        1.1638785833208662,
        1.1064734682500421,
        1.050946468857298,
        0.997230792268812,
        0.9452621254954408,
        0.8949785430468142,
        0.8463204183169135,
        0.7992303386456183,
        0.7536530239691319,
        0.7095351128240996,
        0.6668248754493242,
        0.6254734975538345,
        0.5854325148170854,
        0.5466566742869481,
        0.5091015618719124,
        0.4727242467688124,
        0.43748397440605347,
        0.40334119515412814,
        0.3702575342918304,
        0.33819656480248694,
        0.3071228995910036,
        0.27700246765563685,
        0.24780225880805018,
        0.21949066103892045,
        0.19203748075038574,
        0.1654131027380985,
        0.13958927327199921,
        0.11453882483925559,
        0.09023548053205088,
        0.06665387894642594,
        0.04376956430442336,
        0.02155919153534347,
        0.0,
    ]
)
"""ζ = :func:`damping_ratio` (e) at 64 restitutions spaced evenly in ln e from
ln :data:`ZETA_TABLE_LOWEST` to 0 (computed by that function; tests/test_contact_phase.py checks
nodes and interpolation)."""


@njit(cache=True)
def tabulated_damping_ratio(restitution):
    """ζ for the restitution e, interpolated (cubic Lagrange in ln e on :data:`_ZETA_TABLE`):
    the restitution of the returned ζ (:func:`restitution_of`) is e within 1e-6 e, in ~50 ns
    instead of the ~28 ms of :func:`damping_ratio`'s bisection, which it calls below
    :data:`ZETA_TABLE_LOWEST`. For tosses each with its own e (:func:`settle`)."""
    if restitution >= 1.0:
        return 0.0
    if restitution < ZETA_TABLE_LOWEST:
        return damping_ratio(restitution)
    count = _ZETA_TABLE.shape[0]
    lowest = math.log(ZETA_TABLE_LOWEST)
    spacing = -lowest / (count - 1)
    u = (math.log(restitution) - lowest) / spacing
    i = min(max(int(u) - 1, 0), count - 4)
    total = 0.0
    for j in range(4):
        weight = 1.0
        for k in range(4):
            if k != j:
                weight *= (u - (i + k)) / (j - k)
        total += weight * _ZETA_TABLE[i + j]
    return total
