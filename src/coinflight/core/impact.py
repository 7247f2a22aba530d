"""A coin hitting a horizontal surface: contact geometry and the impact impulse.

Scalar kernels on 3-tuples of floats (lab frame, SI units, the surface normal is +Z), written
so that numba compiles the same functions for the event-driven simulation of
:mod:`coinflight.core.bounce`. The coin is a uniform cylinder of radius r and half-thickness
hh = h/2 whose state is its heads normal n, the velocity v of its centre of mass and its
angular momentum L about the centre of mass (all lab frame).

The impact law
--------------
A sequential Newton-Coulomb impulse at the lowest point of the coin (Catto, *Iterative
dynamics with temporal coherence*, GDC 2005; Stronge, *Impact Mechanics*, 2000, ch. 2-5 for
the collision matrix):

1. normal: if the contact point approaches the surface (u_z < 0), an impulse along +Z that
   reverses its normal velocity, u_z' = −e u_z (Newton's restitution);
2. friction: the tangential impulse that stops the sliding of the contact point (sticking) if
   it lies inside Coulomb's cone |P_t| ≤ μ P_n; otherwise an impulse opposite to the slip of
   magnitude μ P_n, but never more than what stops the slip along its own direction (sliding);
3. if the friction impulse has turned the contact point back towards the surface, a plastic
   normal impulse (u_z' = 0) so that the coin never sinks into it; then 2 and 3 again
   (a few sweeps, projected Gauss-Seidel style) with what is left of the friction cone.

Kinetic energy never grows: every step applies an impulse s d at the contact point along a fixed
direction d, and the kinetic energy is the convex quadratic T(s) = T0 + s d·u + ½ s² d·K d
(K the collision matrix). Step 1 takes s = (1 + e) s_min, within [0, 2 s_min] where
T(s) ≤ T0; step 2 takes the minimiser over the tangential plane (sticking) or s ≤ s_min along
−û_t (sliding); step 3 takes s = s_min. With e = 1 and μ = 0 energy is conserved exactly.
"""

from __future__ import annotations

import math

from numba import njit

Vec = tuple[float, float, float]
FRICTION_SWEEPS = 32
"""Friction / non-penetration sweeps per impact (each one can only dissipate energy)."""


@njit(cache=True)
def dot(a: Vec, b: Vec) -> float:
    """a · b."""
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


@njit(cache=True)
def cross(a: Vec, b: Vec) -> Vec:
    """a × b."""
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


@njit(cache=True)
def lowest_depth(nz: float, radius: float, half_thickness: float) -> float:
    """Depth of the coin's lowest point below its centre of mass, m.

    Notes
    -----
    The support function of a cylinder along −Z: r sqrt(1 − n_z²) + (h/2)|n_z| (the lowest
    point is on the rim of the lower face; a face when n_z = ±1, the edge when n_z = 0).
    Yong & Mahadevan 2011, §III; REFERENCES §5.
    """
    s2 = 1.0 - nz * nz
    return radius * math.sqrt(s2 if s2 > 0.0 else 0.0) + half_thickness * abs(nz)


