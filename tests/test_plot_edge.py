""":func:`coinflight.plotting.edge.plot_edge` with simulated points: what was simulated, and how
far each point sits from each model."""

from __future__ import annotations

import math

import numpy as np
import pytest

from coinflight.plotting.edge import model_distance, plot_edge, simulation_text
from coinflight.probability.result import BinomialEstimate

# At h/d = 1/√3 the dynamic model gives 1/3 and the geometric (1/√3)/√(4/3) = 1/2
# (Yong & Mahadevan 2011, §II-III).
RATIO = 1 / math.sqrt(3)


def test_distance_in_the_models_standard_errors():
    point = BinomialEstimate(successes=400, n=1_000, seed=3)  # p̂ = 0.4
    se_dyn = math.sqrt((1 / 3) * (2 / 3) / 1_000)
    assert model_distance(RATIO, point, "dynamic") == pytest.approx((0.4 - 1 / 3) / se_dyn)
    assert model_distance(RATIO, point, "geometric") == pytest.approx(
        (0.4 - 0.5) / math.sqrt(0.25 / 1_000)
    )
    # No edge at all: the estimate's own s.e. is 0, the model's is not; finite distance.
    none = BinomialEstimate(successes=0, n=100, seed=3)
    assert model_distance(RATIO, none, "dynamic") == pytest.approx(
        -(1 / 3) / math.sqrt((2 / 9) / 100)
    )
    assert model_distance(0.0, none, "dynamic") == 0.0  # P = 0 and none seen


def test_figure_states_the_simulation_and_the_distances():
    simulated = [
        (0.3, BinomialEstimate(successes=180, n=1_000, seed=9)),
        (RATIO, BinomialEstimate(successes=400, n=1_000, seed=9)),
    ]
    text = simulation_text(simulated)
    for words in (
        "1,000 tosses per point",
        "seed 9",
        "ωx ~ U(150, 300) rad/s",
        "v0 ~ U(1.5, 3) m/s",
        "landing dead (e = 0)",
        "μ = 0.3",
        "table 0.5 m below",
    ):
        assert words in text, words
    fig = plot_edge(simulated)
    main, resid = fig.axes
    assert main.get_legend().get_title().get_text() == text
    for model in ("geometric", "dynamic"):
        (line,) = [ln for ln in resid.get_lines() if ln.get_label() == f"from the {model} model"]
        expected = [model_distance(r, s, model) for r, s in simulated]
        np.testing.assert_allclose(line.get_ydata(), expected)
        for z in expected:
            assert f"{z:+.1f}" in [t.get_text() for t in resid.texts]
    assert len(plot_edge().axes) == 1  # no simulation: no distance panel
