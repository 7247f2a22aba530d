"""The rigid, event-driven ending (core/rigid_ending.py on core/rigid_contact.py's modes):
validations against references written here, not the package's kernels.

* The rolling disc: an independent Newton–Euler integration of the no-slip thin disc (SciPy's
  solve_ivp on (n, ω), the contact force solved from the rolling constraint at each instant).
* Euler's disk: energy conserved without resistances; with rolling resistance, the time to
  go from tilt α0 to α against the Moffatt-type relation (3/2)(a/ℓ)√(a/g)(√α0 − √α).
* Convergence as the step tolerance tightens; energy never grows; the frictionless invariants.
* The straight roll on the band (angular momentum about the contact line kept, energy taken;
  the band's two-rim contact is tests/test_band_contact.py's); dead landings
  decided before any ending; the library's landings through ``Surface("table")``.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from _kernels import coin_contact
from coinflight import Coin
from coinflight.core import bounce
from coinflight.core import rigid_contact as rc
from coinflight.core import rigid_ending as re
from coinflight.core.impact import contact_point
from coinflight.core.outcome import Status

G = 9.81
DISC = Coin(radius=0.01, thickness=2e-4, mass=0.005)
NICKEL = Coin.preset("us-nickel")


def _disc(friction=1.0, rolling_resistance=0.0):
    """The ideal thin disc: no thickness (one rim, no band), I1 = m r²/4, I3 = m r²/2, on a
    table whose friction ``friction`` (1e3: no slip in practice) and rolling resistance."""
    c = coin_contact(DISC, friction=1.0)
    return c._replace(
        half_thickness=0.0,
        i1=0.25 * c.mass * c.radius**2,
        i3=0.5 * c.mass * c.radius**2,
        friction=friction,
        rolling_resistance=rolling_resistance,
    )


def _rolling_state(c, n, omega):
    """y = (z, v, n, L) of the coin touching with its lowest rim point, rolling (v = −ω × ρ)."""
    n = np.asarray(n, dtype=float)
    w = np.asarray(omega, dtype=float)
    rho = np.array(contact_point(tuple(n), c.radius, c.half_thickness, c.corner_radius))
    v = -np.cross(w, rho)
    lm = c.i1 * w + (c.i3 - c.i1) * (w @ n) * n
    return np.array([-rho[2], *v, *n, *lm])


def critical_spin(c):
    """Ω_c of a disc rolling upright: stable for Ω > Ω_c, Ω_c² = m g r I1 / (I3 (I3 + m r²))
    (Routh's criterion for the vertical rolling disc; O'Reilly 1996, Nonlinear Dyn. 10:287,
    §6; g / 3r for the thin uniform disc)."""
    m, r = c.mass, c.radius
    return math.sqrt(m * G * r * c.i1 / (c.i3 * (c.i3 + m * r * r)))


# --- the independent reference: Newton–Euler of the no-slip thin disc ------------------------


def _reference(c, n0, omega0, duration, samples, half_band=0.0):
    """n_z at ``samples`` times of the thin disc rolling without slip, from (n0, ω0): the state
    (n, ω); ṅ = ω × n; the unknowns (ω̇, F) from m a = F − m g Z, d(I ω)/dt = ρ × F and the
    rolling constraint differentiated, a = −ω̇ × ρ − ω × ρ̇, with ρ(n) = r (n_z n − Z)/√(1 − n_z²)
    − H n the lowest rim point (n_z > 0; H = ``half_band``, half the thickness of a coin with
    sharp corners, 0 for the thin disc) and ρ̇ its rate along ṅ (complex-step derivative,
    exact to rounding).
    """
    m, r, i1, i3 = c.mass, c.radius, c.i1, c.i3
    z_axis = np.array([0.0, 0.0, 1.0])

    def rho_of(n):
        return r * (n[2] * n - z_axis) / np.sqrt(1.0 - n[2] * n[2]) - half_band * n

    def skew(a):
        return np.array([[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]])

    def rhs(_t, s):
        n, w = s[:3], s[3:]
        nd = np.cross(w, n)
        rho = rho_of(n)
        step = 1e-30
        rhod = np.imag(rho_of(n + 1j * step * nd)) / step
        inertia = i1 * np.eye(3) + (i3 - i1) * np.outer(n, n)
        inertia_rate = (i3 - i1) * (np.outer(nd, n) + np.outer(n, nd))
        a = np.zeros((6, 6))
        b = np.zeros(6)
        a[:3, :3] = m * skew(rho)  # m (ρ × ω̇) − F = −m g Z + m ω × ρ̇
        a[:3, 3:] = -np.eye(3)
        b[:3] = -m * G * z_axis + m * np.cross(w, rhod)
        a[3:, :3] = inertia  # I ω̇ − ρ × F = −İ ω
        a[3:, 3:] = -skew(rho)
        b[3:] = -inertia_rate @ w
        x = np.linalg.solve(a, b)
        return np.concatenate([nd, x[:3]])

    sol = solve_ivp(
        rhs,
        (0.0, duration),
        np.concatenate([n0, omega0]),
        method="DOP853",
        rtol=1e-11,
        atol=1e-13,
        t_eval=samples,
    )
    assert sol.success
    return sol.y[2]


def _ending_tilts(c, y, samples, rtol=re.RTOL):
    """|n_z| at ``samples`` times of the ending (:func:`coinflight.core.rigid_ending.run`,
    carried on piece by piece), and whether every piece ran to its end rolling."""
    counts = np.zeros(8)
    out = [abs(y[6])]
    t = 0.0
    for s in samples[1:]:
        _, status, elapsed = re.run(y, c, rtol, s - t, counts)
        assert status == Status.UNSETTLED  # the piece's duration reached, not settled
        assert counts[7] == re.ENDED_LIMIT
        t += elapsed
        out.append(abs(y[6]))
    return np.array(out)


TILT = math.radians(2.0)
# The largest tilt from upright over 1 s of the ideal disc from 2° of tilt, as issue 27 states
# it (20°, 10.5°, 5.2°, 3.3° at 1.05, 1.2, 1.5, 2 Ω_c, rounded to 2 figures: half a unit of
# the last figure beside each); the reference below reproduces them.
STATED = {1.05: (20.0, 0.5), 1.2: (10.5, 0.05), 1.5: (5.2, 0.05), 2.0: (3.3, 0.05)}


def _upright(c, ratio):
    """n tilted 2° from the vertical plane, spinning at ratio Ω_c about its axis."""
    n = np.array([math.cos(TILT), 0.0, math.sin(TILT)])
    return n, ratio * critical_spin(c) * n


@pytest.mark.parametrize("ratio", [1.05, 1.2, 1.5, 2.0])
def test_rolling_disc_nutation_matches_newton_euler_above_the_critical_spin(ratio):
    # Above Ω_c the upright disc is stable and nutates; the largest tilt over 1 s, sampled
    # every 0.5 ms, of the ending and of the reference agree within 5 % (measured: 1e-10), and
    # the reference gives the stated values to their rounding.
    c = _disc(friction=1e3)
    n0, w0 = _upright(c, ratio)
    samples = np.linspace(0.0, 1.0, 2001)
    reference = np.degrees(np.arcsin(np.abs(_reference(c, n0, w0, 1.0, samples)).max()))
    ending = np.degrees(np.arcsin(_ending_tilts(c, _rolling_state(c, n0, w0), samples).max()))
    assert ending == pytest.approx(reference, rel=0.05)
    stated, rounding = STATED[ratio]
    assert reference == pytest.approx(stated, abs=rounding)
    assert ending > 1.5 * math.degrees(TILT)  # it nutates (a check that the test can fail)


@pytest.mark.parametrize("ratio", [1.05, 1.2, 1.5, 2.0])
def test_rolling_coin_from_state_matches_newton_euler(ratio):
    # The same through the library's public start, Landing.from_state on a rigid-ending table
    # (μ 3, no resistances) and Landing.at: a coin 0.2 mm thick (DISC: its rim's half-band
    # 0.1 mm, I1 = m (r²/4 + h²/12)) from 2° of tilt at ratio Ω_c; the largest tilt over 1 s,
    # every 0.5 ms, against the reference with that rim and those moments, within 5 %
    # (measured: 1e-11; 17.5°, 8.2°, 4.3°, 3.0°: the band's 0.1 mm holds it nearer upright).
    from scipy.spatial.transform import Rotation

    from coinflight.model.surface import Surface
    from coinflight.outcomes.table import Landing

    table = Surface("table", friction=3.0, rolling_resistance=0.0, pivoting_resistance=0.0)
    c = coin_contact(DISC, friction=3.0)
    n0, w0 = _upright(c, ratio)
    # The coin's z axis onto n0: a quarter turn about y, then the 2° tilt back about it.
    orientation = Rotation.from_euler("y", 90.0 - math.degrees(TILT), degrees=True)
    assert np.allclose(orientation.apply([0.0, 0.0, 1.0]), n0, atol=1e-15)
    rho = np.array(contact_point(tuple(n0), c.radius, c.half_thickness, c.corner_radius))
    landing = Landing.from_state(
        DISC,
        table,
        position=(0.0, 0.0, -rho[2]),
        orientation=orientation,
        velocity=-np.cross(w0, rho),
        angular_velocity=w0,
    )
    samples = np.linspace(0.0, 1.0, 2001)
    assert landing.followed_until > 1.0
    ending = np.degrees(np.arcsin(np.abs(landing.at(samples).normal[:, 2]).max()))
    reference = np.degrees(
        np.arcsin(np.abs(_reference(c, n0, w0, 1.0, samples, half_band=c.half_thickness)).max())
    )
    assert ending == pytest.approx(reference, rel=0.05)
    assert ending > 1.4 * math.degrees(TILT)  # it nutates


@pytest.mark.parametrize("ratio", [0.5, 0.8])
def test_rolling_disc_below_the_critical_spin_tilts_away_as_the_ideal_disc(ratio):
    # Below Ω_c it falls: the tilt histories of the ending and the reference over 0.4 s agree
    # within 5 % of the tilt at every 1 ms sample, and the tilt passes 30°.
    c = _disc(friction=1e3)
    n0, w0 = _upright(c, ratio)
    samples = np.linspace(0.0, 0.4, 401)
    reference = np.arcsin(np.abs(_reference(c, n0, w0, 0.4, samples)))
    ending = np.arcsin(_ending_tilts(c, _rolling_state(c, n0, w0), samples))
    assert np.all(np.abs(ending - reference) <= 0.05 * reference)
    assert reference.max() > math.radians(30.0)


def test_rolling_disc_converges_as_the_tolerance_tightens():
    # The largest tilt at 1.2 Ω_c over 1 s at the ending's tolerance and 10 times tighter:
    # changes by less than 1e-6 of it (measured 1e-10).
    c = _disc(friction=1e3)
    n0, w0 = _upright(c, 1.2)
    samples = np.linspace(0.0, 1.0, 2001)
    tilts = [
        _ending_tilts(c, _rolling_state(c, n0, w0), samples, rtol=tol).max()
        for tol in (re.RTOL, re.RTOL / 10)
    ]
    assert abs(tilts[1] - tilts[0]) < 1e-6 * tilts[0]


# --- Euler's disk ------------------------------------------------------------------------------


def _euler_disk(c, tilt, factor=1.0):
    """Steady rolling of the disc at ``tilt`` (of n from the vertical: the disc's angle to the
    table) with its centre at rest: precession Ω² = 4 g / (r sin α) (Moffatt 2000, Nature
    404:833), times ``factor`` (≠ 1: it nutates)."""
    precession = factor * math.sqrt(4.0 * G / (c.radius * math.sin(tilt)))
    n = np.array([math.sin(tilt), 0.0, math.cos(tilt)])
    omega = precession * np.array([0.0, 0.0, 1.0]) + rc.steady_spin(tilt, precession, c) * n
    return _rolling_state(c, n, omega)


def test_eulers_disk_without_resistances_keeps_its_energy_over_five_seconds():
    # Rolling without slip does no work: over 5 s (about 170 turns of precession, nutating)
    # the energy stays within 1e-6 of its start, sampled every 0.1 s, and never rises.
    c = _disc(friction=1e3)
    y = _euler_disk(c, 0.3, factor=1.02)
    e0 = rc.energy(y, c)
    energies = []
    for _ in range(50):
        run = rc.advance_rigid(y, c, 0.1, rtol=re.RTOL)
        assert (run.reason, run.mode, run.switches) == (rc.DURATION, rc.ROLLING, 0)
        energies.append(rc.energy(y, c))
    drift = np.abs(np.array(energies) - e0) / e0
    assert drift.max() < 1e-6
    assert np.diff(energies).max() <= 1e-12 * e0


@pytest.mark.parametrize(("ell", "start", "end"), [(1e-5, 0.15, 0.02), (1e-4, 0.1, 0.02)])
def test_eulers_disk_with_rolling_resistance_follows_the_moffatt_relation(ell, start, end):
    # Small tilt α of a thin disc, its centre at rest: E = (3/2) m g a α (Moffatt 2000) and the
    # rolling resistance ℓ N against ω_h = Ω α, N = m g, Ω² = 4 g/(a α), takes ℓ m g Ω α a
    # second; so √α falls at (2/3)(ℓ/a)√(g/a), and the time from α0 to α is
    # (3/2)(a/ℓ)√(a/g)(√α0 − √α) (issue 27's relation). The ending's time to first cross α,
    # within 5 %.
    c = _disc(friction=1e3, rolling_resistance=ell)
    y = _euler_disk(c, start)
    t = 0.0
    while math.acos(y[6]) > end:
        run = rc.advance_rigid(y, c, 1e-3, rtol=re.RTOL)
        assert run.reason == rc.DURATION and run.mode == rc.ROLLING
        t += run.time
    r = c.radius
    expected = 1.5 * (r / ell) * math.sqrt(r / G) * (math.sqrt(start) - math.sqrt(end))
    assert t == pytest.approx(expected, rel=0.05)


# --- landings carried on by the ending -----------------------------------------------------------


def _handed(count, **surface):
    """The states after the last impact of vigorous nickel tosses whose bounces died out
    (``benchmarks/bench_bounce.py``'s tosses, seed 2026: ωx ~ U(150, 300), ωy, ωz ~ U(−30, 30)
    rad/s, v0 ~ U(1.5, 3) m/s, 0.8 m drop), and their contact record (rigid ending; e 0.5,
    μ 0.3, the surface's default resistances 1e-4 m unless given)."""
    values = {
        "restitution": 0.5,
        "friction": 0.3,
        "rolling_resistance": 1e-4,
        "pivoting_resistance": 1e-4,
        **surface,
    }
    c = coin_contact(NICKEL, **values)
    rng = np.random.default_rng(2026)
    n = 4 * count
    omega = np.column_stack(
        [rng.uniform(150.0, 300.0, n), rng.uniform(-30.0, 30.0, n), rng.uniform(-30.0, 30.0, n)]
    )
    speed = rng.uniform(1.5, 3.0, n)
    states = []
    for k in range(n):
        out = bounce.bounce_loop(tuple(omega[k]), 1.0, speed[k], c, bounce.MAX_IMPACTS)
        if out[4] == bounce.DIED_OUT:
            z, v, m, lm = out[5:]
            states.append(np.array([z, *v, *m, *lm]))
        if len(states) == count:
            break
    assert len(states) == count
    return c, states


def test_landing_outcomes_converge_as_the_tolerance_tightens():
    # 40 hand-off states carried to rest at the ending's tolerance and 10 times tighter: every
    # one settles (none left unsettled), on the same face but for at most one (measured: 84 of
    # 84 alike at 1e-8, 1e-9 and 1e-10; a coin rolling for seconds is chaotic, and its face
    # may turn on a rounding: the face counts then move by one). Their settle times are not
    # compared (a few differ by up to 1.8 s between tolerances, for the same reason).
    c, states = _handed(40)
    faces = []
    for tol in (re.RTOL, re.RTOL / 10):
        row = []
        for y0 in states:
            face, status, _ = re.run(y0.copy(), c, tol, re.DURATION, np.zeros(8))
            assert status == Status.SETTLED_CONTACT
            row.append(face)
        faces.append(np.array(row))
    assert np.count_nonzero(faces[0] != faces[1]) <= 1


def test_energy_never_grows_through_the_ending():
    # Rolling, sliding, hops, impacts, rim changes, the band and the face: 40 hand-off states
    # carried on to rest in pieces of 10 ms; the energy (½ m v² + ½ L·ω + m g z) at the end of
    # each piece is never above that of the piece before, beyond 1e-12 of it (rounding).
    c, states = _handed(40)
    ends = set()
    for y in states:
        counts = np.zeros(8)
        before = rc.energy(y, c)
        for _ in range(4000):
            re.run(y, c, re.RTOL, 0.01, counts)
            after = rc.energy(y, c)
            assert after <= before * (1.0 + 1e-12)
            before = after
            if counts[7] != re.ENDED_LIMIT:
                ends.add(int(counts[7]))
                break
    assert re.ENDED_BARRIER in ends


def test_band_rest_keeps_the_angular_momentum_about_the_contact_line_and_takes_energy():
    # The straight roll's start (_band, once both rims' points stick) removes what is left of
    # the band run's slip, yaw and rocking by the least-energy projection onto rolling
    # straight: impulses on the contact line keep the angular momentum about it,
    # m r (n × Z)·v + L·n, and a projection takes energy, never adds it. Checked on a nickel
    # upright with some slip, yaw and rocking, more than a band run leaves (the band's ω_a
    # against that momentum over I3 + m r², within 1e-12; the energy after below that before).
    c = coin_contact(NICKEL, rolling_resistance=1e-4)
    n = np.array([0.6, 0.8, 0.0])
    w = 30.0 * n + np.array([0.0, 0.0, 2.0]) + 0.5 * np.array([0.8, -0.6, 0.0])
    rho = np.array(contact_point(tuple(n), c.radius, c.half_thickness, c.corner_radius))
    v = -np.cross(w, rho) + np.array([0.01, -0.02, 0.0])
    lm = c.i1 * w + (c.i3 - c.i1) * (w @ n) * n
    y = np.array([-rho[2], *v, *n, *lm])
    line = c.mass * c.radius * np.cross(n, [0.0, 0.0, 1.0]) @ v + lm @ n
    before = rc.energy(y, c)
    re._band(y, c, 0.0)
    spin = y[7:10] @ y[4:7] / c.i3
    assert spin == pytest.approx(line / (c.i3 + c.mass * c.radius**2), rel=1e-12)
    assert rc.energy(y, c) < before


def test_frictionless_ending_keeps_horizontal_momentum_lz_and_l_dot_n():
    # μ = 0 and no resistances: every contact force and impulse is vertical, at ρ in the plane
    # of n and Z, so the horizontal momentum, L_z and L·n are conserved through sliding, hops
    # and impacts (e 0.5); over 0.3 s in pieces of 10 ms. The momentum and L_z, linear in the
    # state, which the Runge–Kutta steps keep to rounding: within 1e-9 of their scale (measured:
    # 0 and 3e-15). L·n, quadratic, which they keep to their tolerance: within RTOL of its scale
    # (measured 1e-10 of it at RTOL 1e-9, 1.2e-8 at 1e-7: ~0.1 RTOL; a horizontal force, a
    # friction left on, would move it by ~μ of it).
    c = coin_contact(NICKEL, restitution=0.5, friction=0.0)
    n = np.array([math.sin(0.8), 0.0, math.cos(0.8)])
    w = np.array([150.0, 50.0, -40.0])  # tumbling enough to hop and bounce
    rho = np.array(contact_point(tuple(n), c.radius, c.half_thickness, c.corner_radius))
    v = np.array([0.3, 0.2, 0.0])
    v[2] = -np.cross(w, rho)[2]
    lm = c.i1 * w + (c.i3 - c.i1) * (w @ n) * n
    y = np.array([-rho[2], *v, *n, *lm])
    p0, lz0, ln0 = y[1:3].copy(), y[9], y[4:7] @ y[7:10]
    scale = np.linalg.norm(y[7:10])
    counts = np.zeros(8)
    moved = 0
    for _ in range(30):
        re.run(y, c, re.RTOL, 0.01, counts)
        moved += counts[0] + counts[1] + counts[2]
        assert np.abs(y[1:3] - p0).max() < 1e-9 * np.linalg.norm(p0)
        assert abs(y[9] - lz0) < 1e-9 * scale
        assert abs(y[4:7] @ y[7:10] - ln0) < re.RTOL * scale
    assert moved > 10  # it ran (one-rim runs, hops and impacts)


def test_coin_rolling_upright_on_its_band_settles_on_edge_and_without_resistance_rolls_on():
    # A nickel upright on its band (n horizontal), rolling straight at 0.3 m/s: both rims
    # touch; with rolling resistance ℓ it slows, (I3 + m r²) ω̇ = −ℓ m g, and ends on edge
    # once its energy is below the barrier; without resistance it rolls on: unsettled at the
    # ending's time limit, on edge.
    for ell, status in ((1e-4, Status.SETTLED_CONTACT), (0.0, Status.UNSETTLED)):
        c = coin_contact(NICKEL, rolling_resistance=ell)
        spin = 0.3 / c.radius
        y = _rolling_state(c, (1.0, 0.0, 0.0), (spin, 0.0, 0.0))
        face, got, t = re.run(y, c, re.RTOL, re.DURATION, np.zeros(8))
        assert (face, got) == (2, status)
        m, r = c.mass, c.radius
        inertia = c.i3 + m * r * r
        if ell:
            settled = math.sqrt(2.0 * (c.barrier - m * G * r) / inertia)
            assert t == pytest.approx((spin - settled) * inertia / (ell * m * G), rel=1e-9)


def test_rigid_surface_lands_tosses_to_rest():
    # Surface("table") through the library's landing (outcomes.table.land): vigorous
    # nickel tosses all end settled (by energy at an impact, or by the ending), none unsettled,
    # and the heads/tails mirror holds: the same tosses launched tails up (the coin turned
    # over, its normal reversed: the same body) end mirrored, every one (measured 60 of 60).
    from coinflight.model.surface import Surface
    from coinflight.outcomes.table import land

    rng = np.random.default_rng(5)
    omega = np.column_stack(
        [rng.uniform(150, 300, 60), rng.uniform(-30, 30, 60), rng.uniform(-30, 30, 60)]
    )
    speed = rng.uniform(1.5, 3.0, 60)
    surface = Surface("table", 0.8, 0.5, 0.3)
    heads = land(NICKEL, omega, speed, 1.0, G, surface)
    assert set(np.unique(heads.status)) <= {Status.SETTLED_ENERGY, Status.SETTLED_CONTACT}
    assert np.count_nonzero(heads.status == Status.SETTLED_CONTACT) > 10
    flipped = omega * np.array([1.0, -1.0, -1.0])
    tails = land(NICKEL, flipped, speed, -1.0, G, surface)
    mirror = np.array([1, 0, 2])[heads.face]
    assert np.array_equal(tails.face, mirror)


def test_planar_tosses_are_fair_at_rest():
    # Tosses spinning about a diameter only (ω = (ωx, 0, 0), ωx ~ U(150, 300) rad/s, v0 ~
    # U(1.5, 3) m/s, 3,000 of them, seed 11) carried to rest by the rigid ending: heads and
    # tails equally likely, |heads − tails| within 3 √(heads + tails) (3 s.d. of the difference
    # for a fair coin; measured 63 of 2,991 on seed 5, 1.2 s.d.).
    from coinflight.model.surface import Surface
    from coinflight.outcomes.table import land

    rng = np.random.default_rng(11)
    n = 3000
    omega = np.zeros((n, 3))
    omega[:, 0] = rng.uniform(150.0, 300.0, n)
    speed = rng.uniform(1.5, 3.0, n)
    out = land(NICKEL, omega, speed, 1.0, G, Surface("table", 0.8, 0.5, 0.3))
    assert not np.any(out.status == Status.UNSETTLED)
    tails, heads, _ = np.bincount(out.face, minlength=3)
    assert abs(int(heads) - int(tails)) < 3.0 * math.sqrt(heads + tails)


@pytest.mark.parametrize("ratio", [0.1, 0.577])
def test_dead_landings_are_decided_before_the_ending(ratio):
    # e = 0: the surface absorbs the coin at its first contact and the well it touches in is
    # the outcome (Yong & Mahadevan 2011's dead landing; tests/test_edge.py checks it against
    # their P = 2 arctan(h/d)/π); no landing reaches the ending, so every face is the well the
    # coin is in at its first contact, as the landing stopped there (max_bounces=0) gives it,
    # toss for toss (2·10⁴ vigorous planar tosses, simulate_edge's ranges).
    from coinflight.model.coin import Coin as _Coin
    from coinflight.model.distributions import Uniform
    from coinflight.model.surface import Surface
    from coinflight.outcomes.table import land
    from coinflight.studies.edge import SIM_LAUNCH_SPEED, SIM_SPIN

    n = 20_000
    rng = np.random.default_rng(3)
    omega = np.zeros((n, 3))
    omega[:, 0] = Uniform(*SIM_SPIN).ppf(rng.random(n))
    speed = Uniform(*SIM_LAUNCH_SPEED).ppf(rng.random(n))
    r, h = 0.012, ratio * 0.024
    coin = _Coin(radius=r, thickness=h, mass=7800.0 * np.pi * r * r * h)
    table = Surface("table", 0.5, 0.0, 0.3)
    out = land(coin, omega, speed, 1.0, G, table)
    assert set(np.unique(out.status)) <= {Status.SETTLED_ENERGY, Status.SETTLED_DEAD}
    first = land(coin, omega, speed, 1.0, G, table, max_bounces=0)
    assert np.array_equal(out.face, first.face)
    assert 0 < np.count_nonzero(out.face == 2) < n


def test_landing_from_state_runs_the_rigid_ending():
    # Landing.from_state with Surface("table"): a nickel set upright on its band, rolling
    # straight at 0.3 m/s, rests on edge at the time its rolling resistance takes to bring its
    # energy below the barrier, (I3 + m r²)(ω − ω_b)/(ℓ m g), ω_b² = 2 (barrier − m g r)/(I3 +
    # m r²) (the band's closed form, within 1e-9); a nickel dropped flat from 0.35 m lands on
    # its start face.
    from scipy.spatial.transform import Rotation

    from coinflight.model.surface import Surface
    from coinflight.outcomes.table import Landing

    table = Surface("table", restitution=0.5, friction=0.3)
    upright = Rotation.from_euler("x", 90, degrees=True)  # heads normal along −y
    n = upright.apply([0.0, 0.0, 1.0])
    r = NICKEL.radius
    spin = 0.3 / r
    omega = spin * n
    velocity = -np.cross(omega, [0.0, 0.0, -r])
    landing = Landing.from_state(
        NICKEL,
        table,
        position=(0.0, 0.0, r),
        orientation=upright,
        velocity=velocity,
        angular_velocity=omega,
    )
    out = landing.outcome
    assert (out.face_name, out.status_name) == ("edge", "settled in contact")
    c = coin_contact(NICKEL, rolling_resistance=1e-4)
    inertia = c.i3 + c.mass * r * r
    settled = math.sqrt(2.0 * (c.barrier - c.mass * G * r) / inertia)
    expected = (spin - settled) * inertia / (1e-4 * c.mass * G)
    assert float(out.settle_time) == pytest.approx(expected, rel=1e-9)
    drop = Landing.from_state(
        NICKEL,
        table,
        position=(0.0, 0.0, 0.35),
        orientation=Rotation.identity(),
        velocity=(0.0, 0.0, 0.0),
        angular_velocity=(1e-6, 0.0, 0.0),
    )
    assert drop.outcome.face_name == "heads"


def test_landing_at_follows_the_rigid_ending_to_rest():
    # Landing.at through the rigid ending: the upright nickel of the test above, rolling on its
    # band, is where the closed form puts it (x = r ∫ω dt along n × Z, ω falling at
    # ℓ m g/(I3 + m r²)) up to the time it settled (followed_until), and not after.
    from scipy.spatial.transform import Rotation

    from coinflight.model.surface import Surface
    from coinflight.outcomes.table import Landing

    table = Surface("table", restitution=0.5, friction=0.3)
    upright = Rotation.from_euler("x", 90, degrees=True)
    n = upright.apply([0.0, 0.0, 1.0])
    r = NICKEL.radius
    spin = 0.3 / r
    landing = Landing.from_state(
        NICKEL,
        table,
        position=(0.0, 0.0, r),
        orientation=upright,
        velocity=-np.cross(spin * n, [0.0, 0.0, -r]),
        angular_velocity=spin * n,
    )
    end = float(landing.outcome.settle_time)
    assert landing.followed_until == pytest.approx(end, rel=1e-12)
    c = coin_contact(NICKEL, rolling_resistance=1e-4)
    slowing = 1e-4 * c.mass * G / (c.i3 + c.mass * r * r)
    times = np.array([0.0, 0.5, 1.0, 0.9 * end])
    states = landing.at(times)
    direction = np.cross(n, [0.0, 0.0, 1.0])
    travelled = r * (spin * times - 0.5 * slowing * times**2)
    assert np.allclose(states.position[:, :2], np.outer(travelled, direction[:2]), atol=1e-9)
    assert np.allclose(states.normal, n, atol=1e-12)
    with pytest.raises(ValueError, match="at most"):
        landing.at([1.01 * end])


def test_carried_position_follows_steady_rolling_on_its_circle():
    # The one-rim contact carries the horizontal position along (y[10:12], integrated with the
    # motion): a nickel rolling steadily at tilt 0.5 rad, precessing at Ω = 8 rad/s (O'Reilly
    # 1996, §5), moves its centre of mass on a circle at constant speed |v|: after T its
    # displacement is the chord 2 (|v|/Ω) sin(Ω T/2) (within 1e-9 m).
    c = coin_contact(NICKEL, friction=2.0)
    tilt, precession = 0.5, 8.0
    n = np.array([math.sin(tilt), 0.0, math.cos(tilt)])
    omega = precession * np.array([0.0, 0.0, 1.0]) + rc.steady_spin(tilt, precession, c) * n
    y = np.append(_rolling_state(c, n, omega), [0.0, 0.0])
    speed = math.hypot(y[1], y[2])
    duration = 0.3
    run = rc.advance_rigid(y, c, duration, rtol=re.RTOL)
    assert (run.reason, run.mode) == (rc.DURATION, rc.ROLLING)
    chord = 2.0 * speed / precession * math.sin(0.5 * precession * duration)
    assert math.hypot(y[10], y[11]) == pytest.approx(chord, abs=1e-9)


def test_a_hop_stopped_at_a_time_is_the_closed_form_flight_there():
    """A hop of the ending stopped ``left`` s into its flight (a time Landing.at asks for
    inside a hop, rigid_ending.run with a duration): the time flown is ``left`` and the state
    is the closed-form flight there (bounce.fly: the ballistic centre of mass, the torque-free
    normal), the horizontal position carried; a hop given the time lands as before."""
    from coinflight.core.impact import lowest_depth

    c = coin_contact(NICKEL)
    i1, i3 = (float(x) for x in NICKEL.moments)
    n = np.array([math.sin(0.5), 0.0, math.cos(0.5)])
    w = np.array([3.0, 40.0, 5.0])
    lm = i1 * w + (i3 - i1) * (w @ n) * n
    z = lowest_depth(n[2], NICKEL.radius, 0.5 * NICKEL.thickness)
    v = (0.2, -0.1, 1.2)  # leaving the table: about 0.24 s of flight
    start = np.array([z, *v, *n, *lm, 0.01, -0.02])
    y = start.copy()
    flown, approach = re._hop(y, c, 0.05)
    assert (flown, approach) == (0.05, math.inf)
    position, velocity, normal = bounce.fly(0.05, z, (0.01, -0.02), v, tuple(n), tuple(lm), c)
    np.testing.assert_allclose(y[[10, 11, 0]], position, rtol=0, atol=1e-12)
    np.testing.assert_allclose(y[1:4], velocity, rtol=0, atol=1e-12)
    np.testing.assert_allclose(y[4:7], normal, rtol=0, atol=1e-12)
    np.testing.assert_array_equal(y[7:10], lm)
    landed = start.copy()
    flown, approach = re._hop(landed, c, math.inf)
    assert 0.05 < flown < 0.3 and approach < 0.0  # it came down onto the table
