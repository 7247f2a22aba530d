"""The contact phase (core/contact_phase.py): its limits, invariants and analytic checks."""

from __future__ import annotations

import math

import numpy as np
import pytest

from _kernels import coin_contact, critical_spin, touching_state
from coinflight import Coin
from coinflight.core import contact_phase as cp
from coinflight.core.contact import CONTACT_ENDING, ROCKING_ENDING
from coinflight.core.impact import angular_velocity, contact_point, lowest_depth
from coinflight.core.outcome import EDGE, HEADS, TAILS, Status
from coinflight.model.surface import Drag, Surface
from coinflight.outcomes.table import TableLanding, land

G = 9.81
NICKEL = Coin.preset("us-nickel")
THICK = Coin(radius=0.012, thickness=0.024 / math.sqrt(3), mass=0.005)  # h/d = 1/√3


def _contact(
    coin,
    e=0.5,
    mu=0.3,
    rolling=0.0,
    pivoting=0.0,
    contact_time=1e-3,
    g=G,
    ending=ROCKING_ENDING,
    corner=0.0,
):
    return coin_contact(
        coin,
        restitution=e,
        friction=mu,
        g=g,
        rest_speed=0.01,
        rolling_resistance=rolling,
        pivoting_resistance=pivoting,
        contact_time=contact_time,
        ending=ending,
        corner_radius=corner,
    )


def _schwager_poschel(zeta):
    """Restitution of the linear dashpot whose force is clipped at zero (Schwager & Pöschel,
    Granular Matter 9:465, 2007, eq 19-20 with ω0 = 1, β = ζ), underdamped."""
    w = math.sqrt(1.0 - zeta * zeta)
    if zeta < 1.0 / math.sqrt(2.0):
        wt = math.pi - math.atan(2.0 * zeta * w / (w * w - zeta * zeta))
    else:
        wt = -math.atan(2.0 * zeta * w / (w * w - zeta * zeta))
    return -math.exp(-zeta * wt / w) * (math.cos(wt) - zeta / w * math.sin(wt))


@pytest.mark.parametrize("zeta", [0.05, 0.2, 0.5, 0.8, 0.95])
def test_linear_law_restitution_matches_schwager_poschel(zeta):
    # The integrator of the dimensionless contact against the closed form; 5e-4 is its
    # step's error at the end of contact (dt = 2e-3, end interpolated linearly).
    assert cp.restitution_of(zeta, 1.0) == pytest.approx(_schwager_poschel(zeta), abs=5e-4)


@pytest.mark.parametrize("e", [0.05, 0.3, 0.5, 0.8, 1.0])
def test_damping_ratio_gives_the_restitution_of_a_rim(e):
    zeta = cp.damping_ratio(e)
    assert cp.restitution_of(zeta, 1.5) == pytest.approx(e, abs=1e-9)
    # e = 1 is no damping; less restitution, more damping.
    assert (zeta == 0.0) == (e == 1.0)
    assert cp.damping_ratio(0.4) > cp.damping_ratio(0.6)


def test_tabulated_damping_ratio_restitutes_with_e():
    # The table of ζ(e) (tosses with their own e) against the bisection it was computed by:
    # exact at its nodes (the same function), within 1e-6 e of e between them (the restitution
    # of the interpolated ζ; measured worst 4e-7 e at 64 nodes), the bisection below its range.
    lowest = cp.ZETA_TABLE_LOWEST
    count = len(cp._ZETA_TABLE)
    for k in (0, 17, 40, count - 2):
        e = math.exp(math.log(lowest) * (1 - k / (count - 1)))
        assert cp.tabulated_damping_ratio(e) == pytest.approx(cp.damping_ratio(e), rel=1e-12)
    rng = np.random.default_rng(7)
    for e in np.concatenate([rng.uniform(lowest, 1.0, 12), np.exp(rng.uniform(-4.6, 0.0, 12))]):
        zeta = cp.tabulated_damping_ratio(float(e))
        assert cp.restitution_of(zeta, 1.5) == pytest.approx(e, rel=1e-6)
    assert cp.tabulated_damping_ratio(0.005) == cp.damping_ratio(0.005)
    assert cp.tabulated_damping_ratio(1.0) == 0.0


def test_contact_modes_and_their_statistics():
    # contact_mode: a coin lying flat is on its face, one tilted 0.6 rad on a rim point, one
    # standing upright on both rims (its edge band), one lifted 1 mm off the table free; the
    # statistics of advance() add up to its time and steps.
    c = _contact(NICKEL)
    assert cp.MODES[cp.contact_mode(touching_state(NICKEL, 0.0, lift=-1e-7), c)] == "face"
    assert cp.MODES[cp.contact_mode(touching_state(NICKEL, 0.6, lift=-1e-7), c)] == "one rim"
    assert (
        cp.MODES[cp.contact_mode(touching_state(NICKEL, math.pi / 2, lift=-1e-7), c)] == "two rims"
    )
    assert cp.MODES[cp.contact_mode(touching_state(NICKEL, 0.6, lift=1e-3), c)] == "free"
    y = touching_state(NICKEL, 0.3, omega=(0.2, 0.1, 30.0), lift=0.002)
    stats = np.zeros((len(cp.MODES), 2))
    t, steps, _ = cp.advance(y, 0.2, c, stats=stats)
    assert stats[:, 0].sum() == pytest.approx(t, rel=1e-12)
    assert stats[:, 1].sum() == steps
    assert stats[0, 1] > 0 and stats[1, 1] > 0  # it fell freely, then met the table on a rim


@pytest.mark.parametrize("e", [0.1, 0.3, 0.6, 0.9])
def test_rim_impact_of_a_coin_restitutes_with_e(e):
    # A frictionless coin tilted 0.6 rad hits on its rim at 2 cm/s, without gravity (which
    # would slow the rebound by g t_contact): the rebound velocity of the rim point over its
    # approach is e (Newton's and Stronge's coincide without friction). Tolerance 0.01: the
    # configuration turns during the contact by an angle that grows with the penetration
    # (measured: +0.003 to +0.007 at 2 cm/s, +0.01 to +0.02 at 10 cm/s).
    c = _contact(NICKEL, e=e, mu=0.0, g=0.0)
    y = touching_state(NICKEL, 0.6, v=(0.0, 0.0, -0.02))
    r, hh = NICKEL.radius, NICKEL.thickness / 2
    i1, i3 = (float(x) for x in NICKEL.moments)

    def normal_speed(y):
        n = tuple(y[4:7])
        w = angular_velocity(tuple(y[7:10]), n, i1, i3)
        rc = np.array(contact_point(n, r, hh))
        return y[3] + np.cross(w, rc)[2]

    before = normal_speed(y)
    for _ in range(1000):
        cp.advance(y, 1e-4, c)
        if y[0] > lowest_depth(y[6], r, hh):  # off the table again
            break
    assert normal_speed(y) / -before == pytest.approx(e, abs=0.01)


