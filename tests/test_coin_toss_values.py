"""Coin and Toss value objects: moments, presets, validation with errors that name the value."""

from __future__ import annotations

import math

import numpy as np
import pytest

from coinflight import PRESETS, Coin, Flight, Toss
from coinflight.core.rigid_body import principal_moments


def test_principal_moments_formula():
    # Stefan & Cheche §2: I1 = I2 = (m/4)(r² + h²/3), I3 = m r²/2.
    i1, i3 = principal_moments(0.01213, 0.00175, 0.00567)
    assert float(i1) == pytest.approx(0.00567 / 4 * (0.01213**2 + 0.00175**2 / 3), rel=1e-15)
    assert float(i3) == pytest.approx(0.00567 * 0.01213**2 / 2, rel=1e-15)
    # Thin-disc limit: I3 = 2 I1.
    i1, i3 = principal_moments(1.0, 0.0, 1.0)
    assert float(i3) == pytest.approx(2 * float(i1), rel=1e-15)


@pytest.mark.parametrize(
    ("name", "mass_g", "diameter_mm", "thickness_mm"),
    [  # REFERENCES §7
        ("us-cent", 2.500, 19.05, 1.52),
        ("us-nickel", 5.000, 21.21, 1.95),
        ("us-dime", 2.268, 17.91, 1.35),
        ("us-quarter", 5.670, 24.26, 1.75),
        ("us-half-dollar", 11.340, 30.61, 2.15),
        ("eur-1", 7.50, 23.25, 2.33),
        ("eur-2", 8.50, 25.75, 2.20),
        ("eur-50c", 7.80, 24.25, 2.38),
        ("gbp-1", 8.75, 23.43, 2.80),
    ],
)
def test_presets_match_references(name, mass_g, diameter_mm, thickness_mm):
    coin = Coin.preset(name)
    assert coin.mass == pytest.approx(mass_g / 1000, rel=1e-12)
    assert coin.diameter == pytest.approx(diameter_mm / 1000, rel=1e-12)
    assert coin.thickness == pytest.approx(thickness_mm / 1000, rel=1e-12)


def test_presets_are_all_listed():
    assert len(PRESETS) == 9


@pytest.mark.parametrize("field", ["radius", "thickness", "mass"])
@pytest.mark.parametrize("bad", [0.0, -0.01, math.inf, math.nan])
def test_coin_rejects_bad_dimensions(field, bad):
    kwargs = {"radius": 0.012, "thickness": 0.0015, "mass": 0.005, field: bad}
    with pytest.raises(ValueError, match=rf"^{field} must be between .* \(in k?g?m?\), got"):
        Coin(**kwargs)


def test_coin_rejects_non_numbers():
    with pytest.raises(TypeError, match="radius must be a number"):
        Coin(radius="big", thickness=0.001, mass=0.005)  # type: ignore[arg-type]


def test_unknown_coin_suggests_a_name():
    with pytest.raises(ValueError, match=r"unknown coin 'us-quater' \(did you mean us-quarter\?\)"):
        Coin.preset("us-quater")


@pytest.mark.parametrize("typed", ["US-Cent", "US-CENT", "us-Cent", "Us-cent"])
def test_coin_presets_are_found_in_any_case(typed):
    assert Coin.preset(typed) == Coin.preset("us-cent")
    assert Coin.preset(typed).name == "US cent"


def test_an_unknown_coin_in_another_case_is_refused_as_typed_with_the_names():
    with pytest.raises(ValueError) as caught:
        Coin.preset("US-Penny")
    assert str(caught.value).startswith("unknown coin 'US-Penny'")
    assert str(caught.value).endswith(
        "known coins: us-cent, us-nickel, us-dime, us-quarter, us-half-dollar, eur-1, eur-2, "
        "eur-50c, gbp-1"
    )


@pytest.mark.parametrize("bad", [0.0, -1.0, math.inf, math.nan])
def test_toss_rejects_bad_flight_time(bad):
    with pytest.raises(ValueError, match=r"flight time must be between 1e-06 and 10000 \(in s\)"):
        Toss(omega=(1.0, 0.0, 0.0), flight_time=bad)


@pytest.mark.parametrize("bad", [0.0, -3.0, math.inf, math.nan])
def test_toss_rejects_bad_launch_speed(bad):
    with pytest.raises(ValueError, match="launch speed must be positive and finite"):
        Toss.from_launch_speed((1.0, 0.0, 0.0), bad)


@pytest.mark.parametrize("bad", [0.0, -9.81, math.inf])
def test_toss_rejects_bad_gravity(bad):
    with pytest.raises(ValueError, match=r"^g must be between 0.001 and 1000 \(in m/s²\)"):
        Toss(omega=(1.0, 0.0, 0.0), flight_time=0.5, g=bad)


def test_toss_rejects_non_finite_spin_and_bad_shapes():
    with pytest.raises(ValueError, match="omega must be finite"):
        Toss(omega=(np.inf, 0.0, 0.0), flight_time=0.5)
    with pytest.raises(ValueError, match="omega must have 3 components"):
        Toss(omega=(1.0, 0.0), flight_time=0.5)
    with pytest.raises(ValueError, match="do not broadcast"):
        Toss(omega=np.zeros((4, 3)), flight_time=np.ones(5))
    with pytest.raises(ValueError, match="start must be one of heads, tails"):
        Toss(omega=(1.0, 0.0, 0.0), flight_time=0.5, start="edge")  # type: ignore[arg-type]


def test_flight_rejects_wrong_types():
    with pytest.raises(TypeError, match="coin must be a Coin"):
        Flight("us-quarter", Toss(omega=(1, 0, 0), flight_time=1))  # type: ignore[arg-type]


