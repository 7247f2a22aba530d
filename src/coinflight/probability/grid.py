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

from coinflight import _validation as v
from coinflight.model.ensemble import TossDistribution
from coinflight.outcomes.base import OutcomeModel, tally_details
from coinflight.outcomes.hand import HAND_CATCH
from coinflight.probability._runner import (
    Executor,
    Progress,
    check_count,
    executor_or_threads,
    run_tasks,
)
from coinflight.probability.registry import Estimator
from coinflight.probability.result import ProbabilityResult, from_counts

MAX_WORK = 8 * 10**8
"""Largest amount of work accepted, about a minute on the reference 2-core machine: the number
of configurations evaluated one by one (brute force, ~1.5e7 a second), or spin nodes × bands
per node (band counting, ~1.3e7 a second; measured in this module's docstring cases)."""
BAND_COUNTS_PER_SECOND = 1.3e7
CONFIGURATIONS_PER_SECOND = 1.5e7
DEFAULT_CELLS = 5000
"""Cells per ranged parameter by default with at most two ranged parameters (the paper's)."""
DEFAULT_CONFIGURATIONS = 10**8
"""With k > 2 ranged parameters the default n is the largest with n^k ≤ this."""
_CHUNK = 1 << 20

NAME = "grid"
"""The method's name (its registry entry, results, messages)."""


def midpoints(n: int) -> np.ndarray:
    """(i + ½)/n for i = 0 … n − 1: centres of n equal cells of [0, 1]."""
    return (np.arange(n) + 0.5) / n


def default_cells(k: int) -> int:
    """Default cells per parameter for k ranged parameters: :data:`DEFAULT_CELLS` for k ≤ 2,
    else the largest n with n^k ≤ :data:`DEFAULT_CONFIGURATIONS` (464 for k = 3, 100 for 4)."""
    if k <= 2:
        return DEFAULT_CELLS
    n = round(DEFAULT_CONFIGURATIONS ** (1.0 / k))
    while n**k > DEFAULT_CONFIGURATIONS:
        n -= 1
    while (n + 1) ** k <= DEFAULT_CONFIGURATIONS:
        n += 1
    return n


_WAY_ON = "use a smaller n, or --method monte-carlo or qmc (or exact where it applies)"
MAX_NODE_BYTES = 2**30
"""Largest memory for band counting's nodes, bytes: n floats per ranged spin, plus the flight
time's n nodes in each of two concurrent tasks (1 GiB: n ≤ 4.5e7 with the flight time alone
ranged). Brute force builds its configurations chunk by chunk (no O(n) array)."""
_SAMPLE = 4096
"""Nodes sampled to estimate the mean square of a spin (for the work bound, not the count)."""


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


def _bands_per_node(dist: TossDistribution, spin_names: tuple[str, ...], n: int) -> float:
    """Typical number of bands a spin node's flight-time range meets (for the work limit).

    ωp ≤ sqrt(ωx² + ωy² + (I3/I1 ωz)²); its root mean square over the product grid is the
    square root of the summed mean squares, each taken over ≤ :data:`_SAMPLE` midpoints (no
    O(n) array). Each node meets about ωp ΔT / 2π + 2 bands, ΔT between the outer time nodes.
    """
    i1, i3 = dist.moments
    weight = {"omega_x": 1.0, "omega_y": 1.0, "omega_z": (i3 / i1) ** 2}
    mean_square = 0.0
    for name in weight:
        if name in spin_names:
            values = getattr(dist, name).ppf(midpoints(min(n, _SAMPLE)))
            mean_square += weight[name] * float(np.mean(np.square(values)))
        else:
            mean_square += weight[name] * getattr(dist, name).mean ** 2
    first, last = dist.flight_time.ppf(np.array([0.5 / n, 1.0 - 0.5 / n]))
    return float(np.sqrt(mean_square)) * float(last - first) / (2.0 * np.pi) + 2.0


def check_work(dist: TossDistribution, n: int, model: OutcomeModel = HAND_CATCH) -> float:
    """ValueError (:func:`coinflight._validation.work_bound`) when the grid of ``n`` cells per
    parameter needs more than :data:`MAX_NODE_BYTES` of nodes or more work than :data:`MAX_WORK`
    (brute force with a slower outcome model: at most an hour of its tosses).

    O(1) time and memory: callers running several grids (convergence) check them all first.
    Returns the estimated time, s on the reference machine.
    """
    n = check_count("n", n)
    ranged = dist.ranged
    k = len(ranged)
    total = n**k
    spin_names = tuple(name for name in ranged if name != "flight_time")
    if model.closed_form_bands and "flight_time" in ranged:
        v.work_bound(
            f"a grid of n = {n} cells per parameter",
            8 * n * (len(spin_names) + 2),
            MAX_NODE_BYTES,
            "bytes of nodes",
            _WAY_ON,
        )
        combos = n ** len(spin_names)
        bands = _bands_per_node(dist, spin_names, n)
        v.work_bound(
            f"a grid of {n}^{k} = {v.quantity(total)} configurations ({v.quantity(combos)} spin "
            f"nodes × ~{v.quantity(bands)} bands each)",
            combos * bands,
            MAX_WORK,
            "band counts",
            _WAY_ON,
            BAND_COUNTS_PER_SECOND,
        )
        return combos * bands / BAND_COUNTS_PER_SECOND
    else:
        v.work_bound(
            f"a grid of {n}^{k} = {v.quantity(total)} configurations, each evaluated one by one "
            "(fast band counting needs a ranged flight time and the hand catch)",
            total,
            min(MAX_WORK, model.rate_for(dist) * v.MAX_RUN_SECONDS),
            "configurations",
            _WAY_ON,
            min(CONFIGURATIONS_PER_SECOND, model.rate_for(dist)),
        )
    return total / min(CONFIGURATIONS_PER_SECOND, model.rate_for(dist))


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

    Raises
    ------
    ValueError
        When the work exceeds :data:`MAX_WORK` (about a minute).

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
    fast = model.closed_form_bands and "flight_time" in ranged
    check_work(dist, n, model)
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
        tallies = {}
        how = "band counting along the flight time"
    else:
        tasks2 = [
            (model, dist, k, n, a, min(total, a + _CHUNK)) for a in range(0, max(total, 1), _CHUNK)
        ]
        sizes = [b - a for (*_, a, b) in tasks2]
        with executor_or_threads(executor, threads) as ex:
            parts = run_tasks(ex, _brute_task, tasks2, sizes, progress)
        c = np.sum(parts, axis=0)
        counts = (int(c[0]), int(c[1]), int(c[2]))
        tallies = tally_details(model, c)
        how = "every configuration evaluated"
    return from_counts(
        counts,
        dist.start_sign,
        NAME,
        n=n,
        samples=total,
        elapsed=time.perf_counter() - t0,
        details={"cells_per_parameter": n, "ranged": list(ranged), "how": how, **tallies},
    )


__all__ = ["check_work", "default_cells", "estimate", "midpoints"]


ESTIMATOR = Estimator(
    name=NAME,
    run=estimate,
    label="method A: grid (x = configurations)",
    description="the paper's method A (N cells per ranged parameter)",
    default_n=default_cells,
    size="cells per ranged parameter (default 5000 with up to 2 ranged parameters, else the "
    "largest N with N^k ≤ 10^8)",
    work=check_work,
    work_units=lambda k, n: n**k,
    series=(5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000),  # up to the paper's 5000
)
