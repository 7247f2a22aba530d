"""The estimators and sweeps on a Dask cluster: the same answer as on threads, bit for bit.

One 2-worker LocalCluster (processes) serves the whole module; the command-line checks join it
through its tcp:// address, and one test starts its own with --scheduler local, as a user does.
"""

from __future__ import annotations

import json
import sys
import time

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

from _cli import answer, one_line_error
from coinflight.cli import app
from coinflight.model.distributions import Normal, Uniform
from coinflight.model.ensemble import TossDistribution
from coinflight.outcomes import outcome_model
from coinflight.probability import estimate
from coinflight.probability.distributed import (
    CONNECT_TIMEOUT,
    TARGET_OVERHEAD,
    DaskExecutor,
    check_scheduler,
    dask_client,
    require_distributed,
)
from coinflight.probability.streams import BLOCK
from coinflight.probability.sweep import Case, sweep

pytest.importorskip("distributed")  # installed by the dev extra: CI runs these tests

runner = CliRunner()
FIG_2A = TossDistribution(omega_x=Uniform(60, 90), flight_time=Uniform(0.6, 0.9))
"""Stefan & Cheche Fig 2a: ωx ~ U(60, 90) rad/s, T ~ U(0.6, 0.9) s."""


@pytest.fixture(scope="module")
def cluster():
    with dask_client("local", 2) as executor:
        yield executor


def _sleep(seconds: float) -> float:
    time.sleep(seconds)
    return seconds


def _square(x: int) -> int:
    return x * x


def _fail_on_three(x: int) -> int:
    if x == 3:
        raise ValueError("task 3 fails")
    return x


def test_monte_carlo_on_dask_is_bit_for_bit_the_threads_answer(cluster):
    # 3 blocks and a part (tasks) on 2 worker processes; the 10^7: the CLI tests below
    n = 3 * BLOCK + 12345
    on_threads = estimate(FIG_2A, "monte-carlo", n=n, seed=9)
    done: list[int] = []
    on_dask = estimate(FIG_2A, "monte-carlo", n=n, seed=9, executor=cluster, progress=done.append)
    assert on_dask.p_heads == on_threads.p_heads
    assert on_dask.counts == on_threads.counts
    assert sum(done) == n  # progress from every future, whatever their order


def test_a_raw_client_is_accepted_as_the_executor(cluster):
    grid = estimate(FIG_2A, "grid", n=300, executor=cluster.client)
    assert grid.p_heads == estimate(FIG_2A, "grid", n=300, threads=2).p_heads


@settings(
    max_examples=6, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture]
)
@given(
    n=st.integers(1, 3 * BLOCK + 17),
    seed=st.integers(0, 2**63),
    chunk=st.integers(1, 2 * BLOCK),
)
def test_any_size_seed_and_chunking_gives_the_threads_answer(cluster, n, seed, chunk):
    dist = TossDistribution(omega_x=Normal(80, 8), omega_z=Uniform(-5, 5), flight_time=0.7)
    mc = estimate(dist, "monte-carlo", n=n, seed=seed, executor=cluster, chunk_size=chunk)
    assert mc.counts == estimate(dist, "monte-carlo", n=n, seed=seed, threads=1).counts


def test_qmc_and_the_grid_sum_in_task_order(cluster):
    # float sums: equal only if the parts are added in the same order as on threads
    qmc = estimate(FIG_2A, "qmc", n=2**12, seed=3, executor=cluster)
    on_threads = estimate(FIG_2A, "qmc", n=2**12, seed=3)
    assert (qmc.p_heads, qmc.stderr) == (on_threads.p_heads, on_threads.stderr)


def test_table_landings_on_dask_equal_threads(cluster):
    table = outcome_model("table")
    dist = TossDistribution(omega_x=Uniform(60, 90), launch_speed=Uniform(1.5, 2.5))
    # 200 landings carried to rest (a few ms each), in 4 chunks on the cluster
    a = estimate(dist, "monte-carlo", n=200, seed=4, model=table, executor=cluster, chunk_size=50)
    b = estimate(dist, "monte-carlo", n=200, seed=4, model=table)
    assert (a.counts, a.details["unsettled"]) == (b.counts, b.details["unsettled"])


