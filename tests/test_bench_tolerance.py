"""benchmarks/bench_tolerance.py: the pure pieces of the step-tolerance study of the contact
ending (disagreement counting, the paired and unpaired tests, the chaos baseline's nudge), and
that its own carrying of the handed states reproduces ``land``'s outcomes (no timings)."""

from __future__ import annotations

import math
import os
import sys
from pathlib import Path

import numpy as np
import pytest

from _bench import load_bench


@pytest.fixture
def bench():  # type: ignore[no-untyped-def]
    return load_bench("bench_tolerance")  # it imports bench_bounce, bench_contact


def test_loading_the_script_leaves_numba_num_threads_as_it_was(monkeypatch):
    # The script sets NUMBA_NUM_THREADS to 1 when unset; left so in the tests' process, a
    # numba config reload after its threads are launched (at 2 here) raises "Cannot set
    # NUMBA_NUM_THREADS to a different value once the threads have been launched" (seen
    # 2026-11-24 with the script loaded bare). The loader restores the variable. Unset first
    # (monkeypatch puts it back after): set, the script would leave it alone anyway.
    monkeypatch.delenv("NUMBA_NUM_THREADS", raising=False)
    load_bench("bench_tolerance")
    assert "NUMBA_NUM_THREADS" not in os.environ


def test_benchmark_module_names_shadow_no_other_module():
    # load_bench leaves benchmarks/ first on sys.path for the session: a script named like a
    # standard-library module, a tests/ helper or an installed package would be imported in
    # its place by every later test. None is: no name of benchmarks/ is found elsewhere on the
    # path (tests/ and site-packages included) or in the standard library.
    from importlib.machinery import PathFinder

    from _bench import BENCH, bench_on_path

    bench_on_path()
    elsewhere = [p for p in sys.path if Path(p or ".").resolve() != BENCH]
    names = sorted(p.stem for p in BENCH.glob("*.py") if not p.stem.startswith("__"))
    assert "bench_contact" in names and len(names) > 10
    for name in names:
        assert name not in sys.stdlib_module_names, name
        assert PathFinder.find_spec(name, elsewhere) is None, name
    helpers = {p.stem for p in Path(__file__).parent.glob("*.py")}
    assert "_bench" in helpers and not helpers & set(names)


def test_disagreements_count_differing_pairs_among_a_mask(bench):
    a = np.array([0, 1, 2, 1, 0])
    b = np.array([0, 2, 2, 0, 1])
    assert bench.disagreements(a, b) == 3
    assert bench.disagreements(a, b, np.array([True, True, True, False, False])) == 1
    assert bench.disagreements(a, a) == 0


def test_discordant_pairs_and_mcnemars_exact_p(bench):
    a = np.array([True] * 6 + [False] * 4)
    b = np.array([False] * 6 + [False] * 4)
    assert bench.discordant(a, b) == (6, 0)
    assert bench.discordant(b, a) == (0, 6)
    # Six discordant pairs all one way: two-sided exact p = 2 (1/2)^6 (McNemar 1947).
    assert bench.mcnemar_p(a, b) == pytest.approx(2 * 0.5**6, rel=1e-12)
    # One each way: p = 1; none discordant: p = 1.
    assert bench.mcnemar_p(np.array([True, False]), np.array([False, True])) == pytest.approx(1.0)
    assert bench.mcnemar_p(a, a) == 1.0


def test_two_proportions_is_the_pooled_z_test(bench):
    # The pooled two-proportion z test written out: z = (p1 − p2)/sqrt(p (1 − p) 2/n),
    # p = erfc(|z|/√2) (Fleiss, Levin & Paik, Statistical Methods for Rates and Proportions,
    # 3rd ed., §2.5, without continuity correction).
    n, k1, k2 = 1000, 520, 470
    p1, p2, pooled = k1 / n, k2 / n, (k1 + k2) / (2 * n)
    z = (p1 - p2) / math.sqrt(pooled * (1 - pooled) * 2 / n)
    diff, se, p = bench.two_proportions(k1, k2, n)
    assert diff == pytest.approx(0.05, abs=1e-15)
    assert se == pytest.approx(math.sqrt(p1 * (1 - p1) / n + p2 * (1 - p2) / n), rel=1e-12)
    assert p == pytest.approx(math.erfc(abs(z) / math.sqrt(2)), rel=1e-9)
    assert bench.two_proportions(0, 0, n) == (0.0, 0.0, 1.0)  # an empty margin: equal
    assert bench.two_proportions(37, 37, n)[2] == 1.0


@pytest.mark.parametrize("size", [1e-12, 1e-6])
def test_the_nudge_is_relative_seeded_and_keeps_n_a_unit_vector(bench, size):
    y = np.array([0.01, 0.3, -0.2, 0.05, 0.6, 0.0, 0.8, 1e-5, -2e-5, 3e-6])
    a = bench.nudged(y, np.random.default_rng(5), size)
    b = bench.nudged(y, np.random.default_rng(5), size)
    assert np.array_equal(a, b)
    assert np.linalg.norm(a[4:7]) == pytest.approx(1.0, abs=1e-15)
    assert a[5] == 0.0  # a zero component stays zero: the nudge is relative
    # Each component times 1 + size z, z the same generator's standard normal draws; the
    # unit normal n = y[4:7] (a unit vector here) then rescaled to length 1.
    z = np.random.default_rng(5).standard_normal(len(y))
    expected = y * (1.0 + size * z)
    expected[4:7] /= math.sqrt(np.sum(expected[4:7] ** 2))
    np.testing.assert_allclose(a, expected, rtol=1e-15, atol=0.0)
    # The size is felt: relative changes of order size (not 0, not 50 times it).
    rel = np.abs(a[[0, 1, 2, 3, 7, 8, 9]] / y[[0, 1, 2, 3, 7, 8, 9]] - 1.0)
    assert 0.05 * size < np.max(rel) < 5.0 * size


