"""The contact duration t_c of an impact as a table's parameter (Surface ``contact_duration``,
--contact-duration, the web API's ``contact_duration``): refused outside 1 μs to 10 ms in one
line, used by every landing's impacts (core.impact.simultaneous_point: two rim points meeting
the table less than t_c apart strike as one), drawn toss by toss, and integrated over by a
probability given a range.

t_c is Hertz's contact time of a coin's rim (Johnson, *Contact Mechanics*, 1985, §11.4: 5e-5
to 3e-4 s on wood, 2e-5 to 4e-5 s on stone or glass; core.impact.CONTACT_DURATION), not
measured for coins, so an answer that depends on it is quoted as a band over it.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from fastapi.testclient import TestClient
from scipy.spatial.transform import Rotation
from typer.testing import CliRunner

from coinflight import Coin
from coinflight.cli import app
from coinflight.core import impact
from coinflight.model.distributions import Uniform
from coinflight.model.surface import (
    CONTACT_DURATION,
    DEFAULT_CONTACT_DURATION,
    TABLE_ONLY,
    Surface,
    contact_distribution,
)
from coinflight.outcomes.table import Landing, TableLanding, contact_record
from coinflight.studies.presets import SURFACE_PRESETS
from coinflight.web import create_app

NICKEL = Coin.preset("us-nickel")
G = 9.81
LOW, HIGH = CONTACT_DURATION.low, CONTACT_DURATION.high
REFUSAL = "contact duration must be between 1e-06 and 0.01 (in s), got {}"


# --- the value: range, default, refusals ------------------------------------------------------


def test_the_default_is_the_kernels_and_the_range_holds_every_surface_of_the_source():
    """Default 1e-4 s (core.impact.CONTACT_DURATION, its source there); the allowed range
    holds Hertz's contact times of every table (2e-5 s on stone or glass to 3e-4 s on wood)
    and every preset's band."""
    assert DEFAULT_CONTACT_DURATION == impact.CONTACT_DURATION == 1e-4
    assert Surface("table").contact_duration == 1e-4
    assert LOW < 2e-5 and HIGH > 3e-4
    for preset in SURFACE_PRESETS.values():
        low, high = preset.contact_duration.bounds
        assert LOW <= low < high <= HIGH
        assert "Hertz" in preset.sources["contact_duration"]


@pytest.mark.parametrize("bad", [0.0, -1e-4, 5e-7, 0.011, math.inf])
def test_a_surface_refuses_a_duration_outside_the_range_in_one_line(bad):
    with pytest.raises(ValueError) as info:
        Surface("table", contact_duration=bad)
    message = str(info.value)
    assert "\n" not in message
    if math.isfinite(bad):
        assert message == REFUSAL.format(bad)
    else:
        assert message.startswith("contact duration")


def test_a_catch_in_the_hand_refuses_a_duration_given():
    with pytest.raises(ValueError) as info:
        Surface("hand", contact_duration=2e-4)
    assert str(info.value) == f"contact duration 0.0002 s {TABLE_ONLY}"
    Surface("hand")  # the default, not given: kept


def test_a_distribution_reaching_outside_the_range_is_refused():
    with pytest.raises(ValueError, match=r"contact duration 0–0.0001 s reaches 0; contact "):
        contact_distribution("contact_duration", Uniform(0.0, 1e-4))
    assert contact_distribution("contact_duration", Uniform(3e-5, 3e-4)).bounds == (3e-5, 3e-4)


def test_the_contact_record_carries_the_surfaces_duration():
    record = contact_record(NICKEL, Surface("table", contact_duration=3e-4), G)
    assert record.contact_duration == 3e-4
    assert contact_record(NICKEL, Surface("table"), G).contact_duration == 1e-4


def _cli(*args):
    return CliRunner().invoke(app, list(args))


TOSS = ["toss", "--omega", "240", "5", "3", "--flight-time", "0.49", "--surface", "table"]


