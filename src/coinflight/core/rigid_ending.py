"""The rigid, event-driven end of a table landing: roll, slide, pivot, hop, band and face (numba).

When the bounces of :mod:`coinflight.core.bounce` die out (a rebound slower than the rest
speed), :func:`settle` carries the coin on until it can no longer leave its well. The coin and
the table are rigid; the motion is a sequence of modes, each with its own equations, and the
switches between them are events located in time:

* **on one rim point**, rolling without slip or sliding with exact Coulomb friction, pivoting
  about the vertical in either (:mod:`coinflight.core.rigid_contact`: the nonholonomic rolling
  disc, its contact force the one that keeps the contact point at rest, O'Reilly 1996,
  Nonlinear Dyn. 10:287; Le Saux, Leine & Glocker 2005, J. Nonlinear Sci. 15:27; the slip
  starting when that force leaves the friction cone, stopping when the slip vanishes);
* **in flight** (a hop): where the normal force of the one-rim contact falls to zero the coin
  leaves the table, and its flight is the closed-form torque-free flight of
  :mod:`coinflight.core.flight` (:func:`coinflight.core.flight.next_contact`) to its next
  contact, where the impact law of :func:`coinflight.core.impact.impact` (Stronge's energetic
  restitution with Coulomb friction) acts; a rebound slower than the rest speed returns the
  coin to the one-rim contact, a faster one flies on;
* **the other rim** (a coin with a flat edge band tipping through upright, n_z crossing 0): an
  impact of the other rim's lowest point, by the same law, then one-rim contact on it or a hop
  (the rocking across the band of Housner's block, 1963, Bull. Seismol. Soc. Am. 53:403);
* **both rims, on the band**: once that rocking has less than :data:`BAND_FRACTION` of the
  energy that would tip the coin over a rim, the coin stands on its band
  (:mod:`coinflight.core.band_contact`): both rims' lowest points touch, each with its own
  normal force ≥ 0 and exact Coulomb friction, sliding or sticking (Glocker & Pfeiffer's
  set-valued contact laws; Le Saux, Leine & Glocker 2005); its slip and its yaw are slowed
  by friction (a yaw ω_z stops in I1 |ω_z| / (μ m g H), H = h/2 − a), and a turning roll
  loads one rim more ((I3 + m r²) ω_a ω_z against m g H): where a rim's normal force reaches
  0 the coin goes on on the other rim alone; where both points stick it rolls straight
  (:func:`_band`), slowed by the rolling resistance, to rest on edge;
* **the face**: the coin lies flat (its tilt below :data:`coinflight.core.rigid_contact.FACE_SINE`):
  at rest on that face if its tumbling energy is below the barrier, else the rim point coming
  down fastest meets the table (:func:`_face_slap`) and the coin flies on.

Dissipation is only where the physics puts it: the impacts (restitution e, friction μ), Coulomb
friction while sliding, and the rolling and pivoting resistances ℓ_r, ℓ_p (torques ℓ F_n
against the horizontal and the vertical part of the angular velocity; Surface parameters
with their sources and ranges in :mod:`coinflight.model.surface`). Without resistances the
energy of a rolling coin is conserved (held by projection to rounding: tested over 5 s of
Euler's disk). Step sizes follow the motion's accuracy (Dormand–Prince 5(4) with error
control, :data:`RTOL`), not a contact stiffness, and the answers converge as the tolerance
tightens (tests/test_rigid_ending.py).

The ending: the coin has settled when its energy is below its well's barrier
(:func:`coinflight.core.rigid_contact.below_barrier`, rigorous: no force of the rigid contact
adds energy), when it lies flat on a face with its tumbling energy below the barrier, or when
it has rolled to rest on its band; the outcome is then the well it is in
(:func:`coinflight.core.impact.resting_face`).

Limits (what is not modelled, and what happens instead):

* rebounds slower than the landing's rest speed (0.01 m/s by default) are ended plastically
  (the normal velocity removed by the least-energy normal impulse), as the bounces' end is;
* a rocking below :data:`BAND_FRACTION` of the edge well's depth is removed at once on
  entering the band (the least-energy projection onto it; the Zeno accumulation of ever
  smaller rim impacts is cut there), the friction of that small impulse left out;
* Painlevé's paradox (a slide with no consistent normal force) is resolved by stopping the
  slip with the least-energy tangential impulse (Génot & Brogliato 1999, Eur. J. Mech.
  A 18:653: a tangential impact);
* a face slap is a single-point impact at the fastest-falling rim point, not the simultaneous
  impact of the face;
* hops are flown without air drag;
* a landing that has not settled after :data:`DURATION` s of motion, :data:`MAX_PHASES`
  phases or :data:`MAX_STEPS` steps is UNSETTLED in the well it is in, as is a coin rolling
  on its band without rolling resistance (the band's closed-form roll is not capped).
"""

