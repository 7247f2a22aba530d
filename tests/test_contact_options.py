"""The rigid ending's parameters as options (issue 11): --rolling-resistance,
--pivoting-resistance and the coin's --corner-radius, in the library, the command line, the
sweep and the web API; the corner radius reaching the rigid 3-D ending, the one ending of every
table landing."""

from __future__ import annotations

import csv
import dataclasses
import json
import math
import pickle
import re

import numpy as np
import pytest
from fastapi.testclient import TestClient
from typer.testing import CliRunner

from _cli import answer, api_answer, one_line_error
from coinflight import Coin, Toss
from coinflight import _validation as v
from coinflight.cli import app
from coinflight.model.distributions import Uniform
from coinflight.model.ensemble import TossDistribution
from coinflight.model.surface import (
    DEFAULT_PIVOTING_RESISTANCE,
    DEFAULT_ROLLING_RESISTANCE,
    TABLE_ONLY,
    Drag,
    Surface,
    _Unset,
)
from coinflight.outcomes.table import (
    AIR_LANDINGS_PER_SECOND,
    BOUNCING_TOSSES_PER_SECOND,
    RIGID_TOSSES_PER_SECOND,
    STATUS_NAMES,
    Landing,
    TableLanding,
    land,
)
from coinflight.probability import estimate
from coinflight.queries.toss import landing_fields
from coinflight.web import create_app

runner = CliRunner()
TOSS = ["toss", "--omega", "240", "5", "3", "--flight-time", "0.49"]
TABLE = ["--surface", "table", "--drop-height", "0.8"]
QUARTER_HALF = 0.5 * Coin.preset("us-quarter").thickness  # 0.000875 m


def _json(*args: str) -> dict:
    """The object of ``coinflight ARGS --json`` (its command line checked and left out)."""
    return answer(runner.invoke(app, [*args, "--json"]), [*args, "--json"])


# --- the coin's corner radius, validated ----------------------------------------------------
def test_the_corner_radius_is_a_validated_coin_property_zero_by_default():
    quarter = Coin.preset("us-quarter")
    assert quarter.corner_radius == 0.0
    assert "corner_radius" not in quarter.to_dict()  # every other JSON as it was
    rounded = quarter.with_corner_radius(QUARTER_HALF)
    assert rounded.corner_radius == QUARTER_HALF
    assert rounded.to_dict()["corner_radius"] == QUARTER_HALF
    assert rounded != quarter and "corner radius a = 0.875 mm" in rounded.describe()
    for bad in (-1e-6, QUARTER_HALF * (1 + 1e-9), math.nan, math.inf):
        with pytest.raises(ValueError, match=r"^corner radius must be between 0 and 0.000875"):
            quarter.with_corner_radius(bad)
    with pytest.raises(TypeError):
        quarter.with_corner_radius("0.1")  # type: ignore[arg-type]
    with pytest.raises(TypeError, match="single number"):
        quarter.with_corner_radius([1e-4, 2e-4])  # type: ignore[arg-type]


# --- the corner radius reaches the rigid ending -----------------------------------------------
def _vigorous(n: int, seed: int) -> tuple[np.ndarray, np.ndarray]:
    rng = np.random.default_rng(seed)
    omega = np.column_stack(
        [rng.uniform(150, 300, n), rng.uniform(-30, 30, n), rng.uniform(-30, 30, n)]
    )
    return omega, rng.uniform(1.5, 3.0, n)


def test_the_corner_radius_reaches_the_rigid_ending():
    """A nickel's sharp rim has an edge well (|n_z| < h / sqrt(d² + h²), 5.3°) and a flat band
    that hold some coins upright in the rigid ending; a rim rounded to a = h/2 has neither (the
    rounded coin's edge well (h/2 − a)/ρ′ closes), so no coin ends on its edge, and the ending
    itself moves differently (other settle times for the same tosses). Through the public API
    only: Coin.with_corner_radius and outcomes.table.land."""
    nickel = Coin.preset("us-nickel")
    surface = Surface("table", drop_height=0.8, restitution=0.5, friction=0.3)
    omega, v0 = _vigorous(150, seed=11)
    sharp = land(nickel, omega, v0, 1.0, 9.81, surface)
    round_ = land(nickel.with_corner_radius(0.5 * nickel.thickness), omega, v0, 1.0, 9.81, surface)
    # The rigid ending ends most of them (below its well's barrier or at rest).
    phase = [STATUS_NAMES.index("settled in contact")]
    assert np.mean(np.isin(sharp.status, phase)) > 0.5
    assert np.mean(np.isin(round_.status, phase)) > 0.5
    edges_sharp = int(np.sum(sharp.face == 2))
    # Measured 14 of these 150 (29 of the first 300, 9.7 %); 3 is more than 3 s.d. below
    # (binomial s.d. 3.6 at 9.7 %).
    assert edges_sharp >= 3, edges_sharp
    assert int(np.sum(round_.face == 2)) == 0
    both = np.isin(sharp.status, phase) & np.isin(round_.status, phase)
    differ = np.abs(sharp.settle_time[both] - round_.settle_time[both]) > 1e-6
    assert np.mean(differ) > 0.5  # not only the final reading of the face: the motion


