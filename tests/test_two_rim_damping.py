"""Two rims pressed together are damped as one pair (core.contact_phase, "Two rims";
JOINT_DAMPING): the damping matrix C = 2 ζ M^½ (M^−½ K M^−½)^½ M^½ of the two arcs' centroids
puts every mode of the pair at the surface's ζ, so an upright coin restitutes with e and its
rocking mode is damped at ζ, where each rim damped alone gave 0.399 at e 0.5 and ~0.29 ζ.

Checked here: the upright drop's rebound against e and the pair's modes' damping against ζ
(measured with benchmarks/bench_two_rims.py's functions); C against its definition (SciPy's
sqrtm, tests/_two_rims.py), its defining equation C W C = 4 ζ² K, symmetric and positive on
random two-rim states; the single rim's damper as an arc vanishes; the derivative with at most
one arc identical to the bit to the per-rim derivative (a reference of it kept here, as it was
at main 7d8c4d1); frictionless torques in the arcs' planes of symmetry and the energy's rate
never positive on two-arc states, damped jointly or each rim alone; the energy never growing
across the switch between the two (a discontinuity of the forces); and a mutant (C built
from W without its coupling) failing the drop."""

from __future__ import annotations

import math
import os
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import _two_rims
from _bench import load_bench
from _kernels import coin_contact
from coinflight import Coin
from coinflight.core import contact_phase as cp
from coinflight.core.contact import CONTACT_ENDING
from coinflight.core.impact import angular_velocity, cross

NICKEL = Coin.preset("us-nickel")
SPEED = math.sqrt(2.0 * 9.81 * 0.1)  # a 10 cm drop, 1.4 m/s
SHORT = cp.CONTACT_TIME / 16  # 62.5 μs


def _bench():  # type: ignore[no-untyped-def]
    return load_bench("bench_two_rims")


@pytest.mark.parametrize("e", [0.2, 0.5, 0.8])
def test_an_upright_drop_on_both_rims_restitutes_with_e(e):
    # Measured (2026-11-24, 10 cm): 0.1982, 0.4987, 0.7995 at t_c 1 ms (contact 1.8-2.3 ms),
    # 0.1998, 0.4999, 0.7999 at 62.5 μs (0.20-0.25 ms); each rim damped alone gave 0.131,
    # 0.398, 0.736 at every t_c. Tolerance: the weight acts during the contact τ, an impulse
    # g τ of 1.6 % (1 ms) and 0.17 % (62.5 μs) of the approach speed, which bounds how far the
    # rebound can part from the law's e: 0.004 and 0.001 (measured 0.0018 and 0.0002).
    bench = _bench()
    for contact_time, tolerance in ((cp.CONTACT_TIME, 0.004), (SHORT, 0.001)):
        c = bench.record(e, contact_time)
        ratio, duration = bench.drop(c, 0.5 * math.pi, SPEED)
        assert abs(ratio - e) < tolerance, (contact_time, ratio)
        assert 0.0 < duration < 5.0 * contact_time  # 1.8-2.3 and 3.1-4 t_c (∝ t_c^(4/5))
        assert abs(ratio - bench.per_rim_upright(c)) > 0.06  # not the per-rim sizing's


def test_the_pairs_rocking_and_bounce_modes_are_damped_at_zeta():
    # An upright nickel resting on both rims, a small lean oscillation (rocking, the rims in
    # antiphase) and a small bounce, their decay's damping ratio (bench_two_rims.mode_damping).
    # Linearised, the joint damping puts both at ζ. Measured (2026-11-24): rocking 1.0028-1.0052
    # ζ at t_c 62.5 μs for e 0.2-0.8, 1.139 ζ at 1 ms (the finite, Hertz-like contact's: each
    # rim alone measured 0.29 ζ at 1 ms against its linearised 0.254 ζ, the same factor 1.14,
    # and tended to it as t_c fell); the bounce, lightly damped (e 0.8), 0.990 ζ. Each rim
    # damped alone gave the rocking mode 0.25 ζ and the bounce 1.39 ζ.
    bench = _bench()
    for e in (0.2, 0.5, 0.8):
        short = bench.record(e, SHORT)
        zeta = cp.damping_of(short)
        assert bench.mode_damping(short, "rocking") == pytest.approx(zeta, rel=0.02)
        c = bench.record(e)
        assert 1.0 < bench.mode_damping(c, "rocking") / zeta < 1.25
        # Linearised, from the phase's own C, K at rest (modal_damping's eigenproblem); with
        # each rim's own damper instead, the same eigenproblem gives per_rim_modes' closed
        # form (0.25 ζ rocking), so it tells the two sizings apart. Tolerance: K by central
        # differences of 1 nm and the centroids' W (the forces act at the centres of
        # pressure): measured 1e-10 (1 ms) to 4e-8 (62.5 μs) relative.
        for record in (c, short):
            assert bench.linearised_modes(record) == pytest.approx((zeta, zeta), rel=1e-6)
        stiffness = cp.stiffness_of(c)
        depth = cp.static_depth(c, stiffness)
        w = bench.rest_mobility(c, depth)
        phi = math.acos(1.0 - depth / (c.radius - c.corner_radius))
        k = np.full(2, 2.0 * phi * stiffness)  # each arc's k = 2 φ* k_l (the module notes)
        per_rim = np.diag(2.0 * zeta * np.sqrt(k / np.diag(w)))
        assert bench.modal_damping(w, per_rim, k) == pytest.approx(bench.per_rim_modes(c), rel=1e-9)
    c = bench.record(0.8)
    assert bench.mode_damping(c, "bounce") == pytest.approx(cp.damping_of(c), rel=0.03)