from __future__ import annotations

import math

import numpy as np

from coinflight.core import band_contact as bc
from coinflight.core import flight
from coinflight.core import rigid_contact as rc
from coinflight.core._jit import njit
from coinflight.core.impact import (
    MAX_STEPS as IMPACT_STEPS,
)
from coinflight.core.impact import (
    SLIP_TOLERANCE,
    TURN_STEP,
    _apply,
    angular_velocity,
    collision_matrix,
    contact_impulse,
    contact_point,
    contact_velocity,
    cross,
    impact,
    lowest_depth,
    resting_face,
)
from coinflight.core.outcome import Face, Status

RTOL = 1e-7
"""Relative tolerance of the one-rim contact's step control in the ending (Dormand–Prince 5(4),
:func:`coinflight.core.rigid_contact.advance_rigid`). The energy does not rest on it: each step
is put back on the energy the flow should have (the start's less the work of friction and the
resistances; :mod:`coinflight.core.rigid_contact`, Integration), so that Euler's disk rolling
5 s without resistances keeps its energy to rounding at any tolerance. Chosen by the answers:
over the 1,504 landings of 2,000 human tosses of a nickel carried to rest (e 0.5, μ 0.3), the
face fractions at 1e-7 and at 1e-9 differ by 0.07, 0.07 and 0.13 points (tails, heads, edge),
far within one binomial standard error (1.3, 1.3 and 0.9 points); 31 of the landings (2.1 %)
end on another face, long chaotic rolls (14 between 1e-9 and 1e-10;
tests/test_rigid_ending.py compares the ending at RTOL and RTOL/10).
Half the steps of 1e-9. Looser is not faster: from ~1e-6 the steps' error in the contact's
slip and friction cone nears :data:`coinflight.core.rigid_contact.SLIP_FLOOR`, and a coin
near the cone's boundary switches between sticking and slipping on the noise, on more
steps."""
MAX_PHASES = 20_000
"""Phases at most (one-rim runs, hops, impacts) in one ending; beyond it the landing is
UNSETTLED in the well it is in."""
MAX_STEPS = 5_000_000
"""Accepted steps of the one-rim contact at most in one ending (about 10 s of CPU); beyond
it the landing is UNSETTLED in the well it is in. A coin spinning fast on its rim while it
slides takes the most (a nickel at 140 rad/s about the vertical: ~8 μs steps)."""
DURATION = 60.0
"""Simulated time at most in one ending, s (a coin rolling without resistance never settles)."""
BAND_FRACTION = 1e-2
"""A coin rocking across its edge band with less than this fraction of the edge well's depth
(the energy that would tip it over a rim) is taken to rest on the band (:func:`_band`); above,
each crossing is an impact of the arriving rim (Stronge's law). Its lever about the centre of
mass is the band's half-width H, small beside r, so an impact takes only a few per cent of the
rocking away whatever e (as a slender rocking block's, Housner 1963: the energy kept
(1 − 2 m H² / (I1 + m ρ²))², 0.97 for a nickel), and most arrive slower than the rest speed
(ended plastically): a tossed nickel that stays upright rocks down to the fraction in some 50
to 100 crossings. The fraction does not decide the outcome (the edges of the report's maps are
the same with 1e-3 or 1e-4)."""
HOP_START = 1e-7
"""First time looked at after a lift-off, s; doubled until the gap is open (the flight's
contact search starts from an open gap)."""