def test_a_rounded_rim_touches_the_table_no_earlier_than_the_sharp_one():
    """The flight meets the rounded rim (core.bounce.next_contact and core.impact take the corner
    radius a): a cylinder (r − a, h/2 − a) swept by a ball of radius a lies inside the sharp
    cylinder (rounding cuts corners away, it lowers no point), so with --bounces 0 the rounded
    coin's first contact is never earlier than the sharp coin's, and later for tosses that land
    on the rim (not face-flat). The well at a sharp coin's face contact is the same (its tilt
    is outside the edge band, far from where the face changes); the edge band is the rounded
    coin's own (never an edge at a = h/2)."""
    nickel = Coin.preset("us-nickel")
    surface = Surface("table", drop_height=0.8)
    omega, v0 = _vigorous(2000, seed=12)
    sharp = land(nickel, omega, v0, 1.0, 9.81, surface, max_bounces=0)
    rounded = nickel.with_corner_radius(0.5 * nickel.thickness)
    round_ = land(rounded, omega, v0, 1.0, 9.81, surface, max_bounces=0)
    assert np.all(round_.first_contact >= sharp.first_contact)
    later = round_.first_contact > sharp.first_contact
    assert np.mean(later) > 0.5
    faces = sharp.face != 2
    np.testing.assert_array_equal(sharp.face[faces], round_.face[faces])
    assert np.sum(sharp.face == 2) > 0 and np.sum(round_.face == 2) == 0


# --- the resistances: every table takes them, one check in the Surface --------------------------
def test_the_surface_takes_and_range_checks_the_resistances_with_marked_defaults():
    """Surface holds the one check (the query, the sweep and simulate_edge rely on it): a table
    takes a resistance given (kept as a plain float) and refuses one out of range in one line;
    a default is range-checked too but marked as not given (left out of the repr), equals the
    same value given, and survives a copy or a pickle."""
    given = Surface("table", 0.8, rolling_resistance=2e-4, pivoting_resistance=0.0)
    assert (given.rolling_resistance, given.pivoting_resistance) == (2e-4, 0.0)
    assert type(given.rolling_resistance) is float and "rolling_resistance=0.0002" in repr(given)
    with pytest.raises(
        ValueError, match=re.escape("pivoting resistance must be between 0 and 0.01")
    ):
        Surface("table", pivoting_resistance=0.02)
    # a default is range-checked too (the mark of a default is a float: nothing else bypasses)
    with pytest.raises(ValueError, match=re.escape("rolling resistance must be between 0 and")):
        Surface("table", rolling_resistance=_Unset(5.0))
    with pytest.raises(ValueError, match=re.escape("pivoting resistance must be between 0 and")):
        Surface("table", pivoting_resistance=_Unset(-1.0))
    table = Surface("table", 0.8)
    assert table.rolling_resistance == DEFAULT_ROLLING_RESISTANCE
    assert table.pivoting_resistance == DEFAULT_PIVOTING_RESISTANCE
    assert type(table.rolling_resistance) is _Unset
    assert "resistance" not in repr(table)  # defaults not given: left out
    assert table == Surface("table", 0.8, rolling_resistance=DEFAULT_ROLLING_RESISTANCE)
    for copy in (table, pickle.loads(pickle.dumps(table)), given):
        assert dataclasses.replace(copy, friction=0.1).friction == 0.1


