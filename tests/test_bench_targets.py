"""benchmarks/bench_targets.py: the table of the landing speed targets built from given rates
(medians, ratios measured / target, met flags, exact keys; no timing), a tiny run of the
command end to end (structure; every rate finite and positive, no threshold on any), and bad
input refused in one line with exit code 2."""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys
from types import ModuleType

import numpy as np
import pytest

from _bench import BENCH, bench_script, load_bench
from coinflight.core.outcome import Status


@pytest.fixture
def bench(monkeypatch: pytest.MonkeyPatch) -> ModuleType:
    monkeypatch.syspath_prepend(str(BENCH))  # the script imports bench_bounce and bench_air
    return load_bench("bench_targets")


def test_each_case_times_what_its_label_says(bench):
    # The review's wiring test (2026-11-24), widened: every case on the same 24 tosses, its
    # outcomes checked against what its label says. Mutants it kills: first_contact without
    # max_bounces=0; a "to rest" row stopped at a bounce limit; rest_human on the vigorous
    # tosses; cases_in_air's "table to rest" without drag; the own-e, μ row without
    # ``contact``.
    size = {c.key: 24 for c in bench.CASES}
    got = {k: fn() for k, fn in bench.calls(size, 5).items()}
    v0 = bench.bench_bounce.tosses(24, 5)[1]
    # First contacts stop at the first contact.
    assert np.all(got["first_contact"].bounces == 0)
    assert np.all(got["air_first_contact"].bounces == 0)
    # Carried to rest: they bounce, none stops at a bounce limit, and some end in the 3-D
    # ending (the planar hand-off is retired: never reported).
    for k in ("rest", "rest_human", "rest_own", "air_rest"):
        assert np.any(got[k].bounces > 0), k
        assert not np.any(got[k].status == Status.BOUNCE_LIMIT), k
        assert not np.any(got[k].status == Status.SETTLED_ROCKING), k
        assert np.any(got[k].status == Status.SETTLED_CONTACT), k
    # Each toss its own e, μ: not the row at e 0.5, μ 0.3; human tosses: not the vigorous.
    assert not np.array_equal(got["rest"].settle_time, got["rest_own"].settle_time)
    assert not np.any(got["rest"].first_contact == got["rest_human"].first_contact)
    B = bench.bench_bounce
    first = bench.land(B.COIN, *B.human_tosses(24, 5), 1.0, B.G, B.SURFACE, max_bounces=0)
    assert np.array_equal(first.first_contact, got["rest_human"].first_contact)
    # Through air, not in vacuum, on the same tosses: every catch differs from the vacuum's
    # 2 v0 / g, every first contact from the vacuum row's.
    catch = got["air_hand"][1]
    assert not np.any(np.isclose(catch, 2.0 * v0 / bench.bench_bounce.G, rtol=1e-9, atol=0.0))
    for air, vacuum in (("air_first_contact", "first_contact"), ("air_rest", "rest")):
        assert not np.any(got[air].first_contact == got[vacuum].first_contact), air


def test_measure_times_two_threads_and_with_cpu_one(bench, monkeypatch):
    # The threads reported are numba's own count after measure sets them (mutant: without
    # numba.set_num_threads the count stays at the 1 set here), and with ``cpu`` each case runs
    # once a round on numba's threads and once in one thread (mutant: the serial calls built
    # with parallel=True). Every land / catch_with_drag call is recorded: (tosses, parallel).
    import numba

    if numba.config.NUMBA_NUM_THREADS < 2:
        pytest.skip("numba has fewer than 2 threads")
    seen: list[tuple[int, bool]] = []

    def spy(real):  # type: ignore[no-untyped-def]
        def call(coin, omega, *args, parallel=True, **kw):  # type: ignore[no-untyped-def]
            seen.append((len(omega), parallel))
            return real(coin, omega, *args, parallel=parallel, **kw)

        return call

    for module, name in ((bench, "land"), (bench.bench_air, "land"),
                         (bench.bench_air, "catch_with_drag")):  # fmt: skip
        monkeypatch.setattr(module, name, spy(getattr(module, name)))
    before = numba.get_num_threads()
    numba.set_num_threads(1)
    try:
        got = bench.measure({c.key: 7 for c in bench.CASES}, 2, 5, cpu=True)
        assert got["threads"] == 2 == numba.get_num_threads()
    finally:
        numba.set_num_threads(before)
    timed = [p for n, p in seen if n == 7]
    assert timed.count(True) == timed.count(False) == 2 * len(bench.CASES)
    assert all(r["one_thread"] is not None for r in got["rows"])