def test_map_keeps_the_order_and_errors_propagate(cluster):
    assert list(cluster.map(_square, range(50))) == [x * x for x in range(50)]
    with pytest.raises(ValueError, match="task 3 fails"):
        list(cluster.map(_fail_on_three, range(8)))
    assert list(cluster.map(_square, [7])) == [49]  # the cluster is still usable


def test_the_overhead_is_measured_once_per_client(cluster):
    overhead = cluster.overhead
    assert 0 < overhead < 1.0
    assert DaskExecutor(cluster.client).overhead == overhead  # cached by the client's id


def test_small_tasks_are_batched_until_the_overhead_is_under_five_percent(cluster):
    # a given overhead (4 ms) and 2 ms tasks (sleep: never shorter on a busy machine), so that
    # the sizing alone is tested: batches of about 4 ms / 5 % = 80 ms, i.e. ~40 tasks
    executor = DaskExecutor(cluster.client, overhead=0.004)
    tasks = [0.002] * 1000
    out = dict(executor.completed(_sleep, tasks, [1] * len(tasks)))
    assert sorted(out) == list(range(1000))
    stats = executor.last
    assert stats.batches < len(tasks) / 10
    # after the first single-task batches (timed), most of the work is sent in batches sized
    # to compute for at least overhead / 5 % at the rate measured when each was sent (the
    # last ones are smaller, so that no worker idles). Judged in tasks, on the sizing: the
    # batches' wall times measured the load as well (a 2 ms sleep wakes late on a busy
    # machine, by as much as the load changes while a batch runs: 48 % once at load 4-7).
    wanted = 0.004 / TARGET_OVERHEAD
    assert len(stats.units) == len(stats.planned) == stats.batches
    assert sum(stats.units) == len(tasks)
    big = sum(u for u, p in zip(stats.units, stats.planned, strict=True) if p >= 0.8 * wanted)
    assert big >= 0.5 * len(tasks), (wanted, stats)
    # The rate sized by is the tasks' own, never faster: a sleep never ends early, so a batch
    # planned for 80 ms holds at most 40 tasks of 2 ms (the plan is not inflated).
    sized = [(u, p) for u, p in zip(stats.units, stats.planned, strict=True) if p > 0]
    assert sized and all(p >= 0.002 * u for u, p in sized), sized


def _burn(seconds: float) -> float:
    """Computes (CPU, not sleep) for ``seconds`` of the thread's CPU time."""
    end = time.thread_time() + seconds
    while time.thread_time() < end:
        pass
    return seconds


def test_batches_are_sized_by_the_cpu_they_cost_outside_the_tasks(cluster):
    # 1 ms of round trip but 4 ms of CPU per task outside it (the client's, the scheduler's,
    # the workers' messaging; given here, so that the sizing alone is tested): batches compute
    # for at least 4 ms / 5 % = 80 ms of CPU, not the 20 ms the round trip alone would ask;
    # a busy machine stretches their wall time, never below their CPU time
    from coinflight.probability import distributed

    executor = DaskExecutor(cluster.client)
    key = str(cluster.client.id)
    measured = distributed._OVERHEADS.get(key)
    distributed._OVERHEADS[key] = (0.001, 0.004, None)
    try:
        tasks = [0.002] * 400
        out = dict(executor.completed(_burn, tasks, [1] * len(tasks)))
    finally:
        if measured is None:
            distributed._OVERHEADS.pop(key)
        else:
            distributed._OVERHEADS[key] = measured
    assert sorted(out) == list(range(400))
    stats = executor.last
    wanted = 0.004 / TARGET_OVERHEAD
    big = sum(d for d in stats.durations if d >= 0.8 * wanted)
    assert big >= 0.5 * stats.compute, (wanted, stats)
    assert stats.cost == pytest.approx(0.004)


