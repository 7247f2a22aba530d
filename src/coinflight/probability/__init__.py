"""Probability of heads over a distribution of tosses: one entry point, four methods.

>>> from coinflight.model.distributions import Uniform
>>> from coinflight.model.ensemble import TossDistribution
>>> d = TossDistribution(Uniform(60, 90), 0, 0, Uniform(0.6, 0.9))  # Stefan & Cheche Fig 2a
>>> round(estimate(d, "exact").p_heads, 6)
0.497471

Methods (one module each):

``exact``
    Integrates the measure of the heads bands (Keller 1986; REFERENCES §3).
``grid``
    Method A of Stefan & Cheche: ``n`` cells per ranged parameter, an exact count.
``monte-carlo``
    ``n`` random tosses; with ``grid_cells=100`` the paper's method B (random draws from a coarse
    grid of 100 cells per parameter).
``qmc``
    Scrambled Sobol points with a randomised error estimate.

:func:`estimate_many` runs one method over a list of distributions (a sweep).
"""

from __future__ import annotations

from typing import Any

from coinflight import _validation as v
from coinflight.model.ensemble import TossDistribution
from coinflight.outcomes.base import HAND_CATCH, HandCatch, OutcomeModel
from coinflight.probability._runner import check_count, check_runner
from coinflight.probability.result import ProbabilityResult, wilson_interval
from coinflight.probability.sweep import ProbabilityResults, estimate_many

METHODS = ("exact", "grid", "monte-carlo", "qmc")
PAPER_B_CELLS = 100
"""Cells per parameter of the paper's method B (Stefan & Cheche §3)."""


def estimate(
    dist: TossDistribution,
    method: str = "exact",
    n: int | None = None,
    seed: int | None = None,
    *,
    model: OutcomeModel = HAND_CATCH,
    executor: Any = None,
    threads: int | None = None,
    progress: Any = None,
    **options: Any,
) -> ProbabilityResult:
    """P(heads) for the tosses ``dist`` by ``method``; see the module notes.

    Parameters
    ----------
    dist : TossDistribution
        The tosses.
    method : {"exact", "grid", "monte-carlo", "qmc"}
    n : int
        Size: cells per ranged parameter (grid, default 5000 for up to two ranged parameters,
        else the largest n with n^k ≤ 10⁸), tosses (monte-carlo, default
        10⁶), points (qmc, default 2²⁰). Not used by exact.
    seed : int, optional
        For monte-carlo and qmc; reported in the result. A TypeError for exact and grid.
    model : OutcomeModel
        How a toss ends (default: caught in the hand).
    executor : object with ``map``, optional
        Runs the independent tasks (default: a thread pool). Not for exact (TypeError).
    threads : int, optional
        Workers of the default thread pool. Not for exact (TypeError).
    progress : callable, optional
        Called with the amount of work done as tasks finish. Not for exact (TypeError).
    **options
        ``grid_cells`` (monte-carlo), ``replicates`` (qmc), ``chunk_size`` (monte-carlo).
    """
    v.instance("dist", dist, TossDistribution, "a TossDistribution")
    v.instance("method", method, str, f"a string, one of {', '.join(METHODS)}")
    if method not in METHODS:
        raise ValueError(f"unknown method {method!r}; choose one of {', '.join(METHODS)}")
    v.instance("model", model, OutcomeModel, "an OutcomeModel (HandCatch, TableLanding)")
    if n is not None:
        check_count("n", n)
    if method in ("exact", "grid") and seed is not None:
        raise TypeError(f"method {method!r} takes no seed (it is deterministic); got seed={seed}")
    if method == "exact":
        if n is not None:
            raise ValueError("the exact method takes no n")
        given = {"executor": executor, "threads": threads, "progress": progress}
        _no_options(method, {k: v for k, v in given.items() if v is not None})
        _no_options(method, options)
        from coinflight.probability import exact

        return exact.estimate(dist, model=model)
    check_runner(executor, threads, progress)
    common: dict[str, Any] = {
        "model": model,
        "executor": executor,
        "threads": threads,
        "progress": progress,
    }
    if method == "grid":
        _no_options(method, options)
        from coinflight.probability import grid

        return grid.estimate(
            dist, grid.default_cells(len(dist.ranged)) if n is None else n, **common
        )
    if method == "monte-carlo":
        _no_options(method, options, ("grid_cells", "chunk_size"))
        from coinflight.probability import monte_carlo

        return monte_carlo.estimate(dist, 10**6 if n is None else n, seed, **common, **options)
    _no_options(method, options, ("replicates",))
    from coinflight.probability import qmc

    return qmc.estimate(dist, 1 << 20 if n is None else n, seed, **common, **options)


def _no_options(method: str, options: dict[str, Any], allowed: tuple[str, ...] = ()) -> None:
    extra = [k for k in options if k not in allowed]
    if extra:
        raise TypeError(f"method {method!r} takes no option {', '.join(extra)}")


def __getattr__(name: str) -> Any:
    if name == "convergence":
        from coinflight.probability.convergence import convergence

        return convergence
    raise AttributeError(name)


__all__ = [
    "METHODS",
    "PAPER_B_CELLS",
    "HandCatch",
    "OutcomeModel",
    "ProbabilityResult",
    "ProbabilityResults",
    "TossDistribution",
    "convergence",
    "estimate",
    "estimate_many",
    "wilson_interval",
]
