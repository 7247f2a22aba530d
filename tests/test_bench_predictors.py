"""benchmarks/face_predictors.py, the kernels benchmarks/bench_predictors.py measures: their
exact properties, not their accuracy (that is the benchmark's); and the benchmark's refusal of
a bad N or --chunk."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from _bench import bench_script, load_bench
from _cli import script_error
from _kernels import coin_contact, touching_state
from coinflight import Coin
from coinflight.core import contact_phase as cp
from coinflight.core.contact import CONTACT_ENDING
from coinflight.core.outcome import EDGE, HEADS, TAILS

fp = load_bench("face_predictors")
NICKEL = Coin.preset("us-nickel")
FRICTIONLESS = coin_contact(NICKEL, friction=0.0, ending=CONTACT_ENDING)
FRICTION = coin_contact(
    NICKEL,
    friction=0.3,
    rolling_resistance=1e-4,
    pivoting_resistance=1e-4,
    ending=CONTACT_ENDING,
)
SWAP = {TAILS: HEADS, HEADS: TAILS, EDGE: EDGE, -1: -1}

angle = st.floats(-math.pi, math.pi)
rate = st.floats(-40.0, 40.0)
speed = st.floats(-0.3, 0.3)


def _state(polar, azimuth, v, omega, lift):
    """The nickel's touching_state (normal at (polar, azimuth), lowest point ``lift`` m up)."""
    return touching_state(NICKEL, polar, azimuth, v, omega, lift)


states = st.builds(
    _state,
    st.floats(0.0, math.pi),
    angle,
    st.tuples(speed, speed, speed),
    st.tuples(rate, rate, rate),
    st.floats(-2e-5, 2e-3),
)
shares = st.tuples(st.floats(0.0, 1.0), st.floats(0.0, 1.0), st.floats(0.0, 1.0))


def _mirror(y):
    """The same body with heads and tails swapped: n → −n (z, v, L and so ω unchanged)."""
    m = y.copy()
    m[4:7] = -m[4:7]
    return m


@settings(max_examples=100, deadline=None)
@given(states, shares)
def test_mirror_gives_the_other_face(y, share):
    for c in (FRICTIONLESS, FRICTION):
        kappa = cp.stiffness_of(c)
        face = fp.predict(y, c, kappa, *share)
        assert fp.predict(_mirror(y), c, kappa, *share) == SWAP[face]
        # the same numbers, to the bit
        assert fp.corner_barrier(_mirror(y), c, share[0], share[1]) == fp.corner_barrier(
            y, c, share[0], share[1]
        )


@settings(max_examples=100, deadline=None)
@given(states)
def test_frictionless_rule_is_the_contact_phases_own_without_friction(y):
    kappa = cp.stiffness_of(FRICTIONLESS)
    assert fp.corner_barrier(y, FRICTIONLESS, 1.0, 1.0) == cp._barrier(y, FRICTIONLESS)
    free, _ = cp.free_energy(y, FRICTIONLESS, kappa)
    assert fp.lifting_energy(y, FRICTIONLESS, kappa, 1.0) == free
    fired = fp.predict(y, FRICTIONLESS, kappa, 1.0, 1.0, 1.0) >= 0
    assert fired == cp.below_barrier(y, FRICTIONLESS, kappa)


@settings(max_examples=100, deadline=None)
@given(states)
def test_no_share_is_the_proof_with_friction(y):
    """(0, 0) is m g ρ less the two terms of _corner_energy taken back out: equal to rounding
    (a few ulps of m g ρ), so the rule is below_barrier's except within those ulps."""
    kappa = cp.stiffness_of(FRICTION)
    ulps = 8 * math.ulp(FRICTION.barrier)
    assert abs(fp.corner_barrier(y, FRICTION, 0.0, 0.0) - FRICTION.barrier) <= ulps
    fired = fp.predict(y, FRICTION, kappa, 0.0, 0.0, 0.0) >= 0
    if abs(cp.energy(y, FRICTION, kappa) - FRICTION.barrier) > ulps:
        assert fired == cp.below_barrier(y, FRICTION, kappa)