def test_the_library_and_the_command_line_take_a_resistance_on_a_table():
    """A resistance given to a table reaches the landing: the toss's JSON reports it, and the
    landing equals the library's on the surface with that resistance."""
    out = _json(*TOSS, *TABLE, "--coin", "us-nickel", "--pivoting-resistance", "0")
    assert (out["rolling_resistance"], out["pivoting_resistance"]) == (
        DEFAULT_ROLLING_RESISTANCE,
        0.0,
    )
    landing = Landing(
        Coin.preset("us-nickel"),
        Toss((240.0, 5.0, 3.0), 0.49),
        Surface("table", 0.8, pivoting_resistance=0.0),
    )
    expected = landing_fields(landing.outcome)
    assert {k: out[k] for k in expected} == expected


# --- the command line ---------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--rolling-resistance", "-1"],
         "--rolling-resistance: rolling resistance must be between 0 and 0.01 (in m), got -1.0"),
        (["--pivoting-resistance", "0.02"],
         "--pivoting-resistance: pivoting resistance must be between 0 and 0.01 (in m), got "
         "0.02"),
        (["--rolling-resistance", "abc"], None),
        (["--corner-radius", "0.001"],
         "--corner-radius: corner radius must be between 0 and 0.000875 (in m), got 0.001: at "
         "most half the thickness h/2"),
        (["--corner-radius", "-0.0001"], None),
        (["--corner-radius", "nan"], None),
        (["--rolling-resistance", "1e-5:1e-3"],
         "--rolling-resistance 1e-05–0.001: this command takes a single value; a distribution "
         "of a contact parameter is for coinflight probability --method monte-carlo, qmc or grid, "
         "which integrate over it"),
    ],
)  # fmt: skip
def test_bad_contact_options_are_one_line_exit_2(args, message):
    said = one_line_error(*TOSS, *TABLE, *args)
    if message is not None:
        assert said == message


@pytest.mark.parametrize(
    "args",
    [["--pivoting-resistance", "1e-4"], ["--corner-radius", "1e-4"], ["--rolling-resistance", "0"]],
)
def test_contact_options_belong_to_the_table(args):
    flag = args[0]
    assert one_line_error(*TOSS, *args) == f"{flag} {TABLE_ONLY}"


@pytest.mark.parametrize(
    ("options", "said"),
    [
        ({"pivoting_resistance": 1e-4}, "pivoting resistance 0.0001 m"),
        (
            {"pivoting_resistance": 1e-4, "rolling_resistance": 0.0},
            "rolling resistance 0 m, pivoting resistance 0.0001 m",
        ),
    ],
)
def test_a_catch_in_the_hand_refuses_the_tables_options_in_the_command_lines_words(options, said):
    """A hand catch has no contact phase: a resistance given to it is refused (not kept
    unused), in one line naming what was given, with the words of the command line's refusal
    of --pivoting-resistance with --surface hand (TABLE_ONLY)."""
    with pytest.raises(ValueError, match=f"^{re.escape(said + ' ' + TABLE_ONLY)}$"):
        Surface("hand", **options)
    assert Surface("hand").rolling_resistance == DEFAULT_ROLLING_RESISTANCE  # no refusal
    assert one_line_error(*TOSS, "--surface", "hand", "--pivoting-resistance", "1e-4") == (
        f"--pivoting-resistance {TABLE_ONLY}"
    )


@pytest.mark.parametrize(
    ("options", "said"),
    [
        ({"restitution": 0.5}, "restitution 0.5"),  # the default's value, given: refused
        ({"friction": 0.3}, "friction 0.3"),
        ({"restitution": 0.0, "friction": 1.0}, "restitution 0, friction 1"),
        ({"friction": 0.2, "rolling_resistance": 1e-3},
         "friction 0.2, rolling resistance 0.001 m"),
    ],
)  # fmt: skip
def test_a_catch_in_the_hand_refuses_a_restitution_or_friction_given_to_it(options, said):
    """A restitution or friction given to a catch in the hand (which has no contact) is refused
    as the command line refuses --restitution with --surface hand (TABLE_ONLY), not kept unused;
    the defaults are marked as not given: a hand surface, and a copy or pickle of it, is no
    refusal, and a table's defaults equal the same values given."""
    with pytest.raises(ValueError, match=f"^{re.escape(said + ' ' + TABLE_ONLY)}$"):
        Surface("hand", **options)
    hand = Surface("hand")
    for copy in (
        hand,
        pickle.loads(pickle.dumps(hand)),
        dataclasses.replace(hand, kind="hand"),
    ):
        assert (copy.restitution, copy.friction) == (0.5, 0.3)
    given = Surface("table", 0.8, restitution=0.5, friction=0.3)
    assert Surface("table", 0.8) == given
    assert repr(given) == (  # a value given is shown (and rebuilt as given); a default is not
        "Surface(kind='table', drop_height=0.8, restitution=0.5, friction=0.3)"
    )
    said = "drop height 0.8 m, restitution 0.5, friction 0.3 " + TABLE_ONLY
    with pytest.raises(ValueError, match=f"^{re.escape(said)}$"):
        dataclasses.replace(given, kind="hand")  # a value given stays given in a copy
    assert dataclasses.replace(Surface("table"), kind="hand") == hand  # the defaults do not


