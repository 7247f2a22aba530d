"""The one random-stream scheme (coinflight.probability.streams) and its guarantees, extended
from the probability Monte Carlo to the bias and edge simulations: the same seed gives the same
answer however the draws are cut, and a shorter run is a prefix of a longer one."""

from __future__ import annotations

import numpy as np
import pytest

from coinflight.probability import streams
from coinflight.studies import bias as b
from coinflight.studies import edge


def _steps(counts):
    return set(np.diff(counts).tolist())


def test_unit_cube_is_a_prefix_across_blocks_and_draws(monkeypatch):
    monkeypatch.setattr(streams, "BLOCK", 1000)
    root = streams.seed_sequence(8)
    long = np.concatenate(list(streams.unit_cube(root, 2500, 3)), axis=1)
    short = np.concatenate(list(streams.unit_cube(root, 1700, 3)), axis=1)
    np.testing.assert_array_equal(short, long[:, :1700])
    monkeypatch.setattr(streams, "DRAW", 7)  # drawing 7 at a time changes nothing
    np.testing.assert_array_equal(
        np.concatenate(list(streams.unit_cube(root, 2500, 3)), axis=1), long
    )


def test_seed_checked_once_for_every_simulation():
    for bad, error in ((-1, ValueError), (1.5, TypeError), (True, TypeError)):
        with pytest.raises(error, match="seed must be a non-negative integer"):
            b.simulate_same_side(80.0, 100, bad, degrees=True)
        with pytest.raises(error, match="seed must be a non-negative integer"):
            edge.simulate_edge([0.5], 10, bad)


@pytest.mark.parametrize("psi", [80.0, "dist"])
def test_same_side_shorter_run_is_a_prefix_of_a_longer_one(psi):
    # Each extra toss adds 0 or 1 same-side toss: with the old scheme (one stream drawing T,
    # then ωp, then the azimuth) every toss of a run changed with n.
    from coinflight.model.distributions import Normal

    spec = Normal(75.0, 6.0) if psi == "dist" else psi
    counts = [b.simulate_same_side(spec, n, 12, degrees=True).successes for n in range(100, 160)]
    assert _steps(counts) <= {0, 1} and counts[-1] > counts[0]


def test_same_side_does_not_depend_on_how_the_draws_are_cut(monkeypatch):
    one = b.simulate_same_side(70.0, 5000, 3, degrees=True)
    monkeypatch.setattr(streams, "DRAW", 333)
    assert b.simulate_same_side(70.0, 5000, 3, degrees=True) == one


def test_edge_shorter_run_is_a_prefix_and_ratios_are_independent_of_the_list():
    counts = [edge.simulate_edge([0.6], n, 5)[0][1].successes for n in range(1, 40)]
    assert _steps(counts) <= {0, 1} and counts[-1] > 0
    (first,) = edge.simulate_edge([0.6], 300, 5)
    assert edge.simulate_edge([0.6, 0.2], 300, 5)[0] == first


def test_no_seed_draws_one_and_reports_it():
    est = b.simulate_same_side(80.0, 200, degrees=True)
    assert isinstance(est.seed, int)
    assert b.simulate_same_side(80.0, 200, est.seed, degrees=True) == est
    ((_, e),) = edge.simulate_edge([0.5], 50)
    assert edge.simulate_edge([0.5], 50, e.seed)[0][1] == e


def test_same_side_at_several_angles_uses_one_seed_and_independent_streams():
    points = b.simulate_same_side_at([80.0, 80.0], 2000, 4, degrees=True)
    assert [a for a, _ in points] == [80.0, 80.0]
    assert {e.seed for _, e in points} == {4}
    assert points[0][1] != points[1][1]  # child streams 0 and 1 differ
