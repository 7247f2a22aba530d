"""Landing on a table: exact first contact, settling, heads↔tails symmetry, edge statistics."""

from __future__ import annotations

import math
import os
import subprocess
import sys

import numpy as np
import pytest
from scipy.optimize import brentq

from coinflight import Coin, Flight, Toss
from coinflight.core.outcome import EDGE, HEADS, TAILS, Status
from coinflight.model.surface import Drag, Surface
from coinflight.outcomes.table import Landing, TableLanding, land

G = 9.81
NICKEL = Coin.preset("us-nickel")
THICK = Coin(radius=0.012, thickness=0.024 / math.sqrt(3), mass=0.005)  # h/d = 1/√3


def _tosses(n, seed, planar=False):
    rng = np.random.default_rng(seed)
    omega = np.column_stack(
        [
            rng.uniform(150.0, 300.0, n),
            np.zeros(n) if planar else rng.uniform(-30.0, 30.0, n),
            np.zeros(n) if planar else rng.uniform(-30.0, 30.0, n),
        ]
    )
    return omega, rng.uniform(1.5, 3.0, n)


def _first_contact_by_scipy(coin, omega, v0, drop):
    """First time after the apex at which the closed-form flight's lowest point meets the table."""
    toss = Toss.from_launch_speed(omega, v0)
    flight = Flight(coin, toss)
    r, hh = coin.radius, 0.5 * coin.thickness

    def gap(t):
        state = flight.at(t)
        nz = state.normal[..., 2]
        return state.height + drop - r * np.sqrt(1 - nz * nz) - hh * np.abs(nz)

    # 400 samples per turn at 300 rad/s: no dip of the gap below zero falls between two.
    t = np.linspace(v0 / G, 2 * v0 / G + 0.5, 20_001)
    values = gap(t)
    k = int(np.argmax(values <= 0))
    tc = brentq(lambda s: float(gap(s)), t[k - 1], t[k], xtol=1e-15)
    nz = float(flight.at(tc).normal[2])
    edge_sine = hh / math.hypot(r, hh)
    face = 2 if abs(nz) < edge_sine else (1 if nz > 0 else 0)
    return tc, face


@pytest.mark.parametrize("coin", [NICKEL, THICK], ids=["nickel", "thick"])
def test_restitution_zero_no_friction_is_first_contact_outcome(coin):
    omega, v0 = _tosses(8, 7)
    surface = Surface("table", drop_height=0.3, restitution=0.0, friction=0.0)
    out = land(coin, omega, v0, 1.0, G, surface)
    for k in range(len(v0)):
        tc, face = _first_contact_by_scipy(coin, omega[k], v0[k], 0.3)
        assert out.first_contact[k] == pytest.approx(tc, abs=1e-9)
        assert out.face[k] == face
        assert out.bounces[k] == 0
    # Stopping at the first contact (a basin map after 0 bounces) sees the same wells.
    first = land(coin, omega, v0, 1.0, G, Surface("table", 0.3, 0.7, 0.4), max_bounces=0)
    np.testing.assert_array_equal(first.face, out.face)
    np.testing.assert_allclose(first.first_contact, out.first_contact, rtol=0, atol=1e-12)


def test_bouncing_coin_settles():
    """Every vigorous landing settles: below the face/edge barrier after a bounce, or carried
    to rest by the rigid ending (200 landings carried to rest; none stops at the safety limit,
    none is reported rocking, the retired code)."""
    omega, v0 = _tosses(200, 11)
    out = land(NICKEL, omega, v0, 1.0, G, Surface("table", 0.8, 0.5, 0.3))
    settled = np.isin(out.status, [Status.SETTLED_ENERGY, Status.SETTLED_CONTACT])
    assert settled.all()
    assert np.any(out.status == Status.SETTLED_CONTACT)
    assert (out.bounces >= 1).mean() > 0.9
    assert np.all(out.settle_time >= out.first_contact)
    assert set(np.unique(out.face)) <= {0, 1, 2}


