"""Thick cylinders against experiments (coinflight.studies.edge_experiments): the band's cells,
reproducibility, the verdict, the work bounds, and the dead-landing limit."""

from __future__ import annotations

import json
import math

import pytest

from coinflight.probability.result import BinomialEstimate
from coinflight.studies.edge import edge_probability
from coinflight.studies.edge_experiments import (
    HAND_DIAMETER,
    HAND_DROP,
    RESISTANCE,
    Band,
    Cell,
    Experiment,
    box_cells,
    edge_experiments,
    experiment_box,
    setting,
)
from coinflight.studies.landing import bouncing_box

# Made-up records: the study takes its data as an argument; these test the machinery only.
THIN = Experiment("made-up, h/d 0.3", 0.3, 200, 20, "hand-table", "test record")
ALL_EDGE = Experiment("made-up, every throw on edge", 0.3, 200, 200, "hand-table", "test record")


def _run(seed=7, **kw):
    kw.setdefault("contact", 4)
    return edge_experiments([THIN, ALL_EDGE], 40, seed, **kw)


def test_structure_cells_and_box():
    r = _run()
    assert r.n == 40 and r.contact_n == 4 and r.seed == 7 and r.points == 2
    (e_lo, e_hi), (mu_lo, mu_hi) = bouncing_box()
    for c in r.comparisons:
        assert c.contact is not None
        # unmeasured: e, μ, diameter, drop (+ resistance): corners and the centre
        assert len(c.rocking.cells) == 2**4 + 1
        assert len(c.contact.cells) == 2**5 + 1
        assert dict(c.box) == {
            "restitution": (e_lo, e_hi),
            "friction": (mu_lo, mu_hi),
            "diameter": HAND_DIAMETER,
            "drop_height": HAND_DROP,
            "resistance": RESISTANCE,
        }
        for band, size in ((c.rocking, 40), (c.contact, 4)):
            assert all(cell.n == size for cell in band.cells)
            centre = band.centre.parameters
            assert centre["restitution"] == pytest.approx(0.5 * (e_lo + e_hi))
            assert centre["diameter"] == pytest.approx(sum(HAND_DIAMETER) / 2)
            for cell in band.cells:
                for name, value in cell.parameters.items():
                    lo, hi = c.box[name]
                    assert lo <= value <= hi
        assert math.isclose(c.contact.centre.parameters["resistance"], math.sqrt(1e-5 * 1e-3))
    rows = r.table()
    assert len(rows) == 4 and all(len(row) == len(r.HEADER) for row in rows)
    data = json.loads(json.dumps(r.to_dict()))
    assert [x["edges"] for x in data["experiments"]] == [20, 200]
    assert len(data["experiments"][0]["bands"][1]["cells"]) == 33
    # A measured fraction of 1 lies above any band of a cylinder of h/d 0.3 (P(edge) < 1).
    assert {b.verdict(ALL_EDGE.observed) for b in r.comparisons[1].bands} == {"above"}


def test_reproducible_from_the_seed_and_prefix():
    one = _run(seed=11).to_dict()
    two = _run(seed=11).to_dict()
    for d in (one, two):
        d.pop("elapsed")
    assert one == two
    # experiment i draws from child i alone: alone, without the contact ending, the same band
    alone = edge_experiments([THIN], 40, 11)
    assert alone.comparisons[0].rocking == _run(seed=11).comparisons[0].rocking
    assert alone.comparisons[0].rocking.cells[0].estimate.seed == 11
    other = _run(seed=12).to_dict()
    other.pop("elapsed")
    assert other != one


def test_band_ordering_and_points():
    r = edge_experiments([THIN], 60, 3, points=3)
    band = r.comparisons[0].rocking
    assert len(band.cells) == 3**4  # the centre is a grid cell with 3 points
    assert band.low.p <= band.centre.p <= band.high.p
    assert all(band.low.p <= c.p <= band.high.p for c in band.cells)
    assert band.cells[-1].parameters == {
        k: pytest.approx((lo + hi) / 2) for k, (lo, hi) in r.comparisons[0].box.items()
    }


def _band(*fractions):
    return Band(
        "rocking", tuple(Cell({"restitution": 0.5}, BinomialEstimate(k, 1000)) for k in fractions)
    )


def test_verdict_and_gap():
    band = _band(200, 300, 250)  # 0.2 – 0.3
    assert band.low.p == 0.2 and band.high.p == 0.3 and band.centre.p == 0.25
    assert band.verdict(BinomialEstimate(250, 1000)) == "inside"
    assert band.gap(BinomialEstimate(250, 1000)) == 0.0
    assert band.verdict(BinomialEstimate(410, 1000)) == "above"
    assert band.gap(BinomialEstimate(410, 1000)) == pytest.approx(0.11)
    assert band.verdict(BinomialEstimate(100, 1000)) == "below"
    assert band.gap(BinomialEstimate(100, 1000)) == pytest.approx(-0.1)
    # the measured interval overlapping the band's end (+2 s.e.) is inside, not above
    assert band.verdict(BinomialEstimate(33, 100)) == "inside"


