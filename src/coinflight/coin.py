"""The coin: a uniform solid cylinder, with presets for real coins."""

from __future__ import annotations

import difflib
from dataclasses import dataclass, field
from types import MappingProxyType

from coinflight import _validation as v
from coinflight.core.rigid_body import principal_moments


@dataclass(frozen=True)
class Coin:
    """A coin modelled as a thin uniform cylinder.

    Parameters
    ----------
    radius : float
        Radius r, m.
    thickness : float
        Thickness h, m.
    mass : float
        Mass m, kg.
    name : str
        A label for reports and figure titles.

    Examples
    --------
    >>> Coin.preset("us-quarter").diameter
    0.02426
    >>> Coin(radius=0.012, thickness=0.0015, mass=0.005).name
    'custom coin'
    """

    radius: float
    thickness: float
    mass: float
    name: str = field(default="custom coin", compare=False)

    def __post_init__(self) -> None:
        for name, unit in (("radius", "m"), ("thickness", "m"), ("mass", "kg")):
            value = v.positive(name, getattr(self, name), unit)
            if value.ndim:
                raise TypeError(
                    f"{name} must be a single number, got an array of shape {value.shape}"
                )
            object.__setattr__(self, name, float(value))

    @classmethod
    def preset(cls, name: str) -> Coin:
        """A real coin by short name, see :data:`PRESETS` (REFERENCES §7)."""
        try:
            return PRESETS[name]
        except KeyError:
            hint = difflib.get_close_matches(str(name), PRESETS, n=1)
            maybe = f" (did you mean {hint[0]}?)" if hint else ""
            raise ValueError(
                f"unknown coin {name!r}{maybe}; known coins: {', '.join(PRESETS)}"
            ) from None

    @classmethod
    def from_mm_g(
        cls, diameter_mm: float, thickness_mm: float, mass_g: float, name: str = "custom coin"
    ) -> Coin:
        """From the units of coin specifications: diameter and thickness in mm, mass in g."""
        d = v.positive("diameter", diameter_mm, "mm")
        return cls(
            radius=float(d) / 2000.0,
            thickness=float(thickness_mm) / 1000.0,
            mass=float(mass_g) / 1000.0,
            name=name,
        )

    @property
    def diameter(self) -> float:
        """Diameter 2r, m."""
        return 2.0 * self.radius

    @property
    def moments(self) -> tuple[float, float]:
        """Principal moments (I1 about a diameter, I3 about the normal), kg m²."""
        i1, i3 = principal_moments(self.radius, self.thickness, self.mass)
        return float(i1), float(i3)

    def describe(self) -> str:
        """One line: name and dimensions in the units people use for coins."""
        return (
            f"{self.name} (d = {self.diameter * 1e3:.2f} mm, h = {self.thickness * 1e3:.2f} mm, "
            f"m = {self.mass * 1e3:.3f} g)"
        )


def _presets() -> dict[str, Coin]:
    # REFERENCES §7: mass g, diameter mm, thickness mm (mint specifications).
    table = [
        ("us-cent", "US cent", 2.500, 19.05, 1.52),
        ("us-nickel", "US nickel", 5.000, 21.21, 1.95),
        ("us-dime", "US dime", 2.268, 17.91, 1.35),
        ("us-quarter", "US quarter", 5.670, 24.26, 1.75),
        ("us-half-dollar", "US half dollar", 11.340, 30.61, 2.15),
        ("eur-1", "€1", 7.50, 23.25, 2.33),
        ("eur-2", "€2", 8.50, 25.75, 2.20),
        ("eur-50c", "€0.50", 7.80, 24.25, 2.38),
        ("gbp-1", "UK £1 (2017)", 8.75, 23.43, 2.80),
    ]
    return {key: Coin.from_mm_g(d, h, m, name=label) for key, label, m, d, h in table}


PRESETS = MappingProxyType(_presets())
"""Real coins by short name (REFERENCES §7)."""

DEFAULT_COIN = "us-quarter"

__all__ = ["DEFAULT_COIN", "PRESETS", "Coin"]
