"""A rigid coin upright on its edge band, both rims touching the table (numba).

A coin with a flat edge band (half-width H = h/2 − a > 0, a the corner radius) standing
upright (n horizontal) touches the table at two points, the lowest points of its two rims,
ρ± = ±H n − r Z from the centre of mass (at n_z = 0 the rounded rim's lowest point is r − a
below the core circle's centre and a lower still). Both gaps held at 0 fix z = r and n_z = 0,
and leave four degrees of freedom: the heading θ of n = (cos θ, sin θ, 0), the spin about n and
the horizontal position. With t = n × Z the velocities are v = v_n n + v_t t (v_z = 0) and
ω = ω_a n + ω_z Z (ω_t = ṅ_z = 0), L = I3 ω_a n + I1 ω_z Z.

Each point has its own contact force F± = f±_n n + f±_t t + N± Z, with N± ≥ 0 and exact
Coulomb friction: a point that slips, at s± = (v_n, v_t − r ω_a ∓ H ω_z) in the (n, t) frame,
is opposed by f± = −μ N± ŝ±; a point that sticks bears whatever keeps it stuck, inside its
cone |f±| ≤ μ N± (the set-valued force laws of Glocker & Pfeiffer's unilateral multibody
contacts, Pfeiffer & Glocker 1996, *Multibody Dynamics with Unilateral Contacts*, Wiley;
Glocker 2001, *Set-Valued Force Laws*, Springer; the rolling disc's stick-slip by Le Saux,
Leine & Glocker 2005, J. Nonlinear Sci. 15:27). Newton–Euler in the turning frame (n, t, Z),
ṅ = −ω_z t, ṫ = ω_z n, with F = Σ F±, the torques Σ ρ± × F± and the resistances T (below):

    m (v̇_n + ω_z v_t) = F_n,   m (v̇_t − ω_z v_n) = F_t,   N+ + N− = m g,
    I3 ω̇_a = −r F_t + T_a,    I1 ω̇_z = −H (f+_t − f−_t) + T_z,
    H (N+ − N−) + r F_n = −I3 ω_a ω_z          (L̇·t, which keeps ω_t = 0).

The last line is the band's balance against tipping: rolling straight without lateral slip
(F_n = m ω_z v_t, v_t = r ω_a) the rims' loads differ by (I3 + m r²) ω_a ω_z / H, so a coin
rolling on its band and turning leaves it (one N reaching 0) once (I3 + m r²) |ω_a ω_z|
exceeds m g H, the band's restoring moment; and a lateral slide tips it once μ r exceeds H
(the sliding block's tipping).

The slips' rates (lab frame, along n and t), linear in the forces:

    ṡ±_n = F_n/m − ω_z (r ω_a ± H ω_z),
    ṡ±_t = F_t (1/m + r²/I3) − r T_a/I3 ± H² (f+_t − f−_t)/I1 ∓ H T_z/I1.

Modes (:data:`SLIDE`, :data:`STICK_PLUS`, :data:`STICK_MINUS`, :data:`ROLL`), each a linear
solve for its unknown forces:

* **SLIDE**, both points slipping: N± from the two normal lines, a 2×2 system whose
  determinant's sign is c_N = 2H + r μ (ŝ−_n − ŝ+_n); c_N ≤ 0 is the band's Painlevé case
  (an event: N± grow without bound as c_N → 0, so one of them reaches 0 first unless both
  numerators vanish with it; the run then ends on the rim loaded more);
* **STICK_PLUS / STICK_MINUS**, the + (−) rim's point sticking, the other slipping at
  2 H |ω_z| (the coin pivoting about the sticking point): F_n from ṡ_n = 0, N± from the
  tipping line, the sticking point's f_t from ṡ_t = 0;
* **ROLL**, both sticking: ω_z = 0 and v_n = 0, rolling straight; N+ = N− = m g/2 (the split
  of the horizontal force between the points is indeterminate, only its sum enters). Nothing
  turns it again: :func:`coinflight.core.rigid_ending._band` rolls it on in closed form.

A pivoting coin on its band (v_n = 0, v_t = r ω_a) slips at ∓H ω_z at the two points:
friction's torque about Z is −μ (N+ + N−) H sgn ω_z = −μ m g H sgn ω_z, so its yaw falls
linearly and stops in I1 |ω_z| / (μ m g H) (10 ms for a nickel at 1 rad/s, μ 0.3), while the
gyroscopic and centripetal moment of its roll, (I3 + m r²) ω_a ω_z, loads one rim more.

Events, located by bisection to :data:`coinflight.core.rigid_contact.EVENT_TIME` (positive
while nothing happens): N+ or N− reaching 0 (one rim lifts: the run stops and hands the
coin to the one-rim contact of :mod:`coinflight.core.rigid_contact` on the other); a slipping
point's slip stopping (its component along the slip at the step's start reaching 0, or its
size :data:`coinflight.core.rigid_contact.SLIP_FLOOR`), then the stick test (the mode with
that point sticking, if its force lies in the cone and both N ≥ 0; else it slides on, from
the direction opposite the force that would have held it); a sticking point's force leaving
its cone (it starts to slip, that way); c_N reaching 0. Without friction (μ = 0) nothing
sticks. The run also stops when both points stick (ROLL), when the energy is below the well's
barrier (:func:`coinflight.core.rigid_contact.below_barrier`) and at its duration.

Rolling and pivoting resistance are the one-rim contact's
(:func:`coinflight.core.rigid_contact._resistance`), at each point with its N, so in sum
T_a = −ℓ_r m g ω_a/sqrt(ω_a² + ω_ε²), T_z = −ℓ_p m g ω_z/sqrt(ω_z² + ω_ε²).

Entering the band (:func:`from_state`): the rocking across the band left when it has died out
(ω_t and v_z) is removed as a rotation about the rims' contact line, which keeps the rims'
horizontal slip, their roll and the yaw (the rocking's energy, at most
:data:`coinflight.core.rigid_ending.BAND_FRACTION` of the edge well's depth, is taken).
Limits: that last rocking is stopped at once, not by the ever smaller impacts of a rocking
block (Housner 1963); a small slip's direction below SLIP_FLOOR is that of its start (as in the
one-rim contact); the Painlevé case ends the band run on the rim loaded more.

The state is the reduced q = (θ, v_n, v_t, ω_a, ω_z[, x, y]); :func:`to_state` and
:func:`from_state` convert from and to the state y = (z, v, n, L[, x, y]) of
:mod:`coinflight.core.rigid_contact`. Integration: Dormand–Prince 5(4) with error control
(the coefficients of :mod:`coinflight.core.dormand_prince`), the sticking constraints restored
after each step by the least-energy projection.
"""