def test_box_cells():
    cells = box_cells({"restitution": (0.3, 0.6), "friction": (0.2, 0.2)})
    assert cells == [
        {"restitution": 0.3, "friction": 0.2},
        {"restitution": 0.6, "friction": 0.2},
        {"restitution": pytest.approx(0.45), "friction": 0.2},
    ]
    assert box_cells({"a": (1.0, 1.0)}) == [{"a": 1.0}]
    geo = box_cells({"resistance": (1e-5, 1e-3)}, 3)
    assert [c["resistance"] for c in geo] == pytest.approx([1e-5, 1e-3, 1e-4])


def test_record_gives_size_and_drop():
    x = Experiment("made-up", 0.5, 10, 1, "hand-table", diameter=0.03, drop_height=0.4)
    box = experiment_box(x, setting("hand-table"), "rocking")
    assert box["diameter"] == (0.03, 0.03) and box["drop_height"] == (0.4, 0.4)
    assert len(box_cells(box)) == 2**2 + 1


@pytest.mark.parametrize(
    ("kwargs", "error", "words"),
    [
        ({"n": 10**7, "points": 3}, ValueError, "more than the limit"),
        ({"n": 10**9}, ValueError, "tosses per cell must be between 1 and"),
        ({"n": 10**6, "contact": 10**6}, ValueError, "more than the limit"),
        ({"n": 0}, ValueError, "tosses per cell must be between 1"),
        ({"n": 10, "contact": 11}, ValueError, "contact-ending tosses per cell"),
        ({"n": 2.5}, TypeError, "tosses per cell must be an integer"),
        ({"n": 10, "points": 10}, ValueError, "points per parameter"),
        (
            {"n": 10, "contact": 2, "restitution": (0.0, 0.5)},
            ValueError,
            "the contact ending acts on landings that bounce",
        ),
        ({"n": 10, "seed": -1}, ValueError, "seed must be a non-negative integer"),
    ],
)
def test_refusals_before_work(kwargs, error, words):
    with pytest.raises(error, match=words):
        edge_experiments([THIN], **kwargs)


def test_bad_records():
    with pytest.raises(ValueError, match="give at least one experiment"):
        edge_experiments([], 10)
    with pytest.raises(TypeError, match="experiment must be an Experiment"):
        edge_experiments([(0.3, 100, 10)], 10)  # type: ignore[list-item]
    with pytest.raises(ValueError, match="edges of an experiment must be between 0 and 10"):
        Experiment("x", 0.3, 10, 11, "hand-table")
    with pytest.raises(ValueError, match="unknown experiment setting 'hand'"):
        Experiment("x", 0.3, 10, 1, "hand")
    with pytest.raises(ValueError, match="thickness/diameter ratio"):
        Experiment("x", 0.0, 10, 1, "hand-table")
    with pytest.raises(ValueError, match="diameter of an experiment must be positive"):
        Experiment("x", 0.3, 10, 1, "hand-table", diameter=-0.02)


# Yong & Mahadevan 2011 (REFERENCES §5): a vigorous planar toss landing dead lands on edge with
# P = 2 arctan(h/d)/π. The hand-table setting with restitution 0 and sticking friction is such a
# toss, for a cylinder of any size (the similarity the study uses for sizes): within 3 s.e.
@pytest.mark.parametrize("diameter", [0.02, 0.05])
def test_dead_landing_reproduces_the_dynamic_model(diameter):
    records = [
        Experiment(f"h/d {r}", r, 10, 1, "hand-table", diameter=diameter, drop_height=0.3)
        for r in (0.3, 0.577)
    ]
    r = edge_experiments(records, 20_000, 2011, restitution=(0.0, 0.0), friction=(0.5, 0.5))
    for c in r.comparisons:
        (cell,) = c.rocking.cells
        model = float(edge_probability(c.experiment.ratio))
        assert abs(cell.p - model) <= 3 * math.sqrt(model * (1 - model) / cell.n)


def test_mujoco_check_same_tosses_in_three_engines():
    from coinflight.studies import mujoco_compare

    if not mujoco_compare.available():
        pytest.skip("MuJoCo (the optional extra) is not installed")
    from coinflight.studies.edge_experiments import mujoco_check

    check = mujoco_check(THIN, 3, 5)
    assert check.parameters["drop_height"] == pytest.approx(sum(HAND_DROP) / 2)
    for est in (check.rocking, check.contact, check.mujoco):
        assert est.n == 3 and est.seed == 5
    assert 0 <= check.mujoco_moving <= 3
    with pytest.raises(ValueError, match="tosses of the MuJoCo check"):
        mujoco_check(THIN, 0)