def _energy_drifts(rtol):
    """Relative energy changes, (E(0.5 s) − E(0)) / E(0), of eight frictionless, elastic drops
    (e = 1, μ = 0, no resistances) of a tilted, spinning nickel on its rim, carried 0.5 s at the
    step tolerance ``rtol`` (drop 0 the one this test began with, seven drawn with seed 5);
    L_z and L·n, conserved by the frictionless contact (no torque about the vertical or the
    normal), are checked on the way: L_z, a linear invariant of the Runge-Kutta steps, to
    rounding, L·n (quadratic) to the step control's errors (10 rtol of the spin's L)."""
    c = _contact(NICKEL, e=1.0, mu=0.0)
    i1, _ = (float(x) for x in NICKEL.moments)
    kappa = cp.stiffness_of(c)
    rng = np.random.default_rng(5)
    drifts = []
    for k in range(8):
        if k == 0:
            tilt, spin = 0.3, (0.2, 0.1, 30.0)
        else:
            tilt = rng.uniform(0.2, 0.6)
            spin = (rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(20.0, 40.0))
        y = touching_state(NICKEL, tilt, omega=spin, lift=0.002)
        e0, ln0, lz0 = cp.energy(y, c, kappa), y[4:7] @ y[7:10], y[9]
        t, _, _ = cp.advance(y, 0.5, c, rtol=rtol)
        assert t == pytest.approx(0.5)
        drifts.append((cp.energy(y, c, kappa) - e0) / e0)
        scale = i1 * spin[2]
        assert abs(y[4:7] @ y[7:10] - ln0) < 10 * rtol * scale
        assert abs(y[9] - lz0) < 1e-12 * scale
    return np.array(drifts)


def test_no_dissipation_conserves_energy_and_momenta():
    # Energy to the step control's error over ~1000 steps and a dozen contacts: it drifts up
    # by ~1e-4 of itself, a different amount for every drop (the motion is chaotic), so eight
    # drops are checked, their median within 2e-4 and each within 5e-4 (measured on 40 such
    # drops, seed 5: median 1.08e-4, largest 2.3e-4; before the stepper kept
    # first-same-as-last across n's renormalisation, 1.18e-4 and 4.3e-4). This test had
    # asserted 1e-4 on the first drop alone: the code before met it there (6.1e-5) and missed
    # it on 28 of the 40; this code misses it on that drop too (1.37e-4), within the new bounds.
    drifts = _energy_drifts(cp.RTOL)
    assert np.median(np.abs(drifts)) < 2e-4
    assert np.max(np.abs(drifts)) < 5e-4


def test_energy_drift_is_the_steppers_and_falls_with_its_tolerance():
    # The drift of the drops above is the stepper's error, not the model's: at a tolerance 100
    # times tighter their median drift is more than 20 times smaller (an error per step
    # ∝ rtol, a 5th-order method's step ∝ rtol^(1/5): ~rtol^(4/5), 40 times for 100; measured
    # medians 9.3e-5 at 1e-7, 1.5e-6 at 1e-9).
    loose = np.median(np.abs(_energy_drifts(cp.RTOL)))
    tight = np.median(np.abs(_energy_drifts(cp.RTOL / 100)))
    assert tight < loose / 20, (loose, tight)


@pytest.mark.parametrize("e", [0.2, 0.7])
def test_frictionless_contact_conserves_lz_and_l_dot_n_and_horizontal_momentum(e):
    # μ = 0 and no resistances, with a dissipative normal force: the contact force is vertical
    # and acts in the plane of n and Z through the rim's lowest point, so L_z, L·n and the
    # horizontal momentum are conserved (the rigid frictionless contact: Stronge 2000, §5);
    # L_z and the momentum to rounding, L·n to the step control's errors (1e-6 of |L|).
    c = _contact(NICKEL, e=e, mu=0.0)
    y = touching_state(NICKEL, 1.0, v=(0.1, -0.2, -0.3), omega=(5.0, -3.0, 20.0))
    ln0, lz0, vh0 = y[4:7] @ y[7:10], y[9], y[1:3].copy()
    cp.advance(y, 0.3, c)
    scale = float(NICKEL.moments[0]) * 20.0
    assert abs(y[4:7] @ y[7:10] - ln0) < 10 * cp.RTOL * scale
    assert abs(y[9] - lz0) < 1e-12 * scale
    np.testing.assert_allclose(y[1:3], vh0, rtol=0, atol=1e-12)


def test_energy_never_grows_with_dissipation():
    c = _contact(NICKEL, e=0.5, mu=0.5, rolling=1e-4, pivoting=1e-4)
    kappa = cp.stiffness_of(c)
    y = touching_state(NICKEL, 0.8, v=(0.2, 0.0, -0.2), omega=(3.0, 10.0, 15.0))
    energies = [cp.energy(y, c, kappa)]
    for _ in range(50):
        cp.advance(y, 0.01, c)
        energies.append(cp.energy(y, c, kappa))
    # Non-increasing up to the integration error (1e-6 of the energy per sample).
    assert np.all(np.diff(energies) <= 1e-6 * energies[0])
    assert energies[-1] < 0.9 * energies[0]


def test_coin_flat_at_rest_stays_at_rest():
    # Lying flat on its face: it sinks by the static compression m g / (2π κ) = g (t_c/π)² and
    # does not move (a tilt below 1e-9 rad, speeds below 1 μm/s over half a second).
    c = _contact(NICKEL)
    y = touching_state(NICKEL, 0.0)
    cp.advance(y, 0.5, c)
    sink = G * (c.contact_time / math.pi) ** 2
    assert y[0] == pytest.approx(NICKEL.thickness / 2 - sink, rel=1e-3)
    assert math.hypot(y[4], y[5]) < 1e-9
    assert np.all(np.abs(y[1:4]) < 1e-6)
    assert np.all(np.abs(y[7:10]) < 1e-9)
    # and the contact phase ends there at once, heads up.
    face, status, t = cp.settle(y[0], tuple(y[1:4]), tuple(y[4:7]), tuple(y[7:10]), c)
    assert (face, status, t) == (HEADS, Status.SETTLED_CONTACT, 0.0)


def _tipping(coin, tilt, rate, sigma):
    """State of a coin at ``tilt`` turning at ``rate`` about Y, pivoting on the lowest point of
    its rim sigma (+1 heads, −1 tails): v = ω × (centre of mass − pivot)."""
    y = touching_state(coin, tilt, omega=(0.0, rate, 0.0))
    n = y[4:7]
    w = np.array([n[2] * n[0], n[2] * n[1], n[2] ** 2 - 1.0])
    w /= np.linalg.norm(w)
    pivot = sigma * coin.thickness / 2 * n + coin.radius * w
    y[1:4] = np.cross([0.0, rate, 0.0], -pivot)
    return y


@pytest.mark.parametrize(("rate", "face"), [(-0.5, HEADS), (0.5, EDGE)])
def test_coin_balanced_on_its_corner_falls_into_the_well_it_tips_to(rate, face):
    # A thick coin (h/d = 1/√3) balanced on its rim with the centre of mass straight above it
    # (tilt arctan(r / (h/2)) from vertical: the top of the heads/edge barrier), tipping at
    # 0.5 rad/s towards its face or towards its edge: it falls into that well and stays.
    corner = math.atan2(THICK.radius, THICK.thickness / 2)
    c = _contact(THICK, e=0.3, mu=0.5, rolling=1e-4, pivoting=1e-4)
    y = _tipping(THICK, corner, rate, -1.0)
    f, status, t = cp.settle(y[0], tuple(y[1:4]), tuple(y[4:7]), tuple(y[7:10]), c)
    assert (f, status) == (face, Status.SETTLED_CONTACT)
    assert 0.0 < t < 1.0


