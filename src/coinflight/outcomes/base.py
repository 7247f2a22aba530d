"""Where a batch of initial conditions becomes counts of faces: the one function boundary.

Every estimator asks an :class:`OutcomeModel` to count the faces of a batch of tosses given as
points of the unit cube (mapped to initial conditions by the distribution's ``ppf``). The hand
catch of the founding paper is :class:`HandCatch`; a landing on a table (bounces, edge) plugs in
by subclassing :class:`OutcomeModel` and overriding :meth:`OutcomeModel.count`.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from coinflight.model.ensemble import PARAMETERS, TossDistribution

Counts = NDArray[np.int64]
"""(tails, heads, edge) counts, shape (3,), followed by the model's extra tallies if any."""


def faces_from_same_side(same: int, n: int, start_sign: float) -> Counts:
    """(tails, heads, edge) from the number of tosses that show the starting face."""
    heads = same if start_sign > 0 else n - same
    return np.array([n - heads, heads, 0], dtype=np.int64)


class OutcomeModel:
    """Counts faces for batches of tosses. Subclasses override :meth:`count`."""

    name = "outcome model"
    tallies: tuple[str, ...] = ()
    """Names of extra counts :meth:`count` returns after (tails, heads, edge), e.g.
    ``("unsettled",)`` for tosses a landing model could not settle (their faces are still
    counted). The estimators add them up and report them in ``details`` (count and fraction)."""
    rate: float = 1e5
    """Tosses a second on the reference 2-core machine, all threads: the estimators' work
    bounds (:func:`coinflight.probability.monte_carlo.check_work` …) turn a size into a time
    with it. Subclasses state their own measured rate."""

    def count(self, dist: TossDistribution, u: NDArray[np.float64]) -> Counts:
        """Face counts for unit-cube points ``u``, shape (len(dist.ranged), n).

        Returns (tails, heads, edge, *tallies), shape (3 + len(:attr:`tallies`),).

        Row r of ``u`` drives parameter ``dist.ranged[r]`` through its distribution's ``ppf``
        (:meth:`~coinflight.model.ensemble.TossDistribution.values`).
        """
        raise NotImplementedError


class HandCatch(OutcomeModel):
    """Caught in the hand at launch height: the face is the sign of n(T)·n0 (Stefan & Cheche)."""

    name = "hand catch"
    rate = 2.5e7
    """Measured: Monte Carlo, 10⁸ tosses of ω_x 60-90 rad/s, T 0.6-0.9 s in 4.2 s on the 2-core
    machine shared with other jobs (benchmarks/bench_probability.py measures it quietly)."""

    def count(self, dist: TossDistribution, u: NDArray[np.float64]) -> Counts:
        from coinflight.core import sampling

        n = u.shape[1]
        i1, i3 = dist.moments
        maps = _affine_maps(dist)
        if maps is not None:
            offset, scale = maps
            if dist.ranged == PARAMETERS and u.flags.c_contiguous:
                rows = u
            else:  # parameter-major and contiguous, so that the kernel vectorises
                rows = np.zeros((4, n))
                rows[[PARAMETERS.index(name) for name in dist.ranged]] = u
            same = sampling.count_same_side_affine(rows, offset, scale, i1, i3)
        else:
            wx, wy, wz, t = dist.values(u)
            same = sampling.count_same_side(wx, wy, wz, t, i1, i3)
        return faces_from_same_side(int(same), n, dist.start_sign)


def tally_details(model: OutcomeModel, counts: NDArray[np.int64]) -> dict[str, float]:
    """``{name: count, name_fraction: count / tosses}`` for the model's extra tallies."""
    n = int(np.sum(counts[:3]))
    out: dict[str, float] = {}
    for name, c in zip(model.tallies, counts[3:], strict=True):
        out[name] = int(c)
        out[f"{name}_fraction"] = int(c) / n if n else 0.0
    return out


def _affine_maps(
    dist: TossDistribution,
) -> tuple[NDArray[np.float64], NDArray[np.float64]] | None:
    """(offset, scale) per parameter when every parameter maps affinely from [0, 1]."""
    offset = np.empty(4)
    scale = np.empty(4)
    for p, name in enumerate(PARAMETERS):
        affine = getattr(dist, name).affine
        if affine is None:
            return None
        offset[p], scale[p] = affine
    return offset, scale


HAND_CATCH = HandCatch()
