"""Simultaneous impacts: a coin meeting the table nearly flat (or upright) strikes it with two
rim points at once, not in sequence (core.impact.simultaneous_point).

Sequential rigid impacts at the two ends of a flat coin set it spinning and turn it over (the
falling-rod paradox; Stoianovici & Hurmuzlu 1996, J. Appl. Mech. 63:307, measure that the
sequential rigid law fails there). Physically the two contacts are one impact: a coin dropped
flat bounces flat, at e times its approach speed (Newton's and Stronge's laws agree on a
frictionless central impact: Stronge, *Impact Mechanics*, 2000, §4.2), and lands on its start
face. The checks below: flat drops over every preset, e and μ; the rebound of one flat impact;
the frictionless two-point impact against an independent Newton LCP solved here with NumPy
(Pfeiffer & Glocker, *Multibody Dynamics with Unilateral Contacts*, 1996); the heads/tails
mirror; continuity in the tilt; energy never made.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from _kernels import impact_record
from coinflight import Coin
from coinflight.core import bounce, impact
from coinflight.core.outcome import Status
from coinflight.model.coin import PRESETS
from coinflight.model.surface import CONTACT_DURATION, Surface
from coinflight.outcomes.table import Landing, contact_record, land

G = 9.81
NICKEL = Coin.preset("us-nickel")
I1, I3 = NICKEL.moments
R, HH, M = NICKEL.radius, 0.5 * NICKEL.thickness, NICKEL.mass
T_C = impact.CONTACT_DURATION


def _lm(n, w, i1=I1, i3=I3):
    """L = I ω for the lab angular velocity ω: I = I1 + (I3 − I1) n nᵀ."""
    n = np.asarray(n, dtype=float)
    w = np.asarray(w, dtype=float)
    return tuple(float(x) for x in i1 * w + (i3 - i1) * float(w @ n) * n)


def _tilted(theta, azimuth=0.0):
    """Heads normal tilted by theta from +z towards the azimuth (rad)."""
    s = math.sin(theta)
    return (s * math.cos(azimuth), s * math.sin(azimuth), math.cos(theta))


# --- flat drops -----------------------------------------------------------------------------

HEIGHTS = (0.05, 0.35)
SPIN = 1e-6  # rad/s at most: "released flat"


def test_released_flat_means_every_impact_within_a_contact_duration():
    # The precondition of the flat-drop test, made explicit: a spin of at most SPIN turns the
    # coin by at most SPIN × (the whole landing's time) — the fall and a geometric series of
    # bounces, 2 e V / (g (1 − e)) — which stays below the tilt at which the slowest impact
    # (at the rest speed) still closes its second contact within half a contact duration,
    # (rest speed) t_c / 4r, for the largest preset. (A second point closes at least at the
    # approach speed; the impact at one end only speeds it.)
    e = 0.9
    speed = math.sqrt(2 * G * max(HEIGHTS))
    duration = math.sqrt(2 * max(HEIGHTS) / G) + 2 * e * speed / (G * (1 - e))
    largest = max(coin.radius for coin in PRESETS.values())
    assert SPIN * duration < bounce.REST_SPEED * T_C / (4 * largest)


@pytest.mark.parametrize("name", sorted(PRESETS))
def test_a_coin_released_flat_lands_on_its_start_face(name):
    """Every preset, e over [0, 0.9], μ over [0, 1] and the contact duration t_c over its
    whole range, 1 μs to 10 ms (per toss, with both ends), both start faces, two drop
    heights: the coin lands on the face it started on. A toss's spin is at most SPIN t_c /
    T_C, so that the precondition above holds for its own t_c (the tilt that closes the
    second contact within half a contact grows as t_c). Before the simultaneous impact a third
    of such drops landed on the other face (a nickel from 0.35 m at e 0.45: all of them)."""
    coin = Coin.preset(name)
    rng = np.random.default_rng(sum(map(ord, name)))
    n = 64
    e = np.concatenate([[0.0, 0.9, 0.0, 0.9, 0.2, 0.45], rng.uniform(0.0, 0.9, n - 6)])
    mu = np.concatenate([[0.0, 0.0, 1.0, 1.0, 0.3, 0.3], rng.uniform(0.0, 1.0, n - 6)])
    low, high = CONTACT_DURATION.low, CONTACT_DURATION.high
    t_c = np.concatenate(
        [[low, high, high, low, T_C, T_C], 10 ** rng.uniform(np.log10(low), np.log10(high), n - 6)]
    )
    w = rng.normal(size=(n, 3))
    w *= (SPIN * t_c / T_C * rng.uniform(0.0, 1.0, n) / np.linalg.norm(w, axis=1))[:, None]
    for height, sign in itertools.product(HEIGHTS, (1.0, -1.0)):
        table = Surface("table", drop_height=height)
        out = land(
            coin,
            w,
            np.zeros(n),
            sign,
            G,
            table,
            contact={"restitution": e, "friction": mu, "contact_duration": t_c},
        )
        start = 1 if sign > 0 else 0
        wrong = np.flatnonzero(out.face != start)
        assert wrong.size == 0, (height, sign, e[wrong], mu[wrong], t_c[wrong])


@pytest.mark.parametrize("name", sorted(PRESETS))
def test_a_flat_impact_bounces_flat(name):
    """One impact of a coin meeting the table flat to within a small fraction of what a
    contact duration separates, with no horizontal velocity: its centre of mass rebounds at
    e times the approach speed, and no spin is made (Stronge 2000 §4.2: a central impact)."""
    coin = Coin.preset(name)
    i1, i3 = coin.moments
    r = coin.radius
    rng = np.random.default_rng(7 + len(name))
    for _ in range(200):
        speed = rng.uniform(0.3, 5.0)
        e, mu = rng.uniform(0.0, 0.9), rng.uniform(0.0, 1.0)
        theta = rng.uniform(0.0, 0.05) * speed * T_C / (4 * r)
        n = _tilted(theta, rng.uniform(0, 2 * math.pi))
        if rng.uniform() < 0.5:
            n = tuple(-x for x in n)  # tails down
        w = rng.normal(size=3)
        w *= rng.uniform(0.0, 1e-4) * speed / r / np.linalg.norm(w)
        lm = _lm(n, w, i1, i3)
        v2, lm2, rebound = impact.impact(
            (0.0, 0.0, -speed), lm, n, impact_record(coin, e, mu, corner_radius=coin.corner_radius)
        )
        assert v2[2] == pytest.approx(e * speed, rel=1e-3, abs=1e-9 * speed)
        assert math.hypot(v2[0], v2[1]) <= 1e-3 * speed
        spin = np.linalg.norm(impact.angular_velocity(lm2, n, i1, i3))
        # No spin made: at most what it had (a tilt rate is restituted, times e), within a
        # rounding-size allowance.
        assert spin <= np.linalg.norm(w) * (1 + 1e-9) + 1e-9 * speed / r
        assert rebound >= 0.0


def test_without_spin_a_flat_impact_is_central_to_rounding():
    # No spin, a tilt inside full simultaneity: the impulse passes below the centre of mass.
    for e, mu in ((0.0, 0.0), (0.45, 0.3), (0.9, 1.0)):
        for theta in (0.0, 1e-12, 1e-9, 1e-6, 1e-4, 1e-3):
            n = _tilted(theta, 0.3)
            v2, lm2, rebound = impact.impact(
                (0.0, 0.0, -2.6), (0.0,) * 3, n, impact_record(NICKEL, e, mu)
            )
            assert v2[2] == pytest.approx(2.6 * e, rel=1e-12, abs=1e-12)
            # Spin made: below 1e-9 V/r (the impulse's moment about the centre of mass is
            # 1e-11 of m V r, the lever the sequential law gives it).
            spin = np.abs(impact.angular_velocity(lm2, n, I1, I3)).max()
            assert spin <= 1e-9 * 2.6 / R
            assert rebound == pytest.approx(2.6 * e, rel=1e-9, abs=1e-12)


# --- the law --------------------------------------------------------------------------------


def _newton_lcp(rc_a, rc_b, n, v, lm, e):
    """The two-point frictionless Newton impact solved independently (NumPy): generalised
    velocity q = (v, ω), mass matrix diag(m, m, m, I_lab), normal Jacobians J_i q =
    v_z + (ω × r_i)_z; find p ≥ 0 with ξ = J q⁺ + e J q⁻ ≥ 0, p·ξ = 0 by trying the four
    active sets; returns the normal velocities of the two points after."""
    n = np.asarray(n)
    inertia = I1 * np.eye(3) + (I3 - I1) * np.outer(n, n)
    mass = np.zeros((6, 6))
    mass[:3, :3] = M * np.eye(3)
    mass[3:, 3:] = inertia
    jac = np.array([np.r_[0, 0, 1, np.cross(r, [0, 0, 1])] for r in (rc_a, rc_b)])
    q = np.r_[v, np.linalg.solve(inertia, lm)]
    delassus = jac @ np.linalg.solve(mass, jac.T)
    u = jac @ q
    for active in ([0, 1], [0], [1], []):
        p = np.zeros(2)
        if active:
            sub = np.ix_(active, active)
            p[active] = np.linalg.solve(delassus[sub], -(1 + e) * u[active])
        after = u + delassus @ p
        if np.all(p >= -1e-15) and np.all(after + e * u >= -1e-12):
            return after
    raise AssertionError("no LCP solution")


@settings(max_examples=200, deadline=None)
@given(
    theta=st.floats(1e-4, 1.0),
    azimuth=st.floats(0.0, 2 * math.pi),
    rate=st.tuples(st.floats(-1.0, 1.0), st.floats(-1.0, 1.0)),
    speed=st.floats(0.5, 5.0),
    e=st.floats(0.0, 1.0),
)
def test_frictionless_flat_impact_is_the_two_point_newton_impact(theta, azimuth, rate, speed, e):
    """μ = 0, both ends of the lowest diameter approaching, fully simultaneous: both leave
    with the normal velocities of the independent two-point Newton LCP (the impulse at the
    centre of the two normal impulses is the same wrench)."""
    # Well inside full simultaneity, and tilted (a tilt below ~1e-7 rad is flat to rounding).
    n = _tilted(theta * speed * T_C / (8 * R), azimuth)
    # A tilt rate about the horizontal axis across the lowest diameter, up to 0.2 V/r.
    axis = np.cross([0, 0, 1], [math.cos(azimuth), math.sin(azimuth), 0])
    w = 0.2 * speed / R * (rate[0] * axis + 0.1 * rate[1] * np.array([0, 0, 1]))
    v = (0.0, 0.0, -speed)
    lm = _lm(n, w)
    rc_a = np.array(impact.contact_point(n, R, HH))  # r ŵ − (h/2) n
    rc_b = -rc_a - 2 * HH * np.array(n)  # −r ŵ − (h/2) n: the other end of the diameter
    omega = np.array(impact.angular_velocity(lm, n, I1, I3))
    u = [v[2] + np.cross(omega, r)[2] for r in (rc_a, rc_b)]
    if max(u) >= 0.0:
        return
    expected = _newton_lcp(rc_a, rc_b, n, v, lm, e)
    v2, lm2, _ = impact.impact(v, lm, n, impact_record(NICKEL, e, 0.0))
    omega2 = np.array(impact.angular_velocity(lm2, n, I1, I3))
    got = [v2[2] + np.cross(omega2, r)[2] for r in (rc_a, rc_b)]
    np.testing.assert_allclose(got, expected, atol=1e-9 * speed)


def test_far_from_flat_it_is_the_single_impact_bit_for_bit():
    rng = np.random.default_rng(3)
    for _ in range(500):
        theta = rng.uniform(0.3, math.pi / 2 - 0.3)
        n = _tilted(theta, rng.uniform(0, 2 * math.pi))
        v = tuple(rng.uniform(-3, 3, 3))
        lm = _lm(n, rng.uniform(-100, 100, 3))
        e, mu = rng.uniform(), rng.uniform(0, 1)
        assert impact.impact(v, lm, n, impact_record(NICKEL, e, mu)) == impact.impact(
            v, lm, n, impact_record(NICKEL, e, mu, contact_duration=0.0)
        )


@settings(max_examples=400, deadline=None)
@given(
    near=st.sampled_from(["flat", "upright"]),
    tilt=st.one_of(st.just(0.0), st.floats(0.0, 1e-6), st.floats(0.0, 0.05)),
    azimuth=st.floats(0.0, 2 * math.pi),
    v=st.tuples(st.floats(-2, 2), st.floats(-2, 2), st.floats(-5, -0.01)),
    w=st.tuples(*[st.floats(-50, 50)] * 3),
    e=st.one_of(st.just(0.0), st.just(1.0), st.floats(0.0, 1.0)),
    mu=st.one_of(st.just(0.0), st.floats(0.0, 1.0), st.just(3.0)),
    corner=st.one_of(st.just(0.0), st.just(1.0), st.floats(0.0, 1.0)),
)
def test_a_simultaneous_impact_never_makes_energy(near, tilt, azimuth, v, w, e, mu, corner):
    """Near flat or upright, where the simultaneous law acts: the kinetic energy never grows,
    the impulse pushes and stays in the friction cone, the lowest point does not end moving
    into the table; without friction the impulse is vertical and leaves the horizontal
    momentum, L·n and L_z unchanged; elastic and frictionless, the energy is conserved."""
    base = tilt if near == "flat" else math.pi / 2 - tilt
    n = _tilted(base, azimuth)
    a = corner * HH
    lm = _lm(n, w)
    before = impact.kinetic_energy(v, lm, n, M, I1, I3)
    v2, lm2, rebound = impact.impact(v, lm, n, impact_record(NICKEL, e, mu, corner_radius=a))
    after = impact.kinetic_energy(v2, lm2, n, M, I1, I3)
    assert after <= before * (1 + 1e-12) + 1e-18
    impulse = M * (np.array(v2) - np.array(v))
    scale = M * (np.abs(v).max() + np.abs(v2).max()) + 1e-30
    assert impulse[2] >= -1e-12 * scale
    assert math.hypot(impulse[0], impulse[1]) <= mu * impulse[2] + 1e-12 * scale
    rc = impact.contact_point(n, R, HH, a)
    approach = impact.contact_velocity(v, impact.angular_velocity(lm, n, I1, I3), rc)[2]
    if approach < 0.0:
        assert rebound >= -1e-12 * scale / M
    if mu == 0.0:
        # Rounding: of the largest angular momentum involved, the impulse's moment included.
        size = max(np.abs(lm).max(), np.abs(lm2).max(), np.abs(impulse).max() * R)
        assert v2[0] == v[0] and v2[1] == v[1]
        assert abs(lm2[2] - lm[2]) <= 1e-12 * size
        # L·n is kept exactly by vertical impulses at points in the plane of n and ẑ (a
        # nearly upright coin's, a tilted face's lowest diameter); a coin flat to rounding
        # (tilt below ~1e-7 rad) is struck along the diameter its tilt rate picks, where a
        # vertical impulse P at a rim point turns L·n by at most P r sin(tilt).
        turn = impulse[2] * R * math.hypot(n[0], n[1]) if near == "flat" else 0.0
        assert abs(np.dot(lm2, n) - np.dot(lm, n)) <= 1e-12 * size + turn
        if e == 1.0:
            assert after == pytest.approx(before, rel=1e-12, abs=1e-18)


# --- symmetry and continuity ----------------------------------------------------------------


def test_heads_and_tails_mirror_bit_for_bit():
    """A coin is the same body turned over: started tails up with the same angular momentum
    in the lab (body ω (ωx, −ωy, −ωz) under the half turn about X), every landing is the
    heads one with the faces swapped, to the bit, through the bounces and the rigid ending
    (400 near-flat drops; 60 tossed coins, most carried to rest at a few ms each)."""
    rng = np.random.default_rng(21)
    n, m = 400, 60
    flat = rng.normal(size=(n, 3)) * 1e-6
    tossed = np.column_stack(
        [rng.uniform(20, 200, m), rng.uniform(-20, 20, m), rng.uniform(-20, 20, m)]
    )
    speed = np.concatenate([np.zeros(n), rng.uniform(0.5, 3.0, m)])
    omega = np.concatenate([flat, tossed])
    for coin, e, mu in ((NICKEL, 0.45, 0.3), (Coin.preset("gbp-1"), 0.8, 0.1)):
        table = Surface("table", drop_height=0.35, restitution=e, friction=mu)
        heads = land(coin, omega, speed, 1.0, G, table)
        tails = land(coin, omega * [1.0, -1.0, -1.0], speed, -1.0, G, table)
        swap = np.array([1, 0, 2], dtype=np.int8)
        np.testing.assert_array_equal(tails.face, swap[heads.face])
        np.testing.assert_array_equal(tails.bounces, heads.bounces)
        np.testing.assert_array_equal(tails.first_contact, heads.first_contact)
        np.testing.assert_array_equal(tails.status, heads.status)
        # the rigid ending's integration is not bit-symmetric (tests/test_bounce.py): its
        # settle times are not compared to the bit, the bounces' are
        bounces_only = heads.status != Status.SETTLED_CONTACT
        np.testing.assert_array_equal(
            tails.settle_time[bounces_only], heads.settle_time[bounces_only]
        )


def test_heads_and_tails_mirror_bit_for_bit_followed_in_time():
    rng = np.random.default_rng(4)
    c = contact_record(NICKEL, Surface("table", restitution=0.45, friction=0.3), G)
    times = np.linspace(0.0, 0.6, 61)
    for _ in range(10):
        n = _tilted(rng.uniform(0, 0.01), rng.uniform(0, 2 * math.pi))
        lm = _lm(n, rng.normal(size=3) * 0.05)
        states = []
        for sign in (1.0, -1.0):
            out = np.full((times.size, bounce.STATE_COLUMNS), np.nan)
            result = bounce.follow(
                0.3,
                (0.0, 0.0),
                (0.0, 0.0, 0.0),
                tuple(sign * x for x in n),
                lm,
                c,
                2000,
                times,
                out,
            )
            states.append((result, out))
        (heads, a), (tails, b) = states
        assert tails[0] == {1: 0, 0: 1, 2: 2}[heads[0]]
        assert tails[1:] == heads[1:]
        np.testing.assert_array_equal(b[:, :3], a[:, :3])
        np.testing.assert_array_equal(b[:, 3:6], -a[:, 3:6])
        np.testing.assert_array_equal(b[:, 6:], a[:, 6:])


def _first_impact(thetas, e=0.45, mu=0.3, speed=2.6):
    """The state after one impact of a nickel falling without spin at ``speed``, tilted by
    each of ``thetas``: rows (v, L, rebound)."""
    rows = []
    for theta in thetas:
        v2, lm2, rebound = impact.impact(
            (0.0, 0.0, -speed), (0.0,) * 3, _tilted(theta), impact_record(NICKEL, e, mu)
        )
        rows.append((*v2, *(x / (M * R) for x in lm2), rebound))
    return np.array(rows)


@pytest.mark.parametrize(("e", "mu"), [(0.0, 0.0), (0.45, 0.3), (0.9, 1.0)])
def test_the_impact_is_continuous_in_the_tilt(e, mu):
    """From exactly flat through the tilts where the two contacts separate (about 0.5-1.3° for
    a nickel at 2.6 m/s) to 3°: halving the step of a sweep halves its largest jump (a
    continuous function), and a tilt of 1e-12 rad lands as the flat coin does."""
    coarse = np.linspace(0.0, math.radians(3.0), 1501)
    fine = np.linspace(0.0, math.radians(3.0), 3001)
    jump_coarse = np.abs(np.diff(_first_impact(coarse, e, mu), axis=0)).max(axis=0)
    jump_fine = np.abs(np.diff(_first_impact(fine, e, mu), axis=0)).max(axis=0)
    big = jump_coarse > 1e-9
    assert np.all(jump_fine[big] < 0.7 * jump_coarse[big]), (jump_fine, jump_coarse)
    flat, tiny = _first_impact([0.0, 1e-12], e, mu)
    np.testing.assert_allclose(tiny, flat, atol=1e-9)


def test_a_tilt_near_flat_does_not_turn_the_coin_over():
    """A nickel released at rest from 0.35 m (e 0.45, μ 0.3), tilted by 0 to 0.2° (every
    impact closing its second contact within the contact duration), and by tilts as small as
    1e-12 rad: it lands on its start face. Before, any tilt above 1e-12 rad landed on the
    other face (exactly flat alone landed heads: a flip at the threshold)."""
    table = Surface("table", restitution=0.45, friction=0.3)
    tilts = np.concatenate([[0.0, 1e-12, 1e-9, 1e-6], np.radians(np.linspace(0.01, 0.2, 39))])
    for theta in tilts:
        for sign, face in ((1.0, "heads"), (-1.0, "tails")):
            landing = Landing.from_state(
                NICKEL,
                table,
                position=(0.0, 0.0, 0.35),
                orientation=Rotation.from_euler("yx", [theta, 0.0 if sign > 0 else math.pi]),
                velocity=(0.0, 0.0, 0.0),
                angular_velocity=(0.0, 0.0, 0.0),
            )
            assert landing.outcome.face_name == face, math.degrees(theta)