@pytest.mark.parametrize(("tip", "face"), [(-6.0, HEADS), (6.0, TAILS)])
def test_coin_standing_on_its_edge_tipped_falls_to_a_face(tip, face):
    # A nickel standing on its edge (n horizontal, on both rims) tipped at 6 rad/s about the rim
    # it tips over: its ½ (I1 + m ρ²) ω² ≈ 1.3e-5 J is above the edge well's barrier
    # m g (ρ − r) ≈ 2.2e-6 J, so it falls over, onto the face its normal tips towards.
    c = _contact(NICKEL, e=0.3, mu=0.5, rolling=1e-4, pivoting=1e-4)
    sigma = -1.0 if tip < 0 else 1.0
    y = _tipping(NICKEL, math.pi / 2, tip, sigma)
    f, status, _ = cp.settle(y[0], tuple(y[1:4]), tuple(y[4:7]), tuple(y[7:10]), c)
    assert (f, status) == (face, Status.SETTLED_CONTACT)
    # Tipped too gently to pass the corner (1/40 of the energy), it rocks back onto its edge.
    y = _tipping(NICKEL, math.pi / 2, tip / 40.0, sigma)
    f, status, _ = cp.settle(y[0], tuple(y[1:4]), tuple(y[4:7]), tuple(y[7:10]), c)
    assert (f, status) == (EDGE, Status.SETTLED_CONTACT)


def test_steady_rolling_in_place_precesses_at_the_rate_of_eulers_equations():
    # A coin rolling on its rim in place (centre of mass at rest, Euler's disk): ω along the
    # line from the centre of mass to the contact point (no slip), and the steady precession
    # Ω Z × L = rc × m g Z of Euler's equations (Moffatt 2000; O'Reilly 1996) fixes |ω|. No
    # friction force is needed (μ = 0, so none of the drilling friction of a finite arc), and
    # the compliant model must keep the tilt and precess at Ω: tilt within 3e-3 (the nutation
    # set off by the initial compression of ~1 μm), precession angle after 0.1 s (~9 rad)
    # within 0.3 %.
    coin, tilt = NICKEL, 0.5
    c = _contact(coin, e=0.5, mu=0.0)
    i1, i3 = (float(x) for x in coin.moments)
    n = np.array([math.sin(tilt), 0.0, math.cos(tilt)])
    rc = np.array(contact_point(tuple(n), coin.radius, coin.thickness / 2))
    u = rc / np.linalg.norm(rc)

    def momentum(lam):
        w = lam * u
        return w, i1 * w + (i3 - i1) * (w @ n) * n

    w1, l1 = momentum(1.0)
    omega1 = w1[2] - w1[0] * math.cos(tilt) / math.sin(tilt)  # ω = Ω Z + ψ' n
    torque = np.cross(rc, [0.0, 0.0, coin.mass * G])[1]
    lam = math.sqrt(torque / (omega1 * np.cross([0.0, 0.0, 1.0], l1)[1]))
    _, lm = momentum(lam)
    precession = lam * omega1
    y = np.array([lowest_depth(n[2], coin.radius, coin.thickness / 2), 0, 0, 0, *n, *lm])
    turned = 0.0
    angle = 0.0
    for _ in range(10):
        cp.advance(y, 0.01, c)
        new = math.atan2(y[5], y[4])
        turned += (new - angle + math.pi) % (2 * math.pi) - math.pi
        angle = new
        assert abs(y[6] - math.cos(tilt)) < 3e-3
    assert turned == pytest.approx(precession * 0.1, rel=3e-3)


def test_frictionless_spinning_coin_settles_by_its_conserved_momenta():
    # Lying flat and spinning at 100 rad/s with μ = 0: its spin energy (3 times what it would
    # take to stand it on its corner) cannot lift it (L·n and L_z are conserved), so it has
    # settled at once, on its face; with friction the same energy could (a rising spinning
    # egg), so it is carried on until the spin is spent.
    frictionless = _contact(NICKEL, e=0.5, mu=0.0)
    y = touching_state(NICKEL, math.pi, omega=(0.0, 0.0, 100.0))
    f, status, t = cp.settle(y[0], tuple(y[1:4]), tuple(y[4:7]), tuple(y[7:10]), frictionless)
    assert (f, status, t) == (TAILS, Status.SETTLED_CONTACT, 0.0)
    rough = _contact(NICKEL, e=0.5, mu=0.3, pivoting=1e-4)
    f, status, t = cp.settle(y[0], tuple(y[1:4]), tuple(y[4:7]), tuple(y[7:10]), rough)
    assert (f, status) == (TAILS, Status.SETTLED_CONTACT)
    assert t > 0.0


def test_contact_phase_is_bounded():
    # A coin rolling upright on its edge at 1 m/s with no rolling or pivoting resistance rolls
    # for ever: the phase stops after its step limit, unsettled, in the well it is in.
    c = _contact(NICKEL, e=0.5, mu=0.3)
    y = touching_state(NICKEL, math.pi / 2, v=(0.0, 1.0, 0.0), omega=(1.0 / NICKEL.radius, 0, 0))
    t, steps, settled = cp.advance(y, math.inf, c, settle_check=True, max_steps=2_000)
    assert (steps, settled) == (2_000, False)
    assert t > 0.0


@pytest.mark.parametrize(("e", "mu"), [(0.3, 0.1), (0.8, 1.0)])
def test_planar_tosses_are_fair_at_rest(e, mu):
    # Issue 11 ("Done when"): planar tosses (spin about a diameter only) end heads and tails
    # equally often at rest, whatever e and μ: |P(H) − P(T)| within 3 standard errors (of
    # 3,000 tosses here, each rolling on its edge for up to seconds; the benchmark's --planar
    # runs 10⁵).
    n = 3_000
    rng = np.random.default_rng(41)
    omega = np.column_stack([rng.uniform(150.0, 300.0, n), np.zeros(n), np.zeros(n)])
    v0 = rng.uniform(1.5, 3.0, n)
    out = land(NICKEL, omega, v0, 1.0, G, Surface("table", 0.8, e, mu, ending="contact"))
    heads = np.mean(out.face == HEADS)
    tails = np.mean(out.face == TAILS)
    se = math.sqrt((heads + tails - (heads - tails) ** 2) / n)
    assert abs(heads - tails) < 3 * se
    assert np.all(out.status != Status.UNSETTLED)
    assert np.any(out.status == Status.SETTLED_CONTACT)


