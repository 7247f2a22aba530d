""":func:`coinflight.plotting.forest.plot_flippers`: the people against two models' predictive
intervals, and the ψ population under p(ψ)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.stats import binom
from typer.testing import CliRunner

from coinflight.cli import app
from coinflight.core.precession import same_side_probability
from coinflight.plotting.forest import plot_flippers
from coinflight.studies import flippers as f
from coinflight.studies.data import load_dataset

TABLE = load_dataset("bartos2023")


@pytest.fixture(scope="module")
def analysis():
    return f.analyse(TABLE, seed=1, repeats=1)


def test_panels_show_the_models_intervals_and_count_who_is_inside(analysis):
    fig = plot_flippers(TABLE, analysis)
    one, population, curve, density = fig.axes
    lik = f.Likelihood.of(TABLE.same_by_person, TABLE.flips_by_person)
    masses = analysis.fit.population.cell_masses()
    inside = int(np.sum((lik.cdf @ masses >= 0.025) & (lik.cdf_below @ masses < 0.975)))
    assert population.get_title().endswith(f": {inside} of 48 inside")
    p = float(same_side_probability(analysis.fit.one_psi))
    k, n = TABLE.same_by_person, TABLE.flips_by_person
    inside_one = int(np.sum((binom.cdf(k, n, p) >= 0.025) & (binom.cdf(k - 1, n, p) < 0.975)))
    assert one.get_title().endswith(f": {inside_one} of 48 inside")
    assert inside_one < inside  # one ψ leaves more people outside
    # The most flips on top: its bar is the one-ψ binomial interval of 20,100 flips.
    bars = one.collections[0].get_segments()
    top = max(bars, key=lambda seg: seg[0][1])
    most = int(np.argmax(n))
    want = f.predictive_interval_one_psi(n[[most]], analysis.fit.one_psi)[0]
    assert [top[0][0], top[1][0]] == pytest.approx(want)
    assert curve.get_lines()[0].get_ydata()[-1] == pytest.approx(0.5)  # p(90°) = ½
    assert density.get_xlim() == (45.0, 90.0)
    # One tick per person at the shrunken ψ.
    ticks = density.collections[-1].get_segments()
    assert sorted(seg[0][0] for seg in ticks) == pytest.approx(
        sorted(math.degrees(q.psi) for q in analysis.people)
    )


def test_cli_writes_the_people_figure(tmp_path):
    out = tmp_path / "people.svg"
    result = CliRunner().invoke(
        app, ["data", "--seed", "1", "--repeats", "1", "--plot-people", str(out)]
    )
    assert result.exit_code == 0, result.output
    assert out.stat().st_size > 10_000 and f"wrote {out}" in result.stdout
