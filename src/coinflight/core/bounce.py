"""Event-driven simulation of a coin that falls onto a table, bounces and settles (numba).

Between impacts the flight is exact: the centre of mass is ballistic and the coin is a
torque-free symmetric top whose normal precesses about the fixed angular momentum L,

    n(τ) = (n0·L̂) L̂ + cos(ωp τ) [n0 − (n0·L̂) L̂] + sin(ωp τ) (L̂ × n0),   ωp = |L| / I1

(Diaconis, Holmes & Montgomery 2007, section 2; REFERENCES §2 — the same motion as
:mod:`coinflight.core.torque_free`, written in the lab frame from any state, which is what a
flight that starts at an impact needs; :mod:`coinflight.core.flight`, shared with the hops of
the rigid ending). The heads normal, the velocity and the angular momentum are the whole state:
a cylinder's contact with a plane does not depend on the spin angle about its own axis.

Contacts are located exactly, not by a time step: conservative advancement (Mirtich,
*Impulse-based dynamic simulation of rigid body systems*, PhD thesis, Berkeley 1996, §3.4),
accelerated by a second-order bound on the gap, steps towards the contact, and a safeguarded
Newton iteration on the gap between the coin's lowest point and the surface polishes the
contact time to machine precision (:func:`coinflight.core.flight.next_contact`). The impact is
:func:`coinflight.core.impact.impact`.

After every impact :func:`after_impact` decides whether the landing has ended (the one ending
of the exact and the air landings). The coin has settled when it can no longer cross the
potential barrier between a face and its edge, m g sqrt(r² + h²/4), the height of its centre
of mass when balanced on the corner of rim and face (m g (a + sqrt((r − a)² + (h/2 − a)²))
over a corner rounded to radius a) (Vulović & Prange 1986; Yong & Mahadevan
2011; REFERENCES §4-5): with the rocking ending, when the energy that can turn it over
(:func:`coinflight.core.flight.tumbling_energy`) is below it; with the rigid ending, when
its whole energy (:func:`coinflight.core.flight.mechanical_energy`) is, which is rigorous, as
no impact or contact force adds energy (:func:`coinflight.core.impact.impact` is tested for
it). Its outcome is then the well it is in (:func:`coinflight.core.impact.resting_face`).
When the bounces die out instead (a rebound slower than ``rest_speed``: the coin chatters on
one rim point while it tips), the end is chosen by the record's ``ending`` flag
(:class:`coinflight.model.surface.Surface` ``ending``): by default the planar rocking of
:func:`rock` (status SETTLED_ROCKING), or the coin carried on in 3-D by the rigid,
event-driven ending of :func:`coinflight.core.rigid_ending.settle` (rolling, sliding and
rocking on its rim or its band, with Coulomb friction and rolling and pivoting resistance)
until it cannot leave its well (status SETTLED_CONTACT).
With e = 0 the surface absorbs the coin at its first contact and the well it touches in is the
outcome, as in Yong & Mahadevan's model of a landing without bounce.

The flights and impacts run in one loop (:func:`bounces_until`) from any state, which can stop
at a given time: a toss's landing starts it at launch (:func:`bounce_loop`); :func:`follow`
starts it from any state above or on the table and records the state at given times (the
flights in closed form, :func:`fly`; after the bounces, what the ending follows,
:func:`ending_states`): the kernel of :meth:`coinflight.outcomes.table.Landing.from_state`.

Every part of a landing meets the same rim: the cylinder (r − a, h/2 − a) swept by a ball of
the corner radius a (``Contact.corner_radius``; :func:`coinflight.core.impact.lowest_depth`):
the flight's contact search, the impacts, the barrier and the edge angle of the wells, the
rigid ending and the rocking of :func:`rock`. With a = 0 (sharp corners) each is, to the bit,
what it was before it took a.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from numpy.typing import NDArray

from coinflight.core import rigid_ending
from coinflight.core._jit import njit, prange
from coinflight.core.contact import RIGID_ENDING, ROCKING_ENDING, Contact
from coinflight.core.flight import (
    CA_TOLERANCE,
    GRAZE_SKIP,
    _first_positive,
    _gap_after,
    _precess_from,
    mechanical_energy,
    next_contact,
    table_impact,
    tumbling_energy,
)
from coinflight.core.impact import (
    angular_velocity,
    contact_point,
    cross,
    dot,
    lowest_depth,
    resting_face,
)
from coinflight.core.outcome import Status

# Why a toss ended (the ``status`` array): :class:`coinflight.core.outcome.Status`.

MAX_IMPACTS = 2_000
REST_SPEED = 0.01
"""Default rebound speed of the contact point below which the bounces have died out, m/s."""


@njit(cache=True)
def rock(n, omega, c):
    """Face the coin ends on when it rocks on its corners in the plane in which it tips.

    The default end of :func:`land` (and of :mod:`coinflight.core.drag`); the 3-D alternative
    is :func:`coinflight.core.rigid_ending.settle`.

    Parameters
    ----------
    n, omega : tuple of 3 floats
        Heads normal and angular velocity (lab) when the bounces have died out.
    c : Contact
        The contact record (:class:`coinflight.core.contact.Contact`): the coin (r, h/2, m,
        I1), gravity, the rim's corner radius a, 0 ≤ a ≤ min(h/2, r) (0: sharp corners,
        Housner's block), and the barrier m g (a + ρ′) between the wells, read from the
        record (computed once, by :meth:`Contact.build <coinflight.core.contact.Contact>`).

    Notes
    -----
    The rocking block of Housner (1963, *Bull. Seismol. Soc. Am.* 53:403): the coin's section
    in the vertical plane through its normal pivots, without slipping or bouncing, about one
    corner at a time. With rounded corners the section is the rectangle 2r′ × 2h′ swept by a
    disc of radius a (r′ = r − a, h′ = h/2 − a: the section of the coin of
    :func:`coinflight.core.impact.lowest_depth`), flat bands 2r′ (faces) and 2h′ (edge)
    joined by quarter circles, and the sharp block is a = 0. Its tilt φ
    (n = sin φ ê + cos φ Z) sees the potential U = m g (a + r′ |sin φ| + h′ |cos φ|) (the
    height of the centre of mass over the section's lowest point): wells at heads (φ = 0),
    edge (±π/2) and tails (π), separated by the corners, the centre of mass balanced over a
    corner's centre, U = m g (a + ρ′), ρ′ = sqrt(r′² + h′²) (:attr:`Contact.barrier
    <coinflight.core.contact.Contact>`).
    Between wells the coin rolls without slipping on one corner's arc: the contact point P,
    below the arc's centre, is the instantaneous centre of rotation, so the kinetic energy is
    ½ I_P φ̇², I_P = I1 + m |CM − P|² = I1 + m (ρ′² + a² + 2 a (U/(m g) − a)) (the centre of
    mass lies U/(m g) − a above the arc's centre, which lies a above P: the kinetic energy of a
    body rolling without slip on its convex contour, rotation about the instantaneous centre;
    the rocking bodies of Glaschke 2016, arXiv:1604.03021),
    and ½ I_P φ̇² + U is conserved: the coin crosses a barrier when this energy exceeds
    U there, whatever I_P. At the bottom of a well the section lies on its flat band (faces:
    half-length r′, the centre of mass h/2 above it; edge: h′ and r) and the next corner's arc
    lands: the pivot jumps from one end of the band to the other, and angular momentum about
    the new pivot P₂ is conserved (Housner 1963) while the old one P₁ lifts, so φ̇ is
    multiplied by (I1 + m (CM − P₁)·(CM − P₂)) / (I1 + m |CM − P₂|²) =
    (I1 + m b² cos γ) / (I1 + m b²), b² = r′² + (h/2)² with cos γ = ((h/2)² − r′²)/b² at a
    face, b² = r² + h′² with cos γ = (r² − h′²)/b² at the edge (γ the angle between the band's
    ends seen from the centre of mass; Housner's corners at a = 0). The kinetic energy, the
    same I_P just before and after, goes by the ratio's square. When that ratio is ≤ 0 (a
    thin coin slapping flat) the coin stops there. The coin ends in the first well whose
    barrier its energy cannot pass. At a = h/2 the edge band has shrunk to a point
    (h′ = 0): the edge is the top of the barrier (ratio 1, no well), and the coin never ends
    on its edge.
    """
    radius, hh, mass, i1, g = c.radius, c.half_thickness, c.mass, c.i1, c.g
    corner = c.corner_radius
    barrier = c.barrier  # m g (a + ρ′), the record's
    # The section's inner rectangle (r′, h′) and the corner's centre seen from the centre of
    # mass; a = 0 leaves every expression as Housner's sharp block computed it, to the bit.
    r_in = radius - corner
    h_in = hh - corner
    rho_in2 = r_in * r_in + h_in * h_in
    angle = math.atan2(r_in, h_in)  # the face/edge barriers at |φ| = angle, π − angle
    horizontal = math.hypot(n[0], n[1])
    ndot = cross(omega, n)
    if horizontal > 1e-12:
        ex, ey = n[0] / horizontal, n[1] / horizontal
    else:
        h2 = math.hypot(ndot[0], ndot[1])
        if h2 == 0.0:
            return 1 if n[2] > 0.0 else 0
        ex, ey = ndot[0] / h2, ndot[1] / h2
    phi = math.atan2(horizontal, n[2])  # in [0, π]
    # dφ/dt = ṅ · ∂n/∂φ with ∂n/∂φ = cos φ ê − sin φ Z.
    phidot = (ndot[0] * ex + ndot[1] * ey) * math.cos(phi) - ndot[2] * math.sin(phi)
    lift = r_in * abs(math.sin(phi)) + h_in * abs(math.cos(phi))  # CM above the arc's centre
    inertia = i1 + mass * (rho_in2 + corner * corner + 2.0 * corner * lift)  # about P
    energy = 0.5 * inertia * phidot * phidot + mass * g * (corner + lift)
    # Wells k = 0 heads (φ = 0), 1 edge (π/2), 2 tails (π), 3 edge (−π/2), in order of φ.
    if phi < angle:
        k = 0
    elif phi > math.pi - angle:
        k = 2
    elif h_in > 0.0:
        k = 1
    else:  # a = h/2: no edge well, φ = π/2 is the top of the barrier
        k = 0 if phi < 0.5 * math.pi else 2
    direction = 1 if phidot >= 0.0 else -1
    towards_centre = (phi - 0.5 * math.pi * k) * phidot < 0.0
    if not towards_centre:
        if energy < barrier:
            return _well_face(k)
        k = (k + direction) % 4
    # The band's ends seen from the centre of mass at the bottom of a face and of the edge well.
    face2 = r_in * r_in + hh * hh
    cos_face = (hh * hh - r_in * r_in) / face2
    edge2 = radius * radius + h_in * h_in
    cos_edge = (radius * radius - h_in * h_in) / edge2
    for _ in range(10_000):
        if k % 2 == 0:
            bottom = mass * g * hh
            ratio = (i1 + mass * face2 * cos_face) / (i1 + mass * face2)
        else:
            bottom = mass * g * radius
            ratio = (i1 + mass * edge2 * cos_edge) / (i1 + mass * edge2)
        if ratio <= 0.0:
            return _well_face(k)
        energy = bottom + (energy - bottom) * ratio * ratio
        if energy < barrier:
            return _well_face(k)
        k = (k + direction) % 4
    return _well_face(k)


@njit(cache=True)
def _well_face(k):
    if k == 0:
        return 1
    if k == 2:
        return 0
    return 2


DIED_OUT = -2
"""``status`` of :func:`bounce_loop` when the bounces died out (a rebound slower than
``rest_speed``, e > 0): the landing's ending (:func:`died_out`) takes the state from there."""


@njit(cache=True)
def land_one(omega_body, start_sign, launch_speed, c, max_bounces):
    """One toss from launch to rest; see :func:`land` (returns face, bounces, times, status).

    The bounces of :func:`bounce_loop`, then, if they died out, the ending of
    :func:`died_out`."""
    face, bounces, first, t, status, z, v, n, lm = bounce_loop(
        omega_body, start_sign, launch_speed, c, max_bounces
    )
    if status == DIED_OUT:
        face, status, duration = died_out(z, v, n, lm, c)
        return face, bounces, first, t + duration, status
    return face, bounces, first, t, status


@njit(cache=True)
def bounce_loop(omega_body, start_sign, launch_speed, c, max_bounces):
    """One toss from launch to the end of its bounces: (face, bounces, first contact, time,
    status, z, v, n, L).

    ``status`` is a :class:`coinflight.core.outcome.Status` when the landing ended at a contact
    (face its well), or :data:`DIED_OUT` when the bounces died out with e > 0 (face −1): then
    (z, v, n, L) is the state after the last impact, which :func:`died_out` (in
    :func:`land_one`) carries to the end, and ``time`` is that impact's. The contacts and
    impacts are those of the rounded rim, corner radius ``c.corner_radius``
    (:func:`coinflight.core.flight.next_contact`, :func:`impact_step`); the loop is
    :func:`bounces_until`."""
    i1, i3 = c.i1, c.i3
    wx, wy, wz = omega_body
    # Launch attitude: identity heads up, a half turn about lab X tails up (flips y and z).
    s = 1.0 if start_sign > 0 else -1.0
    n = (0.0, 0.0, s)
    lm = (i1 * wx, s * i1 * wy, s * i3 * wz)
    v = (0.0, 0.0, launch_speed)
    # The coin leaves the hand and is looked for on the way down, from the apex on.
    face, status, t, z, _, v, n, lm, _, bounces, first, _ = bounces_until(
        math.inf,
        0.0,
        c.drop_height,
        (0.0, 0.0),
        v,
        n,
        lm,
        launch_speed / c.g,
        0,
        -1.0,
        0,
        c,
        max_bounces,
    )
    return face, bounces, first, t, status, z, v, n, lm


RUNNING = -3
"""``status`` of :func:`bounces_until` stopped at its stop time, the landing not over."""


@njit(cache=True)
def bounces_until(t_stop, t, z, xy, v, n, lm, tau, bounces, first, count, c, max_bounces):
    """Flights and impacts from the state at time t until the landing ends or the next contact
    comes after ``t_stop``.

    Parameters
    ----------
    t_stop : float
        Stop before a contact later than this, s (∞: to the end of the bounces).
    t, z, xy, v, n, lm :
        The state at the start of a flight: its time (s), the height of the centre of mass
        (m), its horizontal position (x, y) (m), velocity (m/s), heads normal and angular
        momentum about the centre of mass (kg m²/s), lab frame.
    tau : float
        Look for the next contact from this time into the flight on, s (the apex after a
        launch, the time :func:`leave` gives after an impact, 0 from a state above the table).
    bounces, first, count :
        Impacts after which the coin flew on so far, the time of the first contact (−1: none
        yet) and the contacts met (impacts and grazes; at most :data:`MAX_IMPACTS` in all).
    c : Contact
    max_bounces : int
        As :func:`land`.

    Returns
    -------
    (face, status, t, z, xy, v, n, lm, tau, bounces, first, count)
        ``status`` a :class:`coinflight.core.outcome.Status`, :data:`DIED_OUT` (face −1) as in
        :func:`bounce_loop`, or :data:`RUNNING` when stopped at ``t_stop``: then the state is
        that of the flight in progress at its start time t (its motion at t_stop in closed
        form: :func:`fly`), and a call with the values returned carries on.
    """
    radius, hh, i1, i3 = c.radius, c.half_thickness, c.i1, c.i3
    corner, g, edge_sine = c.corner_radius, c.g, c.edge_sine
    x, y = xy
    while count < MAX_IMPACTS:
        tc, n1, approach = next_contact(tau, z, v[2], g, n, lm, i1, i3, radius, hh, corner)
        if tc >= 0.0 and t + tc > t_stop:
            return -1, RUNNING, t, z, (x, y), v, n, lm, tau, bounces, first, count
        count += 1
        n = n1
        if tc < 0.0:
            face = resting_face(n[2], edge_sine)
            return face, Status.UNSETTLED, t, z, (x, y), v, n, lm, tau, bounces, first, count
        norm = math.sqrt(dot(n, n))
        n = (n[0] / norm, n[1] / norm, n[2] / norm)
        t += tc
        x += v[0] * tc
        y += v[1] * tc
        z = lowest_depth(n[2], radius, hh, corner)
        v = (v[0], v[1], v[2] - g * tc)
        if approach >= 0.0:
            # A graze within CA_TOLERANCE: no impact, fly on from a little later.
            tau = GRAZE_SKIP
            continue
        if first < 0.0:
            first = t
        if bounces >= max_bounces:
            face = resting_face(n[2], edge_sine)
            return face, Status.BOUNCE_LIMIT, t, z, (x, y), v, n, lm, tau, bounces, first, count
        v, lm, face, status, tau = impact_step(z, v, n, lm, c)
        if status != -1:
            return face, status, t, z, (x, y), v, n, lm, tau, bounces, first, count
        bounces += 1
    face = resting_face(n[2], edge_sine)
    return face, Status.UNSETTLED, t, z, (x, y), v, n, lm, tau, bounces, first, count


@njit(cache=True)
def impact_step(z, v, n, lm, c):
    """The impact of the coin touching the table at (z, v, n, lm), and what follows it:
    (v, lm, face, status, tau).

    The impact is :func:`coinflight.core.impact.impact` (Stronge's law at the lowest point, or
    the simultaneous impact of a coin meeting the table nearly flat or upright), the verdict
    :func:`impact_verdict`; status −1 (face −1) if the coin flies on, its next contact looked
    for from ``tau`` into the flight (:func:`leave`)."""
    v, lm, rebound = table_impact(v, lm, n, c)
    face, status = impact_verdict(z, v, lm, n, rebound, c)
    if status != -1:
        return v, lm, face, status, 0.0
    return v, lm, -1, -1, leave(rebound, z, v, n, lm, c)


@njit(cache=True)
def leave(rebound, z, v, n, lm, c):
    """Time into the flight after an impact (the contact point leaving at ``rebound``, m/s)
    from which the next contact is looked for, s: the gap grows like rebound·τ − A τ²/2 at
    first, with A bounding the downward acceleration of any point of the coin; its peak, or
    earlier if the gap is not positive there (:func:`_first_positive`)."""
    omega = angular_velocity(lm, n, c.i1, c.i3)
    accel = c.g + 2.0 * dot(omega, omega) * c.reach
    tau = rebound / accel
    g, i1, radius, hh, corner = c.g, c.i1, c.radius, c.half_thickness, c.corner_radius
    if _gap_after(tau, z, v[2], g, n, lm, i1, radius, hh, corner) <= 0.0:
        tau = _first_positive(tau, z, v[2], g, n, lm, i1, radius, hh, corner)
    return tau


@njit(cache=True)
def after_impact(z, v, lm, n, rebound, c):
    """How a landing ends after an impact, if it does: (face, status, duration of a contact
    phase, s); status −1 (and face −1) if the coin flies on.

    The one ending of every landing kernel (:func:`land_one` through :func:`bounce_loop`, and
    through air :func:`coinflight.core.drag.ending`): :func:`impact_verdict`, and, when the
    bounces died out, :func:`died_out`.
    """
    face, status = impact_verdict(z, v, lm, n, rebound, c)
    if status == DIED_OUT:
        return died_out(z, v, n, lm, c)
    return face, status, 0.0


@njit(cache=True)
def impact_verdict(z, v, lm, n, rebound, c):
    """(face, status) after an impact, in this order:

    * the coin is trapped in its well: with the rigid 3-D ending, its whole energy
      (:func:`coinflight.core.flight.mechanical_energy`, rigorous: nothing adds energy
      afterwards) is below the barrier of ``c.barrier``; with the rocking ending, its
      tumbling energy (:func:`coinflight.core.flight.tumbling_energy`) is (status
      SETTLED_ENERGY);
    * e = 0 and the rebound below ``rest_speed``: the surface absorbed it (SETTLED_DEAD);
    * the bounces died out (rebound below ``rest_speed``): :data:`DIED_OUT` (face −1), for
      :func:`died_out`;
    * else the coin flies on: status −1, face −1.
    """
    if c.ending != ROCKING_ENDING:  # the rigid 3-D ending
        free = mechanical_energy(v, lm, n, c.mass, c.i1, c.i3, c.g, z)
    else:
        free = tumbling_energy(v, lm, n, c.mass, c.i1, c.g, z)
    if free < c.barrier:
        return resting_face(n[2], c.edge_sine), Status.SETTLED_ENERGY
    if rebound < c.rest_speed:
        if c.restitution == 0.0:
            return resting_face(n[2], c.edge_sine), Status.SETTLED_DEAD
        return -1, DIED_OUT
    return -1, -1


@njit(cache=True)
def died_out(z, v, n, lm, c):
    """The end of a landing whose bounces died out: (face, status, duration, s), by
    ``c.ending``: the rigid 3-D ending (:func:`coinflight.core.rigid_ending.settle`,
    SETTLED_CONTACT or UNSETTLED, its duration) or the planar rocking of :func:`rock`
    (SETTLED_ROCKING, 0)."""
    if c.ending == RIGID_ENDING:
        return rigid_ending.settle(z, v, n, lm, c)
    omega = angular_velocity(lm, n, c.i1, c.i3)
    face = rock(n, omega, c)
    return face, Status.SETTLED_ROCKING, 0.0


CONTACT_GAP = CA_TOLERANCE
"""A coin started with its lowest point within this distance of the table, m, is in contact
(:func:`follow`): the flight's search hands over to the contact at the same gap."""

STATE_COLUMNS = 12
"""Columns of a state row in :func:`follow`: position (x, y, z) of the centre of mass (m),
heads normal, velocity (m/s) and angular momentum about the centre of mass (kg m²/s), lab."""


@njit(cache=True)
def fly(tau, z, xy, v, n, lm, c):
    """The closed-form flight: (position, velocity, normal) tau into a flight that starts at
    (z, xy, v, n, lm): ballistic centre of mass, torque-free normal
    (:func:`coinflight.core.flight.precess`)."""
    m = _precess_from(n, lm, c.i1, tau)
    g = c.g
    position = (xy[0] + v[0] * tau, xy[1] + v[1] * tau, z + v[2] * tau - 0.5 * g * tau * tau)
    return position, (v[0], v[1], v[2] - g * tau), m


@njit(cache=True)
def _store(states, k, position, n, v, lm):
    for j in range(3):
        states[k, j] = position[j]
        states[k, 3 + j] = n[j]
        states[k, 6 + j] = v[j]
        states[k, 9 + j] = lm[j]


@njit(cache=True)
def ending_states(t, z, xy, v, n, lm, status, c, times, k, states):
    """The states the ending reaches at ``times[k:]`` (≥ t, the time the bounces ended with
    ``status``, the coin at (z, xy, v, n, lm)), written into ``states[k:]``: (the index of the
    first time not followed, the latest time the ending follows, s).

    The hook through which an ending that follows the coin in time hands :func:`follow` its
    motion (any status: a coin trapped in its well still moves). The rocking ending does not
    (its hand-off decides the face from the state alone), so nothing after t is followed:
    (k, t). The rigid ending does (:func:`coinflight.core.rigid_ending.states`), to the time
    it settled or gave up.
    """
    if c.ending == RIGID_ENDING and (
        status == Status.SETTLED_CONTACT or status == Status.UNSETTLED
    ):
        return rigid_ending.states(t, z, xy, v, n, lm, c, times, k, states)
    return k, t


@njit(cache=True)
def follow(z, xy, v, n, lm, c, max_bounces, times, states):
    """A landing from any state, followed in time.

    Parameters
    ----------
    z, xy, v, n, lm :
        The state at time 0: height of the centre of mass above the table z = 0 (m), its
        horizontal position (m), velocity (m/s), heads normal and angular momentum about the
        centre of mass (kg m²/s), lab frame. The lowest point must not be below the table by
        more than :data:`CONTACT_GAP` (the caller checks).
    c : Contact
    max_bounces : int
        As :func:`land`.
    times : ndarray, shape (m,)
        Sorted times ≥ 0, s, at which to record the state.
    states : ndarray, shape (m, :data:`STATE_COLUMNS`)
        Written: row k the state at ``times[k]`` (after an impact at that very time), for the
        rows followed.

    Returns
    -------
    (face, bounces, first contact, end of the bounces, settle time, status, followed, until)
        As :func:`land_one`, with the time the bounces ended (s), the number of times
        followed (the rows of ``states`` written: the flights in closed form and the impacts
        up to the end of the bounces, then what the ending follows, :func:`ending_states`)
        and the latest time followed, s (∞: to the end).

    Notes
    -----
    A coin started within :data:`CONTACT_GAP` of the table is in contact: approaching (its
    lowest point moving down), it strikes at once (:func:`impact_step`); otherwise the
    verdict after an impact decides (:func:`impact_verdict`, with the lowest point's normal
    velocity as the rebound): trapped in its well, absorbed (e = 0), handed to the ending
    (slower than the rest speed: :func:`died_out`), or flying off. Elsewhere the flight is
    searched from time 0 on (:func:`bounces_until`).
    """
    m = times.shape[0]
    k = 0
    t, tau, bounces, first, count = 0.0, 0.0, 0, -1.0, 0
    face, status = -1, -1
    gap = z - lowest_depth(n[2], c.radius, c.half_thickness, c.corner_radius)
    if gap <= CONTACT_GAP:
        rc = contact_point(n, c.radius, c.half_thickness, c.corner_radius)
        uz = cross(angular_velocity(lm, n, c.i1, c.i3), rc)[2] + v[2]
        first = 0.0
        if uz < 0.0:
            count = 1
            if max_bounces <= 0:
                face = resting_face(n[2], c.edge_sine)
                status = Status.BOUNCE_LIMIT
            else:
                v, lm, face, status, tau = impact_step(z, v, n, lm, c)
                if status == -1:
                    bounces = 1
        else:
            face, status = impact_verdict(z, v, lm, n, uz, c)
            if status == -1:
                tau = leave(uz, z, v, n, lm, c)
        while k < m and times[k] <= 0.0:  # after the impact, if any
            _store(states, k, (xy[0], xy[1], z), n, v, lm)
            k += 1
    while status == -1:
        t_stop = times[k] if k < m else math.inf
        face, status, t, z, xy, v, n, lm, tau, bounces, first, count = bounces_until(
            t_stop, t, z, xy, v, n, lm, tau, bounces, first, count, c, max_bounces
        )
        if status == RUNNING:
            while k < m and times[k] <= t_stop:
                position, vk, nk = fly(times[k] - t, z, xy, v, n, lm, c)
                _store(states, k, position, nk, vk, lm)
                k += 1
            status = -1
    end = t
    duration = 0.0
    if status == DIED_OUT:
        face, status, duration = died_out(z, v, n, lm, c)
    while k < m and times[k] <= end:  # at the last contact itself: the state after it
        _store(states, k, (xy[0], xy[1], z), n, v, lm)
        k += 1
    k, until = ending_states(end, z, xy, v, n, lm, status, c, times, k, states)
    return face, bounces, first, end, end + duration, status, k, until


@njit(cache=True)
def with_surface(
    c, restitution, friction, rolling_resistance, pivoting_resistance, contact_duration
):
    """The contact record ``c`` with this toss's restitution, friction, rolling and pivoting
    resistance and contact duration (the other fields as they are): a per-toss surface for
    distributions of what is not measured."""
    return Contact(
        c.radius,
        c.half_thickness,
        c.mass,
        c.i1,
        c.i3,
        restitution,
        friction,
        c.drop_height,
        c.g,
        c.rest_speed,
        c.reach,
        c.edge_sine,
        c.barrier,
        rolling_resistance,
        pivoting_resistance,
        c.ending,
        c.corner_radius,
        contact_duration,
    )


def _batch_kernel(parallel: bool) -> Any:
    """The loop over a batch, compiled for numba's threads (parallel) or for the calling thread
    with the GIL released. One source; the closure's ``loop`` keeps the two apart in numba's
    on-disk cache (whose key ignores the ``parallel`` flag but hashes closure variables).
    Each toss lands with its own restitution, friction, resistances and contact duration
    (``restitution[k]``, ``friction[k]``, ``rolling[k]``, ``pivoting[k]``, ``duration[k]``) on
    the surface of ``contact``."""
    loop = prange if parallel else range

    def batch(
        omega,
        start_sign,
        launch_speed,
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
                with_surface(
                    contact, restitution[k], friction[k], rolling[k], pivoting[k], duration[k]
                ),
                max_bounces,
            )

    return njit(cache=True, parallel=parallel, nogil=True)(batch)


_land_batch = _batch_kernel(parallel=True)
_land_batch_serial = _batch_kernel(parallel=False)


def land(
    omega: NDArray[np.float64],
    launch_speed: NDArray[np.float64],
    start_sign: NDArray[np.float64],
    contact: Contact,
    *,
    max_bounces: int = MAX_IMPACTS,
    parallel: bool = True,
    restitution: NDArray[np.float64] | None = None,
    friction: NDArray[np.float64] | None = None,
    rolling_resistance: NDArray[np.float64] | None = None,
    pivoting_resistance: NDArray[np.float64] | None = None,
    contact_duration: NDArray[np.float64] | None = None,
) -> tuple[
    NDArray[np.int8], NDArray[np.int32], NDArray[np.float64], NDArray[np.float64], NDArray[np.int8]
]:
    """Land a batch of tosses on a table, in parallel over the tosses.

    Parameters
    ----------
    omega : ndarray, shape (n, 3)
        Body-frame angular velocity at launch, rad/s.
    launch_speed : ndarray, shape (n,)
        Upward speed of the centre of mass at launch, m/s.
    start_sign : ndarray, shape (n,)
        +1 heads up at launch, −1 tails up.
    contact : Contact
        The coin, the surface (drop height, e, μ), gravity and the rest speed, built once by
        :meth:`coinflight.core.contact.Contact.build`.
    max_bounces : int
        Stop at the contact that follows this many bounces and report the well the coin is in
        there (0: the first contact); by default, run until the coin settles.
    parallel : bool
        Spread the tosses over numba's threads (True), or run them in the calling thread with
        the GIL released (False: for callers that run several batches in their own threads).
    restitution, friction : ndarray, shape (n,), optional
        Each toss's own coefficient of restitution and of friction (distributions of what is
        not measured); by default the contact's single values.
    rolling_resistance, pivoting_resistance : ndarray, shape (n,), optional
        Each toss's own rolling and pivoting resistance, m (used by the rigid ending only);
        by default the contact's single values.
    contact_duration : ndarray, shape (n,), optional
        Each toss's own contact duration t_c of an impact, s (when two rim points strike as
        one, :func:`coinflight.core.impact.simultaneous_point`); by default the contact's.

    Returns
    -------
    face : ndarray of int8, shape (n,)
        TAILS 0, HEADS 1, EDGE 2.
    bounces : ndarray of int32, shape (n,)
        Impacts after which the coin left the surface again.
    first_contact, settle_time : ndarray, shape (n,)
        Time of the first and of the last contact since launch, s.
    status : ndarray of int8, shape (n,)
        Why the toss ended (:class:`coinflight.core.outcome.Status`).
    """
    omega = np.ascontiguousarray(omega, dtype=np.float64).reshape(-1, 3)
    n = omega.shape[0]
    speed = np.ascontiguousarray(np.broadcast_to(launch_speed, (n,)), dtype=np.float64)
    sign = np.ascontiguousarray(np.broadcast_to(start_sign, (n,)), dtype=np.float64)
    face = np.empty(n, dtype=np.int8)
    bounces = np.empty(n, dtype=np.int32)
    first = np.empty(n)
    settle = np.empty(n)
    status = np.empty(n, dtype=np.int8)
    e = _per_toss(contact.restitution if restitution is None else restitution, n)
    mu = _per_toss(contact.friction if friction is None else friction, n)
    rolling = contact.rolling_resistance if rolling_resistance is None else rolling_resistance
    pivoting = contact.pivoting_resistance if pivoting_resistance is None else pivoting_resistance
    duration = contact.contact_duration if contact_duration is None else contact_duration
    kernel = _land_batch if parallel else _land_batch_serial
    kernel(
        omega,
        sign,
        speed,
        contact,
        e,
        mu,
        _per_toss(rolling, n),
        _per_toss(pivoting, n),
        _per_toss(duration, n),
        int(max_bounces),
        face,
        bounces,
        first,
        settle,
        status,
    )
    return face, bounces, first, settle, status


def _per_toss(value: float | NDArray[np.float64], n: int) -> NDArray[np.float64]:
    return np.ascontiguousarray(np.broadcast_to(np.asarray(value, dtype=np.float64), (n,)))
