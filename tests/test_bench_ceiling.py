"""benchmarks/bench_ceiling.py: the pure pieces of the combined ceiling of the contact phase
(the combination arithmetic, the rotation integral, the contact episodes, the weighted median,
the hops' bound, the oracle's stop on a constructed record), its sampled trace of a run on a
closed-form case (a coin turning torque-free in the air: ∫|ω| dt = |ω| T), the durations it
gives ``bench_tolerance.carry``, and its refusal of bad options. No timings."""

from __future__ import annotations

import math
from types import ModuleType

import numpy as np
import pytest

from _bench import BENCH, load_bench
from _cli import script_error


@pytest.fixture
def bench(monkeypatch: pytest.MonkeyPatch) -> ModuleType:
    import numba

    monkeypatch.syspath_prepend(str(BENCH))  # the script imports its neighbours
    # The script sets NUMBA_NUM_THREADS to 1 unless set (for its one-thread timings); here it
    # must stay what numba runs with, or numba refuses a change once its threads are launched.
    threads = numba.config.NUMBA_NUM_THREADS  # type: ignore[attr-defined]
    monkeypatch.setenv("NUMBA_NUM_THREADS", str(threads))
    return load_bench("bench_ceiling")


def test_rotation_of_a_constant_turn_rate_is_omega_times_the_time(bench):
    # A coin rolling at constant |ω| = 40 rad/s for T = 0.3 s, sampled unevenly: ω T.
    t = np.array([0.0, 0.01, 0.05, 0.051, 0.2, 0.3])
    assert bench.rotation(t, np.full(6, 40.0)) == pytest.approx(12.0, rel=1e-14)


def test_rotation_is_exact_for_a_turn_rate_linear_in_time(bench):
    # |ω| = 10 + 100 t over [0, 0.5]: ∫ = 10 · 0.5 + 50 · 0.25 = 17.5 (a left sum gives 15.0
    # on these samples, a right one 20.0).
    t = np.array([0.0, 0.1, 0.25, 0.5])
    assert bench.rotation(t, 10.0 + 100.0 * t) == pytest.approx(17.5, rel=1e-14)
    turns = bench.segment_turns(t, 10.0 + 100.0 * t)
    assert turns.sum() == pytest.approx(17.5, rel=1e-14)
    assert turns[0] == pytest.approx(10.0 * 0.1 + 50.0 * 0.01, rel=1e-14)
    assert bench.rotation(t[:1], np.array([3.0])) == 0.0


def test_episodes_count_touchdowns_and_hops_inside_a_stretch(bench):
    free, one, two = 0, 1, 2
    # In contact at the hand-off, a hop seen at a sample, a hop inside a stretch, a hop seen
    # at the last sample: three episodes (the first contact and two touchdowns), the last hop
    # unfinished.
    modes = [one, one, free, free, two, one, one, free]
    hopped = [False, True, True, True, False, True, True]
    assert bench.episodes(modes, hopped) == 3
    # The stretch between samples 4 and 5 had a hop inside (both ends in contact): one more.
    hopped[4] = True
    assert bench.episodes(modes, hopped) == 4
    # Handed off the table (rising from the last impact): its first touchdown counts, not
    # the hand-off.
    assert bench.episodes([free, one, one], [True, False]) == 1
    assert bench.episodes([free, free], [True]) == 0
    assert bench.episodes([], []) == 0


def test_weighted_median_is_the_median_of_the_values_repeated(bench):
    values = np.array([5.0, 1.0, 3.0, 2.0])
    weights = np.array([1.0, 3.0, 1.0, 2.0])  # 1, 1, 1, 2, 2, 3, 5: median 2
    assert bench.weighted_median(values, weights) == 2.0
    assert bench.weighted_median(values, np.array([1.0, 1.0, 5.0, 0.0])) == 3.0
    assert bench.weighted_median(np.array([7.0]), np.array([2.0])) == 7.0
    # An even total: the lower median (the ⌈W/2⌉-th value), not the upper.
    assert bench.weighted_median(np.array([1.0, 2.0]), np.array([1.0, 1.0])) == 1.0
    assert bench.weighted_median(np.array([2.0, 1.0]), np.array([2.0, 2.0])) == 1.0
    assert math.isnan(bench.weighted_median(values, np.zeros(4)))


