"""The published thick-coin edge points against coinflight's two no-bounce models.

The claims of docs/physics.rst, section "Published edge experiments", checked from the shipped
data (coinflight.datasets.edges) and coinflight.studies.edge.edge_probability, so the page
cannot drift from them. Tolerances: binomial standard errors of the data, sqrt(p(1-p)/n).
Hernández-Navarro & Piñero's bouncing closed form is not implemented (its equations were not
readable), so there is nothing of theirs to test here.
"""

from __future__ import annotations

import pytest

from coinflight.datasets.edges import edge_experiments
from coinflight.studies.edge import edge_probability


def _z(fraction: float, stderr: float, ratio: float, model: str) -> float:
    return (fraction - float(edge_probability(ratio, model))) / stderr  # type: ignore[arg-type]


@pytest.fixture(scope="module")
def measured():
    return {round(r.ratio, 3): r for r in edge_experiments(kind="measured")}


def test_the_thin_cylinder_lands_on_edge_less_than_either_model(measured):
    r = measured[0.354]
    assert r.stderr is not None
    # docs: -19 s.e. against the geometric model, -8 s.e. against the dynamic one
    assert _z(r.fraction, r.stderr, r.ratio, "geometric") == pytest.approx(-18.8, abs=0.05)
    assert _z(r.fraction, r.stderr, r.ratio, "dynamic") == pytest.approx(-7.9, abs=0.05)


def test_the_one_third_cylinder_lies_between_the_models(measured):
    r = measured[0.577]
    assert r.stderr is not None
    # docs: -6 s.e. against the geometric model, +5 s.e. against the dynamic one
    assert _z(r.fraction, r.stderr, r.ratio, "geometric") == pytest.approx(-5.8, abs=0.05)
    assert _z(r.fraction, r.stderr, r.ratio, "dynamic") == pytest.approx(4.9, abs=0.05)


def test_the_designed_ratios_are_the_models_one_third_points(measured):
    # the two cylinders were built at the ratios where each model gives P(edge) = 1/3
    assert float(edge_probability(measured[0.354].ratio, "geometric")) == pytest.approx(
        1 / 3, abs=1e-5
    )
    assert float(edge_probability(measured[0.577].ratio, "dynamic")) == pytest.approx(
        1 / 3, abs=1e-5
    )