@settings(max_examples=100, deadline=None)
@given(states, shares, st.floats(0.0, 0.5))
def test_more_energy_never_fires_more(y, share, kick):
    """More vertical speed (kinetic energy that no rule sets aside) never turns a rule on."""
    for c in (FRICTIONLESS, FRICTION):
        kappa = cp.stiffness_of(c)
        faster = y.copy()
        faster[3] = math.copysign(abs(y[3]) + kick, y[3])
        assert fp.lifting_energy(faster, c, kappa, share[2]) >= fp.lifting_energy(
            y, c, kappa, share[2]
        )
        if fp.predict(faster, c, kappa, *share) >= 0:
            assert fp.predict(y, c, kappa, *share) >= 0


@settings(max_examples=100, deadline=None)
@given(states, shares, shares)
def test_larger_shares_fire_on_more_states(y, a, b):
    low = tuple(min(p, q) for p, q in zip(a, b, strict=True))
    high = tuple(max(p, q) for p, q in zip(a, b, strict=True))
    kappa = cp.stiffness_of(FRICTION)
    assert fp.corner_barrier(y, FRICTION, high[0], high[1]) >= fp.corner_barrier(
        y, FRICTION, low[0], low[1]
    )
    if fp.predict(y, FRICTION, kappa, *low) >= 0:
        assert fp.predict(y, FRICTION, kappa, *high) >= 0


def test_a_fired_rule_names_the_well_the_coin_is_in():
    """At rest on a face (below every barrier) each rule names that face; tilted into the
    edge well at rest, the edge; a fast toss fires none."""
    kappa = cp.stiffness_of(FRICTION)
    out = np.empty(len(fp.NAMES), dtype=np.int64)
    for polar, face in ((0.0, HEADS), (math.pi, TAILS), (0.5 * math.pi, EDGE)):
        y = _state(polar, 0.3, (0.0, 0.0, 0.0), (0.0, 0.0, 0.0), 0.0)
        fp.predict_all(y, FRICTION, kappa, fp.SHARES, out)
        assert out.tolist() == [face] * len(fp.NAMES)
    y = _state(0.4, 0.3, (0.2, 0.0, 1.0), (150.0, 0.0, 10.0), 0.0)
    fp.predict_all(y, FRICTION, kappa, fp.SHARES, out)
    assert out.tolist() == [-1] * len(fp.NAMES)


@pytest.mark.parametrize("row", range(len(fp.NAMES)))
def test_predict_all_is_predict_row_by_row(row):
    rng = np.random.default_rng(4)
    kappa = cp.stiffness_of(FRICTION)
    out = np.empty(len(fp.NAMES), dtype=np.int64)
    for _ in range(50):
        y = _state(
            rng.uniform(0, math.pi),
            rng.uniform(-math.pi, math.pi),
            rng.uniform(-0.1, 0.1, 3),
            rng.uniform(-10, 10, 3),
            rng.uniform(0, 1e-3),
        )
        fp.predict_all(y, FRICTION, kappa, fp.SHARES, out)
        assert out[row] == fp.predict(y, FRICTION, kappa, *fp.SHARES[row])


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (["0"], "N must be a whole number ≥ 1, got 0"),
        (["3", "--chunk", "0"], "--chunk must be a finite number > 0 (simulated s), got 0.0"),
        (
            ["3", "--chunk=-1e-3"],
            "--chunk must be a finite number > 0 (simulated s), got -0.001",
        ),
        (["3", "--chunk", "inf"], "--chunk must be a finite number > 0 (simulated s), got inf"),
        (["3", "--resistance", "-1"], "--resistance must be a finite number ≥ 0 (m), got -1.0"),
    ],
)
def test_bad_input_is_one_line_before_any_toss(args, words, tmp_path):
    assert script_error(bench_script("bench_predictors"), args, tmp_path) == words