def test_hop_factor_is_all_steps_over_those_in_contact(bench):
    stats = np.zeros((4, 2))
    stats[:, 1] = [20.0, 60.0, 15.0, 5.0]  # free, one rim, two rims, face
    stats[:, 0] = [9.0, 1.0, 1.0, 1.0]  # the time does not enter
    assert bench.hop_factor(stats) == pytest.approx(100.0 / 80.0, rel=1e-15)
    stats[1:, 1] = 0.0
    assert bench.hop_factor(stats) == math.inf


def test_landing_factor_and_the_combined_rate(bench):
    # Amdahl: the bounces (B) are left alone, the phase (P) gets F times cheaper.
    assert bench.landing_factor(2.0, 98.0, 1.0) == 1.0
    assert bench.landing_factor(0.0, 98.0, 7.0) == pytest.approx(7.0, rel=1e-15)
    assert bench.landing_factor(2.0, 98.0, 7.0) == pytest.approx(100.0 / 16.0, rel=1e-15)
    assert bench.landing_factor(2.0, 98.0, math.inf) == pytest.approx(50.0, rel=1e-15)
    f, rate = bench.combined(3_000.0, 2.0, 98.0, (2.0, 1.5, 7.0 / 3.0))
    assert f == pytest.approx(7.0, rel=1e-15)
    assert rate == pytest.approx(3_000.0 * 100.0 / 16.0, rel=1e-14)
    assert bench.combined(3_000.0, 2.0, 98.0, ())[1] == pytest.approx(3_000.0, rel=1e-15)


def test_caps_count_the_steps_of_an_ideal_integrator_on_constructed_stretches(bench):
    # Four one-step stretches (dt s, turn rad, free s): a hop at 100 rad/s for 0.8 ms (the 1
    # ms cap: 0.8 steps; π/8 a step: 0.08 / (π/8)); contact at 50 rad/s for 0.1 ms (a tenth
    # of its 1 ms cap at most: held); contact at 500 rad/s for 0.5 ms (π/8 binds: its cap
    # π/8/500 = 0.785 ms; 0.25 rad = 0.637 steps); a half-hop at 200 rad/s for 1 ms.
    cap = math.pi / 8.0
    dt = np.array([8e-4, 1e-4, 5e-4, 1e-3])
    turns = np.array([0.08, 0.005, 0.25, 0.2])
    free = np.array([8e-4, 0.0, 0.0, 5e-4])
    out = bench.caps(dt, turns, np.ones(4), free)
    assert out["rot_hop"] == pytest.approx(0.08 + 0.1, rel=1e-14)
    assert out["rot_contact"] == pytest.approx(0.005 + 0.25 + 0.1, rel=1e-14)
    need = [0.8, 0.1, 0.25 / cap, 1.0]
    assert out["cap"] == pytest.approx(sum(need), rel=1e-14)
    assert out["cap_contact"] == pytest.approx(0.1 + 0.25 / cap + 0.5, rel=1e-14)
    assert out["turn"] == pytest.approx(0.535 / cap, rel=1e-14)
    assert out["turn_contact"] == pytest.approx(0.355 / cap, rel=1e-14)
    assert out["held"] == 0.0  # 0.1 ms is a tenth of 1 ms, not below it
    dt[1] = 0.99e-4
    out = bench.caps(dt, turns, np.ones(4), free)
    assert (out["held"], out["held_contact"]) == (1.0, 1.0)
    # The same stretch as ten steps of 9.9 μs: ten held steps, the same caps.
    ten = bench.caps(dt, turns, np.array([1.0, 10.0, 1.0, 1.0]), free)
    assert ten["held"] == 10.0
    assert ten["cap"] == pytest.approx(out["cap"], rel=1e-14)


