"""Randomised quasi-Monte Carlo: scrambled Sobol points (SciPy) with a randomised error estimate.

R independent scramblings (default 16), each of 2^m points; the estimate is the mean over the
scramblings and its standard error their standard deviation over √R (Owen 1997; L'Ecuyer &
Lemieux 2002). Scrambling r is seeded by child r of the seed's ``SeedSequence``
(:func:`coinflight.probability.streams.generator`).
"""

from __future__ import annotations

import math
import time
from collections.abc import Iterator
from typing import Any

import numpy as np

from coinflight import _validation as v
from coinflight.model.ensemble import TossDistribution
from coinflight.outcomes.base import OutcomeModel, tally_details
from coinflight.outcomes.hand import HAND_CATCH
from coinflight.probability import _runner, conditional
from coinflight.probability._runner import Executor, Progress, check_count
from coinflight.probability.registry import Estimator
from coinflight.probability.result import ProbabilityResult, from_counts, interval, sampled
from coinflight.probability.streams import SeedLike, generator, seed_sequence

DEFAULT_REPLICATES = 16
MAX_REPLICATES = 1024
"""Most scramblings: each is a task with its own seed and Sobol engine (2^30 of them would build
a billion before a point is drawn); 16 already give the error estimate (Owen 1997)."""
SOBOL_BITS = 30
"""Bits of SciPy's Sobol generator (its default): at most 2^30 points per scrambling."""
SOBOL_POINTS_PER_SECOND = 2.5e7
"""Scrambled Sobol points a second (SciPy) on the reference 2-core machine, on top of the
outcome model's own time (with the hand catch about half of all the time)."""
_CHUNK = 1 << 18
BLOCK = 1 << 22
"""Points of one scrambling per task (a power of two): the task resumes the scrambling's
sequence where the one before ended (``Sobol.fast_forward``), so the points are those of one
run whatever the blocks, and a progress bar moves every 2^22 points (about a third of a
second on the 2-core machine) instead of once per scrambling (minutes at n = 2^34)."""

NAME = "qmc"
"""The method's name (its registry entry, results, messages)."""


def _sobol(
    k: int, root: np.random.SeedSequence, replicate: int, points: int, start: int = 0
) -> Iterator[Any]:
    """Scrambling ``replicate``'s Sobol points ``start`` to ``start + points`` in k dimensions,
    in chunks of powers of two (which keep Sobol's balance, and SciPy's warning, in check),
    each as a contiguous (k, size) array."""
    from scipy.stats import qmc

    sobol = qmc.Sobol(
        d=k, scramble=True, seed=generator(root, replicate, bit_generator=np.random.PCG64)
    )
    if start:
        sobol.fast_forward(start)
    done = 0
    while done < points:
        size = min(_CHUNK, points - done)
        yield np.ascontiguousarray(sobol.random(size).T)
        done += size


def _task(args: tuple[Any, ...]) -> np.ndarray:
    model, dist, root, replicate, start, points = args
    k = len(dist.ranged)
    counts = np.zeros(3 + len(model.tallies), dtype=np.int64)
    if k == 0:
        return model.count(dist, np.zeros((0, points)))
    for u in _sobol(k, root, replicate, points, start):
        counts += model.count(dist, u)
    return counts


def _conditional_task(args: tuple[Any, ...]) -> float:
    """The mean of P(same | spins) over one scrambling's points (spins only)."""
    dist, root, replicate, points = args
    k = len(conditional.ranged_spins(dist))
    if k == 0:
        wx, wy, wz = (np.full(1, getattr(dist, n).mean) for n in conditional.SPINS)
        return float(conditional.same_side_given_spins(dist, wx, wy, wz)[0])
    chunks = _sobol(k, root, replicate, points)
    sums = [float(np.sum(conditional.same_side_at(dist, u))) for u in chunks]
    return math.fsum(sums) / points


def _spread(per: np.ndarray) -> tuple[float, float]:
    """Standard error of the mean over the scramblings' estimates ``per`` and the half-width
    of its 95 % Student t interval (Owen 1997; L'Ecuyer & Lemieux 2002)."""
    from scipy.stats import t as student_t

    stderr = float(np.std(per, ddof=1) / math.sqrt(len(per)))
    return stderr, float(student_t.ppf(0.975, len(per) - 1)) * stderr


