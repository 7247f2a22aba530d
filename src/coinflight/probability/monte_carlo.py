"""Monte Carlo: plain (continuous draws) and the paper's method B (draws from a coarse grid).

Reproducibility: the tosses come from :mod:`coinflight.probability.streams` (blocks of
:data:`~coinflight.probability.streams.BLOCK` tosses, one SFC64 stream per block and ranged
parameter). Tasks group whole blocks, so the estimate is the same for every chunk size, thread
count and executor, and a run of n tosses is the first n tosses of any longer run with the same
seed. Parameter-major draws also give the compiled
kernels contiguous rows, which they need to vectorise.
"""

from __future__ import annotations

import math
import time
from typing import Any

import numpy as np

from coinflight.model.ensemble import TossDistribution
from coinflight.outcomes.base import OutcomeModel, tally_details
from coinflight.outcomes.hand import HAND_CATCH
from coinflight.probability import conditional
from coinflight.probability._runner import (
    Executor,
    Progress,
    check_count,
    check_tosses,
    executor_or_threads,
    run_tasks,
)
from coinflight.probability.registry import Estimator
from coinflight.probability.result import (
    Z95,
    ProbabilityResult,
    from_counts,
    sampled,
    wilson_interval,
)
from coinflight.probability.streams import (
    BLOCK,
    SeedLike,
    seed_sequence,
    unit_cube,
)

DEFAULT_CHUNK = BLOCK
"""Tosses per task: one block, so that a progress bar moves every ~2²⁰ tosses (~15 ms of
compute); larger tasks are no faster (``benchmarks/bench_probability.py`` times them)."""

NAME = "monte-carlo"
"""The method's name (its registry entry, results, messages)."""


def _task(args: tuple[Any, ...]) -> np.ndarray:
    model, dist, entropy, spawn_key, pool_size, first, last, n, cells = args
    root = np.random.SeedSequence(entropy, spawn_key=spawn_key, pool_size=pool_size)
    counts = np.zeros(3 + len(model.tallies), dtype=np.int64)
    k = len(dist.ranged)
    for u in unit_cube(root, n, k, first_block=first, last_block=last, cells=cells):
        counts += model.count(dist, u)
    return counts


CONDITIONAL_RATE = 4e6
"""Spins a second of the ``conditional-on-spin`` mode (closed form over T for each), 2-core
machine (benchmarks/bench_probability.py)."""


def _conditional_task(args: tuple[Any, ...]) -> np.ndarray:
    """Σ P(same | spins) and Σ P² over each block of the task, shape (blocks, 2)."""
    dist, entropy, spawn_key, pool_size, first, last, n = args
    root = np.random.SeedSequence(entropy, spawn_key=spawn_key, pool_size=pool_size)
    k = len(conditional.ranged_spins(dist))
    out = np.zeros((last - first, 2))
    for b in range(first, last):
        parts = []
        for u in unit_cube(root, n, k, first_block=b, last_block=b + 1):
            p = conditional.same_side_at(dist, u)
            parts.append((float(np.sum(p)), float(np.sum(p * p))))
        out[b - first] = [math.fsum(x for x, _ in parts), math.fsum(y for _, y in parts)]
    return out


def _conditional(
    dist: TossDistribution,
    n: int,
    root: np.random.SeedSequence,
    ex: Executor,
    per_task: int,
    progress: Progress | None,
) -> tuple[float, float]:
    """Mean and standard error of P(same | spins) over n random spins (blocks summed exactly,
    so that the answer does not depend on how blocks are grouped into tasks)."""
    n_blocks = math.ceil(n / BLOCK)
    tasks, sizes = [], []
    for first in range(0, n_blocks, per_task):
        last = min(n_blocks, first + per_task)
        tasks.append((dist, root.entropy, root.spawn_key, root.pool_size, first, last, n))
        sizes.append(min(n, last * BLOCK) - first * BLOCK)
    sums = np.concatenate(run_tasks(ex, _conditional_task, tasks, sizes, progress))
    mean = math.fsum(sums[:, 0]) / n
    second = math.fsum(sums[:, 1]) / n
    var = max(0.0, second - mean * mean) * n / max(1, n - 1)
    return mean, math.sqrt(var / n)


def check_work(
    n: int, model: OutcomeModel = HAND_CATCH, dist: TossDistribution | None = None
) -> None:
    """ValueError naming the time when ``n`` tosses of ``model`` exceed the run limit
    (:data:`coinflight._validation.MAX_RUN_SECONDS`, at ``model.rate_for(dist)`` tosses a
    second)."""
    check_tosses(NAME, check_count("n", n), model.rate_for(dist))


