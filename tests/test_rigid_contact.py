"""The rigid one-rim contact (core/rigid_contact.py): analytic limits, conservation laws, mode
changes, Painlevé."""

from __future__ import annotations

import math

import numpy as np
import pytest

from _kernels import coin_contact, critical_spin
from coinflight import Coin
from coinflight.core import flight
from coinflight.core import rigid_contact as rc
from coinflight.core.impact import collision_matrix, contact_point

G = 9.81
NICKEL = Coin.preset("us-nickel")


def _state(c, tilt, v=(0.0, 0.0, 0.0), omega=(0.0, 0.0, 0.0), rolling=False, azim=0.0):
    """(z, v, n, L) of a coin whose n = (sin tilt cos azim, sin tilt sin azim, cos tilt)
    touching the table with its lowest rim point, the contact point's normal velocity 0 (and,
    ``rolling``, all of it)."""
    n = np.array([math.sin(tilt) * math.cos(azim), math.sin(tilt) * math.sin(azim), math.cos(tilt)])
    w = np.asarray(omega, dtype=float)
    lm = c.i1 * w + (c.i3 - c.i1) * (w @ n) * n
    rho = np.array(contact_point(tuple(n), c.radius, c.half_thickness, c.corner_radius))
    v = np.array(v, dtype=float)
    spin = np.cross(w, rho)
    if rolling:
        v = -spin
    v[2] = -spin[2]
    return np.array([-rho[2], *v, *n, *lm])


def _steady(c, tilt, precession):
    """The steady rolling of :func:`coinflight.core.rigid_contact.steady_spin`."""
    psi = rc.steady_spin(tilt, precession, c)
    n = np.array([math.sin(tilt), 0.0, math.cos(tilt)])
    return _state(c, tilt, omega=precession * np.array([0.0, 0.0, 1.0]) + psi * n, rolling=True)


@pytest.mark.parametrize(
    ("coin", "tilt", "precession"),
    [
        (NICKEL, 0.5, 8.0),
        (NICKEL, 1.0, 10.0),
        (NICKEL, 1.2, -6.0),
        (NICKEL, 0.3, 25.0),
        (NICKEL.with_corner_radius(3e-4), 0.5, 8.0),  # rolling on a rounded rim
    ],
)
def test_steady_rolling_in_a_circle_is_a_stationary_solution(coin, tilt, precession):
    # The closed form of steady_spin (O'Reilly 1996; derived in its docstring) against the
    # integrator: over 50 ms (~1/2 to 2 turns of precession) the tilt stays within 1e-6 in n_z,
    # n precesses at Ω within 1e-6 rad, the energy within RTOL (1e-8), and it rolls throughout.
    c = coin_contact(coin, friction=2.0)
    y = _steady(c, tilt, precession)
    e0 = rc.energy(y, c)
    run = rc.advance_rigid(y, c, 0.05)
    assert (run.reason, run.mode, run.switches) == (rc.DURATION, rc.ROLLING, 0)
    assert abs(y[6] - math.cos(tilt)) < 1e-6
    turned = math.atan2(y[5], y[4])
    assert abs((turned - precession * 0.05 + math.pi) % (2 * math.pi) - math.pi) < 1e-6
    assert abs(rc.energy(y, c) - e0) < rc.RTOL * e0


def test_steady_spin_of_a_thin_disc_is_the_classical_relation():
    # The steady rolling of a thin disc in the literature's form (O'Reilly 1996, §5; Cushman,
    # Hermans & Kemppainen 1995; α the disc's angle to the table, here the tilt of n from Z):
    # (I3 + m r²) ω3 Ω sin α − I1 Ω² sin α cos α + m g r cos α = 0, ω3 = ψ' + Ω cos α the spin
    # about n. Solved for ψ' and compared.
    disc = _disc(friction=2.0)
    m, r, i1, i3 = disc.mass, disc.radius, disc.i1, disc.i3
    for tilt, omega in [(0.4, 7.0), (1.1, -12.0)]:
        s, co = math.sin(tilt), math.cos(tilt)
        w3 = (i1 * omega**2 * s * co - m * G * r * co) / ((i3 + m * r * r) * omega * s)
        expected = w3 - omega * co
        assert rc.steady_spin(tilt, omega, disc) == pytest.approx(expected, rel=1e-6)
    # Its centre fixed (ω3 = 0: ψ' = −Ω cos α, v = 0; Moffatt 2000, Nature 404:833, the end of
    # Euler's disk): Ω² = m g r / (I1 sin α) = 4 g / (r sin α) for a thin disc (I1 = m r²/4).
    for tilt in (0.3, 0.9):
        omega = math.sqrt(4.0 * G / (r * math.sin(tilt)))
        assert rc.steady_spin(tilt, omega, disc) == pytest.approx(-omega * math.cos(tilt), rel=1e-9)
        y = _steady(disc, tilt, omega)
        assert np.abs(y[1:4]).max() < 1e-12 * omega * r