def test_setting_row_combines_the_right_factors(bench):
    # Constructed measurements: the bounces B = 0.04 s, the shipped phase P = 1.96 s (so a
    # landing costs twice the reference's 1.0 s: today's rate halves); RTOL 1e-5 and the oracle
    # at 1e-7 each 2×, the oracle at 1e-5 4×; hops 20 % of the shipped steps but 50 % of the
    # oracle at 1e-5's (the bound is taken in that run: 2×).
    stats = {v: np.zeros((4, 2)) for v in bench.VARIANTS}
    stats["shipped 1e-7"][:, 1] = [20.0, 60.0, 15.0, 5.0]
    stats["oracle 1e-5"][:, 1] = [10.0, 8.0, 2.0, 0.0]
    cpu = {"shipped 1e-7": 1.96, "rtol 1e-5": 0.98, "oracle 1e-7": 0.98, "oracle 1e-5": 0.49}
    res = {"bounces": 0.04, "phase": 1.96, "cpu": cpu, "stats": stats}
    res["floors"] = {"1 ms cap": 25.0, "π/8": 4.0}
    row = bench.setting_row(3_000.0, 1.0, res)
    here = 1_500.0
    assert row["here"] == pytest.approx(here, rel=1e-15)
    assert (row["f_rtol"], row["f_or7"], row["f_or5"]) == pytest.approx((2.0, 2.0, 4.0))
    assert row["hops"] == pytest.approx(2.0, rel=1e-15)
    assert row["f"] == pytest.approx(8.0, rel=1e-15)
    assert row["ceiling"] == pytest.approx(here * 2.0 / (0.04 + 1.96 / 8.0), rel=1e-14)
    rigid = 8.0 * bench.RIGID_STEPS
    assert row["rigid"] == pytest.approx(here * 2.0 / (0.04 + 1.96 / rigid), rel=1e-14)
    factor, landings = row["floors"]["1 ms cap"]
    assert factor == pytest.approx(4.0, rel=1e-15)  # 100 shipped steps over 25
    assert landings == pytest.approx(here * 2.0 / (0.04 + 1.96 / 4.0), rel=1e-14)
    assert row["floors"]["π/8"][0] == pytest.approx(25.0, rel=1e-15)
    assert row["free"] == pytest.approx(here * 2.0 / 0.04, rel=1e-14)


def test_predictors_carry_runs_at_the_tolerance_it_is_given(bench):
    # bench_predictors.carry in one chunk (no restart of the step size) takes the steps
    # bench_tolerance.carry takes at the same tolerance on every toss the upright decision
    # does not end, and fewer at 1e-5 than at 1e-7 (the oracle's records at 1e-5 are at 1e-5).
    from coinflight.core.outcome import Status

    tol = bench.bench_tolerance
    omega, v0 = tol.bench_bounce.tosses(12, 7)
    cs = tol.records(12, (0.5, 0.3))
    states, handed, face, status = tol.handoffs(cs, omega, v0)
    steps = {}
    for rtol in (1e-7, 1e-5):
        run = tol.carry(states, cs, handed, face, status, rtol)
        ours = np.zeros(12, dtype=int)
        for k in np.flatnonzero(handed):
            ours[k] = bench.bench_predictors.carry(states[k].copy(), cs[k], 1e3, rtol=rtol)["steps"]
        settled = handed & (run.status == Status.SETTLED_CONTACT)
        assert settled.sum() >= 3
        assert np.array_equal(ours[settled], run.steps[settled])
        steps[rtol] = ours[handed].sum()
    assert steps[1e-5] < 0.8 * steps[1e-7]


