"""A benchmark-only knob: the exponent of the contact phase's normal law (no change to defaults).

The contact phase (:mod:`coinflight.core.contact_phase`) presses each rim on the table with a
linear spring per radian of rim, κ d(φ), whose sum over a short arc is Hertz-like: F ∝ d0^(3/2)
in the depth d0 of the rim's lowest point (a curved rim on a plane), with the damping of Tsuji,
Tanaka & Ishida (1992). MuJoCo's contact is linear in the depth. To ask whether that exponent is
why the two engines part, :func:`use_exponent` swaps the phase's ``_rim`` (the kernel that
``rim_contact``, the derivative and the energy all call) for a family of laws with the same
geometry, before any kernel is compiled (into a temporary numba cache, removed at exit; the
package's cache is not touched):

* the elastic energy of a rim is U_p = C (U_a)^β, β = 2 (p + 1)/5, U_a the default arc's
  energy κ ∫ d²/2 dφ. Its force and moment are λ times the arc's (λ = C β U_a^(β−1)): the same
  centre of pressure, and a potential, so the law is conservative and the energy test of the
  phase stays exact. On a short arc, U_a = (8√2/15) κ d0^(5/2) / sqrt(B) (B = r s), so
  F = K_p d0^p: p = 3/2 is the default law (left in place); for p = 1 C is set so
  that an upright rim (B = r) has K_1 = 2πκ = π² m / t_c², the face's stiffness: a coin on
  one upright rim point (effective mass m) would sink for t_c, as a coin dropped flat does.
  Upright, a sharp coin touches with both rims, so its stiffness is 2 K_1 and the contact
  lasts ~t_c/√2 (undamped; 0.76 and 0.74 ms measured, damped, below). (Tilted, the
  stiffness grows as B^(−2/5); a face flat on the table gets F ∝ d^(3/5): a benchmark knob,
  not a model of a face.)
* the damping is the default arc's with ζ_p (:func:`damping_ratio`: the dimensionless law
  x'' = −x^p − 2 ζ sqrt(p x^(p−1)) x' of :func:`coinflight.core.contact_phase.restitution_of`
  restitutes with e) and scaled by sqrt((2p/3) λ), so that on a short arc it is
  2 ζ_p sqrt(K_t m_eff) ḋ0 with K_t = dF/dd0 = p F / d0, as the default's is for p = 3/2.

The upright decision (:func:`coinflight.core.contact_phase.upright_decided`) bounds the
rims' sinking with the 3/2 law: with another exponent the tosses are carried to rest by
:func:`coinflight.core.contact_phase.advance` with ``decide=False``.

Checked (2026-11-23, by hand, not a test): p = 1 gives F = 2πκ d0 on an upright rim to four
digits at d0 = 0.1, 1 and 10 μm, and F = −∂U_p/∂z on a rim tilted 0.7 rad to six
(tests/test_bench_normal_law.py checks both rims' 2 × 2πκ d0 at 1 μm through the phase's
derivative, and the copy's geometry against ``_rim``'s). A nickel
dropped upright on both rims (frictionless, t_c 1 ms) stays in contact 0.76 ms at 0.1 m/s and
0.74 ms at 1 m/s with p = 1 (rebound 0.38, 0.40 of its speed), 5.7 and 3.0 ms with p = 3/2
(0.18, 0.39); MuJoCo's calibrated contact 0.8 ms at both (0.50, 0.52). (That both laws rebounded
two rims at ~0.4 rather than e = 0.5 was the phase's own, measured before 2026-11-24: each rim's
damper was sized for the effective mass at its own arc, as if it carried the coin alone, so two
rims pressed together were damped √2 times harder. The phase now damps a pressed pair jointly,
:data:`coinflight.core.contact_phase.JOINT_DAMPING`, sized for the default law's tangent
stiffness 2 φ κ: :func:`use_exponent` switches it off for p = 1, whose rims are so damped each
alone, as before.)
"""

from __future__ import annotations

import atexit
import math
import os
import shutil
import tempfile

EXPONENTS = (1.0, 1.5)
"""Exponents the knob accepts: the linear law and the default (3/2)."""


_CACHE: list[str] = []
"""The temporary cache :func:`fresh_cache` made, if it was called."""


def fresh_cache() -> None:
    """Compile numba kernels into a temporary cache directory (removed at exit), before any
    is compiled: a patched global is then read by the compiler, not a cached kernel."""
    cache = tempfile.mkdtemp(prefix="coinflight-law-")
    atexit.register(shutil.rmtree, cache, True)
    os.environ["NUMBA_CACHE_DIR"] = cache
    _CACHE.append(cache)