@pytest.mark.parametrize("bad", ["0", "0.02", "abc", "1e-7:1e-4"])
def test_the_command_line_refuses_a_bad_duration_with_exit_2(bad):
    result = _cli(*TOSS, "--contact-duration", bad)
    assert result.exit_code == 2, result.output
    (line,) = result.stderr.strip().splitlines()
    assert line.startswith("coinflight: error: --contact-duration")
    if bad == "0":
        assert line.endswith(REFUSAL.format(0.0))


def test_the_command_line_refuses_a_range_where_a_single_value_is_taken():
    result = _cli(*TOSS, "--contact-duration", "3e-5:3e-4")
    assert result.exit_code == 2
    assert "--contact-duration" in result.stderr and "single value" in result.stderr


def test_the_command_line_refuses_it_for_the_hand():
    result = _cli("toss", "--omega", "240", "5", "3", "--flight-time", "0.49",
                  "--contact-duration", "1e-4")  # fmt: skip
    assert result.exit_code == 2
    assert result.stderr.strip() == f"coinflight: error: --contact-duration {TABLE_ONLY}"


def test_the_help_lists_the_option():
    for command in ("toss", "probability"):
        result = _cli(command, "--help")
        assert result.exit_code == 0
        assert "--contact-duration" in result.stdout


def test_toss_json_reports_the_duration_and_matches_the_library():
    out = []
    for given in (None, "3e-4"):
        extra = [] if given is None else ["--contact-duration", given]
        result = _cli(*TOSS, "--drop-height", "0.3", *extra, "--json")
        assert result.exit_code == 0, result.output
        out.append(json.loads(result.stdout))
    assert out[0]["contact_duration"] == 1e-4
    assert out[1]["contact_duration"] == 3e-4
    from coinflight import Toss

    landing = Landing(
        Coin.preset("us-quarter"),
        Toss((240.0, 5.0, 3.0), 0.49),
        Surface("table", drop_height=0.3, contact_duration=3e-4),
    ).outcome
    assert out[1]["outcome"] == landing.face_name
    assert out[1]["settle_time"] == float(landing.settle_time)


@pytest.fixture(scope="module")
def client():
    with TestClient(create_app()) as c:
        yield c


def test_the_web_api_takes_it_and_refuses_a_bad_one_as_the_command_line(client):
    url = "/api/toss?omega=240,5,3&flight_time=0.49&surface=table&drop_height=0.3"
    good = client.get(url + "&contact_duration=3e-4")
    assert good.status_code == 200, good.text
    assert good.json()["contact_duration"] == 3e-4
    bad = client.get(url + "&contact_duration=0")
    assert bad.status_code == 422
    result = _cli(*TOSS, "--drop-height", "0.3", "--contact-duration", "0")
    assert bad.json()["detail"] == result.stderr.strip().removeprefix("coinflight: error: ")


# --- the physics: where t_c decides a landing -------------------------------------------------


def _dropped(table, theta, sign=1.0, height=0.35):
    """The face a nickel released at rest at ``height`` (m), tilted by ``theta`` (rad), lands
    on (started heads up for sign +1, tails up for −1)."""
    return Landing.from_state(
        NICKEL,
        table,
        position=(0.0, 0.0, height),
        orientation=Rotation.from_euler("yx", [theta, 0.0 if sign > 0 else math.pi]),
        velocity=(0.0, 0.0, 0.0),
        angular_velocity=(0.0, 0.0, 0.0),
    ).outcome.face_name


DURATIONS = (LOW, 3e-5, 1e-4, 3e-4, 1e-3, HIGH)


@pytest.mark.parametrize("t_c", DURATIONS)
def test_a_flat_drop_lands_on_its_start_face_for_every_duration(t_c):
    """A nickel released flat (and tilted by up to 0.8 v t_c / 4r, within which its second
    rim point closes in the first half of the contact: one simultaneous impact, the model's
    criterion, core.impact.simultaneity) lands on its start face, heads or tails, for t_c over
    the whole range."""
    table = Surface("table", restitution=0.45, friction=0.3, contact_duration=t_c)
    speed = math.sqrt(2 * G * 0.35)
    simultaneous = speed * t_c / (4 * NICKEL.radius)
    for theta in np.concatenate([[0.0, 1e-12], simultaneous * np.linspace(0.05, 0.8, 16)]):
        for sign, face in ((1.0, "heads"), (-1.0, "tails")):
            assert _dropped(table, theta, sign) == face, (t_c, theta)


