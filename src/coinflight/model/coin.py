"""The coin: a uniform solid cylinder, with presets for real coins."""

from __future__ import annotations

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
    corner_radius : float
        Radius a of the rounded corners of the rim, m, 0 ≤ a ≤ min(h/2, r) (default 0: sharp
        corners): the coin is then a cylinder of radius r − a and thickness h − 2a swept by a
        ball of radius a. Not measured for any coin (worn coins are rounder than new ones): carry a
        band, not a value. Only a table landing reads it
        (:meth:`coinflight.core.contact.Contact.build`): the flight's contacts, the impacts
        and the rigid ending touch the table with the rounded rim, and every landing's
        face/edge wells (the energy barrier and the edge angle) are the rounded coin's (see
        :class:`coinflight.core.contact.Contact`).

    Examples
    --------
    >>> Coin.preset("us-quarter").diameter
    0.02426
    >>> Coin(radius=0.012, thickness=0.0015, mass=0.005).name
    'custom coin'
    >>> Coin(radius=0.012, thickness=0.0015, mass=0.005, corner_radius=0.001)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: corner radius must be between 0 and 0.00075 (in m), got 0.001: at most half...
    """

    radius: float
    thickness: float
    mass: float
    name: str = field(default="custom coin", compare=False)
    corner_radius: float = 0.0

    def __post_init__(self) -> None:
        odd = []
        for quantity in (RADIUS, THICKNESS, MASS):
            value = quantity.check(getattr(self, quantity.name))
            object.__setattr__(self, quantity.name, value)
            if not quantity.is_usual(value):
                odd.append((quantity, value))
        v.instance("name", self.name, str, "a string")
        object.__setattr__(
            self,
            "corner_radius",
            check_corner_radius(self.corner_radius, self.thickness, self.radius),
        )
        if odd:
            v.warn_unusual(_unusual_coin(odd), stacklevel=3)

    @classmethod
    def preset(cls, name: str) -> Coin:
        """A real coin by short name in any case (``US-Cent`` is ``us-cent``), see
        :data:`PRESETS` (REFERENCES §7); an unknown name is refused as typed, the names listed."""
        if isinstance(name, str):
            folded = {key.casefold(): key for key in PRESETS}
            name = folded.get(name.casefold(), name)
        return v.known("coin", name, PRESETS)

    @classmethod
    def from_mm_g(
        cls, diameter_mm: float, thickness_mm: float, mass_g: float, name: str = "custom coin"
    ) -> Coin:
        """From the units of coin specifications: diameter and thickness in mm, mass in g.

        >>> Coin.from_mm_g(diameter_mm=24.26, thickness_mm=1.75, mass_g=5.67).radius
        0.01213
        """
        d = v.number("diameter_mm", diameter_mm, "mm")
        h = v.number("thickness_mm", thickness_mm, "mm")
        m = v.number("mass_g", mass_g, "g")
        return cls(radius=d / 2000.0, thickness=h / 1000.0, mass=m / 1000.0, name=name)

    @property
    def diameter(self) -> float:
        """Diameter 2r, m."""
        return 2.0 * self.radius

    @property
    def moments(self) -> tuple[float, float]:
        """Principal moments (I1 about a diameter, I3 about the normal), kg m²."""
        i1, i3 = principal_moments(self.radius, self.thickness, self.mass)
        return float(i1), float(i3)

    def with_corner_radius(self, corner_radius: float) -> Coin:
        """The same coin with rim corners rounded to ``corner_radius`` a, m (0 ≤ a ≤ min(h/2, r)).

        >>> Coin.preset("us-nickel").with_corner_radius(3e-4).corner_radius
        0.0003
        """
        import dataclasses

        return dataclasses.replace(self, corner_radius=corner_radius)

    def to_dict(self) -> dict[str, object]:
        """JSON-ready: name, radius (m), thickness (m), mass (kg) and, when not 0, the corner
        radius (m; left out for sharp corners, so that the JSON of every other coin, and the
        random streams of sweep rows keyed on it, stay as they were).

        >>> Coin.preset("us-quarter").to_dict()["radius"]
        0.01213
        """
        out: dict[str, object] = {
            "name": self.name,
            "radius": self.radius,
            "thickness": self.thickness,
            "mass": self.mass,
        }
        if self.corner_radius:
            out["corner_radius"] = self.corner_radius
        return out

    def describe(self) -> str:
        """One line: name and dimensions in the units people use for coins."""
        corner = (
            f", corner radius a = {self.corner_radius * 1e3:.3g} mm" if self.corner_radius else ""
        )
        return (
            f"{self.name} (d = {self.diameter * 1e3:.2f} mm, h = {self.thickness * 1e3:.2f} mm, "
            f"m = {self.mass * 1e3:.3f} g{corner})"
        )


RADIUS = v.Quantity("radius", "m", 1e-6, 1e3, (1e-3, 0.1), "a coin's size (1 mm to 10 cm)")
"""Radius: hard range 1 µm to 1 km (the moments r² m stay far from underflow and overflow), a
warning outside 1 mm to 10 cm (the largest circulating coins are about 5 cm across)."""
THICKNESS = v.Quantity(
    "thickness", "m", 1e-6, 1e3, (1e-4, 0.05), "a coin's thickness (0.1 mm to 5 cm)"
)
"""Thickness: hard range 1 µm to 1 km, a warning outside 0.1 mm to 5 cm (bullion coins reach a
few cm; millimetres given as metres land near 1 m)."""
MASS = v.Quantity("mass", "kg", 1e-9, 1e6, (1e-4, 1.0), "a coin's mass (0.1 g to 1 kg)")
"""Mass: hard range 1 µg to 1000 t, a warning outside 0.1 g to 1 kg."""


def check_corner_radius(
    value: object, thickness: float, radius: float, name: str = "corner radius"
) -> float:
    """``value`` (m) as a float between 0 and the smaller of half the ``thickness`` and the
    ``radius`` (a rim corner rounded by a is the cylinder (r − a, h/2 − a) swept by a ball of
    radius a, which needs both to be ≥ 0), but not a = r = h/2, a ball, which has no faces nor
    edge to land on; else TypeError or a ValueError naming ``name``, the value and the range."""
    arr = v.as_float_array(name, value)  # type: ignore[arg-type]
    if arr.ndim:
        raise TypeError(f"{name} must be a single number, got an array of shape {arr.shape}")
    half = 0.5 * thickness
    why = "half the thickness h/2" if half <= radius else "the radius r (a coin thicker than wide)"
    try:
        corner = float(v.in_range(name, arr, 0.0, min(half, radius), "m"))
    except ValueError as exc:
        raise ValueError(f"{exc}: at most {why}") from None
    if corner > 0.0 and corner == half == radius:
        raise ValueError(
            f"{name} must be below {corner:g} m for a coin as thick as it is wide, got "
            f"{corner:g}: a = r = h/2 is a ball, which has no faces"
        )
    return corner


def _unusual_coin(odd: list[tuple[v.Quantity, float]]) -> str:
    """One warning for the coin's unusual dimensions, with the likely unit mix-up."""
    guesses = []
    if any(q is not MASS and value > q.high_usual for q, value in odd):
        guesses.append("millimetres")
    if any(q is MASS and value > q.high_usual for q, value in odd):
        guesses.append("grams")
    ask = f"did you give {' and '.join(guesses)}? " if guesses else ""
    what = "; ".join(f"{q.describe(value)} is not {q.usual_text}" for q, value in odd)
    return f"{what}: {ask}Coin takes m and kg; see Coin.from_mm_g for mm and g"


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

__all__ = [
    "DEFAULT_COIN",
    "MASS",
    "PRESETS",
    "RADIUS",
    "THICKNESS",
    "Coin",
    "check_corner_radius",
]
