"""Work and memory are bounded before anything is allocated (issue 10, items 3, 4, 6 and 5).

Every size a user gives (grid cells, tosses, Sobol points, convergence series, frames, figure
points, boundary curves, bounces, drag integrations) is checked against a stated limit by one
function, :func:`coinflight._validation.work_bound`, whose refusal names the request, the
estimate (with its time at the measured rate), the limit and the way on. Each reported case is
here, in the library and through the command line (exit 2, one line, no traceback); "before
allocating" is checked with tracemalloc: the peak of a refusal is far below the would-be size;
"before any work" by the functions doing the work, made to fail the test if called (not by a
clock: the machine is shared).
"""

from __future__ import annotations

import math
import re
import tracemalloc
from decimal import Decimal

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from _cli import one_line_error
from _work import MB, RUNS_TASKS, command_work, counted_catch, never_run, refused_cheaply
from coinflight import Coin, Toss
from coinflight import _validation as v
from coinflight.model.distributions import Uniform
from coinflight.model.ensemble import TossDistribution
from coinflight.probability import estimate

runner = CliRunner()
FIG_2A = TossDistribution(Uniform(60, 90), 0, 0, Uniform(0.6, 0.9))  # Stefan & Cheche Fig 2a
QUARTER = Coin(radius=0.01213, thickness=0.00175, mass=0.00567)  # REFERENCES §7, in SI
HUGE = [2**63, 99999999999999999999999, 2**2000]


# --- the one refusal --------------------------------------------------------------------------


def test_work_bound_names_request_estimate_time_limit_and_way_on():
    v.work_bound("x", 100, 100, "tosses", "use less", 10.0)  # at the limit: accepted
    with pytest.raises(ValueError) as info:
        v.work_bound("monte-carlo with n = 7200", 7200, 3600, "tosses", "use a smaller n", 1.0)
    assert str(info.value) == (
        "monte-carlo with n = 7200 is 7,200 tosses (about 2 h at 1 tosses/s), more than the "
        "limit of 3,600 tosses (about 60 min); use a smaller n"
    )
    # Integers beyond float range are refused like any other (no OverflowError), as themselves.
    with pytest.raises(
        ValueError, match=r"is 1\.15e\+602 points, more than the limit of 10 points; y$"
    ):
        v.work_bound("a request", 2**2000, 10, "points", "y")


@pytest.mark.parametrize(
    ("amount", "limit", "words"),
    [
        # one over the limit: whole numbers in full, never two alike (was "2e+03 ... 2e+03")
        (2001, 2000, "is 2,001 curves, more than the limit of 2,000 curves"),
        (2001.0, 2000.0, "is 2,001 curves, more than the limit of 2,000 curves"),
        (np.int64(2001), 2000, "is 2,001 curves, more than the limit of 2,000 curves"),
        (10**6 + 1, 10**6, "is 1,000,001 curves, more than the limit of 1,000,000 curves"),
        (
            10**12 + 1,
            10**12,
            "is 1,000,000,000,001 curves, more than the limit of 1,000,000,000,000 curves",
        ),
        (
            1e12 + 1,
            1e12,
            "is 1,000,000,000,001 curves, more than the limit of 1,000,000,000,000 curves",
        ),
        # an estimate a fraction over: as many decimals as part the two, no more
        (2000.3, 2000, "is 2,000.3 curves, more than the limit of 2,000 curves"),
        (2000.04, 2000, "is 2,000.04 curves, more than the limit of 2,000 curves"),
        (1800.0000001, 1800.0, "is 1,800.0000001 curves, more than the limit of 1,800 curves"),
        (1667.3, 1500.0, "is 1,670 curves, more than the limit of 1,500 curves"),
        # an estimate with 3 significant digits, not false precision (was "94,308,161")
        (94308161.0, 10**6, "is 94,300,000 curves, more than the limit of 1,000,000 curves"),
        (2001.4, 2000, "is 2,001 curves, more than the limit of 2,000 curves"),
        # rounded, an estimate never reads at or below its limit
        (6150000002.0, 6150000001, "is 6,150,000,002 curves, more than the limit of"),
        # a float within rounding of its limit: no digit beyond either's shortest form (repr)
        (1.1 + 2.2, 3.3, "is 3.3000000000000003 curves, more than the limit of 3.3 curves"),
        (0.1 + 0.2, 0.3, "is 0.30000000000000004 curves, more than the limit of 0.3 curves"),
        (1.52, 1.5, "is 1.52 curves, more than the limit of 1.5 curves"),
        # from 10^15 in scientific notation, the digits needed and no more
        (2**63, 9e10, "is 9.22e+18 curves, more than the limit of 90,000,000,000 curves"),
        (
            10**15 + 2,
            10**15,
            "is 1.000000000000002e+15 curves, more than the limit of 1e+15 curves",
        ),
        (1e300, 1e15, "is 1e+300 curves, more than the limit of 1e+15 curves"),
        # the boundary of "in full below 10^15" (EXACT_BELOW)
        (
            10**15 - 1,
            10**15 - 2,
            "is 999,999,999,999,999 curves, more than the limit of 999,999,999,999,998 curves",
        ),
        (
            10**14 + 1,
            10**14,
            "is 100,000,000,000,001 curves, more than the limit of 100,000,000,000,000 curves",
        ),
        (float("inf"), 5, "is inf curves, more than the limit of 5 curves"),
    ],
)
def test_work_bound_prints_counts_in_full_and_never_alike(amount, limit, words):
    with pytest.raises(ValueError, match=f"^w {re.escape(words)}"):
        v.work_bound("w", amount, limit, "curves", "y")
    v.work_bound("w", limit, limit, "curves", "y")  # the limit itself: accepted