from __future__ import annotations

import math

import numpy as np

from coinflight.core import dormand_prince as dp
from coinflight.core import rigid_contact as rc
from coinflight.core._jit import njit
from coinflight.core.flight import (
    SLIP_SPEED,
)
from coinflight.core.impact import angular_velocity, lowest_depth

SLIDE = 0
"""Band mode: both rims' points slip."""
STICK_PLUS = 1
"""Band mode: the + rim's point (at +H n) sticks, the − rim's slips."""
STICK_MINUS = 2
"""Band mode: the − rim's point (at −H n) sticks, the + rim's slips."""
ROLL = 3
"""Band mode: both stick, rolling straight."""

DURATION = 0
"""Why a band run stopped: its duration has passed."""
LIFT_PLUS = 1
"""N+ reached 0: the + rim lifts, the coin goes on on its − rim (n_z > 0)."""
LIFT_MINUS = 2
"""N− reached 0: the − rim lifts, the coin goes on on its + rim (n_z < 0)."""
ROLLING = 3
"""Both points stick: the coin rolls straight (mode ROLL)."""
BELOW_BARRIER = 4
"""The energy is below the well's barrier."""
STEP_FAILED = 5
"""60 trial steps in a row rejected, or the step budget spent."""
NOT_BAND = 6
"""The state handed to :func:`run_band` is no band state (a normal force would be negative)."""

TILT = 1e-12
"""n_z given to a coin leaving its band by a rim's lift (the sign picks the rim it goes on on in
:mod:`coinflight.core.rigid_contact`, which takes the lower rim by n_z's sign)."""


@njit(cache=True)
def _half_band(c):
    return c.half_thickness - c.corner_radius


@njit(cache=True)
def _slips(q, c):
    """(s_n, s+_t, s−_t): the two points' slip (s_n shared), m/s."""
    common = q[2] - c.radius * q[3]
    hw = _half_band(c) * q[4]
    return q[1], common - hw, common + hw


