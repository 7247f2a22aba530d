"""Values are validated once, at their root: physical ranges in the value objects, argument types
in the estimator API, one wording for every error (the field, the value, the allowed range).

Each reported failure of issue 10 (items 5, 6, 7, 9) is a case here, in the library and, for the
command line, through typer's CliRunner (exit code 2, one line on stderr, no traceback).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from typer.testing import CliRunner

from _cli import one_line_error
from coinflight import Coin, Toss
from coinflight._validation import PlausibilityWarning, Quantity
from coinflight.cli import app
from coinflight.model.coin import MASS, PRESETS, RADIUS, THICKNESS
from coinflight.model.distributions import Uniform
from coinflight.model.ensemble import TossDistribution
from coinflight.model.surface import Surface
from coinflight.model.toss import GRAVITY
from coinflight.outcomes.table import Landing, TableLanding
from coinflight.probability import estimate

runner = CliRunner()
QUARTER = {"radius": 0.01213, "thickness": 0.00175, "mass": 0.00567}  # REFERENCES §7, in SI
FIG_2A = TossDistribution(Uniform(60, 90), 0, 0, Uniform(0.6, 0.9))  # Stefan & Cheche Fig 2a


# --- the coin ---------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("field", "bad", "message"),
    [
        # Reported: mass 1e-320 → ZeroDivisionError in the torque-free flight (I3/I1 = 0/0).
        ("mass", 1e-320, "mass must be between 1e-09 and 1e+06 (in kg), got 1e-320"),
        # Reported: radius 1e308 → "Found zero norm quaternions in `quat`" (r² overflows).
        ("radius", 1e308, "radius must be between 1e-06 and 1000 (in m), got 1e+308"),
        ("radius", 1e-320, "radius must be between 1e-06 and 1000 (in m), got 1e-320"),
        ("thickness", 0.0, "thickness must be between 1e-06 and 1000 (in m), got 0.0"),
        ("thickness", math.nan, "thickness must be between 1e-06 and 1000 (in m), got nan"),
    ],
)
def test_coin_outside_its_hard_range_is_a_value_error(field, bad, message):
    with pytest.raises(ValueError) as info:
        Coin(**{**QUARTER, field: bad})
    assert str(info.value) == message


def test_coin_hard_range_ends_are_allowed_and_the_flight_stays_finite():
    # The ends of the hard ranges are accepted (with the warning of an unusual coin), and the
    # arithmetic of the flight survives them: that is what the hard range is for.
    from coinflight.model.toss import Flight

    for radius, thickness, mass in [(1e-6, 1e3, 1e-9), (1e3, 1e-6, 1e6), (1e3, 1e3, 1e-9)]:
        with pytest.warns(PlausibilityWarning):
            coin = Coin(radius=radius, thickness=thickness, mass=mass)
        outcome = Flight(coin, Toss((80.0, 3.0, 1.0), 0.7)).outcome
        assert np.isfinite(outcome.rotations) and np.isfinite(outcome.psi)


@pytest.mark.parametrize("field", ["radius", "thickness", "mass"])
@pytest.mark.parametrize("bad", ["0.01", True, np.bool_(True), None, [0.01, 0.02], 1j])
def test_coin_fields_must_be_numbers(field, bad):
    # Reported: Coin(radius="0.01") and radius=True were accepted. A string is text however
    # numeric it reads, and True is not 1.0.
    with pytest.raises(TypeError, match=rf"^{field} must be a (single )?number"):
        Coin(**{**QUARTER, field: bad})


def test_coin_name_must_be_a_string():
    with pytest.raises(TypeError, match=r"^name must be a string, got int 3$"):
        Coin(**QUARTER, name=3)  # type: ignore[arg-type]


def test_a_coin_in_millimetres_and_grams_is_accepted_with_a_warning():
    # Reported: a US quarter given in mm and g as if in m and kg was accepted without a word.
    with pytest.warns(PlausibilityWarning) as caught:
        coin = Coin(radius=12.13, thickness=1.75, mass=5.67)
    assert len(caught) == 1  # one warning for the coin, not one per field
    assert str(caught[0].message) == (
        "radius 12.13 m is not a coin's size (1 mm to 10 cm); "
        "thickness 1.75 m is not a coin's thickness (0.1 mm to 5 cm); "
        "mass 5.67 kg is not a coin's mass (0.1 g to 1 kg): "
        "did you give millimetres and grams? Coin takes m and kg; see Coin.from_mm_g for mm and g"
    )
    assert caught[0].filename == __file__  # points at the caller, not at coinflight
    assert coin.radius == 12.13


def test_one_odd_field_names_only_that_field():
    with pytest.warns(PlausibilityWarning) as caught:
        Coin(**{**QUARTER, "radius": 12.13})
    assert str(caught[0].message).startswith(
        "radius 12.13 m is not a coin's size (1 mm to 10 cm): did you give millimetres?"
    )
    with pytest.warns(PlausibilityWarning, match=r"^mass 5e-06 kg is not a coin's mass .*: Coin"):
        Coin(**{**QUARTER, "mass": 5e-6})


def test_from_mm_g_builds_the_same_coin_in_spec_units():
    # US quarter: d 24.26 mm, h 1.75 mm, m 5.670 g (REFERENCES §7); no warning (pytest runs with
    # warnings as errors).
    coin = Coin.from_mm_g(diameter_mm=24.26, thickness_mm=1.75, mass_g=5.67)
    assert coin == Coin.preset("us-quarter")
    assert coin.radius == pytest.approx(0.01213, rel=1e-15)
    with pytest.raises(TypeError, match=r"^thickness_mm must be a number"):
        Coin.from_mm_g(diameter_mm=24.26, thickness_mm="1.75", mass_g=5.67)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match=r"^mass_g must be finite"):
        Coin.from_mm_g(diameter_mm=24.26, thickness_mm=1.75, mass_g=math.inf)


def test_every_preset_is_a_usual_coin():
    for coin in PRESETS.values():
        for quantity in (RADIUS, THICKNESS, MASS):
            assert quantity.is_usual(getattr(coin, quantity.name)), (coin.name, quantity.name)


def test_quantity_check_is_the_one_wording():
    q = Quantity("drop height", "m", 0.0, 1e3)
    assert q.check(np.float64(2.0)) == 2.0
    assert q.check(1000) == 1000.0
    for bad, shown in [(-1.0, "-1.0"), (1000.5, "1000.5"), (math.inf, "inf")]:
        with pytest.raises(ValueError) as info:
            q.check(bad)
        assert str(info.value) == f"drop height must be between 0 and 1000 (in m), got {shown}"
    with pytest.raises(TypeError, match=r"^drop height must be a single number, got an array"):
        q.check([1.0, 2.0])
    with pytest.raises(TypeError, match=r"^drop height must be a number or an array of numbers"):
        q.check("1")


# --- the toss: g and the flight time ----------------------------------------------------------


@pytest.mark.parametrize(
    ("bad", "shown"), [(0.0, "0.0"), (1e-320, "1e-320"), (-9.81, "-9.81"), (1e308, "1e+308")]
)
def test_gravity_outside_its_range_is_a_value_error(bad, shown):
    message = f"g must be between 0.001 and 1000 (in m/s²), got {shown}"
    with pytest.raises(ValueError) as info:
        Toss((80.0, 0.0, 0.0), 0.7, g=bad)
    assert str(info.value) == message
    with pytest.raises(ValueError) as info:
        Toss.from_launch_speed((80.0, 0.0, 0.0), 3.4, g=bad)
    assert str(info.value) == message
    with pytest.raises(ValueError) as info:
        TossDistribution(Uniform(60, 90), 0, 0, Uniform(0.6, 0.9), g=bad)
    assert str(info.value) == message


def test_gravity_must_be_a_number():
    with pytest.raises(TypeError, match=r"^g must be a number"):
        Toss((80.0, 0.0, 0.0), 0.7, g=True)
    with pytest.raises(TypeError, match=r"^g must be a number"):
        TossDistribution(Uniform(60, 90), 0, 0, Uniform(0.6, 0.9), g="9.81")  # type: ignore[arg-type]


def test_unusual_gravity_is_a_warning():
    with pytest.warns(PlausibilityWarning, match=r"^g 981 m/s² is not a surface gravity .*cm/s²\?"):
        Toss((80.0, 0.0, 0.0), 0.7, g=981.0)
    with pytest.warns(PlausibilityWarning, match=r"^g 0.01 m/s² is not a surface gravity"):
        TossDistribution(Uniform(60, 90), 0, 0, Uniform(0.6, 0.9), g=0.01)
    assert GRAVITY.is_usual(1.62) and GRAVITY.is_usual(274.0)  # the Moon, the Sun's surface
    Toss((80.0, 0.0, 0.0), 0.7, g=1.62)  # no warning: pytest turns one into an error


def test_flight_time_and_launch_speed_keep_the_apex_finite():
    with pytest.raises(ValueError, match=r"^flight time must be between 1e-06 and 10000 \(in s\)"):
        Toss((0.0, 0.0, 0.0), 1e300)  # the apex g T² / 8 was nan
    with pytest.raises(ValueError) as info:
        Toss.from_launch_speed((0.0, 0.0, 0.0), 1e300)
    assert str(info.value) == (
        "launch speed must give a flight time 2 v0 / g between 1e-06 and 10000 s, got 1e+300 m/s "
        "(T = 2.04e+299 s at g = 9.81 m/s²)"
    )
    with pytest.warns(PlausibilityWarning, match=r"^g 1000 m/s²"):
        toss = Toss((0.0, 0.0, 0.0), 1e4, g=1e3)  # the corner of the ranges
    assert np.isfinite(toss.apex) and float(toss.apex) == pytest.approx(1.25e10, rel=1e-12)


def test_bool_arrays_are_not_spins():
    with pytest.raises(TypeError, match=r"^omega must be a number or an array of numbers"):
        Toss(np.array([True, False, False]), 0.7)


# --- the table -------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("field", "bad", "message"),
    [
        # Found by tests/test_cli_generated.py: --drag 1e308 overflowed in the integration.
        ("coefficient", 1e308, "drag coefficient must be between 0 and 10, got 1e+308"),
        ("spin_damping", 1.0, "spin damping must be between 0 and 0.001 (in N m s), got 1.0"),
        ("air_density", True, None),
    ],
)
def test_drag_is_bounded(field, bad, message):
    from coinflight.model.surface import Drag

    if message is None:
        with pytest.raises(TypeError, match=r"^air density must be a number"):
            Drag(**{field: bad})
        return
    with pytest.raises(ValueError) as info:
        Drag(**{field: bad})
    assert str(info.value) == message


def test_drop_height_is_bounded():
    with pytest.raises(ValueError) as info:
        Surface("table", drop_height=1e308)
    assert str(info.value) == "drop height must be between 0 and 1000 (in m), got 1e+308"
    with pytest.raises(TypeError, match=r"^drop height must be a number"):
        Surface("table", drop_height=True)


def test_a_landing_from_the_highest_table_drop_lands_at_the_free_fall_time():
    # Reported: --drop-height 1e308 printed "lands on the table at t = -1.0000 s". At the top of
    # the range the first contact comes when the centre of mass has fallen the drop height less
    # the coin's reach (between h/2 and r), by z(t) = v0 t − g t²/2 (Stefan & Cheche §2).
    coin, drop, g = Coin.preset("us-quarter"), 1000.0, 9.81
    toss = Toss((80.0, 0.0, 0.0), 0.7, g=g)
    first = float(Landing(coin, toss, Surface("table", drop_height=drop)).outcome.first_contact)
    v0 = float(toss.launch_speed)

    def fall_time(depth: float) -> float:
        return (v0 + math.sqrt(v0 * v0 + 2.0 * g * depth)) / g

    assert fall_time(drop - coin.radius) <= first <= fall_time(drop - coin.thickness / 2)


@pytest.mark.parametrize(("bad", "error"), [(2.5, TypeError), (True, TypeError), (-1, ValueError)])
def test_max_bounces_is_a_whole_number(bad, error):
    # Reported: bounces=2.5 was accepted (and truncated to 2).
    surface = Surface("table", drop_height=0.3)
    with pytest.raises(error, match=r"^max_bounces must be"):
        TableLanding(surface, max_bounces=bad)
    with pytest.raises(error, match=r"^max_bounces must be"):
        Landing(Coin.preset("us-quarter"), Toss((80.0, 0, 0), 0.7), surface, max_bounces=bad)


# --- the estimator API ------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"dist": None}, "^dist must be a TossDistribution, got NoneType None$"),
        ({"dist": {}}, r"^dist must be a TossDistribution, got dict \{\}$"),
        ({"method": 3}, "^method must be a string, one of exact, grid, monte-carlo, qmc"),
        ({"model": "hand"}, "^model must be an OutcomeModel"),
        ({"method": "grid", "n": 2.5}, "^n must be an integer, got float 2.5$"),
        ({"method": "grid", "n": 8, "executor": object()}, "^executor must be None .* map"),
        ({"method": "grid", "n": 8, "progress": 5}, "^progress must be a callable .* got int 5$"),
        ({"method": "grid", "n": 8, "threads": "2"}, "^threads must be an integer, got str '2'$"),
        ({"method": "qmc", "n": 64, "threads": True}, "^threads must be an integer, got bool"),
    ],
)
def test_estimate_names_the_bad_argument(kwargs, message):
    # Reported: AttributeError, IndexError or "'int' object is not callable" from deep inside.
    kwargs = {"dist": FIG_2A, **kwargs}
    with pytest.raises(TypeError, match=message):
        estimate(**kwargs)


def test_estimate_threads_must_be_a_sensible_count():
    from coinflight.probability._runner import MAX_THREADS

    with pytest.raises(ValueError, match=r"^threads must be between 1 and 1024, got 0$"):
        estimate(FIG_2A, "grid", 8, threads=0)
    # issue: --threads 99999999999999999999 was accepted (a pool that size)
    with pytest.raises(ValueError, match=r"^threads must be between 1 and 1024, got 10{20}$"):
        estimate(FIG_2A, "grid", 8, threads=10**20)
    assert MAX_THREADS == 1024
    assert estimate(FIG_2A, "grid", 8, threads=MAX_THREADS).p_heads == pytest.approx(
        estimate(FIG_2A, "grid", 8, threads=1).p_heads
    )


def test_the_estimators_check_the_runner_options_themselves():
    # Called directly, not through estimate: the same check, in the shared runner.
    from coinflight.probability import grid

    with pytest.raises(TypeError, match=r"^progress must be a callable"):
        grid.estimate(FIG_2A, 8, progress=5)
    with pytest.raises(TypeError, match=r"^executor must be None"):
        grid.estimate(FIG_2A, 8, executor=object())


# --- the bias Monte Carlo check ---------------------------------------------------------------


def test_same_side_simulation_needs_enough_tosses_for_a_standard_error():
    from coinflight.studies import bias as b

    # Reported: from one toss, "± 0.000000, +0.00 s.e. from the closed form".
    with pytest.raises(ValueError, match=r"^number of tosses must be at least 100 \(from fewer"):
        b.simulate_same_side(90.0, 1, seed=0, degrees=True)
    with pytest.raises(TypeError, match=r"^number of tosses must be an integer"):
        b.simulate_same_side(90.0, 100.0, seed=0, degrees=True)  # type: ignore[arg-type]
    est = b.simulate_same_side(90.0, b.MIN_TOSSES, seed=0, degrees=True)
    assert est.n == 100 and 0.0 < est.stderr < 0.06  # sqrt(p (1 - p) / n) ≤ 0.05 at n = 100


# --- the command line -------------------------------------------------------------------------

TOSS = ("toss", "--omega", "80", "0", "0", "--flight-time", "0.7")


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (
            (*TOSS, "--radius", "0.012", "--thickness", "0.0015", "--mass", "1e-320"),
            "mass must be between 1e-09 and 1e+06 (in kg), got 1e-320",
        ),
        (
            (*TOSS, "--radius", "1e308", "--thickness", "0.0015", "--mass", "0.005"),
            "radius must be between 1e-06 and 1000 (in m), got 1e+308",
        ),
        (
            (*TOSS, "--surface", "table", "--drop-height", "1e308"),
            "drop height must be between 0 and 1000 (in m), got 1e+308",
        ),
        (
            (*TOSS, "--g", "0"),
            "Invalid value for '--g': g must be between 0.001 and 1000 (in m/s²), got 0.0",
        ),
        (
            ("bias", "--psi", "90", "--monte-carlo", "1"),
            "number of tosses must be at least 100 (from fewer the standard error is not "
            "meaningful), got 1",
        ),
        (
            ("bias", "--preset", "human", "--monte-carlo", "1"),
            "number of tosses must be at least 100 (from fewer the standard error is not "
            "meaningful), got 1",
        ),
    ],
)
def test_cli_reported_cases_are_one_line_errors(args, message):
    assert one_line_error(*args) == message


def test_cli_plot_basin_zero_gravity(tmp_path):
    # Reported: plot basin --g 0 (with --launch-speed, T = 2 v0 / g) → ZeroDivisionError.
    out = tmp_path / "basin.png"
    message = one_line_error(
        "plot", "basin", "--g", "0", "--launch-speed", "2:3", "--resolution", "20", "--out", out
    )
    assert message == "Invalid value for '--g': g must be between 0.001 and 1000 (in m/s²), got 0.0"
    assert not out.exists()


@pytest.mark.parametrize(("enlarge", "shown"), [("1e-320", "1e-320"), ("1e308", "1e+308")])
def test_cli_animate_enlarge(tmp_path, enlarge, shown):
    # Reported: --enlarge 1e-320 → "Singular matrix"; 1e308 → "Axis limits cannot be NaN or Inf".
    out = tmp_path / "toss.gif"
    message = one_line_error("animate", "-T", "0.7", "--out", out, "--enlarge", enlarge)
    assert message == f"enlarge must be between 0.001 and 1e+06, got {shown}"
    assert not out.exists()


def test_cli_coin_in_millimetres_warns_on_one_line_and_goes_on():
    result = runner.invoke(
        app, [*TOSS, "--radius", "12.13", "--thickness", "1.75", "--mass", "5.67"]
    )
    assert result.exit_code == 0, result.output
    assert "lands HEADS up" in result.stdout
    lines = result.stderr.splitlines()
    assert len(lines) == 1
    assert lines[0].startswith(
        "coinflight: warning: radius 12.13 m is not a coin's size (1 mm to 10 cm); "
    )
    assert lines[0].endswith("see Coin.from_mm_g for mm and g")


def test_cli_unusual_gravity_warns_once(tmp_path):
    result = runner.invoke(app, [*TOSS, "--g", "981"])
    assert result.exit_code == 0, result.output
    assert result.stderr == (
        "coinflight: warning: g 981 m/s² is not a surface gravity (0.1 to 300 m/s²; Earth 9.81): "
        "did you give cm/s²?\n"
    )
    result = runner.invoke(
        app,
        ["probability", "--omega-x", "60:90", "--flight-time", "0.6:0.9", "--g", "981"],
    )
    assert result.exit_code == 0, result.output
    assert result.stderr.count("coinflight: warning: g 981 m/s²") == 1
