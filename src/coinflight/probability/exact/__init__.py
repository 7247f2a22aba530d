"""Exact P(heads): integrate the measure of the heads bands instead of sampling.

This module chooses the integral (``_CASES``, the first that applies) and runs it, or
estimates its cost beforehand (:func:`estimated_seconds`); each
integral lives in a module of its own beside it: :mod:`.closed_form` (the band sums),
:mod:`.quadrature` (adaptive QUADPACK over the spins' quantiles), :mod:`.gauss` (the Gauss
product rule over the spins for a normal flight time), :mod:`.omega_psi` (Gauss–Legendre in
(Ω, ψ)); :mod:`.common` holds what they share (the tolerance, the spin densities).

Which integral is used (``details["how"]``):

* ``closed form``: ω_z = 0 (the paper's cases a and b), the flight time uniform or fixed, at
  most one of ωx, ωy a uniform range and the other fixed. A finite sum over the band pieces
  (:func:`coinflight.core.bands.diameter_spin_integral`); error at rounding level (~1e-14).
  (:mod:`.closed_form`)
* ``closed form in T``: every spin fixed (precession allowed), any flight-time distribution
  with a CDF: Σ over bands of CDF(hi) − CDF(lo). (:mod:`.closed_form`)
* ``closed form in one spin, quadrature in the other``: ω_z = 0, T fixed or uniform, both
  ωx and ωy ranged, one of them uniform: the closed form over the uniform one inside an
  adaptive quadrature over the other's quantiles (:mod:`.quadrature`).
* ``closed form in T, Gauss product rule over the spins split at ψ = 45°``: a normal flight
  time (or launch speed) with one or two ranged spins (uniform or normal; where this rule
  refuses, the (Ω, ψ) rule below runs instead and ``details["fallback"]`` says why):
  P(same side | spins) over T as the wrapped-normal series
  (:func:`coinflight.core.bands.same_side_normal_time`), then
  Gauss–Legendre panels over the spins with the kink at ψ = 45° put on a coordinate (ω_z
  inner, or the radius of polar coordinates in (ωx, ωy) when ω_z is fixed ≠ 0 or the cone's
  apex or a uniform ω_z's rims lie in the box) and smoothed by a change of variable; node
  counts raised until two agree within 1e-9 (their difference is the error estimate), else a
  ValueError. The work of the first two orders is bounded before anything is computed.
  (:mod:`.gauss`)
* ``closed form in T, Gauss–Legendre over the spins in (Ω, ψ)``: a fixed or uniform flight
  time (or launch speed) with any ranged spins (uniform or normal, up to all three), e.g.
  precession with a fixed T, or all four parameters ranged; and a normal flight time with
  three ranged spins (the wrapped-normal series as the inner function, 2-100x faster than
  the product rule there, and equal to it within 1e-10). P(same side | spins) depends on
  Ω = √(Ω⊥² + ((I3/I1) ω_z)²) and ψ only; the azimuth of (ωx, ωy) is integrated out in closed
  form (a uniform box's arc length, a fixed component's Jacobian) or by an interpolant (a
  normal component), ω_z's sign folded, and the rest integrated over Ω (inner, cut at every
  band edge, box corner and range end, all explicit in Ω) and ψ ∈ (45°, 90°] (outer, cut
  where those curves cross) by Gauss–Legendre through a smoothstep; node counts raised until
  two agree within 1e-9. ``details["spin integral"]`` says which form
  ran ("2-D", "axial fixed", "plane fixed" or "diameter"). (:mod:`.omega_psi`)
* ``quadrature``: otherwise (spins of another kind, e.g. a truncated normal), with at most two
  ranged spin components and a ranged flight time: adaptive quadrature
  (``scipy.integrate.quad``) over the ranged spins, in probability space (u = CDF(ω)), of the
  closed form in T. The error estimate is reported. (:mod:`.quadrature`)
* Anything else (distributions other than fixed, uniform and normal beyond those): a
  ValueError naming the methods to use instead.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass

from coinflight.core import bands
from coinflight.model.distributions import Fixed, Normal, Uniform
from coinflight.model.ensemble import TossDistribution
from coinflight.outcomes.base import OutcomeModel
from coinflight.probability.exact.closed_form import (
    MAX_PIECES,
    PIECES_PER_SECOND,
    _closed_form,
    _closed_form_in_t,
    _one_uniform_diameter_spin,
)
from coinflight.probability.exact.common import _SPINS, _USE_INSTEAD, TOLERANCE, _Details
from coinflight.probability.exact.gauss import (
    GAUSS_ORDERS,
    MAX_PANELS,
    MAX_SPIN_POINTS,
    SPIN_POINTS_PER_SECOND,
    _gauss_applies,
    _gauss_points,
    _gauss_spins,
    _resolution,
)
from coinflight.probability.exact.omega_psi import (
    _OMEGA_PSI,
    MAX_CROSSING_SAMPLES,
    MAX_POLAR_POINTS,
    POLAR_ORDERS,
    POLAR_POINTS_PER_SECOND,
    _omega_psi,
    _omega_psi_applies,
    _polar_seconds,
    _times,
)
from coinflight.probability.exact.quadrature import (
    MAX_EVALUATIONS,
    _closed_form_and_quadrature,
    _closed_form_in_t_quadrature,
    _spins_by_quadrature,
    _two_diameter_spins_one_uniform,
)
from coinflight.probability.registry import Estimator
from coinflight.probability.result import ProbabilityResult, from_same_side

__all__ = [
    "GAUSS_ORDERS",
    "MAX_CROSSING_SAMPLES",
    "MAX_EVALUATIONS",
    "MAX_PANELS",
    "MAX_PIECES",
    "MAX_POLAR_POINTS",
    "MAX_SPIN_POINTS",
    "NAME",
    "PIECES_PER_SECOND",
    "POLAR_ORDERS",
    "POLAR_POINTS_PER_SECOND",
    "SPIN_POINTS_PER_SECOND",
    "TOLERANCE",
    "estimate",
    "estimated_seconds",
]

NAME = "exact"
"""The method's name (its registry entry, results, messages)."""