@njit(cache=True)
def _resist(q, c):
    """(T_a, T_z): the rolling and pivoting resistance torques in sum over both points, N m."""
    eps = SLIP_SPEED / c.radius
    weight = c.mass * c.g
    ta, tz = 0.0, 0.0
    if c.rolling_resistance > 0.0:
        ta = -c.rolling_resistance * weight * q[3] / math.sqrt(q[3] * q[3] + eps * eps)
    if c.pivoting_resistance > 0.0:
        tz = -c.pivoting_resistance * weight * q[4] / math.sqrt(q[4] * q[4] + eps * eps)
    return ta, tz


@njit(cache=True)
def _direction(sn, st, dn, dt):
    """A slipping point's slip direction: its own above SLIP_FLOOR, else (dn, dt), the
    direction it started in, unless the slip points against it (friction then opposes the
    slip itself)."""
    size = math.sqrt(sn * sn + st * st)
    if size > rc.SLIP_FLOOR:
        return sn / size, st / size
    if size > 0.0 and sn * dn + st * dt < 0.0:
        return sn / size, st / size
    return dn, dt


@njit(cache=True)
def forces(q, c, mode, d):
    """(N+, N−, f+_n, f+_t, f−_n, f−_t, c_N) of the band mode (module notes), N; d = (d+_n,
    d+_t, d−_n, d−_t), the slip directions of slipping points below SLIP_FLOOR. c_N ≤ 0:
    Painlevé (the forces then 0)."""
    m, r, i1, i3, mu = c.mass, c.radius, c.i1, c.i3, c.friction
    hb = _half_band(c)
    wa, wz = q[3], q[4]
    ta, tz = _resist(q, c)
    weight = m * c.g
    gyro = -i3 * wa * wz  # H (N+ − N−) + r F_n
    if mode == ROLL:
        ft = m * r * ta / (i3 + m * r * r)
        return 0.5 * weight, 0.5 * weight, 0.0, 0.5 * ft, 0.0, 0.5 * ft, 1.0
    sn, sp, sm = _slips(q, c)
    if mode == SLIDE:
        pn, pt = _direction(sn, sp, d[0], d[1])
        qn, qt = _direction(sn, sm, d[2], d[3])
        a21 = hb - r * mu * pn
        a22 = -hb - r * mu * qn
        coef = a21 - a22  # 2H + r μ (ŝ−_n − ŝ+_n)
        if coef <= 0.0:
            return 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, coef
        det = -coef
        np_ = (weight * a22 - gyro) / det
        nm = (gyro - a21 * weight) / det
        return np_, nm, -mu * np_ * pn, -mu * np_ * pt, -mu * nm * qn, -mu * nm * qt, coef
    sigma = 1.0 if mode == STICK_PLUS else -1.0
    fn = m * wz * (r * wa + sigma * hb * wz)
    diff = (gyro - r * fn) / hb
    np_ = 0.5 * (weight + diff)
    nm = 0.5 * (weight - diff)
    if mode == STICK_PLUS:
        other = nm
        on, ot = _direction(sn, sm, d[2], d[3])
    else:
        other = np_
        on, ot = _direction(sn, sp, d[0], d[1])
    fon = -mu * other * on
    fot = -mu * other * ot
    k = 1.0 / m + r * r / i3
    j = hb * hb / i1
    fst = (r * ta / i3 + sigma * hb * tz / i1 - fot * (k - j)) / (k + j)
    fsn = fn - fon
    if mode == STICK_PLUS:
        return np_, nm, fsn, fst, fon, fot, 1.0
    return np_, nm, fon, fot, fsn, fst, 1.0


@njit(cache=True)
def _rates(q, out, c, mode, d):
    """dq/dt in ``mode``."""
    _, _, fpn, fpt, fmn, fmt, _ = forces(q, c, mode, d)
    m, r = c.mass, c.radius
    ta, tz = _resist(q, c)
    fn, ft = fpn + fmn, fpt + fmt
    vn, vt, wz = q[1], q[2], q[4]
    out[0] = wz
    out[1] = fn / m - wz * vt
    out[2] = ft / m + wz * vn
    out[3] = (-r * ft + ta) / c.i3
    out[4] = (-_half_band(c) * (fpt - fmt) + tz) / c.i1
    if q.shape[0] > 5:
        cs, sn = math.cos(q[0]), math.sin(q[0])
        out[5] = vn * cs + vt * sn
        out[6] = vn * sn - vt * cs