# Why an ending stopped (counts of :func:`settle_counts`).
ENDED_BARRIER = 0
ENDED_FACE = 1
ENDED_LIMIT = 2
ENDED_BAND = 3


@njit(cache=True)
def _hop(y, c, left):
    """Fly the coin in state y (just left the table, or rebounded) to its next contact, closed
    form (:func:`coinflight.core.flight.next_contact`); y is set to the state at that contact
    (or left unchanged for a hop too small to open the gap), or, for a contact more than
    ``left`` s away, to the state in flight ``left`` s on. Returns (time, approach speed of the
    contact point there; ≥ 0 for no flight or a graze, ∞ for a flight stopped at ``left``)."""
    z, vz = y[0], y[3]
    n = (y[4], y[5], y[6])
    lm = (y[7], y[8], y[9])
    r, hh, corner, i1, i3, g = c.radius, c.half_thickness, c.corner_radius, c.i1, c.i3, c.g
    tau = HOP_START
    opened = False
    closed = False
    for _ in range(60):
        gap = flight._gap_after(tau, z, vz, g, n, lm, i1, r, hh, corner)
        if gap > flight.CA_TOLERANCE:
            opened = True
            break
        if gap < -flight.CA_TOLERANCE:
            closed = True
            break
        tau *= 2.0
    if closed:
        # A hop lower than the contact search's tolerance: its end bisected (the gap, within
        # ±flight.CA_TOLERANCE at tau/2, is below it at tau), and the coin comes down there.
        lo, hi = 0.5 * tau, tau
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            if flight._gap_after(mid, z, vz, g, n, lm, i1, r, hh, corner) < 0.0:
                hi = mid
            else:
                lo = mid
        m = flight._precess_from(n, lm, i1, hi)
        size = math.sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2])
        y[0] = lowest_depth(m[2] / size, r, hh, corner)
        y[3] = vz - g * hi
        y[4], y[5], y[6] = m[0] / size, m[1] / size, m[2] / size
        _carry(y, hi)
        return hi, _approach(y, c)
    if not opened:
        return 0.0, 0.0  # no hop: the contact goes on
    total = 0.0
    for _ in range(1000):
        tc, m, approach = flight.next_contact(tau, z, vz, g, n, lm, i1, i3, r, hh, corner)
        if tc < 0.0:
            return -1.0, 0.0
        if total + tc > left:
            # Stopped in the air: the closed-form flight (ballistic centre, precessing normal).
            s = left - total
            m = flight._precess_from(n, lm, i1, s)
            size = math.sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2])
            y[0] = z + vz * s - 0.5 * g * s * s
            y[3] = vz - g * s
            y[4], y[5], y[6] = m[0] / size, m[1] / size, m[2] / size
            _carry(y, left)
            return left, math.inf
        size = math.sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2])
        m = (m[0] / size, m[1] / size, m[2] / size)
        total += tc
        z = lowest_depth(m[2], r, hh, corner)
        vz = vz - g * tc
        n = m
        if approach < 0.0:
            break
        tau = flight.GRAZE_SKIP  # a graze: fly on from a little later, as the bounces do
    y[0] = z
    y[3] = vz
    y[4], y[5], y[6] = n
    _carry(y, total)
    return total, approach


@njit(cache=True)
def _carry(y, tau):
    """The horizontal position (y[10], y[11], when y carries it) after a flight of tau s."""
    if y.shape[0] > 10:
        y[10] += y[1] * tau
        y[11] += y[2] * tau


