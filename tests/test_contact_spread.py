"""Restitution and friction as distributions over the tosses (issue 11: "uncertainty, not a
point"): the values, the per-toss kernel, the estimators that integrate over them, the refusals
and the command line."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scipy import stats
from typer.testing import CliRunner

from _cli import one_line_error
from _kernels import coin_contact
from coinflight.cli import app
from coinflight.core import bounce
from coinflight.model.coin import Coin
from coinflight.model.distributions import Fixed, Normal, TruncatedNormal, Uniform
from coinflight.model.ensemble import TossDistribution
from coinflight.model.surface import (
    MAX_FRICTION,
    TABLE_ONLY,
    Drag,
    Surface,
    contact_distribution,
)
from coinflight.outcomes.table import TableLanding
from coinflight.probability import estimate

TABLE = TableLanding(Surface("table", drop_height=0.3))
G = 9.81
SPINS = {"omega_x": Uniform(150.0, 300.0), "omega_z": 20.0, "launch_speed": Uniform(2.0, 3.0)}


# --- the values -------------------------------------------------------------------------------
def test_a_normal_contact_parameter_is_truncated_not_clipped():
    d = contact_distribution("friction", Normal(0.1, 0.1))
    assert isinstance(d, TruncatedNormal)
    # SciPy's truncnorm is the reference: mass outside [0, MAX_FRICTION] left out, the rest
    # renormalised.
    ref = stats.truncnorm(-1.0, (MAX_FRICTION - 0.1) / 0.1, loc=0.1, scale=0.1)
    u = np.linspace(0.01, 0.99, 7)
    np.testing.assert_allclose(d.ppf(u), ref.ppf(u), rtol=1e-12)
    assert d.mean == pytest.approx(ref.mean(), rel=1e-12)
    assert d.kept == pytest.approx(stats.norm.cdf(1.0), rel=1e-12)  # Φ(1): 84 % kept
    assert d.ppf(np.array([1e-12]))[0] >= 0.0  # no draw below the range, none piled at 0
    assert "truncated to [0, 3]" in d.describe() and "84.1 % kept" in d.describe()
    e = contact_distribution("restitution", Normal(0.9, 0.2))
    assert e.bounds == (0.0, 1.0) and e.ppf(np.array([0.999999]))[0] <= 1.0


@pytest.mark.parametrize(
    ("name", "value", "words"),
    [
        ("restitution", 1.2, "restitution must be between 0 and 1, got 1.2"),
        ("friction", -0.1, "friction must be between 0 and 3, got -0.1"),
        ("friction", 3.5, "friction must be between 0 and 3, got 3.5"),
        ("restitution", Uniform(0.3, 1.1), "reaches 1.1; restitution must be between 0 and 1"),
        ("friction", Uniform(-0.1, 0.3), "reaches -0.1; friction must be between 0 and 3"),
        ("friction", Uniform(0.3, 12.0), "reaches 12; friction must be between 0 and 3"),
        (
            "friction",
            Normal(-0.2, 0.1),
            "mean outside the physical range; friction must be between 0 and 3",
        ),
        ("restitution", Normal(1.5, 0.1), "mean outside the physical range"),
    ],
)
def test_contact_values_outside_their_range_are_refused(name, value, words):
    with pytest.raises(ValueError, match=words.replace("(", r"\(")):
        contact_distribution(name, value)


def test_the_contact_parameters_are_ranged_after_the_toss_parameters():
    d = TossDistribution(**SPINS, restitution=Uniform(0.3, 0.6), friction=0.4)
    assert d.ranged == ("omega_x", "flight_time", "restitution")
    assert d.friction == Fixed(0.4)
    u = np.array([[0.5, 0.25], [0.5, 0.5], [0.0, 1.0]])
    values = d.contact_values(u)
    np.testing.assert_allclose(values["restitution"], [0.3, 0.6])
    np.testing.assert_allclose(values["friction"], [0.4, 0.4])
    assert "restitution = 0.3–0.6 (toss by toss)" in d.describe()
    with pytest.raises(ValueError, match="restitution must be between 0 and 1"):
        TossDistribution(**SPINS, restitution=Uniform(0.5, 1.5))


# --- the kernel: each toss its own e and μ -------------------------------------------------------
def _contact(coin, e, mu):
    # the library's default resistances (1e-4 m), which stop the rolling of the rigid ending
    return coin_contact(
        coin,
        restitution=e,
        friction=mu,
        drop_height=0.3,
        rolling_resistance=1e-4,
        pivoting_resistance=1e-4,
    )


def test_per_toss_contact_is_the_same_as_one_surface_per_toss():
    coin = Coin.preset("us-nickel")
    rng = np.random.default_rng(5)
    n = 32  # landings carried to rest (a few ms each), four times over
    omega = np.column_stack([rng.uniform(150, 300, n), rng.uniform(-5, 5, n), np.full(n, 20.0)])
    speed = rng.uniform(2.0, 3.0, n)
    e = rng.uniform(0.0, 0.9, n)
    mu = rng.uniform(0.0, 1.0, n)
    base = _contact(coin, 0.5, 0.3)
    assert bounce.with_surface(base, 0.2, 0.7, 1e-4, 2e-4, 3e-4) == base._replace(
        restitution=0.2,
        friction=0.7,
        rolling_resistance=1e-4,
        pivoting_resistance=2e-4,
        contact_duration=3e-4,
    )
    together = bounce.land(omega, speed, 1.0, base, restitution=e, friction=mu)
    for k in range(n):
        alone = bounce.land(omega[k : k + 1], speed[k : k + 1], 1.0, _contact(coin, e[k], mu[k]))
        for a, b in zip(together, alone, strict=True):
            assert a[k] == b[0]
    # Without arrays, the contact's own values for every toss.
    plain = bounce.land(omega, speed, 1.0, base)
    same = bounce.land(
        omega, speed, 1.0, base, restitution=np.full(n, 0.5), friction=np.full(n, 0.3)
    )
    for a, b in zip(plain, same, strict=True):
        np.testing.assert_array_equal(a, b)


def test_per_toss_resistances_are_the_same_as_one_surface_per_toss():
    # The rigid 3-D ending (where the resistances act): tosses given their own rolling and
    # pivoting resistance land exactly as each on its own surface.
    coin = Coin.preset("us-nickel")
    rng = np.random.default_rng(8)
    n = 24
    omega = np.column_stack([rng.uniform(150, 300, n), rng.uniform(-5, 5, n), np.full(n, 20.0)])
    speed = rng.uniform(2.0, 3.0, n)
    rolling = rng.uniform(1e-5, 1e-3, n)
    pivoting = rng.uniform(1e-5, 1e-3, n)

    def record(lr, lp):
        return _resisting(coin, lr, lp)

    base = record(1e-4, 1e-4)
    together = bounce.land(
        omega, speed, 1.0, base, rolling_resistance=rolling, pivoting_resistance=pivoting
    )
    settle_differs = 0
    for k in range(n):
        alone = bounce.land(
            omega[k : k + 1], speed[k : k + 1], 1.0, record(rolling[k], pivoting[k])
        )
        for a, b in zip(together, alone, strict=True):
            assert a[k] == b[0]
        plain = bounce.land(omega[k : k + 1], speed[k : k + 1], 1.0, base)
        settle_differs += plain[3][0] != alone[3][0]
    assert settle_differs > 0  # the resistances did reach the kernel (they change settle times)


def _resisting(coin, rolling, pivoting):
    return coin_contact(
        coin,
        drop_height=0.3,
        rolling_resistance=float(rolling),
        pivoting_resistance=float(pivoting),
    )


# --- the estimators integrate over them ------------------------------------------------------
def test_the_grid_over_restitution_is_the_mean_of_the_grids_at_its_nodes():
    # Method A over (ωx, e): n × n configurations; the same as n grids over ωx alone, one at
    # each restitution node (i + ½)/n of e's range, summed. Exact counts, no tolerance.
    n = 12
    spread = TossDistribution(
        omega_x=Uniform(150.0, 300.0), flight_time=0.5, restitution=Uniform(0.2, 0.8)
    )
    whole = estimate(spread, "grid", n=n, model=TABLE)
    parts = np.zeros(3, dtype=int)
    for i in range(n):
        e = 0.2 + 0.6 * (i + 0.5) / n
        at = TossDistribution(omega_x=Uniform(150.0, 300.0), flight_time=0.5, restitution=e)
        parts += np.array(estimate(at, "grid", n=n, model=TABLE).counts)
    assert tuple(parts) == whole.counts


def test_monte_carlo_over_friction_is_seeded_and_reported():
    d = TossDistribution(**SPINS, friction=Normal(0.4, 0.1), restitution=Uniform(0.3, 0.6))
    # landings carried to rest cost a few ms each: 200 tosses, 100 below
    a = estimate(d, "monte-carlo", n=200, seed=7, model=TABLE)
    b = estimate(d, "monte-carlo", n=200, seed=7, model=TABLE)
    assert a.counts == b.counts and a.seed == 7
    # A fixed value in the distribution is the surface's value: the same tosses, same faces.
    fixed = TossDistribution(**SPINS, restitution=0.5, friction=0.3)
    plain = TossDistribution(**SPINS)
    assert (
        estimate(fixed, "monte-carlo", n=100, seed=3, model=TABLE).counts
        == estimate(plain, "monte-carlo", n=100, seed=3, model=TABLE).counts
    )
    from coinflight.queries.landing import describe_for, settings_for

    assert "normal(0.4, sd 0.1) truncated to [0, 3]" in describe_for(TABLE, d)
    settings = settings_for(TABLE, d)
    assert settings["friction"] == {
        "kind": "truncated-normal",
        "mean": 0.4,
        "sd": 0.1,
        "low": 0.0,
        "high": MAX_FRICTION,
    }
    assert settings["restitution"] == {"kind": "uniform", "low": 0.3, "high": 0.6}


def test_qmc_takes_contact_distributions():
    d = TossDistribution(**SPINS, restitution=Uniform(0.3, 0.6))
    r = estimate(d, "qmc", n=64, seed=2, model=TABLE)
    assert math.isclose(r.p_heads + r.p_tails + r.p_edge, 1.0)


def test_tosses_through_air_land_with_their_own_contact_values():
    """Through air (drag and spin damping) each toss takes its own restitution, friction,
    resistances and contact duration, as without: the batch with per-toss values lands each
    toss as a landing alone on a table of its values does, bit for bit; the estimators take
    the distributions (a Monte Carlo run through air with a drawn restitution)."""
    from coinflight.outcomes.table import land

    coin = Coin.preset("us-nickel")
    air = Drag(coefficient=1.17, spin_damping=1e-7)
    rng = np.random.default_rng(4)
    n = 6
    omega = np.column_stack([rng.uniform(150, 250, n), rng.uniform(-20, 20, (n, 2))])
    v0 = rng.uniform(1.5, 2.5, n)
    values = {
        "restitution": rng.uniform(0.2, 0.7, n),
        "friction": rng.uniform(0.1, 0.8, n),
        "rolling_resistance": rng.uniform(5e-5, 5e-4, n),
        "pivoting_resistance": rng.uniform(5e-5, 5e-4, n),
        "contact_duration": rng.uniform(5e-5, 5e-4, n),
    }
    table = Surface("table", drop_height=0.3)
    batch = land(coin, omega, v0, 1.0, G, table, drag=air, contact=values)
    for k in range(n):
        own = Surface("table", 0.3, *(float(values[name][k]) for name in values))
        alone = land(coin, omega[k : k + 1], v0[k : k + 1], 1.0, G, own, drag=air)
        assert (batch.face[k], batch.bounces[k], batch.status[k]) == (
            alone.face[0],
            alone.bounces[0],
            alone.status[0],
        )
        assert batch.settle_time[k] == alone.settle_time[0]
    d = TossDistribution(**SPINS, restitution=Uniform(0.3, 0.6))
    model = TableLanding(table, air)
    r = estimate(d, "monte-carlo", n=12, seed=2, model=model)
    assert sum(r.counts) == 12


@pytest.mark.parametrize(
    ("method", "model", "words"),
    [
        ("monte-carlo", None, "hand catch has no contact with a surface"),
        (
            "exact",
            TABLE,
            "the exact method handles the hand catch only, not table landing; use "
            "--method grid, monte-carlo or qmc",
        ),
    ],
)
def test_models_that_cannot_take_contact_distributions_refuse_them(method, model, words):
    d = TossDistribution(**SPINS, restitution=Uniform(0.3, 0.6))
    kwargs = {} if model is None else {"model": model}
    with pytest.raises(ValueError, match=words):
        estimate(d, method, n=None if method == "exact" else 100, **kwargs)


# --- the command line ---------------------------------------------------------------------------
PROB = [
    "probability",
    "--omega-x",
    "150:300",
    "--omega-z",
    "20",
    "--launch-speed",
    "2:3",
    "--surface",
    "table",
    "--drop-height",
    "0.3",
    "-m",
    "monte-carlo",
    "--n",
    "100",
    "--seed",
    "4",
    "-q",
]


def test_cli_probability_integrates_over_restitution_and_friction():
    args = [*PROB, "--restitution", "0.3:0.6", "--friction", "normal:0.4,0.1"]
    result = CliRunner().invoke(app, [*args, "--json"])
    assert result.exit_code == 0, result.output
    out = json.loads(result.stdout)
    assert out["restitution"] == {"kind": "uniform", "low": 0.3, "high": 0.6}
    assert out["distribution"]["friction"]["kind"] == "truncated-normal"
    d = TossDistribution(
        **SPINS,
        coin=Coin.preset("us-quarter"),
        restitution=Uniform(0.3, 0.6),
        friction=Normal(0.4, 0.1),
    )
    lib = estimate(d, "monte-carlo", n=100, seed=4, model=TABLE)
    assert [out["counts"][k] for k in ("tails", "heads", "edge")] == list(lib.counts)
    text = CliRunner().invoke(app, args)
    assert text.exit_code == 0, text.output
    assert "restitution 0.3–0.6, friction normal(0.4, sd 0.1) truncated to [0, 3]" in text.stdout


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (
            [
                "toss",
                "--omega",
                "80",
                "0",
                "0",
                "--flight-time",
                "0.7",
                "--surface",
                "table",
                "--restitution",
                "0.3:0.6",
            ],
            "--restitution 0.3–0.6: this command takes a single value",
        ),
        ([*PROB, "--restitution", "0.3:1.6"], "restitution must be between 0 and 1"),
        ([*PROB, "--friction", "normal:-1,0.1"], "friction must be between 0 and 3"),
        ([*PROB, "--friction", "low"], "--friction 'low'"),
    ],
)
def test_cli_refuses_contact_distributions_where_they_do_not_apply(args, words):
    assert words in one_line_error(*args)


# --- surface presets ---------------------------------------------------------------------------
def test_surface_presets_carry_their_ranges_and_sources():
    from coinflight.studies.presets import SURFACE_PRESETS, surface_preset

    wood = surface_preset("coin-on-wood")
    # Module notes of coinflight.studies.presets: e 0.3-0.6 (a band around Pletser 2022's
    # assumed 0.5), μ 0.2-0.6 (Engineering ToolBox, wood on metal, clean and dry, static).
    assert wood.restitution == Uniform(0.3, 0.6) and wood.friction == Uniform(0.2, 0.6)
    table = surface_preset("coin-on-table")
    assert table.friction == Uniform(0.05, 0.5)  # Pletser 2022 (0.05) to our upper bound 0.5
    for p in SURFACE_PRESETS.values():
        assert set(p.sources) == {"restitution", "friction", "contact_duration"}
        for name, d in p.contact.items():
            lo, hi = d.bounds
            assert f"{lo:g}-{hi:g}" in p.sources[name]  # each range quoted with its source
            assert contact_distribution(name, d) == d
    with pytest.raises(ValueError, match=r"unknown surface preset 'wood'.*coin-on-wood"):
        surface_preset("wood")


def test_cli_surface_preset_integrates_over_the_ranges_and_is_replaced_by_given_values():
    args = [*PROB, "--surface-preset", "coin-on-wood", "--friction", "0.3"]
    result = CliRunner().invoke(app, [*args, "--json"])
    assert result.exit_code == 0, result.output
    out = json.loads(result.stdout)
    assert out["surface_preset"]["name"] == "coin-on-wood"
    assert out["restitution"] == {"kind": "uniform", "low": 0.3, "high": 0.6}
    assert out["friction"] == 0.3  # given: replaces the preset's range
    # the preset's contact duration too (Hertz's contact times on wood, presets' notes)
    assert out["contact_duration"] == {"kind": "uniform", "low": 5e-5, "high": 3e-4}
    d = TossDistribution(
        **SPINS, restitution=Uniform(0.3, 0.6), contact_duration=Uniform(5e-5, 3e-4)
    )
    model = TableLanding(Surface("table", drop_height=0.3, friction=0.3))
    lib = estimate(d, "monte-carlo", n=100, seed=4, model=model)
    assert [out["counts"][k] for k in ("tails", "heads", "edge")] == list(lib.counts)
    text = CliRunner().invoke(app, args)
    assert "surface preset coin-on-wood: restitution 0.3–0.6, friction 0.2–0.6" in text.stdout


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (
            [
                "toss",
                "--omega",
                "80",
                "0",
                "0",
                "--flight-time",
                "0.7",
                "--surface",
                "table",
                "--surface-preset",
                "coin-on-wood",
            ],
            "this command takes single values",
        ),
        ([*PROB, "--surface-preset", "oak"], "unknown surface preset 'oak'"),
        (
            [
                "probability",
                "--omega-x",
                "60:90",
                "--flight-time",
                "0.6:0.9",
                "--surface-preset",
                "coin-on-wood",
            ],
            f"--surface-preset {TABLE_ONLY}",
        ),
    ],
)
def test_cli_surface_preset_refusals(args, words):
    assert words in one_line_error(*args)


def test_the_kernels_take_per_toss_what_a_distribution_spreads():
    """The landing kernels' per-toss arguments (core.bounce.PER_TOSS, in their order) are the
    contact parameters a distribution of tosses spreads (model.ensemble.CONTACT), and a name
    the kernels do not take is a TypeError naming it."""
    from coinflight.model.ensemble import CONTACT

    assert bounce.PER_TOSS == CONTACT
    contact = coin_contact(Coin.preset("us-nickel"))
    with pytest.raises(TypeError, match="unexpected per-toss values stiffness"):
        bounce.land(np.array([[200.0, 0.0, 0.0]]), 2.0, 1.0, contact, stiffness=np.ones(1))
