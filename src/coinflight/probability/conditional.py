"""P(same side) given the spins, in closed form over the flight time: the conditioning that the
exact method, and the ``conditional-on-spin`` variance reduction of Monte Carlo and QMC, share.

Conditional on the spins (ωx, ωy, ω_z), the coin shows its starting face iff the phase ωp T lies
in the bands (2πm − a, 2πm + a) (Diaconis, Holmes & Montgomery 2007, section 2;
:mod:`coinflight.core.bands`). Over the flight-time distribution that measure is closed form:
the band indicator for a fixed T, the band length over [t1, t2] for a uniform T
(:func:`~coinflight.core.bands.time_average_uniform`), the wrapped-normal series or normal-CDF
differences for a normal T (:func:`~coinflight.core.bands.same_side_normal_time`). Averaging it
over random spins instead of averaging the 0/1 outcome over random (spins, T) is conditional
Monte Carlo (Rao–Blackwellisation): the same mean, a variance never larger (Robert & Casella
2004, Monte Carlo Statistical Methods, §4.2).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from coinflight.core import bands
from coinflight.model.distributions import Distribution, Fixed, Normal, Uniform, unit_cube_values
from coinflight.model.ensemble import TossDistribution
from coinflight.probability.result import ProbabilityResult, from_same_side, interval, sampled

if TYPE_CHECKING:
    from coinflight.outcomes.base import OutcomeModel

FloatArray = NDArray[np.float64]

SPINS = ("omega_x", "omega_y", "omega_z")
"""The spin components, in the order of :data:`coinflight.model.ensemble.PARAMETERS`."""

MODE = "conditional-on-spin"
"""The name of this variance reduction (results' ``details["variance_reduction"]``)."""


def ranged_spins(dist: TossDistribution) -> tuple[str, ...]:
    """The ranged spin components (the flight time left out), in :data:`SPINS` order."""
    return tuple(name for name in SPINS if not getattr(dist, name).is_fixed)


def check_flight_time(t: Distribution) -> None:
    """ValueError unless the closed form over T exists for ``t`` (fixed, uniform, normal)."""
    if not isinstance(t, Fixed | Uniform | Normal):
        raise ValueError(
            f"the conditional-on-spin mode needs a fixed, uniform or normal flight time, got "
            f"{type(t).__name__}"
        )


def check(
    dist: TossDistribution, model: OutcomeModel, method: str, grid_cells: int | None = None
) -> None:
    """ValueError unless ``method`` can run in this mode: ``model`` has closed-form bands (the
    hand catch), no grid cells (Monte Carlo's method B), a flight time with a closed form."""
    if not model.closed_form_bands:
        raise ValueError(
            f"the {MODE} variance reduction needs the hand catch's closed-form "
            f"bands, not {model.name}; use {method} without it"
        )
    if grid_cells is not None:
        raise ValueError(f"grid cells (method B) do not combine with {MODE}")
    check_flight_time(dist.flight_time)


def same_side_given_spins(
    dist: TossDistribution, wx: FloatArray, wy: FloatArray, wz: FloatArray
) -> FloatArray:
    """P(same side | spins) over ``dist``'s flight time, for arrays of spins (rad/s)."""
    i1, i3 = dist.moments
    perp2 = wx * wx + wy * wy
    axial2 = (i3 / i1 * wz) ** 2
    t = dist.flight_time
    if isinstance(t, Normal):
        return bands.same_side_normal_time(perp2, axial2, t.mean, t.sd)
    turns, wp, a = bands.precession_bands(perp2, axial2)
    if isinstance(t, Uniform):
        inside = bands.time_average_uniform(wp, a, t.low, t.high)
    else:
        check_flight_time(t)
        inside = bands.in_band(wp * t.mean, a).astype(float)
    return np.where(turns, inside, 1.0)


def spins_from_unit(dist: TossDistribution, u: FloatArray) -> tuple[FloatArray, ...]:
    """Spins (wx, wy, wz) for points ``u`` of shape (len(ranged_spins), m) of the unit cube."""
    spins = {name: getattr(dist, name) for name in SPINS}
    return tuple(unit_cube_values(spins, ranged_spins(dist), u).values())


def same_side_at(dist: TossDistribution, u: FloatArray) -> FloatArray:
    """P(same side | spins) at points ``u`` of the spins' unit cube (:func:`spins_from_unit`)."""
    return same_side_given_spins(dist, *spins_from_unit(dist, u))


def details(dist: TossDistribution) -> dict[str, Any]:
    """The mode's entries of a result's ``details``: its name and the ranged spins."""
    return {"variance_reduction": MODE, "spins": list(ranged_spins(dist))}


def result(
    dist: TossDistribution,
    same: float,
    stderr: float,
    half: float,
    *,
    method: str,
    n: int,
    root: np.random.SeedSequence,
    t0: float,
    details: dict[str, Any],
) -> ProbabilityResult:
    """The result of ``method`` in this mode from P(same side) ``same``, its standard error and
    the half-width ``half`` of its 95 % interval (no counts: averages of probabilities)."""
    p = same if dist.start_sign > 0 else 1.0 - same
    fields = sampled(n, stderr, interval(p, half), root, t0)
    return from_same_side(same, dist.start_sign, method, **fields, details=details)


__all__ = [
    "MODE",
    "SPINS",
    "check",
    "check_flight_time",
    "details",
    "ranged_spins",
    "result",
    "same_side_at",
    "same_side_given_spins",
    "spins_from_unit",
]
