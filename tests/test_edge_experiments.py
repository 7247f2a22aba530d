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
    MIN_TOSSES_TO_JUDGE,
    RESISTANCE,
    Band,
    Cell,
    Experiment,
    box_cells,
    edge_experiments,
    experiment_box,
    setting,
)
from coinflight.studies.presets import bouncing_box

# Made-up records: the study takes its data as an argument; these test the machinery only.
THIN = Experiment("made-up, h/d 0.3", 0.3, 200, 20, "hand-table", "test record")
ALL_EDGE = Experiment("made-up, every throw on edge", 0.3, 200, 200, "hand-table", "test record")


def _run(seed=7, **kw):
    return edge_experiments([THIN, ALL_EDGE], 20, seed, **kw)


def test_structure_cells_and_box():
    r = _run()
    assert r.n == 20 and r.seed == 7 and r.points == 2 and r.psi is None
    (e_lo, e_hi), (mu_lo, mu_hi) = bouncing_box()
    for c in r.comparisons:
        # unmeasured: e, μ, diameter, drop, resistance: the corners and the centre
        assert len(c.band.cells) == 2**5 + 1
        assert dict(c.box) == {
            "restitution": (e_lo, e_hi),
            "friction": (mu_lo, mu_hi),
            "diameter": HAND_DIAMETER,
            "drop_height": HAND_DROP,
            "resistance": RESISTANCE,
        }
        assert all(cell.n == 20 for cell in c.band.cells)
        centre = c.band.centre.parameters
        assert centre["restitution"] == pytest.approx(0.5 * (e_lo + e_hi))
        assert centre["diameter"] == pytest.approx(sum(HAND_DIAMETER) / 2)
        assert math.isclose(centre["resistance"], math.sqrt(1e-5 * 1e-3))
        for cell in c.band.cells:
            for name, value in cell.parameters.items():
                lo, hi = c.box[name]
                assert lo <= value <= hi
    rows = r.table()
    assert len(rows) == 2 and all(len(row) == len(r.HEADER) for row in rows)
    data = json.loads(json.dumps(r.to_dict()))
    assert [x["edges"] for x in data["experiments"]] == [20, 200]
    assert len(data["experiments"][0]["band"]["cells"]) == 33
    # A measured fraction of 1 lies above any band of a cylinder of h/d 0.3 (P(edge) < 1).
    assert r.comparisons[1].band.verdict(ALL_EDGE.observed) == "above"


def test_reproducible_from_the_seed_and_prefix():
    one = _run(seed=11).to_dict()
    two = _run(seed=11).to_dict()
    for d in (one, two):
        d.pop("elapsed")
    assert one == two
    # experiment i draws from child i alone: alone, the same band
    alone = edge_experiments([THIN], 20, 11)
    assert alone.comparisons[0].band == _run(seed=11).comparisons[0].band
    assert alone.comparisons[0].band.cells[0].estimate.seed == 11
    other = _run(seed=12).to_dict()
    other.pop("elapsed")
    assert other != one


def test_band_ordering_and_points():
    r = edge_experiments([THIN], 8, 3, points=3)
    band = r.comparisons[0].band
    assert len(band.cells) == 3**5  # the centre is a grid cell with 3 points
    assert band.low.p <= band.centre.p <= band.high.p
    assert all(band.low.p <= c.p <= band.high.p for c in band.cells)
    box = r.comparisons[0].box
    centre = {k: (lo + hi) / 2 for k, (lo, hi) in box.items()}
    centre["resistance"] = math.sqrt(box["resistance"][0] * box["resistance"][1])  # geometric
    assert band.cells[-1].parameters == {k: pytest.approx(x) for k, x in centre.items()}


def _band(*fractions):
    return Band(tuple(Cell({"restitution": 0.5}, BinomialEstimate(k, 1000)) for k in fractions))


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


