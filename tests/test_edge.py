"""Thick coins: Yong & Mahadevan's closed forms for P(edge) and the ratios for P(edge) = 1/3."""

from __future__ import annotations

import math

import numpy as np
import pytest

from coinflight.edge import edge_probability, ratio_for


# Yong & Mahadevan 2011 (REFERENCES §5): P(edge) = 1/3 at h/d = 1/(2√2) ≈ 0.354 for a random
# orientation at rest, and at h/d = 1/√3 ≈ 0.577 for vigorous planar tosses without bounce.
@pytest.mark.parametrize(
    ("model", "ratio", "printed"),
    [("geometric", 1 / (2 * math.sqrt(2)), 0.354), ("dynamic", 1 / math.sqrt(3), 0.577)],
)
def test_ratio_for_one_third(model, ratio, printed):
    found = ratio_for(1 / 3, model)
    assert found == pytest.approx(ratio, rel=1e-12)
    assert round(found, 3) == printed
    assert float(edge_probability(found, model)) == pytest.approx(1 / 3, rel=1e-12)


@pytest.mark.parametrize("model", ["geometric", "dynamic"])
def test_edge_probability_limits_and_monotone(model):
    x = np.linspace(0.0, 50.0, 2001)
    p = edge_probability(x, model)
    assert p[0] == 0.0
    assert np.all(np.diff(p) > 0)
    assert p[-1] == pytest.approx(1.0, abs=0.02)


def test_geometric_is_solid_angle_fraction():
    # Monte Carlo over uniformly random directions of the vertical in the coin's frame: edge iff
    # the vertical is within arctan(h/d) of the coin's plane. 10⁶ draws: binomial sd ≈ 4.7e-4.
    rng = np.random.default_rng(20110101)
    u = rng.normal(size=(1_000_000, 3))
    u /= np.linalg.norm(u, axis=1, keepdims=True)
    ratio = 0.3
    edge = np.abs(u[:, 2]) < math.sin(math.atan(ratio))
    p = float(edge_probability(ratio, "geometric"))
    assert edge.mean() == pytest.approx(p, abs=5 * math.sqrt(p * (1 - p) / edge.size))


@pytest.mark.parametrize(
    ("call", "match"),
    [
        (lambda: edge_probability(-0.1), "ratio must be non-negative"),
        (lambda: edge_probability(0.1, "magic"), "edge model must be one of"),
        (lambda: ratio_for(1.0), "strictly between 0 and 1"),
        (lambda: ratio_for(1.5), "between 0 and 1"),
    ],
)
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()