@settings(max_examples=300, deadline=None)
@given(
    limit=st.one_of(
        st.integers(1, 10**20), st.floats(1e-3, 1e20, allow_nan=False, allow_infinity=False)
    ),
    above=st.one_of(st.integers(1, 10**6), st.floats(1e-12, 1e6)),
    relative=st.booleans(),
)
def test_an_amount_over_its_limit_never_reads_as_the_limit(limit, above, relative):
    amount = limit * (1 + above) if relative else limit + above
    if not amount > limit:  # rounding kept it at the limit: nothing to refuse
        return
    with pytest.raises(ValueError) as info:
        v.work_bound("w", amount, limit, "tosses", "y")
    words = re.fullmatch(
        r"w is (\S+) tosses, more than the limit of (\S+) tosses; y", str(info.value)
    )
    assert words, str(info.value)
    shown, most = (Decimal(x.replace(",", "")) for x in words.groups())
    assert shown > most  # distinct, and in the right order
    for text, value in zip(words.groups(), (amount, limit), strict=True):
        assert_reads_as(text, value)


def assert_reads_as(text, value):
    """``text`` shows ``value`` rounded to the digits it shows, never with more digits than
    the float's shortest round-trip form (``repr``), and when it shows as many, reads back
    as that float."""
    shown = Decimal(text.replace(",", ""))
    if isinstance(value, int) and abs(value) < v.EXACT_BELOW:
        assert shown == value, text  # an exact count, in full
        return
    digits = len(shown.normalize().as_tuple().digits)
    last = Decimal(1).scaleb(shown.normalize().as_tuple().exponent)  # its last digit's unit
    assert abs(shown - Decimal(value)) <= last, (text, value)  # a rounding of the value
    if isinstance(value, float):
        most = len(Decimal(repr(value)).normalize().as_tuple().digits)
        assert digits <= most, (text, repr(value))  # no digit beyond repr's: no binary noise
        if digits == most:
            assert float(shown) == value, (text, repr(value))  # reads back as the float


@settings(max_examples=500, deadline=None)
@given(
    x=st.floats(allow_nan=False, allow_infinity=False).filter(lambda x: x != 0),
    decimals=st.integers(0, 17),
)
@example(x=5.960464477539063e-08, decimals=13)  # 2⁻²⁴: 16 digits round the tie to "…062"
def test_a_shown_float_never_has_more_digits_than_its_shortest_form(x, decimals):
    assert_reads_as(v.quantity(x, decimals), x)


@settings(max_examples=300, deadline=None)
@given(
    limit=st.floats(1e-3, 1e20, allow_nan=False, allow_infinity=False),
    ulps=st.integers(1, 4),
)
def test_a_float_within_rounding_of_its_limit_reads_back_as_itself(limit, ulps):
    amount = limit
    for _ in range(ulps):
        amount = math.nextafter(amount, math.inf)
    shown, most = v.over_limit(amount, limit)
    assert Decimal(shown.replace(",", "")) > Decimal(most.replace(",", ""))
    assert_reads_as(shown, amount)
    assert_reads_as(most, limit)


def test_an_amount_that_takes_as_long_as_its_limit_is_not_timed_twice():
    # "270,001 tosses (about 60 min …), more than … 270,000 tosses (about 60 min)": the limit's
    # duration alone, with the rate
    with pytest.raises(ValueError) as info:
        v.work_bound("w", 270_001, 270_000, "tosses", "y", 75.0)
    assert str(info.value) == (
        "w is 270,001 tosses, more than the limit of 270,000 tosses (about 60 min at "
        "75 tosses/s); y"
    )
    with pytest.raises(ValueError) as info:  # durations that differ: both
        v.work_bound("w", 540_000, 270_000, "tosses", "y", 75.0)
    assert "is 540,000 tosses (about 2 h at 75 tosses/s), more than the limit of 270,000 " in (
        str(info.value)
    )


