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
2011; REFERENCES §4-5): when its whole energy
(:func:`coinflight.core.flight.mechanical_energy`) is below it, which is rigorous, as no impact
or contact force adds energy (:func:`coinflight.core.impact.impact` is tested for it). Its
outcome is then the well it is in (:func:`coinflight.core.impact.resting_face`). When the
bounces die out instead (a rebound slower than ``rest_speed``: the coin chatters on one rim
point while it tips), the rigid, event-driven ending of
:func:`coinflight.core.rigid_ending.settle` carries it on in 3-D (rolling, sliding, pivoting,
hopping and rocking on its rims, with Coulomb friction and rolling and pivoting resistance)
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
the flight's contact search, the impacts, the barrier and the edge angle of the wells and the
rigid ending. With a = 0 (sharp corners) each is, to the bit,
what it was before it took a.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from coinflight.core import rigid_ending
from coinflight.core._jit import njit, prange
from coinflight.core.contact import Contact
from coinflight.core.flight import (
    CA_TOLERANCE,
    GRAZE_SKIP,
    _first_positive,
    _gap_after,
    _precess_from,
    mechanical_energy,
    next_contact,
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

# Why a toss ended (the ``status`` array): :class:`coinflight.core.outcome.Status`.

if TYPE_CHECKING:
    # A batch's ω (n, 3), v0 (n,) and start sign (n,) (batch_inputs); its face, bounces,
    # first contact, settle time and status, each of shape (n,).
    Tosses = tuple[NDArray[np.float64], NDArray[np.float64], NDArray[np.float64]]
    Landed = tuple[
        NDArray[np.int8],
        NDArray[np.int32],
        NDArray[np.float64],
        NDArray[np.float64],
        NDArray[np.int8],
    ]

MAX_IMPACTS = 2_000
REST_SPEED = 0.01
"""Default rebound speed of the contact point below which the bounces have died out, m/s."""


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
    v, lm, rebound = impact(v, lm, n, c)
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

    * the coin is trapped in its well: its whole energy
      (:func:`coinflight.core.flight.mechanical_energy`) is below the barrier ``c.barrier``,
      which is rigorous, as no impact or contact force adds energy afterwards (status
      SETTLED_ENERGY);
    * e = 0 and the rebound below ``rest_speed``: the surface absorbed it (SETTLED_DEAD);
    * the bounces died out (rebound below ``rest_speed``): :data:`DIED_OUT` (face −1), for
      :func:`died_out`;
    * else the coin flies on: status −1, face −1.
    """
    if mechanical_energy(v, lm, n, c.mass, c.i1, c.i3, c.g, z) < c.barrier:
        return resting_face(n[2], c.edge_sine), Status.SETTLED_ENERGY
    if rebound < c.rest_speed:
        if c.restitution == 0.0:
            return resting_face(n[2], c.edge_sine), Status.SETTLED_DEAD
        return -1, DIED_OUT
    return -1, -1


@njit(cache=True)
def died_out(z, v, n, lm, c):
    """The end of a landing whose bounces died out: (face, status, duration, s), the rigid,
    event-driven ending of :func:`coinflight.core.rigid_ending.settle` (SETTLED_CONTACT or
    UNSETTLED, its duration)."""
    return rigid_ending.settle(z, v, n, lm, c)


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

    The rigid ending's motion (:func:`coinflight.core.rigid_ending.states`), to the time it
    settled or gave up, after bounces that died out; after a landing that ended at an impact
    (below the barrier, dead, the bounce limit) nothing after t is followed: (k, t).
    """
    if status == Status.SETTLED_CONTACT or status == Status.UNSETTLED:
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
    **per_toss: ArrayLike,
) -> Landed:
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
    **per_toss : ndarray, shape (n,), optional
        Each toss's own value of any of :data:`PER_TOSS` (distributions of what is not
        measured): ``restitution`` and ``friction``, ``rolling_resistance`` and
        ``pivoting_resistance`` (m, used by the rigid ending), ``contact_duration`` (t_c of an
        impact, s: when two rim points strike as one,
        :func:`coinflight.core.impact.simultaneous_point`); by default the contact's.

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
    kernel = _land_batch if parallel else _land_batch_serial
    return run_batch(kernel, (), omega, launch_speed, start_sign, contact, max_bounces, per_toss)


PER_TOSS = (
    "restitution",
    "friction",
    "rolling_resistance",
    "pivoting_resistance",
    "contact_duration",
)
"""The contact record's fields a batch of landings may give each toss its own value of (the
arguments of the batch kernels, in this order, after the contact record)."""


def run_batch(
    kernel: Any,
    before: tuple[Any, ...],
    omega: ArrayLike,
    launch_speed: ArrayLike,
    start_sign: ArrayLike,
    contact: Contact,
    max_bounces: int,
    per_toss: Mapping[str, ArrayLike],
) -> Landed:
    """Run a batch landing ``kernel`` (this module's or :func:`coinflight.core.drag.land`'s) on
    the tosses (:func:`batch_inputs`): its arguments ``before`` the contact record (the air,
    for drag's), each toss's values of :data:`PER_TOSS` (``per_toss``; the contact's where
    not given; TypeError for another name); the outputs (face, bounces, first contact,
    settle time, status), each of shape (n,)."""
    unknown = sorted(set(per_toss) - set(PER_TOSS))
    if unknown:
        raise TypeError(f"unexpected per-toss values {', '.join(unknown)}; allowed: {PER_TOSS}")
    omega, speed, sign = batch_inputs(omega, launch_speed, start_sign)
    n = omega.shape[0]
    surface = [
        np.ascontiguousarray(
            np.broadcast_to(np.asarray(per_toss.get(name, getattr(contact, name)), float), (n,))
        )
        for name in PER_TOSS
    ]
    out: Landed = (
        np.empty(n, dtype=np.int8),
        np.empty(n, dtype=np.int32),
        np.empty(n),
        np.empty(n),
        np.empty(n, dtype=np.int8),
    )
    kernel(omega, sign, speed, *before, contact, *surface, int(max_bounces), *out)
    return out


def batch_inputs(omega: ArrayLike, launch_speed: ArrayLike, start_sign: ArrayLike) -> Tosses:
    """A batch's tosses as the kernels read them: ω (n, 3), v0 (n,) and the start sign (n,),
    contiguous float64 (v0 and the sign broadcast to n)."""
    omega = np.ascontiguousarray(omega, dtype=np.float64).reshape(-1, 3)
    n = omega.shape[0]
    speed = np.ascontiguousarray(np.broadcast_to(launch_speed, (n,)), dtype=np.float64)
    sign = np.ascontiguousarray(np.broadcast_to(start_sign, (n,)), dtype=np.float64)
    return omega, speed, sign
