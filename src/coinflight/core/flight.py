"""The closed-form flight of a coin between contacts, and the search for its next contact (numba).

Between contacts the flight is exact: the centre of mass is ballistic and the coin is a
torque-free symmetric top whose normal precesses about the fixed angular momentum L,

    n(τ) = (n0·L̂) L̂ + cos(ωp τ) [n0 − (n0·L̂) L̂] + sin(ωp τ) (L̂ × n0),   ωp = |L| / I1

(Diaconis, Holmes & Montgomery 2007, section 2; REFERENCES §2 — the same motion as
:mod:`coinflight.core.torque_free`, written in the lab frame from any state, which is what a
flight that starts at an impact needs). Contacts are located exactly, not by a time step:
conservative advancement (Mirtich, *Impulse-based dynamic simulation of rigid body systems*,
PhD thesis, Berkeley 1996, §3.4), accelerated by a second-order bound on the gap, then a
safeguarded Newton iteration on the gap (:func:`next_contact`). With the energies that decide
whether a coin can still leave its well (:func:`tumbling_energy`, :func:`mechanical_energy`).

The one flight of the table landing's bounces (:mod:`coinflight.core.bounce`) and of the hops of
its rigid ending (:mod:`coinflight.core.rigid_ending`), both of which import it from here.
"""

from __future__ import annotations

import math

from coinflight.core._jit import njit
from coinflight.core.impact import (
    angular_velocity,
    contact_point,
    cross,
    dot,
    lowest_depth,
)

MAX_STEPS = 100_000
"""Steps of the contact search at most (:func:`next_contact`)."""
CA_TOLERANCE = 1e-9
"""Conservative advancement hands over to Newton within this gap, m."""
GAP_TOLERANCE = 1e-13
"""Newton stops within this distance of the surface, m."""
GRAZE_SKIP = 1e-6
"""After a graze (closest approach within CA_TOLERANCE, no impact), fly on from this time, s."""
SLIP_SPEED = 5e-3
"""v_ε, m/s: the speed below which the rolling and pivoting resistance of the rigid ending's
contacts (:mod:`coinflight.core.rigid_contact`, :mod:`coinflight.core.band_contact`) are
regularised, as torques ∝ ω / sqrt(ω² + ω_ε²) with ω_ε = v_ε / r (the rim moving at v_ε;
0.47 rad/s for a nickel)."""


@njit(cache=True)
def precess(n0: tuple, lhat: tuple, rate: float, tau: float) -> tuple:
    """Normal after time tau of torque-free precession about lhat at ``rate`` (DHM 2007 §2)."""
    c = dot(n0, lhat)
    ca = math.cos(rate * tau)
    sa = math.sin(rate * tau)
    w = cross(lhat, n0)
    return (
        c * lhat[0] + ca * (n0[0] - c * lhat[0]) + sa * w[0],
        c * lhat[1] + ca * (n0[1] - c * lhat[1]) + sa * w[1],
        c * lhat[2] + ca * (n0[2] - c * lhat[2]) + sa * w[2],
    )


@njit(cache=True)
def tumbling_energy(v, angular_momentum, n, mass, i1, g, z):
    """Energy that can turn the coin over: ½ m v_z² + |L⊥|²/2I1 + m g z, J.

    The horizontal motion of the centre of mass and the spin about the coin's own axis leave
    the height of its centre of mass and the tilt of its normal unchanged; only the vertical
    motion, the tumbling (L⊥ = L − (L·n) n) and the height can lift the centre of mass over
    the corner, at height sqrt(r² + h²/4).
    """
    ln = dot(angular_momentum, n)
    l_perp2 = dot(angular_momentum, angular_momentum) - ln * ln
    return 0.5 * mass * v[2] * v[2] + 0.5 * l_perp2 / i1 + mass * g * z


@njit(cache=True)
def mechanical_energy(v, angular_momentum, n, mass, i1, i3, g, z):
    """All the coin's energy: ½ m v² + ½ L·ω + m g z (translation, rotation, height), J.

    No force of a landing adds energy (the impact law of :func:`coinflight.core.impact.impact`
    and the rigid ending's contact forces only store or dissipate it), so once this is below
    the barrier of the coin's well, m g sqrt(r² + h²/4), the coin can never leave that well:
    the well is the outcome, whatever friction later does with the horizontal motion and the
    spin (which :func:`tumbling_energy` leaves out, and which friction can turn into tumbling).
    """
    omega = angular_velocity(angular_momentum, n, i1, i3)
    return 0.5 * mass * dot(v, v) + 0.5 * dot(angular_momentum, omega) + mass * g * z