def _two_rim_state(c, depth, lean, azimuth, v, omega):
    """(z, v, n, L) of a coin upright in its band leaned by ``lean`` rad, its lower rim's lowest
    point ``depth`` m in the table (both rims touch while |lean| (h − 2a) < depth)."""
    tilt = 0.5 * math.pi + lean
    n = np.array(
        [math.sin(tilt) * math.cos(azimuth), math.sin(tilt) * math.sin(azimuth), math.cos(tilt)]
    )
    core, hh = c.radius - c.corner_radius, c.half_thickness - c.corner_radius
    lowest = core * math.sqrt(max(0.0, 1.0 - n[2] ** 2)) + hh * abs(n[2]) + c.corner_radius
    w = np.asarray(omega, dtype=float)
    lm = c.i1 * w + (c.i3 - c.i1) * (w @ n) * n
    return np.array([lowest - depth, *v, *n, *lm])


two_rim_states = st.tuples(
    st.floats(1e-7, 3e-5),  # depth, m
    st.floats(-0.95, 0.95),  # lean, as a share of the largest that keeps both rims in
    st.floats(0.0, 2 * math.pi),  # azimuth
    st.tuples(*[st.floats(-0.5, 0.5)] * 3),  # v, m/s
    st.tuples(*[st.floats(-200.0, 200.0)] * 3),  # ω, rad/s
    st.sampled_from([0.0, 0.3, 1.0]),  # μ
    st.sampled_from([0.0, 2e-4]),  # corner radius, m
    st.sampled_from([0.2, 0.5, 0.8]),  # e
)


@settings(max_examples=300, deadline=None)
@given(two_rim_states)
def test_the_pairs_damping_matrix_is_its_definition_symmetric_and_positive(args):
    depth, share, azimuth, v, omega, mu, corner, e = args
    c = coin_contact(
        NICKEL, restitution=e, friction=mu, ending=CONTACT_ENDING, corner_radius=corner
    )
    hb = c.half_thickness - corner
    y = _two_rim_state(c, depth, share * depth / (2.0 * hb), azimuth, v, omega)
    stiff, zeta = cp.stiffness_of(c), cp.damping_of(c)
    one, two = _two_rims.arc(-1.0, y, c), _two_rims.arc(1.0, y, c)
    assert one is not None and two is not None  # both arcs in the table
    w = _two_rims.mobility(one, two, c)
    k = np.array([one["k"], two["k"]])
    ok, c11, c12, c22 = cp.joint_damping(w[0, 0], w[0, 1], w[1, 1], k[0], k[1], zeta)
    assert ok
    got = np.array([[c11, c12], [c12, c22]])
    expected = _two_rims.damping_matrix(w, k, zeta)
    np.testing.assert_allclose(got, expected, rtol=1e-9, atol=1e-12 * np.abs(expected).max())
    # C W C = 4 ζ² K: C/2ζ is the geometric mean M # K, the positive solution of G M⁻¹ G = K
    np.testing.assert_allclose(got @ w @ got, 4 * zeta**2 * np.diag(k), rtol=1e-9, atol=1e-9)
    assert c11 > 0.0 and c22 > 0.0 and c11 * c22 - c12 * c12 > 0.0  # symmetric positive
    # The phase's own pair on this state (its arcs, ρ and mobility): the same matrix, when
    # it damps the pair jointly (both joint forces positive).
    lower, f1, q1, f2, q2, joint, d11, d12, d22 = cp.rims_contact(y, c, stiff, zeta)
    rims, expected_joint = _two_rims.rims(y, c, zeta)
    assert joint == expected_joint
    if joint:
        mine = np.array([[d11, d12], [d12, d22]])
        if lower > 0:  # rim 1 the heads rim: the reference's order reversed
            mine = mine[::-1, ::-1]
        np.testing.assert_allclose(mine, got, rtol=1e-12)
        forces = ((f2, q2), (f1, q1)) if lower > 0 else ((f1, q1), (f2, q2))
        for (force, q), (ref, ref_q, _) in zip(forces, rims, strict=True):
            assert force == pytest.approx(ref, rel=1e-9, abs=1e-12 * c.mass * c.g)
            # The centres of pressure (each coupling's moment about its arc's centroid), q =
            # moment/force: C's 1e-9 relative agreement over a force small against the weight
            # grows as mg/F (measured 1.7e-11 m at F ~ mg; the mutant moving the coupling's
            # moment to the arc's lowest point is 2e-5 m off).
            tolerance = 1e-9 * c.radius * (1.0 + c.mass * c.g / force)
            np.testing.assert_allclose(q, ref_q, rtol=0.0, atol=tolerance)


