"""Named distributions of tosses (``--preset NAME``) and of what is not measured about a surface
(``--surface-preset NAME``).

``human``: a person's natural toss, caught in the hand
-------------------------------------------------------
Built from the published measurements (REFERENCES §2, Diaconis, Holmes & Montgomery 2007,
quoting Keller 1986 and their own filmed flips) and modelling choices of ours (the spreads):

=====================  =====================================  ==================================
quantity               value                                  source
=====================  =====================================  ==================================
launch speed v0        normal, mean 2.4 m/s, sd 10 %          mean: Diaconis via Keller (§2);
                       (flight time T = 2 v0 / g ≈ 0.49 s)    spread: our assumption
spin about a diameter  ωx normal, mean 38 rev/s               mean: Diaconis via Keller (§2);
                       (238.8 rad/s), sd 10 %; ωy = 0         spread: our assumption
cone angle ψ           set by ωz: cot ψ = I3 ωz / (I1 ωx),    "near but below 90°"; per-flip
                       ωz normal with mean (I1/I3)·238.8·     p(ψ) 0.500 to 0.545, mean 0.508
                       cot ψ0 and sd half of it, ψ0 = 82.05°  (DHM's filmed flips, §2)
=====================  =====================================  ==================================

The typical angle ψ0 is the one number fitted: it makes the closed-form average of p(ψ)
(:func:`coinflight.studies.bias.expected_same_side`) equal 0.508, the mean DHM report and the pooled
rate Bartoš et al. measured over 350,757 flips (0.5077, REFERENCES §6). It gives ψ with median
82.1° and 95 % of tosses between 74° and 89.8° (a few per cent just above 90°), and per-flip
p(ψ) from 0.500 to about 0.537 (99.5th percentile), as DHM describe. ωz scales with I1/I3 so that
the ψ distribution is the same for every coin. The 10 % spreads make ωp T vary by about 2.6
turns (sd), enough for the phase to be uniform, which is what the closed form assumes; their
values are not published and barely matter (the bias depends on ψ alone). The spread of ωz
(half its mean) sets the spread of ψ and, with ψ0, the range of per-flip p(ψ) above.

Surface presets: what a coin meets on wood or on a table top
-------------------------------------------------------------
No source measures the restitution, the friction or the contact duration of a coin on a table;
the literature gives ranges (below). A surface preset spreads each parameter *uniformly* over
its range (our choice: no source gives a distribution), so that a probability integrates over it
(:meth:`coinflight.model.ensemble.TossDistribution.with_contact`) and quotes a band, not a
point.

==============  ===========  ============  =========================================================
preset          restitution  friction      sources
==============  ===========  ============  =========================================================
coin-on-wood    0.3–0.6      0.2–0.6       e: our band around the single value e = 0.5 that
                                           Pletser (2022, Foundations, doi:10.3390/
                                           foundations2030039, §2.2) assumes for a 50-eurocent
                                           coin; no measured value for a coin is known to us.
                                           μ: wood on metal, clean and dry, static, 0.2–0.6
                                           (Engineering ToolBox, "Friction and Friction
                                           Coefficients", engineeringtoolbox.com/
                                           friction-coefficients-d_778.html).
coin-on-table   0.3–0.6      0.05–0.5      e: as above. μ: from the 0.05 Pletser (2022, §2.2)
                                           assumes for a 50-eurocent coin to 0.5, our choice of
                                           an upper bound (no source we found measures a coin
                                           on a laminate or varnished top).
==============  ===========  ============  =========================================================

The contact duration t_c of an impact (how far apart two rim points may strike and still make
one simultaneous impact, :data:`coinflight.core.impact.CONTACT_DURATION`) is spread too:
5e-5 to 3e-4 s on wood (coin-on-wood) and 2e-5 to 3e-4 s on a table top, which may be wood,
laminate, stone or glass (coin-on-table). Both are Hertz's contact time t_c = 2.87 (m*² /
(R E*² v))^(1/5) (Johnson, *Contact Mechanics*, 1985, §11.4) of a coin's rim (corner radius
≈ 0.3 mm, effective mass m/5, m = 2.3-11 g) striking at 1-3 m/s a surface of modulus E*
0.5-10 GPa (wood across and along the grain: 5e-5 to 3e-4 s) or 50-70 GPa (stone, glass:
2e-5 to 4e-5 s); not measured for coins.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable
from types import MappingProxyType
from typing import Any

from coinflight import _validation as v
from coinflight.core import precession
from coinflight.model.coin import DEFAULT_COIN, Coin
from coinflight.model.distributions import Distribution, Fixed, Normal, Uniform, as_distribution
from coinflight.model.ensemble import TossDistribution
from coinflight.model.toss import STANDARD_GRAVITY, Start

HUMAN_LAUNCH_SPEED = 2.4
"""Upward launch speed of a natural toss, m/s (Diaconis via Keller; REFERENCES §2)."""

HUMAN_SPIN = 38.0 * 2.0 * math.pi
"""Spin of a natural toss, 38 rev/s in rad/s (Diaconis via Keller; REFERENCES §2)."""

HUMAN_RELATIVE_SPREAD = 0.10
"""Standard deviation of launch speed and spin relative to their means (our assumption)."""

HUMAN_PSI = math.radians(82.05)
"""Typical cone angle ψ of a natural toss, rad: the one number fitted, so that the average
p(ψ) over the preset is 0.508 (DHM's mean; Bartoš et al.'s pooled rate)."""

HUMAN_COT_PSI_RELATIVE_SD = 0.5
"""Spread of cot ψ (of ωz) relative to its typical value (keeps ψ mostly below 90°)."""


def human(
    coin: Coin | None = None, start: Start = "heads", g: float = STANDARD_GRAVITY
) -> TossDistribution:
    """A person's natural toss caught in the hand; see the module notes for every number.

    Parameters
    ----------
    coin : Coin, optional
        Default the US quarter.
    start : {"heads", "tails"}
        Face up at launch.
    g : float
        Gravitational acceleration, m/s².

    Returns
    -------
    TossDistribution
        ωx ~ Normal(238.8, 23.9) rad/s, ωy = 0, ωz ~ Normal(μ, μ/2) with
        μ = (I1/I3)·238.8·cot 82.05° rad/s, T = 2 v0 / g with v0 ~ Normal(2.4, 0.24) m/s.
    """
    the_coin = coin if coin is not None else Coin.preset(DEFAULT_COIN)
    i1, i3 = the_coin.moments
    wz = float(precession.axial_spin(HUMAN_SPIN, HUMAN_PSI, i1, i3))
    return TossDistribution.from_launch_speed(
        omega_x=Normal(HUMAN_SPIN, HUMAN_RELATIVE_SPREAD * HUMAN_SPIN),
        omega_y=Fixed(0.0),
        omega_z=Normal(wz, HUMAN_COT_PSI_RELATIVE_SD * wz),
        launch_speed=Normal(HUMAN_LAUNCH_SPEED, HUMAN_RELATIVE_SPREAD * HUMAN_LAUNCH_SPEED),
        coin=the_coin,
        start=start,
        g=g,
    )


PRESETS: MappingProxyType[str, Callable[..., TossDistribution]] = MappingProxyType({"human": human})
"""Toss presets by name: each a factory ``(coin=None, start="heads", g=9.81)``."""


OVERRIDABLE = ("omega_x", "omega_y", "omega_z", "flight_time", "launch_speed")
"""Initial conditions a caller may set on top of a preset (see :func:`preset`)."""


def preset(
    name: str,
    coin: Coin | None = None,
    start: Start = "heads",
    g: float = STANDARD_GRAVITY,
    **overrides: Distribution | float,
) -> TossDistribution:
    """The preset ``name`` for ``coin``, with any initial condition replaced by ``overrides``.

    Parameters
    ----------
    name : str
        A key of :data:`PRESETS`.
    coin, start, g
        Passed to the preset's factory.
    **overrides : Distribution or float
        ``omega_x``, ``omega_y``, ``omega_z`` (rad/s), and one of ``flight_time`` (s) or
        ``launch_speed`` (m/s, T = 2 v0 / g): these replace the preset's own; the others stay.

    Raises
    ------
    ValueError
        For an unknown preset (listing the known ones), an unknown override, or both
        ``flight_time`` and ``launch_speed``.

    Examples
    --------
    >>> preset("human", omega_z=0.0).spin_about_diameter  # the same toss with no precession
    True
    """
    factory = v.known("preset", name, PRESETS)
    unknown = [k for k in overrides if k not in OVERRIDABLE]
    if unknown:
        raise ValueError(
            f"cannot override {', '.join(unknown)} of a preset; allowed: {', '.join(OVERRIDABLE)}"
        )
    if "flight_time" in overrides and "launch_speed" in overrides:
        raise ValueError("give at most one of flight_time and launch_speed")
    dist = factory(coin=coin, start=start, g=g)
    changes: dict[str, Any] = {k: as_distribution(val, k) for k, val in overrides.items()}
    # The flight time given replaces the preset's launch speed, and the other way round.
    if "launch_speed" in changes:
        changes["flight_time"] = None
    elif "flight_time" in changes:
        changes["launch_speed"] = None
    return dataclasses.replace(dist, **changes) if changes else dist


@dataclasses.dataclass(frozen=True)
class SurfacePreset:
    """A named surface: the ranges of its restitution, friction and contact duration, and their
    sources.

    Attributes
    ----------
    name : str
    restitution, friction : Distribution
        Uniform over the literature's range (see the module notes).
    sources : dict
        {"restitution": ..., "friction": ..., "contact_duration": ...}: where each range
        comes from.
    contact_duration : Distribution
        t_c of an impact, s: uniform over Hertz's contact times for the surface (see the
        module notes).
    """

    name: str
    restitution: Distribution
    friction: Distribution
    sources: MappingProxyType[str, str]
    contact_duration: Distribution

    @property
    def contact(self) -> dict[str, Distribution]:
        """{"restitution": ..., "friction": ..., "contact_duration": ...}, for
        :meth:`~coinflight.model.ensemble.TossDistribution.with_contact`."""
        return {
            "restitution": self.restitution,
            "friction": self.friction,
            "contact_duration": self.contact_duration,
        }

    def describe(self) -> str:
        """One line: the name and the three ranges."""
        return (
            f"{self.name}: restitution {self.restitution.describe()}, friction "
            f"{self.friction.describe()}, contact duration {self.contact_duration.describe('s')}"
            " (uniform over the literature's ranges)"
        )

    def to_dict(self) -> dict[str, Any]:
        """JSON: name, the three distributions and the sources."""
        return {
            "name": self.name,
            "restitution": self.restitution.to_dict(),
            "friction": self.friction.to_dict(),
            "contact_duration": self.contact_duration.to_dict(),
            "sources": dict(self.sources),
        }


_RESTITUTION_SOURCE = (
    "0.3-0.6: our band around e = 0.5, the value Pletser (2022, Foundations, "
    "doi:10.3390/foundations2030039, §2.2) assumes for a 50-eurocent coin; "
    "not measured for coins"
)

_DURATION_SOURCE = (
    "{} s: Hertz's contact time (Johnson, Contact Mechanics, 1985, §11.4) of a coin's rim "
    "(corner radius 0.3 mm, effective mass m/5, m = 2.3-11 g) at 1-3 m/s on {}; not measured "
    "for coins"
)

SURFACE_PRESETS: MappingProxyType[str, SurfacePreset] = MappingProxyType(
    {
        "coin-on-wood": SurfacePreset(
            "coin-on-wood",
            Uniform(0.3, 0.6),
            Uniform(0.2, 0.6),
            MappingProxyType(
                {
                    "restitution": _RESTITUTION_SOURCE,
                    "friction": "0.2-0.6: wood on metal, clean and dry, static "
                    "(Engineering ToolBox, 'Friction and Friction Coefficients', "
                    "engineeringtoolbox.com/friction-coefficients-d_778.html)",
                    "contact_duration": _DURATION_SOURCE.format(
                        "5e-05-0.0003", "wood (E* 0.5-10 GPa, across and along the grain)"
                    ),
                }
            ),
            Uniform(5e-5, 3e-4),
        ),
        "coin-on-table": SurfacePreset(
            "coin-on-table",
            Uniform(0.3, 0.6),
            Uniform(0.05, 0.5),
            MappingProxyType(
                {
                    "restitution": _RESTITUTION_SOURCE,
                    "friction": "0.05-0.5: from the 0.05 Pletser (2022, Foundations, "
                    "doi:10.3390/foundations2030039, §2.2) assumes for a 50-eurocent coin "
                    "to 0.5, our upper bound; not measured for coins",
                    "contact_duration": _DURATION_SOURCE.format(
                        "2e-05-0.0003",
                        "a table top of wood (5e-5 to 3e-4 s), laminate, stone or glass "
                        "(E* 50-70 GPa: 2e-5 to 4e-5 s)",
                    ),
                }
            ),
            Uniform(2e-5, 3e-4),
        ),
    }
)
"""Surface presets by name (see the module notes for every number and its source)."""


def surface_preset(name: str) -> SurfacePreset:
    """The surface preset ``name`` (a key of :data:`SURFACE_PRESETS`), else a ValueError
    listing the known ones.

    Examples
    --------
    >>> print(surface_preset("coin-on-wood").describe())  # doctest: +ELLIPSIS
    coin-on-wood: restitution 0.3–0.6, friction 0.2–0.6, contact duration 5e-05–0.0003 s (...)
    """
    return v.known("surface preset", name, SURFACE_PRESETS)


def bouncing_box() -> tuple[tuple[float, float], tuple[float, float]]:
    """((e_low, e_high), (μ_low, μ_high)): the union of the surface presets' boxes
    (:data:`SURFACE_PRESETS`)."""
    presets = list(SURFACE_PRESETS.values())
    e = [b for p in presets for b in p.restitution.bounds]
    mu = [b for p in presets for b in p.friction.bounds]
    return (min(e), max(e)), (min(mu), max(mu))


__all__ = [
    "HUMAN_LAUNCH_SPEED",
    "HUMAN_PSI",
    "HUMAN_SPIN",
    "OVERRIDABLE",
    "PRESETS",
    "SURFACE_PRESETS",
    "SurfacePreset",
    "bouncing_box",
    "human",
    "preset",
    "surface_preset",
]


def psi_range(dist: TossDistribution) -> tuple[float, float, float]:
    """The precession angle ψ (degrees) of a preset's spins: (low, median, high), the ends
    holding 95 % of them, at the median ωx and ωy = 0 (ψ falls as ωz grows).

    ψ is the cone angle between the normal and the angular momentum (Diaconis, Holmes &
    Montgomery 2007; :func:`coinflight.core.torque_free.cone_angle`).
    """
    import numpy as np

    from coinflight.core.torque_free import cone_angle

    u = np.array([0.025, 0.5, 0.975])
    omega = np.stack([dist.omega_x.ppf(0.5 + 0 * u), 0 * u, dist.omega_z.ppf(u)], axis=-1)
    low, median, high = np.degrees(cone_angle(omega, *dist.moments))[::-1]
    return float(low), float(median), float(high)