def _rates(bench: ModuleType, value: float = 1.0) -> dict[str, list[float]]:
    return {c.key: [value] for c in bench.CASES}


def test_the_targets_are_the_issues(bench):
    # Issue 27, "Done when": ≥ 20,000 human or vigorous tosses carried to rest a second on
    # 2 cores, first contact ≥ 2 M/s; issue 11's: tosses with air drag ≥ 100,000/s (the hand
    # catch and the first contact: landings through air carried to rest are a reference row,
    # their cost the rigid ending's).
    target = {c.key: c.target for c in bench.CASES}
    assert target == {
        "first_contact": 2_000_000.0,
        "rest": 20_000.0,
        "rest_human": 20_000.0,
        "rest_own": 20_000.0,
        "air_hand": 100_000.0,
        "air_first_contact": 100_000.0,
        "air_rest": None,
    }
    for c in bench.CASES:
        assert (bench.REF in c.label) is (c.target is None), c.key
    assert bench.THREADS == 2
    assert bench.bench_bounce.TO_REST_TARGET == 20_000.0


def test_rows_give_the_median_the_ratio_and_met(bench):
    size = bench.sizes(False)
    rates = _rates(bench)
    # Medians of the rounds (not the mean: 1, 2, 30 has median 2, mean 11).
    rates["first_contact"] = [1_000_000.0, 3_000_000.0, 2_500_000.0]
    rates["rest"] = [1.0, 2.0, 30.0]
    rates["rest_own"] = [20_000.0]  # exactly at the target: met
    rates["rest_human"] = [19_999.0]  # just below: not met
    rates["air_rest"] = [56_440.0]  # a reference row: no target, ratio or met
    rates["air_hand"] = [250_000.0, 200_000.0]  # even count: mean of the middle two
    rows = bench.rows(rates, size)
    assert [r["key"] for r in rows] == [c.key for c in bench.CASES]
    for r in rows:
        assert tuple(r) == bench.ROW_KEYS
    by = {r["key"]: r for r in rows}
    first = by["first_contact"]
    assert first["measured"] == 2_500_000.0
    assert first["ratio"] == pytest.approx(1.25, rel=1e-15)
    assert first["met"] is True
    assert first["n"] == 1_000_000 and first["rounds"] == [1_000_000.0, 3_000_000.0, 2_500_000.0]
    assert by["rest"]["measured"] == 2.0
    assert by["rest"]["ratio"] == pytest.approx(2.0 / 20_000.0, rel=1e-15)
    assert by["rest"]["met"] is False
    assert by["rest_own"]["ratio"] == 1.0 and by["rest_own"]["met"] is True
    assert by["rest_human"]["met"] is False
    assert by["air_rest"]["target"] is by["air_rest"]["ratio"] is by["air_rest"]["met"] is None
    assert by["air_rest"]["measured"] == 56_440.0
    assert by["air_hand"]["measured"] == 225_000.0
    assert by["air_hand"]["ratio"] == pytest.approx(2.25, rel=1e-15)
    assert by["air_hand"]["met"] is True
    assert by["air_hand"]["ratio"] == pytest.approx(2.25, rel=1e-15)
    assert by["rest_own"]["ratio"] == pytest.approx(1.0, rel=1e-15)
    assert all(r["one_thread"] is None and r["one_thread_ratio"] is None for r in rows)
    assert json.loads(json.dumps(rows)) == rows  # numbers as numbers, booleans as booleans
    text = bench.table(rows)
    assert text.count("\n") == len(rows) + 1  # the header, the rows, the note
    assert text.splitlines()[-1] == bench.REF_NOTE
    assert "2,500,000" in text and "1.250  yes" in text and "0.000  no" in text
    assert "CPU" not in text
    # One column width from the longest label: every row's tosses end in the same column.
    lines = text.splitlines()
    ends = {line.index("tosses") + len("tosses") for line in lines[:1]}
    for r, line in zip(rows, lines[1:-1], strict=True):
        ends.add(line.index(f"{r['n']:,}") + len(f"{r['n']:,}"))
    assert len(ends) == 1
    assert max(len(line) for line in lines) <= 100  # fits the docstring's pasted output
    ref = lines[1 + [r["key"] for r in rows].index("air_rest")]
    assert ref.split()[-3:] == ["ref", "-", "-"]


