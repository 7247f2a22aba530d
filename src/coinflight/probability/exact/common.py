"""What the exact integrals share: the tolerance, the wording of a refusal, the spin densities."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from coinflight import _validation as v
from coinflight.model.distributions import Distribution, Normal, Uniform

TOLERANCE = 1e-9
"""Absolute and relative tolerance asked of the quadrature: 1e-9, the accuracy the exact method
promises. (1e-10 is beyond what round-off in the band sums allows for normal distributions:
QUADPACK then warns and takes twice as long.)"""
_SPINS = ("omega_x", "omega_y", "omega_z")
_USE_INSTEAD = "use --method grid, monte-carlo or qmc instead"
_Details = dict[str, Any]
_NORMAL_SPAN = 9.0
"""A normal spin is integrated over mean ± 9 sd (all but 2e-19 of its mass)."""


def _pdf(d: Distribution, x: np.ndarray) -> np.ndarray:
    """Density of a uniform or normal spin distribution at ``x``."""
    if isinstance(d, Uniform):
        return np.where((x >= d.low) & (x <= d.high), 1.0 / (d.high - d.low), 0.0)
    assert isinstance(d, Normal)
    z = (x - d.mean) / d.sd
    return np.exp(-0.5 * z * z) / (d.sd * math.sqrt(2.0 * math.pi))


def _support(d: Distribution) -> tuple[float, float]:
    """Where a spin's mass lies: a uniform's range, a normal's mean ± 9 sd."""
    if isinstance(d, Uniform):
        return d.low, d.high
    assert isinstance(d, Normal)
    return d.mean - _NORMAL_SPAN * d.sd, d.mean + _NORMAL_SPAN * d.sd


def _normal_marks(d: Normal) -> np.ndarray:
    """Where a normal spin's density changes pace: its support's ends (mean ± 9 sd), mean ± 3
    sd and its mean, in increasing order."""
    return d.mean + d.sd * np.array([-_NORMAL_SPAN, -3.0, 0.0, 3.0, _NORMAL_SPAN])


def _by_orders(
    rule: str,
    ranged: int,
    orders: tuple[int, ...],
    points: Callable[[int], int],
    integral: Callable[[int], float],
    limits: tuple[float, float],
    unit: str,
    rate: float,
    details: _Details,
) -> tuple[float, float]:
    """(value, error) of a rule with ``n`` nodes a panel, ``n`` each of ``orders`` in turn,
    until two in a row agree within :data:`TOLERANCE` (their difference is the error estimate,
    not below the rounding of the sums); a ValueError when none do.

    ``rule`` names the rule in the refusals (with its ``ranged`` spins), ``points(n)`` is the work
    of order ``n`` in ``unit`` (reported in ``details`` with the nodes a panel), ``integral(n)``
    its value. The work is bounded before anything is computed: the first two orders' (no
    answer without both) by ``limits[0]``, the sum of all orders so far, before each order's
    nodes are allocated, by ``limits[1]`` (refused rather than loosened), at ``rate`` points a
    second.
    """
    what = f"{rule} over {ranged} ranged spins"
    v.work_bound(what, sum(points(n) for n in orders[:2]), limits[0], unit, _USE_INSTEAD, rate=rate)
    previous, previous_n, change, used = math.nan, 0, math.nan, 0
    for n in orders:
        order_points = points(n)
        where = what + (
            f" (at {previous_n} nodes a panel {change:.2g} from the order before), "
            f"to {n} nodes a panel,"
            if math.isfinite(change)
            else ""
        )
        v.work_bound(where, used + order_points, limits[1], unit, _USE_INSTEAD, rate=rate)
        used += order_points
        value = integral(n)
        change = abs(value - previous)
        if change <= TOLERANCE:
            details["nodes per panel"] = n
            details[unit] = used
            return value, max(change, 4e-16 * math.sqrt(max(order_points, 1)))
        previous, previous_n = value, n
    raise ValueError(
        f"{rule} did not reach its tolerance {TOLERANCE:g} with {orders[-1]} "
        f"nodes per panel (last change {change:.2g}); {_USE_INSTEAD}"
    )