def test_the_oracles_stop_on_a_constructed_record(bench):
    last = bench.bench_predictors.last_well_change
    tails, heads, edge = 0, 1, 2
    # (time, steps, well) after the hand-off and after each chunk.
    wells = [(0.0, 0, heads), (0.002, 9, edge), (0.004, 20, heads), (0.006, 31, edge)]
    wells += [(0.008, 40, edge), (0.010, 44, edge)]
    assert last(wells, edge) == 3  # never outside the edge well from the fourth record on
    assert last(wells[:3], heads) == 2
    assert last([(0.0, 0, tails), (0.002, 5, tails)], tails) == 0  # never leaves its well
    assert last([(0.0, 0, tails), (0.002, 5, heads)], tails) == 2  # past the record


def test_trace_of_a_coin_turning_in_the_air_gives_omega_times_the_time(bench):
    # Torque-free (high above the table, only gravity on the centre): |ω| of a symmetric top
    # is constant, so ∫|ω| dt = |ω| T, with no contact episode; sampled at every step and
    # every 7th alike.
    import bench_contact  # beside the script, on the path the fixture prepends
    from coinflight.core import contact_phase as cp
    from coinflight.core.impact import angular_velocity

    c = bench_contact.contact(0.5, 0.3)
    n = np.array([math.sin(0.4), 0.0, math.cos(0.4)])
    omega = np.array([120.0, -30.0, 45.0])
    lm = c.i1 * omega + (c.i3 - c.i1) * (omega @ n) * n
    y0 = np.array([1.0, 0.1, 0.0, 0.0, *n, *lm])
    w = angular_velocity(tuple(lm), tuple(n), c.i1, c.i3)
    speed = math.sqrt(sum(x * x for x in w))
    assert speed == pytest.approx(float(np.linalg.norm(omega)), rel=1e-12)
    duration = 0.05
    steps = cp.advance(y0.copy(), duration, c, settle_check=True)[1]
    for budget in (steps * steps, steps * steps / 14.0):
        tr = bench.trace(y0, c, duration, steps, budget)
        assert tr["steps"] == steps
        assert tr["time"] == pytest.approx(duration, rel=1e-12)
        assert tr["rotation"] == pytest.approx(speed * duration, rel=1e-6)
        assert tr["episodes"] == 0
        assert tr["count"].sum() == steps
    assert tr["stride"] == 7
    assert np.sum(tr["turn"] * tr["count"]) == pytest.approx(speed * duration, rel=1e-6)


def test_carry_stops_each_toss_at_its_duration(bench):
    # bench_tolerance.carry with durations: unlimited is the run without them to the bit; a
    # toss given 0 s takes no step; one given half its time stops there, in fewer steps.
    omega, v0 = bench.bench_tolerance.bench_bounce.tosses(12, 7)
    cs = bench.bench_tolerance.records(12, (0.5, 0.3))
    states, handed, face, status = bench.bench_tolerance.handoffs(cs, omega, v0)
    assert handed.sum() >= 3
    carry = bench.bench_tolerance.carry
    full = carry(states, cs, handed, face, status, 1e-7)
    same = carry(states, cs, handed, face, status, 1e-7, durations=np.full(12, math.inf))
    for a, b in ((full.face, same.face), (full.steps, same.steps), (full.time, same.time)):
        assert np.array_equal(a, b)
    half = carry(states, cs, handed, face, status, 1e-7, durations=0.5 * full.time)
    assert np.all(half.time[handed] <= 0.5 * full.time[handed] * (1.0 + 1e-12))
    assert np.all(half.steps[handed] < full.steps[handed])
    none = carry(states, cs, handed, face, status, 1e-7, durations=np.zeros(12))
    assert np.all(none.steps[handed] == 0)


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (["0"], "N 0: must be at least 1"),
        (["--rounds", "0"], "--rounds 0: must be at least 1"),
        (["--chunk", "-1"], "--chunk -1: must be a finite number > 0"),
        (["--rate", "nan"], "--rate nan: must be a finite number > 0"),
        (["--settings", "0,5"], "--settings '0,5': must be indices among 0-2"),
    ],
)
def test_bad_options_are_refused_in_one_line(args, words, tmp_path):
    assert script_error(BENCH / "bench_ceiling.py", args, tmp_path) == words