def test_a_band_of_a_few_tosses_per_cell_does_not_judge_a_point_inside_it():
    """--quick's band, four tosses a cell: 0.000 to 0.500 spans a measured 0.41 by its
    noise alone; it says so instead of "inside". A point it lies wholly below is still above."""
    few = Band(
        tuple(Cell({"restitution": 0.5}, BinomialEstimate(k, 4)) for k in (0, 2, 1)),
    )
    assert (few.low.p, few.high.p) == (0.0, 0.5)
    assert few.verdict(BinomialEstimate(410, 1000)) == "too few tosses to judge"
    lower = Band((Cell({"restitution": 0.5}, BinomialEstimate(1, 4)),))
    assert lower.verdict(BinomialEstimate(1000, 1000)) == "above"  # > 0.25 + 2 × 0.217
    enough = Band(  # the same fractions at MIN_TOSSES_TO_JUDGE tosses a cell judge it
        tuple(
            Cell(
                {"restitution": 0.5},
                BinomialEstimate(k * MIN_TOSSES_TO_JUDGE // 4, MIN_TOSSES_TO_JUDGE),
            )
            for k in (0, 2, 1)
        ),
    )
    assert enough.verdict(BinomialEstimate(410, 1000)) == "inside"


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
    box = experiment_box(x, setting("hand-table"))
    assert box["diameter"] == (0.03, 0.03) and box["drop_height"] == (0.4, 0.4)
    assert len(box_cells(box)) == 2**3 + 1  # e, μ and the resistance


@pytest.mark.parametrize(
    ("kwargs", "error", "words"),
    [
        ({"n": 10**7, "points": 3}, ValueError, "more than the limit"),
        ({"n": 10**9}, ValueError, "tosses per cell must be between 1 and"),
        ({"n": 10**4}, ValueError, "more than the limit"),
        ({"n": 0}, ValueError, "tosses per cell must be between 1"),
        ({"n": 2.5}, TypeError, "tosses per cell must be an integer"),
        ({"n": 10, "points": 10}, ValueError, "points per parameter"),
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
# toss, for a cylinder of any size (simulate_edge's diameter): within 3 s.e. A dead landing
# ends at its first impact, so the resistance (the box's one other axis) changes nothing.
@pytest.mark.parametrize("diameter", [0.02, 0.05])
def test_dead_landing_reproduces_the_dynamic_model(diameter):
    records = [
        Experiment(f"h/d {r}", r, 10, 1, "hand-table", diameter=diameter, drop_height=0.3)
        for r in (0.3, 0.577)
    ]
    r = edge_experiments(records, 10_000, 2011, restitution=(0.0, 0.0), friction=(0.5, 0.5))
    for c in r.comparisons:
        cell, *others = c.band.cells
        assert len(others) == 2 and all(x.estimate == cell.estimate for x in others)
        model = float(edge_probability(c.experiment.ratio))
        assert abs(cell.p - model) <= 3 * math.sqrt(model * (1 - model) / cell.n)


def test_mujoco_check_same_tosses_in_both_engines():
    from coinflight.studies import mujoco_compare

    if not mujoco_compare.available():
        pytest.skip("MuJoCo (the optional extra) is not installed")
    from coinflight.studies.edge_experiments import mujoco_check

    check = mujoco_check(THIN, 3, 5)
    assert check.parameters["drop_height"] == pytest.approx(sum(HAND_DROP) / 2)
    for est in (check.coinflight, check.mujoco):
        assert est.n == 3 and est.seed == 5
    assert 0 <= check.mujoco_moving <= 3
    with pytest.raises(ValueError, match="tosses of the MuJoCo check"):
        mujoco_check(THIN, 0)


def test_axial_spin_puts_the_normal_on_the_stated_cone():
    # ωz = (I1/I3) ωx cot ψ (Diaconis, Holmes & Montgomery 2007, §2), I1/I3 of a uniform
    # cylinder = (3r² + h²)/12 ÷ r²/2 = (3 + 4 (h/d)²)/6; ωx the hand setting's median.
    from coinflight.model.distributions import Fixed, Normal
    from coinflight.studies.edge_experiments import axial_spin
    from coinflight.studies.presets import HUMAN_COT_PSI_RELATIVE_SD, HUMAN_PSI, HUMAN_SPIN

    spin = setting("hand-table").spin
    for ratio in (0.354, 0.577):
        ratio_i = (3 + 4 * ratio**2) / 6
        for psi in (80.0, 60.0, 45.0):
            wz = axial_spin(ratio, spin, psi)
            assert isinstance(wz, Fixed)
            expected = ratio_i * HUMAN_SPIN / math.tan(math.radians(psi))
            assert wz.value == pytest.approx(expected, rel=1e-4)  # moments printed to 5 digits
        assert axial_spin(ratio, spin, 90.0) == Fixed(0.0)
        human = axial_spin(ratio, spin, "human")
        assert isinstance(human, Normal)
        mean = ratio_i * HUMAN_SPIN / math.tan(HUMAN_PSI)
        assert human.mean == pytest.approx(mean, rel=1e-4)
        assert human.sd == pytest.approx(HUMAN_COT_PSI_RELATIVE_SD * human.mean)


@pytest.mark.parametrize(
    ("psi", "error", "words"),
    [
        (0.0, ValueError, "psi must be above 0 and at most 90 degrees, got 0"),
        (95.0, ValueError, "psi must be above 0 and at most 90 degrees, got 95"),
        ("coin", ValueError, "psi must be a cone angle in degrees or 'human', got 'coin'"),
        (float("nan"), ValueError, "psi must be finite"),
    ],
)
def test_psi_refused_before_work(psi, error, words):
    from coinflight.studies.edge_experiments import wobble_sweep

    with pytest.raises(error, match=words):
        edge_experiments([THIN], 10, psi=psi)
    with pytest.raises(error, match=words):
        wobble_sweep([THIN], 10, psis=[psi])


def test_progress_is_called_first_once_checked_and_before_any_toss(monkeypatch):
    # The contract a caller relies on to tell a refused input (before the first progress call)
    # from a fault of the run (after it): bench_edge_experiments.py's one-line errors.
    import coinflight.outcomes.table as table
    import coinflight.studies.edge as edge
    from coinflight.studies import mujoco_compare
    from coinflight.studies.edge_experiments import mujoco_check, wobble_sweep

    def no_toss(*_args, **_kwargs):
        raise AssertionError("a toss ran")

    monkeypatch.setattr(edge, "simulate_edge", no_toss)
    monkeypatch.setattr(table, "land", no_toss)
    runs = [
        lambda said: edge_experiments([THIN], 10, 1, progress=said.append),
        lambda said: wobble_sweep([THIN], 10, 1, progress=said.append),
    ]
    if mujoco_compare.available():
        runs.append(lambda said: mujoco_check(THIN, 3, 1, psi=80.0, progress=said.append))
    for run in runs:
        said: list[str] = []
        with pytest.raises(AssertionError, match="a toss ran"):
            run(said)
        assert len(said) == 1 and "about " in said[0]  # the size and its time, no more
    said = []
    with pytest.raises(ValueError, match="psi must be above 0"):
        edge_experiments([THIN], 10, progress=said.append, psi=0.0)
    with pytest.raises(ValueError, match="psi must be above 0"):
        wobble_sweep([THIN], 10, psis=[0.0], progress=said.append)
    if mujoco_compare.available():
        with pytest.raises(ValueError, match="psi must be above 0"):
            mujoco_check(THIN, 3, 1, psi=0.0, progress=said.append)
    assert said == []  # a refusal comes before it


@pytest.mark.parametrize(
    "call, words",
    [
        (lambda p: edge_experiments([THIN], 10, progress=p, g=-1.0), "g must be"),
        (lambda p: edge_experiments([THIN], 10, progress=p, restitution=(2, 3)), "restitution"),
        (lambda p: edge_experiments([THIN], 10, progress=p, friction=(-1, 5)), "friction"),
        (lambda p: _wobble([THIN], 10, progress=p, g=float("nan")), "g must be"),
        (
            lambda p: _wobble(
                [THIN],
                2,
                progress=p,
                cells=[
                    {
                        "restitution": 0.5,
                        "friction": 0.3,
                        "diameter": 0.02,
                        "drop_height": 0.3,
                        "resistance": -1.0,
                    }
                ],
            ),
            "resistance",
        ),
        (
            lambda p: _wobble(
                [THIN],
                10,
                progress=p,
                cells=[{"restitution": 0.5, "friction": 0.3, "diameter": -1, "drop_height": 0.3}],
            ),
            "diameter",
        ),
    ],
)
def test_every_input_is_refused_before_progress_is_first_called(call, words):
    # Found by a reviewer: g, e, μ, a cell's values and the resistance were checked only by
    # the first toss, after progress had said the run started (so a caller took the refusal for
    # a fault of the run).
    said: list[str] = []
    with pytest.raises((ValueError, TypeError), match=words):
        call(said.append)
    assert said == []


def _wobble(*args, **kwargs):
    from coinflight.studies.edge_experiments import wobble_sweep

    return wobble_sweep(*args, **kwargs)


def test_wobble_sweep_shares_the_tosses_of_the_planar_band():
    # Common random numbers: ψ = 90 (no axial spin) at a cell gives edge_experiments' count at
    # that cell, toss for toss, and ψ = 60 its count with that wobble; every row names its ψ
    # and cell. A box of the resistance alone (the record gives size and drop; e and μ fixed)
    # keeps the wobbling tosses, which roll for long, few.
    from coinflight.studies.edge_experiments import wobble_sweep

    x = Experiment("made-up", 0.3, 200, 20, "hand-table", diameter=0.035, drop_height=0.35)
    fixed = {"restitution": (0.45, 0.45), "friction": (0.325, 0.325)}
    band = edge_experiments([x], 50, 9, **fixed)
    centre = band.comparisons[0].band.centre
    cell = dict(centre.parameters)
    assert cell == pytest.approx(
        {
            "restitution": 0.45,
            "friction": 0.325,
            "diameter": 0.035,
            "drop_height": 0.35,
            "resistance": 1e-4,
        }
    )
    rows = wobble_sweep([x], 50, 9, psis=[90.0, 60.0], cells=[cell])
    assert [(r.psi, dict(r.parameters)) for r in rows] == [(90.0, cell), (60.0, cell)]
    assert rows[0].estimate.successes == centre.estimate.successes
    wobbling = edge_experiments([x], 50, 9, psi=60.0, **fixed).comparisons[0].band
    assert wobbling.centre.parameters["psi"] == 60.0
    assert wobbling.centre.estimate.successes == rows[1].estimate.successes


def test_from_dataset_marks_counts_derived_from_a_fraction():
    """The shipped Stand-up Maths rows give a fraction, not a count: the study's count is
    round(fraction × n) and says so (≈ in the table, edges_derived in the JSON)."""
    from coinflight.datasets import edge_experiments as records
    from coinflight.studies.edge_experiments import from_dataset

    kept, left = from_dataset(records())
    assert kept and all(x.edges_derived for x in kept)
    assert {x.edges for x in kept} == {round(r.fraction * r.n) for r in records("measured")}
    assert left  # the nickel's extrapolation is not a measurement
    given = Experiment("counted", 0.3, 200, 20, "hand-table", "test record")
    assert not given.edges_derived
    r = edge_experiments(kept[:1], 20, 3)
    assert r.table()[0][2].endswith(f"≈{kept[0].edges}/{kept[0].n}")
    assert r.to_dict()["experiments"][0]["edges_derived"] is True


def test_mujoco_check_is_bounded_before_any_landing(monkeypatch):
    """The landings and MuJoCo's run counted before anything runs (a landing that started
    would fail this test)."""
    from coinflight.outcomes import table
    from coinflight.studies.edge_experiments import mujoco_check

    def never(*args, **kwargs):
        raise AssertionError("a landing ran before the work bound")

    monkeypatch.setattr(table, "land", never)
    with pytest.raises(ValueError, match="more than the limit"):
        mujoco_check(THIN, 100_000, 1)


def test_the_band_with_the_human_wobble_is_over_the_whole_box():
    # Human tosses (the preset's wobble): the same box, resistance included, and the
    # measurement beside it with its binomial error.
    r = edge_experiments([THIN], 4, 5, psi="human")
    (c,) = r.comparisons
    assert len(c.band.cells) == 2**5 + 1 and all(cell.n == 4 for cell in c.band.cells)
    assert "resistance" in c.box and r.psi == "human"
    assert all("psi" in cell.parameters for cell in c.band.cells)
    data = r.to_dict()
    assert data["experiments"][0]["stderr"] == pytest.approx(math.sqrt(0.1 * 0.9 / 200))
    assert data["experiments"][0]["band"]["verdict"] in {
        "above",
        "below",
        "too few tosses to judge",
    }
    assert r.table()[0][2].startswith("0.100 ± 0.021 (")  # the measurement's binomial error