def test_the_pair_becomes_the_single_rim_damper_as_an_arc_vanishes():
    # K = diag(k1, k2), k2 → 0 (the upper rim's arc closing): C → diag(2 ζ sqrt(k1/W11), 0),
    # the damper _rim gives the lower rim alone (its m_eff = 1/W11); the coupling and the
    # closing rim's own damping vanish as sqrt(k2).
    w11, w12, w22, k1, zeta = 1.4e2, 1.1e2, 1.6e2, 700.0, 0.23
    single = 2.0 * zeta * math.sqrt(k1 / w11)
    errors = []
    for k2 in (1e-2, 1e-6, 1e-10):
        ok, c11, c12, c22 = cp.joint_damping(w11, w12, w22, k1, k2, zeta)
        assert ok
        errors.append(abs(c11 / single - 1.0))
        assert abs(c12) < 10 * single * math.sqrt(k2 / k1)
        assert 0.0 < c22 < 10 * single * math.sqrt(k2 / k1)
    assert errors[-1] < 1e-4 and errors[0] > errors[1] > errors[2]
    # A degenerate pair (both rims one circle: a = h/2) is left to each rim alone.
    assert not cp.joint_damping(w11, w11, w11, k1, k1, zeta)[0]


def _per_rim_derivative(y, c, stiffness, zeta):
    """The contact phase's dy/dt with each rim damped alone: the derivative as it was at main
    7d8c4d1 (before the joint damping), its assembly kept here in the same operations and order
    (so to the bit), each rim's force from cp.rim_contact (the kernel _rim, unchanged). It
    duplicates _derivative's force and torque assembly (``duplicates`` D1) deliberately: a
    frozen copy of the code before the change, which the phase's own must keep matching."""
    mass, i1, i3, radius, hh = c.mass, c.i1, c.i3, c.radius, c.half_thickness
    mu, rolling, pivoting = c.friction, c.rolling_resistance, c.pivoting_resistance
    v = (y[1], y[2], y[3])
    n = (y[4], y[5], y[6])
    lm = (y[7], y[8], y[9])
    omega = angular_velocity(lm, n, i1, i3)
    spin_eps = cp.SLIP_SPEED / radius
    fx, fy, fz = 0.0, 0.0, -mass * c.g
    tx, ty, tz = 0.0, 0.0, 0.0
    lower = -1.0 if n[2] >= 0.0 else 1.0
    for sigma in (lower, -lower):
        fn, q, rt, _ = cp.rim_contact(
            sigma, y[0], v, n, omega, radius, hh, mass, i1, i3, stiffness, zeta,
            c.corner_radius, mu,
        )  # fmt: skip
        if fn <= 0.0:
            continue
        fz += fn
        tx += q[1] * fn
        ty -= q[0] * fn
        if mu > 0.0:
            u = cross(omega, q)
            ux, uy = v[0] + u[0], v[1] + u[1]
            k = -mu * fn / math.sqrt(ux * ux + uy * uy + cp.SLIP_SPEED * cp.SLIP_SPEED)
            gx, gy = k * ux, k * uy
            fx += gx
            fy += gy
            tx -= q[2] * gy
            ty += q[2] * gx
            tz += q[0] * gy - q[1] * gx
        drill = mu * rt + pivoting
        if drill > 0.0:
            tz -= drill * fn * omega[2] / math.sqrt(omega[2] * omega[2] + spin_eps * spin_eps)
        if rolling > 0.0:
            k = (
                -rolling
                * fn
                / math.sqrt(omega[0] * omega[0] + omega[1] * omega[1] + spin_eps * spin_eps)
            )
            tx += k * omega[0]
            ty += k * omega[1]
    nd = cross(omega, n)
    return np.array(
        [v[2], fx / mass, fy / mass, fz / mass, nd[0], nd[1], nd[2], tx, ty, tz]
    )  # fmt: skip