DISC = Coin(radius=0.01, thickness=2e-4, mass=0.005)


def _disc(friction):
    """A disc of no thickness: the thin disc's record with its half-thickness set to 0 and I1
    to m r²/4 (one rim, no band and so no second rim to meet)."""
    c = coin_contact(DISC, friction=friction)
    return c._replace(half_thickness=0.0, i1=0.25 * c.mass * c.radius**2)


def _wobbling(c):
    """A coin rolling without slip, not steadily: the steady rolling at tilt 0.5, Ω 8 rad/s
    with its angular velocity 10 % faster (it nutates; μ 2 holds it from slipping)."""
    tilt, precession = 0.5, 8.0
    n = np.array([math.sin(tilt), 0.0, math.cos(tilt)])
    omega = precession * np.array([0.0, 0.0, 1.0]) + rc.steady_spin(tilt, precession, c) * n
    return _state(c, tilt, omega=1.1 * omega, rolling=True)


def test_rolling_without_resistance_keeps_its_energy_and_converges():
    # Rolling without slip does no work (the contact point is at rest), so the energy is an
    # integral: each step is put back on it (rigid_contact._keep_energy), and over 40 ms it
    # stays within 1e-14 of its start (rounding; measured ≤ 1.2e-16) at RTOL 1e-7, 1e-8 and
    # 1e-11. The stepper's own error shows in the motion instead: n after 40 ms within 1e-7 of
    # its value at 1e-11 at RTOL 1e-8 (measured 6.9e-9), ~10 times closer than at 1e-7
    # (6.5e-8): more than 5 times, the error falling with the tolerance.
    c = coin_contact(NICKEL, friction=2.0)
    normals = []
    for rtol in (1e-7, 1e-8, 1e-11):
        y = _wobbling(c)
        e0 = rc.energy(y, c)
        run = rc.advance_rigid(y, c, 0.04, rtol=rtol)
        assert (run.reason, run.mode, run.switches) == (rc.DURATION, rc.ROLLING, 0)
        assert abs(rc.energy(y, c) - e0) < 1e-14 * e0
        assert run.gap_drift < 1e-9 and run.speed_drift < 1e-7  # the projections' corrections
        normals.append(y[4:7].copy())
    errors = [np.abs(n - normals[2]).max() for n in normals[:2]]
    assert errors[1] < 1e-7
    assert errors[1] < errors[0] / 5


def _resistance_power(y, c):
    """F_z τ·ω, the power of the rolling and pivoting resistance torques while rolling (module
    notes: −ℓ_r F_z ω_h / sqrt(ω_h² + ω_ε²), −ℓ_p F_z ω_z / sqrt(ω_z² + ω_ε²) Z), W."""
    omega = np.array(rc.angular_velocity(tuple(y[7:10]), tuple(y[4:7]), c.i1, c.i3))
    fz = rc.rolling_force(y, c)[2]
    eps = flight.SLIP_SPEED / c.radius
    wh2, wz2 = omega[0] ** 2 + omega[1] ** 2, omega[2] ** 2
    return -fz * (
        c.rolling_resistance * wh2 / math.sqrt(wh2 + eps * eps)
        + c.pivoting_resistance * wz2 / math.sqrt(wz2 + eps * eps)
    )