def check_work(
    n: int,
    replicates: int = DEFAULT_REPLICATES,
    model: OutcomeModel = HAND_CATCH,
    dist: TossDistribution | None = None,
) -> None:
    """ValueError unless ``n`` is ``replicates`` × a power of two, its points fit Sobol's
    :data:`SOBOL_BITS` bits per scrambling and the run limit
    (:data:`coinflight._validation.MAX_RUN_SECONDS`); nothing is allocated."""
    n = check_count("n", n)
    replicates = v.count("replicates", replicates, 2, MAX_REPLICATES)
    points = n // replicates
    if n % replicates or points & (points - 1):
        below = replicates * 2 ** max(0, math.floor(math.log2(max(1, n // replicates))))
        raise ValueError(
            f"qmc needs n = {replicates} replicates × a power of two, got n = {n}; "
            f"try {below} or {2 * below}"
        )
    v.work_bound(
        f"qmc with n = {n} in {replicates} scramblings",
        n // replicates,
        2**SOBOL_BITS,
        "points per scrambling",
        f"SciPy's Sobol sequence has {SOBOL_BITS} bits; use n ≤ {replicates} × 2^{SOBOL_BITS} "
        f"= {replicates << SOBOL_BITS}",
    )
    _runner.check_tosses(NAME, n, rate(model, dist), "use a smaller n (16 × a power of two)")


def rate(model: OutcomeModel = HAND_CATCH, dist: TossDistribution | None = None) -> float:
    """Points a second: the model's tosses (of ``dist``) and SciPy's scrambled Sobol points
    together."""
    return 1.0 / (1.0 / model.rate_for(dist) + 1.0 / SOBOL_POINTS_PER_SECOND)


def estimate(
    dist: TossDistribution,
    n: int,
    seed: SeedLike = None,
    *,
    replicates: int = DEFAULT_REPLICATES,
    model: OutcomeModel = HAND_CATCH,
    executor: Executor | None = None,
    threads: int | None = None,
    progress: Progress | None = None,
    variance_reduction: str | None = None,
) -> ProbabilityResult:
    """Scrambled-Sobol estimate of P(heads) from ``n`` points in ``replicates`` scramblings.

    ``n`` must be ``replicates`` × a power of two (Sobol points keep their balance only in
    powers of two); the error message names the nearest valid values otherwise. With
    ``variance_reduction="conditional-on-spin"`` the points are spins only and each carries
    P(same side | spins) in closed form over the flight time
    (:mod:`coinflight.probability.conditional`; hand catch only): a smooth integrand but at
    ψ = 45°, where scrambled Sobol points converge much faster than on the 0/1 outcome.
    """
    t0 = time.perf_counter()
    n = check_count("n", n)
    replicates = v.count("replicates", replicates, 2, MAX_REPLICATES)
    check_work(n, replicates, model, dist)
    points = n // replicates
    root = seed_sequence(seed)
    if variance_reduction is not None:
        return _estimate_conditional(
            dist, n, replicates, points, root, model, executor, threads, progress, t0
        )
    block = min(points, BLOCK)
    starts = range(0, points, block)
    tasks = [(model, dist, root, r, start, block) for r in range(replicates) for start in starts]
    with _runner.executor_or_threads(executor, threads) as ex:
        blocks = _runner.run_tasks(ex, _task, tasks, [block] * len(tasks), progress)
    # Each scrambling's counts: the sum of its blocks (in task order).
    parts = [np.sum(blocks[i : i + len(starts)], axis=0) for i in range(0, len(tasks), len(starts))]
    counts = np.sum(parts, axis=0)
    col = 1
    per = np.array([p[col] / points for p in parts])
    stderr, half = _spread(per)
    p = float(per.mean())
    return from_counts(
        (int(counts[0]), int(counts[1]), int(counts[2])),
        dist.start_sign,
        NAME,
        **sampled(n, stderr, interval(p, half), root, t0),
        details={
            "replicates": replicates,
            "points_per_replicate": points,
            **tally_details(model, counts),
        },
    )


def _estimate_conditional(
    dist: TossDistribution,
    n: int,
    replicates: int,
    points: int,
    root: np.random.SeedSequence,
    model: OutcomeModel,
    executor: Executor | None,
    threads: int | None,
    progress: Progress | None,
    t0: float,
) -> ProbabilityResult:
    """The ``conditional-on-spin`` mode of :func:`estimate`."""
    conditional.check(dist, model, NAME)
    tasks = [(dist, root, r, points) for r in range(replicates)]
    with _runner.executor_or_threads(executor, threads) as ex:
        per = np.array(
            _runner.run_tasks(ex, _conditional_task, tasks, [points] * replicates, progress)
        )
    stderr, half = _spread(per)
    return conditional.result(
        dist,
        math.fsum(per) / replicates,
        stderr,
        half,
        method=NAME,
        n=n,
        root=root,
        t0=t0,
        details={
            "replicates": replicates,
            "points_per_replicate": points,
            **conditional.details(dist),
        },
    )


def _work(dist: TossDistribution, n: int, model: OutcomeModel = HAND_CATCH) -> float:
    check_work(n, model=model, dist=dist)
    return n / rate(model, dist)


ESTIMATOR = Estimator(
    name=NAME,
    run=estimate,
    label="scrambled Sobol (x = points)",
    description="scrambled Sobol points",
    default_n=lambda k: 1 << 20,
    size="points, 16 × a power of two (default 1048576)",
    seeded=True,
    options=("replicates", "variance_reduction"),
    work=_work,
    series=tuple(16 << k for k in range(2, 17)),
    modes=(conditional.MODE,),
)