@njit(cache=True)
def _project(q, c, mode):
    """The sticking points' constraints restored by the least-energy velocity change (metric
    diag(m, m, I3, I1) on (v_n, v_t, ω_a, ω_z)); returns the slip removed, m/s."""
    if mode == SLIDE:
        return 0.0
    m, r, i1, i3 = c.mass, c.radius, c.i1, c.i3
    hb = _half_band(c)
    removed = abs(q[1])
    q[1] = 0.0
    if mode == ROLL:
        removed = max(removed, hb * abs(q[4]))
        q[4] = 0.0
        hw = 0.0
        jz = 0.0
    else:
        hw = hb if mode == STICK_PLUS else -hb
        jz = hw
    # J = (0, 1, −r, −σH): v_t − r ω_a − σ H ω_z = 0.
    slip = q[2] - r * q[3] - hw * q[4]
    lam = slip / (1.0 / m + r * r / i3 + jz * jz / i1)
    q[2] -= lam / m
    q[3] += r * lam / i3
    q[4] += jz * lam / i1
    return max(removed, abs(slip))


@njit(cache=True)
def to_state(q, c, tilt, y):
    """y = (z, v, n, L[, x, y]) of the band state q, n tilted to n_z = ``tilt`` (0 on the band;
    ±:data:`TILT` to hand the coin to one rim) about t, ω_t = 0."""
    cs, sn = math.cos(q[0]), math.sin(q[0])
    flat = math.sqrt(1.0 - tilt * tilt)
    n = (cs * flat, sn * flat, tilt)
    tx, ty = sn, -cs
    wx, wy, wz = q[3] * n[0], q[3] * n[1], q[3] * n[2] + q[4]
    y[0] = lowest_depth(tilt, c.radius, c.half_thickness, c.corner_radius)
    y[1] = q[1] * cs + q[2] * tx
    y[2] = q[1] * sn + q[2] * ty
    y[3] = 0.0
    y[4], y[5], y[6] = n
    wn = wx * n[0] + wy * n[1] + wz * n[2]
    i1, i3 = c.i1, c.i3
    y[7] = i1 * wx + (i3 - i1) * wn * n[0]
    y[8] = i1 * wy + (i3 - i1) * wn * n[1]
    y[9] = i1 * wz + (i3 - i1) * wn * n[2]
    if y.shape[0] > 10 and q.shape[0] > 5:
        y[10], y[11] = q[5], q[6]


@njit(cache=True)
def from_state(y, c, q):
    """q of the state y at n_z ≈ 0 (the other rim just come down): n made horizontal and the
    rocking removed as a rotation about the rims' contact points, so their horizontal slip is
    kept: ω_t → 0, v → v + ω_t t × ρ± (v_n + r ω_t along n, the same for both rims), v_z → 0.
    Returns the kinetic energy removed, J."""
    size = math.sqrt(y[4] * y[4] + y[5] * y[5])
    nx, ny = y[4] / size, y[5] / size
    tx, ty = ny, -nx
    n = (y[4], y[5], y[6])
    omega = angular_velocity((y[7], y[8], y[9]), n, c.i1, c.i3)
    before = 0.5 * c.mass * (y[1] * y[1] + y[2] * y[2] + y[3] * y[3])
    before += 0.5 * (y[7] * omega[0] + y[8] * omega[1] + y[9] * omega[2])
    wt = omega[0] * tx + omega[1] * ty
    q[0] = math.atan2(ny, nx)
    q[1] = y[1] * nx + y[2] * ny + c.radius * wt
    q[2] = y[1] * tx + y[2] * ty
    q[3] = omega[0] * nx + omega[1] * ny
    q[4] = omega[2]
    if q.shape[0] > 5 and y.shape[0] > 10:
        q[5], q[6] = y[10], y[11]
    after = 0.5 * c.mass * (q[1] * q[1] + q[2] * q[2])
    after += 0.5 * (c.i3 * q[3] * q[3] + c.i1 * q[4] * q[4])
    return before - after