def estimate(
    dist: TossDistribution,
    n: int,
    seed: SeedLike = None,
    *,
    grid_cells: int | None = None,
    model: OutcomeModel = HAND_CATCH,
    executor: Executor | None = None,
    threads: int | None = None,
    chunk_size: int = DEFAULT_CHUNK,
    progress: Progress | None = None,
    variance_reduction: str | None = None,
) -> ProbabilityResult:
    """Monte Carlo estimate of P(heads) from ``n`` random tosses.

    Parameters
    ----------
    dist : TossDistribution
        The tosses.
    n : int
        Number of tosses (events).
    seed : int, optional
        Seed; the result reports it (drawn from the OS when None).
    grid_cells : int, optional
        None: draws from the continuous distributions. An integer: the paper's method B, each
        ranged parameter drawn among the midpoints of ``grid_cells`` equal-probability cells
        (Stefan & Cheche §3 use 100); the estimate then converges to that coarse grid's value.
    model : OutcomeModel
        How a toss ends (default: caught in the hand).
    executor : object with ``map``, optional
        Runs the tasks (default: a thread pool of ``threads`` workers).
    chunk_size : int
        Tosses per task, rounded up to whole blocks of :data:`BLOCK` (no effect on the result).
    progress : callable, optional
        Called with the number of tosses done as tasks finish.
    variance_reduction : {None, "conditional-on-spin"}
        ``"conditional-on-spin"``: draw the ``n`` spins only and average P(same side | spins)
        in closed form over the flight time (:mod:`coinflight.probability.conditional`); the
        hand catch only. The result says so in ``details["variance_reduction"]``.

    Notes
    -----
    Standard error sqrt(p(1 − p)/n); 95 % interval by Wilson's score method. Conditional on
    the spins: the standard error is the sample standard deviation of P(same | spins) over √n,
    the 95 % interval p ± 1.96 s.e.
    """
    t0 = time.perf_counter()
    n = check_count("n", n)
    chunk_size = check_count("chunk size", chunk_size)
    cells = 0 if grid_cells is None else check_count("grid cells", grid_cells)
    if variance_reduction is not None:
        return _estimate_conditional(
            dist, n, seed, grid_cells, model, executor, threads, chunk_size, progress, t0
        )
    check_work(n, model, dist)
    root = seed_sequence(seed)
    n_blocks = math.ceil(n / BLOCK)
    per_task = max(1, math.ceil(chunk_size / BLOCK))
    tasks = []
    sizes = []
    for first in range(0, n_blocks, per_task):
        last = min(n_blocks, first + per_task)
        tasks.append(
            (model, dist, root.entropy, root.spawn_key, root.pool_size, first, last, n, cells)
        )
        sizes.append(min(n, last * BLOCK) - first * BLOCK)
    with executor_or_threads(executor, threads) as ex:
        parts = run_tasks(ex, _task, tasks, sizes, progress)
    counts = np.sum(parts, axis=0)
    heads = int(counts[1])
    p = heads / n
    method_name = NAME
    details: dict[str, Any] = {"grid_cells": grid_cells, "block": BLOCK, "rng": "SFC64"}
    details.update(tally_details(model, counts))
    return from_counts(
        (int(counts[0]), heads, int(counts[2])),
        dist.start_sign,
        method_name,
        **sampled(n, math.sqrt(p * (1.0 - p) / n), wilson_interval(heads, n), root, t0),
        details=details,
    )


def _estimate_conditional(
    dist: TossDistribution,
    n: int,
    seed: SeedLike,
    grid_cells: int | None,
    model: OutcomeModel,
    executor: Executor | None,
    threads: int | None,
    chunk_size: int,
    progress: Progress | None,
    t0: float,
) -> ProbabilityResult:
    """The ``conditional-on-spin`` mode of :func:`estimate`."""
    conditional.check(dist, model, NAME, grid_cells)
    check_tosses(f"{NAME} ({conditional.MODE})", n, CONDITIONAL_RATE)
    root = seed_sequence(seed)
    with executor_or_threads(executor, threads) as ex:
        same, se = _conditional(dist, n, root, ex, max(1, math.ceil(chunk_size / BLOCK)), progress)
    return conditional.result(
        dist,
        same,
        se,
        Z95 * se,
        method=NAME,
        n=n,
        root=root,
        t0=t0,
        details={**conditional.details(dist), "block": BLOCK, "rng": "SFC64"},
    )


def _work(dist: TossDistribution, n: int, model: OutcomeModel = HAND_CATCH) -> float:
    check_work(n, model, dist)
    return n / model.rate_for(dist)


ESTIMATOR = Estimator(
    name=NAME,
    run=estimate,
    label="method B: random events (x = events)",
    description="N random tosses (with --grid-cells 100: the paper's method B)",
    default_n=lambda k: 10**6,
    size="tosses (default 1000000)",
    seeded=True,
    options=("grid_cells", "chunk_size", "variance_reduction"),
    work=_work,
    series=(100, 300, 1000, 3000, 10**4, 3 * 10**4, 10**5, 3 * 10**5, 10**6, 10**7),
    sizes_keyword="event_sizes",
    modes=(conditional.MODE,),
)