@pytest.mark.parametrize(
    ("options", "said"),
    [
        ({"drop_height": 0.8}, "drop height 0.8 m"),
        ({"drop_height": 0.0}, "drop height 0 m"),  # the default's value, given: refused
        ({"drop_height": 0.3, "friction": 0.2}, "drop height 0.3 m, friction 0.2"),
    ],
)
def test_a_catch_in_the_hand_refuses_a_drop_height_and_a_copy_does_not_carry_one(options, said):
    """A catch in the hand is at the launch height (Stefan & Cheche): a drop height given to it
    is refused in the TABLE_ONLY words, not kept unused, and ``dataclasses.replace(table,
    kind="hand")`` refuses a table's drop height given rather than carry it silently; the
    default (0 m, marked as not given) is no refusal, and a table left at it lands as one given
    0 m."""
    with pytest.raises(ValueError, match=f"^{re.escape(said + ' ' + TABLE_ONLY)}$"):
        Surface("hand", **options)
    table = Surface("table", **options)
    with pytest.raises(ValueError, match=f"^{re.escape(said + ' ' + TABLE_ONLY)}$"):
        dataclasses.replace(table, kind="hand")
    hand = dataclasses.replace(Surface("table"), kind="hand")
    assert hand == Surface("hand") and hand.drop_height == 0.0
    assert type(hand.drop_height) is _Unset and "drop_height" not in repr(hand)
    assert Surface("table") == Surface("table", drop_height=0.0)
    assert type(Surface("table", drop_height=0.0).drop_height) is float  # given: a plain float
    # the command line and the web page refuse it in one line, before the surface is built
    assert one_line_error(*TOSS, "--surface", "hand", "--drop-height", "0.8") == (
        f"--drop-height {TABLE_ONLY}"
    )
    with TestClient(create_app()) as web:
        response = web.get("/api/toss?omega=240,5,3&flight_time=0.49&surface=hand&drop_height=0.8")
    assert response.status_code == 422
    assert response.json() == {"detail": f"--drop-height {TABLE_ONLY}"}


def test_a_table_at_the_default_drop_height_lands_as_one_given_it():
    """The marked default drop height reaches the kernels as 0 m: the same landings, faces and
    JSON as with drop_height=0.0 given (a table level with the launch point)."""
    coin = Coin.preset("us-quarter")
    rng = np.random.default_rng(11)
    omega = np.column_stack([rng.uniform(150, 300, 30), rng.uniform(-30, 30, (30, 2))])
    flight = rng.uniform(0.4, 0.6, 30)
    default, given = (TableLanding(Surface("table", **kw)) for kw in ({}, {"drop_height": 0.0}))
    np.testing.assert_array_equal(
        default.faces(coin, omega, flight, 1, 9.81), given.faces(coin, omega, flight, 1, 9.81)
    )
    assert default.to_dict() == given.to_dict()
    assert json.dumps(default.to_dict()) == json.dumps(given.to_dict())