def test_the_phase_refusal_quotes_spin_and_time_as_estimates():
    # was "(2e+05 rad/s for 1e+04 s)" beside "2,000,000,000 rad"
    with pytest.raises(ValueError) as info:
        v.phase_budget(2e5, 1e4)
    assert str(info.value).startswith(
        "spin × flight time must be at most 1,000,000,000 rad, got 2,000,000,000 rad "
        "(200,000 rad/s for 10,000 s): "
    )
    with pytest.raises(ValueError, match=r"got 1,230,000,000 rad \(123,000 rad/s for 10,000 s\)"):
        v.phase_budget(123_456.7, 10_000.0)


@pytest.mark.parametrize(
    ("seconds", "text"),
    [
        (40, "40 s"),
        (7200, "2 h"),
        (720, "12 min"),
        (86400 * 45, "45 days"),
        (7000, "120 min"),  # two digits, as a whole number (was "1.2e+02 min")
        (3.2e13, "1,000,000 years"),
    ],
)
def test_duration_reads_as_a_person_would_say_it(seconds, text):
    assert v.duration(seconds) == text


# --- grid (reported: n = 1e9 allocated 7.45 GiB; n = 2^63 an IndexError) -----------------------


@pytest.mark.parametrize("n", [10**9, 10**12, *HUGE])
def test_grid_refuses_before_allocating(n):
    message = refused_cheaply(lambda: estimate(FIG_2A, "grid", n=n), "bytes of nodes", RUNS_TASKS)
    assert f"a grid of n = {n} cells per parameter" in message
    assert "more than the limit of 1,073,741,824 bytes of nodes" in message
    assert "monte-carlo or qmc" in message


def test_grid_work_check_is_constant_memory():
    from coinflight.probability import grid

    # 3e7 cells: accepted (5.7 bands × 3e7 nodes ≤ 8e8), and the check itself builds no
    # O(n) array (the nodes alone would be 240 MB each).
    tracemalloc.start()
    seconds = grid.check_work(FIG_2A, 3 * 10**7)
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    assert peak < MB
    assert 0 < seconds < 60


def test_grid_brute_force_with_table_landings_is_bounded_by_their_rate():
    from coinflight.model.surface import Surface
    from coinflight.outcomes.table import RIGID_TOSSES_PER_SECOND, TableLanding

    model = TableLanding(Surface("table", drop_height=0.3))
    message = refused_cheaply(
        lambda: estimate(FIG_2A, "grid", n=10**5, model=model), "configurations", RUNS_TASKS
    )
    cells = float(10**5) ** 2  # n per axis, two axes
    rate = RIGID_TOSSES_PER_SECOND  # the time quoted at the rate of landings carried to rest
    took = f"about {v.duration(cells / rate)} at {v.estimate(rate)} configurations/s"
    assert f"{v.quantity(cells)} configurations ({took})" in message


# --- Monte Carlo and QMC (reported: 2^63 ran until killed; SciPy's 'increasing bits' leaked) ----


@pytest.mark.parametrize("n", HUGE)
def test_monte_carlo_counts_are_bounded_by_time(n):
    """Refused at the hand catch's measured rate (the constant the bound uses, not a copy of
    its text): the limit is an hour of tosses at that rate."""
    from coinflight.outcomes.hand import HAND_CATCH

    message = refused_cheaply(
        lambda: estimate(FIG_2A, "monte-carlo", n=n, seed=1), "tosses", RUNS_TASKS
    )
    assert message.startswith(f"monte-carlo with n = {n} is ")
    rate = HAND_CATCH.rate
    limit = f"{v.quantity(rate * v.MAX_RUN_SECONDS)} tosses (about {v.duration(v.MAX_RUN_SECONDS)})"
    assert f"years at {v.estimate(rate)} tosses/s), more than the limit of {limit}" in message
    assert v.duration(v.MAX_RUN_SECONDS) == "60 min"  # the limit the users are told: an hour


