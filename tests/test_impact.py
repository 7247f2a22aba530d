"""The impact kernel: contact geometry and an impulse that never creates kinetic energy."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from coinflight import Coin
from coinflight.core import impact

COIN = Coin.preset("us-nickel")
I1, I3 = COIN.moments
R, HH, M = COIN.radius, 0.5 * COIN.thickness, COIN.mass

unit = st.tuples(*[st.floats(-1, 1)] * 3).filter(lambda a: math.hypot(*a) > 1e-3)
vec = st.tuples(*[st.floats(-5, 5)] * 3)
spin = st.tuples(*[st.floats(-300, 300)] * 3)


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
@given(n=unit, v=vec, w=spin, e=st.floats(0.0, 1.0), mu=st.floats(0.0, 2.0))
def test_kinetic_energy_never_grows(n, v, w, e, mu):
    n, v, lm = _state(n, v, w)
    before = impact.kinetic_energy(v, lm, n, M, I1, I3)
    v2, lm2, rebound = impact.impact(v, lm, n, R, HH, M, I1, I3, e, mu)
    after = impact.kinetic_energy(v2, lm2, n, M, I1, I3)
    assert after <= before * (1 + 1e-12) + 1e-18
    # The contact point never ends moving into the surface.
    assert rebound >= -1e-12 * (1 + math.sqrt(sum(c * c for c in v)))


@settings(max_examples=100, deadline=None)
@given(n=unit, v=vec, w=spin)
def test_elastic_frictionless_keeps_energy_and_reverses_normal_velocity(n, v, w):
    n, v, lm = _state(n, v, w)
    rc = impact.contact_point(n, R, HH)
    u = impact.contact_velocity(v, impact.angular_velocity(lm, n, I1, I3), rc)
    v2, lm2, rebound = impact.impact(v, lm, n, R, HH, M, I1, I3, 1.0, 0.0)
    before = impact.kinetic_energy(v, lm, n, M, I1, I3)
    after = impact.kinetic_energy(v2, lm2, n, M, I1, I3)
    assert after == pytest.approx(before, rel=1e-9, abs=1e-15)
    assert rebound == pytest.approx(abs(u[2]), rel=1e-9, abs=1e-12)
    # Frictionless: the impulse is vertical, so the horizontal velocity is untouched.
    assert v2[:2] == pytest.approx(v[:2], abs=1e-12)


def test_restitution_sets_rebound_of_flat_drop():
    # A coin falling flat at 2 m/s without spin: the rebound is e times the impact speed.
    for e in (0.0, 0.3, 0.8):
        v2, _lm2, rebound = impact.impact(
            (0.0, 0.0, -2.0), (0.0, 0.0, 0.0), (0.0, 0.0, 1.0), R, HH, M, I1, I3, e, 0.5
        )
        assert v2 == pytest.approx((0.0, 0.0, 2.0 * e), abs=1e-12)
        assert rebound == pytest.approx(2.0 * e, abs=1e-12)


def test_sticking_friction_stops_the_slip():
    # Tilted coin, sliding fast sideways onto the table with large μ: the contact point sticks.
    n = _unit((0.5, 0.0, 0.8))
    n, v, lm = _state(n, (1.0, 0.5, -2.0), (0.0, 0.0, 0.0))
    v2, lm2, _ = impact.impact(v, lm, n, R, HH, M, I1, I3, 0.0, 10.0)
    rc = impact.contact_point(n, R, HH)
    u = impact.contact_velocity(v2, impact.angular_velocity(lm2, n, I1, I3), rc)
    # The friction and non-penetration sweeps converge geometrically: after FRICTION_SWEEPS
    # the contact point moves at well under 1e-9 of the 2 m/s impact speed.
    assert u == pytest.approx((0.0, 0.0, 0.0), abs=2e-9)


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
    mu=st.floats(0.0, 2.0),
)
def test_impulse_acts_through_the_contact_point(n, v, w, e, mu):
    """Any contact impulse J at P leaves the angular momentum about P unchanged:
    L_P = L_cm − r_P × m v_cm (Goldsmith, Impact, 1960, ch. 2), whatever e and μ."""
    n, v, lm = _state(n, v, w)
    rc = np.array(impact.contact_point(n, R, HH))
    v2, lm2, _ = impact.impact(v, lm, n, R, HH, M, I1, I3, e, mu)
    before = np.array(lm) - np.cross(rc, M * np.array(v))
    after = np.array(lm2) - np.cross(rc, M * np.array(v2))
    np.testing.assert_allclose(after, before, rtol=0, atol=1e-12 * (np.abs(before).max() + 1e-9))


@settings(max_examples=300, deadline=None)
@given(n=unit, v=vec, w=spin, e=st.floats(0.0, 1.0))
def test_frictionless_impact_is_vertical(n, v, w, e):
    """μ = 0: the impulse is vertical, so the horizontal momentum and the vertical component of
    the angular momentum about the centre of mass do not change."""
    n, v, lm = _state(n, v, w)
    v2, lm2, _ = impact.impact(v, lm, n, R, HH, M, I1, I3, e, 0.0)
    assert v2[0] == v[0] and v2[1] == v[1]
    assert lm2[2] == pytest.approx(lm[2], rel=1e-12, abs=1e-18)