@pytest.mark.parametrize(
    "surface",
    [
        Surface("hand"),
        Surface("table", 0.8),
        Surface("table", 0.8, restitution=0.4, friction=0.3, contact_duration=2e-4),
        Surface("table", 0.8, rolling_resistance=2e-4),
    ],
)
def test_a_surface_is_rebuilt_from_its_repr_its_fields_a_pickle_or_a_copy(surface):
    """repr, dataclasses.asdict, pickling and dataclasses.replace rebuild a surface equal to it,
    with the same fields given: a catch in the hand's marked defaults are not given back as a
    refused restitution or friction, nor a table's as resistances given."""
    rebuilt = (
        eval(repr(surface), {"Surface": Surface}),  # the text Surface writes
        Surface(**dataclasses.asdict(surface)),
        pickle.loads(pickle.dumps(surface)),
        dataclasses.replace(surface),
    )
    for copy in rebuilt:
        assert copy == surface and repr(copy) == repr(surface)
        for field in dataclasses.fields(Surface):
            assert type(getattr(copy, field.name)) is type(getattr(surface, field.name))
    if surface.kind == "hand":
        assert "restitution" not in repr(surface) and "friction" not in repr(surface)
        assert type(dataclasses.asdict(surface)["restitution"]) is _Unset
    with pytest.raises(ValueError, match=re.escape(TABLE_ONLY)):
        Surface("hand", restitution=0.5)  # a value given, even the default's, is still refused


def test_the_command_line_refuses_a_restitution_or_friction_with_the_hand():
    """coinflight toss --surface hand --restitution/--friction: exit 2, one line; without them
    the hand's toss is unchanged (its JSON has no contact parameter)."""
    for flag, value in (("--restitution", "0.5"), ("--friction", "0.3")):
        said = one_line_error(*TOSS, "--surface", "hand", flag, value)
        assert said == f"{flag} {TABLE_ONLY}"
    out = _json(*TOSS, "--surface", "hand")
    assert "restitution" not in out and "friction" not in out


def test_a_tables_default_restitution_and_friction_land_as_the_same_values_given():
    """The marked defaults reach the kernels as the plain numbers: the same landings, bit for
    bit, as with restitution 0.5 and friction 0.3 given (40 landings carried to rest)."""
    rng = np.random.default_rng(5)
    omega = np.column_stack([rng.uniform(150, 300, 40), rng.uniform(-30, 30, (40, 2))])
    v0 = rng.uniform(1.5, 3.0, 40)
    coin = Coin.preset("us-nickel")
    default = land(coin, omega, v0, 1.0, 9.81, Surface("table", 0.8))
    given = land(coin, omega, v0, 1.0, 9.81, Surface("table", 0.8, 0.5, 0.3))
    for name in ("face", "status", "bounces", "first_contact", "settle_time"):
        np.testing.assert_array_equal(getattr(default, name), getattr(given, name))


def test_toss_json_reports_the_contact_options_and_equals_the_library():
    out = _json(
        *TOSS, *TABLE, "--coin", "us-nickel", "--rolling-resistance", "2e-4",
        "--pivoting-resistance", "5e-5", "--corner-radius", "3e-4",
    )  # fmt: skip
    assert "ending" not in out
    assert (out["rolling_resistance"], out["pivoting_resistance"]) == (2e-4, 5e-5)
    assert out["coin"]["corner_radius"] == 3e-4
    landing = Landing(
        Coin.preset("us-nickel").with_corner_radius(3e-4),
        Toss((240.0, 5.0, 3.0), 0.49),
        Surface("table", 0.8, rolling_resistance=2e-4, pivoting_resistance=5e-5),
    )
    expected = landing_fields(landing.outcome)
    assert {k: out[k] for k in expected} == expected
    assert out["status"] in ("settled in contact", "settled")


def test_the_default_json_reports_the_default_resistances_and_no_corner_radius():
    """A table toss's JSON always reports the resistances its landing used (the defaults when
    none is given, the same object as with them given); sharp corners add no key."""
    out = _json(*TOSS, *TABLE)
    assert "ending" not in out and "corner_radius" not in out
    assert "corner_radius" not in out["coin"]
    assert (out["rolling_resistance"], out["pivoting_resistance"]) == (
        DEFAULT_ROLLING_RESISTANCE,
        DEFAULT_PIVOTING_RESISTANCE,
    )
    assert out == _json(
        *TOSS, *TABLE, "--corner-radius", "0",
        "--rolling-resistance", str(DEFAULT_ROLLING_RESISTANCE),
        "--pivoting-resistance", str(DEFAULT_PIVOTING_RESISTANCE),
    )  # fmt: skip