@pytest.mark.parametrize("restitution", [0.0, 0.5])
def test_monte_carlo_limit_follows_the_outcome_model(restitution):
    from coinflight.model.surface import Drag, Surface
    from coinflight.outcomes.table import (
        AIR_LANDINGS_PER_SECOND,
        RIGID_TOSSES_PER_SECOND,
        TableLanding,
    )

    surface = Surface("table", drop_height=0.3, restitution=restitution)
    model = TableLanding(surface, Drag(coefficient=1.0))
    message = refused_cheaply(
        lambda: estimate(FIG_2A, "monte-carlo", n=10**8, seed=1, model=model),
        "tosses",
        RUNS_TASKS,
    )
    # the limit and time follow the landings through air: dead ones (e = 0) at the air's
    # rate, those carried to rest at the rigid ending's
    rate = AIR_LANDINGS_PER_SECOND if restitution == 0.0 else RIGID_TOSSES_PER_SECOND
    took = f"(about {v.duration(1e8 / rate)} at {v.estimate(rate)} tosses/s)"
    limit = v.quantity(rate * v.MAX_RUN_SECONDS)
    assert f"is 100,000,000 tosses {took}, more than the limit of {limit} tosses" in message


@pytest.mark.parametrize("n", [16 << 31, 2**63])
def test_qmc_points_fit_sobols_bits(n):
    message = refused_cheaply(
        lambda: estimate(FIG_2A, "qmc", n=n, seed=1), "points per", RUNS_TASKS
    )
    assert "more than the limit of 1,073,741,824 points per scrambling" in message
    assert "use n ≤ 16 × 2^30 = 17179869184" in message
    assert "bits`" not in message  # SciPy's own words never reach the user


def test_qmc_within_sobols_bits_is_bounded_by_time():
    # 16 × 2^30 points fit the bits, but take about 23 min: accepted (an hour is the limit).
    from coinflight.probability import qmc

    qmc.check_work(16 << 30)
    with pytest.raises(ValueError, match="qmc needs n = 16 replicates × a power of two"):
        qmc.check_work(100)


def test_qmc_replicates_are_bounded_before_seeding():
    # 2^30 scramblings of one point each: a billion seeds and Sobol engines before any point.
    refused_cheaply(
        lambda: estimate(FIG_2A, "qmc", n=2**30, replicates=2**30, seed=1),
        "replicates must be between 2 and 1024, got 1073741824",
        RUNS_TASKS,
    )


# --- convergence (reported: --grid-sizes 99999999999 allocated 745 GiB) ---------------------


@pytest.mark.parametrize(
    ("sizes", "match"),
    [
        ({"grid_sizes": [5, 99999999999]}, "a grid of n = 99999999999 cells per parameter"),
        ({"event_sizes": [100, 2**63]}, f"monte-carlo with n = {2**63}"),
        ({"qmc_sizes": [64, 2**63]}, "points per scrambling"),
        # Each size allowed, the series not: 2 × 8e10 tosses is 1.8 h.
        (
            {"event_sizes": [8 * 10**10, 8 * 10**10]},
            r"series \(monte-carlo\) is 6,400 s of work, more than the limit of 3,600 s",
        ),
    ],
)
def test_convergence_checks_every_size_before_computing(sizes, match):
    from coinflight.probability.convergence import convergence

    methods = [
        m
        for m, key in [("grid", "grid_sizes"), ("monte-carlo", "event_sizes"), ("qmc", "qmc_sizes")]
        if key in sizes
    ]
    refused_cheaply(lambda: convergence(FIG_2A, methods, **sizes), match, RUNS_TASKS)


# --- figures and animation (reported: animate --omega 1e9 allocated 33 GiB) -------------------


def test_animation_refuses_too_many_turns_before_drawing():
    import mpl_toolkits.mplot3d.art3d  # noqa: F401  (imported before timing)

    from coinflight.model.toss import Flight
    from coinflight.plotting import animation
    from coinflight.plotting.animation import animate_toss

    toss = Toss(omega=(1e9, 0.0, 0.0), flight_time=0.7)
    drawing = [(Flight, "at"), (animation, "new_figure")]  # the frames' states, the figure
    message = refused_cheaply(lambda: animate_toss(QUARTER, toss), "points", drawing)
    assert "the n·Z curve of a toss turning 1.11e+08 times (40 points a turn)" in message
    with pytest.raises(ValueError, match="frames must be between 2 and 2000, got 99999"):
        animate_toss(QUARTER, Toss(omega=(80.0, 0.0, 0.0), flight_time=0.7), frames=99999)