def test_default_ending_is_the_rocking_hand_off(monkeypatch):
    # The contact phase is opt-in (Surface(ending="contact")): by default a landing ends as it
    # did before it, with the planar rocking of bounce.rock. Checked against the kernel's own
    # Python source run with ``rock`` recorded and ``settle`` forbidden: the same faces and
    # statuses, toss for toss, and rock called for every "settled rocking" toss.
    from coinflight.core import bounce

    assert Surface("table").ending == "rocking"
    assert "ending" not in TableLanding(Surface("table")).to_dict()
    contact = TableLanding(Surface("table", ending="contact"))
    assert contact.to_dict()["ending"] == "contact"
    assert TableLanding(Surface("table")).rate > 100 * contact.rate
    refusal = "ending must be one of rocking, contact, rigid; got 'planar'"
    with pytest.raises(ValueError, match=refusal):
        Surface("table", ending="planar")  # type: ignore[arg-type]
    rng = np.random.default_rng(11)
    n = 40
    omega = np.column_stack(
        [rng.uniform(150.0, 300.0, n), rng.uniform(-30.0, 30.0, n), rng.uniform(-30.0, 30.0, n)]
    )
    v0 = rng.uniform(1.5, 3.0, n)
    surface = Surface("table", 0.8, 0.5, 0.3)
    out = land(NICKEL, omega, v0, 1.0, G, surface)
    assert np.any(out.status == Status.SETTLED_ROCKING)
    # neither of the contact ending's statuses: carried to rest in contact, decided upright
    contact_statuses = [Status.SETTLED_CONTACT, Status.DECIDED_UPRIGHT]
    assert not np.any(np.isin(out.status, contact_statuses))
    # ... which the contact ending gives these tosses (measured: 26 settled, 5 decided of 40)
    by_contact = land(NICKEL, omega, v0, 1.0, G, Surface("table", 0.8, 0.5, 0.3, ending="contact"))
    assert all(np.any(by_contact.status == s) for s in contact_statuses)

    rocked = []
    planar_rocking = bounce.rock

    def rock(*args):
        face = planar_rocking(*args)
        rocked.append(face)
        return face

    def settle(*args):
        raise AssertionError("the default ending called the contact phase")

    land_one = bounce.land_one.py_func
    c = coin_contact(NICKEL)  # as outcomes.table.land builds it, the ending left at its default
    assert c.ending == ROCKING_ENDING
    monkeypatch.setitem(land_one.__globals__, "died_out", bounce.died_out.py_func)
    monkeypatch.setitem(land_one.__globals__, "rock", rock)
    monkeypatch.setitem(land_one.__globals__, "settle", settle)
    for k in range(n):
        face, bounces, _, _, status = land_one(tuple(omega[k]), 1.0, v0[k], c, bounce.MAX_IMPACTS)
        assert (face, bounces, status) == (out.face[k], out.bounces[k], out.status[k])
    assert len(rocked) == np.count_nonzero(out.status == Status.SETTLED_ROCKING)


def _rolling(coin, ratio, tilt):
    """A coin rolling without slip on its rim, its plane tilted by ``tilt`` from the vertical,
    spinning at ``ratio`` times the critical Ω_c (no rolling or pivoting resistance)."""
    spin = ratio * critical_spin(coin)
    return touching_state(
        coin,
        math.pi / 2 - tilt,
        v=(0.0, -spin * coin.radius, 0.0),
        omega=(spin * math.cos(tilt), 0.0, spin * math.sin(tilt)),
    )


def _largest_tilt(coin, y, duration, c):
    """Largest sine of the tilt from the vertical (n_z) over ``duration`` s, every 5 ms."""
    largest = abs(y[6])
    for _ in range(round(duration / 0.005)):
        cp.advance(y, 0.005, c)
        largest = max(largest, abs(y[6]))
    return largest


def test_thin_rolling_disc_falls_below_the_critical_speed_and_stays_up_above():
    # Issue 11: the contact phase against the stability limit of a rolling disc. A thin disc
    # (h = r / 50: a knife edge, its edge well 0.6° wide) rolling upright, tilted 2°, with
    # sticking friction: at half the critical spin the tilt grows and it falls (n_z past 0.5
    # within 0.3 s); at twice the critical spin it rolls on upright, its tilt never above the
    # 2° it started with (plus 10 %) over 0.3 s, ~3 turns.
    disc = Coin(radius=0.01, thickness=0.0002, mass=0.005)
    assert critical_spin(disc) == pytest.approx(math.sqrt(G / (3 * disc.radius)), rel=1e-3)
    c = _contact(disc, e=0.5, mu=1.0)
    start = math.sin(math.radians(2.0))
    assert _largest_tilt(disc, _rolling(disc, 0.5, math.radians(2.0)), 0.3, c) > 0.5
    assert _largest_tilt(disc, _rolling(disc, 2.0, math.radians(2.0)), 0.3, c) < 1.1 * start


def test_slow_nickel_rolling_upright_stays_in_its_sharp_edge_well():
    # Why the contact ending's edge rates are not credible (issue 11): a nickel's rim is
    # modelled as a flat band with sharp corners, so upright it stands in a static well
    # arctan(h / 2r) = 5.3° wide. Rolling at half the critical spin, tilted 2°, it does not fall
    # as the thin disc does: it stays within its well (tilt below 5.3°) for 0.3 s. A real rim
    # with rounded corners has a narrower well (none for fully rounded corners).
    c = _contact(NICKEL, e=0.5, mu=1.0)
    well = c.edge_sine
    assert _largest_tilt(NICKEL, _rolling(NICKEL, 0.5, math.radians(2.0)), 0.3, c) < well


def test_whole_energy_decides_the_well_after_an_impact_in_the_contact_ending():
    # bounce.after_impact: with the contact ending a coin is trapped in its well after an
    # impact only when its whole energy (translation, rotation, height) is below m g ρ, which
    # nothing later can raise; the rocking ending's tumbling energy leaves out the horizontal
    # motion, which friction can still turn into tumbling. A nickel lying flat, sliding at
    # 0.5 m/s (½ m v² = 1.3 barriers above m g h/2): trapped for the rocking ending, not for
    # the contact ending; at 0.1 m/s trapped for both.
    from coinflight.core import bounce

    n = (0.0, 0.0, 1.0)
    z = NICKEL.thickness / 2
    rocking = _contact(NICKEL)
    contact = _contact(NICKEL, ending=CONTACT_ENDING)
    for speed, trapped in ((0.5, False), (0.1, True)):
        v = (speed, 0.0, 0.0)
        face, status, _ = bounce.after_impact(z, v, (0.0, 0.0, 0.0), n, 1.0, contact)
        assert (face, status) == ((HEADS, Status.SETTLED_ENERGY) if trapped else (-1, -1))
        face, status, _ = bounce.after_impact(z, v, (0.0, 0.0, 0.0), n, 1.0, rocking)
        assert (face, status) == (HEADS, Status.SETTLED_ENERGY)
    # The bounces died out (rebound below the rest speed) above the barrier: the contact phase.
    face, status, duration = bounce.after_impact(z, (0.5, 0.0, 0.0), (0.0,) * 3, n, 0.0, contact)
    assert (face, status) == (HEADS, Status.SETTLED_CONTACT)
    assert duration > 0.0


def test_contact_ending_heads_tails_symmetry():
    # Issue 11 ("Done when"): the start-face flip (ω → (ωx, −ωy, −ωz), started tails) is the
    # mirror toss, through the bounces and the contact phase (whose rims are summed lower rim
    # first): exactly the same tosses, faces swapped.
    rng = np.random.default_rng(5)
    n = 200
    omega = np.column_stack(
        [rng.uniform(150.0, 300.0, n), rng.uniform(-30.0, 30.0, n), rng.uniform(-30.0, 30.0, n)]
    )
    v0 = rng.uniform(1.5, 3.0, n)
    surface = Surface("table", 0.8, 0.5, 0.3, ending="contact")
    heads = land(NICKEL, omega, v0, 1.0, G, surface)
    tails = land(NICKEL, omega * [1.0, -1.0, -1.0], v0, -1.0, G, surface)
    assert np.any(heads.status == Status.SETTLED_CONTACT)
    swap = np.array([1, 0, 2], dtype=np.int8)
    np.testing.assert_array_equal(tails.face, swap[heads.face])
    np.testing.assert_array_equal(tails.status, heads.status)
    np.testing.assert_array_equal(tails.settle_time, heads.settle_time)


