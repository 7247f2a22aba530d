"""The three-sided coin (issue 27): the ratio h/d for a chosen P(edge), its band and its error
(:mod:`coinflight.studies.edge_target`)."""

from __future__ import annotations

import math

import pytest

from coinflight.studies.edge import simulate_edge
from coinflight.studies.edge_target import (
    check_probability,
    max_evaluations,
    target_box,
    target_ratio,
)


@pytest.mark.parametrize("p", [1 / 3, 0.2])
def test_dead_landings_find_yong_and_mahadevans_dynamic_root(p):
    # Restitution 0 is the setting of the dynamic model (Yong & Mahadevan 2011, §III):
    # P(edge) = 2 arctan(h/d)/π, so P = p at h/d = tan(πp/2): 1/√3 ≈ 0.5774 at p = 1/3,
    # 0.3249 at p = 0.2. Within 4 of the root's stated errors (20,000 tosses a ratio).
    result = target_ratio(p, 20_000, 7, restitution=0.0, friction=0.3)
    (cell,) = result.cells
    expected = math.tan(math.pi * p / 2)
    assert cell.stderr < 0.02 * expected  # a root to about 1 %, so the check has teeth
    assert abs(cell.ratio - expected) < 4 * cell.stderr
    # the slope the error uses is the model's dP/dx = 2/(π(1 + x²)), within 4 of its errors
    assert abs(cell.slope - 2 / (math.pi * (1 + expected**2))) < 4 * cell.slope_stderr
    assert result.yong_mahadevan["dynamic"] == pytest.approx(expected, rel=1e-12)


def test_the_band_ends_land_on_edge_p_of_the_time_within_the_stated_error():
    # Each end of the band, landed again with other tosses (another seed) at its own (e, μ,
    # resistances): P(edge) there is p within 4 standard errors of the difference (the new
    # estimate's binomial error and the root's error times the slope; both shrink as 1/√n).
    # n = 1,500: each root to about 2 % (the check's 10,000 tosses: ± 0.005 in P).
    p, n = 1 / 3, 1_500
    result = target_ratio(p, n, 11)
    assert len(result.cells) == 9  # e, μ and the resistances not given: 8 corners and centre
    for cell in (result.low, result.high):
        lo, p_lo, hi, p_hi = cell.bracket
        assert lo <= cell.ratio <= hi and p_lo <= p <= p_hi
        assert hi / lo <= 2.0  # one step of the bracket's search
        ((_, check),) = simulate_edge(
            [cell.ratio],
            10_000,
            12,
            restitution=cell.parameters["restitution"],
            friction=cell.parameters["friction"],
            rolling_resistance=cell.parameters["resistance"],
            pivoting_resistance=cell.parameters["resistance"],
        )
        sigma = math.hypot(check.stderr, cell.slope * cell.stderr)
        assert abs(check.p - p) < 4 * sigma, (dict(cell.parameters), check.p, sigma)
    assert result.low.ratio <= result.centre.ratio <= result.high.ratio


def test_common_random_numbers_and_the_seed():
    kw = {"friction": 0.3, "rolling_resistance": 1e-4, "pivoting_resistance": 1e-4}
    a = target_ratio(0.25, 300, 5, **kw)
    b = target_ratio(0.25, 300, 5, **kw)
    assert a.to_dict() | {"elapsed": 0} == b.to_dict() | {"elapsed": 0}
    assert a.seed == 5 and a.to_dict()["method"].startswith("common random numbers")
    # the restitution's two ends and the centre: three cells, each its own root
    assert [c.parameters["restitution"] for c in a.cells] == pytest.approx([0.3, 0.6, 0.45])
    assert all(c.evaluations <= max_evaluations(0.25, 1e-3) for c in a.cells)


def test_the_box_spreads_what_is_not_given():
    # e and μ: the surface presets' ranges; both resistances one value 1e-5–1e-3 m when neither
    # is given, each at its own range under its own name when the other is.
    assert target_box() == {
        "restitution": (0.3, 0.6),
        "friction": (0.05, 0.6),
        "resistance": (1e-5, 1e-3),
    }
    assert target_box(restitution=0.5)["resistance"] == (1e-5, 1e-3)
    box = target_box(rolling_resistance=2e-4)
    assert box["rolling_resistance"] == (2e-4, 2e-4)
    assert box["pivoting_resistance"] == (1e-5, 1e-3) and "resistance" not in box
    # Dead landings (e = 0) never reach the rigid ending, where alone the resistances act: no
    # dimension of theirs, no cells that could only repeat each other.
    assert target_box(restitution=0.0, friction=0.3) == {
        "restitution": (0.0, 0.0),
        "friction": (0.3, 0.3),
    }