def test_plot_toss_refuses_too_many_turns_and_panels():
    import matplotlib.gridspec  # noqa: F401  (imported before timing)

    from coinflight.model.toss import Flight
    from coinflight.plotting import toss as toss_plot
    from coinflight.plotting.toss import plot_toss

    warm = Flight(QUARTER, Toss(omega=(80.0, 0.0, 0.0), flight_time=0.7))
    warm.catch, warm.outcome  # noqa: B018  (compiled and imported before timing)

    fast = Toss(omega=(2.2e-308, 1e-320, 1e9), flight_time=0.521912)  # the generated case
    drawing = [(toss_plot, "normal_path"), (toss_plot, "new_figure")]  # the path, the figure
    message = refused_cheaply(lambda: plot_toss(QUARTER, fast), "points", drawing)
    assert "the path of the normal over" in message
    many = Toss(omega=(80.0, 0.0, 0.0), flight_time=np.linspace(0.5, 0.9, 101))
    with pytest.raises(ValueError, match=r"number of panels \(flight times\) must be between 1 "):
        plot_toss(QUARTER, many)


def test_basin_boundaries_are_bounded():
    from coinflight.studies.basin import basin_map

    basin = basin_map(QUARTER, spin=(-1e9, 1e9), flight_time=(0.6, 0.9), resolution=(4, 4))
    message = refused_cheaply(basin.boundaries, "curves", [])  # the work: the curves' arrays
    assert "more than the limit of 2,000 curves" in message
    assert "--no-boundaries" in message


def test_basin_boundaries_are_refused_before_the_map(tmp_path, monkeypatch):
    # A wide range was refused only when drawn, after its map (a regression there would hang,
    # not fail): now before it, the map's grid and its catches made to fail if they run.
    from coinflight.outcomes.hand import HandCatch
    from coinflight.queries.basin import basin_query
    from coinflight.queries.values import TableArgs
    from coinflight.studies import basin

    the_map = [(basin, "midpoints"), (HandCatch, "faces")]
    wide = {"spin": (-1e9, 1e9), "flight_time": (0.6, 0.9), "resolution": (500, 500)}
    message = refused_cheaply(
        lambda: basin.basin_map(QUARTER, **wide, boundaries=True), "curves", the_map
    )
    drawn = basin.basin_map(QUARTER, **{**wide, "resolution": (2, 2)})
    assert message == refused_cheaply(drawn.boundaries, "curves", [])  # the same words
    # The web's boundaries on a table: refused before its map too.
    table = TableArgs("table", 0.3, None, None, None)
    words = "the analytic boundaries belong to the catch in the hand"
    refused_cheaply(
        lambda: basin_query(QUARTER, omega_x="60:90", table=table, boundaries=True),
        words,
        [*the_map, *RUNS_TASKS],
    )
    # The command line: one line, nothing drawn or computed.
    never_run(monkeypatch, command_work())
    monkeypatch.chdir(tmp_path)
    assert "--no-boundaries" in one_line_error("plot", "basin", "--omega-x", "-1e9:1e9",
                                               "--out", "b.png")  # fmt: skip
    assert not list(tmp_path.iterdir())


@pytest.mark.parametrize(
    ("spin", "psi", "omega_z"),
    [
        ((60.0, 6900.0), None, 0.0),
        ((60.0, 6980.0), None, 0.0),  # just over the limit: 2 × (999 + 2) curves
        ((-6980.0, 10.0), None, 0.0),
        ((-50.0, 6850.0), None, 500.0),
        ((-50.0, 6975.0), None, 3000.0),
        ((0.0, 6950.0), None, 1e5),  # never turns over: no curves
        ((1.0, 6950.0), math.radians(80.0), 0.0),
        ((1.0, 7100.0), math.radians(80.0), 0.0),
        ((1.0, 9e9), math.radians(30.0), 0.0),  # ψ < 45°: no curves
    ],
)
def test_basin_boundaries_checked_before_the_map_as_when_drawn(spin, psi, omega_z):
    # The check from the box alone (its spin axis' ends) refuses exactly the maps whose
    # boundaries refuse when drawn, at the limit too.
    from coinflight.studies import basin

    box = {"flight_time": (0.6, 0.9), "spin": spin, "psi": psi, "omega_z": omega_z}
    drawn = basin.basin_map(QUARTER, **box, resolution=(2, 2))
    try:
        curves = len(drawn.boundaries())
    except ValueError as exc:
        with pytest.raises(ValueError) as info:
            basin.check_boundaries(QUARTER, **box)
        assert str(info.value) == str(exc)
    else:
        basin.check_boundaries(QUARTER, **box)
        assert curves <= basin.MAX_BOUNDARIES