@njit(cache=True)
def _impact(y, c):
    """The impact of the coin's lowest point (:func:`coinflight.core.impact.impact`) on y in
    place; returns the rebound speed of the contact point."""
    v = (y[1], y[2], y[3])
    lm = (y[7], y[8], y[9])
    n = (y[4], y[5], y[6])
    v, lm, rebound = impact(v, lm, n, c)
    y[0] = lowest_depth(n[2], c.radius, c.half_thickness, c.corner_radius)
    y[1], y[2], y[3] = v
    y[7], y[8], y[9] = lm
    return rebound


@njit(cache=True)
def _approach(y, c):
    """Normal velocity of the coin's lowest point (the rim by n_z's sign), m/s."""
    n = (y[4], y[5], y[6])
    rho = contact_point(n, c.radius, c.half_thickness, c.corner_radius)
    omega = angular_velocity((y[7], y[8], y[9]), n, c.i1, c.i3)
    return y[3] + cross(omega, rho)[2]


@njit(cache=True)
def _rocking_died_out(y, c):
    """Whether a coin whose other rim has just come down (n_z = 0) has stopped rocking across
    its band: its rocking, ½ (I1 + m r²) ṅ_z², below :data:`BAND_FRACTION` of the energy that
    would tip it over a rim's corner (the edge well's depth, barrier − m g r). It is then put
    on its band (:func:`coinflight.core.band_contact.run_band`: both rims touching, each
    with its normal force and Coulomb friction), if the band can hold it (both normal forces
    ≥ 0)."""
    n = (y[4], y[5], y[6])
    omega = angular_velocity((y[7], y[8], y[9]), n, c.i1, c.i3)
    m, r = c.mass, c.radius
    tilt_rate = omega[0] * n[1] - omega[1] * n[0]  # ṅ_z
    rocking = 0.5 * (c.i1 + m * r * r) * tilt_rate * tilt_rate
    return rocking < BAND_FRACTION * (c.barrier - m * c.g * r)


@njit(cache=True)
def _band(y, c, duration):
    """A coin rolling straight on its band, both rims' points sticking (the mode
    :data:`coinflight.core.band_contact.ROLL`), to rest on edge: (face, status, time).

    The drift of the band's run is removed first by the least-energy projection onto rolling
    straight (ω = ω_a n, v = r ω_a n × Z), which keeps the angular momentum about the contact
    line, ω_a = (m r (n × Z)·v + L·n) / (I3 + m r²). Rolling straight, nothing turns it (no
    yaw without slip), and it slows under the rolling resistance alone,
    (I3 + m r²) ω̇_a = −ℓ_r m g sgn(ω_a); it has settled on edge once
    ½ (I3 + m r²) ω_a² + m g r is below the barrier. Without rolling resistance it rolls on
    (UNSETTLED).
    """
    nx, ny = y[4], y[5]
    size = math.sqrt(nx * nx + ny * ny)
    nx, ny = nx / size, ny / size
    m, r, i3 = c.mass, c.radius, c.i3
    tx, ty = ny, -nx  # n × Z
    inertia = i3 + m * r * r
    rate = (m * r * (tx * y[1] + ty * y[2]) + nx * y[7] + ny * y[8]) / inertia
    y[0] = lowest_depth(0.0, r, c.half_thickness, c.corner_radius)
    y[1], y[2], y[3] = r * rate * tx, r * rate * ty, 0.0
    y[4], y[5], y[6] = nx, ny, 0.0
    y[7], y[8], y[9] = i3 * rate * nx, i3 * rate * ny, 0.0
    excess = 2.0 * (c.barrier - m * c.g * y[0]) / inertia
    settled = math.sqrt(excess) if excess > 0.0 else 0.0
    if abs(rate) < settled:
        return Face.EDGE, Status.SETTLED_CONTACT, 0.0
    if c.rolling_resistance > 0.0:
        slowing = c.rolling_resistance * m * c.g / inertia
        rolled = (abs(rate) - settled) / slowing
        if rolled <= duration:
            return Face.EDGE, Status.SETTLED_CONTACT, rolled
    return Face.EDGE, Status.UNSETTLED, duration