@njit(cache=True, inline="always")
def _motion_energy(y, c):
    """:func:`mechanical_energy` of a contact state y = (z, v, n, L) (lab frame, SI) with the
    contact record ``c`` (:class:`coinflight.core.contact.Contact`): ½ m v² + ½ L·ω + m g z, J."""
    v = (y[1], y[2], y[3])
    n = (y[4], y[5], y[6])
    lm = (y[7], y[8], y[9])
    return mechanical_energy(v, lm, n, c.mass, c.i1, c.i3, c.g, y[0])


@njit(cache=True, inline="always")
def _dissipative(c):
    """Whether anything dissipates the coin's energy in contact but the impacts (friction or a
    rolling or pivoting resistance)."""
    return c.friction > 0.0 or c.rolling_resistance > 0.0 or c.pivoting_resistance > 0.0


@njit(cache=True, inline="always")
def _motion_free_energy(y, c):
    """(e, f): :func:`_motion_energy` of y and its part that can lift the coin over the barrier
    of its well (:func:`_barrier`): all of it with friction or resistances, else less the
    horizontal kinetic energy (conserved, not free). Used by
    :func:`coinflight.core.rigid_contact.below_barrier`."""
    e = _motion_energy(y, c)
    if _dissipative(c):
        return e, e
    return e, e - 0.5 * c.mass * (y[1] * y[1] + y[2] * y[2])


@njit(cache=True)
def _corner_energy(ln, lz, nz, c):
    """Least energy of the coin balanced on a corner at n_z = nz with L·n = ln and L_z = lz, J:
    the barrier m g ρ plus the least rotational energy with those L·n and L_z there,
    (L·n)²/2I3 + (L_z − (L·n) n_z)² / (2 I1 (1 − n_z²))."""
    return c.barrier + 0.5 * ln * ln / c.i3 + 0.5 * (lz - ln * nz) ** 2 / (c.i1 * (1.0 - nz * nz))


@njit(cache=True, inline="always")
def _barrier(y, c):
    """The barrier of the well the coin of state y is in, J, which no force of a contact can
    lift it over once its free energy (:func:`_motion_free_energy`) is below it: with friction
    or resistances m g ρ (``c.barrier``: Vulović & Prange 1986), as nothing but the impacts and
    those forces act and none of them adds energy; frictionless and without resistances, the
    horizontal momentum, L_z and L·n are conserved, so the least energy on the corners of the
    well (n_z = ±sin(edge)) at the conserved L·n, L_z (:func:`_corner_energy`; the nearer
    corner's for a face, the lower of the two on the edge)."""
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
def _gap(tau, z0, vz0, g, n0, lhat, rate, radius, hh, corner):
    """(height of the coin's lowest point above the surface, normal) at tau: z − depth(n_z), the
    depth of the rounded rim (:func:`coinflight.core.impact.lowest_depth`: the cylinder
    (r − a, h/2 − a) swept by a ball of radius a = ``corner``)."""
    n = precess(n0, lhat, rate, tau)
    z = z0 + vz0 * tau - 0.5 * g * tau * tau
    return z - lowest_depth(n[2], radius, hh, corner), n


@njit(cache=True)
def _gap_rate(tau, vz0, g, n, angular_momentum, i1, i3, radius, hh, corner):
    """d(gap)/dt: vertical velocity of the lowest material point (envelope theorem), the
    lowest point of the rounded rim (:func:`coinflight.core.impact.contact_point`)."""
    omega = angular_velocity(angular_momentum, n, i1, i3)
    rc = contact_point(n, radius, hh, corner)
    return vz0 - g * tau + cross(omega, rc)[2]