@pytest.mark.parametrize(("band", "allowed"), [(998.5, True), (999.001, False)])
def test_basin_boundaries_at_their_limit(band, allowed):
    # The fastest spin ω = band × 2π / T_hi: bands k = 0 .. int(ω T_hi / 2π) + 1, two curves
    # each; band 998.5 is exactly the limit (k up to 999: 2,000 curves), accepted by the check
    # and when drawn; past band 999 one more band (2,002 curves), refused by both.
    from coinflight.studies import basin

    top = band * 2 * math.pi / 0.9
    curves = 2 * (int(top * 0.9 / (2 * math.pi)) + 2)
    assert curves == (basin.MAX_BOUNDARIES if allowed else basin.MAX_BOUNDARIES + 2)
    box = {"flight_time": (0.6, 0.9), "spin": (60.0, top)}
    drawn = basin.basin_map(QUARTER, **box, resolution=(2, 2))
    if allowed:
        basin.check_boundaries(QUARTER, **box)
        basin.basin_map(QUARTER, **box, resolution=(2, 2), boundaries=True)
        assert 0 < len(drawn.boundaries()) <= basin.MAX_BOUNDARIES
    else:
        words = "is 2,002 curves, more than the limit of 2,000 curves"  # "2e+03 ... 2e+03" once
        for refused in (
            lambda: basin.check_boundaries(QUARTER, **box),
            lambda: basin.basin_map(QUARTER, **box, resolution=(2, 2), boundaries=True),
            drawn.boundaries,
        ):
            with pytest.raises(ValueError, match=re.escape(words)):
                refused()


# --- counts of bias and edge simulations, bounces -------------------------------------------


@pytest.mark.parametrize("n", HUGE)
def test_same_side_simulation_is_bounded(n):
    from coinflight.probability import streams
    from coinflight.studies.bias import simulate_same_side

    message = refused_cheaply(
        lambda: simulate_same_side(45.0, n, 0, degrees=True),
        "tosses",
        [(streams, "unit_cube")],  # the tosses' draws
    )
    assert "more than the limit of 14,400,000,000 tosses (about 60 min)" in message


def test_edge_simulation_is_bounded():
    from coinflight.studies.edge import simulate_edge

    too_many = f"number of tosses must be between 1 and 10000000, got {2**63}"
    with pytest.raises(ValueError, match=too_many):
        simulate_edge([0.3], 2**63, 1)
    with pytest.raises(TypeError, match=r"number of tosses must be an integer, got float 2\.5"):
        simulate_edge([0.3], 2.5, 1)  # type: ignore[arg-type]
    with pytest.raises(ValueError, match=r"ratio must be between 0\.001 and 100, got 1e"):
        simulate_edge([0.3, 1e308], 10, 1)
    message = refused_cheaply(
        lambda: simulate_edge(np.full(100, 0.3), 10**7, 1), "tosses", RUNS_TASKS
    )
    assert "100 ratios × 10,000,000 tosses is 1,000,000,000 tosses" in message


def test_max_bounces_is_bounded_by_the_kernels_impact_limit():
    from coinflight.core import bounce
    from coinflight.model.surface import Surface
    from coinflight.outcomes.table import MAX_BOUNCES, TableLanding

    assert MAX_BOUNCES == bounce.MAX_IMPACTS
    table = Surface("table", drop_height=0.3)
    with pytest.raises(ValueError, match="max_bounces must be between 0 and 2000, got 10"):
        TableLanding(table, max_bounces=10**23)


# --- the drag integrator (reported: hangs with spin damping; tiny coins) ----------------------


def test_any_spin_damping_on_a_tiny_coin_ends_quickly():
    # Reported: spin damping 1 ran > 30 s. The damping's decays are exact and its steps bounded
    # (core.drag), so the strongest accepted K on a 1 mm coin (K/I1 = 4e7 1/s) is not refused,
    # and its toss takes no more steps than check_air's estimate without damping (steps_needed:
    # "spin damping never does" need more). Steps are counted, not timed (the machine is
    # shared): the kernel's own loop, catch_one.py_func, runs with its step size counted and
    # its budget MAX_STEPS set to that estimate (a regression ends at the budget, not hours).
    from coinflight.core import drag
    from coinflight.model.surface import Drag
    from coinflight.outcomes.air import catch_with_drag, drag_model

    tiny = Coin(radius=1e-3, thickness=1e-4, mass=1e-4)  # I1 = 2.5e-11 kg m²
    omega = np.array([[80.0, 0.0, 0.0]])
    damped = Drag(1.17, spin_damping=1e-3)
    face, t = catch_with_drag(tiny, omega, 3.43, 1.0, 9.81, damped)
    assert int(face[0]) == 1 and 0.5 < float(t[0]) < 0.7

    air = drag_model(tiny, damped, 9.81)
    budget = drag.steps_needed(air, 3.43, 0.0, 80.0)
    assert budget < drag.MAX_STEPS / 1000  # about 130 steps
    steps, (face_py, t_py, _) = counted_catch(omega[0], 3.43, air, budget)
    assert 0 < steps <= budget
    assert (face_py, t_py) == (int(face[0]), float(t[0]))  # the same toss (beyond budget: t = -1)