def test_help_says_what_each_option_does_its_units_default_and_that_it_is_unmeasured():
    result = runner.invoke(app, ["toss", "--help"], env={"COLUMNS": "400"})
    text = " ".join(result.stdout.split())
    for words in (
        "--rolling-resistance", "rolling resistance length ℓ_r, "
        "m, 0 to 0.01", "default 1e-4). Not measured for coins", "--pivoting-resistance",
        "--corner-radius", "rim corners, m, 0 to half the thickness (or the radius if smaller;",
        "Not measured for coins (worn coins are rounder): quote a band",
    ):  # fmt: skip
        assert words in text, words


# --- probability: distributions, the work bound -------------------------------------------------
PROBABILITY = ["probability", "--omega-x", "150:300", "--flight-time", "0.4:0.6", *TABLE]


def test_probability_on_a_table_is_reproducible_from_its_seed():
    args = [*PROBABILITY, "--restitution", "0.3:0.6", "--corner-radius", "3e-4",
            "--rolling-resistance", "5e-4", "--method", "monte-carlo", "--n", "60",
            "--seed", "7", "-q"]  # fmt: skip
    first, again = _json(*args), _json(*args)
    drop = ("elapsed",)
    assert {k: v for k, v in first.items() if k not in drop} == {
        k: v for k, v in again.items() if k not in drop
    }
    assert first["seed"] == 7 and sum(first["counts"].values()) == 60
    assert first["restitution"] == {"kind": "uniform", "low": 0.3, "high": 0.6}
    assert "ending" not in first and first["rolling_resistance"] == 5e-4
    assert first["corner_radius"] == 3e-4 and first["coin_dimensions"]["corner_radius"] == 3e-4
    one_thread = _json(*args, "--threads", "1")  # the same tosses whatever the threads
    assert one_thread["counts"] == first["counts"]


def test_resistance_distributions_are_drawn_toss_by_toss():
    """The model takes them (checked against 0 to 1 cm, truncated normals); the rigid ending
    draws them toss by toss (tests/test_contact_spread.py: each toss as on its own surface),
    reproducibly from the seed, in the library and from the command line."""
    dist = TossDistribution(
        Uniform(150, 300), flight_time=Uniform(0.4, 0.6), rolling_resistance=Uniform(1e-5, 1e-3)
    )
    assert dist.ranged == ("omega_x", "flight_time", "rolling_resistance")
    u = np.random.default_rng(1).random((3, 5))
    values = dist.contact_values(u)["rolling_resistance"]
    assert np.all((values >= 1e-5) & (values <= 1e-3))
    assert "rolling_resistance = 1e-05–0.001 m (toss by toss)" in dist.describe()
    said = (
        "pivoting resistance 0–0.02 m reaches 0.02; pivoting resistance must be between 0 and "
        "0.01 m"
    )
    with pytest.raises(ValueError, match=f"^{re.escape(said)}$"):
        dist.with_contact(pivoting_resistance=Uniform(0.0, 0.02))  # the range, named
    contact = TableLanding(Surface("table", 0.8))
    first = estimate(dist, "monte-carlo", n=20, seed=1, model=contact)
    again = estimate(dist, "monte-carlo", n=20, seed=1, model=contact)
    assert first.counts == again.counts and sum(first.counts) == 20
    out = _json(*PROBABILITY, "--pivoting-resistance", "normal:1e-4,5e-5", "--method",
                "monte-carlo", "--n", "20", "--seed", "3", "-q")  # fmt: skip
    assert out["pivoting_resistance"]["kind"] == "truncated-normal"  # to 0 to 0.01 m
    assert sum(out["counts"].values()) == 20


def test_the_work_bounds_know_the_rigid_endings_rate():
    """The rigid ending's landings carried to rest are bounded at RIGID_TOSSES_PER_SECOND
    (benchmarks/bench_bounce.py --rigid-rates, its docstring), drag-free or through air; a
    bounce limit or a dead landing never reaches the ending (the bounces alone, or through
    air)."""
    table = Surface("table", 0.8)
    drag = Drag(coefficient=1.17)
    assert TableLanding(table).rate == TableLanding(table, drag).rate == RIGID_TOSSES_PER_SECOND
    assert TableLanding(table, max_bounces=3).rate == BOUNCING_TOSSES_PER_SECOND
    assert TableLanding(table, drag, max_bounces=3).rate == AIR_LANDINGS_PER_SECOND
    dead = Surface("table", 0.8, restitution=0.0)
    assert TableLanding(dead).rate == BOUNCING_TOSSES_PER_SECOND
    assert TableLanding(dead, drag).rate == AIR_LANDINGS_PER_SECOND


