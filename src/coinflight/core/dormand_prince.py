"""Dormand–Prince 5(4): the Runge–Kutta pair the contact kernels step with (numba).

The explicit pair of Dormand & Prince (1980, J. Comput. Appl. Math. 6:19), coefficients as in
Hairer, Nørsett & Wanner, *Solving Ordinary Differential Equations I* (2nd ed.), table II.5.2;
the error measured component by component against ``rtol (scale_i + max(|y_i|, |y_new_i|))``
and the step accepted when the largest ratio is at most 1 (ibid., II.4). The kernels that
integrate a contact mode (:mod:`coinflight.core.rigid_contact`,
:mod:`coinflight.core.band_contact`) evaluate their own
rates; these functions form the points at which they evaluate them and the error of a step, so
the arithmetic of the pair is written once.
"""

from __future__ import annotations

import numpy as np

from coinflight.core._jit import njit

A21 = 1.0 / 5.0
A31, A32 = 3.0 / 40.0, 9.0 / 40.0
A41, A42, A43 = 44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0
A51, A52, A53, A54 = 19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0
A61, A62, A63 = 9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0
A64, A65 = 49.0 / 176.0, -5103.0 / 18656.0
B1, B3, B4, B5, B6 = 35.0 / 384.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0
"""The fifth-order solution's weights (b2 = 0; b7 = 0: the pair is first same as last)."""
E1, E3, E4 = 71.0 / 57600.0, -71.0 / 16695.0, 71.0 / 1920.0
E5, E6, E7 = -17253.0 / 339200.0, 22.0 / 525.0, -1.0 / 40.0
"""The difference of the fifth- and fourth-order weights (the error estimate's)."""


@njit(cache=True)
def workspace(size):
    """The arrays a step needs for a state of ``size`` components: the seven stages' rates
    k1 … k7, the stage point and the new state."""
    return (
        np.empty(size),
        np.empty(size),
        np.empty(size),
        np.empty(size),
        np.empty(size),
        np.empty(size),
        np.empty(size),
        np.empty(size),
        np.empty(size),
    )


@njit(cache=True)
def stage(s, y, h, k1, k2, k3, k4, k5, k6, out):
    """``out`` = the point of stage ``s`` (2 to 6) of a step of ``h`` from ``y``, from the rates
    of the stages before it; ``s`` = 7: the fifth-order solution (where the last rate, k7, is
    evaluated). Returns ``out``."""
    n = y.shape[0]
    if s == 2:
        for i in range(n):
            out[i] = y[i] + h * A21 * k1[i]
    elif s == 3:
        for i in range(n):
            out[i] = y[i] + h * (A31 * k1[i] + A32 * k2[i])
    elif s == 4:
        for i in range(n):
            out[i] = y[i] + h * (A41 * k1[i] + A42 * k2[i] + A43 * k3[i])
    elif s == 5:
        for i in range(n):
            out[i] = y[i] + h * (A51 * k1[i] + A52 * k2[i] + A53 * k3[i] + A54 * k4[i])
    elif s == 6:
        for i in range(n):
            out[i] = y[i] + h * (
                A61 * k1[i] + A62 * k2[i] + A63 * k3[i] + A64 * k4[i] + A65 * k5[i]
            )
    else:
        for i in range(n):
            out[i] = y[i] + h * (B1 * k1[i] + B3 * k3[i] + B4 * k4[i] + B5 * k5[i] + B6 * k6[i])
    return out


@njit(cache=True, inline="always")
def estimate(i, h, k1, k3, k4, k5, k6, k7):
    """The error estimate of component ``i`` of a step of ``h``: h Σ e_j k_j, the difference of
    the fifth- and fourth-order solutions."""
    return h * (E1 * k1[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i] + E7 * k7[i])


@njit(cache=True)
def error_ratio(y, new, h, k1, k3, k4, k5, k6, k7, rtol, scale, size):
    """The largest ratio of a step's error estimate to its tolerance over the first ``size``
    components: |h Σ e_j k_j| / (rtol (scale_i + max(|y_i|, |new_i|))). At most 1 accepts the
    step; a NaN anywhere gives NaN (never accepted)."""
    err = 0.0
    for i in range(size):
        r = abs(estimate(i, h, k1, k3, k4, k5, k6, k7)) / (
            rtol * (scale[i] + max(abs(y[i]), abs(new[i])))
        )
        if not r <= err:
            err = r
    return err


__all__ = ["error_ratio", "estimate", "stage", "workspace"]
