"""MuJoCo runs carried to rest (coinflight.studies.mujoco_compare, the optional extra): each toss
stops as soon as it has settled, a coin still rolling at the limit is counted as moving, never
dropped, and the edge check compares the same tosses in both engines."""

from __future__ import annotations

import math

import numpy as np
import pytest

from coinflight.core.outcome import EDGE, HEADS
from coinflight.model.coin import Coin
from coinflight.studies import landing as study
from coinflight.studies import mujoco_compare

mujoco = pytest.importorskip("mujoco")

NICKEL = Coin.preset("us-nickel")


def _states(m, poses):
    """mjSTATE_FULLPHYSICS rows of (z, quaternion, lab velocity, body angular velocity)."""
    spec = mujoco.mjtState.mjSTATE_FULLPHYSICS
    d = mujoco.MjData(m)
    out = np.empty((len(poses), mujoco.mj_stateSize(m, spec)))
    for k, (z, quat, vel, omega) in enumerate(poses):
        mujoco.mj_resetData(m, d)
        d.qpos[:3] = (0.0, 0.0, z)
        d.qpos[3:7] = quat
        d.qvel[:3] = vel
        d.qvel[3:6] = omega
        mujoco.mj_getState(m, d, out[k], spec)
    return out


def test_a_flat_coin_stops_early_and_an_edge_roller_is_counted_as_moving():
    # Two coins just above the table: one face-down flat and still, one upright on its rim
    # rolling at 1 m/s (its axis horizontal: body z = lab y, spin u / r about it). The flat
    # one has settled after the first window; the roller (rolling resistance 1e-4 m slows it
    # by ~0.06 m/s², so it rolls for seconds) is still moving at a 0.5 s limit, counted on its
    # edge, not dropped.
    r, hh = NICKEL.radius, NICKEL.thickness / 2
    m = mujoco_compare.model(NICKEL, 0.3, 0.5)
    upright = (math.sqrt(0.5), -math.sqrt(0.5), 0.0, 0.0)  # body z onto lab y
    states = _states(
        m,
        [
            (hh + 1e-5, (1.0, 0.0, 0.0, 0.0), (0.0, 0.0, 0.0), (0.0, 0.0, 0.0)),
            (r + 1e-5, upright, (1.0, 0.0, 0.0), (0.0, 0.0, 1.0 / r)),
        ],
    )
    datas = [mujoco.MjData(m)]
    limit = 0.5
    out = mujoco_compare._carry(m, datas, states, np.zeros(2), NICKEL, 9.81, limit, 1.0)
    assert out.first.tolist() == [HEADS, EDGE]
    assert out.rest.tolist() == [HEADS, EDGE]
    assert out.moving.tolist() == [False, True]
    window = mujoco_compare.WINDOW
    assert out.rest_time[0] <= window + 1e-9  # stopped at the first check, not at the limit
    assert limit <= out.rest_time[1] < limit + window + 1e-9
    assert out.edge_time[0] == 0.0 and out.edge_time[1] > limit - window
    # The cost is the steps each toss needed: the flat coin one window, the roller to the limit.
    steps_per_window = round(window / mujoco_compare.TIMESTEP)
    assert out.steps == steps_per_window * (1 + math.ceil(limit / window + 1e-9))


def test_a_rocking_coin_at_its_turning_point_is_not_at_rest():
    # At rest means slow now and REST_CHECK s before: a coin momentarily still (a turning
    # point) but moving 10 ms earlier has not settled; one still at both times has.
    state = np.zeros(14)
    state[3] = 0.02  # high above the table: not trapped in a face's well by its energy
    state[4] = 1.0
    before = state.copy()
    before[11] = 1.0  # turning at 1 rad/s 10 ms earlier
    edge_sine = NICKEL.thickness / math.hypot(NICKEL.thickness, 2 * NICKEL.radius)
    args = (NICKEL, 9.81, edge_sine)
    assert mujoco_compare._settled(state[None], *args).tolist() == [True]
    assert mujoco_compare._settled(state[None], *args, before[None]).tolist() == [False]
    assert mujoco_compare._settled(state[None], *args, state[None]).tolist() == [True]


def test_mujoco_work_is_bounded_before_it_starts(monkeypatch):
    from coinflight.outcomes import table

    def never(*args, **kwargs):
        raise AssertionError("a landing ran before the work bound")

    monkeypatch.setattr(table, "land", never)
    with pytest.raises(ValueError, match="MuJoCo tosses carried up to 20 s past their first"):
        study.mujoco_comparison(10**6, seed=1)
    with pytest.raises(ValueError, match="settle limit must be a positive number of s, got 0"):
        study.mujoco_comparison(3, seed=1, limit=0.0)


def test_run_from_places_coins_as_given():
    # Lab-frame states (coinflight's hand-off form): a coin face-down at rest (the quaternion
    # for n = −z, the one special case), and one upright rolling along x at 0.5 m/s (spin u / r
    # about its axis n = y): tails at once, and on its edge still rolling at a 0.3 s limit.
    r, hh = NICKEL.radius, NICKEL.thickness / 2
    u = 0.5
    run = mujoco_compare.run_from(
        NICKEL,
        [hh + 1e-5, r + 1e-5],
        [[0.0, 0.0, 0.0], [u, 0.0, 0.0]],
        [[0.0, 0.0, -1.0], [0.0, 1.0, 0.0]],
        [[0.0, 0.0, 0.0], [0.0, u / r, 0.0]],
        0.5,
        0.3,
        3.0,
        threads=1,
        engine=mujoco_compare.Engine(limit=0.3),
    )
    assert run.first.tolist() == [0, EDGE] and run.rest.tolist() == [0, EDGE]
    assert run.moving.tolist() == [False, True]
    q = mujoco_compare._quaternion_to(np.array([[0.0, 0.0, -1.0], [0.6, 0.0, 0.8]]))
    m = np.empty(9)
    mujoco.mju_quat2Mat(m, q[1])
    np.testing.assert_allclose(m.reshape(3, 3)[:, 2], [0.6, 0.0, 0.8], atol=1e-15)
    mujoco.mju_quat2Mat(m, q[0])
    np.testing.assert_allclose(m.reshape(3, 3)[:, 2], [0.0, 0.0, -1.0], atol=1e-15)