@pytest.mark.parametrize(
    ("coin", "restitution", "friction"),
    [(THICK, 0.6, 0.3), (NICKEL, 0.5, 1.0), (NICKEL, 0.0, 0.3), (THICK, 1.0, 0.0)],
)
def test_heads_tails_symmetry(coin, restitution, friction):
    # A half turn about a diameter swaps the faces and leaves the cylinder as it was: started
    # tails with ω = (ωx, −ωy, −ωz) is the mirror toss of started heads with (ωx, ωy, ωz). The
    # lab-frame state is the same with n → −n, on which the contact point, the collision matrix
    # and the impact law depend only through sign-symmetric terms: exactly the same tosses,
    # the same faces and statuses through the rigid ending too (60 tosses: landings carried to
    # rest cost milliseconds; e = 1, which never dies out, stops at the 2,000 impacts' safety
    # limit, a millisecond a toss: 500; a dead landing, e = 0, is fast: 5,000). The bounces'
    # times are the same to the bit; the rigid ending's integration is not bit-symmetric (its
    # rounding differs in the mirror: measured up to 1e-15 relative, grown by its events to
    # 5e-4 relative on one in sixty), so its settle times are not compared to the bit.
    omega, v0 = _tosses({0.0: 5_000, 1.0: 500}.get(restitution, 60), 13)
    surface = Surface("table", 0.5, restitution, friction)
    heads = land(coin, omega, v0, 1.0, G, surface)
    tails = land(coin, omega * [1.0, -1.0, -1.0], v0, -1.0, G, surface)
    swap = np.array([1, 0, 2], dtype=np.int8)
    np.testing.assert_array_equal(tails.face, swap[heads.face])
    np.testing.assert_array_equal(tails.bounces, heads.bounces)
    np.testing.assert_array_equal(tails.status, heads.status)
    np.testing.assert_array_equal(tails.first_contact, heads.first_contact)
    bounces_only = heads.status != Status.SETTLED_CONTACT
    if restitution in (0.5, 0.6):
        assert 0 < np.sum(bounces_only) < len(v0)  # both kinds of landing are compared
    np.testing.assert_array_equal(tails.settle_time[bounces_only], heads.settle_time[bounces_only])


@pytest.mark.parametrize("friction", [0.0, 0.3, 1.0, 2.0])
def test_restitution_zero_never_bounces(friction):
    # Issue 11: with the sequential Newton-then-friction impulse, friction lifted the rim off
    # the table and 8-19 % of "dead" landings flew again. Stronge's law with e = 0 ends the
    # impact at u_z = 0, whatever the friction: the coin stays at its first contact.
    omega, v0 = _tosses(20_000, 23)
    out = land(NICKEL, omega, v0, 1.0, G, Surface("table", 0.8, 0.0, friction))
    assert np.all(out.bounces == 0)
    assert np.all(np.isin(out.status, [Status.SETTLED_DEAD, Status.SETTLED_ENERGY]))
    first = land(NICKEL, omega, v0, 1.0, G, Surface("table", 0.8, 0.0, friction), max_bounces=0)
    np.testing.assert_array_equal(out.face, first.face)


def test_planar_tosses_reproduce_yong_mahadevan_dynamic_edge_probability():
    # Yong & Mahadevan 2011 (REFERENCES §5): vigorous planar tosses landing without bounce
    # give P(edge) = 2 arctan(h/d)/π = 1/3 at h/d = 1/√3. Tolerance: 4 binomial sd.
    n = 100_000
    omega, v0 = _tosses(n, 17, planar=True)
    out = land(THICK, omega, v0, 1.0, G, Surface("table", 0.5, 0.0, 0.0))
    p = float(np.mean(out.face == 2))
    assert abs(p - 1 / 3) < 4 * math.sqrt(p * (1 - p) / n)


def test_drag_path_agrees_with_kernel_without_drag():
    # The SciPy path (event location on the integrated flight) with a negligible drag against
    # the exact event-driven kernel: the same bounces and outcome, contact times to 1e-8 s.
    omega, v0 = _tosses(3, 19)
    surface = Surface("table", 0.4, 0.5, 0.3)
    exact = land(NICKEL, omega, v0, 1.0, G, surface)
    slow = land(NICKEL, omega, v0, 1.0, G, surface, drag=Drag(coefficient=1e-12))
    np.testing.assert_array_equal(slow.face, exact.face)
    np.testing.assert_array_equal(slow.bounces, exact.bounces)
    np.testing.assert_allclose(slow.first_contact, exact.first_contact, atol=1e-8)
    # Every later contact too (DOP853 at rtol 1e-12 against the closed form).
    np.testing.assert_allclose(slow.settle_time, exact.settle_time, atol=1e-8)


