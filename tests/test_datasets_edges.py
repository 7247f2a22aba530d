"""The shipped thick-coin edge dataset (coinflight.datasets.edges): rows, provenance, loader."""

from __future__ import annotations

import dataclasses
import math

import pytest

from coinflight.datasets import EDGE_SOURCES, EdgeExperiment, edge_experiments
from coinflight.datasets.edges import KINDS, parse_edge_experiments


def test_every_row_is_sourced_and_consistent():
    rows = edge_experiments()
    assert len(rows) == 3
    for r in rows:
        assert r.source in EDGE_SOURCES and r.citation == EDGE_SOURCES[r.source]
        assert r.kind in KINDS
        assert r.ratio > 0.0 and 0.0 < r.fraction < 1.0
        assert r.setting and r.how_read
        if r.edges is not None:
            # a fraction must be the counts' when both are given
            assert r.n is not None and r.fraction == pytest.approx(r.edges / r.n, abs=5e-5)


def test_the_measured_points_and_their_binomial_error():
    rows = edge_experiments(kind="measured")
    assert [(r.source, r.n, r.edges, r.fraction) for r in rows] == [
        ("standup_maths_2018", 1000, None, 0.132),
        ("standup_maths_2018", 1000, None, 0.41),
    ]
    # the two nominal ratios are 1/(2 sqrt 2) and 1/sqrt 3 (5 decimals in the file)
    assert rows[0].ratio == pytest.approx(1 / (2 * math.sqrt(2)), abs=5e-6)
    assert rows[1].ratio == pytest.approx(1 / math.sqrt(3), abs=5e-6)
    assert rows[0].stderr == pytest.approx(math.sqrt(0.132 * 0.868 / 1000), rel=1e-12)


def test_the_extrapolation_is_not_data():
    (nickel,) = edge_experiments(kind="extrapolated")
    assert nickel.source == "murray_teare_1993" and nickel.n is None and nickel.stderr is None
    assert nickel.fraction == pytest.approx(1 / 6000, rel=1e-4)
    assert nickel.ratio == pytest.approx(1.95 / 21.21, abs=5e-5)  # US Mint nickel
    assert "10.1103/PhysRevE.48.2547" in nickel.citation


def test_records_are_frozen():
    row = edge_experiments()[0]
    assert isinstance(row, EdgeExperiment)
    with pytest.raises(dataclasses.FrozenInstanceError):
        row.fraction = 0.5  # type: ignore[misc]


def test_bad_kind_and_bad_rows():
    with pytest.raises(ValueError, match="edge dataset kind must be one of measured, extrapol"):
        edge_experiments(kind="simulated")
    header = "source,ratio,n,edges,fraction,kind,setting,how_read\n"
    with pytest.raises(ValueError, match="edge dataset source must be one of"):
        parse_edge_experiments(header + "nobody,0.3,10,1,0.1,measured,x,y\n")
    with pytest.raises(ValueError, match="edge dataset kind must be one of"):
        parse_edge_experiments(header + "murray_teare_1993,0.3,10,1,0.1,guessed,x,y\n")
    # comments are skipped; empty counts read as None
    (row,) = parse_edge_experiments(
        "# note\n" + header + "murray_teare_1993,0.3,,,0.1,measured,x,y"
    )
    assert (row.n, row.edges) == (None, None)