def test_the_study_reproduces_lands_outcomes_and_counts_against_the_tightest(bench, monkeypatch):
    # study() stops (SystemExit) if its carrying at RTOL differs from land() on the same
    # tosses. It must run each tolerance as given: 1e-5 takes fewer steps than the default
    # (the tightest of the two, against which the faces are counted).
    from coinflight.core import contact_phase as cp

    loose, n, seed = 1e-5, 8, 3
    name, setting = "e 0.5, μ 0.3", (0.5, 0.3)
    plain = bench.study(n, seed, name, setting, [loose, cp.RTOL], None, 0)
    assert 0 < plain["handed"] <= n
    assert plain[f"steps {loose:g}"] < plain[f"steps {cp.RTOL:g}"]
    # On these seeded tosses 1e-5 and the default agree, and a 1e-12 nudge changes no face
    # (measured; about 3 % and 1e-4 of handed tosses differ in the large runs).
    assert plain[f"differ {cp.RTOL:g}"] == 0
    assert plain[f"differ {loose:g}"] == 0
    assert plain[f"nudge {bench.NUDGE:g} at {cp.RTOL:g}"] == 0

    # A known change: one face flipped (the first handed toss, tails <-> heads) in the run at
    # 1e-5 of the unperturbed states, and in the run at the default of the nudged states.
    # The count against the tightest and the chaos baseline must see exactly it.
    carry = bench.carry
    seen: list[np.ndarray] = []

    def flipping(states, cs, handed, base_face, base_status, rtol):
        run = carry(states, cs, handed, base_face, base_status, rtol)
        if not seen:
            seen.append(states.copy())
        nudged = not np.array_equal(states, seen[0])
        if (rtol == loose and not nudged) or (rtol == cp.RTOL and nudged):
            k = int(np.flatnonzero(handed)[0])
            run.face[k] = 1 - run.face[k] if run.face[k] < 2 else 0
        return run

    monkeypatch.setattr(bench, "carry", flipping)
    flipped = bench.study(n, seed, name, setting, [loose, cp.RTOL], None, 0)
    assert flipped[f"differ {loose:g}"] == 1
    assert flipped[f"differ {cp.RTOL:g}"] == 0
    assert flipped[f"nudge {bench.NUDGE:g} at {cp.RTOL:g}"] == 1


@pytest.mark.parametrize(
    ("argv", "words"),
    [
        (["--settings", "3"], "--settings '3': must be indices among 0,1,2"),
        (["--settings", "x"], "--settings 'x'"),
        (["--extra", "0", "--subset", "1"], "--extra 0: must be in (0, 1)"),
        (["--subset", "1"], "--subset 1: must be at least 0, and more than 0 only with --extra"),
        (["--subset", "-1", "--extra", "1e-10"], "--subset -1"),
        (["--tolerances", "1e-7,abc"], "--tolerances '1e-7,abc': must be comma-separated"),
        (["--tolerances", "1e-7,0"], "--tolerances '1e-7,0'"),
        (["--nudges=-1e-6"], "--nudges '-1e-6'"),
        (["0"], "N 0: must be at least 1"),
    ],
)
def test_bad_arguments_end_in_one_line_and_exit_code_2(bench, monkeypatch, capsys, argv, words):
    monkeypatch.setattr("sys.argv", ["bench_tolerance.py", *argv])
    with pytest.raises(SystemExit) as exit_:
        bench.main()
    assert exit_.value.code == 2
    err = capsys.readouterr().err
    assert words in err
    assert "Traceback" not in err


def test_no_handed_toss_reports_0_handed(bench, monkeypatch, capsys):
    # Every toss settling in its bounces (handoff returns "not handed"): no medians of empty
    # arrays, a line saying so.
    import bench_contact

    monkeypatch.setattr(bench_contact, "handoff", lambda *a: (np.zeros(10), False))
    result = bench.study(3, 3, "e 0.5, μ 0.3", (0.5, 0.3), [1e-5, 1e-7], 1e-8, 2)
    assert result == {"handed": 0}
    assert "0 handed to the contact phase" in capsys.readouterr().out


def test_the_uncertainty_exponent_is_the_log_log_slope(bench):
    # Shares exactly 0.3 δ^0.45 (counts of 10^12 handed, rounded: relative error < 1e-7) give
    # α = 0.45; a smooth boundary's f ∝ δ gives 1; sizes that changed nothing are left out.
    m = 10**12
    counts = {d: (round(0.3 * d**0.45 * m), m) for d in (1e-9, 1e-8, 1e-7, 1e-6, 1e-5)}
    alpha, se, k = bench.uncertainty_exponent(counts)
    assert alpha == pytest.approx(0.45, abs=1e-6)
    assert se < 1e-6
    assert k == 5
    smooth = {d: (round(2.0 * d * m), m) for d in (1e-6, 1e-5, 1e-4)} | {1e-12: (0, m)}
    assert bench.uncertainty_exponent(smooth)[0] == pytest.approx(1.0, abs=1e-6)
    assert bench.uncertainty_exponent(smooth)[2] == 3
    # Fewer than three sizes that changed a face: no fit.
    alpha, se, k = bench.uncertainty_exponent({1e-6: (5, 100), 1e-5: (9, 100), 1e-4: (0, 100)})
    assert math.isnan(alpha) and math.isnan(se) and k == 2