@pytest.mark.filterwarnings("ignore::coinflight._validation.PlausibilityWarning")
def test_a_fall_too_slow_to_integrate_is_refused_before_any_work():
    from coinflight.core import drag
    from coinflight.model.surface import Drag
    from coinflight.outcomes.air import catch_with_drag

    leaf = Coin(radius=1.0, thickness=1e-3, mass=1e-6)  # a 2 m leaf: v_t ≈ 1e-3 m/s
    message = refused_cheaply(
        lambda: catch_with_drag(leaf, np.array([[80.0, 0.0, 0.0]]), 3.43, 1.0, 9.81, Drag(10.0)),
        "integration steps a toss",
        [(drag, "catch")],  # the integrator
    )
    assert "air drag C_d = 10" in message and "use a smaller C_d" in message


# --- the reported command lines ---------------------------------------------------------------

FIG = ["--omega-x", "60:90", "--flight-time", "0.6:0.9"]


@pytest.mark.parametrize(
    ("args", "expected"),
    [
        (["probability", *FIG, "--method", "grid", "--n", "1000000000"], "bytes of nodes"),
        (["probability", *FIG, "--method", "grid", "--n", str(2**63)], "bytes of nodes"),
        (["probability", *FIG, "--method", "monte-carlo", "--n", str(2**63)], "years at"),
        (["probability", *FIG, "--method", "qmc", "--n", str(2**63)], "SciPy's Sobol sequence"),
        (["convergence", *FIG, "--grid-sizes", "99999999999", "--out", "x"], "bytes of nodes"),
        (
            [
                "convergence",
                *FIG,
                "--methods",
                "monte-carlo",
                "--event-sizes",
                str(2**63),
                "--out",
                "x",
            ],
            "years at",
        ),
        (
            ["animate", "--omega", "1e9", "0", "0", "--flight-time", "0.7", "--out", "a.gif"],
            "1.11e+08 times",
        ),
        (["bias", "--psi", "45", "--monte-carlo", str(2**63)], "more than the limit"),
        (
            ["plot", "bias", "--psi-points", "45", "--monte-carlo", str(2**63), "--out", "b.png"],
            "more than the limit",
        ),
        (
            [
                "plot",
                "bias",
                "--psi-points",
                "45,50,60,70,80",
                "--monte-carlo",
                "10000000000",
                "--out",
                "b.png",
            ],
            "5 angles × 10,000,000,000 tosses is 50,000,000,000 tosses (about 3.5 h",
        ),
        (["plot", "toss", "--omega", "0", "0", "1e9", "-T", "0.7", "--out", "t.png"], "points"),
        (["plot", "basin", "--omega-x", "-1e9:1e9", "--out", "b.png"], "--no-boundaries"),
        (["plot", "edge", "--max-ratio", "1e308", "--out", "e.png"], "at most 100"),
        (
            [
                "toss",
                "--omega",
                "80",
                "0",
                "0",
                "-T",
                "0.7",
                "--surface",
                "table",
                "--bounces",
                "99999999999999999999999",
            ],
            "--bounces must be between 0 and 2000",
        ),
        (
            [
                "toss",
                "--omega",
                "80",
                "0",
                "0",
                "-T",
                "0.7",
                "--surface",
                "table",
                "--drop-height",
                "1000",
                "--drag",
                "10",
                "--radius",
                "0.1",
                "--thickness",
                "1e-4",
                "--mass",
                "1e-4",
            ],
            "would need about 94,300,000 integration steps a toss, more than the 1,000,000 allowed",
        ),
    ],
)
def test_reported_command_lines_end_in_one_line(args, expected, tmp_path, monkeypatch):
    # Refused before any work: what would do it (every estimator's, study's and map's tasks,
    # the bias study's draws, the flights through air, any figure, a movie's frames included)
    # fails the test if called (not a clock: the machine is shared).
    never_run(monkeypatch, command_work())
    monkeypatch.chdir(tmp_path)
    assert expected in one_line_error(*args)
    assert not list(tmp_path.iterdir())  # nothing written


def _exact_plan_work() -> list[tuple[object, str]]:
    """The exact method's integrals and the (Ω, ψ) rule's own allocations: its band-edge
    curves and its panels (the issue's 20 s and 1.7 GB before the refusal)."""
    from _work import exact_work
    from coinflight.probability.exact import omega_psi

    return [*exact_work(), (omega_psi, "_edges"), (omega_psi, "_panels")]