@njit(cache=True)
def _face_slap(y, c):
    """The impact of a coin lying flat (tilt below
    :data:`coinflight.core.rigid_contact.FACE_SINE`) that still tumbles: at the point of its
    lower rim that comes down fastest (within 2 r sin(tilt) ≤ 0.2 mm of the table for a
    nickel), by the law of :func:`coinflight.core.impact.impact` (Stronge). y in place; returns
    that point's normal velocity after (before, if it was not coming down)."""
    n = (y[4], y[5], y[6])
    v = (y[1], y[2], y[3])
    lm = (y[7], y[8], y[9])
    omega = angular_velocity(lm, n, c.i1, c.i3)
    # An orthonormal pair (a, b) in the coin's plane; the rim point R (cos φ a + sin φ b)
    # comes down at (ω × ŵ)_z R, least at ŵ ∝ −((ω × a)_z a + (ω × b)_z b).
    a = cross(n, (1.0, 0.0, 0.0)) if abs(n[0]) < 0.9 else cross(n, (0.0, 1.0, 0.0))
    size = math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2])
    a = (a[0] / size, a[1] / size, a[2] / size)
    b = cross(n, a)
    ca = cross(omega, a)[2]
    cb = cross(omega, b)[2]
    norm = math.sqrt(ca * ca + cb * cb)
    if norm == 0.0:
        return 0.0
    big_r = c.radius - c.corner_radius
    sign = 1.0 if n[2] >= 0.0 else -1.0
    big_h = c.half_thickness - c.corner_radius
    rho = (
        -big_r * (ca * a[0] + cb * b[0]) / norm - sign * big_h * n[0],
        -big_r * (ca * a[1] + cb * b[1]) / norm - sign * big_h * n[1],
        -big_r * (ca * a[2] + cb * b[2]) / norm - sign * big_h * n[2] - c.corner_radius,
    )
    u = contact_velocity(v, omega, rho)
    if u[2] >= 0.0:
        return u[2]
    k = collision_matrix(rho, n, c.mass, c.i1, c.i3)
    impulse, _ = contact_impulse(
        u, k, c.restitution, c.friction, TURN_STEP, SLIP_TOLERANCE, IMPACT_STEPS
    )
    v, lm = _apply(impulse, v, lm, rho, c.mass)
    y[1], y[2], y[3] = v
    y[7], y[8], y[9] = lm
    omega = angular_velocity(lm, n, c.i1, c.i3)
    return contact_velocity(v, omega, rho)[2]


@njit(cache=True)
def _energy(y, c):
    v = (y[1], y[2], y[3])
    n = (y[4], y[5], y[6])
    lm = (y[7], y[8], y[9])
    return flight.mechanical_energy(v, lm, n, c.mass, c.i1, c.i3, c.g, y[0])


@njit(cache=True)
def _tumbling(y, c):
    v = (y[1], y[2], y[3])
    n = (y[4], y[5], y[6])
    lm = (y[7], y[8], y[9])
    return flight.tumbling_energy(v, lm, n, c.mass, c.i1, c.g, y[0])


@njit(cache=True)
def _hops(y, c, counts, left):
    """Hops and their impacts, from a coin leaving the table, until it stays in contact: each
    hop flown in closed form (:func:`_hop`) to its impact (:func:`_impact`), until a rebound is
    slower than ``rest_speed``, the energy is below the barrier, or no flight opens the gap
    (the contact goes on, its normal speed removed by the frictionless normal impulse of least
    energy: a plastic touch). ``y`` is advanced in place and ``counts`` updated (impacts in
    [2], flight time in [5]). A flight still in the air ``left`` s after the first hop began
    stops there (y the state in flight). Returns (time flown, landed): landed False when a hop
    found no contact (the landing is then unsettled)."""
    total = 0.0
    for _ in range(MAX_PHASES):
        flown, approach = _hop(y, c, left - total)
        if flown < 0.0:
            return total, False
        total += flown
        counts[5] += flown
        if approach == math.inf:
            break  # stopped in the air at the time asked for
        if approach >= 0.0:
            rc._project(y, c, rc.SLIDING)
            break
        counts[2] += 1.0
        rebound = _impact(y, c)
        if rebound < c.rest_speed or _energy(y, c) < c.barrier:
            break
    return total, True