def test_landing_through_air_ends_in_the_same_contact_phase():
    # core.drag.ending is bounce.after_impact: with a negligible drag the landing through air
    # reaches the same contact phase and the same faces as the exact flights.
    rng = np.random.default_rng(19)
    n = 6
    omega = np.column_stack(
        [rng.uniform(150.0, 300.0, n), rng.uniform(-30.0, 30.0, n), rng.uniform(-30.0, 30.0, n)]
    )
    v0 = rng.uniform(1.5, 3.0, n)
    surface = Surface("table", 0.4, 0.5, 0.3, ending="contact")
    exact = land(NICKEL, omega, v0, 1.0, G, surface)
    air = land(NICKEL, omega, v0, 1.0, G, surface, drag=Drag(coefficient=1e-12))
    assert np.any(exact.status == Status.SETTLED_CONTACT)
    np.testing.assert_array_equal(air.status, exact.status)
    np.testing.assert_array_equal(air.face, exact.face)


def test_rounded_corners_move_the_barrier_and_the_edge_well():
    # Contact.build's corner radius a: the coin is a cylinder (r − a, h/2 − a) swept by a ball
    # of radius a, so its corner sits at a + ρ′ above the table when balanced, ρ′ = sqrt((r −
    # a)² + (h/2 − a)²), and its edge well spans |n_z| < (h/2 − a)/ρ′; a = 0 is the sharp coin.
    sharp = _contact(NICKEL)
    hh, r = NICKEL.thickness / 2, NICKEL.radius
    a = 0.5 * hh
    c = _contact(NICKEL, corner=a)
    inner = math.hypot(r - a, hh - a)
    assert c.barrier == pytest.approx(NICKEL.mass * G * (a + inner), rel=1e-14)
    assert c.edge_sine == pytest.approx((hh - a) / inner, rel=1e-14)
    assert c.barrier < sharp.barrier and c.edge_sine < sharp.edge_sine
    assert c._replace(corner_radius=0.0, barrier=sharp.barrier, edge_sine=sharp.edge_sine) == sharp
    # A coin lying flat rests on its face at z = h/2 whatever its corners (the face's
    # penetration is the same): sunk to the equilibrium of its weight, it stays at rest.
    y = touching_state(NICKEL, 0.0)
    y[0] -= NICKEL.mass * G / (2 * math.pi * cp.stiffness_of(c))
    cp.advance(y, 0.05, c)
    assert abs(y[3]) < 1e-4 and abs(y[6] - 1.0) < 1e-9


def test_fully_rounded_rim_has_no_edge_well():
    # With a = h/2 the rim is a half-round, and the edge well vanishes: a nickel standing upright
    # and nudged at 0.15 rad/s, which the sharp coin's edge well holds (as in
    # test_coin_standing_on_its_edge_tipped_falls_to_a_face), falls onto the face it tips to.
    for a, face in ((0.0, EDGE), (NICKEL.thickness / 2, HEADS)):
        c = _contact(NICKEL, e=0.3, mu=0.5, rolling=1e-4, pivoting=1e-4, corner=a)
        y = _tipping(NICKEL, math.pi / 2, -0.15, -1.0)
        f, status, _ = cp.settle(y[0], tuple(y[1:4]), tuple(y[4:7]), tuple(y[7:10]), c)
        assert (f, status) == (face, Status.SETTLED_CONTACT)
        # and it does lie on that face (with a = h/2 every tilt but upright reads as a face).
        cp.advance(y, 1.0, c)
        assert (y[6] > 0.999) if face == HEADS else (abs(y[6]) < c.edge_sine)


def test_upright_coin_sliding_in_its_plane_rolls_at_two_thirds_of_its_speed():
    """Coulomb friction at the rim, the closed form of a sliding disc (e.g. Goldstein's ball
    and disc problems): a coin standing upright in its edge band, sliding along its plane at v0
    without turning, slips at u = v − ω r decelerating at μ g (1 + m r²/I3) until it rolls at
    v0 / (1 + I3/(m r²)), after a time v0 / (μ g (1 + m r²/I3)); the friction's work
    μ m g × (the slip distance) is the energy lost. Fails if friction acts at the wrong point
    (no torque: no rolling), with the wrong sign, or by more than μ F_n."""
    mu, v0 = 0.3, 0.3
    c = _contact(NICKEL, e=0.5, mu=mu)
    kappa = cp.stiffness_of(c)
    y = touching_state(NICKEL, 0.5 * math.pi, v=(0.0, v0, 0.0))  # n = X, sliding along Y
    y[0] = NICKEL.radius - G * (c.contact_time / math.pi) ** 2  # resting on its band
    i1, i3 = (float(x) for x in NICKEL.moments)
    m, r = NICKEL.mass, NICKEL.radius
    ratio = m * r * r / i3
    rate = mu * G * (1.0 + ratio)
    t_slip = v0 / rate
    e0 = cp.energy(y, c, kappa)
    cp.advance(y, 0.5 * t_slip, c)
    w = angular_velocity(tuple(y[7:10]), tuple(y[4:7]), i1, i3)
    slip = y[2] + w[0] * r  # contact point velocity along Y: v + ω × (−r Z)
    assert slip == pytest.approx(0.5 * v0, rel=0.02)
    assert y[2] == pytest.approx(v0 - mu * G * 0.5 * t_slip, rel=0.01)
    cp.advance(y, 1.5 * t_slip, c)
    w = angular_velocity(tuple(y[7:10]), tuple(y[4:7]), i1, i3)
    rolling = v0 / (1.0 + 1.0 / ratio)
    assert y[2] == pytest.approx(rolling, rel=0.01)
    assert -w[0] * r == pytest.approx(rolling, rel=0.01)
    assert abs(y[6]) < 1e-3  # still upright
    lost = e0 - cp.energy(y, c, kappa)
    work = mu * m * G * v0 * v0 / (2.0 * rate)  # μ m g ∫ u dt, u falling linearly to 0
    assert lost == pytest.approx(work, rel=0.02)


def _roller(coin, c, speed, yaw):
    """A coin upright in its edge band (n = X, on both rims at the static depth), rolling
    without slip along Y at ``speed`` and turning at ``yaw`` rad/s about the vertical."""
    y = touching_state(
        coin, 0.5 * math.pi, v=(0.0, speed, 0.0), omega=(-speed / coin.radius, 0.0, yaw)
    )
    y[0] = coin.radius - cp.static_depth(c, cp.stiffness_of(c))
    return y


def _decided(y, c, budget=cp.MAX_STEPS * cp.MAX_STEP):
    return cp.upright_decided(y, c, cp.stiffness_of(c), cp.damping_of(c), budget)


def _band_moment(coin, speed, yaw):
    """The turn's overturning moment over the band's m g h/2 (sharp corners): gyroscopic
    I3 ω ψ' with ω = v/r, and centripetal m v ψ' at the centre's height r (O'Reilly 1996)."""
    i3 = float(coin.moments[1])
    moment = (i3 * speed / coin.radius + coin.mass * coin.radius * speed) * yaw
    return moment / (coin.mass * G * coin.thickness / 2)