def test_with_at_most_one_arc_the_derivative_is_the_per_rim_ones_to_the_bit():
    # Random states touching with one rim (any tilt), lying nearly flat, or upright in the band
    # (where both arcs may press: there the joint damping changes the derivative, which must
    # then differ from the per-rim one on most states whose pair it damps). Against main
    # 7d8c4d1 itself (its src in another process, 2026-11-24): identical on all 15,480 of
    # 20,000 such states with at most one arc.
    rng = np.random.default_rng(7)
    out = np.empty(10)
    one = joint = changed = 0
    for k in range(1500):
        mu = (0.0, 0.3, 1.0)[k % 3]
        corner = (0.0, 2e-4)[k % 2]
        c = coin_contact(
            NICKEL, restitution=0.5, friction=mu, ending=CONTACT_ENDING, corner_radius=corner,
            rolling_resistance=1e-4, pivoting_resistance=1e-4,
        )  # fmt: skip
        stiff, zeta = cp.stiffness_of(c), cp.damping_of(c)
        depth = rng.uniform(1e-8, 3e-5)
        kind = k % 5
        if kind < 2:
            lean = rng.uniform(-1.5, 1.5) - 0.5 * math.pi
        elif kind == 2:
            lean = rng.choice([0.0, math.pi]) + rng.normal(0.0, 1e-3) - 0.5 * math.pi
        else:
            lean = rng.uniform(-1.5, 1.5) * depth / (2.0 * (c.half_thickness - corner))
        v = rng.normal(0.0, rng.choice([1e-3, 0.3]), 3)
        omega = rng.normal(0.0, rng.choice([1.0, 100.0]), 3)
        y = _two_rim_state(c, depth, lean, rng.uniform(0.0, 2 * math.pi), v, omega)
        cp._derivative(y, out, c, stiff, zeta)
        reference = _per_rim_derivative(y, c, stiff, zeta)
        if cp.MODES[cp.contact_mode(y, c)] != "two rims":
            one += 1
            assert np.array_equal(out, reference), y
        elif cp.rims_contact(y, c, stiff, zeta)[5]:
            joint += 1
            changed += not np.array_equal(out, reference)
    assert one > 800 and joint > 100, (one, joint)
    assert changed > 0.95 * joint, (changed, joint)


@settings(max_examples=200, deadline=None)
@given(two_rim_states)
def test_the_two_rims_keep_the_frictionless_invariants_and_only_dissipate(args):
    # Frictionless, without resistances: the pair's forces act in each arc's plane of symmetry
    # (through n and the vertical), so the torque has no part along n or the vertical (L·n and
    # L_z conserved, as a rigid frictionless contact: Stronge 2000, §5), the horizontal force
    # is 0, and the mechanical energy (with the springs') never grows: its rate along the flow,
    # by central differences of cp.energy, at most rounding (C symmetric positive; each rim's
    # own damper positive on the fall-back).
    depth, share, azimuth, v, omega, _, corner, e = args
    c = coin_contact(
        NICKEL, restitution=e, friction=0.0, ending=CONTACT_ENDING, corner_radius=corner
    )
    y = _two_rim_state(
        c, depth, share * depth / (2.0 * (c.half_thickness - corner)), azimuth, v, omega
    )
    stiff, zeta = cp.stiffness_of(c), cp.damping_of(c)
    # On joint states and on those the pair falls back to each rim alone (a joint force not
    # positive: most random states, and where the forces are discontinuous) alike.
    out = np.empty(10)
    cp._derivative(y, out, c, stiff, zeta)
    n, torque = y[4:7], out[7:10]
    scale = c.mass * c.g * c.radius + np.abs(torque).max()
    assert abs(torque @ n) < 1e-12 * scale and abs(torque[2]) < 1e-12 * scale
    assert np.allclose(out[1:3], 0.0, atol=1e-15)
    h = 1e-9
    rate = (cp.energy(y + h * out, c, stiff) - cp.energy(y - h * out, c, stiff)) / (2 * h)
    power = c.mass * c.g * SPEED  # a scale of the contact's power, W
    assert rate < 1e-6 * power