def test_near_flat_drops_scale_with_the_duration():
    """Small tilts: whether two contacts make one impact depends on the tilt only through
    gap / (closing speed × t_c) ∝ θ / t_c, so a grid of tilts in units of v t_c / 4r lands the
    same for every t_c while the tilts are small: face for face up to 10 μs (tilts below
    0.04°), and, at 30 and 100 μs (up to 1.1°), with the same fraction turned over to two
    tilts in forty (there the tilts' second-order terms, sin θ ≠ θ and the gravity between
    the bounces, move the edges of the turned-over bands) — and the grid turns some drops
    over (the parameter decides them)."""
    speed = math.sqrt(2 * G * 0.35)
    units = np.linspace(0.02, 3.0, 40)
    faces = []
    for t_c in (LOW, 3e-6, 1e-5, 3e-5, 1e-4):
        table = Surface("table", restitution=0.45, friction=0.3, contact_duration=t_c)
        unit = speed * t_c / (4 * NICKEL.radius)
        faces.append([_dropped(table, theta) for theta in unit * units])
    assert faces[1] == faces[0] and faces[2] == faces[0]
    turned = [f.count("tails") for f in faces]
    assert 0 < turned[0] < len(units)
    assert all(abs(t - turned[0]) <= 2 for t in turned[3:]), turned


def test_the_wrong_face_fraction_over_a_grid_of_tilts_changes_with_the_duration():
    """Tilts 0.05° to 3°, a nickel from 0.35 m (e 0.45, μ 0.3): the fraction that lands on the
    other face differs across the plausible range of t_c (3e-5 to 3e-4 s) and the allowed
    one: at 1 μs every one of them turns over (the sequential impacts' falling rod, whose face
    is set by the drop speed and e, not by the tilt: at this speed the other one), at 10 ms none
    (every one a simultaneous impact)."""
    tilts = np.radians(np.linspace(0.05, 3.0, 60))

    def wrong(t_c):
        table = Surface("table", restitution=0.45, friction=0.3, contact_duration=t_c)
        return np.mean([_dropped(table, theta) != "heads" for theta in tilts])

    fractions = [wrong(t_c) for t_c in (LOW, 3e-5, 3e-4, HIGH)]
    assert fractions[0] == 1.0 and fractions[-1] == 0.0
    assert fractions[1] > fractions[2]


# --- per toss and integrated over -------------------------------------------------------------


def test_per_toss_durations_are_each_tosss_own():
    """``land``'s per-toss ``contact_duration`` array lands each toss as its own surface does."""
    from coinflight.outcomes.table import land

    rng = np.random.default_rng(27)
    n = 24
    omega = np.column_stack([rng.uniform(0.0, 0.4, n), np.zeros(n), np.zeros(n)])
    t_c = 10 ** rng.uniform(math.log10(3e-5), math.log10(3e-4), n)
    speed = np.full(n, 1.96)
    together = land(NICKEL, omega, speed, 1.0, G, Surface("table", drop_height=0.35),
                    parallel=False, contact={"contact_duration": t_c})  # fmt: skip
    for k in range(n):
        table = Surface("table", drop_height=0.35, contact_duration=float(t_c[k]))
        alone = land(NICKEL, omega[k : k + 1], speed[k : k + 1], 1.0, G, table, parallel=False)
        assert together.face[k] == alone.face[0]
        assert together.settle_time[k] == alone.settle_time[0]


PROBABILITY = [
    "probability", "--omega-x", "0:0.3", "--flight-time", "0.4", "--surface", "table",
    "--drop-height", "0.35", "--restitution", "0.45", "--method", "monte-carlo", "--n", "3000",
    "--seed", "1", "--json",
]  # fmt: skip


def _p_tails(duration):
    result = _cli(*PROBABILITY, "--contact-duration", duration)
    assert result.exit_code == 0, result.output
    out = json.loads(result.stdout)
    return out["p_tails"], out["stderr"], out


