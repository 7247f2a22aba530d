"""Same-side probability of a precessing coin (Diaconis, Holmes & Montgomery 2007).

A coin in torque-free flight keeps its angular momentum M fixed; its heads normal n turns about
M̂ on a cone of half-angle ψ = angle(n, M). Started heads up (n0 = Z), after a flight time T

    n(T)·n0 = cos²ψ + sin²ψ cos(ωp T),

and the coin shows the face it started with iff that is positive. When the phase ωp T is spread
over many turns (as it is for any real hand), it is in effect uniform on the circle and the
fraction of tosses that land on the starting side is a function of ψ alone,
:func:`same_side_probability`.

All angles in radians. No validation here: the value layer (:mod:`coinflight.studies.bias`)
checks input.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from coinflight.core.bands import never_turns_over

FloatArray = NDArray[np.float64]


def same_side_probability(psi: ArrayLike) -> FloatArray:
    """Probability that the coin lands on the side it started, for precession angle ψ.

    Parameters
    ----------
    psi : array_like
        Angle ψ between the heads normal and the angular momentum, rad, in [0, π].

    Returns
    -------
    ndarray
        p(ψ), same shape as ``psi``; in [1/2, 1].

    Notes
    -----
    Diaconis, Holmes & Montgomery 2007, "Dynamical bias in the coin toss", SIAM Review 49(2),
    section 2 (REFERENCES §2):

        p(ψ) = 1/2 + (1/π) arcsin(cot²ψ)   for π/4 ≤ ψ ≤ 3π/4,   1 otherwise.

    It is the fraction of the circle of phases φ = ωp T on which cos²ψ + sin²ψ cos φ > 0, i.e.
    cos φ > −cot²ψ. Outside [π/4, 3π/4] cot²ψ ≥ 1: the coin only wobbles and never turns over.
    cot²ψ is written cos²ψ / sin²ψ clipped to 1, which is exact at ψ = π/2 and never divides
    by zero inside the branch that uses it.
    """
    psi = np.asarray(psi, dtype=float)
    c2 = np.cos(psi) ** 2
    s2 = np.sin(psi) ** 2
    inside = ~never_turns_over(c2, s2)  # π/4 < ψ < 3π/4
    cot2 = np.where(inside, c2 / np.where(inside, s2, 1.0), 1.0)
    return np.asarray(0.5 + np.arcsin(np.minimum(cot2, 1.0)) / np.pi)


def angle_for_same_side(p: ArrayLike) -> FloatArray:
    """Inverse of :func:`same_side_probability` on the branch π/4 ≤ ψ ≤ π/2.

    Parameters
    ----------
    p : array_like
        Same-side probability, in [1/2, 1].

    Returns
    -------
    ndarray
        ψ in [π/4, π/2], rad (NaN where p is outside [1/2, 1]). The mirror angle π − ψ gives the
        same probability (a spin about the normal in the opposite sense).

    Notes
    -----
    Solving p = 1/2 + (1/π) arcsin(cot²ψ) (Diaconis, Holmes & Montgomery 2007) for ψ:
    cot ψ = sqrt(sin(π (p − 1/2))), ψ = arctan2(1, cot ψ). p = 1 is reached for every
    ψ ≤ π/4; the inverse returns the largest of them, π/4.
    """
    p = np.asarray(p, dtype=float)
    ok = (p >= 0.5) & (p <= 1.0)
    cot = np.sqrt(np.sin(np.pi * (np.where(ok, p, 0.5) - 0.5)))
    return np.asarray(np.where(ok, np.arctan2(1.0, cot), np.nan))


def axial_spin(omega_perp: ArrayLike, psi: ArrayLike, i1: ArrayLike, i3: ArrayLike) -> FloatArray:
    """Spin about the normal ω_z that puts the normal on a cone of half-angle ψ (rad/s).

    Parameters
    ----------
    omega_perp : array_like
        Transverse spin Ω⊥ = sqrt(ωx² + ωy²), rad/s.
    psi : array_like
        Cone angle ψ, rad, in (0, π).
    i1, i3 : array_like
        Principal moments, kg m².

    Notes
    -----
    cos ψ = I3 ω_z / |M| with |M| = sqrt((I1 Ω⊥)² + (I3 ω_z)²) (Diaconis, Holmes & Montgomery
    2007, section 2), so ω_z = (I1 / I3) Ω⊥ cot ψ.
    """
    psi = np.asarray(psi, dtype=float)
    return np.asarray(
        np.asarray(i1, dtype=float)
        / np.asarray(i3, dtype=float)
        * np.asarray(omega_perp, dtype=float)
        * np.cos(psi)
        / np.sin(psi)
    )


def spin_on_cone(
    precession_rate: ArrayLike, psi: ArrayLike, i1: ArrayLike, i3: ArrayLike
) -> tuple[FloatArray, FloatArray]:
    """Body spin (Ω⊥, ω_z) with precession rate ωp and cone angle ψ.

    Parameters
    ----------
    precession_rate : array_like
        ωp = |M| / I1, rad/s.
    psi : array_like
        Cone angle ψ, rad, in [0, π].
    i1, i3 : array_like
        Principal moments, kg m².

    Returns
    -------
    omega_perp, omega_z : ndarray
        Transverse spin Ω⊥ = ωp sin ψ and axial spin ω_z = (I1 / I3) ωp cos ψ, rad/s,
        broadcast together.

    Notes
    -----
    From M = (I1 ωx, I1 ωy, I3 ω_z), |M| = I1 ωp and cos ψ = I3 ω_z / |M| (Diaconis, Holmes &
    Montgomery 2007, section 2). Unlike :func:`axial_spin` it is defined at ψ = 0 and π.
    """
    wp = np.asarray(precession_rate, dtype=float)
    psi = np.asarray(psi, dtype=float)
    ratio = np.asarray(i1, dtype=float) / np.asarray(i3, dtype=float)
    return np.asarray(wp * np.sin(psi)), np.asarray(ratio * wp * np.cos(psi))
