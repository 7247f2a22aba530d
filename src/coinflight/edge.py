"""Thick coins: the probability of landing on edge as a function of thickness / diameter.

Two closed-form models of Yong & Mahadevan (2011, "Probability, geometry, and dynamics in the
tossing of thin disks", Am. J. Phys. 79:1195, arXiv:1008.4559; REFERENCES §5), and the root
finding that gives the ratio h/d for a chosen P(edge) (1/3 for a fair "three-sided coin").
The simulated P(edge) of real bounces comes from :mod:`coinflight.landing`.
"""

from __future__ import annotations

from typing import Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from coinflight import _validation as v

EdgeModel = Literal["geometric", "dynamic"]
MODELS: tuple[EdgeModel, ...] = ("geometric", "dynamic")


def edge_probability(ratio: ArrayLike, model: EdgeModel = "dynamic") -> NDArray[np.float64]:
    """P(edge) of a coin of thickness / diameter ``ratio`` = h/d.

    Parameters
    ----------
    ratio : array_like
        h/d ≥ 0.
    model : {"geometric", "dynamic"}
        ``"geometric"``: the coin comes to rest in a uniformly random orientation; it stands on
        its edge when its centre of mass lies above the edge, i.e. when the vertical, seen in
        the coin's frame, points within arctan(h/d) of the coin's plane: a band of the sphere of
        solid-angle fraction sin(arctan(h/d)) = (h/d)/sqrt(1 + (h/d)²).
        ``"dynamic"``: a vigorous toss spinning in a vertical plane lands, without bouncing, at
        a uniformly random angle in that plane: the edge takes 4 arctan(h/d) of the 2π,
        P(edge) = 2 arctan(h/d)/π.

    Notes
    -----
    Yong & Mahadevan 2011, §II (geometric, "solid angle") and §III (dynamic, "planar").
    """
    x = v.non_negative("thickness/diameter ratio", ratio)
    v.choice("edge model", model, MODELS)
    if model == "geometric":
        return np.asarray(x / np.sqrt(1.0 + x * x))
    return np.asarray(2.0 * np.arctan(x) / np.pi)


def ratio_for(probability: float = 1.0 / 3.0, model: EdgeModel = "dynamic") -> float:
    """The ratio h/d at which P(edge) equals ``probability`` (root of :func:`edge_probability`).

    Yong & Mahadevan 2011 find, for P(edge) = 1/3, h/d = 1/(2√2) ≈ 0.354 (geometric) and
    1/√3 ≈ 0.577 (dynamic).

    Examples
    --------
    >>> round(ratio_for(1 / 3, "geometric"), 4), round(ratio_for(1 / 3, "dynamic"), 4)
    (0.3536, 0.5774)
    """
    from scipy.optimize import brentq

    p = v.in_range("edge probability", probability, 0.0, 1.0)
    if p.ndim:
        raise TypeError("edge probability must be a single number")
    if not 0.0 < float(p) < 1.0:
        raise ValueError(f"edge probability must be strictly between 0 and 1, got {float(p)!r}")
    v.choice("edge model", model, MODELS)
    target = float(p)

    def excess(x: float) -> float:
        return float(edge_probability(x, model)) - target

    high = 1.0
    while excess(high) < 0.0:  # both models tend to 1 as h/d → ∞
        high *= 2.0
    return float(brentq(excess, 0.0, high, xtol=1e-15, rtol=4 * np.finfo(float).eps))


__all__ = ["MODELS", "edge_probability", "ratio_for"]