@njit(cache=True)
def run(y, c, rtol, duration, counts, stop=False):
    """:func:`settle` on the state y (modified in place), with the step tolerance ``rtol`` and
    at most ``duration`` s (a coin that comes to rest on its band returns with the state it
    entered it in and the time its closed-form roll ends, which may be later, and without
    rolling resistance is UNSETTLED there; with ``stop``, ``duration`` is a time asked for:
    the band's roll stops there too, y the state then). ``counts`` (8 floats) receives
    (one-rim runs, hops, impacts, rim changes, time rolling, time sliding or in flight,
    accepted steps, how it ended: :data:`ENDED_BARRIER`, :data:`ENDED_FACE`,
    :data:`ENDED_BAND`, :data:`ENDED_LIMIT`). Returns (face, status, time)."""
    for i in range(8):
        counts[i] = 0.0
    inner = np.zeros(7)
    band = np.zeros(4)
    t = 0.0
    for _ in range(MAX_PHASES):
        if rc.below_barrier(y, c):
            counts[7] = ENDED_BARRIER
            return resting_face(y[6], c.edge_sine), Status.SETTLED_CONTACT, t
        if t >= duration:
            break
        budget = MAX_STEPS - counts[6]
        if budget < 1.0:
            break
        elapsed, _mode, reason = rc._run(
            y, c, duration - t, True, int(budget), rtol, c.rest_speed, inner
        )
        counts[0] += 1.0
        counts[4] += inner[6]
        counts[5] += elapsed - inner[6]
        counts[6] += inner[0]
        t += elapsed
        if reason == rc.BELOW_BARRIER:
            continue  # the test at the top ends it
        if reason == rc.STEP_FAILED:
            continue  # restarted from its state (classified afresh, steps from the start)
        hop = False
        if reason == rc.FACE:
            if _tumbling(y, c) < c.barrier:
                counts[7] = ENDED_FACE
                return resting_face(y[6], c.edge_sine), Status.SETTLED_CONTACT, t
            # Flat, still tumbling: the rim point coming down fastest meets the table.
            counts[2] += 1.0
            hop = _face_slap(y, c) >= 0.0 or _energy(y, c) >= c.barrier
        elif reason == rc.LIFT_OFF:
            counts[1] += 1.0
            hop = True
        elif reason == rc.NOT_IN_CONTACT or reason == rc.SECOND_RIM or reason == rc.PAINLEVE:
            if reason == rc.SECOND_RIM:
                counts[3] += 1.0
                if _rocking_died_out(y, c):
                    spent, why = bc.run_band(y, c, duration - t, rtol, budget - inner[0], band)
                    if why != bc.NOT_BAND:
                        t += spent
                        counts[6] += band[0]
                        counts[4] += band[2]
                        counts[5] += spent - band[2]
                        if why == bc.ROLLING:
                            # The band's straight roll is closed form: not capped, unless it never
                            # ends.
                            cap = math.inf if c.rolling_resistance > 0.0 else DURATION - t
                            if stop:
                                cap = min(cap, duration - t)
                            face, status, rolled = _band(y, c, cap)
                            if stop:
                                _roll(y, c, rolled)  # the state at the time asked for
                            counts[4] += rolled
                            counts[7] = (
                                ENDED_BAND if status == Status.SETTLED_CONTACT else ENDED_LIMIT
                            )
                            return face, status, t + rolled
                        # A rim lifted (one-rim contact on the other), below the barrier (the test
                        # at the top), the duration (idem), or a failed run (restarted).
                        continue
            if reason == rc.PAINLEVE:
                # No consistent normal force for the slide: the slip is stopped by a tangential
                # impulse at the contact (Génot & Brogliato 1999, Eur. J. Mech. A 18:653: the
                # paradox resolved by a tangential impact), dissipative, the least kinetic
                # energy removed (the projection onto rolling).
                rc._project(y, c, rc.ROLLING)
            counts[2] += 1.0
            rebound = _impact(y, c)
            hop = rebound >= c.rest_speed and _energy(y, c) >= c.barrier
        else:
            break  # duration, step budget, a failed step
        if hop:
            flown, landed = _hops(y, c, counts, duration - t)
            t += flown
            if not landed:
                return resting_face(y[6], c.edge_sine), Status.UNSETTLED, t
    counts[7] = ENDED_LIMIT
    return resting_face(y[6], c.edge_sine), Status.UNSETTLED, t


