"""Which face ends up and why a landing ended: integer codes shared by every kernel and estimator.

:class:`Face` and :class:`Status` are ``IntEnum``\\ s: their members are the integers the
kernels store in their ``int8`` arrays (numba compiles a member as its integer: a kernel may
return ``Face.EDGE`` or store it in an array; only ``int(member)`` is not compiled, compare or
store the member itself instead), and their names are the words reports print.
"""

from __future__ import annotations

from enum import IntEnum

import numpy as np
from numpy.typing import ArrayLike, NDArray


class Face(IntEnum):
    """The face up at the end of a toss (``face`` arrays, ``np.bincount`` order)."""

    TAILS = 0
    HEADS = 1
    EDGE = 2

    @property
    def label(self) -> str:
        """``"tails"``, ``"heads"`` or ``"edge"``."""
        return self.name.lower()


class Status(IntEnum):
    """Why a landing on a surface ended (``status`` arrays of the landing kernels).

    The values are the codes of the outputs (``status`` in JSON and arrays); 6 is no longer
    used (it was the upright decision of a 3-D ending since removed)."""

    SETTLED_ENERGY = 0
    """Energy below the face/edge barrier: the outcome is certain."""
    SETTLED_DEAD = 1
    """e = 0: the surface absorbs the coin at its first contact, which decides (Yong &
    Mahadevan)."""
    BOUNCE_LIMIT = 2
    """Stopped at the contact after ``max_bounces`` bounces, as asked (basin maps)."""
    UNSETTLED = 3
    """Still bouncing after the safety limit of impacts; the outcome is the well it is in."""
    SETTLED_ROCKING = 4
    """The bounces died out (rebound below the rest speed); the coin rocked on its corners until
    it was trapped in a well (the planar hand-off of :func:`coinflight.core.bounce.rock`, the
    default ending)."""
    SETTLED_CONTACT = 5
    """The bounces died out; the coin then rolled, slid, pivoted and rocked in contact with the
    surface, in 3-D (:mod:`coinflight.core.rigid_ending`, ``Surface(ending="rigid")``), until
    it was at rest or its energy could no longer take it out of its well."""

    @property
    def label(self) -> str:
        """What reports print: ``"settled"``, ``"landed dead"``, ``"bounce limit"``,
        ``"unsettled"``, ``"settled rocking"`` or ``"settled in contact"``."""
        return _STATUS_LABELS[self]


_STATUS_LABELS = {
    Status.SETTLED_ENERGY: "settled",
    Status.SETTLED_DEAD: "landed dead",
    Status.BOUNCE_LIMIT: "bounce limit",
    Status.UNSETTLED: "unsettled",
    Status.SETTLED_ROCKING: "settled rocking",
    Status.SETTLED_CONTACT: "settled in contact",
}

TAILS = Face.TAILS
HEADS = Face.HEADS
EDGE = Face.EDGE
FACE_NAMES = tuple(face.label for face in Face)
"""("tails", "heads", "edge"), indexed by face code."""
STATUS_NAMES = tuple(status.label for status in Status)
"""("settled", "landed dead", "bounce limit", "unsettled", "settled rocking", "settled in contact"),
by status code."""


def same_side(alignment: ArrayLike) -> NDArray[np.bool_]:
    """True where the coin shows, at catch, the face it started with: n(T)·n0 > 0.

    The edge-on set n(T)·n0 = 0 has measure zero for a thin coin; the paper's rule leaves it out
    of the starting face ("cos θ > 0", Stefan & Cheche §2.1), so it counts as the other face.
    (The probability of the same side for a cone angle ψ is
    :func:`coinflight.core.precession.same_side_probability`.)
    """
    return np.asarray(alignment, dtype=float) > 0.0


def face_from_alignment(alignment: ArrayLike, start_sign: ArrayLike) -> NDArray[np.int8]:
    """Face up at catch from n(T)·n0 and the starting face (+1 heads, −1 tails).

    The starting face where :func:`same_side`, the other face elsewhere (Stefan & Cheche §2.1:
    started heads up, heads iff cos θ > 0).
    """
    same = same_side(alignment)
    heads = np.where(np.asarray(start_sign, dtype=float) > 0, same, ~same)
    return np.where(heads, Face.HEADS, Face.TAILS).astype(np.int8)