def test_rolling_with_resistances_loses_the_energy_their_torques_take():
    # Rolling without slip, the contact force does no work; the resistance torques F_z τ do
    # F_z τ·ω. The wobbling coin with ℓ_r = ℓ_p = 1e-4 m over 40 ms: the energy's change
    # (0.47 % of it) equals that power integrated along the run (Simpson's rule on 160 samples,
    # its error measured 3e-10 of it; 5e-9 on 80) within RTOL of it, and the projections
    # remove below 1e-7 m/s.
    c = coin_contact(NICKEL, friction=2.0, rolling_resistance=1e-4, pivoting_resistance=1e-4)
    y = _wobbling(c)
    e0 = rc.energy(y, c)
    chunks, h = 160, 0.04 / 160
    power = [_resistance_power(y, c)]
    for _ in range(chunks):
        run = rc.advance_rigid(y, c, h)
        assert (run.reason, run.mode) == (rc.DURATION, rc.ROLLING)
        assert run.speed_drift < 1e-7
        power.append(_resistance_power(y, c))
    taken = h / 3 * (power[0] + power[-1] + 4 * sum(power[1:-1:2]) + 2 * sum(power[2:-1:2]))
    change = rc.energy(y, c) - e0
    assert change < -1e-3 * e0
    assert abs(change - taken) < rc.RTOL * abs(change)


def _largest_tilt(c, y, duration):
    """Largest n_z over ``duration`` s, every 5 ms (or until the run stops)."""
    largest = abs(y[6])
    for _ in range(round(duration / 0.005)):
        run = rc.advance_rigid(y, c, 0.005)
        largest = max(largest, abs(y[6]))
        if run.reason != rc.DURATION:
            break
    return largest


def test_thin_disc_rolling_upright_is_stable_above_the_critical_spin_and_falls_below():
    # O'Reilly 1996 (Routh): a thin disc rolling upright at spin Ω, tilted by θ from the
    # vertical, heading φ, linearised: (I1 + m r²) θ'' = m g r θ − (I3 + m r²) Ω φ' and
    # I1 φ'' = I3 Ω θ' (the gyroscopic couple). From θ(0) = θ0, θ'(0) = φ'(0) = 0:
    # φ' = (I3/I1) Ω (θ − θ0), so θ oscillates about θ_eq = θ0 Ω² / (Ω² − Ω_c²) for
    # Ω > Ω_c, Ω_c² = m g r I1 / (I3 (I3 + m r²)) (the critical spin), reaching at most
    # 2 θ_eq − θ0 = θ0 (Ω² + Ω_c²) / (Ω² − Ω_c²): 5/3 θ0 at Ω = 2 Ω_c; below Ω_c it falls.
    # Tilted 2°, rolling without slip (μ 1), over 0.3 s: at 2 Ω_c the largest tilt is 5/3 of
    # the start within 2 % (the linearisation's error at 3°, measured 0.4 %); at Ω_c / 2 it
    # falls (n_z past 0.5). (The compliant phase's test keeps a 0.2 mm thick disc within 1.1 θ0:
    # its sharp band holds it; this disc has none.)
    c = _disc(friction=1.0)
    tilt = math.radians(2.0)
    start = math.sin(tilt)
    for ratio in (2.0, 0.5):
        spin = ratio * critical_spin(DISC)
        y = _state(
            c,
            math.pi / 2 - tilt,
            omega=(spin * math.cos(tilt), 0.0, spin * math.sin(tilt)),
            rolling=True,
        )
        largest = _largest_tilt(c, y, 0.3)
        if ratio > 1.0:
            assert largest == pytest.approx(start * (ratio**2 + 1) / (ratio**2 - 1), rel=0.02)
        else:
            assert largest > 0.5


def test_frictionless_sliding_conserves_energy_horizontal_momentum_lz_and_l_dot_n():
    # μ = 0: the contact force is vertical, N Z at ρ, so the horizontal momentum is conserved;
    # its torque ρ × Z is horizontal (L_z conserved) and perpendicular to n (ρ lies in the plane
    # of n and Z), and L·(ω × n) = 0 for a symmetric top, so L·n is conserved; no work is done.
    c = coin_contact(NICKEL, friction=0.0)
    y = _state(c, 0.8, v=(0.3, 0.2, 0.0), omega=(1.0, -1.0, 8.0))
    e0, p0, lz0, ln0 = rc.energy(y, c), y[1:3].copy(), y[9], y[4:7] @ y[7:10]
    run = rc.advance_rigid(y, c, 0.03)
    assert (run.reason, run.mode) == (rc.DURATION, rc.SLIDING)
    assert abs(rc.energy(y, c) - e0) < rc.RTOL * e0
    assert np.abs(y[1:3] - p0).max() < 1e-12
    assert abs(y[9] - lz0) < 1e-12 * abs(lz0)
    assert abs(y[4:7] @ y[7:10] - ln0) < rc.RTOL * np.linalg.norm(y[7:10])