@njit(cache=True)
def _feasible(q, c, mode, d):
    """Whether the mode's forces are consistent: N± ≥ 0, c_N > 0, sticking points in the cone."""
    np_, nm, fpn, fpt, fmn, fmt, coef = forces(q, c, mode, d)
    if coef <= 0.0 or np_ < 0.0 or nm < 0.0:
        return False
    mu = c.friction
    if mode in (STICK_PLUS, ROLL) and math.sqrt(fpn * fpn + fpt * fpt) > mu * np_:
        return False
    return not (mode in (STICK_MINUS, ROLL) and math.sqrt(fmn * fmn + fmt * fmt) > mu * nm)


@njit(cache=True)
def _start_direction(q, c, stick_mode, d):
    """The direction a point that cannot stick starts to slip in: against the force that would
    have held it (the slip ray's first guess, :func:`coinflight.core.rigid_contact.slip_start`)."""
    _, _, fpn, fpt, fmn, fmt, _ = forces(q, c, stick_mode, d)
    fn, ft = (fpn, fpt) if stick_mode == STICK_PLUS else (fmn, fmt)
    size = math.sqrt(fn * fn + ft * ft)
    if size == 0.0:
        return 0.0, 1.0
    return -fn / size, -ft / size


@njit(cache=True)
def _sticks(q, c, sigma, d):
    """Whether the point ``sigma`` (:data:`STICK_PLUS` or :data:`STICK_MINUS`) can stick, its
    force inside its cone; if not, its slide's starting direction is put in ``d``."""
    if _feasible(q, c, sigma, d):
        return True
    _slide_from(q, c, sigma, d)
    return False


@njit(cache=True)
def _slide_from(q, c, sigma, d):
    """Put in ``d`` the starting direction of the slide of the point ``sigma`` whose force
    would leave its cone (against that force)."""
    dn, dt = _start_direction(q, c, sigma, d)
    if sigma == STICK_PLUS:
        d[0], d[1] = dn, dt
    else:
        d[2], d[3] = dn, dt


@njit(cache=True)
def classify(q, c, d):
    """The band mode of q (d, the slipping points' start directions, set in place): a point
    whose slip is below SLIP_FLOOR sticks if the mode with it sticking has its force in the
    cone, else slips from :func:`_start_direction`. Returns the mode, or −1 if that mode needs
    a negative normal force (a rim lifts: no band state)."""
    sn, sp, sm = _slips(q, c)
    small_p = math.sqrt(sn * sn + sp * sp) <= rc.SLIP_FLOOR and c.friction > 0.0
    small_m = math.sqrt(sn * sn + sm * sm) <= rc.SLIP_FLOOR and c.friction > 0.0
    if small_p and small_m:
        return ROLL if _feasible(q, c, ROLL, d) else -1
    for sigma in (STICK_PLUS, STICK_MINUS):
        small = small_p if sigma == STICK_PLUS else small_m
        if not small:
            continue
        np_, nm, _, _, _, _, _ = forces(q, c, sigma, d)
        if np_ < 0.0 or nm < 0.0:
            return -1
        if _sticks(q, c, sigma, d):
            return sigma
    if _feasible(q, c, SLIDE, d):
        return SLIDE
    return -1


@njit(cache=True)
def _events(q, c, mode, d, start, floor):
    """(N+, N−, c_N, + point, − point): positive while nothing happens. A slipping point's
    value is its slip along ``start`` (its direction at the step's start) or its size less
    ``floor`` (whichever is less); a sticking point's, its cone's margin μ N − |f|."""
    np_, nm, fpn, fpt, fmn, fmt, coef = forces(q, c, mode, d)
    sn, sp, sm = _slips(q, c)
    mu = c.friction
    if mode == STICK_PLUS:
        ep = mu * np_ - math.sqrt(fpn * fpn + fpt * fpt)
    else:
        along = sn * start[0] + sp * start[1]
        ep = min(along, math.sqrt(sn * sn + sp * sp) - floor[0]) if mu > 0.0 else 1.0
    if mode == STICK_MINUS:
        em = mu * nm - math.sqrt(fmn * fmn + fmt * fmt)
    else:
        along = sn * start[2] + sm * start[3]
        em = min(along, math.sqrt(sn * sn + sm * sm) - floor[1]) if mu > 0.0 else 1.0
    if coef <= 0.0:
        return 1.0, 1.0, coef, ep, em
    return np_, nm, coef, ep, em


@njit(cache=True)
def _crossed(e):
    return e[0] < 0.0 or e[1] < 0.0 or e[2] <= 0.0 or e[3] < 0.0 or e[4] < 0.0