@pytest.mark.parametrize(("friction", "rate"), [(0.0, 4.0), (0.0, 5.0), (0.3, 6.0)])
def test_stepping_across_the_fall_back_the_energy_never_grows(friction, rate):
    # An upright nickel at rest on both rims given a lean rate (rad/s) rocks until the upper
    # rim's joint force reaches 0 while its arc still presses: the pair falls back to each rim
    # alone (or, μ 0.3, back), a discontinuity of the forces (the switched rim's from ~0 to
    # about a fifth of the other's, which drops as much: measured 2026-11-24, 1.2e-5 → 0.0101 N
    # and 0.0494 → 0.0389 N at 4 rad/s). Across it, stepped by 10 μs (1-2 steps each,
    # measured): the mechanical energy never grows (each step's change at most 1e-15 J, ~1e4
    # ulps of its 5.2e-4 J; measured ≤ −2.7e-17 J frictionless, −2.7e-11 J at μ 0.3), the
    # stepper takes at most 4 steps over the switch (measured 2), and the total normal force
    # jumps by less than 2 % of the weight (measured 0.9, 0.4, 0.65 %).
    c = coin_contact(NICKEL, restitution=0.5, friction=friction, ending=CONTACT_ENDING)
    stiff, zeta = cp.stiffness_of(c), cp.damping_of(c)
    depth = cp.static_depth(c, stiff)
    y = np.array([c.radius - depth, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, c.i1 * rate, 0.0])
    energy, joint, both, forces, steps = [cp.energy(y, c, stiff)], [], [], [], []
    for _ in range(400):
        record = cp.rims_contact(y, c, stiff, zeta)
        joint.append(record[5])
        forces.append((record[1], record[3]))
        both.append(cp.MODES[cp.contact_mode(y, c)] == "two rims")
        steps.append(cp.advance(y, 1e-5, c)[1])
        energy.append(cp.energy(y, c, stiff))
    assert np.diff(energy).max() <= 1e-15
    flips = [k for k in range(399) if joint[k] != joint[k + 1] and both[k] and both[k + 1]]
    assert len(flips) == 1, flips  # one switch with both arcs pressing
    k = flips[0]
    assert max(steps[k - 1 : k + 2]) <= 4
    before, after = np.array(forces[k]), np.array(forces[k + 1])
    assert abs(after.sum() - before.sum()) < 0.02 * c.mass * c.g
    # the discontinuity itself: the rim near 0 on the joint side carries a fifth of the other
    jointly, alone = (before, after) if joint[k] else (after, before)
    low = int(np.argmin(jointly))
    assert jointly[low] < 1e-3 * jointly[1 - low] and alone[low] > 0.1 * alone[1 - low]


MUTANT = """
import math, sys
import numba
sys.path.insert(0, {bench!r})
from coinflight.core import contact_phase as cp
inner = cp.joint_damping

@numba.njit
def uncoupled(w11, w12, w22, k1, k2, zeta):  # C from W without its coupling W12
    return inner(w11, 0.0 * w12, w22, k1, k2, zeta)

{patch}
import bench_two_rims as b
c = b.record(0.5)
print(b.drop(c, 0.5 * math.pi, math.sqrt(2 * 9.81 * 0.1))[0])
"""


@pytest.mark.slow
def test_a_pair_damped_without_its_coupling_fails_the_drop(tmp_path: Path):
    # The mutant: W12 := 0 in the pair's mobility, so C is diagonal (each rim its own
    # 2 ζ sqrt(k_i/W_ii), the per-rim sizing): the upright drop at e 0.5 rebounds at ~0.399
    # and fails test_an_upright_drop_on_both_rims_restitutes_with_e, which holds the unpatched
    # kernels' 0.4987 (so they are not run again here). The kernels compile in tmp_path's
    # numba cache (numba's on-disk index does not see a patched global; the package's cache is
    # not touched).
    bench = str(Path(__file__).resolve().parents[1] / "benchmarks")
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "numba"))
    code = MUTANT.format(bench=bench, patch="cp.joint_damping = uncoupled")
    run = subprocess.run(
        [sys.executable, "-c", textwrap.dedent(code)], capture_output=True, text=True,
        env=env, timeout=900, cwd=tmp_path,
    )  # fmt: skip
    assert run.returncode == 0, run.stderr
    mutant = float(run.stdout.split()[-1])
    assert abs(mutant - 0.5) > 0.09 and mutant == pytest.approx(0.398, abs=0.003)
