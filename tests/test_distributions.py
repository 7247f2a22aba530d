"""Distributions of initial conditions and the TossDistribution built from them."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from coinflight import Coin
from coinflight.model.distributions import (
    Fixed,
    Normal,
    Uniform,
    as_distribution,
    parse_distribution,
    unit_cube_values,
)
from coinflight.model.ensemble import PARAMETERS, TossDistribution


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("10", Fixed(10.0)),
        ("-3.5", Fixed(-3.5)),
        ("60:90", Uniform(60.0, 90.0)),
        (" -10:1e1 ", Uniform(-10.0, 10.0)),
        ("normal:3.5,0.2", Normal(3.5, 0.2)),
        ("NORMAL:0,1", Normal(0.0, 1.0)),
    ],
)
def test_parse(text, expected):
    assert parse_distribution(text, "--omega-x", "rad/s") == expected


@pytest.mark.parametrize(
    ("text", "words"),
    [
        ("90:60", "reversed"),
        ("5:5", "empty"),
        ("normal:1,0", "standard deviation"),
        ("normal:1,-2", "standard deviation"),
        ("normal:1", "normal:MEAN,SD"),
        ("a:b", "'a' is not a number"),
        ("1:2:3", "LOW:HIGH"),
        ("", "not a number"),
        ("nan", "not finite"),
        ("1:inf", "not finite"),
    ],
)
def test_parse_errors_name_option_and_text(text, words):
    with pytest.raises(ValueError) as info:
        parse_distribution(text, "--omega-x", "rad/s")
    message = str(info.value)
    assert "--omega-x" in message
    assert repr(text.strip()) in message
    assert words in message


def test_constructor_errors():
    with pytest.raises(ValueError, match="reversed"):
        Uniform(2.0, 1.0)
    with pytest.raises(ValueError, match="standard deviation"):
        Normal(1.0, 0.0)
    with pytest.raises(TypeError):
        as_distribution("60:90")  # type: ignore[arg-type]
    # A bare distribution names its kind and field; attached to a parameter, the parameter.
    with pytest.raises(ValueError, match="Uniform high must be finite, got inf"):
        Uniform(60.0, math.inf)
    with pytest.raises(ValueError, match="Normal mean must be finite, got nan"):
        Normal(math.nan, 1.0)
    with pytest.raises(ValueError, match="omega_x must be finite, got nan"):
        TossDistribution(math.nan, 0, 0, 0.7)
    with pytest.raises(ValueError, match="flight_time must be finite, got inf"):
        TossDistribution(60.0, 0, 0, math.inf)
    with pytest.raises(ValueError, match="launch_speed must be finite"):
        TossDistribution.from_launch_speed(60.0, 0, 0, math.nan)
    with pytest.raises(TypeError, match="omega_z: expected a number"):
        TossDistribution(60.0, 0, "1", 0.7)  # type: ignore[arg-type]


@settings(deadline=None)  # the first call imports SciPy
@given(
    st.floats(-100.0, 100.0),
    st.floats(0.1, 100.0),
    st.floats(1e-6, 1 - 1e-6),
)
def test_ppf_inverts_cdf(low, width, u):
    # Round-off of x − low relative to the width: ≤ 1e-16 × 200 / 0.1 ≈ 2e-13.
    for dist in (Uniform(low, low + width), Normal(low, width)):
        x = dist.ppf(u)
        assert dist.cdf(x) == pytest.approx(u, rel=1e-9, abs=1e-11)


def test_protocol_values():
    u = Uniform(60.0, 90.0)
    assert (u.mean, u.bounds, u.affine, u.is_fixed) == (75.0, (60.0, 90.0), (60.0, 30.0), False)
    f = Fixed(10.0)
    assert (f.mean, f.bounds, f.affine, f.is_fixed) == (10.0, (10.0, 10.0), (10.0, 0.0), True)
    n = Normal(3.0, 0.5)
    assert n.affine is None and n.bounds == (-np.inf, np.inf) and not n.is_fixed
    # Midpoints of equal-probability cells: for a uniform range, the paper's midpoints.
    np.testing.assert_allclose(u.ppf([0.25, 0.75]), [67.5, 82.5])
    assert n.ppf(0.5) == pytest.approx(3.0)
    assert n.to_dict() == {"kind": "normal", "mean": 3.0, "sd": 0.5}
    assert u.scaled(2.0) == Uniform(120.0, 180.0)
    assert n.scaled(2.0) == Normal(6.0, 1.0)


def test_sampling_respects_the_distribution():
    rng = np.random.default_rng(0)
    x = Uniform(1.0, 2.0).sample(rng, 10_000)
    assert x.min() >= 1.0 and x.max() <= 2.0
    # Mean of 10⁴ draws: standard error 0.5 / 100; 5 standard errors.
    assert abs(Normal(3.0, 0.5).sample(rng, 10_000).mean() - 3.0) < 5 * 0.005


def test_toss_distribution():
    d = TossDistribution(Uniform(60, 90), 0, 10.0, Uniform(0.6, 0.9), start="tails")
    assert d.ranged == ("omega_x", "flight_time")
    assert d.omega_y == Fixed(0.0) and d.omega_z == Fixed(10.0)
    assert d.start_sign == -1.0
    assert d.coin == Coin.preset("us-quarter")
    wx, _wy, wz, t = d.values(np.array([[0.5, 0.0], [0.5, 1.0]]))
    np.testing.assert_allclose(wx, [75.0, 60.0])
    np.testing.assert_allclose(t, [0.75, 0.9])
    np.testing.assert_allclose(wz, [10.0, 10.0])
    assert list(d.parameters) == list(PARAMETERS)
    with pytest.raises(ValueError, match="shape"):
        d.values(np.zeros((3, 2)))


def test_from_launch_speed_uses_eq_11():
    # Stefan & Cheche eq 11: T = 2 v0 / g.
    d = TossDistribution.from_launch_speed(80.0, 0, 0, Uniform(3.0, 5.0), g=10.0)
    assert isinstance(d.flight_time, Uniform)
    assert (d.flight_time.low, d.flight_time.high) == pytest.approx((0.6, 1.0), rel=1e-15)
    d = TossDistribution.from_launch_speed(80.0, 0, 0, Normal(4.0, 0.1), g=10.0)
    assert isinstance(d.flight_time, Normal)
    assert (d.flight_time.mean, d.flight_time.sd) == pytest.approx((0.8, 0.02), rel=1e-15)


@pytest.mark.parametrize(
    ("speed", "words"),
    [
        (Normal(0.1, 1.0), "launch speed normal(0.1, sd 1) m/s reaches speeds ≤ 0 m/s"),
        (Uniform(-1.0, 3.0), "launch speed -1–3 m/s reaches speeds ≤ 0 m/s"),
        (Fixed(0.0), "launch speed 0 m/s reaches"),
    ],
)
def test_launch_speed_errors_name_the_launch_speed(speed, words):
    # The user's numbers, not the flight times they convert to.
    with pytest.raises(ValueError, match=re.escape(words)):
        TossDistribution.from_launch_speed(80.0, 0, 0, speed)


@pytest.mark.parametrize("flight_time", [Uniform(-0.1, 0.5), Fixed(0.0), Normal(0.5, 0.1)], ids=str)
def test_flight_time_must_be_positive(flight_time):
    with pytest.raises(ValueError, match="flight time"):
        TossDistribution(80.0, 0, 0, flight_time)


def test_bad_start_and_g():
    with pytest.raises(ValueError, match="start"):
        TossDistribution(80.0, 0, 0, 0.7, start="edge")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="g"):
        TossDistribution(80.0, 0, 0, 0.7, g=-1.0)


def test_unit_cube_values_take_each_ranged_row_and_repeat_a_fixed_mean():
    """The ranged distributions read their own row of u (in the order given), through their
    inverse CDF; a fixed one is its value at every point."""
    u = np.array([[0.1, 0.5, 0.9], [0.25, 0.5, 0.75]])
    got = unit_cube_values(
        {"a": Uniform(0.0, 10.0), "b": Fixed(3.0), "c": Normal(0.0, 1.0)}, ("c", "a"), u
    )
    assert list(got) == ["a", "b", "c"]
    np.testing.assert_allclose(got["a"], [2.5, 5.0, 7.5], rtol=1e-15)  # row 1: u of "a"
    np.testing.assert_array_equal(got["b"], [3.0, 3.0, 3.0])
    # Φ⁻¹(0.1), Φ⁻¹(0.5), Φ⁻¹(0.9) (row 0: u of "c"); ±1.2815515655446004 (scipy.special.ndtri)
    np.testing.assert_allclose(got["c"], [-1.2815515655446004, 0.0, 1.2815515655446004],
                               rtol=1e-12, atol=1e-15)  # fmt: skip


@pytest.mark.parametrize(
    "make, error, words",
    [
        # issue: Fixed([1, 2]) raised NumPy's "only length-1 arrays can be converted"
        (lambda: Fixed([1, 2]), TypeError, "Fixed value must be a single number, got an array"),
        (lambda: Fixed(np.array([3.0])), TypeError, "Fixed value must be a single number"),
        (lambda: Uniform([0, 1], 2), TypeError, "Uniform low must be a single number"),
        (lambda: Uniform(0, [1, 2]), TypeError, "Uniform high must be a single number"),
        (lambda: Normal([0.0], 1.0), TypeError, "Normal mean must be a single number"),
        (lambda: Normal(0.0, [1, 2]), TypeError, "Normal standard deviation must be a single"),
        # issue: Uniform(-1e308, 1e308).ppf(0.5) = inf; its width overflows
        (lambda: Uniform(-1e308, 1e308), ValueError, r"range -1e\+308:1e\+308 is too wide"),
        (lambda: Uniform(-1.7e308, 1e308), ValueError, "is too wide"),
        (lambda: Normal(0.0, 1e308), ValueError, r"normal\(0, sd 1e\+308\) is too wide"),
        (lambda: Normal(1.7e308, 1e307), ValueError, "is too wide"),
    ],
)
def test_a_distribution_refuses_arrays_and_overflowing_widths_in_its_own_words(make, error, words):
    with pytest.raises(error, match=words):
        make()


@given(
    lo=st.floats(-1e308, 1e308),
    width=st.floats(1e-300, 1.7e308),
    u=st.floats(0.0, 1.0),
)
def test_every_accepted_uniform_has_finite_quantiles(lo, width, u):
    hi = lo + width
    try:
        d = Uniform(lo, hi)
    except ValueError as e:  # an empty or too-wide range, refused in words
        assert "empty" in str(e) or "too wide" in str(e) or "finite" in str(e)
        return
    assert math.isfinite(float(d.ppf(u)))
    assert d.low <= float(d.ppf(u)) <= d.high


@given(mean=st.floats(-1e308, 1e308), sd=st.floats(1e-300, 1e308), u=st.floats(1e-16, 1 - 1e-16))
def test_every_accepted_normal_has_finite_quantiles(mean, sd, u):
    try:
        d = Normal(mean, sd)
    except ValueError as e:
        assert "too wide" in str(e)
        return
    assert math.isfinite(float(d.ppf(u)))
