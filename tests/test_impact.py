"""The impact kernel: contact geometry and Stronge's impact law in impulse space (energetic
restitution, Coulomb friction with stick, slip and swerve), checked by its invariants."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from _kernels import impact_record
from coinflight import Coin
from coinflight.core import impact
from coinflight.model.surface import MAX_FRICTION

COIN = Coin.preset("us-nickel")
I1, I3 = COIN.moments
R, HH, M = COIN.radius, 0.5 * COIN.thickness, COIN.mass

unit = st.tuples(*[st.floats(-1, 1)] * 3).filter(lambda a: math.hypot(*a) > 1e-3)
vec = st.tuples(*[st.floats(-5, 5)] * 3)
spin = st.tuples(*[st.floats(-300, 300)] * 3)
# μ over the whole range a Surface takes (0 to MAX_FRICTION = 3: the properties below are
# validated up to it), the common 0-2 drawn as often as before and both ends explicitly.
frictions = st.one_of(
    st.just(0.0), st.floats(0.0, 2.0), st.floats(0.0, MAX_FRICTION), st.just(MAX_FRICTION)
)


def _unit(a):
    n = math.sqrt(sum(c * c for c in a))
    return tuple(c / n for c in a)


def _state(n, v, w):
    # Angular momentum from a lab angular velocity: L = I ω, I = I1 + (I3 − I1) n nᵀ.
    wn = sum(a * b for a, b in zip(w, n, strict=True))
    lm = tuple(I1 * wi + (I3 - I1) * wn * ni for wi, ni in zip(w, n, strict=True))
    return _unit(n), tuple(float(c) for c in v), lm


@pytest.mark.parametrize("nz", [1.0, 0.9, 0.3, 0.0, -0.2, -1.0])
def test_lowest_point_is_lowest_point_of_the_cylinder(nz):
    # Brute force over points of both rims (the lowest point of a cylinder is on a rim).
    n = np.array([math.sqrt(1 - nz * nz), 0.0, nz])
    a = np.cross(n, [0.0, 1.0, 0.0])
    a /= np.linalg.norm(a)
    b = np.cross(n, a)
    phi = np.linspace(0, 2 * np.pi, 200_001)
    rim = R * (np.cos(phi)[:, None] * a + np.sin(phi)[:, None] * b)
    points = np.concatenate([rim + HH * n, rim - HH * n])
    depth = -points[:, 2].min()
    assert impact.lowest_depth(nz, R, HH) == pytest.approx(depth, abs=1e-12)
    rc = impact.contact_point(tuple(n), R, HH)
    assert -rc[2] == pytest.approx(depth, abs=1e-12)
    # It is a point of the coin: on a face plane, at distance r from the axis.
    along = float(np.dot(rc, n))
    assert abs(along) == pytest.approx(HH, abs=1e-15)
    assert np.linalg.norm(np.array(rc) - along * n) == pytest.approx(R if abs(nz) < 1 else 0.0)


@settings(max_examples=300, deadline=None)
@given(n=unit, v=vec, w=spin, e=st.floats(0.0, 1.0), mu=frictions)
def test_kinetic_energy_never_grows(n, v, w, e, mu):
    n, v, lm = _state(n, v, w)
    before = impact.kinetic_energy(v, lm, n, M, I1, I3)
    v2, lm2, rebound = impact.impact(v, lm, n, impact_record(COIN, e, mu))
    after = impact.kinetic_energy(v2, lm2, n, M, I1, I3)
    assert after <= before * (1 + 1e-12) + 1e-18
    # The contact point never ends moving into the surface.
    assert rebound >= -1e-12 * (1 + math.sqrt(sum(c * c for c in v)))


@settings(max_examples=100, deadline=None)
@given(n=unit, v=vec, w=spin)
def test_elastic_frictionless_keeps_energy_and_reverses_normal_velocity(n, v, w):
    # The single impact at the lowest point (duration 0: no second contact joins it; the
    # simultaneous impact's own properties are in tests/test_simultaneous_impact.py).
    n, v, lm = _state(n, v, w)
    rc = impact.contact_point(n, R, HH)
    u = impact.contact_velocity(v, impact.angular_velocity(lm, n, I1, I3), rc)
    v2, lm2, rebound = impact.impact(v, lm, n, impact_record(COIN, 1.0, 0.0, contact_duration=0.0))
    before = impact.kinetic_energy(v, lm, n, M, I1, I3)
    after = impact.kinetic_energy(v2, lm2, n, M, I1, I3)
    assert after == pytest.approx(before, rel=1e-12, abs=1e-18)
    assert rebound == pytest.approx(abs(u[2]), rel=1e-12, abs=1e-14)
    # Frictionless: the impulse is vertical, so the horizontal velocity is untouched.
    assert v2[:2] == pytest.approx(v[:2], abs=1e-12)


def test_restitution_sets_rebound_of_flat_drop():
    # A coin falling flat at 2 m/s without spin: the rebound is e times the impact speed.
    for e in (0.0, 0.3, 0.8):
        v2, _lm2, rebound = impact.impact(
            (0.0, 0.0, -2.0), (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), impact_record(COIN, e, 0.5)
        )
        assert v2 == pytest.approx((0.0, 0.0, 2.0 * e), abs=1e-12)
        assert rebound == pytest.approx(2.0 * e, abs=1e-12)


def test_sticking_friction_stops_the_slip():
    # Tilted coin, sliding fast sideways onto the table with large μ: the contact point sticks.
    n = _unit((0.5, 0.0, 0.8))
    n, v, lm = _state(n, (1.0, 0.5, -2.0), (0.0, 0.0, 0.0))
    v2, lm2, _ = impact.impact(v, lm, n, impact_record(COIN, 0.0, 10.0))
    rc = impact.contact_point(n, R, HH)
    u = impact.contact_velocity(v2, impact.angular_velocity(lm2, n, I1, I3), rc)
    # The slip is brought exactly to rest (its last part by one straight segment in impulse
    # space) and e = 0 ends the impact at u_z = 0: the contact point is at rest to rounding.
    assert u == pytest.approx((0.0, 0.0, 0.0), abs=1e-14)


def test_resting_face_wells():
    # Yong & Mahadevan: edge iff the normal is within arctan(h/d) of the horizontal.
    edge_sine = HH / math.hypot(R, HH)
    assert impact.resting_face(0.99, edge_sine) == 1
    assert impact.resting_face(-0.99, edge_sine) == 0
    assert impact.resting_face(0.5 * edge_sine, edge_sine) == 2
    assert impact.resting_face(-1.01 * edge_sine, edge_sine) == 0


@settings(max_examples=300, deadline=None)
@given(
    n=unit,
    v=vec,
    w=spin,
    e=st.floats(0.0, 1.0),
    mu=frictions,
)
def test_impulse_acts_through_the_contact_point(n, v, w, e, mu):
    """Any contact impulse J at P leaves the angular momentum about P unchanged:
    L_P = L_cm − r_P × m v_cm (Goldsmith, Impact, 1960, ch. 2), whatever e and μ. (The impact
    at the lowest point alone, duration 0: a simultaneous impact acts elsewhere,
    tests/test_simultaneous_impact.py.)"""
    n, v, lm = _state(n, v, w)
    rc = np.array(impact.contact_point(n, R, HH))
    v2, lm2, _ = impact.impact(v, lm, n, impact_record(COIN, e, mu, contact_duration=0.0))
    before = np.array(lm) - np.cross(rc, M * np.array(v))
    after = np.array(lm2) - np.cross(rc, M * np.array(v2))
    np.testing.assert_allclose(after, before, rtol=0, atol=1e-12 * (np.abs(before).max() + 1e-9))


@settings(max_examples=300, deadline=None)
@given(n=unit, v=vec, w=spin, e=st.floats(0.0, 1.0))
def test_frictionless_impact_is_vertical(n, v, w, e):
    """μ = 0: the impulse is vertical, so the horizontal momentum and the vertical component of
    the angular momentum about the centre of mass do not change."""
    n, v, lm = _state(n, v, w)
    v2, lm2, _ = impact.impact(v, lm, n, impact_record(COIN, e, 0.0))
    assert v2[0] == v[0] and v2[1] == v[1]
    assert lm2[2] == pytest.approx(lm[2], rel=1e-12, abs=1e-18)


# Steel coins of any proportions: radius 5-30 mm, thickness 0.5-40 mm (wafer to cylinder).
coins = st.builds(
    lambda r, h: Coin(radius=r, thickness=h, mass=7800.0 * math.pi * r * r * h),
    st.floats(5e-3, 3e-2),
    st.floats(5e-4, 4e-2),
)


# A rim's corner radius a as a fraction of h/2 (0: sharp corners, 1: a rim without a flat band).
corners = st.one_of(st.just(0.0), st.just(1.0), st.floats(0.0, 1.0))


def _impulse_and_state(coin, n, v, w, e, mu, kernel=None, corner=0.0, duration=0.0):
    """(state before, state after, contact point, approach velocity) of one impact, the rim's
    corners rounded with a = ``corner`` × h/2. Stronge's law at the lowest point alone by
    default (``duration`` 0: no second contact joins it; the simultaneous impact of a coin
    landing nearly flat or upright is tested in tests/test_simultaneous_impact.py)."""
    i1, i3 = coin.moments
    r, hh = coin.radius, 0.5 * coin.thickness
    a = corner * hh
    n = _unit(n)
    wn = sum(a * b for a, b in zip(w, n, strict=True))
    lm = tuple(i1 * wi + (i3 - i1) * wn * ni for wi, ni in zip(w, n, strict=True))
    v = tuple(float(c) for c in v)
    rc = impact.contact_point(n, r, hh, a)
    u = impact.contact_velocity(v, impact.angular_velocity(lm, n, i1, i3), rc)
    law = impact.impact if kernel is None else kernel
    v2, lm2, rebound = law(
        v, lm, n, impact_record(coin, e, mu, corner_radius=a, contact_duration=duration)
    )
    return (v, lm), (v2, lm2), rc, u, rebound


def violations(coin, n, v, w, e, mu, kernel=None, corner=0.0):
    """Names of the impact law's invariants that one impact breaks (empty if none); rim corners
    rounded with a = ``corner`` × h/2."""
    i1, i3 = coin.moments
    m = coin.mass
    (v, lm), (v2, lm2), rc, u, rebound = _impulse_and_state(coin, n, v, w, e, mu, kernel, corner)
    n = _unit(n)
    bad = []
    before = impact.kinetic_energy(v, lm, n, m, i1, i3)
    after = impact.kinetic_energy(v2, lm2, n, m, i1, i3)
    if after > before * (1 + 1e-12) + 1e-18:
        bad.append("energy grows")
    impulse = np.array(v2) * m - np.array(v) * m
    # The impulse is measured as m (v' − v): its rounding is ~2⁻⁵² m |v|, not 2⁻⁵² |P| (a tiny
    # impulse on a fast coin, e.g. 6e-7 N s at 1 m/s, is known only to ~5e-18 N s).
    scale = np.abs(impulse).max() + m * max(np.abs(v).max(), np.abs(v2).max()) + 1e-30
    if math.hypot(impulse[0], impulse[1]) > mu * impulse[2] + 1e-12 * scale:
        bad.append("outside the friction cone")
    if impulse[2] < -1e-12 * scale:
        bad.append("pulls the coin down")
    speed = math.sqrt(sum(c * c for c in u))
    if u[2] < 0 and rebound < -1e-12 * (1 + speed):
        bad.append("sinks into the surface")
    if u[2] < 0 and e == 0.0 and abs(rebound) > 1e-12:
        bad.append("e = 0 leaves a normal velocity")
    lp0 = np.array(lm) - np.cross(rc, m * np.array(v))
    lp1 = np.array(lm2) - np.cross(rc, m * np.array(v2))
    if np.abs(lp1 - lp0).max() > 1e-12 * (np.abs(lp0).max() + 1e-9):
        bad.append("angular momentum about the contact point changes")
    return bad


@settings(max_examples=400, deadline=None)
@given(
    coin=coins,
    n=unit,
    v=vec,
    w=spin,
    e=st.one_of(st.just(0.0), st.just(1.0), st.floats(0.0, 1.0)),
    mu=frictions,
    corner=corners,
)
def test_impact_law_invariants(coin, n, v, w, e, mu, corner):
    """Stronge's law (Stronge 2000, ch. 4-5): kinetic energy never grows, |P_t| ≤ μ P_n, the normal
    impulse pushes, the contact point never ends moving into the surface, e = 0 leaves it no normal
    velocity (|u_z'| ≤ 1e-12 m/s), and the impulse acts through the contact point. Any e, μ up to
    :data:`~coinflight.model.surface.MAX_FRICTION` (μ ≳ 1e11 the cone can no longer be told from the
    rounding of the measured P_n), coin, orientation and velocities, and any rim corner radius 0 ≤ a
    ≤ h/2 (the contact point of the rounded rim, core.impact.contact_point)."""
    assert violations(coin, n, v, w, e, mu, corner=corner) == []


@settings(max_examples=300, deadline=None)
@given(coin=coins, n=unit, v=vec, w=spin, e=st.floats(0.0, 1.0), corner=corners)
def test_frictionless_impact_keeps_horizontal_momentum_and_axial_and_vertical_spin(
    coin, n, v, w, e, corner
):
    """μ = 0: the impulse is vertical and acts at a rim point lying in the plane of n and ẑ, so
    the horizontal momentum, L·n (spin about the coin's axis) and L_z are unchanged, both about
    the centre of mass and about the vertical through the contact point. So with rounded
    corners (any a in [0, h/2]): the contact point, the core rim point less a ẑ, is in that
    plane too."""
    (v, lm), (v2, lm2), rc, _u, _ = _impulse_and_state(coin, n, v, w, e, 0.0, corner=corner)
    n = _unit(n)
    assert v2[0] == v[0] and v2[1] == v[1]
    # Rounding of a component is ~2⁻⁵² of the largest angular momentum involved, before or after
    # (a coin with no spin gets one from the impulse: L·n' is then zero to ~1e-21).
    size = max(math.sqrt(sum(c * c for c in lm)), math.sqrt(sum(c * c for c in lm2))) + 1e-30
    assert (
        abs(
            sum(a * b for a, b in zip(lm2, n, strict=True))
            - sum(a * b for a, b in zip(lm, n, strict=True))
        )
        <= 1e-12 * size
    )
    assert abs(lm2[2] - lm[2]) <= 1e-12 * size
    lp0 = np.array(lm) - np.cross(rc, coin.mass * np.array(v))
    lp1 = np.array(lm2) - np.cross(rc, coin.mass * np.array(v2))
    assert abs(lp1[2] - lp0[2]) <= 1e-12 * size


@settings(max_examples=200, deadline=None)
@given(coin=coins, n=unit, v=vec, w=spin, corner=corners)
def test_elastic_frictionless_impact_keeps_energy_exactly(coin, n, v, w, corner):
    """e = 1, μ = 0: the kinetic energy is conserved and the normal velocity of the contact
    point reversed, at any rim corner radius a in [0, h/2]."""
    i1, i3 = coin.moments
    (v, lm), (v2, lm2), _rc, u, rebound = _impulse_and_state(coin, n, v, w, 1.0, 0.0, corner=corner)
    n = _unit(n)
    before = impact.kinetic_energy(v, lm, n, coin.mass, i1, i3)
    after = impact.kinetic_energy(v2, lm2, n, coin.mass, i1, i3)
    assert after == pytest.approx(before, rel=1e-12, abs=1e-18)
    if u[2] < 0:
        assert rebound == pytest.approx(-u[2], rel=1e-12, abs=1e-14)


def test_a_sign_flipped_friction_is_caught(monkeypatch):
    """Mutation test: friction pushing along the slip instead of against it (the one sliding
    rate every step takes, run in Python) must break at least one invariant."""
    from coinflight.core import impact as module

    def pushes(ux, uy, friction):
        s = math.hypot(ux, uy)
        return friction * ux / s, friction * uy / s

    monkeypatch.setattr(module, "_friction_rate", pushes)
    monkeypatch.setattr(module, "_rk4", module._rk4.py_func)
    monkeypatch.setattr(module, "contact_impulse", module.contact_impulse.py_func)
    monkeypatch.setattr(module, "_strike", module._strike.py_func)
    mutant = module.impact.py_func
    rng = np.random.default_rng(11)
    broken = 0
    for _ in range(100):
        n = tuple(rng.normal(size=3))
        v = tuple(rng.uniform(-5, 5, 3))
        w = tuple(rng.uniform(-300, 300, 3))
        broken += bool(violations(COIN, n, v, w, float(rng.uniform()), 0.5, kernel=mutant))
    assert broken > 0
    # The same sample passes with the real law.
    monkeypatch.undo()
    rng = np.random.default_rng(11)
    for _ in range(100):
        n = tuple(rng.normal(size=3))
        v = tuple(rng.uniform(-5, 5, 3))
        w = tuple(rng.uniform(-300, 300, 3))
        assert violations(COIN, n, v, w, float(rng.uniform()), 0.5) == []


def test_integration_converges():
    """The law integrated 20 times finer (turns of 0.01 rad per step, slips stopped below
    1e-6 |u0|) gives the same impulse: within 1e-3 (relative) for most random impacts and
    3e-2 for all but 1 %, the cases whose slip swerves close to rest (the module notes)."""
    rng = np.random.default_rng(5)
    errors = []
    for _ in range(2000):
        n = _unit(tuple(rng.normal(size=3)))
        v = tuple(rng.uniform(-5, 5, 3))
        w = rng.uniform(-300, 300, 3)
        _n, _v, lm = _state(n, v, w)
        rc = impact.contact_point(n, R, HH)
        u = impact.contact_velocity(v, impact.angular_velocity(lm, n, I1, I3), rc)
        if u[2] >= 0:
            continue
        k = impact.collision_matrix(rc, n, M, I1, I3)
        e, mu = float(rng.uniform()), float(rng.uniform(0.05, 1.5))
        coarse, steps = impact.contact_impulse(
            u, k, e, mu, impact.TURN_STEP, impact.SLIP_TOLERANCE, impact.MAX_STEPS
        )
        assert steps <= impact.MAX_STEPS
        fine, fine_steps = impact.contact_impulse(u, k, e, mu, 0.01, 1e-6, 100_000)
        if fine_steps < 100_000:
            errors.append(np.linalg.norm(np.subtract(coarse, fine)) / np.linalg.norm(fine))
    errors = np.array(errors)
    assert len(errors) > 900
    assert np.median(errors) < 1e-3
    assert np.percentile(errors, 99) < 3e-2


def _planar_slip_then_stick(u, k, e, mu):
    """Stronge's planar law (2000, ch. 4) solved by hand for a contact sliding along y (t = y,
    n = z) that slips to a stop during compression and then sticks: with K the 2x2 collision
    matrix, slip decelerates at du_t/dp = K_tn − μ sign K_tt until it stops at p_s, then sticks
    (|K_tn/K_tt| ≤ μ: the critical friction of the stick); compression ends where u_n = 0 and
    restitution when the normal work done in it is e² times that of compression. The impulse
    (0, P_t, P_n)."""
    assert u[0] == 0.0 and k[1] == 0.0 and k[2] == 0.0  # planar: nothing along x
    ktt, ktn, knn = k[3], k[4], k[5]
    ut, un = u[1], u[2]
    sign = 1.0 if ut > 0 else -1.0
    # Sliding: dP_t/dp = −μ sign, du_t/dp = −μ sign K_tt + K_tn, du_n/dp = −μ sign K_tn + K_nn.
    p_stop = ut / (mu * sign * ktt - ktn)
    assert p_stop > 0 and abs(ktn / ktt) <= mu
    un_stop = un + p_stop * (knn - mu * sign * ktn)
    assert un_stop < 0  # the slip stops during compression
    work = p_stop * (un + un_stop) / 2
    # Sticking: P_t grows at −K_tn/K_tt, u_n at the Schur complement K_nn − K_tn²/K_tt.
    c = knn - ktn * ktn / ktt
    p_c = p_stop - un_stop / c
    w_c = work - un_stop * un_stop / (2 * c)
    p_end = p_c + math.sqrt(2 * e * e * -w_c / c)
    pt_end = -mu * sign * p_stop - ktn / ktt * (p_end - p_stop)
    return (0.0, pt_end, p_end)


def test_planar_impact_is_stronges_two_dimensional_solution():
    """A coin tipping in the yz plane and sliding along y: the slip keeps its line, so the law is
    Stronge's planar one (2000, ch. 4), solved by hand (:func:`_planar_slip_then_stick`)."""
    n = (0.0, math.sin(0.4), math.cos(0.4))
    v = (0.0, -0.3, -3.0)
    lm = (-I1 * 40.0, 0.0, 0.0)
    e, mu = 0.5, 0.9
    rc = impact.contact_point(n, R, HH)
    u = impact.contact_velocity(v, impact.angular_velocity(lm, n, I1, I3), rc)
    k = impact.collision_matrix(rc, n, M, I1, I3)
    impulse, _ = impact.contact_impulse(
        u, k, e, mu, impact.TURN_STEP, impact.SLIP_TOLERANCE, impact.MAX_STEPS
    )
    assert impulse == pytest.approx(_planar_slip_then_stick(u, k, e, mu), rel=1e-12, abs=1e-15)


def test_planar_stick_above_a_critical_friction_between_2_and_the_largest():
    """Stronge's planar law again (:func:`_planar_slip_then_stick`), where the answer depends on
    μ above 2: a contact sliding along +y stops slipping only if μ exceeds K_tn/K_tt (Stronge
    2000, ch. 4: below it the slip never stops), and for this body that critical μ is 2.62,
    between 2 and :data:`~coinflight.model.surface.MAX_FRICTION`. No coin's is: K_tn/K_tt =
    r_t |r_n| / (k² + r_n²) ≤ |r_c| / (2k), k the radius of gyration about x, at most 1 for a
    uniform disc (|r_c|² / k² ≤ 4; the nickel's reaches 0.89 over tilts); it needs k small beside
    the lever arm, so the body is the nickel's outline (its rim point at tilt 0.2 rad) with its
    mass gathered in a hub, I1 = I3 = m (0.15 r)². At μ = MAX_FRICTION the slip stops and sticks;
    a law that capped μ below 2.62 (as min(μ, 2) in the sliding rate) would not stop it."""
    tilt = 0.2
    n = (0.0, math.sin(tilt), math.cos(tilt))
    rc = impact.contact_point(n, R, HH)
    hub = M * (0.15 * R) ** 2
    k = impact.collision_matrix(rc, n, M, hub, hub)
    assert 2.0 < k[4] / k[3] < MAX_FRICTION
    u = (0.0, 0.05, -2.0)  # m/s: sliding along +y, the slip's stop within compression
    e = 0.5
    impulse, _ = impact.contact_impulse(
        u, k, e, MAX_FRICTION, impact.TURN_STEP, impact.SLIP_TOLERANCE, impact.MAX_STEPS
    )
    expected = _planar_slip_then_stick(u, k, e, MAX_FRICTION)
    assert impulse == pytest.approx(expected, rel=1e-12, abs=1e-15)
