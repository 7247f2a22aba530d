"""Which face ends up: integer codes shared by every kernel and estimator."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

TAILS = 0
HEADS = 1
EDGE = 2
FACE_NAMES = ("tails", "heads", "edge")


def face_from_alignment(alignment: ArrayLike, start_sign: ArrayLike) -> NDArray[np.int8]:
    """Face up at catch from n(T)·n0 and the starting face (+1 heads, −1 tails).

    The heads normal points up at catch iff start_sign · n(T)·n0 > 0 (Stefan & Cheche §2.1:
    started heads up, heads iff cos θ > 0). The edge-on set cos θ = 0 has measure zero for a thin
    coin and is counted as tails, the paper's ``cos θ < 0`` side being open.
    """
    up = np.asarray(start_sign, dtype=float) * np.asarray(alignment, dtype=float) > 0.0
    return np.where(up, HEADS, TAILS).astype(np.int8)


def same_side(alignment: ArrayLike) -> NDArray[np.bool_]:
    """True where the coin shows, at catch, the face it started with."""
    return np.asarray(alignment, dtype=float) > 0.0