def _profiling() -> bool:
    import dask

    return bool(dask.config.get("distributed.worker.profile.enabled"))


def test_the_local_cluster_workers_run_without_the_statistical_profiler(cluster):
    # a thread sampling the computing thread every 10 ms (Dask's default), for a dashboard
    # coinflight does not serve: off in the workers dask_client starts (LOCAL_CONFIG)
    assert set(cluster.client.run(_profiling).values()) == {False}


def test_a_sweep_on_dask_equals_the_sweep_on_threads(cluster):
    cases = [
        Case(TossDistribution(omega_x=Normal(m, sd), flight_time=Uniform(0.5, 0.8)))
        for m in (60, 80, 100)
        for sd in (5, 10)
    ]
    on_dask = sweep(cases, "monte-carlo", n=20_000, seed=11, executor=cluster)
    on_threads = sweep(list(reversed(cases)), "monte-carlo", n=20_000, seed=11, threads=2)
    assert [r.counts for r in on_dask] == [r.counts for r in reversed(on_threads)]


def _cli(*args):
    return runner.invoke(app, [str(a) for a in args])


MC_9 = [
    "probability", "--omega-x", "60:90", "--flight-time", "0.6:0.9", "--method", "monte-carlo",
    "--n", "10000000", "--seed", "9", "--json",
]  # fmt: skip


def test_cli_on_a_running_scheduler_prints_the_threads_answer(cluster):
    address = cluster.client.scheduler.address
    assert address.startswith("tcp://")
    on_dask = _cli(*MC_9, "--scheduler", address)
    plain = _cli(*MC_9)
    assert on_dask.exit_code == 0, on_dask.output
    assert json.loads(on_dask.stdout)["p_heads"] == json.loads(plain.stdout)["p_heads"]


@pytest.mark.slow
def test_cli_local_cluster_of_two_workers_prints_the_threads_answer():
    # the command, with its own LocalCluster (started and closed by the command)
    on_dask = _cli(*MC_9, "--scheduler", "local", "--workers", "2")
    assert on_dask.exit_code == 0, on_dask.output
    plain = _cli(*MC_9)
    assert json.loads(on_dask.stdout)["p_heads"] == json.loads(plain.stdout)["p_heads"]
    assert json.loads(plain.stdout)["p_heads"] == pytest.approx(0.497471, abs=4 * 0.000159)


def test_convergence_on_dask_writes_the_threads_table(cluster, tmp_path):
    args = [
        "convergence", "--omega-x", "60:90", "--flight-time", "0.6:0.9", "--seed", "2",
        "--methods", "grid,monte-carlo", "--grid-sizes", "10,50", "--event-sizes", "1000,1100000",
    ]  # fmt: skip
    a = _cli(*args, "--out", tmp_path / "a", "--scheduler", cluster.client.scheduler.address)
    b = _cli(*args, "--out", tmp_path / "b")
    assert a.exit_code == 0 and b.exit_code == 0, a.output + b.output
    assert (tmp_path / "a.csv").read_text() == (tmp_path / "b.csv").read_text()


def test_an_unreachable_scheduler_is_one_line_within_seconds(monkeypatch):
    # Bounded by the connection's timeout, checked by value (not timed: the machine is
    # shared): the one client made is asked to give up after CONNECT_TIMEOUT = 5 s.
    import distributed

    made = []
    client = distributed.Client

    def recorded(*args, **kwargs):
        made.append((args, kwargs))
        return client(*args, **kwargs)

    monkeypatch.setattr(distributed, "Client", recorded)
    message = one_line_error(*MC_9, "--scheduler", "tcp://127.0.0.1:1")
    assert "cannot reach a Dask scheduler at tcp://127.0.0.1:1 within 5 s" in message
    assert CONNECT_TIMEOUT == 5.0
    assert made == [(("tcp://127.0.0.1:1",), {"timeout": CONNECT_TIMEOUT})]