@pytest.mark.parametrize(("speed", "yaw"), [(0.3, 0.0), (0.8, 0.1), (0.1, 0.5), (0.0, 0.0)])
def test_upright_roller_is_decided_on_edge_and_integration_agrees(speed, yaw):
    # Rolling upright in its band with a turn well inside the band's moment and μ N, at rest or
    # not: decided at once (settle: edge, no time; status DECIDED_UPRIGHT for a roller, but
    # SETTLED_CONTACT at rest, where the energy test, taken first, already holds), and carried
    # on to rest without the decision it does end on edge, settled by its energy.
    c = _contact(NICKEL, e=0.5, mu=0.3, rolling=1e-4, pivoting=1e-4, ending=CONTACT_ENDING)
    y = _roller(NICKEL, c, speed, yaw)
    assert _band_moment(NICKEL, speed, yaw) < cp.UPRIGHT_MARGIN
    assert _decided(y, c)
    at_rest = speed == 0.0
    assert cp.below_barrier(y, c, cp.stiffness_of(c)) == at_rest
    f, status, t = cp.settle(y[0], tuple(y[1:4]), tuple(y[4:7]), tuple(y[7:10]), c)
    expected = Status.SETTLED_CONTACT if at_rest else Status.DECIDED_UPRIGHT
    assert (f, status, t) == (EDGE, expected, 0.0)
    assert status is expected  # numba returns the IntEnum member, not a bare integer
    decided = cp.advance(y.copy(), math.inf, c, settle_check=True, decide=True)
    assert decided == (0.0, 0, cp.Ending.SETTLED if at_rest else cp.Ending.DECIDED)
    _, _, ending = cp.advance(y, math.inf, c, settle_check=True)
    assert ending is cp.Ending.SETTLED
    assert abs(y[6]) < c.edge_sine


@pytest.mark.parametrize("share", [1.05, 0.9, 1.01 * cp.UPRIGHT_MARGIN])
def test_upright_roller_turning_beyond_the_bands_moment_is_not_decided(share):
    # The same roller turning so that the overturning moment exceeds the band's m g h/2 (1.05),
    # or is within it but beyond the margin, is left to the integration.
    c = _contact(NICKEL, e=0.5, mu=0.3, rolling=1e-4, pivoting=1e-4, ending=CONTACT_ENDING)
    speed = 0.3
    yaw = share / _band_moment(NICKEL, speed, 1.0)
    assert _band_moment(NICKEL, speed, yaw) == pytest.approx(share)
    assert not _decided(_roller(NICKEL, c, speed, yaw), c)
    assert _decided(_roller(NICKEL, c, speed, 0.98 * cp.UPRIGHT_MARGIN / share * yaw), c)


def test_upright_roller_needing_more_than_mu_n_is_not_decided():
    # A turn the band could hold (moment 0.6 of the margin) but whose centripetal force
    # m v ψ' exceeds μ m g (μ = 0.015): not decided; with μ = 0.3 the same state is.
    speed = 0.3
    yaw = 0.6 * cp.UPRIGHT_MARGIN / _band_moment(NICKEL, speed, 1.0)
    assert speed * yaw > 0.015 * G
    for mu, decided in ((0.015, False), (0.3, True)):
        c = _contact(NICKEL, e=0.5, mu=mu, rolling=1e-4, pivoting=1e-4, ending=CONTACT_ENDING)
        assert _decided(_roller(NICKEL, c, speed, yaw), c) == decided


def test_upright_roller_without_rolling_resistance_is_not_decided_and_settle_carries_it_on():
    # ℓ_r = 0 (allowed by Surface): the roller never stops rolling, so it is not decided and
    # settle gives what carrying it on gives: UNSETTLED after MAX_STEPS, with the same time.
    c = _contact(NICKEL, e=0.5, mu=0.3, rolling=0.0, pivoting=1e-4, ending=CONTACT_ENDING)
    y = _roller(NICKEL, c, 0.3, 0.0)
    assert not _decided(y, c)
    f, status, t = cp.settle(y[0], tuple(y[1:4]), tuple(y[4:7]), tuple(y[7:10]), c)
    on = y.copy()
    t_on, steps, settled = cp.advance(on, math.inf, c, settle_check=True)
    assert (steps, settled) == (cp.MAX_STEPS, False)
    assert (f, status, t) == (EDGE, Status.UNSETTLED, t_on)


def test_upright_roller_rolling_longer_than_the_step_budget_is_not_decided():
    # The rolling resistance brakes ω = v/r at ℓ_r m g / (I3 + m r²) (the torque ℓ_r F_n of
    # _derivative): a roller whose time to stop exceeds the time the steps left can cover is
    # not decided, one within it is (2 % either side of the predicted time).
    rolling, speed = 1e-4, 0.3
    c = _contact(NICKEL, e=0.5, mu=0.3, rolling=rolling, pivoting=1e-4, ending=CONTACT_ENDING)
    i3 = float(NICKEL.moments[1])
    m, r = NICKEL.mass, NICKEL.radius
    stop = (speed / r) * (i3 + m * r * r) / (rolling * m * G)
    y = _roller(NICKEL, c, speed, 0.0)
    assert not _decided(y, c, 0.98 * stop)
    assert _decided(y, c, 1.02 * stop)


def test_upright_roller_not_decided_without_a_band_friction_or_both_rims():
    # No band (a = h/2), no friction, one rim lifted (tilted 0.05 rad: the rims sink ~30 μm,
    # so smaller tilts keep both pressed) or the coin sliding in its plane (0.3 m/s, not
    # rolling): not decided.
    base = dict(e=0.5, mu=0.3, rolling=1e-4, pivoting=1e-4, ending=CONTACT_ENDING)
    c = _contact(NICKEL, **{**base, "corner": NICKEL.thickness / 2})
    assert not _decided(_roller(NICKEL, c, 0.3, 0.0), c)
    c = _contact(NICKEL, **{**base, "mu": 0.0})
    assert not _decided(_roller(NICKEL, c, 0.3, 0.0), c)
    c = _contact(NICKEL, **base)
    y = _roller(NICKEL, c, 0.3, 0.0)
    tilted = touching_state(NICKEL, 0.5 * math.pi - 0.05, v=(0.0, 0.3, 0.0))
    tilted[0] = y[0]
    tilted[7:10] = y[7:10]
    assert not _decided(tilted, c)
    sliding = touching_state(NICKEL, 0.5 * math.pi, v=(0.0, 0.3, 0.0))
    sliding[0] = y[0]
    assert not _decided(sliding, c)