def test_planar_coulomb_sliding_decelerates_by_mu_times_the_normal_impulse():
    # A coin sliding in the plane of n and Z, not spinning out of it, stays in that plane and
    # slides along x: m Δv_x = −μ ∫N dt and m Δv_z = ∫N dt − m g t, so
    # v_x(t) = v_x(0) − μ (g t + v_z(t) − v_z(0)) exactly (Coulomb): μ g for a coin whose
    # centre's height would not change (this one, leaning 0.35 rad, falls towards its face).
    mu = 0.3
    c = coin_contact(NICKEL, friction=mu)
    y = _state(c, 0.35, v=(0.6, 0.0, 0.0))
    vx0, vz0 = y[1], y[3]
    t = 0.0
    for _ in range(4):  # 20 ms (it falls flat, the face event, at ~30 ms)
        run = rc.advance_rigid(y, c, 0.005)
        assert (run.reason, run.mode) == (rc.DURATION, rc.SLIDING)
        t += run.time
        assert y[1] == pytest.approx(vx0 - mu * (G * t + y[3] - vz0), abs=1e-9)
        assert abs(y[2]) < 1e-12 and abs(y[7]) < 1e-15 and abs(y[9]) < 1e-15


def test_a_slide_comes_to_rolling_and_the_contact_point_stops():
    # A steep coin (n 0.9 rad from Z) sliding at 0.1 m/s in the plane of n and Z with μ 1:
    # friction stops the slip within a few ms (an event), the stick test holds, and it rolls
    # on with its contact point at rest.
    c = coin_contact(NICKEL, friction=1.0)
    y = _state(c, 0.9, v=(0.1, 0.0, 0.0))
    run = rc.advance_rigid(y, c, 0.05)
    assert (run.mode, run.reason, run.switches) == (rc.ROLLING, rc.DURATION, 1)
    assert 0.04 < run.rolling_time < 0.05
    _, _, _, _, _, u = rc.constraint_terms(y, c)
    assert np.abs(u).max() < 1e-7


def test_rolling_coin_starts_to_slip_when_its_force_reaches_the_cone():
    # A nickel leaning 1.2 rad, rolling and spinning (ω = (5, 20, 30) rad/s, n's azimuth 0.7),
    # μ 2, resistances 1e-4 m: its rolling force reaches μ F_z at t = 0.0442192726 s, the
    # crossing found by an independent derivation of the rolling equations integrated by
    # scipy's DOP853 at rtol 1e-11 with the cone as its event (review of 2026-11-24). Here:
    # the force stays in the cone, checked every 1 ms while rolling, and the slip starts
    # (ROLLING to SLIDING) at that time within 1e-8 s.
    c = coin_contact(NICKEL, friction=2.0, rolling_resistance=1e-4, pivoting_resistance=1e-4)
    y = _state(c, 1.2, omega=(5.0, 20.0, 30.0), rolling=True, azim=0.7)
    rolled = 0.0
    for _ in range(50):
        f = rc.rolling_force(y, c)
        assert math.hypot(f[0], f[1]) <= c.friction * f[2]
        run = rc.advance_rigid(y, c, 1e-3)
        rolled += run.rolling_time
        if run.mode != rc.ROLLING:
            break
    assert (run.mode, run.switches) == (rc.SLIDING, 1)
    assert rolled == pytest.approx(0.0442192726, abs=1e-8)


def test_slip_starts_along_the_ray_where_it_grows():
    # A stuck contact the cone cannot hold slides along ŝ with u̇_h = λ ŝ, λ > 0 (the ray;
    # Batlle 1996, Le Saux, Leine & Glocker 2005 §4): at ŝ = slip_start, the sliding force
    # F = N (Z − μ ŝ) gives u̇ = W' F + b₀ whose horizontal part is parallel to ŝ and along it.
    # Rolling states drawn at random (seed 1), those outside the cone; in 3-D with resistances
    # the ray is off the stick force's opposite (slip_start's first guess) by up to degrees,
    # so its iteration on N(ŝ) is what is tested.
    rng = np.random.default_rng(1)
    off = []
    for _ in range(40):
        mu = rng.uniform(0.1, 0.8)
        c = coin_contact(NICKEL, friction=mu, rolling_resistance=1e-4, pivoting_resistance=1e-4)
        tilt, omega, azim = rng.uniform(0.3, 1.5), rng.normal(0, 30, 3), rng.uniform(0, 6)
        y = _state(c, tilt, omega=omega, rolling=True, azim=azim)
        f = rc.rolling_force(y, c)
        if f[2] <= 0 or math.hypot(f[0], f[1]) <= mu * f[2]:
            continue
        s = np.array(rc.slip_start(y, c))
        w, b, *_ = rc.constraint_terms(y, c)
        force, coef = rc.sliding_force(y, c, s[0], s[1])
        assert coef > 0.0 and force[2] > 0.0
        u_dot = np.array(w).reshape(3, 3) @ np.array(force) + np.array(b)
        size = math.hypot(u_dot[0], u_dot[1])
        assert abs(u_dot[0] * s[1] - u_dot[1] * s[0]) < 1e-9 * size
        assert u_dot[:2] @ s > 0.0
        guess = -np.array(f[:2]) / math.hypot(f[0], f[1])
        off.append(math.degrees(math.acos(min(1.0, guess @ s))))
    assert len(off) >= 5 and max(off) > 1.0