@pytest.mark.parametrize(
    ("args", "words"),
    [
        (["--scheduler", "foo"], "--scheduler 'foo' is neither local nor an address"),
        (["--scheduler", "tcp://host:99999"], "port 1–65535"),
        (["--workers", "2"], "--workers applies to --scheduler local only"),
        (["--scheduler", "tcp://127.0.0.1:8786", "--workers", "2"], "--workers applies to"),
        (["--scheduler", "local", "--threads", "2"], "--threads applies without --scheduler"),
    ],
)
def test_bad_scheduler_options_are_one_line(args, words):
    assert words in one_line_error(*MC_9, *args)


def test_exact_takes_no_scheduler():
    message = one_line_error("probability", "--omega-x", "60:90", "--flight-time", "0.6:0.9",
                             "--scheduler", "local")  # fmt: skip
    assert message == "--scheduler does not apply to the exact method (one task)"


def test_without_dask_the_error_says_how_to_install_it(monkeypatch):
    monkeypatch.setitem(sys.modules, "distributed", None)
    with pytest.raises(ModuleNotFoundError, match=r'pip install "coinflight\[dask\]"'):
        require_distributed()
    assert 'pip install "coinflight[dask]"' in one_line_error(*MC_9, "--scheduler", "local")


def test_library_checks_name_the_value():
    with pytest.raises(ValueError, match="'tcp://x' is neither local nor an address"):
        check_scheduler("tcp://x")
    with pytest.raises(TypeError, match="scheduler must be"):
        check_scheduler(8786)
    with pytest.raises(ValueError, match="workers applies to the local scheduler only"):
        check_scheduler("tcp://127.0.0.1:8786", 2)
    with pytest.raises(TypeError, match=r"client must be a distributed\.Client"):
        DaskExecutor(object())
    with (
        pytest.raises(ValueError, match="cannot reach a Dask scheduler"),
        dask_client("tcp://127.0.0.1:1", timeout=0.5),
    ):
        pass  # pragma: no cover


def test_results_do_not_depend_on_the_number_of_tasks_in_flight(cluster):
    # many more tasks than workers, finishing out of order: assembled by index
    cases = np.arange(40)
    assert list(cluster.map(_square, cases)) == [int(x) ** 2 for x in cases]


def test_edge_simulation_on_dask_equals_the_serial_counts(cluster):
    from coinflight.studies.edge import simulate_edge

    plain = simulate_edge([0.3, 0.6], 1500, seed=2)
    on_dask = simulate_edge([0.3, 0.6], 1500, seed=2, executor=cluster)
    assert [e.successes for _, e in on_dask] == [e.successes for _, e in plain]


def test_basin_map_in_stripes_on_dask_is_the_same_map(cluster):
    from coinflight.model.coin import Coin
    from coinflight.studies.basin import STRIPE_CELLS, basin_map

    coin = Coin.preset("us-quarter")
    resolution = (300, 2 * STRIPE_CELLS // 300 + 7)  # three stripes, the last one short
    plain = basin_map(coin, resolution=resolution)
    on_dask = basin_map(coin, resolution=resolution, executor=cluster)
    assert np.array_equal(plain.face, on_dask.face)


def test_cli_edge_and_plot_basin_take_the_scheduler(cluster, tmp_path):
    address = cluster.client.scheduler.address
    edge = ["edge", "--ratios", "0.3,0.6", "--simulate", "800", "--seed", "3", "--json"]
    a, b = _cli(*edge, "--scheduler", address), _cli(*edge)
    assert answer(a, [*edge, "--scheduler", address]) == answer(b, edge)
    basin = ["plot", "basin", "--resolution", "120", "--scheduler", address]
    c = _cli(*basin, "--out", tmp_path / "b.png")
    d = _cli(*basin[:-2], "--out", tmp_path / "c.png")
    assert c.exit_code == 0, c.output
    assert c.stdout.splitlines()[0] == d.stdout.splitlines()[0]  # P(heads) on the grid
    assert "--scheduler applies with --simulate" in one_line_error("edge", "--scheduler", address)
