"""Exact P(same side) by adaptive quadrature (QUADPACK through :func:`scipy.integrate.quad`
and ``nquad``) over the ranged spins' quantiles of a closed form: the closed form over one
uniform diameter spin inside a quadrature over the other, and the closed form in T inside a
quadrature over one or two spins of any kind (e.g. a truncated normal). Bounded by
:data:`MAX_EVALUATIONS`; chosen by :mod:`coinflight.probability.exact`."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from coinflight.model.distributions import Fixed, Uniform
from coinflight.model.ensemble import TossDistribution
from coinflight.probability.exact.closed_form import (
    MAX_PIECES,
    _check_pieces,
    _closed_form_diameter,
    _p_same_fixed_spins,
)
from coinflight.probability.exact.common import (
    _SPINS,
    TOLERANCE,
    _Details,
)

MAX_EVALUATIONS = 500_000
"""Budget of integrand evaluations for the adaptive quadrature, so that ``exact`` always ends
in bounded time: about 25-30 s on the reference 2-core machine. Only distributions beyond
fixed, uniform and normal spins reach that quadrature now (e.g. a truncated normal spin); past
the budget a ValueError names the sampling methods instead."""


class _OverBudget(Exception):
    """Raised inside the integrand when the quadrature has used its evaluation budget."""


def _quad(f: Callable[..., float], dims: int, details: dict[str, Any]) -> tuple[float, float]:
    """∫ f over [0, 1]^dims by adaptive Gauss–Kronrod (QUADPACK), with its error estimate.

    At most :data:`MAX_EVALUATIONS` evaluations of ``f``; past them a ValueError (the
    tolerance is never loosened). QUADPACK's warnings (round-off prevents the tolerance) are
    kept in ``details["warning"]`` rather than printed: the error estimate is reported either
    way.
    """
    import warnings

    from scipy.integrate import IntegrationWarning, nquad, quad

    budget = MAX_EVALUATIONS
    used = 0

    def counted(*u: float) -> float:
        nonlocal used
        used += 1
        if used > budget:
            raise _OverBudget
        return f(*u)

    opts = {"epsabs": TOLERANCE, "epsrel": TOLERANCE, "limit": 2000}
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", IntegrationWarning)
        try:
            if dims == 1:
                val, err = quad(counted, 0.0, 1.0, **opts)
            else:
                val, err = nquad(counted, [(0.0, 1.0)] * dims, opts=opts)
        except _OverBudget:
            raise ValueError(
                f"the exact quadrature did not reach its tolerance {TOLERANCE:g} within its "
                f"budget of {budget:,} integrand evaluations (a kinked integrand in {dims} "
                "dimensions); use --method qmc, monte-carlo or grid instead"
            ) from None
    details["evaluations"] = used
    messages = [" ".join(str(w.message).split()) for w in caught]
    if messages:
        details["warning"] = messages[0]
    return float(val), float(err)


def _two_diameter_spins_one_uniform(dist: TossDistribution, ranged: list[str]) -> bool:
    """Spin about a diameter, T fixed or uniform, both spins ranged, one of them uniform."""
    return (
        dist.spin_about_diameter
        and isinstance(dist.flight_time, Uniform | Fixed)
        and len(ranged) == 2
        and any(isinstance(getattr(dist, n), Uniform) for n in ranged)
    )


def _closed_form_and_quadrature(
    dist: TossDistribution, ranged: list[str], details: _Details
) -> tuple[float, float]:
    """One uniform spin in closed form, the other by quadrature over its quantiles."""
    t = dist.flight_time
    assert isinstance(t, Fixed | Uniform)  # _two_diameter_spins_one_uniform
    x_name = next(n for n in ranged if isinstance(getattr(dist, n), Uniform))
    c_name = "omega_y" if x_name == "omega_x" else "omega_x"
    x_dist, c_dist = getattr(dist, x_name), getattr(dist, c_name)
    _check_pieces(x_dist, 0.0, t.value if isinstance(t, Fixed) else t.high, MAX_PIECES / 1000)

    def inner(u: float) -> float:
        return _closed_form_diameter(x_dist, float(c_dist.ppf(u)), t, MAX_PIECES / 1000)

    return _quad(inner, 1, details)


def _spins_by_quadrature(dist: TossDistribution, ranged: list[str]) -> bool:
    """T ranged and at most two ranged spins."""
    return not isinstance(dist.flight_time, Fixed) and len(ranged) <= 2


def _closed_form_in_t_quadrature(
    dist: TossDistribution, ranged: list[str], details: _Details
) -> tuple[float, float]:
    """The band integral over T in closed form, quadrature over the ranged spins' quantiles."""
    i1, i3 = dist.moments
    spins = {name: getattr(dist, name) for name in _SPINS}

    def integrand(*u: float) -> float:
        w = {n: spins[n].mean for n in _SPINS}
        for name, ui in zip(ranged, u, strict=True):
            w[name] = float(spins[name].ppf(ui))
        return _p_same_fixed_spins(
            w["omega_x"], w["omega_y"], w["omega_z"], dist.flight_time, i1, i3
        )

    return _quad(integrand, len(ranged), details)
