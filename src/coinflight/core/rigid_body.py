"""Mass properties of a coin modelled as a uniform solid cylinder."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray


def principal_moments(
    radius: ArrayLike, thickness: ArrayLike, mass: ArrayLike
) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Principal moments of inertia of a uniform cylinder about its centre of mass.

    Parameters
    ----------
    radius, thickness, mass : array_like
        Radius r and thickness h in m, mass m in kg; broadcast together.

    Returns
    -------
    i1 : ndarray
        Moment about any diameter (the body x and y axes), kg m².
    i3 : ndarray
        Moment about the symmetry axis (the body z axis, the coin's normal), kg m².

    Notes
    -----
    Stefan & Cheche, section 2: I1 = I2 = (m/4)(r² + h²/3), I3 = m r²/2.
    """
    r = np.asarray(radius, dtype=float)
    h = np.asarray(thickness, dtype=float)
    m = np.asarray(mass, dtype=float)
    i1 = 0.25 * m * (r * r + h * h / 3.0)
    i3 = 0.5 * m * r * r
    return i1, i3
