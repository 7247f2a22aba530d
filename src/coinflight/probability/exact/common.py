"""What the exact integrals share: the tolerance, the wording of a refusal, the spin densities."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

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