@njit(cache=True)
def _roll(y, c, s):
    """The coin rolling straight on its band (y as :func:`_band` left it) s seconds on, in
    place: slowed by the rolling resistance, to rest at most."""
    m, r, i3 = c.mass, c.radius, c.i3
    nx, ny = y[4], y[5]
    tx, ty = ny, -nx
    rate = (nx * y[7] + ny * y[8]) / i3
    slowing = c.rolling_resistance * m * c.g / (i3 + m * r * r)
    sign = 1.0 if rate >= 0.0 else -1.0
    s = min(s, abs(rate) / slowing) if slowing > 0.0 else s
    now = rate - sign * slowing * s
    rolled = r * (rate * s - 0.5 * sign * slowing * s * s)
    if y.shape[0] > 10:
        y[10] += rolled * tx
        y[11] += rolled * ty
    y[1], y[2], y[3] = r * now * tx, r * now * ty, 0.0
    y[7], y[8], y[9] = i3 * now * nx, i3 * now * ny, 0.0


@njit(cache=True)
def states(t0, z, xy, v, n, lm, c, times, k, out):
    """The motion of the ending from the state (z, xy, v, n, lm) at t0 (the end of the
    bounces) at ``times[k:]`` (sorted, s), into the rows of ``out`` (position, normal,
    velocity, angular momentum: :data:`coinflight.core.bounce.STATE_COLUMNS`), up to the time
    the coin settled: (the index of the first time not followed, that time).

    Each time is reached by a run of the ending from t0 stopped there: the same steps as the
    uninterrupted run of :func:`settle` up to the last one, which ends at the time, so every
    state lies on the one motion the outcome comes from (a run stopped and carried on at each
    time would restart its step control, and a chaotic roll would part from it). m times cost
    up to m runs of the ending."""
    start = np.empty(12)
    start[0] = z
    start[1], start[2], start[3] = v
    start[4], start[5], start[6] = n
    start[7], start[8], start[9] = lm
    start[10], start[11] = xy
    y = start.copy()
    counts = np.empty(8)
    _, _, elapsed = run(y, c, RTOL, DURATION, counts)
    end = t0 + elapsed
    m = times.shape[0]
    while k < m and times[k] <= end:
        for j in range(12):
            y[j] = start[j]
        if times[k] > t0:
            run(y, c, RTOL, times[k] - t0, counts, True)
        for j in range(3):
            out[k, j] = (y[10], y[11], y[0])[j]
            out[k, 3 + j] = y[4 + j]
            out[k, 6 + j] = y[1 + j]
            out[k, 9 + j] = y[7 + j]
        k += 1
    return k, end


@njit(cache=True)
def settle(z, v, n, lm, c):
    """Carry a coin whose bounces died out on until it cannot leave its well: (face, status,
    time, s), status SETTLED_CONTACT or UNSETTLED (module notes). (z, v, n, L): the height of
    its centre of mass, its velocity, heads normal and angular momentum (lab, SI) just after
    the last impact."""
    y = np.empty(10)
    y[0] = z
    y[1], y[2], y[3] = v
    y[4], y[5], y[6] = n
    y[7], y[8], y[9] = lm
    counts = np.empty(8)
    return run(y, c, RTOL, DURATION, counts)


__all__ = ["DURATION", "MAX_PHASES", "RTOL", "run", "settle", "states"]