def test_values_are_frozen():
    coin = Coin.preset("eur-2")
    with pytest.raises(AttributeError):
        coin.radius = 1.0  # type: ignore[misc]


def test_toss_keeps_private_read_only_arrays():
    omega = np.array([80.0, 0.0, 0.0])
    toss = Toss(omega=omega, flight_time=0.7)
    omega[0] = np.nan  # the caller's array changes; the validated toss does not
    assert toss.omega.tolist() == [80.0, 0.0, 0.0]
    with pytest.raises(ValueError, match="read-only"):
        toss.omega[0] = 1.0


@pytest.mark.parametrize(("omega", "flight_time"), [((1e200, 0, 0), 0.7), ((2e5, 0, 0), 1e4)])
def test_toss_refuses_phases_rounding_would_decide(omega, flight_time):
    with pytest.raises(
        ValueError, match=r"spin component × flight time must be at most 1,000,000,000 rad, got "
    ):
        Toss(omega=omega, flight_time=flight_time)


def test_edge_on_counts_as_the_other_face_whatever_the_start():
    """n(T)·n0 = 0 (measure zero): not the starting face, for either start (Stefan & Cheche
    §2.1: heads up iff cos θ > 0), so the face and the same-side flag always agree."""
    from coinflight.core.outcome import HEADS, TAILS, face_from_alignment, same_side

    alignment = np.array([0.5, 0.0, -0.5])
    assert face_from_alignment(alignment, 1.0).tolist() == [HEADS, TAILS, TAILS]
    assert face_from_alignment(alignment, -1.0).tolist() == [TAILS, HEADS, HEADS]
    assert same_side(alignment).tolist() == [True, False, False]


@pytest.mark.parametrize(
    "omega, flight_time, words",
    [
        # issue: an empty omega was accepted (a toss of no tosses)
        (np.empty((0, 3)), 0.7, r"omega \(shape \(0, 3\)\) and flight time .* hold no toss"),
        ((80.0, 0.0, 0.0), np.empty(0), "hold no toss"),
        # issue: 4 spins and flight times of shape (4, 1) were broadcast to 4 × 4 tosses
        (
            np.full((4, 3), 50.0),
            np.full((4, 1), 0.7),
            r"omega \(shape \(4, 3\), 4 tosses\) and flight time \(shape \(4, 1\)\) have "
            r"different numbers of axes, which would broadcast to 4 × 4 tosses; give one "
            r"flight time per spin \(shape \(4,\)\)",
        ),
        (np.full((2, 4, 3), 50.0), np.full(4, 0.7), "different numbers of axes"),
    ],
)
def test_toss_refuses_no_tosses_and_implicit_outer_products(omega, flight_time, words):
    with pytest.raises(ValueError, match=words):
        Toss(omega=omega, flight_time=flight_time)


def test_toss_keeps_the_broadcasts_a_user_spells_out():
    # One spin for many times, one time for many spins, and an explicit grid (same axes).
    assert Toss(omega=(50.0, 0.0, 0.0), flight_time=np.full(5, 0.7)).shape == (5,)
    assert Toss(omega=np.full((4, 3), 50.0), flight_time=0.7).shape == (4,)
    assert Toss(omega=np.full((4, 1, 3), 50.0), flight_time=np.full((1, 5), 0.7)).shape == (4, 5)


def test_flight_at_a_time_before_the_launch_is_refused():
    # issue: Flight.at(-5.0) answered a state 5 s before the toss
    flight = Flight(Coin.preset("us-quarter"), Toss(omega=(80.0, 0.0, 0.0), flight_time=0.7))
    with pytest.raises(ValueError, match=r"t must be non-negative and finite \(in s\), got -5.0"):
        flight.at(-5.0)
    with pytest.raises(ValueError, match="t must be non-negative"):
        flight.at([0.1, -1e-300])
    assert flight.at(0.0).height == pytest.approx(0.0)


@pytest.mark.parametrize(
    "t, words",
    [
        (np.full((4, 1), 0.3), r"different numbers of axes, which would broadcast to 4 × 4"),
        ([0.1, 0.2], r"the toss batch \(4 tosses\) and t \(shape \(2,\)\) do not broadcast"),
        (1e308, r"t must be at most 10000 s \(the longest flight time\), got 1e\+308 s"),
    ],
)
def test_flight_at_refuses_outer_products_mismatches_and_absurd_times(t, words):
    # Found by the hostile run: Flight.at made 4 × 4 states of 4 tosses and 4 × 1 times,
    # NumPy's "shape mismatch" for 2 times, a zero-norm quaternion error for t = 1e308.
    flight = Flight(Coin.preset("us-quarter"), Toss(omega=np.full((4, 3), 50.0), flight_time=0.7))
    with pytest.raises(ValueError, match=words):
        flight.at(t)
    assert flight.at(np.full(4, 0.3)).normal.shape == (4, 3)


def test_messages_show_arrays_on_one_line():
    from coinflight.model.ensemble import TossDistribution
    from coinflight.probability import estimate

    with pytest.raises(TypeError) as info:
        TossDistribution(np.ones((4, 1)), 0, 0, 0.7)
    assert "\n" not in str(info.value) and "[[1.] [1.] [1.] [1.]]" in str(info.value)
    with pytest.raises(TypeError) as info:
        estimate(TossDistribution(60.0, 0, 0, 0.7), "monte-carlo", n=np.ones((2, 3)), seed=1)
    assert str(info.value) == "n must be an integer, got array of float64 [[1. 1. 1.] [1. 1. 1.]]"