@njit(cache=True)
def _step(q, h, c, mode, d, k1, k2, k3, k4, k5, k6, k7, tmp, new):
    """One Dormand–Prince step of h from q (k1 = f(q) given): ``new``, k7 = f(new). The stages
    written out (a loop picking each one's arrays at run time is markedly slower)."""
    dp.stage(2, q, h, k1, k2, k3, k4, k5, k6, tmp)
    _rates(tmp, k2, c, mode, d)
    dp.stage(3, q, h, k1, k2, k3, k4, k5, k6, tmp)
    _rates(tmp, k3, c, mode, d)
    dp.stage(4, q, h, k1, k2, k3, k4, k5, k6, tmp)
    _rates(tmp, k4, c, mode, d)
    dp.stage(5, q, h, k1, k2, k3, k4, k5, k6, tmp)
    _rates(tmp, k5, c, mode, d)
    dp.stage(6, q, h, k1, k2, k3, k4, k5, k6, tmp)
    _rates(tmp, k6, c, mode, d)
    dp.stage(7, q, h, k1, k2, k3, k4, k5, k6, new)
    _rates(new, k7, c, mode, d)


@njit(cache=True)
def _step_start(q, c, mode, d, start, floor):
    """The slipping points' directions (``start``) and floors at a step's start."""
    sn, sp, sm = _slips(q, c)
    for side in range(2):
        st = sp if side == 0 else sm
        size = math.sqrt(sn * sn + st * st)
        dn, dt = _direction(sn, st, d[2 * side], d[2 * side + 1])
        start[2 * side], start[2 * side + 1] = dn, dt
        floor[side] = rc.SLIP_FLOOR if size > rc.SLIP_FLOOR else 0.0


@njit(cache=True)
def _below(q, c, y):
    to_state(q, c, 0.0, y)
    return rc.below_barrier(y, c)