def test_less_resistance_bounds_the_rigid_ending_at_a_lower_rate():
    """A coin with less rolling and pivoting resistance rolls and spins longer: the rigid
    ending's rate for the work bounds is RIGID_TOSSES_PER_SECOND at the default 1e-4 m and
    above, falls as the square root of the larger resistance below it, and bottoms out at
    RIGID_SLOWEST without any (table.rigid_rate); tosses that draw their resistances are
    bounded at the harmonic mean over the draws (the expected time a landing)."""
    from coinflight.model.distributions import Uniform
    from coinflight.model.ensemble import TossDistribution
    from coinflight.outcomes.table import RIGID_SLOWEST, rigid_rate

    def rate(rolling, pivoting):
        return TableLanding(Surface("table", 0.8, 0.5, 0.3, rolling, pivoting)).rate

    assert rate(1e-3, 1e-3) == rate(1e-4, 1e-4) == rate(0.0, 1e-4) == RIGID_TOSSES_PER_SECOND
    assert rate(1e-5, 1e-5) == pytest.approx(RIGID_TOSSES_PER_SECOND * math.sqrt(0.1))
    assert rate(1e-5, 1e-5) > rate(1e-6, 0.0) > rate(1e-9, 1e-9) == rate(0.0, 0.0)
    assert rate(0.0, 0.0) == RIGID_SLOWEST
    dist = TossDistribution(omega_x=Uniform(150.0, 300.0), flight_time=Uniform(0.4, 0.6))
    drawn = dist.with_contact(rolling_resistance=Uniform(0.0, 2e-4))
    model = TableLanding(Surface("table", 0.8))
    # The expected time of a landing over ℓ_r ~ U(0, 2e-4) (ℓ_p = 1e-4 m: the rate from it).
    assert model.rate_for(drawn) == pytest.approx(RIGID_TOSSES_PER_SECOND, rel=1e-12)
    both = drawn.with_contact(pivoting_resistance=Uniform(0.0, 2e-4))
    u = (np.arange(4000) + 0.5) / 4000 * 2e-4
    expected = 1.0 / np.mean(1.0 / rigid_rate(u[:, None], u[None, :]))
    assert model.rate_for(both) == pytest.approx(expected, rel=0.02)
    assert RIGID_SLOWEST < model.rate_for(both) < RIGID_TOSSES_PER_SECOND


def test_a_map_of_rigid_landings_is_bounded_by_its_rate(tmp_path):
    said = one_line_error(
        "plot", "basin", *TABLE, "--out", tmp_path / "map.png"
    )  # 500×500 cells at 70 a second: 3,571 s
    assert said.startswith("a map of 500×500 table landings")
    assert not (tmp_path / "map.png").exists()


def test_the_library_bounds_a_map_of_rigid_landings_before_allocating_it():
    """studies.basin_map refuses, at the model's rate, a map beyond an hour (5000×5000 rigid
    landings would be 99 h); the commands keep their own minute (queries.basin.MAP_SECONDS)."""
    from coinflight.studies.basin import basin_map

    model = TableLanding(Surface("table", 0.8))
    rate = RIGID_TOSSES_PER_SECOND  # the rigid ending's measured rate, the model's
    assert model.rate == rate
    limit = rate * v.MAX_RUN_SECONDS  # an hour of landings at that rate
    said = (
        f"a map of 5,000×5,000 tosses (table landing) is 25,000,000 tosses (about "
        f"{v.duration(2.5e7 / rate)} at {v.estimate(rate)} tosses/s), more than the limit of "
        f"{v.quantity(limit)} tosses (about 60 min); use a coarser resolution"
    )
    with pytest.raises(ValueError, match=f"^{re.escape(said)}$"):
        basin_map(Coin.preset("us-nickel"), resolution=(5000, 5000), outcome=model)
    side = math.isqrt(int(limit)) + 1  # the smallest square map beyond the limit
    with pytest.raises(
        ValueError, match=re.escape(f"more than the limit of {v.quantity(limit)} tosses")
    ):
        basin_map(Coin.preset("us-nickel"), resolution=(side, side), outcome=model)
    one = basin_map(Coin.preset("us-nickel"), (0.4, 0.5), (150, 300), resolution=(1, 2),
                    outcome=model)  # fmt: skip
    assert one.face.shape == (2, 1)


