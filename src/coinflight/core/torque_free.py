"""Closed-form torque-free motion of a symmetric coin (I1 = I2 ≠ I3).

Conventions used throughout coinflight
--------------------------------------
* The body frame has z along the coin's normal on the heads side; x and y are diameters.
* An attitude ``R`` maps body components to lab components, ``v_lab = R v_body``; the body
  angular velocity ω obeys dR/dt = R [ω]×.
* At launch the body frame coincides with the lab frame when the coin starts heads up, and is
  turned by π about the lab X axis when it starts tails up (``start_sign`` = +1 or -1).
* Gravity acts along −Z and exerts no torque about the centre of mass, so the attitude does not
  depend on g or on the centre of mass's flight.

Notes
-----
For a symmetric body the angular momentum M is fixed in the lab, and
ω = M / I1 + λ ẑ_body with λ = (I1 − I3) ω_z / I1. The attitude is therefore the composition
of a rotation about M̂ at the precession rate ωp = |M| / I1 and a rotation about the body's own
symmetry axis at rate λ:

    R(t) = Rot(M t / I1) · R0 · Rot(λ t ẑ)

(Diaconis, Holmes & Montgomery 2007, section 2; Landau & Lifshitz, Mechanics §33). In the body
frame (ωx, ωy) turn about z at q = (I3 − I1) ω_z / I1 = −λ (Stefan & Cheche eqs 7-9). The normal
precesses on a cone of half-angle ψ = angle(n, M) about M̂, so that
n(t)·n0 = cos²ψ + sin²ψ cos(ωp t).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import ArrayLike, NDArray

if TYPE_CHECKING:
    from scipy.spatial.transform import Rotation

FloatArray = NDArray[np.float64]
Real = float | FloatArray


def angular_momentum_body(omega: ArrayLike, i1: ArrayLike, i3: ArrayLike) -> FloatArray:
    """Angular momentum M about the centre of mass, body components (kg m²/s).

    Notes
    -----
    Stefan & Cheche eq 3: S = Σ I_ii ω_i e_i, with I1 = I2.
    """
    w = np.asarray(omega, dtype=float)
    i1 = np.asarray(i1, dtype=float)[..., None]
    i3 = np.asarray(i3, dtype=float)
    moments = np.concatenate(np.broadcast_arrays(i1, i1, i3[..., None]), axis=-1)
    return w * moments


def precession_rate(omega: ArrayLike, i1: ArrayLike, i3: ArrayLike) -> FloatArray:
    """Rate ωp = |M| / I1 at which the normal turns about the angular momentum (rad/s).

    Notes
    -----
    Diaconis, Holmes & Montgomery 2007, section 2. With ω_z = 0 this is Stefan & Cheche's
    Ω = sqrt(ωx0² + ωy0²) (eq 9).
    """
    w = np.asarray(omega, dtype=float)
    i1 = np.asarray(i1, dtype=float)
    i3 = np.asarray(i3, dtype=float)
    transverse = w[..., 0] ** 2 + w[..., 1] ** 2
    axial = (i3 / i1 * w[..., 2]) ** 2
    return np.sqrt(transverse + axial)


def cone_angle(omega: ArrayLike, i1: ArrayLike, i3: ArrayLike) -> FloatArray:
    """Angle ψ between the heads normal and the angular momentum, in [0, π] (rad).

    ψ = π/2 for a spin about a diameter (the paper's cases); ψ = 0 when there is no spin at all
    (the normal then stays put, as on a cone of zero opening).

    Notes
    -----
    cos ψ = I3 ω_z / |M| (Diaconis, Holmes & Montgomery 2007, section 2), written with arctan2
    so that it is well defined and accurate for every ω.
    """
    w = np.asarray(omega, dtype=float)
    i1 = np.asarray(i1, dtype=float)
    i3 = np.asarray(i3, dtype=float)
    transverse = i1 * np.hypot(w[..., 0], w[..., 1])
    return np.arctan2(transverse, i3 * w[..., 2])


def normal_alignment(wx: Real, wy: Real, wz: Real, t: Real, i1: Real, i3: Real) -> Real:
    """n(t)·n0: cosine of the dihedral angle between the coin's plane at launch and at t.

    The face that ends up is decided by its sign alone: positive means the coin shows the face
    it started with. Written from components and NumPy ufuncs only, so that the same function
    serves arrays here and is compiled as-is by numba for the sampling kernels.

    Notes
    -----
    n(t)·n0 = cos²ψ + sin²ψ cos(ωp t) (Diaconis, Holmes & Montgomery 2007), rewritten as
    1 − ½ (Ω⊥ t)² sinc²(ωp t / 2) with Ω⊥ = sqrt(ωx² + ωy²), which needs no division by |M|
    and is exact at ω = 0. With ω_z = 0 it is Stefan & Cheche's cos θ = cos(Ω t) (eq 14).
    """
    perp2 = wx * wx + wy * wy
    axial = i3 / i1 * wz
    half_angle = 0.5 * np.sqrt(perp2 + axial * axial) * t
    # np.sinc is the normalised sinc, sin(πx)/(πx).
    s = np.sinc(half_angle / np.pi)
    return 1.0 - 0.5 * perp2 * t * t * s * s


def body_angular_velocity(
    omega: ArrayLike, i1: ArrayLike, i3: ArrayLike, t: ArrayLike
) -> FloatArray:
    """Body-frame angular velocity at time t, given its value at launch (rad/s).

    Notes
    -----
    Stefan & Cheche eqs 6-9: ω_z is constant and (ωx, ωy) turn at q = (I3 − I1) ω_z / I1.
    """
    w = np.asarray(omega, dtype=float)
    t = np.asarray(t, dtype=float)
    i1 = np.asarray(i1, dtype=float)
    i3 = np.asarray(i3, dtype=float)
    phase = (i3 - i1) / i1 * w[..., 2] * t
    c, s = np.cos(phase), np.sin(phase)
    wx = c * w[..., 0] - s * w[..., 1]
    wy = s * w[..., 0] + c * w[..., 1]
    return np.stack(np.broadcast_arrays(wx, wy, w[..., 2] + 0.0 * t), axis=-1)


def initial_attitude(start_sign: ArrayLike) -> Rotation:
    """Attitude at launch: identity heads up (+1), a half turn about lab X tails up (−1)."""
    from scipy.spatial.transform import Rotation

    sign = np.asarray(start_sign, dtype=float)
    angle = np.where(sign > 0, 0.0, np.pi)
    rotvec = np.stack([angle, np.zeros_like(angle), np.zeros_like(angle)], axis=-1)
    return Rotation.from_rotvec(rotvec)


def attitude(
    omega: ArrayLike, i1: ArrayLike, i3: ArrayLike, t: ArrayLike, start_sign: ArrayLike = 1.0
) -> Rotation:
    """Attitude R(t) (body → lab) of a torque-free symmetric coin; batched over tosses.

    Parameters
    ----------
    omega : array_like, shape (..., 3)
        Body-frame angular velocity at launch, rad/s.
    i1, i3 : array_like
        Principal moments, kg m² (see :func:`coinflight.core.rigid_body.principal_moments`).
    t : array_like
        Time since launch, s.
    start_sign : array_like
        +1 heads up at launch, −1 tails up.

    Returns
    -------
    scipy.spatial.transform.Rotation
        A stack of rotations with the broadcast shape of the inputs (flattened by scipy to one
        leading dimension when that shape has more than one dimension).

    Notes
    -----
    R(t) = Rot(M_lab t / I1) · R0 · Rot(λ t ẑ), λ = (I1 − I3) ω_z / I1; see the module notes.
    """
    from scipy.spatial.transform import Rotation

    w = np.asarray(omega, dtype=float)
    t = np.asarray(t, dtype=float)
    i1 = np.asarray(i1, dtype=float)
    i3 = np.asarray(i3, dtype=float)
    sign = np.asarray(start_sign, dtype=float)
    shape = np.broadcast_shapes(w.shape[:-1], t.shape, i1.shape, i3.shape, sign.shape)
    w = np.broadcast_to(w, (*shape, 3)).reshape(-1, 3)
    t = np.broadcast_to(t, shape).reshape(-1)
    i1 = np.broadcast_to(i1, shape).reshape(-1)
    i3 = np.broadcast_to(i3, shape).reshape(-1)
    r0 = initial_attitude(np.broadcast_to(sign, shape).reshape(-1))
    m_lab = r0.apply(angular_momentum_body(w, i1, i3))
    precession = Rotation.from_rotvec(m_lab * (t / i1)[:, None])
    spin_angle = (i1 - i3) / i1 * w[:, 2] * t
    spin = Rotation.from_rotvec(np.stack([0 * spin_angle, 0 * spin_angle, spin_angle], axis=-1))
    result = precession * r0 * spin
    return result if shape else result[0]


def rotations(omega: ArrayLike, i1: ArrayLike, i3: ArrayLike, t: ArrayLike) -> FloatArray:
    """Number of turns of the normal about the angular momentum in time t: ωp t / 2π.

    Notes
    -----
    For a spin about a diameter this is θ(T)/2π with θ(T) = Ω T (Stefan & Cheche eqs 11, 15).
    """
    return precession_rate(omega, i1, i3) * np.asarray(t, dtype=float) / (2.0 * np.pi)