@njit(cache=True)
def contact_point(n: Vec, radius: float, half_thickness: float) -> Vec:
    """Lowest point of the coin relative to its centre of mass, lab frame, m.

    r ŵ − sign(n_z) (h/2) n, where ŵ is the unit vector of the coin's plane pointing most
    downwards, (−Z + n_z n)/sqrt(1 − n_z²). A coin lying flat touches with the centre of its
    lower face.
    """
    nz = n[2]
    s2 = 1.0 - nz * nz
    sign = 1.0 if nz >= 0.0 else -1.0
    if s2 <= 1e-24:
        return (
            -sign * half_thickness * n[0],
            -sign * half_thickness * n[1],
            -sign * half_thickness * n[2],
        )
    k = radius / math.sqrt(s2)
    return (
        k * nz * n[0] - sign * half_thickness * n[0],
        k * nz * n[1] - sign * half_thickness * n[1],
        k * (nz * nz - 1.0) - sign * half_thickness * n[2],
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


@njit(cache=True)
def impact(
    v: Vec,
    angular_momentum: Vec,
    n: Vec,
    radius: float,
    half_thickness: float,
    mass: float,
    i1: float,
    i3: float,
    restitution: float,
    friction: float,
) -> tuple[Vec, Vec, float]:
    """State just after the coin hits the surface z = const with its lowest point.

    Parameters
    ----------
    v : tuple of 3 floats
        Velocity of the centre of mass before the impact, m/s.
    angular_momentum : tuple of 3 floats
        Angular momentum about the centre of mass before the impact, kg m²/s.
    n : tuple of 3 floats
        Heads normal (unit), lab frame.
    radius, half_thickness, mass, i1, i3 : float
        The coin (m, m, kg, kg m², kg m²).
    restitution, friction : float
        e in [0, 1] and μ ≥ 0.

    Returns
    -------
    v, angular_momentum : tuple of 3 floats
        After the impact.
    rebound : float
        Normal velocity of the contact point after the impact, m/s (≥ 0).

    Notes
    -----
    Sequential Newton-Coulomb impulse; see the module notes for the law and why the kinetic
    energy never grows.
    """
    rc = contact_point(n, radius, half_thickness)
    ez = (0.0, 0.0, 1.0)
    omega = angular_velocity(angular_momentum, n, i1, i3)
    u = contact_velocity(v, omega, rc)
    if u[2] >= 0.0:
        return v, angular_momentum, u[2]
    kzz = _coupling(rc, ez, ez, n, mass, i1, i3)
    # 1. Newton's restitution along the normal.
    pn = -(1.0 + restitution) * u[2] / kzz
    v, angular_momentum = _apply((0.0, 0.0, pn), v, angular_momentum, rc, mass)
    # 2-3, repeated: Coulomb friction, then a plastic normal impulse if friction turned the
    # contact point back into the surface; each friction impulse spends what is left of the
    # cone's budget μ (total normal impulse) − |total tangential impulse|.
    if friction > 0.0:
        ex = (1.0, 0.0, 0.0)
        ey = (0.0, 1.0, 0.0)
        kxx = _coupling(rc, ex, ex, n, mass, i1, i3)
        kxy = _coupling(rc, ex, ey, n, mass, i1, i3)
        kyy = _coupling(rc, ey, ey, n, mass, i1, i3)
        det = kxx * kyy - kxy * kxy
        tx = 0.0
        ty = 0.0
        for _ in range(FRICTION_SWEEPS):
            omega = angular_velocity(angular_momentum, n, i1, i3)
            u = contact_velocity(v, omega, rc)
            slip = math.hypot(u[0], u[1])
            if slip == 0.0:
                break
            budget = friction * pn - math.hypot(tx, ty)
            if budget <= 0.0:
                break
            px = -(kyy * u[0] - kxy * u[1]) / det
            py = -(-kxy * u[0] + kxx * u[1]) / det
            if px * px + py * py > budget * budget:
                dx, dy = -u[0] / slip, -u[1] / slip
                s_min = slip / (kxx * dx * dx + 2.0 * kxy * dx * dy + kyy * dy * dy)
                step = budget if budget < s_min else s_min
                px, py = step * dx, step * dy
            v, angular_momentum = _apply((px, py, 0.0), v, angular_momentum, rc, mass)
            tx += px
            ty += py
            omega = angular_velocity(angular_momentum, n, i1, i3)
            u = contact_velocity(v, omega, rc)
            if u[2] < 0.0:
                dn = -u[2] / kzz
                pn += dn
                v, angular_momentum = _apply((0.0, 0.0, dn), v, angular_momentum, rc, mass)
            elif math.hypot(u[0], u[1]) <= 1e-15 * (1.0 + slip):
                break
    omega = angular_velocity(angular_momentum, n, i1, i3)
    u = contact_velocity(v, omega, rc)
    return v, angular_momentum, u[2]


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