def _gauss_or_omega_psi(
    dist: TossDistribution, ranged: list[str], details: _Details
) -> tuple[float, float]:
    """The Gauss product rule over the spins (:func:`_gauss_spins`, fastest with a normal T and
    one or two ranged spins); where it refuses (not converged, or over its budget), the
    (Ω, ψ) rule (:func:`_omega_psi`), e.g. ωx and ω_z ranged across 0 with a narrow T. If
    both refuse, the Gauss rule's reason is given."""
    try:
        return _gauss_spins(dist, ranged, details)
    except ValueError as gauss_error:
        fallback: _Details = {}
        try:
            result = _omega_psi(dist, ranged, fallback)
        except ValueError:
            raise gauss_error from None
        details.clear()
        details.update(fallback, how=_OMEGA_PSI, fallback=f"the Gauss rule refused: {gauss_error}")
        return result


_FEW_TERMS = 1e-4
"""Seconds of an integral that is a sum of a few terms."""


def _closed_form_seconds(dist: TossDistribution, ranged: list[str]) -> float:
    """The closed form's band pieces at their measured rate (one uniform spin), else a sum of
    a few terms."""
    x = getattr(dist, ranged[0]) if ranged else None
    if not isinstance(x, Uniform):
        return _FEW_TERMS
    t2 = _times(dist.flight_time)[1]
    pieces = bands.diameter_spin_pieces(0.0, max(abs(x.low), abs(x.high)), 0.0, t2)
    return _FEW_TERMS + 2.0 * pieces / PIECES_PER_SECOND


def _gauss_seconds(dist: TossDistribution, ranged: list[str]) -> float:
    """The spin points of the Gauss rule's first two orders at their measured rate."""
    h = _resolution(dist, ranged)
    points = sum(_gauss_points(dist, ranged, h, n) for n in GAUSS_ORDERS[:2])
    return points / SPIN_POINTS_PER_SECOND


def _not_estimated(dist: TossDistribution, ranged: list[str]) -> None:
    """An adaptive quadrature: it ends within its own bound, unestimated."""
    return None