# --- sweep --------------------------------------------------------------------------------------
def test_sweep_over_resistances_and_corner_radii(tmp_path):
    out = tmp_path / "s.csv"
    result = runner.invoke(app, [
        "sweep", "--omega-x", "150:300", "--flight-time", "0.4:0.6", *TABLE,
        "--rolling-resistance", "1e-5,1e-3",
        "--corner-radius", "0,3e-4", "--method", "monte-carlo", "--n", "20", "--seed", "3",
        "--out", str(out), "-q",
    ])  # fmt: skip
    assert result.exit_code == 0, result.output
    with open(out, newline="", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    # 2 corner radii × 2 rolling resistances
    assert len(rows) == 4
    seen = {(r["coin.corner_radius"], r["rolling_resistance"]) for r in rows}
    assert seen == {(a, ell) for a in ("", "0.0003") for ell in ("1e-05", "0.001")}
    assert "ending" not in rows[0]
    assert len({r["key"] for r in rows}) == 4 and len({r["stream"] for r in rows}) == 4


@pytest.mark.parametrize(
    ("args", "start"),
    [
        (["--surface", "hand,table", "--corner-radius", "1e-4"],
         "--corner-radius applies to --surface table only"),
        (["--surface", "hand", "--pivoting-resistance", "1e-4,2e-4"],
         f"--pivoting-resistance {TABLE_ONLY}"),
        (["--surface", "table", "--pivoting-resistance", "1e-4,0.02"],
         "--pivoting-resistance"),
        (["--surface", "table", "--corner-radius", "0.001"], "--corner-radius: US quarter: corner "
         "radius must be between 0 and 0.000875"),
        (["--surface", "table", "--method", "qmc"],
         "on a table each landing is carried to rest through the rigid 3-D ending"),
    ],
)  # fmt: skip
def test_sweep_refuses_bad_contact_options_in_one_line(args, start, tmp_path):
    said = one_line_error(
        "sweep", "--omega-x", "150:300", "--flight-time", "0.4:0.6", *args,
        "--method" if "--method" not in args else "--seed",
        "monte-carlo" if "--method" not in args else "1", "--n" if "qmc" not in args else "-q",
        *(["10"] if "qmc" not in args else []), "--out", tmp_path / "s.csv",
    )  # fmt: skip
    assert said.startswith(start), said


# --- the web API: the same object, the same one-line errors -------------------------------------
@pytest.fixture(scope="module")
def client():
    with TestClient(create_app()) as c:
        yield c


def test_the_api_gives_the_command_lines_object(client):
    url = (
        "/api/toss?omega=240,5,3&flight_time=0.49&surface=table&drop_height=0.8"
        "&rolling_resistance=2e-4&pivoting_resistance=5e-5&corner_radius=3e-4&coin=us-nickel"
    )
    expected = _json(
        *TOSS, *TABLE, "--rolling-resistance", "2e-4", "--pivoting-resistance", "5e-5",
        "--corner-radius", "3e-4", "--coin", "us-nickel",
    )  # fmt: skip
    assert api_answer(client.get(url)) == expected
    url = (
        "/api/probability?omega_x=150:300&flight_time=0.4:0.6&surface=table&drop_height=0.8"
        "&corner_radius=2e-4&restitution=0.3:0.6&method=monte-carlo&n=30&seed=4"
    )
    got = api_answer(client.get(url))
    expected = _json(*PROBABILITY, "--corner-radius", "2e-4", "--restitution", "0.3:0.6",
                     "--method", "monte-carlo", "--n", "30", "--seed", "4", "-q")  # fmt: skip
    for obj in (got, expected):
        obj.pop("elapsed")
        obj.pop("inputs")  # the command line repeats its typed options; the API its own
    assert got == expected


@pytest.mark.parametrize(
    ("query", "args"),
    [
        ("corner_radius=0.001", ["--corner-radius", "0.001"]),
        ("rolling_resistance=-1", ["--rolling-resistance", "-1"]),
        ("pivoting_resistance=0.02", ["--pivoting-resistance", "0.02"]),
    ],
)  # fmt: skip
def test_the_api_refuses_in_the_command_lines_words(client, query, args):
    response = client.get(f"/api/toss?omega=240,5,3&flight_time=0.49&surface=table&{query}")
    assert response.status_code == 422
    assert response.json()["detail"] == one_line_error(*TOSS, "--surface", "table", *args)