@njit(cache=True)
def next_contact(tau, z0, vz0, g, n0, angular_momentum, i1, i3, radius, hh, corner):
    """First time ≥ tau at which the coin's lowest point reaches the surface z = 0.

    The state (height z0 of the centre of mass above the surface, vertical velocity vz0,
    normal n0, angular momentum L) is given at time 0. Returns (time, normal then, vertical
    velocity of the lowest point then); time is −1 if no contact was found within the step
    limit. ``corner`` is the rim's corner radius a (0: sharp): the coin is the cylinder
    (r − a, h/2 − a) swept by a ball of radius a (its lowest point:
    :func:`coinflight.core.impact.lowest_depth`). It lies inside the sharp cylinder, so the
    bounds below, written with the sharp cylinder's reach sqrt(r² + h²/4), hold for it.

    Notes
    -----
    Each step is at least the conservative-advancement step, which provably cannot close the
    gap (the centre of mass falls at most at |v_z| + g dt, and no point of the coin turns
    faster than |ω| ρ; Mirtich 1996, §3.4), and at most 1/8 of a turn; within that it goes as
    far as the gap's Taylor bound gap + gap'·τ − (g + 2|ω|²ρ) τ²/2 stays positive. A step
    that ends below the surface brackets the contact, which a safeguarded Newton iteration
    (Newton inside the bracket, else bisection) then finds to GAP_TOLERANCE.
    """
    lmag = math.sqrt(dot(angular_momentum, angular_momentum))
    if lmag > 0.0:
        lhat = (angular_momentum[0] / lmag, angular_momentum[1] / lmag, angular_momentum[2] / lmag)
    else:
        lhat = (0.0, 0.0, 1.0)
    rate = lmag / i1
    omega = angular_velocity(angular_momentum, n0, i1, i3)
    w2 = dot(omega, omega)
    rho = math.sqrt(radius * radius + hh * hh)
    spin_bound = math.sqrt(w2) * rho
    accel = g + 2.0 * w2 * rho
    max_step = 0.25 * math.pi / (math.sqrt(w2) + 1e-300)
    gap, n = _gap(tau, z0, vz0, g, n0, lhat, rate, radius, hh, corner)
    speed = _gap_rate(tau, vz0, g, n, angular_momentum, i1, i3, radius, hh, corner)
    lo = tau
    hi = -1.0
    for _ in range(MAX_STEPS):
        if gap <= CA_TOLERANCE:
            break
        lo = tau
        vz = vz0 - g * tau
        a = (-vz if vz < 0.0 else 0.0) + spin_bound
        safe = 2.0 * gap / (a + math.sqrt(a * a + 2.0 * g * gap))
        # Positive root of gap + speed τ − accel τ²/2 = 0.
        taylor = (speed + math.sqrt(speed * speed + 2.0 * accel * gap)) / accel
        step = taylor if taylor < max_step else max_step
        if step < safe:
            step = safe
        tau += step
        gap, n = _gap(tau, z0, vz0, g, n0, lhat, rate, radius, hh, corner)
        speed = _gap_rate(tau, vz0, g, n, angular_momentum, i1, i3, radius, hh, corner)
        if gap < -CA_TOLERANCE:
            hi = tau
            break
    else:
        return -1.0, n, 0.0
    # Safeguarded Newton on the gap: lo keeps gap > 0 (no earlier contact), hi once bracketed.
    for _ in range(100):
        if abs(gap) <= GAP_TOLERANCE or (hi < 0.0 and speed >= 0.0):
            break
        if gap > 0.0:
            lo = tau
        else:
            hi = tau
        trial = tau - gap / speed if speed < 0.0 else 0.5 * (lo + hi)
        if hi > 0.0 and not (lo < trial < hi):
            trial = 0.5 * (lo + hi)
        if trial == tau:
            break
        tau = trial
        gap, n = _gap(tau, z0, vz0, g, n0, lhat, rate, radius, hh, corner)
        speed = _gap_rate(tau, vz0, g, n, angular_momentum, i1, i3, radius, hh, corner)
    return tau, n, speed


@njit(cache=True)
def _precess_from(n, lm, i1, tau):
    lmag = math.sqrt(dot(lm, lm))
    if lmag == 0.0:
        return n
    return precess(n, (lm[0] / lmag, lm[1] / lmag, lm[2] / lmag), lmag / i1, tau)


@njit(cache=True)
def _gap_after(tau, z, vz, g, n, lm, i1, radius, hh, corner):
    """Gap under the rounded rim (corner radius ``corner``;
    :func:`coinflight.core.impact.lowest_depth`) tau after an impact."""
    m = _precess_from(n, lm, i1, tau)
    return z + vz * tau - 0.5 * g * tau * tau - lowest_depth(m[2], radius, hh, corner)


@njit(cache=True)
def _first_positive(tau, z, vz, g, n, lm, i1, radius, hh, corner):
    """A time in (0, tau] after an impact where the gap is positive, by halving tau."""
    for _ in range(200):
        tau *= 0.5
        if _gap_after(tau, z, vz, g, n, lm, i1, radius, hh, corner) > 0.0:
            return tau
    return tau


__all__ = [
    "CA_TOLERANCE",
    "GAP_TOLERANCE",
    "GRAZE_SKIP",
    "SLIP_SPEED",
    "mechanical_energy",
    "next_contact",
    "precess",
    "tumbling_energy",
]