@dataclass(frozen=True)
class _Case:
    """One integral of the exact method: its name in ``details["how"]``, whether it applies to
    a distribution (with its ranged spins), the integral, and its cost in seconds counted
    before it runs (None: not estimated; a ValueError: refused)."""

    how: str
    applies: Callable[[TossDistribution, list[str]], bool]
    run: Callable[[TossDistribution, list[str], _Details], tuple[float, float]]
    seconds: Callable[[TossDistribution, list[str]], float | None]


_CASES = (
    _Case("closed form", _one_uniform_diameter_spin, _closed_form, _closed_form_seconds),
    _Case(
        "closed form in T",
        lambda dist, ranged: not ranged,
        _closed_form_in_t,
        lambda dist, ranged: _FEW_TERMS,
    ),
    _Case(
        "closed form in one spin, quadrature in the other",
        _two_diameter_spins_one_uniform,
        _closed_form_and_quadrature,
        _not_estimated,
    ),
    _Case(
        "closed form in T, Gauss product rule over the spins split at ψ = 45°",
        _gauss_applies,
        _gauss_or_omega_psi,
        _gauss_seconds,
    ),
    _Case(_OMEGA_PSI, _omega_psi_applies, _omega_psi, lambda dist, ranged: _polar_seconds(dist)),
    _Case(
        "closed form in T, quadrature over the spins",
        _spins_by_quadrature,
        _closed_form_in_t_quadrature,
        _not_estimated,
    ),
)
"""The integrals this method does, in order of preference; the first that applies runs."""


def _case(dist: TossDistribution, model: OutcomeModel | None) -> tuple[_Case | None, list[str]]:
    """The integral for ``dist`` (None if none applies) and its ranged spins; a ValueError for
    a model without closed-form bands."""
    if model is not None and not model.closed_form_bands:
        raise ValueError(
            f"the exact method handles the hand catch only, not {model.name}; " + _USE_INSTEAD
        )
    ranged = [name for name in _SPINS if not getattr(dist, name).is_fixed]
    return next((case for case in _CASES if case.applies(dist, ranged)), None), ranged


def _refusal(dist: TossDistribution, ranged: list[str]) -> str:
    """Why no exact integral here handles the distribution, and what to use instead."""
    odd = [
        f"{name} ({type(d).__name__})"
        for name in (*_SPINS, "flight_time")
        if not isinstance(d := getattr(dist, name), Fixed | Uniform | Normal)
    ]
    return (
        "the exact method integrates fixed, uniform and normal distributions only, not "
        f"{', '.join(odd) or 'this one'}; {_USE_INSTEAD}"
    )


def estimate(dist: TossDistribution, *, model: OutcomeModel | None = None) -> ProbabilityResult:
    """Exact P(heads) for the hand catch; see the module notes for what is supported.

    The first of the integrals in ``_CASES`` that applies to the distribution is done.

    Raises
    ------
    ValueError
        For distributions that no exact integral here handles, naming the methods to use.
    """
    t0 = time.perf_counter()
    case, ranged = _case(dist, model)
    if case is None:
        raise ValueError(_refusal(dist, ranged))
    details: _Details = {}
    p_same, error = case.run(dist, ranged, details)
    details.setdefault("how", case.how)  # a runner that fell back to another integral says so
    return from_same_side(
        min(1.0, max(0.0, p_same)),
        dist.start_sign,
        NAME,
        error_estimate=error,  # a deterministic result: no 95 % interval
        elapsed=time.perf_counter() - t0,
        details=details,
    )


def estimated_seconds(dist: TossDistribution, model: OutcomeModel | None = None) -> float | None:
    """Seconds the exact method will take on ``dist`` (2-core reference machine), from the
    work of the integral that would run, counted before it runs: its band pieces, spin points
    or integrand points (the first two orders, the least that gives an error estimate) at
    the measured rates. None where no estimate is made (the adaptive quadrature, a model
    other than the hand catch, a distribution refused or over budget: those end early or
    within their own bound). For a sweep's work bound
    (:func:`coinflight.probability.sweep.check_sweep_work`)."""
    if model is not None and not model.closed_form_bands:
        return None
    case, ranged = _case(dist, model)
    if case is None:
        return None
    try:
        return case.seconds(dist, ranged)
    except ValueError:
        return None


ESTIMATOR = Estimator(NAME, estimate, "exact value", "band integral (Keller 1986)", parallel=False)