def test_friction_on_a_small_slip_never_does_positive_work():
    # Below SLIP_FLOOR a slip the cone cannot stop slides along the ray (SLIP_FLOOR's notes),
    # but not when the slip points against it: the friction there opposes the slip. A steady
    # rolling state outside the cone (μ 1, as in the test below) given slips of 5 μm/s at angles
    # round the ray: the sliding force's power on the slip, F_h·u_h, is never positive.
    c = coin_contact(NICKEL, friction=1.0)
    base = _steady(c, 0.5, 8.0)
    ray = np.array(rc.slip_start(base, c))
    for angle in np.linspace(0.0, 2.0 * math.pi, 13)[:-1]:
        y = base.copy()
        turn = np.array([[math.cos(angle), -math.sin(angle)], [math.sin(angle), math.cos(angle)]])
        y[1:3] += 5e-6 * turn @ ray  # the centre's velocity moves the contact point's alike
        _, _, _, _, _, u = rc.constraint_terms(y, c)
        f, coef, _, _ = rc._force(y, c, rc.SLIDING, 0.0, 0.0, 1.0 if y[6] >= 0.0 else -1.0)
        assert coef > 0.0 and f[2] > 0.0
        assert f[0] * u[0] + f[1] * u[1] <= 0.0


def test_a_slide_the_cone_cannot_stop_reverses():
    # A nickel leaning 0.9 rad sliding at 0.01 m/s in the plane of n and Z, μ 0.5: the slip
    # along +x falls to 0 at ~47.6 ms, where the rolling force lies outside the cone (the stick
    # test fails): it slides on, the other way. Planar Coulomb sliding along ±x gives
    # m Δv_x = ∓μ ∫N dt, m Δv_z = ∫N dt − m g Δt, so Δv_x = ∓μ (g Δt + Δv_z) over each ms
    # (the slip's sign at its start), and it never rolls; two switches (the stop below
    # SLIP_FLOOR, where the stick test fails, then the reversal itself).
    mu = 0.5
    c = coin_contact(NICKEL, friction=mu)
    y = _state(c, 0.9, v=(0.01, 0.0, 0.0))
    switches = 0
    for k in range(50):
        before = y.copy()
        _, _, _, _, _, u = rc.constraint_terms(y, c)
        run = rc.advance_rigid(y, c, 1e-3)
        assert (run.mode, run.reason, run.rolling_time) == (rc.SLIDING, rc.DURATION, 0.0)
        switches += run.switches
        if run.switches == 0:
            sign = 1.0 if u[0] > 0.0 else -1.0
            expected = before[1] - sign * mu * (G * 1e-3 + y[3] - before[3])
            assert y[1] == pytest.approx(expected, abs=1e-9)
        else:
            assert k == 47  # the reversal, in the 48th ms
    _, _, _, _, _, u = rc.constraint_terms(y, c)
    assert switches == 2 and u[0] < -1e-3


def test_rolling_that_needs_more_than_mu_n_slides():
    # The steady rolling of the first test at μ 2 needs |F_h| = m Ω |v| (Ω 8 rad/s, tilt 0.5),
    # 1.03 μ N at μ = 1: started rolling, the stick test fails and it slides from the start.
    c = coin_contact(NICKEL, friction=1.0)
    y = _steady(c, 0.5, 8.0)
    f = rc.rolling_force(y, c)
    assert math.hypot(f[0], f[1]) > c.friction * f[2]
    run = rc.advance_rigid(y, c, 0.01)
    assert run.mode == rc.SLIDING and run.rolling_time == 0.0


