"""The hand catch of the founding paper: caught at launch height, the face is the sign of n(T)·n0.

Stefan & Cheche eq 14; Diaconis, Holmes & Montgomery (2007) for the precessing coin. Its faces
are the closed-form bands of :mod:`coinflight.core.bands` (``closed_form_bands``), which the exact
method and the grid's band counting use directly.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from coinflight.model.ensemble import PARAMETERS, TossDistribution
from coinflight.model.surface import TABLE_ONLY
from coinflight.outcomes.base import (
    Counts,
    FaceArray,
    FloatArray,
    OutcomeModel,
    faces_from_same_side,
)

if TYPE_CHECKING:
    from coinflight.model.coin import Coin


class HandCatch(OutcomeModel):
    """Caught in the hand at launch height: the face is the sign of n(T)·n0 (Stefan & Cheche)."""

    name = "hand catch"
    summary = "caught at launch height (no bounce)"
    surface_refusal = TABLE_ONLY
    closed_form_bands = True
    rate = 2.5e7
    """Tosses a second by Monte Carlo over the paper's box (ω_x 60-90 rad/s, T 0.6-0.9 s) on the
    reference 2-core machine, both threads (``benchmarks/bench_probability.py`` measures it)."""

    def faces(
        self, coin: Coin, omega: FloatArray, flight_time: FloatArray, start_sign: float, g: float
    ) -> FaceArray:
        """Sign of n(T)·n0 from the closed form, one vectorised call (g does not enter)."""
        from coinflight.core import torque_free
        from coinflight.core.outcome import face_from_alignment

        del g
        i1, i3 = coin.moments
        omega = np.asarray(omega, dtype=float)
        align = torque_free.normal_alignment(
            omega[..., 0], omega[..., 1], omega[..., 2], flight_time, i1, i3
        )
        return face_from_alignment(align, start_sign)

    def count(self, dist: TossDistribution, u: NDArray[np.float64]) -> Counts:
        """Counts by the compiled kernels of :mod:`coinflight.core.sampling` (affine fast path)."""
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

    def describe(self) -> str:
        return "caught in the hand, no air drag"

    def to_dict(self) -> dict[str, Any]:
        return {"surface": "hand", "drag": None}


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
"""The hand catch, the estimators' default outcome model."""

__all__ = ["HAND_CATCH", "HandCatch"]