def test_bouncing_landings_with_few_tosses():
    # Bouncing landings carried to rest by the rigid ending still answer for a handful of
    # tosses per ratio (every parameter given: one cell, the resistances among its values).
    result = target_ratio(
        1 / 3,
        30,
        3,
        restitution=0.45,
        friction=0.3,
        rolling_resistance=1e-4,
        pivoting_resistance=1e-4,
    )
    (cell,) = result.cells
    lo, p_lo, hi, p_hi = cell.bracket
    assert lo <= cell.ratio <= hi and p_lo <= 1 / 3 <= p_hi
    assert cell.parameters["rolling_resistance"] == cell.parameters["pivoting_resistance"] == 1e-4
    assert "ending" not in result.to_dict()


def test_measured_rows_come_with_their_binomial_error():
    result = target_ratio(1 / 3, 100, 1, restitution=0.0, friction=0.3)
    rows = result.to_dict()["measured"]
    assert [round(r["ratio"], 3) for r in rows] == [0.354, 0.577]
    for r in rows:
        assert r["stderr"] == pytest.approx(math.sqrt(r["fraction"] * (1 - r["fraction"]) / 1000))


@pytest.mark.parametrize(
    ("value", "error", "words"),
    [
        (0.0, ValueError, "edge probability must be strictly between 0 and 1, got 0.0"),
        (1.0, ValueError, "strictly between 0 and 1, got 1.0"),
        (2, ValueError, "strictly between 0 and 1, got 2"),
        (math.nan, ValueError, "edge probability"),
        ("abc", TypeError, "edge probability"),
    ],
)
def test_bad_probability(value, error, words):
    with pytest.raises(error, match=words):
        check_probability(value)
    with pytest.raises(error, match=words):
        target_ratio(value, 10, 1)


def test_refusals_before_anything_runs():
    with pytest.raises(ValueError, match="more than the limit of 3,600 s"):
        target_ratio(1 / 3, 10**6, 1)
    with pytest.raises(ValueError, match="corner radius must be between 0"):
        target_ratio(1 / 3, 10, 1, corner_radius=0.02)
    with pytest.raises(ValueError, match=r"^pivoting resistance acts on landings that bounce"):
        target_ratio(1 / 3, 10, 1, restitution=0.0, pivoting_resistance=1e-4)


def test_a_target_out_of_reach_is_said(monkeypatch):
    # A landing that never puts a coin on edge (a stand-in for simulate_edge): the bracket's
    # search climbs to h/d = 100, within the bound on evaluations, and says so.
    from coinflight.probability.result import BinomialEstimate
    from coinflight.studies import edge

    tried = []

    def never(ratios, n, seed, **kwargs):
        tried.append(float(ratios[0]))
        return [(float(ratios[0]), BinomialEstimate(0, n, 1))]

    monkeypatch.setattr(edge, "simulate_edge", never)
    with pytest.raises(ValueError, match=r"P\(edge\) = 0.5 is not reached for h/d between 0.001"):
        target_ratio(0.5, 10, 1, restitution=0.45, friction=0.3)
    assert tried[-1] == 100.0 and len(tried) - 1 <= max_evaluations(0.5, 1e-3)


def test_a_wobble_lowers_the_ratio_and_is_checked_first():
    # With the human preset's wobble (ψ ≈ 82°) more thick cylinders stay on edge than with
    # planar tosses (edge_experiments' notes), so P = 1/3 comes at a thinner cylinder: the
    # same tosses (seed), one cell, the roots apart by many errors.
    # The resistances given (one cell) at the band's high end: a wobbling cylinder rolls on its
    # rim, and on a table of little resistance lands a few times a second. 500 tosses: each
    # root to about 5 %, the gap (about 0.4 at 4,000 tosses) still many errors wide.
    kw = {"restitution": 0.45, "friction": 0.325}
    kw |= {"rolling_resistance": 1e-3, "pivoting_resistance": 1e-3}
    planar = target_ratio(1 / 3, 500, 3, **kw).centre
    human = target_ratio(1 / 3, 500, 3, psi="human", **kw)
    assert human.setting["psi"] == "human"
    gap = planar.ratio - human.centre.ratio
    assert gap > 5 * math.hypot(planar.stderr, human.centre.stderr)
    with pytest.raises(ValueError, match="psi must be above 0 and at most 90 degrees"):
        target_ratio(1 / 3, 10, 1, psi=120.0)