def test_a_probability_integrates_over_a_range_of_durations():
    """Quarters barely spun (0 to 0.3 rad/s: tilts 0-9° at the first impact, where t_c decides
    the first or the second rim's strike and the later slow bounces): P(tails) at
    t_c = 3e-5 s and at 3e-4 s differ by many standard errors, and over the range 3e-5:3e-4
    (drawn toss by toss) it lies between the two, apart from both (not one end's value)."""
    low, se_low, _ = _p_tails("3e-5")
    high, se_high, _ = _p_tails("3e-4")
    ranged, se, out = _p_tails("3e-5:3e-4")
    assert out["contact_duration"] == {"kind": "uniform", "low": 3e-5, "high": 3e-4}
    assert out["distribution"]["contact_duration"] == out["contact_duration"]
    lo, hi = sorted([(low, se_low), (high, se_high)])
    assert hi[0] - lo[0] > 10 * math.hypot(se_low, se_high)
    assert lo[0] + 4 * math.hypot(lo[1], se) < ranged < hi[0] - 4 * math.hypot(hi[1], se)


def test_a_surface_preset_spreads_the_duration():
    """--surface-preset coin-on-wood draws t_c uniformly over 5e-5 to 3e-4 s toss by toss."""
    result = _cli(*PROBABILITY[:-1], "--surface-preset", "coin-on-wood", "--json")
    assert result.exit_code == 0, result.output
    out = json.loads(result.stdout)
    assert out["distribution"]["contact_duration"] == {
        "kind": "uniform", "low": 5e-5, "high": 3e-4,
    }  # fmt: skip
    assert out["surface_preset"]["contact_duration"] == out["distribution"]["contact_duration"]


def test_the_table_model_names_the_duration_it_was_given():
    default = TableLanding(Surface("table"))
    assert "contact_duration" not in default.to_dict()  # a sweep row's stream keyed on it
    given = TableLanding(Surface("table", contact_duration=3e-4))
    assert given.to_dict()["contact_duration"] == 3e-4
    assert "contact duration 0.0003 s" in given.describe()
    spread = {"contact_duration": Uniform(3e-5, 3e-4)}
    assert "contact duration 3e-05–0.0003 s" in default.describe(spread)


def test_the_web_api_integrates_over_a_range_as_the_command_line(client):
    """The same counts from the page's API as from the command line (n = 1000: the server
    bounds a request's work at the rate of landings carried to rest)."""
    url = (
        "/api/probability?omega_x=0:0.3&flight_time=0.4&surface=table&drop_height=0.35"
        "&restitution=0.45&method=monte-carlo&n=1000&seed=1&contact_duration=3e-5:3e-4"
    )
    response = client.get(url)
    assert response.status_code == 200, response.text
    api = response.json()
    args = [*PROBABILITY, "--contact-duration", "3e-5:3e-4"]
    args[args.index("--n") + 1] = "1000"
    result = _cli(*args)
    assert result.exit_code == 0, result.output
    cli = json.loads(result.stdout)
    assert api["counts"] == cli["counts"]
    assert api["contact_duration"] == cli["contact_duration"]


def test_a_sweep_lists_durations_row_by_row(tmp_path):
    """``sweep --contact-duration 3e-5,3e-4``: one row per value, each naming its t_c, and
    the near-flat tosses above turn over far more often at the longer one (as the
    probability's fixed values above)."""
    import csv

    out = tmp_path / "sweep.csv"
    result = _cli(
        "sweep", "--omega-x", "0:0.3", "--flight-time", "0.4", "--surface", "table",
        "--drop-height", "0.35", "--restitution", "0.45", "--contact-duration", "3e-5,3e-4",
        "--method", "monte-carlo", "--n", "2000", "--seed", "1", "--out", str(out),
    )  # fmt: skip
    assert result.exit_code == 0, result.output
    with out.open() as f:
        rows = list(csv.DictReader(f))
    assert [float(r["contact_duration"]) for r in rows] == [3e-5, 3e-4]
    (short, long) = rows
    gap = float(long["p_tails"]) - float(short["p_tails"])
    assert gap > 10 * math.hypot(float(short["stderr"]), float(long["stderr"]))
