"""The rounded rim in flight and at impact: the coin is the cylinder (r − a, h/2 − a) swept by a
ball of radius a, and core.impact.lowest_depth / contact_point, core.bounce.next_contact and
core.impact.impact use its lowest point. The impact law's invariants at any a are in
tests/test_impact.py."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from _kernels import coin_air, coin_contact
from coinflight import Coin
from coinflight.core import bounce, drag, impact

COIN = Coin.preset("us-nickel")
I1, I3 = COIN.moments
R, HH = COIN.radius, 0.5 * COIN.thickness
G = 9.81


@pytest.mark.parametrize("corner", [0.0, 0.3, 1.0])
@pytest.mark.parametrize("nz", [1.0, 0.95, 0.6, 0.1, 0.0, -0.4, -1.0])
def test_lowest_point_is_that_of_the_swept_surface(nz, corner):
    """Brute force over the rounded rim's surface: the torus of the rim's corners, points
    (r − a) ρ̂(φ) ± (h/2 − a) n + a (cos ψ ρ̂(φ) ± sin ψ n), ψ in [0, π/2], on both rims (the
    faces' flat disks are never lower than its top circle). Its lowest point is the kernels'."""
    a = corner * HH
    n = np.array([math.sqrt(1 - nz * nz), 0.0, nz])
    e1 = np.cross(n, [0.0, 1.0, 0.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(n, e1)
    phi = np.linspace(0, 2 * np.pi, 4001)[:, None]
    psi = np.linspace(0, 0.5 * np.pi, 401)[None, :]
    rho_z = np.cos(phi) * e1[2] + np.sin(phi) * e2[2]  # the height of ρ̂(φ)
    low = math.inf
    for side in (1.0, -1.0):
        ball = a * (np.cos(psi) * rho_z + side * np.sin(psi) * n[2])
        z = (R - a) * rho_z + side * (HH - a) * n[2] + ball
        low = min(low, float(z.min()))
    depth = impact.lowest_depth(nz, R, HH, a)
    # A grid's minimum is above the true one by at most amplitude × (1 − cos(δ/2)) ≤ A δ²/8
    # for each angle (δφ = 2π/4000, δψ = π/800; amplitudes at most r and a).
    grid = (R * (2 * np.pi / 4000) ** 2 + a * (np.pi / 800) ** 2) / 8.0
    assert depth == pytest.approx(-low, abs=grid + 1e-15)
    assert depth >= -low - 1e-15  # the grid never finds a lower point
    rc = impact.contact_point(tuple(n), R, HH, a)
    assert -rc[2] == pytest.approx(depth, abs=1e-15)
    # The point is on the body: a ball of radius a about it, moved up by a, is the core
    # cylinder's rim point (or a point of its lower face when the coin lies flat).
    core = np.array(rc) + np.array([0.0, 0.0, a])
    along = float(np.dot(core, n))
    assert abs(along) == pytest.approx(HH - a, abs=1e-15)
    radial = np.linalg.norm(core - along * n)
    assert radial == pytest.approx(R - a if abs(nz) < 1 else 0.0, abs=1e-15)


def test_sharp_corners_are_the_sharp_cylinder_to_the_last_bit():
    """a = 0 gives exactly the sharp cylinder's depth and contact point (the kernels subtract and
    add 0.0), so every landing at a = 0 is what it was before the corner radius reached them."""
    rng = np.random.default_rng(3)
    for _ in range(200):
        n = rng.normal(size=3)
        n = tuple(n / np.linalg.norm(n))
        sharp = R * math.sqrt(max(1.0 - n[2] * n[2], 0.0)) + HH * abs(n[2])
        assert impact.lowest_depth(n[2], R, HH, 0.0) == sharp
        assert impact.contact_point(n, R, HH, 0.0) == impact.contact_point(n, R, HH)


@pytest.mark.parametrize("tilt", [0.02, 0.1, 0.4])
@pytest.mark.parametrize("corner", [0.0, 0.5, 1.0])
def test_first_contact_of_a_falling_tilted_coin_is_the_analytic_time(tilt, corner):
    """A coin falling without rotation, its normal tilted by a fixed angle θ, from height z0 with
    vertical velocity vz0: its lowest point is (r − a) sin θ + (h/2 − a) cos θ + a below its
    centre (the swept cylinder's support function), so the first contact is at the root of
    z0 + vz0 t − g t²/2 = that depth, t = (vz0 + sqrt(vz0² + 2 g (z0 − depth))) / g. The kernel's
    contact time agrees to 1e-9 s; at a = h/2 it is later than the sharp coin's by more."""
    a = corner * HH
    n = (math.sin(tilt), 0.0, math.cos(tilt))
    z0, vz0 = 0.8, 0.5
    depth = (R - a) * math.sin(tilt) + (HH - a) * math.cos(tilt) + a
    expected = (vz0 + math.sqrt(vz0 * vz0 + 2.0 * G * (z0 - depth))) / G
    t, n_at, speed = bounce.next_contact(0.0, z0, vz0, G, n, (0.0, 0.0, 0.0), I1, I3, R, HH, a)
    assert t == pytest.approx(expected, abs=1e-9)
    assert n_at == pytest.approx(n, abs=1e-15)  # no rotation
    assert speed == pytest.approx(vz0 - G * expected, abs=1e-9)
    sharp = R * math.sin(tilt) + HH * math.cos(tilt)
    sharp_time = (vz0 + math.sqrt(vz0 * vz0 + 2.0 * G * (z0 - sharp))) / G
    # The rounded coin falls a (sin θ + cos θ − 1) further: > 1e-9 s later unless a = 0.
    assert (t - sharp_time > 1e-8) == (a > 0.0)


@pytest.mark.parametrize("through_air", [False, True])
def test_a_rounded_rim_is_touched_no_earlier_in_both_landing_kernels(through_air):
    """The rounded coin lies inside the sharp cylinder, so in both landing kernels (vacuum:
    core.bounce; air: core.drag, with its own contact search) the first contact at a = h/2 is
    never earlier than at a = 0 for the same toss, and later for those landing on the rim."""
    rng = np.random.default_rng(5)
    n = 300
    omega = np.column_stack(
        [rng.uniform(150, 300, n), rng.uniform(-30, 30, n), rng.uniform(-30, 30, n)]
    )
    v0 = rng.uniform(1.5, 3.0, n)
    first = []
    for a in (0.0, HH):
        contact = coin_contact(COIN, corner_radius=a)
        if through_air:
            air = coin_air(COIN, drag_coefficient=1.17)
            out = drag.land(omega, v0, 1.0, air, contact, max_bounces=0)
        else:
            out = bounce.land(omega, v0, np.ones(n), contact, max_bounces=0)
        first.append(out[2])
    assert np.all(first[1] >= first[0])
    assert np.mean(first[1] > first[0]) > 0.5


# --- the face/edge barrier on the rounded rim (the Contact record's) -----------------------------
THICK = Coin(radius=0.012, thickness=0.024 / math.sqrt(3), mass=0.005)  # h/d = 1/√3


def _centre_of_mass(coin, a, phi):
    """The centre of mass of the section (the rectangle (r − a, h/2 − a) swept by a disc of
    radius a) rolling without slip on the corner whose centre C is lowest for φ in (0, π/2):
    C = CM + (r − a) u − (h/2 − a) n, u = (cos φ, −sin φ), and C = (a φ, a) (it rolls)."""
    r_in, h_in = coin.radius - a, 0.5 * coin.thickness - a
    n = np.array([math.sin(phi), math.cos(phi)])
    u = np.array([math.cos(phi), -math.sin(phi)])
    return np.array([a * phi, a]) - r_in * u + h_in * n


@pytest.mark.parametrize("coin", [COIN, THICK])
@pytest.mark.parametrize("share", [0.0, 0.3, 0.8, 1.0])
def test_the_barrier_is_the_top_of_the_rounded_corner(coin, share):
    """The face/edge barrier the landing's ending reads (Contact.barrier, the potential energy
    a coin must exceed to leave a face, core.bounce.impact_verdict) is m g (a + ρ′),
    ρ′ = sqrt((r − a)² + (h/2 − a)²): the closed form, to 1e-14, and the maximum of m g z_CM of
    the section rolling on its corner (a dense search over φ, not the closed form), to 1e-9."""
    hh = 0.5 * coin.thickness
    a = share * hh
    closed = coin.mass * G * (a + math.hypot(coin.radius - a, hh - a))
    assert coin_contact(coin, corner_radius=a).barrier == pytest.approx(closed, rel=1e-14)
    grid = np.linspace(0.0, 0.5 * math.pi, 200_001)
    heights = [_centre_of_mass(coin, a, p)[1] for p in grid[::1000]]
    top = int(np.argmax(heights)) * 1000
    fine = grid[max(0, top - 1000) : top + 1001]
    barrier = coin.mass * G * max(_centre_of_mass(coin, a, p)[1] for p in fine)
    assert barrier == pytest.approx(closed, rel=1e-9)


@pytest.mark.parametrize(
    ("radius", "thickness", "bound", "why"),
    [
        (0.0106, 0.00195, 0.000975, "at most half the thickness h/2"),  # a nickel: h/2 < r
        (0.012, 0.048, 0.012, "at most the radius r (a coin thicker than wide)"),  # h/d = 2
    ],
)
def test_the_corner_radius_is_bounded_by_the_smaller_of_half_thickness_and_radius(
    radius, thickness, bound, why
):
    """The rounded coin is the cylinder (r − a, h/2 − a) swept by a ball of radius a: both must
    be ≥ 0, so a ≤ min(h/2, r). At the bound the coin is accepted (a = r = h/2 would be a
    sphere, refused: test_a_ball_is_refused); just above it, refused with a line naming the
    value, the range and the reason."""
    coin = Coin(radius=radius, thickness=thickness, mass=0.005, corner_radius=bound)
    assert coin.corner_radius == bound
    with pytest.raises(ValueError, match=rf"got {1.01 * bound:g}: {re.escape(why)}"):
        Coin(radius=radius, thickness=thickness, mass=0.005, corner_radius=1.01 * bound)


def test_a_ball_is_refused():
    """a = r = h/2 rounds the coin into a ball: no faces, no edge, no well to end in (its
    contact record would divide by ρ′ = 0). Refused with a line naming the value and why; a
    hair below it the coin is accepted."""
    with pytest.raises(ValueError, match=r"below 0\.005 m .* got 0\.005: .* a ball"):
        Coin(radius=0.005, thickness=0.01, mass=0.004, corner_radius=0.005)
    assert Coin(radius=0.005, thickness=0.01, mass=0.004, corner_radius=0.00499).corner_radius