@pytest.mark.parametrize(
    "omega_x, omega_z",
    [
        ("normal:0,1e6", 0.0),  # the line: ω_z = 0, the one-spin (diameter) plan
        ("normal:0,1e6", 5.0),  # a fixed axial spin: the plan along A = const
        ("normal:0,1e6", (0.0, 10.0)),  # the 2-D plan
        ("0:1e6", 3.0),
    ],
)
def test_exact_omega_psi_refuses_from_a_count_before_building_its_plan(omega_x, omega_z):
    # `probability -T 0.6:0.9 --omega-x normal:0,1e6` refused after 20 s and 1.7 GB: the
    # plan's band edges and graded mesh were built (a Python loop over 10⁷ points) before the
    # bound. Now the edges are counted and refused first: neither they nor the panels are
    # built, and the memory peak stays small.
    from coinflight.model.distributions import Normal

    x = (
        Normal(0.0, float(omega_x.split(",")[1]))
        if omega_x.startswith("normal")
        else Uniform(*map(float, omega_x.split(":")))
    )
    z = Uniform(*omega_z) if isinstance(omega_z, tuple) else omega_z
    dist = TossDistribution(omega_x=x, omega_y=0, omega_z=z, flight_time=Uniform(0.6, 0.9))
    refused_cheaply(
        lambda: estimate(dist, "exact"),
        r"the exact \(Ω, ψ\) rule( over [12] ranged spins is .* integrand points|'s search "
        r"for where band edges cross the spin box is .* curve samples)",
        _exact_plan_work(),
    )
    # and its time estimate (for sweeps and the web's share of its limit) allocates nothing
    from coinflight.probability.exact import estimated_seconds

    with pytest.MonkeyPatch.context() as patch:
        never_run(patch, _exact_plan_work())
        tracemalloc.start()
        try:
            seconds = estimated_seconds(dist)
            _, peak = tracemalloc.get_traced_memory()
        finally:
            tracemalloc.stop()
    assert seconds is None or seconds > 30.0  # over the rule's half-minute budget
    assert peak < 16 * MB


def test_exact_refusal_on_the_command_line_runs_no_plan(monkeypatch):
    never_run(monkeypatch, _exact_plan_work())
    line = one_line_error("probability", "-T", "0.6:0.9", "--omega-x", "normal:0,1e6")
    assert line.startswith("the exact (Ω, ψ) rule over 1 ranged spins is 85,900,000 integrand")


def test_qmc_reports_progress_per_block_with_the_points_of_one_run(monkeypatch):
    # `probability --method qmc --n 17179869184` (accepted: about an hour) moved its progress
    # bar once per scrambling, minutes apart. A scrambling is now cut into blocks that resume
    # its sequence (Sobol.fast_forward): the same points, the same answer, and progress
    # every block.
    from coinflight.probability import qmc

    dist = TossDistribution(
        omega_x=Uniform(60, 90), omega_y=0, omega_z=Uniform(0, 20), flight_time=Uniform(0.6, 0.9)
    )
    whole = estimate(dist, "qmc", n=16 * 2**12, seed=5)
    monkeypatch.setattr(qmc, "BLOCK", 2**8)
    calls: list[int] = []
    blocks = estimate(dist, "qmc", n=16 * 2**12, seed=5, progress=calls.append)
    assert (blocks.p_heads, blocks.ci95) == (whole.p_heads, whole.ci95)
    assert calls == [2**8] * (16 * 2**4)


def test_bias_monte_carlo_reports_progress_as_it_goes():
    # `bias --monte-carlo 2147483648` (accepted: about 9 min) printed nothing until its end.
    from coinflight.probability import streams
    from coinflight.queries.bias import bias_query

    calls: list[int] = []
    n = 3 * streams.BLOCK + 5
    answer = bias_query(80.0, None, None, n, 7, Coin.preset("us-quarter"), calls.append)
    assert sum(calls) == n and len(calls) >= 4
    assert answer.payload()["monte_carlo"]["n"] == n


def test_paper_progress_counts_every_estimate_it_runs():
    # `paper --events 1000000000` (accepted: minutes) moved its bar once per figure; the bar
    # now counts the probabilities' work units, its total counted before any runs.
    from coinflight.report.paper import paper_numbers, paper_work

    calls: list[int] = []
    paper_numbers(events=1000, progress=calls.append)
    assert sum(calls) == paper_work(1000)
    assert len(calls) > 4 * 8  # many updates per figure, not one
    # at 10⁹ events the total is dominated by them: 4 figures × (10⁹ + its series)
    assert paper_work(10**9) > 8 * 10**9