@njit(cache=True)
def run_band(y, c, duration, rtol, max_steps, counts):
    """Carry the coin in state y (its n_z ≈ 0: the other rim has just come down) on its band
    for at most ``duration`` s (y in place): (time, reason). The reasons: :data:`DURATION`,
    :data:`LIFT_PLUS` / :data:`LIFT_MINUS` (y tilted by ±:data:`TILT` onto the rim that stays),
    :data:`ROLLING` (y the state rolling straight), :data:`BELOW_BARRIER`, :data:`STEP_FAILED`,
    :data:`NOT_BAND` (y unchanged: no band mode has both N ≥ 0). ``counts`` (4 floats):
    accepted steps, mode changes, time with a point sticking, kinetic energy removed on entry."""
    for i in range(4):
        counts[i] = 0.0
    size = 7 if y.shape[0] > 10 else 5
    q = np.zeros(size)
    d = np.array([0.0, 1.0, 0.0, 1.0])
    removed = from_state(y, c, q)
    mode = classify(q, c, d)
    if mode < 0:
        return 0.0, NOT_BAND
    counts[3] = removed
    _project(q, c, mode)
    scratch = np.empty(y.shape[0])
    k1, k2, k3, k4, k5, k6, k7, tmp, new = dp.workspace(size)
    trial = np.empty(size)
    start = np.empty(4)
    floor = np.empty(2)
    speed = max(math.sqrt(c.g * c.reach), 0.01)
    scale = (1.0, speed, speed, speed / c.reach, speed / c.reach)
    t = 0.0
    h = 1e-4
    reason = DURATION
    stalled = 0
    _rates(q, k1, c, mode, d)
    while True:
        if mode == ROLL:
            reason = ROLLING
            break
        if _below(q, c, scratch):
            reason = BELOW_BARRIER
            break
        if t >= duration:
            reason = DURATION
            break
        if counts[0] >= max_steps:
            reason = STEP_FAILED
            break
        h = min(h, rc.MAX_STEP, duration - t)
        _step_start(q, c, mode, d, start, floor)
        err = math.inf
        for _ in range(60):
            _step(q, h, c, mode, d, k1, k2, k3, k4, k5, k6, k7, tmp, new)
            err = dp.error_ratio(q, new, h, k1, k3, k4, k5, k6, k7, rtol, scale, 5)
            if err <= 1.0:
                break
            h *= max(0.2, 0.9 * err**-0.2) if err < math.inf else 0.2
        if not err <= 1.0:
            reason = STEP_FAILED
            break
        counts[0] += 1.0
        if not _crossed(_events(new, c, mode, d, start, floor)):
            t += h
            if mode != SLIDE:
                counts[2] += h
            for i in range(size):
                q[i] = new[i]
            _project(q, c, mode)
            for i in range(size):
                k1[i] = k7[i]
            h *= min(5.0, 0.9 * err**-0.2) if err > 0.0 else 5.0
            continue
        # An event within the step: bisected to its first crossing.
        lo, hi = 0.0, h
        for i in range(size):
            trial[i] = new[i]
        while hi - lo > rc.EVENT_TIME and hi - lo > 1e-15 * hi:
            mid = 0.5 * (lo + hi)
            _step(q, mid, c, mode, d, k1, k2, k3, k4, k5, k6, k7, tmp, new)
            if _crossed(_events(new, c, mode, d, start, floor)):
                hi = mid
                for i in range(size):
                    trial[i] = new[i]
            else:
                lo = mid
        ev = _events(trial, c, mode, d, start, floor)
        for i in range(size):
            q[i] = trial[i]
        t += hi
        if mode != SLIDE:
            counts[2] += hi
        counts[1] += 1.0
        # Events in a row that each advance less than STALL_TIME: a point hovering between
        # stick and slip at its cone's boundary; the caller restarts the run.
        stalled = stalled + 1 if hi < rc.STALL_TIME else 0
        if stalled > rc.STALL_EVENTS:
            reason = STEP_FAILED
            break
        if ev[0] < 0.0 or ev[1] < 0.0 or ev[2] <= 0.0:
            if ev[2] <= 0.0:
                # Painlevé: the band run ends on the rim loaded more at the step's start.
                np_, nm, _, _, _, _, _ = forces(q, c, SLIDE, d)
                lift_plus = np_ < nm
            else:
                lift_plus = ev[0] < 0.0
            # The rim that stays: a slip of its point below SLIP_FLOOR is stopped here, in the
            # band's coordinates (no rocking), not by the one-rim contact's rolling projection,
            # whose impulse at a point r below the centre would set the coin rocking back
            # towards the band at ~slip/r.
            stays = STICK_MINUS if lift_plus else STICK_PLUS
            sn, sp, sm = _slips(q, c)
            slip = sm if lift_plus else sp
            if c.friction > 0.0 and math.sqrt(sn * sn + slip * slip) <= rc.SLIP_FLOOR:
                _project(q, c, stays)
            to_state(q, c, TILT if lift_plus else -TILT, y)
            return t, LIFT_PLUS if lift_plus else LIFT_MINUS
        mode = _switch(q, c, mode, d, ev)
        _project(q, c, mode)
        _rates(q, k1, c, mode, d)
        h = max(h, 1e-7)
    to_state(q, c, 0.0, y)
    return t, reason


@njit(cache=True)
def _switch(q, c, mode, d, ev):
    """The mode after a stick or slip event (``ev`` from :func:`_events`)."""
    sn, sp, sm = _slips(q, c)
    floor = rc.SLIP_FLOOR
    if mode in (STICK_PLUS, STICK_MINUS):
        stuck_event = ev[3] < 0.0 if mode == STICK_PLUS else ev[4] < 0.0
        if stuck_event:
            # The sticking point's force has left its cone: it slips, against that force.
            _slide_from(q, c, mode, d)
            return SLIDE
        # The other point's slip (2 H |ω_z|) has stopped: both stick.
        if _feasible(q, c, ROLL, d):
            return ROLL
        return mode
    # SLIDE: a slip has stopped (or reversed): the stick test, the other point as it is.
    small_p = math.sqrt(sn * sn + sp * sp) <= floor or ev[3] < 0.0
    small_m = math.sqrt(sn * sn + sm * sm) <= floor or ev[4] < 0.0
    if small_p and small_m and _feasible(q, c, ROLL, d):
        return ROLL
    for sigma in (STICK_PLUS, STICK_MINUS):
        stopped = ev[3] < 0.0 if sigma == STICK_PLUS else ev[4] < 0.0
        if not stopped:
            continue
        if _sticks(q, c, sigma, d):
            return sigma
    return SLIDE


__all__ = [
    "ROLL",
    "SLIDE",
    "STICK_MINUS",
    "STICK_PLUS",
    "classify",
    "forces",
    "from_state",
    "run_band",
    "to_state",
]
