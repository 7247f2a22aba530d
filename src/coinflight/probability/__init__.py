"""Probability of heads over a distribution of tosses: one entry point, four methods.

>>> from coinflight.model.distributions import Uniform
>>> from coinflight.model.ensemble import TossDistribution
>>> d = TossDistribution(Uniform(60, 90), 0, 0, Uniform(0.6, 0.9))  # Stefan & Cheche Fig 2a
>>> round(estimate(d, "exact").p_heads, 6)
0.497471

Methods (one module each, declared once in :mod:`coinflight.probability.registry`):

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
from coinflight.outcomes.base import OutcomeModel
from coinflight.outcomes.hand import HAND_CATCH
from coinflight.probability import registry
from coinflight.probability.result import ProbabilityResult, wilson_interval
from coinflight.probability.sweep import ProbabilityResults, estimate_many

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
    method : str
        A name of :func:`coinflight.probability.registry.names` (built in: exact, grid,
        monte-carlo, qmc).
    n : int
        Size: cells per ranged parameter (grid, default 5000 for up to two ranged parameters,
        else the largest n with n^k ≤ 10⁸), tosses (monte-carlo, default
        10⁶), points (qmc, default 2²⁰). Not used by exact.
    seed : int or SeedSequence, optional
        For the seeded methods (monte-carlo, qmc); None draws a fresh one from the OS, and the
        result reports it either way. A TypeError for exact and grid.
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
    estimator = registry.get(method)
    v.instance("model", model, OutcomeModel, "an OutcomeModel (HandCatch, TableLanding)")
    return estimator(
        dist,
        n,
        seed,
        model=model,
        executor=executor,
        threads=threads,
        progress=progress,
        **options,
    )


def __getattr__(name: str) -> Any:
    if name == "METHODS":  # read at each use, so that registered estimators appear
        return registry.names()
    if name == "convergence":
        from coinflight.probability.convergence import convergence

        return convergence
    raise AttributeError(name)


__all__ = [
    "METHODS",
    "PAPER_B_CELLS",
    "ProbabilityResult",
    "ProbabilityResults",
    "convergence",
    "estimate",
    "estimate_many",
    "wilson_interval",
]
