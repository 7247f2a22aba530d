"""Which face ends up: integer codes shared by every kernel and estimator."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

TAILS = 0
HEADS = 1
EDGE = 2
FACE_NAMES = ("tails", "heads", "edge")


def same_side(alignment: ArrayLike) -> NDArray[np.bool_]:
    """True where the coin shows, at catch, the face it started with: n(T)·n0 > 0.

    The edge-on set n(T)·n0 = 0 has measure zero for a thin coin; the paper's rule leaves it out
    of the starting face ("cos θ > 0", Stefan & Cheche §2.1), so it counts as the other face.
    """
    return np.asarray(alignment, dtype=float) > 0.0


def face_from_alignment(alignment: ArrayLike, start_sign: ArrayLike) -> NDArray[np.int8]:
    """Face up at catch from n(T)·n0 and the starting face (+1 heads, −1 tails).

    The starting face where :func:`same_side`, the other face elsewhere (Stefan & Cheche §2.1:
    started heads up, heads iff cos θ > 0).
    """
    same = same_side(alignment)
    heads = np.where(np.asarray(start_sign, dtype=float) > 0, same, ~same)
    return np.where(heads, HEADS, TAILS).astype(np.int8)