def test_upright_decision_off_is_the_integration_to_the_bit():
    # A toss that lands and comes to roll upright: with the decision the phase stops where
    # upright_decided first holds; without it, the same steps to that point give the same state
    # to the bit (the decision only stops), the probe row records that point, and it goes on
    # to rest on edge.
    c = _contact(NICKEL, e=0.5, mu=0.3, rolling=1e-4, pivoting=1e-4, ending=CONTACT_ENDING)
    start = touching_state(NICKEL, 0.5 * math.pi - 0.05, v=(0.0, 0.4, -0.05), lift=1e-4)
    start[7:10] = _roller(NICKEL, c, 0.4, 2.0)[7:10]
    on = start.copy()
    t_on, steps_on, settled = cp.advance(on, math.inf, c, settle_check=True, decide=True)
    assert settled is cp.Ending.DECIDED and abs(on[6]) < c.edge_sine
    assert _decided(on, c)
    off = start.copy()
    t_off, steps_off, _ = cp.advance(off, math.inf, c, max_steps=steps_on)
    assert steps_off == steps_on
    assert t_off == t_on
    assert np.array_equal(on, off)
    stats = np.zeros((len(cp.MODES) + 1, 2))
    stats[-1] = -1.0
    rest = start.copy()
    t_rest, steps_rest, settled = cp.advance(rest, math.inf, c, settle_check=True, stats=stats)
    assert settled is cp.Ending.SETTLED and abs(rest[6]) < c.edge_sine
    assert tuple(stats[-1]) == (t_on, steps_on)
    assert steps_rest > steps_on and t_rest > t_on


def test_decided_upright_is_the_status_exactly_where_the_decision_ended_the_phase():
    # Seeded vigorous tosses (μ 0.6, where a quarter of the handed coins end upright): a
    # landing's status is DECIDED_UPRIGHT exactly where the phase's probe row says
    # upright_decided first held (the handed state rebuilt by bounce_loop and carried on with
    # the decision, advance(decide=True)), all of them on edge, and every other handed coin
    # SETTLED_CONTACT. Carried on to rest without the decision (decide=False), a decided coin
    # settles by its energy (Ending.SETTLED: never DECIDED without decide), on edge, at a later
    # time; its face and the landing's other fields are those of the decided run.
    from coinflight.core import bounce
    from coinflight.outcomes.table import contact_record

    surface = Surface("table", 0.8, 0.5, 0.6, ending="contact")
    n = 60
    rng = np.random.default_rng(11)
    omega = np.column_stack(
        [rng.uniform(150.0, 300.0, n), rng.uniform(-30.0, 30.0, n), rng.uniform(-30.0, 30.0, n)]
    )
    v0 = rng.uniform(1.5, 3.0, n)
    out = land(NICKEL, omega, v0, 1.0, G, surface)
    c = contact_record(NICKEL, surface, G)
    fired = np.zeros(n, dtype=bool)
    handed = np.zeros(n, dtype=bool)
    for k in range(n):
        *_, status, z, v, nn, lm = bounce.bounce_loop(
            tuple(omega[k]), 1.0, v0[k], c, bounce.MAX_IMPACTS
        )
        if status != bounce.DIED_OUT:
            assert out.status[k] == status
            continue
        handed[k] = True
        y = np.array([z, *v, *nn, *lm])
        stats = np.zeros((len(cp.MODES) + 1, 2))
        stats[-1] = -1.0
        on = y.copy()
        t_on, steps_on, ending = cp.advance(
            on, math.inf, c, settle_check=True, decide=True, stats=stats
        )
        fired[k] = stats[-1, 1] >= 0.0
        assert (ending is cp.Ending.DECIDED) == fired[k]
        if fired[k]:
            assert tuple(stats[-1]) == (t_on, steps_on)
            _, _, carried = cp.advance(y, math.inf, c, settle_check=True, decide=False)
            assert carried is cp.Ending.SETTLED
            assert abs(y[6]) < c.edge_sine
    decided = out.status == Status.DECIDED_UPRIGHT
    np.testing.assert_array_equal(decided, fired)
    assert 5 <= decided.sum() < handed.sum()  # both kinds occur (measured: 16 of 43 handed)
    assert np.all(out.face[decided] == EDGE)
    assert np.all(out.status[handed & ~decided] == Status.SETTLED_CONTACT)


def test_contact_ending_describe_says_its_time_is_the_decisions():
    # The contact ending's settle_time is when the outcome was decided (at rest or below the
    # barrier: "settled in contact"; an upright roller decided on edge, possibly still rolling:
    # "decided upright"): the line says which, with the settle_time it reports. The two
    # tosses found by a scan of ωx and T (drop 0.5 m, e 0.3, μ 0.3, ℓ_r = ℓ_p = 1e-4 m).
    from coinflight import Toss
    from coinflight.outcomes.table import Landing
    from coinflight.queries.toss import landing_fields, landing_line

    surface = Surface(
        "table", 0.5, 0.3, ending="contact", rolling_resistance=1e-4, pivoting_resistance=1e-4
    )
    landing = Landing(NICKEL, Toss((240.0, 5.0, 3.0), 0.49), surface)
    out = landing_fields(landing.outcome)
    assert out["status"] == "settled in contact"
    text = landing_line(landing.outcome)
    assert f"decided at t = {out['settle_time']:.4f} s" in text
    assert "at rest or below its well's barrier; settled in contact" in text
    landing = Landing(NICKEL, Toss((220.0, 5.0, 3.0), 0.48), surface)
    out = landing_fields(landing.outcome)
    assert (out["outcome"], out["status"]) == ("edge", "decided upright")
    assert int(landing.outcome.status) == Status.DECIDED_UPRIGHT
    text = landing_line(landing.outcome)
    assert f"decided at t = {out['settle_time']:.4f} s while rolling upright" in text
    assert "a measured predictor of ending on edge, not a proof; decided upright" in text


def test_decided_upright_rollers_carried_on_end_on_edge_at_rest():
    # States chosen to stress the decision (seed 2026): turns using 0.4-0.5 of the band's
    # moment m g h′, lean rates up to ±1 rad/s, tilts up to ±0.01 rad, sharp or 0.5 mm
    # corners, 0.3-1 m/s, e ~ U(0.2, 0.8), μ ~ U(0.3, 0.6), ℓ_r = ℓ_p = 3e-3 m (short rolls).
    # Each state upright_decided takes is carried on without the decision (decide=False):
    # every one must come to rest, on edge (the decision is a measured predictor, not a proof).
    rng = np.random.default_rng(2026)
    i3 = float(NICKEL.moments[1])
    m, r = NICKEL.mass, NICKEL.radius
    decided = 0
    for _ in range(1000):
        corner = float(rng.choice([0.0, 5e-4]))
        c = _contact(
            NICKEL,
            e=rng.uniform(0.2, 0.8),
            mu=rng.uniform(0.3, 0.6),
            rolling=3e-3,
            pivoting=3e-3,
            ending=CONTACT_ENDING,
            corner=corner,
        )
        hb = NICKEL.thickness / 2 - corner
        speed = rng.uniform(0.3, 1.0)
        share = rng.uniform(0.4, 0.5)
        yaw = share * m * G * hb / ((i3 / r + m * r) * speed) * rng.choice([-1.0, 1.0])
        lean_rate = rng.uniform(-1.0, 1.0)
        tilt = 0.5 * math.pi + rng.uniform(-0.01, 0.01)
        y = touching_state(NICKEL, tilt, v=(0.0, speed, 0.0), omega=(-speed / r, lean_rate, yaw))
        y[0] = r - cp.static_depth(c, cp.stiffness_of(c))
        if not _decided(y, c):
            continue
        decided += 1
        _, _, settled = cp.advance(y, math.inf, c, settle_check=True, decide=False)
        assert settled, (decided, speed, yaw, lean_rate, corner)
        assert abs(y[6]) < c.edge_sine, (decided, speed, yaw, lean_rate, corner)
        if decided == 30:
            break
    assert decided == 30