def test_rows_with_one_thread_per_cpu_second(bench):
    rates = _rates(bench)
    cpu = _rates(bench, 2.0)
    cpu["rest"] = [1_000.0, 1_500.0, 30_000.0]  # median 1,500
    cpu["rest_human"] = [10_000.0]  # 2 × 10,000 = the target exactly
    cpu["air_rest"] = [30_000.0]  # a reference row: its rate, no ratio
    by = {r["key"]: r for r in bench.rows(rates, bench.sizes(True), cpu)}
    assert by["rest"]["one_thread"] == 1_500.0
    assert by["rest"]["one_thread_ratio"] == pytest.approx(2 * 1_500 / 20_000, rel=1e-15)
    assert by["rest_human"]["one_thread_ratio"] == 1.0
    assert by["rest_human"]["met"] is False  # met is the wall clock's, on 2 threads
    assert by["air_rest"]["one_thread"] == 30_000.0 and by["air_rest"]["one_thread_ratio"] is None
    text = bench.table(list(by.values()))
    cpu_lines = text.splitlines()[len(by) + 2 :]  # after the header, the rows and the note
    assert cpu_lines[0].startswith("one thread (parallel=False)") and len(cpu_lines) == len(by) + 1
    assert "1,500" in cpu_lines[2] and cpu_lines[2].endswith("0.150")
    assert cpu_lines[-1].endswith(" -") and max(len(line) for line in cpu_lines) <= 100
    cpu["air_hand"] = [math.nan]
    with pytest.raises(ValueError, match="air_hand"):
        bench.rows(rates, bench.sizes(True), cpu)


@pytest.mark.parametrize("bad", [0.0, -1.0, math.nan, math.inf])
def test_rows_refuse_a_rate_not_finite_and_positive(bench, bad):
    rates = _rates(bench)
    rates["air_rest"] = [1.0, bad]
    with pytest.raises(ValueError, match=r"for air_rest$"):
        bench.rows(rates, bench.sizes(True))


def test_rows_refuse_a_case_without_rates(bench):
    rates = _rates(bench)
    del rates["rest_own"]
    with pytest.raises(ValueError, match="no rate measured for rest_own"):
        bench.rows(rates, bench.sizes(True))
    rates["rest_own"] = []
    with pytest.raises(ValueError, match="rest_own"):
        bench.rows(rates, bench.sizes(True))