def test_landing_value_object_and_table_model():
    toss = Toss(omega=[[240.0, 5.0, 3.0], [200.0, 0.0, 0.0]], flight_time=0.49)
    landing = Landing(NICKEL, toss, Surface("table", 0.8))
    assert landing.outcome.face.shape == (2,)
    single = Landing(NICKEL, Toss((240.0, 5.0, 3.0), 0.49), Surface("table", 0.8)).outcome
    assert single.face_name == ("heads", "tails", "edge")[[1, 0, 2].index(int(single.face))]
    assert single.face == landing.outcome.face[0]
    model = TableLanding(Surface("table", 0.8))
    assert model.name == "table landing"


@pytest.mark.parametrize(
    ("call", "match"),
    [
        (lambda: Surface("table", restitution=1.2), "restitution must be between 0 and 1"),
        (lambda: Surface("table", restitution=-0.1), "restitution must be between 0 and 1"),
        (lambda: Surface("table", friction=-0.1), "friction must be between 0 and 3"),
        (lambda: Surface("table", friction=3.5), "friction must be between 0 and 3, got 3.5"),
        (lambda: Surface("table", drop_height=-0.2), "surface above the launch point"),
        (lambda: Surface("floor"), "surface must be one of hand, table"),
        (
            lambda: Landing(NICKEL, Toss((200.0, 0, 0), 0.05), Surface("table", 0.0)).outcome,
            "the coin must clear the surface",
        ),
    ],
)
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()


@pytest.mark.parametrize("spin_z", [0.0, 50.0])
def test_flat_drop_bounces_straight_and_stays_up(spin_z):
    # No tumbling: the coin falls flat, hits with its whole face (contact at the centre), bounces
    # straight up with e times the speed, and ends the face it started with.
    for start, face in ((1.0, 1), (-1.0, 0)):
        out = land(
            NICKEL, np.array([[0.0, 0.0, spin_z]]), 1.0, start, G, Surface("table", 0.5, 0.5, 0.3)
        )
        assert out.face[0] == face
        assert out.status[0] == Status.SETTLED_ENERGY
        # First contact: the face, h/2 below the centre of mass, reaches the table.
        z0, v0 = 0.5 - NICKEL.thickness / 2, 1.0
        t_first = (v0 + math.sqrt(v0 * v0 + 2 * G * z0)) / G
        assert out.first_contact[0] == pytest.approx(t_first, rel=1e-12)


def test_benchmark_labels_heads_and_tails_by_the_face_codes():
    # benchmarks/bench_bounce.py printed np.bincount(face) (ordered TAILS, HEADS, EDGE) as
    # "P(heads, tails, edge)": three heads, one tails and one edge must read 0.6, 0.2, 0.2.
    from benchmarks.bench_bounce import face_fractions

    face = np.array([HEADS, HEADS, TAILS, HEADS, EDGE], dtype=np.int8)
    assert face_fractions(face) == "P(heads, tails, edge) = (0.6000, 0.2000, 2.00e-01)"


_FORK_AFTER_SERIAL = """
import os, sys
import numpy as np
from _kernels import coin_contact
from coinflight import Coin
from coinflight.core import bounce

c = coin_contact(Coin.preset("us-nickel"), drop_height=0.3)
rng = np.random.default_rng(3)
omega = np.column_stack([rng.uniform(150, 300, 8), rng.uniform(-5, 5, 8), np.full(8, 20.0)])
speed = rng.uniform(2.0, 3.0, 8)
serial = bounce.land(omega, speed, 1.0, c, parallel=False)
pid = os.fork()
if pid == 0:
    together = bounce.land(omega, speed, 1.0, c, parallel=True)
    same = all(np.array_equal(a, b) for a, b in zip(serial, together))
    os._exit(0 if same else 3)
sys.exit(os.waitstatus_to_exitcode(os.waitpid(pid, 0)[1]))
"""


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="fork() as on Linux")
def test_parallel_landing_in_a_child_forked_after_a_serial_one():
    # A serial landing must not start numba's threading layer: a process forked after it that
    # runs the parallel kernel was killed with GNU OpenMP ("Terminating: fork() called from a
    # process already using GNU OpenMP", SIGTERM) when land() entered numba's
    # parallel_chunksize (which starts the layer) for parallel=False too. The child's parallel
    # landing must end (exit 0) with the serial one's results.
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(p for p in sys.path if p)}
    run = subprocess.run(
        [sys.executable, "-c", _FORK_AFTER_SERIAL],
        env=env,
        capture_output=True,
        text=True,
        timeout=900,
        check=False,
    )
    assert run.returncode == 0, (run.returncode, run.stderr[-2000:])
