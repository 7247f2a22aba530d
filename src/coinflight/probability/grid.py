"""Method A of Stefan & Cheche: N cells per ranged parameter, probability = favourable / total.

The configurations are the midpoints of N equal-probability cells per ranged parameter,
u_i = (i + ½)/N mapped through the parameter's ppf (for a uniform range: the paper's midpoints).
The result is an exact count for that grid, not a sample.

Speed: when the flight time is ranged, the time nodes are never visited one by one.
For each spin node the starting face shows iff ωp T falls in bands (2πm − a, 2πm + a)
(:func:`coinflight.core.sampling.count_same_side_time_bands`), so the nodes in each band are
counted with floor/ceil: O(N^(k−1) × bands) work instead of N^k. Otherwise, every
configuration is evaluated (compiled brute force).
"""

from __future__ import annotations

import time
from typing import Any

import numpy as np

from coinflight.ensemble import TossDistribution
from coinflight.probability._runner import (
    Executor,
    Progress,
    check_count,
    executor_or_threads,
    run_tasks,
)
from coinflight.probability.outcome import HAND_CATCH, HandCatch, OutcomeModel
from coinflight.probability.result import ProbabilityResult, from_counts

MAX_BRUTE_FORCE = 10**12
"""Largest number of configurations evaluated one by one (about an hour of compute)."""
_CHUNK = 1 << 20


def midpoints(n: int) -> np.ndarray:
    """(i + ½)/n for i = 0 … n − 1: centres of n equal cells of [0, 1]."""
    return (np.arange(n) + 0.5) / n


def _band_task(args: tuple[Any, ...]) -> int:
    from coinflight.core import sampling

    dist, spin_nodes, spin_names, first, last, n = args
    shape = tuple(len(nodes) for nodes in spin_nodes)
    idx = np.unravel_index(np.arange(first, last), shape) if shape else ()
    spins = {}
    for name in ("omega_x", "omega_y", "omega_z"):
        if name in spin_names:
            k = spin_names.index(name)
            spins[name] = np.ascontiguousarray(spin_nodes[k][idx[k]])
        else:
            spins[name] = np.full(last - first, getattr(dist, name).mean)
    i1, i3 = dist.moments
    t_nodes = np.ascontiguousarray(dist.flight_time.ppf(midpoints(n)), dtype=float)
    return int(
        sampling.count_same_side_time_bands(
            spins["omega_x"], spins["omega_y"], spins["omega_z"], t_nodes, i1, i3
        )
    )


def _brute_task(args: tuple[Any, ...]) -> np.ndarray:
    model, dist, k, n, first, last = args
    if k == 0:
        return model.count(dist, np.zeros((0, last - first)))
    idx = np.unravel_index(np.arange(first, last), (n,) * k)
    return model.count(dist, np.stack([(i + 0.5) / n for i in idx]))


def estimate(
    dist: TossDistribution,
    n: int,
    *,
    model: OutcomeModel = HAND_CATCH,
    executor: Executor | None = None,
    threads: int | None = None,
    progress: Progress | None = None,
) -> ProbabilityResult:
    """Method A: exact fraction of heads over the grid of N^k cell midpoints.

    Parameters
    ----------
    dist : TossDistribution
        The tosses; k = ``len(dist.ranged)`` parameters vary.
    n : int
        Cells per ranged parameter (the paper: 5000, so 5000² configurations).

    Notes
    -----
    Stefan & Cheche §3, method A. Band structure: Keller (1986); Diaconis, Holmes & Montgomery
    (2007) for the precessing coin.
    """
    t0 = time.perf_counter()
    n = check_count("n", n)
    ranged = dist.ranged
    k = len(ranged)
    total = n**k
    spin_names = tuple(name for name in ranged if name != "flight_time")
    fast = isinstance(model, HandCatch) and "flight_time" in ranged
    if fast:
        spin_nodes = [getattr(dist, name).ppf(midpoints(n)) for name in spin_names]
        combos = n ** len(spin_names)
        tasks = [
            (dist, spin_nodes, spin_names, a, min(combos, a + _CHUNK), n)
            for a in range(0, combos, _CHUNK)
        ]
        sizes = [(b - a) * n for (_, _, _, a, b, _) in tasks]
        with executor_or_threads(executor, threads) as ex:
            same = sum(run_tasks(ex, _band_task, tasks, sizes, progress))
        heads = same if dist.start_sign > 0 else total - same
        counts = (total - heads, heads, 0)
        how = "band counting along the flight time"
    else:
        if total > MAX_BRUTE_FORCE:
            raise ValueError(
                f"a grid of {n}^{k} = {total:.3g} configurations is too large to evaluate one by "
                "one (fast counting needs a ranged flight time); use a smaller n, or "
                "--method monte-carlo or qmc"
            )
        tasks2 = [
            (model, dist, k, n, a, min(total, a + _CHUNK)) for a in range(0, max(total, 1), _CHUNK)
        ]
        sizes = [b - a for (*_, a, b) in tasks2]
        with executor_or_threads(executor, threads) as ex:
            parts = run_tasks(ex, _brute_task, tasks2, sizes, progress)
        c = np.sum(parts, axis=0)
        counts = (int(c[0]), int(c[1]), int(c[2]))
        how = "every configuration evaluated"
    return from_counts(
        counts,
        dist.start_sign,
        "grid",
        n=n,
        samples=total,
        elapsed=time.perf_counter() - t0,
        details={"cells_per_parameter": n, "ranged": list(ranged), "how": how},
    )


__all__ = ["estimate", "midpoints"]