def test_fast_tumbling_steep_coin_lifts_off():
    # A coin leaning 1.2 rad from flat, tumbling about y with its contact point at rest: at
    # 60 rad/s the centripetal acceleration of the contact point (~ω² ρ ≈ 40 g) exceeds g,
    # the normal force needed is negative and the run stops at once (lift-off, FREE); at
    # 5 rad/s it rolls.
    c = coin_contact(NICKEL, friction=0.5)
    fast = _state(c, 1.2, omega=(0.0, 60.0, 0.0), rolling=True)
    assert rc.rolling_force(fast, c)[2] < 0.0
    run = rc.advance_rigid(fast, c, 0.01)
    assert (run.time, run.mode, run.reason) == (0.0, rc.FREE, rc.LIFT_OFF)
    slow = _state(c, 1.2, omega=(0.0, 5.0, 0.0), rolling=True)
    run = rc.advance_rigid(slow, c, 0.005)
    assert (run.mode, run.reason) == (rc.ROLLING, rc.DURATION)


def test_painleve_paradox_is_detected_and_not_integrated():
    # Painlevé: sliding with c_N = K_zz − μ K_zx ŝ_x ≤ 0. For a nickel leaning at 1.05 rad the
    # collision matrix (core/impact.py) gives K_zz / K_zx ≈ 1.12: sliding in +x with μ 1.5 is
    # inconsistent (reported at once), with μ 0.9 it slides.
    tilt = 1.05
    n = (math.sin(tilt), 0.0, math.cos(tilt))
    k = collision_matrix(
        contact_point(n, NICKEL.radius, NICKEL.thickness / 2),
        n,
        NICKEL.mass,
        *(float(x) for x in NICKEL.moments),
    )
    assert 1.0 < k[5] / k[2] < 1.25
    for mu, reason in ((1.5, rc.PAINLEVE), (0.9, rc.DURATION)):
        c = coin_contact(NICKEL, friction=mu)
        y = _state(c, tilt, v=(0.5, 0.0, 0.0))
        run = rc.advance_rigid(y, c, 1e-3)
        assert run.reason == reason


def test_a_state_approaching_the_table_needs_an_impact_first():
    c = coin_contact(NICKEL, friction=0.3)
    y = _state(c, 0.5)
    y[3] = -0.1
    before = y.copy()
    run = rc.advance_rigid(y, c, 0.01)
    assert (run.time, run.reason) == (0.0, rc.NOT_IN_CONTACT)
    assert np.array_equal(y[1:], before[1:])


def test_settle_stops_when_the_energy_falls_below_the_barrier():
    # A nickel rolling steadily at tilt 0.8, Ω 12 rad/s (μ 2), resistances 1e-3 m: its energy
    # starts above the barrier m g ρ (the contact phase's ending) and the resistances take it
    # below in ~0.35 s: the run stops at the first accepted step below it, and the step before
    # it is above (the same run one step short).
    c = coin_contact(NICKEL, friction=2.0, rolling_resistance=1e-3, pivoting_resistance=1e-3)
    y = _steady(c, 0.8, 12.0)
    start = y.copy()
    assert rc.energy(y, c) > 2.0 * c.barrier
    run = rc.advance_rigid(y, c, 1.0, settle=True)
    assert run.reason == rc.BELOW_BARRIER and 0.1 < run.time < 1.0
    assert rc.energy(y, c) < c.barrier
    before = rc.advance_rigid(start, c, 1.0, settle=True, max_steps=run.steps - 1)
    assert before.reason == rc.MAX_STEPS_REACHED
    assert rc.energy(start, c) >= c.barrier


def test_settle_stops_below_the_barrier():
    # A slowly rolling coin with resistances: its energy is below m g ρ from the start.
    c = coin_contact(NICKEL, friction=0.5, rolling_resistance=1e-4, pivoting_resistance=1e-4)
    y = _state(c, 0.3, omega=(0.0, 0.0, 3.0), rolling=True)
    assert rc.energy(y, c) < c.barrier
    assert rc.advance_rigid(y, c, 0.01, settle=True).reason == rc.BELOW_BARRIER
    y = _state(c, 0.3, omega=(0.0, 0.0, 3.0), rolling=True)
    assert rc.advance_rigid(y, c, 0.01).reason == rc.DURATION