def damping_ratio(restitution: float, exponent: float) -> float:
    """ζ for which the dimensionless law of exponent p restitutes with e (bisection on
    :func:`coinflight.core.contact_phase.restitution_of`, which falls as ζ grows)."""
    from coinflight.core import contact_phase as cp

    if restitution >= 1.0:
        return 0.0
    lo, hi = 0.0, 1.0
    while cp.restitution_of(hi, exponent) > restitution:
        lo, hi = hi, 2.0 * hi
    for _ in range(50):
        mid = 0.5 * (lo + hi)
        if cp.restitution_of(mid, exponent) > restitution:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def use_exponent(exponent: float) -> None:
    """Make the contact phase's rim law F ∝ d0^p (module notes): patches ``contact_phase._rim``,
    through which :func:`~coinflight.core.contact_phase.rim_contact`, the derivative and the
    energy all go. Call after :func:`fresh_cache`, before any kernel of
    :mod:`coinflight.core.contact_phase` is compiled. p = 3/2 leaves everything as it is."""
    if exponent not in EXPONENTS:
        raise ValueError(f"exponent must be one of {EXPONENTS}, got {exponent!r}")
    if exponent == 1.5:
        return
    from coinflight.core import contact_phase as cp

    if not _fresh(cp):
        raise RuntimeError(
            "use_exponent needs fresh_cache() first, before any kernel of contact_phase is "
            "imported or compiled"
        )
    cp._rim = rim_law(exponent)
    # The pair's joint damping (contact_phase._pair) sizes two pressed rims with the default
    # law's tangent stiffness 2 φ κ and elastic sums: with another law each rim is damped alone.
    cp.JOINT_DAMPING = False


def _fresh(module) -> bool:  # type: ignore[no-untyped-def]
    """Whether every numba kernel of ``module`` caches into :func:`fresh_cache`'s directory (the
    module was imported after it) and none is compiled yet (a patched global still reaches
    them, and nothing patched is written into the package's own cache)."""
    cache = os.environ.get("NUMBA_CACHE_DIR")
    if cache not in _CACHE:
        return False
    kernels = [
        f
        for f in vars(module).values()
        if hasattr(f, "signatures") and f.py_func.__module__ == module.__name__
    ]
    return all(not f.signatures and f._cache._cache_path.startswith(str(cache)) for f in kernels)


def rim_law(exponent: float):  # type: ignore[no-untyped-def]
    """The kernel of ``contact_phase._rim`` (the same signature) with the law F ∝ d0^p: its body
    copied, the law changed where marked (module notes)."""
    from numba import njit

    from coinflight.core.contact_phase import _damper
    from coinflight.core.impact import cross

    beta = 2.0 * (exponent + 1.0) / 5.0
    scale = math.sqrt(2.0 * exponent / 3.0)

    @njit(cache=True)
    def _rim(
        sigma, z, v, n, omega, s, w, radius, hh, mass, i1, i3, stiffness, zeta, corner, friction=0.0
    ):  # type: ignore[no-untyped-def]
        # The default's arc sums (contact_phase._rim), the law changed where marked.
        radius -= corner
        hh -= corner
        a = corner - z - sigma * hh * n[2]
        b = radius * s
        if a + b <= 0.0:
            return 0.0, (0.0, 0.0, 0.0), 0.0, 0.0
        if a >= b:
            phi, sp, cp_ = math.pi, 0.0, -1.0
        else:
            cp_ = -a / b
            phi = math.acos(cp_)
            sp = math.sqrt((1.0 - cp_) * (1.0 + cp_))
        i0 = 2.0 * phi
        ic = 2.0 * sp
        icc = phi + sp * cp_
        elastic = stiffness * (a * i0 + b * ic)
        moment = stiffness * (a * ic + b * icc)
        ua = 0.5 * stiffness * (a * a * i0 + 2.0 * a * b * ic + b * b * icc)
        if ua <= 0.0:
            return 0.0, (0.0, 0.0, 0.0), 0.0, 0.0
        # Changed: U_p = C U_a^β, its force and moment λ times the arc's (module notes).
        k_arc = 8.0 * math.sqrt(2.0) * stiffness / (15.0 * math.sqrt(radius))
        c = 2.0 * math.pi * stiffness / ((exponent + 1.0) * k_arc**beta)
        energy = c * ua**beta
        lam = c * beta * ua ** (beta - 1.0)
        elastic *= lam
        moment *= lam
        wn = cross(omega, n)
        ww = cross(omega, w)
        a0 = -(v[2] + sigma * hh * wn[2])
        a1 = -radius * ww[2]
        k = radius * sp / phi
        centroid = (
            sigma * hh * n[0] + k * w[0],
            sigma * hh * n[1] + k * w[1],
            sigma * hh * n[2] + k * w[2] - corner,
        )
        # the damper for the normal mass friction leaves, and m_eff, as the default's
        zeta, m_eff = _damper(centroid, v, n, omega, mass, i1, i3, friction, zeta)
        # Changed: the damper times sqrt((2p/3) λ) (ζ is ζ_p, from the record).
        gamma = scale * math.sqrt(lam) * zeta * math.sqrt(2.0 * phi * stiffness * m_eff) / phi
        force = elastic + gamma * (a0 * i0 + a1 * ic)
        if force <= 0.0:
            return 0.0, (0.0, 0.0, 0.0), 0.0, energy
        moment += gamma * (a0 * ic + a1 * icc)
        kq = radius * moment / force
        q = (
            sigma * hh * n[0] + kq * w[0],
            sigma * hh * n[1] + kq * w[1],
            sigma * hh * n[2] + kq * w[2] - corner,
        )
        ratio = sp / phi
        pivot = radius * math.sqrt(max(0.0, 1.0 - ratio * ratio))
        return force, q, pivot, energy

    return _rim