def test_energy_test_shortcut_decides_as_the_whole_energy():
    # below_barrier (the test after every step) skips the springs' energies when the rest of
    # the energy already reaches the barrier; it must decide as free_energy's free < barrier on
    # every state, with friction (barrier m g ρ) and frictionless (the 3-D corner barrier).
    # States around the barrier, pressed into the table by up to 20 μm and tilted every way,
    # so that both the shortcut and the full sum are taken and both answers occur.
    rng = np.random.default_rng(11)
    taken = {"shortcut": 0, "full": 0, "below": 0, "above": 0}
    for mu in (0.3, 0.0):
        c = _contact(NICKEL, e=0.5, mu=mu)
        kappa = cp.stiffness_of(c)
        for _ in range(4000):
            tilt = rng.uniform(0.0, math.pi)
            speed = rng.uniform(0.0, 0.3) * rng.choice([0.0, 1.0])
            spin = rng.uniform(-20.0, 20.0, 3) * rng.choice([0.0, 0.3, 1.0])
            y = touching_state(NICKEL, tilt, v=rng.normal(0.0, speed, 3), omega=spin)
            y[0] -= rng.uniform(0.0, 2e-5)
            free, barrier = cp.free_energy(y, c, kappa)
            decided = cp.below_barrier(y, c, kappa)
            assert decided == (free < barrier)
            motion = cp._motion_energy(y, c)
            if mu == 0.0:
                motion -= 0.5 * c.mass * (y[1] ** 2 + y[2] ** 2)
            taken["shortcut" if motion >= barrier else "full"] += 1
            taken["below" if decided else "above"] += 1
    assert min(taken.values()) > 100, taken


def _arc_energy_closed_form(y, coin, stiffness):
    """The lower rim's elastic energy by rim_contact's closed form, ½ κ (a² i0 + 2ab ic +
    b² icc), without its clamp at 0 (corner radius 0)."""
    hh = coin.thickness / 2
    a = -y[0] + hh * y[6]
    b = coin.radius * math.sqrt(1.0 - y[6] ** 2)
    cos = -a / b
    phi = math.acos(cos)
    sin = math.sqrt((1.0 - cos) * (1.0 + cos))
    terms = a * a * 2.0 * phi + 2.0 * a * b * 2.0 * sin + b * b * (phi + sin * cos)
    return 0.5 * stiffness * terms


def test_energy_test_shortcut_holds_where_the_springs_closed_form_is_negative():
    # below_barrier's shortcut is exact because the springs' energies are ≥ 0; their closed
    # form cancels on a short arc (a coin pressed 1e-11 to 1e-10 m into the table), where it is
    # negative by rounding, so rim_contact clamps it at 0. Built here: such an arc, and the rest
    # of the energy on the barrier (the least vertical speed that reaches it), so that a
    # negative spring energy would bring the whole energy below the barrier (free < barrier)
    # while the shortcut says not below. κ = 1e9 N/m (a stiffer contact) makes the negative
    # closed form, ~3e-24 J per N/m here, larger than the barrier's rounding (~1e-19 J).
    c = _contact(NICKEL, e=0.5, mu=0.3)
    kappa = 1e9
    base = touching_state(NICKEL, 1.2)
    closed = {}
    for depth in np.logspace(-11, -9.5, 60):
        y = base.copy()
        y[0] -= depth
        closed[depth] = _arc_energy_closed_form(y, NICKEL, kappa)
    depth = min(closed, key=closed.get)
    assert closed[depth] < -1e-16  # the closed form is negative, above the rounding below
    y = base.copy()
    y[0] -= depth
    rest = cp._motion_energy(y, c)
    barrier = c.barrier
    assert rest < barrier
    y[3] = math.sqrt(2.0 * (barrier - rest) / c.mass)
    while cp._motion_energy(y, c) < barrier:
        y[3] = np.nextafter(y[3], np.inf)
    assert cp._motion_energy(y, c) - barrier < -closed[depth] / 100  # on the barrier
    free, at = cp.free_energy(y, c, kappa)
    assert at == barrier and free >= barrier
    assert not cp.below_barrier(y, c, kappa)
    spring = cp.rim_contact(
        -1.0,
        y[0],
        (y[1], y[2], y[3]),
        (y[4], y[5], y[6]),
        (0.0, 0.0, 0.0),
        NICKEL.radius,
        NICKEL.thickness / 2,
        c.mass,
        c.i1,
        c.i3,
        kappa,
        0.0,
    )[3]
    assert spring == 0.0


@pytest.mark.parametrize(
    ("tilt", "v", "omega"),
    [
        (0.8, (0.2, 0.0, -0.2), (3.0, 10.0, 15.0)),  # one rim, sliding and spinning
        (1.4, (0.1, 0.05, -0.1), (0.0, 0.0, 8.0)),  # near the edge band, yawing
        (1.55, (0.3, 0.0, 0.0), (0.0, -25.0, 2.0)),  # upright, rolling
    ],
)
def test_integration_agrees_with_a_tight_reference_of_the_same_equations(tilt, v, omega):
    # The stepper (Dormand-Prince 5(4) at RTOL, first same as last across n's renormalisation,
    # the derivative of _rim) against SciPy's DOP853 at rtol 1e-12 on the same right-hand side
    # (cp._derivative), 20 ms from a coin touching the table: every component within 1e-4 of
    # the step control's scales at RTOL (5 times the largest difference measured on these
    # cases, 2e-5; the code before the first-same-as-last change differed from the reference
    # alike; up to 3.6e-4 on a coin dropped flat 1 mm, not tested: the contact's kinks, its
    # onset and the d^(3/2) law lower the order), and within 4e-7 at RTOL/100 (measured
    # 7.7e-9 to 7.6e-8). The second bound is the one a wrong first-same-as-last stage fails:
    # k6 carried instead of k7 differs by 6.5e-5 at RTOL (within 1e-4) but by 7.8e-7 to 2.6e-6
    # at RTOL/100 on all three cases (measured by making that change).
    from scipy.integrate import solve_ivp

    c = _contact(NICKEL, e=0.5, mu=0.3, rolling=1e-4, pivoting=1e-4)
    kappa, zeta = cp.stiffness_of(c), cp.damping_of(c)
    i1, _ = (float(x) for x in NICKEL.moments)
    y0 = touching_state(NICKEL, tilt, v=v, omega=omega)

    def rhs(_t, y):
        out = np.empty(10)
        cp._derivative(np.ascontiguousarray(y), out, c, kappa, zeta)
        return out

    speed = max(math.sqrt(G * c.reach), 0.01)
    scale = np.array([c.reach, *(3 * [speed]), 1.0, 1.0, 1.0, *(3 * [i1 * speed / c.reach])])
    ref = solve_ivp(rhs, (0.0, 0.02), y0, method="DOP853", rtol=1e-12, atol=1e-14 * scale)
    assert ref.success
    for rtol, bound in ((cp.RTOL, 1e-4), (cp.RTOL / 100, 4e-7)):
        y = y0.copy()
        t, steps, _ = cp.advance(y, 0.02, c, rtol=rtol)
        assert t == pytest.approx(0.02) and steps > 10
        assert np.max(np.abs(y - ref.y[:, -1]) / scale) < bound, rtol