def test_hand_off_states_run_without_energy_gain_or_failure():
    # The states the bounces hand to the ending (vigorous nickel tosses, e 0.5, μ 0.3,
    # resistances 1e-4 m, as benchmarks/bench_rigid.py draws them): each put on the rigid
    # contact (its rebound of at most rest_speed removed) and run up to 0.3 s with the energy
    # ending. Nothing here adds energy (friction and the resistances take it; the projections
    # and the stick impulses remove a little): the energy at the end is at most the start's
    # (plus 1e-9 of it), and no run fails its steps or runs out of them (the hand-off states
    # include fast tumbling coins nearly flat, which once divided by zero).
    from coinflight.core import bounce

    c = coin_contact(NICKEL, friction=0.3, rolling_resistance=1e-4, pivoting_resistance=1e-4)
    rng = np.random.default_rng(7)
    omega = np.column_stack(
        [rng.uniform(150, 300, 60), rng.uniform(-30, 30, 60), rng.uniform(-30, 30, 60)]
    )
    v0 = rng.uniform(1.5, 3.0, 60)
    reasons = set()
    runs = 0
    for k in range(60):
        *_, status, z, v, n, lm = bounce.bounce_loop(
            tuple(omega[k]), 1.0, v0[k], c, bounce.MAX_IMPACTS
        )
        if status != bounce.DIED_OUT:
            continue
        y = np.array([z, *v, *n, *lm])
        if rc.advance_rigid(y, c, 0.0, approach=c.rest_speed).reason != rc.DURATION:
            continue
        e0 = rc.energy(y, c)
        run = rc.advance_rigid(y, c, 0.3, settle=True)
        runs += 1
        reasons.add(run.reason)
        assert rc.energy(y, c) <= e0 * (1.0 + 1e-9)
        assert run.reason not in (rc.STEP_FAILED, rc.MAX_STEPS_REACHED)
    assert runs >= 30 and len(reasons) >= 3


@pytest.mark.parametrize("rate", [2.0, 5.0, 10.0])
def test_coin_tipping_to_upright_stops_when_the_other_rim_touches(rate):
    # A nickel leaning 1.45 rad from flat, rolling (μ 1) as it tips towards upright at
    # ``rate`` rad/s: its other rim reaches the table when n_z crosses 0 (the band contact,
    # not built): the run stops there, located within 1e-10 of n_z = 0. Rolling without
    # resistances does no work: the energy is kept (within 1e-6 of it: the stepper's, measured
    # 2.6e-8..8.9e-8 over these ~20 steps at RTOL 1e-8), and the state is left on the
    # first rim (its gap and normal speed ~0), not put on the other rim by an impulse there
    # (which took 1.7e-4..1.7e-3 of the energy once), whose normal speed is the flow's.
    # The run keeps its rim past n_z = 0, so no trial step straddling the crossing sees a jump
    # in the force: at most 2 rejected steps (measured 0; 30-33 when the lower rim's point was
    # taken at every stage), and the crossing is located in at most 15 trial steps (measured
    # 8-11 by regula falsi; 21-22 by bisection).
    c = coin_contact(NICKEL, friction=1.0)
    y = _state(c, 1.45, omega=(0.0, rate, 0.0), rolling=True)
    e0 = rc.energy(y, c)
    run = rc.advance_rigid(y, c, 0.2)
    assert run.reason == rc.SECOND_RIM and 0.0 < run.time < 0.2
    assert run.rejected <= 2 and run.event_steps <= 15
    assert abs(y[6]) < 1e-10
    assert abs(rc.energy(y, c) - e0) < 1e-6 * e0
    assert run.speed_drift < 1e-7
    n = y[4:7]
    omega = np.array(rc.angular_velocity(tuple(y[7:10]), tuple(n), c.i1, c.i3))
    w_hat = (n[2] * n - np.array([0.0, 0.0, 1.0])) / math.sqrt(1.0 - n[2] ** 2)
    first = c.radius * w_hat - c.half_thickness * n  # the rim it rolled on (n_z > 0 at start)
    other = c.radius * w_hat + c.half_thickness * n
    assert abs(y[0] + first[2]) < 1e-10
    assert abs(y[3] + np.cross(omega, first)[2]) < 1e-7
    # The other rim closes at the tipping speed (ġ = v_z + (ω × ρ)_z, ~rate h), not stopped.
    assert y[3] + np.cross(omega, other)[2] < -0.1 * rate * c.half_thickness