def test_sizes_and_the_work_bound(bench):
    full, quick = bench.sizes(False), bench.sizes(True)
    assert full["first_contact"] == 1_000_000 and full["rest"] == full["rest_human"] == 1_000
    assert all(quick[k] == full[k] // 10 for k in full)
    assert set(bench.sizes(False, 7).values()) == {7}
    # The estimate is rounds × Σ n / quiet rate: linear in both.
    one = bench.seconds_estimate(full, 1)
    assert bench.seconds_estimate(full, 4) == pytest.approx(4 * one, rel=1e-12)
    assert one == pytest.approx(sum(c.size / c.quiet_rate for c in bench.CASES), rel=1e-12)


def test_the_report_has_exactly_its_keys(bench):
    measured = {
        "threads": 2,
        "load": {"before": [1.0, 2.0, 3.0], "after": [1.5, 2.0, 3.0]},
        "rows": bench.rows(_rates(bench, 10.0), bench.sizes(True)),
        "mujoco": None,
    }
    rep = bench.report(measured, bench.Recorder("bench_targets", ["--quick"]), 11, 3)
    assert set(rep) == {
        "benchmark", "figures", "command", "date", "machine", "versions", "load",
    }  # fmt: skip
    assert rep["command"] == "python benchmarks/bench_targets.py --quick"
    fig = rep["figures"]
    assert set(fig) == {"seed", "own_rates_seed", "rounds", "threads", "targets", "mujoco"}
    assert fig["seed"] == 11 and fig["rounds"] == 3
    assert fig["own_rates_seed"] == 7 == bench.bench_bounce.OWN_RATES_SEED
    assert rep["load"] == measured["load"]  # the timing's own load, not the run's
    assert set(rep["machine"]) == {"processor", "cpus", "system"}
    assert set(rep["versions"]) == {"coinflight", "python", "numpy", "numba", "scipy", "mujoco"}
    text = bench.text(rep)
    assert "load average 1.00 before, 1.50 after" in text
    assert "MuJoCo" not in text
    skipped = bench.text({**rep, "figures": {**fig, "mujoco": {"skipped": "MuJoCo not installed"}}})
    assert skipped.splitlines()[-2] == "MuJoCo: skipped, MuJoCo not installed"


def _run(*args: str) -> subprocess.CompletedProcess[str]:
    env = dict(os.environ, NUMBA_NUM_THREADS="2")
    return subprocess.run(
        [sys.executable, str(bench_script("bench_targets")), *args],
        capture_output=True,
        text=True,
        env=env,
        timeout=600,
    )


def test_a_tiny_run_gives_the_whole_report():
    from coinflight.studies import mujoco_compare

    args = ("--quick", "--json", "--n", "24", "--rounds", "2", "--seed", "5", "--mujoco", "3")
    done = _run(*args, "--cpu")
    assert done.returncode == 0, done.stderr
    rep = json.loads(done.stdout)
    assert rep["command"] == (
        "python benchmarks/bench_targets.py --quick --json --n 24 --rounds 2 --seed 5 --mujoco 3 "
        "--cpu"
    )
    fig = rep["figures"]
    assert fig["seed"] == 5 and fig["rounds"] == 2 and fig["threads"] == 2
    assert len(rep["load"]["before"]) == len(rep["load"]["after"]) == 3
    rows = fig["targets"]
    assert [r["key"] for r in rows] == [
        "first_contact", "rest", "rest_human", "rest_own", "air_hand", "air_first_contact",
        "air_rest",
    ]  # fmt: skip
    for r in rows:
        assert list(r) == [
            "key", "target_name", "n", "measured", "target", "ratio", "met", "rounds",
            "one_thread", "one_thread_ratio",
        ]  # fmt: skip
        assert r["n"] == 24 and len(r["rounds"]) == 2
        for x in (r["measured"], *r["rounds"], r["one_thread"]):
            assert isinstance(x, float) and math.isfinite(x) and x > 0.0
        if r["target"] is None:  # a reference row
            assert r["ratio"] is r["met"] is r["one_thread_ratio"] is None
            continue
        assert math.isfinite(r["one_thread_ratio"]) and r["one_thread_ratio"] > 0.0
        assert r["ratio"] == pytest.approx(r["measured"] / r["target"], rel=1e-12)
        assert r["met"] is (r["ratio"] >= 1.0)
    mj = fig["mujoco"]
    if not mujoco_compare.available():
        assert set(mj) == {"skipped"}
        return
    assert mj["n"] == 3 and mj["mujoco"] == rep["versions"]["mujoco"]
    for key in ("mujoco_rate", "coinflight_rate", "ratio"):
        assert math.isfinite(mj[key]) and mj[key] > 0.0
    assert mj["ratio"] == pytest.approx(mj["coinflight_rate"] / mj["mujoco_rate"], rel=1e-12)


@pytest.mark.parametrize(
    ("args", "says"),
    [
        (["--rounds", "0"], "--rounds must be between 1 and 100, got 0"),
        (["--n", "0"], "--n must be between 1 and 10000000, got 0"),
        (["--seed", "-1"], "--seed must be at least 0, got -1"),
        (["--mujoco", "-2"], "--mujoco must be between 0 and 10000, got -2"),
        (["--rounds", "x"], "argument --rounds: invalid int value: 'x'"),
        (["--n", "10000000"], "more than the limit"),
    ],
)
def test_bad_input_is_one_line_and_exit_code_2(bench, capsys, args, says):
    with pytest.raises(SystemExit) as stop:
        bench.parse(args)
    assert stop.value.code == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("bench_targets.py: ")
    assert says in err


def test_the_command_refuses_zero_rounds_in_one_line():
    done = _run("--rounds", "0")
    assert done.returncode == 2
    assert done.stdout == ""
    assert done.stderr == "bench_targets.py: --rounds must be between 1 and 100, got 0\n"
