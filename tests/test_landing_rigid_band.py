"""The US nickel's P(edge) (issue 27; coinflight.studies.landing.nickel_band): the band over
what is not measured, the edges by how they ended, the fully rounded rim's none, and the
report's section."""

from __future__ import annotations

import json

import numpy as np
import pytest

from coinflight.core.outcome import EDGE
from coinflight.model.coin import Coin
from coinflight.model.surface import Surface
from coinflight.outcomes.table import land
from coinflight.probability import streams
from coinflight.report import landing as report
from coinflight.report.document import Document
from coinflight.studies import landing as study

SEED = 5


def _tosses(n: int, seed: int = SEED):
    dist = study.map_tosses()
    omega, v0 = study._draw(dist, n, streams.child(streams.seed_sequence(seed), 0))
    return dist.coin, omega, v0


@pytest.fixture(scope="module")
def small():
    return study.nickel_band(6, SEED, 24)


def test_traced_landings_are_lands_faces():
    """The toss-by-toss landing that reads how each landing stopped lands as ``land`` does:
    the same faces, per-toss e, μ and resistances, sharp and rounded rims."""
    coin, omega, v0 = _tosses(24)
    rng = np.random.default_rng(1)
    e = rng.uniform(0.3, 0.6, 24)
    mu = rng.uniform(0.2, 0.6, 24)
    ell = 10.0 ** rng.uniform(-4.0, -3.0, 24)
    for a in (0.0, study.CORNER_RADIUS):
        rounded = coin.with_corner_radius(a)
        surface = Surface("table", study.DROP_HEIGHT)
        contact = {
            "restitution": e,
            "friction": mu,
            "rolling_resistance": ell,
            "pivoting_resistance": ell,
        }
        theirs = land(rounded, omega, v0, 1.0, 9.81, surface, contact=contact).face
        ours, path = study.traced_landings(coin, omega, v0, e, mu, ell, a)
        np.testing.assert_array_equal(ours, theirs)
        # Every edge has a path, no face has one.
        assert np.all((path >= 0) == (ours == EDGE))


def test_a_fully_rounded_rim_leaves_no_coin_on_edge():
    """a = h/2: no flat band, no edge well; the same tosses with sharp corners (the nickel
    band's highest corner of coin-on-wood: e 0.6, μ 0.6, ℓ 1e-5 m) do end on edge."""
    coin, omega, v0 = _tosses(40)
    sharp, _ = study.traced_landings(coin, omega, v0, 0.6, 0.6, 1e-5, 0.0)
    assert np.count_nonzero(sharp == EDGE) > 0
    rounded, path = study.traced_landings(coin, omega, v0, 0.6, 0.6, 1e-5, coin.thickness / 2)
    assert np.count_nonzero(rounded == EDGE) == 0
    assert np.all(path == -1)


def test_the_band_holds_the_integrated_value_and_counts_every_edge_by_its_path(small):
    for b in small.bands:
        assert b.edge.shape == (2, 2, 2, 2) and 0.0 <= b.centre <= 1.0
        assert b.low[0] == min(b.edge.min(), b.centre) and b.high[0] == max(b.edge.max(), b.centre)
        (lo, lo_se), (hi, hi_se) = b.low, b.high
        p = b.integrated
        assert lo <= hi
        # The integrated value lies in the band of the box's cells within its error (3 s.e.
        # of the difference, the band's ends and the integrated value binomial).
        assert lo - 3 * np.hypot(lo_se, p.stderr) <= p.p <= hi + 3 * np.hypot(hi_se, p.stderr)
        assert int(b.integrated_paths.sum()) == p.successes
        np.testing.assert_array_equal(b.paths.sum(axis=-1), np.rint(b.edge * b.n))
        for k in range(4):
            low, high = b.axis(k)
            assert np.isclose(0.5 * (low[0] + high[0]), b.edge.mean())
    assert small.round_rim.successes == 0
    assert small.round_rim_parameters["corner_radius"] == Coin.preset(study.COIN).thickness / 2


def test_the_seed_reproduces_the_band(small):
    again = study.nickel_band(6, SEED, 24)
    for a, b in zip(small.bands, again.bands, strict=True):
        np.testing.assert_array_equal(a.edge, b.edge)
        np.testing.assert_array_equal(a.paths, b.paths)
        assert a.integrated == b.integrated and a.centre == b.centre
    assert again.round_rim == small.round_rim


def test_the_work_is_bounded_before_it_runs():
    with pytest.raises(ValueError, match="the nickel's band"):
        study.nickel_band(10**6, SEED)


def test_the_report_section_and_its_numbers(small):
    doc = Document("t")
    doc.add(*report._band_section(small))
    text = doc.to_markdown()
    assert "The US nickel's P(edge): a band over what is not measured, and why" in text
    assert "1 in 6,000" in text
    for path in study.EDGE_PATHS:
        assert path in text
    numbers = json.loads(json.dumps(report._band_numbers(small)))
    assert numbers["paths"] == list(study.EDGE_PATHS)
    assert numbers["murray_teare"] == study.MURRAY_TEARE
    assert numbers["round_rim"]["edges"] == 0
    for b, row in zip(small.bands, numbers["bands"], strict=True):
        assert row["preset"] == b.preset
        assert row["low"] == b.low[0] and row["high"] == b.high[0]
        assert row["p_edge_centre"] == b.centre
        assert row["integrated"] == b.integrated.p
        assert sum(row["integrated_edges_by_path"].values()) == b.integrated.successes
        assert set(row["axes"]) == {"corner_radius", "resistance", "friction", "restitution"}