@pytest.mark.parametrize("tilt", [0.2, 0.5])
def test_coin_falling_flat_stops_when_its_face_comes_down(tilt):
    # A nickel at rest leaning on its rim falls towards its face; the run stops at
    # s = FACE_SINE (located within 1e-10, in at most 20 trial steps: measured 14-15 by regula
    # falsi, 55-56 by bisection), before the face's slap (not built).
    c = coin_contact(NICKEL, friction=1.0)
    y = _state(c, tilt)
    run = rc.advance_rigid(y, c, 1.0)
    assert run.reason == rc.FACE and 0.0 < run.time < 1.0
    assert run.event_steps <= 20
    assert math.sqrt(1.0 - y[6] ** 2) == pytest.approx(rc.FACE_SINE, abs=1e-10)


def test_a_slide_that_friction_stops_sticks_at_a_loose_tolerance():
    # A nickel sliding on its rim, spinning at 112 rad/s about the vertical, its slip 10 mm/s
    # (the state 1.6 s into the rigid ending of a human toss; μ 0.3, resistances 1e-4 m): over
    # the next 0.3 s friction stops its slip, and it sticks and slips again at the cone's
    # boundary, rolling 0.14305 s of them at RTOL 1e-9. At 1e-5 the steps' error in the slip,
    # were it left to the tolerance alone, reaches SLIP_FLOOR: a slip that friction has stopped
    # would hover above the floor on that error, sliding on (rolling 0.011 s, measured before
    # the slip's own error bound). Held below SLIP_ERROR, it is followed down to the stick: the
    # rolling time within 2 % of 1e-9's (measured 1.2 %), and at 1e-7 within 1e-4 (2e-5).
    c = coin_contact(NICKEL, friction=0.3, rolling_resistance=1e-4, pivoting_resistance=1e-4)
    start = np.array(
        [
            1.0623688660938260e-02,
            4.4132162119864572e-02,
            -5.1537521713186839e-02,
            9.3582236559775118e-04,
            9.1675902553557498e-01,
            3.6559324328693710e-01,
            1.6091758624215555e-01,
            1.6230093659677345e-06,
            8.3969257126256987e-07,
            1.6287760074119476e-05,
        ]
    )
    rolled = {}
    for rtol in (1e-9, 1e-7, 1e-5):
        run = rc.advance_rigid(start.copy(), c, 0.3, rtol=rtol)
        assert run.reason == rc.DURATION
        rolled[rtol] = run.rolling_time
    assert 0.1 < rolled[1e-9] < 0.2
    assert rolled[1e-7] == pytest.approx(rolled[1e-9], rel=1e-4)
    assert rolled[1e-5] == pytest.approx(rolled[1e-9], rel=0.02)


@pytest.mark.parametrize("friction", [0.1, 0.3])
def test_a_slides_dissipation_converges_under_the_energy_projection(friction):
    # A nickel at tilt 0.5 sliding at 0.5 m/s and spinning at 30 rad/s (resistances 1e-4 m) for
    # 50 ms: Coulomb friction takes 5 % (μ 0.1, to the face event) or 43 % (μ 0.3) of its
    # energy. Each step is put on the energy less the quadrature of the friction's and the
    # resistances' work (rigid_contact._keep_energy), which must neither add nor remove
    # dissipation: the energy at the end converges to its value at RTOL 1e-11 as the
    # tolerance tightens, within 1e-6 of the start's at 1e-7 (measured 1.4e-7 and 5.9e-9) and
    # 1e-8 at 1e-9 (8.6e-10 and 8.0e-11).
    c = coin_contact(NICKEL, friction=friction, rolling_resistance=1e-4, pivoting_resistance=1e-4)
    start = _state(c, 0.5, v=(0.5, 0.0, 0.0), omega=(0.0, 0.0, 30.0))
    e0 = rc.energy(start, c)
    ends = {}
    for rtol in (1e-11, 1e-9, 1e-7):
        y = start.copy()
        run = rc.advance_rigid(y, c, 0.05, rtol=rtol)
        assert run.mode == rc.SLIDING and run.switches == 0
        ends[rtol] = rc.energy(y, c)
    assert e0 - ends[1e-11] > 0.05 * e0
    assert abs(ends[1e-7] - ends[1e-11]) < 1e-6 * e0
    assert abs(ends[1e-9] - ends[1e-11]) < 1e-8 * e0
