"""A reference of the contact phase's rim forces computed apart from its kernels, for the tests:
each rim alone (the module notes' arc sums, its damper ζ/sqrt(ρ) sized for m_eff = 1/K_zz of
``impact.collision_matrix`` at the arc's centroid) and two pressed rims damped as one pair
(``contact_phase._pair``), the pair's damping matrix by its definition
C = 2 ζ M^½ (M^−½ K M^−½)^½ M^½ with SciPy's ``sqrtm`` and NumPy's inverse, not by the closed
form under test; M the inverse of the two centroids' normal mobility
W_ij = 1/m + (r_i × Z)·I⁻¹(r_j × Z) (Stronge 2000, eq 5.7, I⁻¹ from NumPy's inverse of the
coin's inertia tensor), each rim's row and column scaled by sqrt(ρ_i)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import scipy.linalg

from coinflight.core import contact_phase as cp
from coinflight.core.impact import angular_velocity, collision_matrix

Z = np.array([0.0, 0.0, 1.0])


def arc(sigma: float, y: np.ndarray, c: Any) -> dict[str, Any] | None:
    """Rim σ's arc d(φ) = a + b cos φ > 0 of the core circle and what its forces are built of:
    half-angle φ*, centroid rc, sums, the even penetration rate a0 + a1 cos φ, ρ, K_zz; None
    for an empty arc."""
    z, v, n, lm = y[0], np.asarray(y[1:4]), np.asarray(y[4:7]), np.asarray(y[7:10])
    corner = c.corner_radius
    core, hh = c.radius - corner, c.half_thickness - corner
    down = -Z + n[2] * n  # the coin plane's most downward direction
    s = float(np.linalg.norm(down))
    w = down / s
    a, b = corner - z - sigma * hh * n[2], core * s
    if a + b <= 0.0:
        return None
    phi = math.pi if a >= b else math.acos(-a / b)
    i0, ic, icc = 2.0 * phi, 2.0 * math.sin(phi), phi + math.sin(phi) * math.cos(phi)
    omega = np.asarray(angular_velocity(tuple(lm), tuple(n), c.i1, c.i3))
    rc = sigma * hh * n + core * math.sin(phi) / phi * w - corner * Z
    _, _, kxz, _, kyz, kzz = collision_matrix(tuple(rc), tuple(n), c.mass, c.i1, c.i3)
    u = v + np.cross(omega, rc)
    rho = 1.0
    if c.friction > 0.0:
        share = c.friction / math.hypot(u[0], u[1], cp.SLIP_SPEED)
        rho = max(1.0 - share * (kxz * u[0] + kyz * u[1]) / kzz, cp.SLIDING_MASS_FLOOR)
    stiff = cp.stiffness_of(c)
    return {
        "sigma": sigma, "n": n, "w": w, "core": core, "hh": hh, "corner": corner,
        "phi": phi, "i0": i0, "ic": ic, "icc": icc, "rc": rc, "rho": rho, "kzz": kzz,
        "k": i0 * stiff,
        "elastic": stiff * (a * i0 + b * ic), "moment": stiff * (a * ic + b * icc),
        "a0": -(v[2] + sigma * hh * np.cross(omega, n)[2]),
        "a1": -core * np.cross(omega, w)[2],
    }  # fmt: skip


def _finish(r: dict[str, Any], force: float, moment: float) -> tuple[float, Any, float]:
    if force <= 0.0:
        return 0.0, None, 0.0
    q = r["sigma"] * r["hh"] * r["n"] + r["core"] * moment / force * r["w"] - r["corner"] * Z
    ratio = math.sin(r["phi"]) / r["phi"]
    return force, q, r["core"] * math.sqrt(max(0.0, 1.0 - ratio * ratio))


def single(r: dict[str, Any] | None, zeta: float) -> tuple[float, Any, float]:
    """(F_n, q, r_t) of one rim damped alone: γ = 2 (ζ/sqrt(ρ)) sqrt(K_t/K_zz) / (2 φ*) on
    the even rate (the module notes' "Restitution")."""
    if r is None:
        return 0.0, None, 0.0
    gamma = zeta / math.sqrt(r["rho"]) * math.sqrt(r["k"] / r["kzz"]) / r["phi"]
    force = r["elastic"] + gamma * (r["a0"] * r["i0"] + r["a1"] * r["ic"])
    moment = r["moment"] + gamma * (r["a0"] * r["ic"] + r["a1"] * r["icc"])
    return _finish(r, force, moment)


def mobility(one: dict[str, Any], two: dict[str, Any], c: Any) -> np.ndarray:
    """The two centroids' normal mobility W (1/kg), each rim's row and column times sqrt(ρ)."""
    n = one["n"]
    inertia = c.i1 * (np.eye(3) - np.outer(n, n)) + c.i3 * np.outer(n, n)
    inverse = np.linalg.inv(inertia)
    arms = [np.cross(r["rc"], Z) for r in (one, two)]
    w = np.array([[1.0 / c.mass + arms[i] @ inverse @ arms[j] for j in (0, 1)] for i in (0, 1)])
    scale = np.sqrt([one["rho"], two["rho"]])
    return w * np.outer(scale, scale)


def damping_matrix(w: np.ndarray, k: np.ndarray, zeta: float) -> np.ndarray:
    """C = 2 ζ M^½ (M^−½ K M^−½)^½ M^½, M = W⁻¹, K = diag(k), by its definition (SciPy)."""
    mass = np.linalg.inv(w)
    root = np.real(scipy.linalg.sqrtm(mass))
    inv_root = np.linalg.inv(root)
    middle = np.real(scipy.linalg.sqrtm(inv_root @ np.diag(k) @ inv_root))
    return 2.0 * zeta * root @ middle @ root


def rims(y: np.ndarray, c: Any, zeta: float) -> tuple[list[tuple[float, Any, float]], bool]:
    """Both rims' (F_n, q, r_t), tails rim (σ = −1) first, as the phase applies them, and
    whether the pair was damped together: jointly when both arcs are non-empty and both joint
    forces are positive, else each alone."""
    one, two = arc(-1.0, y, c), arc(1.0, y, c)
    alone = [single(one, zeta), single(two, zeta)]
    if zeta <= 0.0 or one is None or two is None:
        return alone, False
    big_c = damping_matrix(mobility(one, two, c), np.array([one["k"], two["k"]]), zeta)
    rates = [(r["a0"] * r["i0"] + r["a1"] * r["ic"]) / r["i0"] for r in (one, two)]
    out = []
    for i, r in enumerate((one, two)):
        j = 1 - i
        gamma = big_c[i, i] / r["i0"]
        cross = big_c[i, j] * rates[j]
        force = r["elastic"] + gamma * (r["a0"] * r["i0"] + r["a1"] * r["ic"]) + cross
        moment = (
            r["moment"]
            + gamma * (r["a0"] * r["ic"] + r["a1"] * r["icc"])
            + cross * r["ic"] / r["i0"]
        )
        if force <= 0.0:
            return alone, False
        out.append(_finish(r, force, moment))
    return out, True
