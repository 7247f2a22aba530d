"""Where the coin ends and what slows it: the landing surface and the air, as value objects."""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, fields
from types import MappingProxyType
from typing import Any

from coinflight import _validation as v
from coinflight.model.distributions import (
    Distribution,
    Fixed,
    Normal,
    TruncatedNormal,
    as_distribution,
)

AIR_DENSITY = 1.2
"""Density of air at 20 °C and sea level, kg/m³ (ISO 2533 standard atmosphere: 1.204)."""

DEFAULT_RESTITUTION = 0.5
"""Coefficient of restitution of a coin on a wooden table: 0.5, the value Pletser (2022,
Foundations, doi:10.3390/foundations2030039) assumes; not measured for coins."""

DEFAULT_FRICTION = 0.3
"""Coulomb friction coefficient of metal on wood: 0.3, inside the 0.2-0.6 static range tabulated
for wood on metal, clean and dry (Engineering ToolBox); not measured for coins."""

MAX_FRICTION = 3.0
"""Largest Coulomb friction coefficient μ a surface takes, far above what a coin meets (0.2-0.6,
metal on wood: :data:`DEFAULT_FRICTION`): the range the landing models are validated over
(tests/test_impact.py's impact-law properties draw μ up to it), not a physical limit. Far
beyond, the impact law's cone |P_t| ≤ μ P_n can no longer be told from
the rounding of P_n (μ ≳ 1e11), and near the largest float μ P_n overflows (the contact point
left moving into the table)."""

DEFAULT_ROLLING_RESISTANCE = 1e-4
"""Rolling resistance ℓ_r of a coin's rim on a table, m: an assumption. No source measures it
for a coin (REFERENCES §5); 1e-4 m is MuJoCo's default rolling friction (XML reference,
``geom/@friction``), and 1e-5 to 1e-3 m the band to carry (a hard rim on hard wood to a rim
sinking into a varnish or a cloth)."""

RESISTANCE_BAND = (1e-5, 1e-3)
"""The plausible range of the rolling and pivoting resistance of a coin's rim on a table, m
(:data:`DEFAULT_ROLLING_RESISTANCE` gives why): the band a table result is quoted over."""

DEFAULT_PIVOTING_RESISTANCE = 1e-4
"""Pivoting (drilling) resistance ℓ_p of a coin's rim on a table, m (the rigid ending's contact
is a point, with no drilling friction of its own): an assumption, as the rolling resistance
(band 1e-5 to 1e-3 m; MuJoCo's default torsional friction, 5e-3 m, is half a coin's radius)."""

DEFAULT_CONTACT_DURATION = 1e-4
"""Contact duration t_c of one impact of a coin's rim on a table, s: how far apart in time two
rim points may strike and still make one simultaneous impact
(:data:`coinflight.core.impact.CONTACT_DURATION`, the same number, where its derivation is;
a literal here so that ``import coinflight`` stays free of numba; Hertz's
contact time, Johnson 1985 §11.4, for a coin's rim on wood 5e-5 to 3e-4 s, on stone or glass
2e-5 to 4e-5 s); not measured for coins."""

TABLE_ONLY = (
    "applies to --surface table only (Surface(kind='table') in Python), not to a catch in the "
    "hand (--surface hand, the default): the hand catches the coin at the launch height, with "
    "no bounce or ending"
)
"""The one refusal of a table's option given to a catch in the hand, after what was given
(``--restitution applies to …`` on the command line, ``drop height 0.8 m, restitution 0.5
applies to …`` from :class:`Surface`)."""

TABLE_PARAMETERS = (
    "drop_height",
    "restitution",
    "friction",
    "rolling_resistance",
    "pivoting_resistance",
    "contact_duration",
    "corner_radius",
    "max_bounces",
)
"""What a surface kind may take beyond its name, in the order a refusal names them: the
:class:`Surface` fields ``drop_height``, ``restitution``, ``friction``,
``rolling_resistance``, ``pivoting_resistance`` and ``contact_duration``, the coin's rounded
rim ``corner_radius`` (the command line's --corner-radius) and ``max_bounces`` (--bounces). A
table takes them all, a catch in the hand none; an outcome model declares those it reads
(:attr:`coinflight.outcomes.base.OutcomeModel.surface_parameters`), and a :class:`Surface` of
its kind refuses any other given."""


@dataclass(frozen=True)
class SurfaceKind:
    """A kind of surface a toss may end on: a name of :func:`surface_kinds`.

    Registered by :func:`coinflight.outcomes.register` (the built-ins, ``"hand"`` and
    ``"table"``, when :mod:`coinflight.outcomes` is imported, which ``import coinflight``
    does), and read by :class:`Surface`, the command line's --surface and the web API.

    Attributes
    ----------
    name : str
        What ``Surface(kind=...)``, --surface and the API's ``surface=`` call it.
    summary : str
        One line: how a toss ends there (--surface's help, the page's menu).
    takes : tuple of str
        Which of :data:`TABLE_PARAMETERS` it reads; a :class:`Surface` of this kind refuses
        the others given.
    refusal : str
        The words after what was given that it does not take (``restitution 0.7 …``).
    build : callable
        ``(surface, drag, max_bounces) -> OutcomeModel``, for
        :func:`coinflight.outcomes.outcome_model`.
    model : type
        The outcome model's class (:class:`coinflight.outcomes.base.OutcomeModel`).
    """

    name: str
    summary: str
    takes: tuple[str, ...]
    refusal: str
    build: Callable[..., Any]
    model: type[Any]


_SURFACE_KINDS: dict[str, SurfaceKind] = {}


def surface_kinds() -> Mapping[str, SurfaceKind]:
    """The registered surface kinds by name, in the order registered (read-only; changed by
    :func:`coinflight.outcomes.register` and :func:`coinflight.outcomes.unregister`)."""
    return MappingProxyType(_SURFACE_KINDS)


def surface_kind(name: object) -> SurfaceKind:
    """The registered surface kind ``name``; ValueError naming the registered ones."""
    v.choice("surface", name, _SURFACE_KINDS)
    return _SURFACE_KINDS[str(name)]


def add_surface_kind(kind: SurfaceKind) -> None:
    """Add or replace ``kind`` (through :func:`coinflight.outcomes.register`, which checks it)."""
    _SURFACE_KINDS[kind.name] = kind


def remove_surface_kind(name: str) -> None:
    """Remove the kind ``name`` (:func:`coinflight.outcomes.unregister`); nothing if none."""
    _SURFACE_KINDS.pop(name, None)


class _Unset(float):
    """A contact parameter the caller did not give: its default value, marked as such.

    A catch in the hand refuses a drop height, restitution, friction or resistance given to it
    (:data:`TABLE_ONLY`), but keeps the defaults. The mark is a float (the kernels and JSON
    see the plain default) that :func:`dataclasses.replace`, pickling and
    :func:`dataclasses.asdict` (its deep copy keeps the subclass) pass back unchanged, so a copy
    of a surface, or one rebuilt from its fields, is not refused; ``repr`` leaves the marked
    defaults out (:meth:`Surface.__repr__`), so its text rebuilds the surface too.
    """

    __slots__ = ()


_UNSET_DROP = _Unset(0.0)
_UNSET_RESTITUTION = _Unset(DEFAULT_RESTITUTION)
_UNSET_FRICTION = _Unset(DEFAULT_FRICTION)
_UNSET_ROLLING = _Unset(DEFAULT_ROLLING_RESISTANCE)
_UNSET_PIVOTING = _Unset(DEFAULT_PIVOTING_RESISTANCE)
_UNSET_DURATION = _Unset(DEFAULT_CONTACT_DURATION)

ROLLING_RESISTANCE = v.Quantity("rolling resistance", "m", 0.0, 0.01)
"""ℓ_r: 0 to 1 cm (a coin's radius: a torque ℓ F_n above that stops any rolling at once)."""
PIVOTING_RESISTANCE = v.Quantity("pivoting resistance", "m", 0.0, 0.01)
"""ℓ_p: 0 to 1 cm, as the rolling resistance."""
CONTACT_DURATION = v.Quantity("contact duration", "s", 1e-6, 1e-2)
"""t_c of an impact (:data:`DEFAULT_CONTACT_DURATION`): 1 μs to 10 ms. Hertz's contact time of
a coin's rim is 2e-5 s on stone or glass and 3e-4 s on soft wood; 1 μs is twenty times
shorter than the stiffest table's (and a positive t_c keeps the simultaneous impact: 0 would be
the sequential rigid law and its falling-rod paradox), 10 ms thirty times longer than the
softest's (beyond it, the fall the simultaneous impact leaves out over t_c, g t_c² / 2 ≈ 0.5
mm at 10 ms, is a quarter of a coin's thickness)."""


DROP_HEIGHT = v.Quantity("drop height", "m", 0.0, 1e3)
"""How far below launch the table lies: 0 to 1 km (the fall stays seconds to minutes long,
even at the smallest g, and the bounce kernel's times finite)."""


DRAG_COEFFICIENT = v.Quantity("drag coefficient", "", 0.0, 10.0)
"""C_d: 0 to 10 (a flat disc broadside on is 1.17, no shape reaches 3; 1e308 overflowed)."""
SPIN_DAMPING = v.Quantity("spin damping", "N m s", 0.0, 1e-3)
"""k: 0 to 10⁻³ N m s. A quarter's spin decays at k / I1 ≈ 4600 /s at the top, stopping within
a millisecond; far beyond (k = 1) the integration of a table landing is too stiff to end."""
AIR_DENSITY_RANGE = v.Quantity("air density", "kg/m³", 1e-6, 1e4)
"""ρ: 10⁻⁶ to 10⁴ kg/m³ (thin air on Mars is 0.02, water 1000)."""


def _single(name: str, value: float, low: float, high: float) -> float:
    arr = v.in_range(name, value, low, high)
    if arr.ndim:
        raise TypeError(f"{name} must be a single number, got an array of shape {arr.shape}")
    return float(arr)


@dataclass(frozen=True)
class Surface:
    """Where the toss ends.

    Parameters
    ----------
    kind : str
        A registered surface kind (:func:`surface_kinds`; ValueError naming them for another).
        ``"hand"``: caught at launch height, no bounce (Stefan & Cheche). ``"table"``: the coin
        falls onto a hard horizontal surface, bounces and settles heads, tails or on its edge.
        Another kind (:func:`coinflight.outcomes.register`) takes the parameters below that its
        model declares (:attr:`SurfaceKind.takes`) and refuses the others given, as the hand
        refuses them all.
    drop_height : float
        How far the surface lies below the launch height of the centre of mass, m (≥ 0; a
        surface above the launch point is not allowed; default 0). Only for ``"table"``: a
        catch in the hand is at the launch height by definition (Stefan & Cheche), so it refuses
        one given to it (ValueError, :data:`TABLE_ONLY`), as a restitution or friction, and
        ``dataclasses.replace(table, kind="hand")`` refuses a table's drop height given.
    restitution : float
        Newton's coefficient of restitution e of the contact's normal velocity, in [0, 1]
        (default :data:`DEFAULT_RESTITUTION`).
    friction : float
        Coulomb friction coefficient μ of the coin on the surface, 0 to :data:`MAX_FRICTION` (the
        range the landing models are validated over; default :data:`DEFAULT_FRICTION`). Both for
        ``"table"`` only: a catch in the hand, which has no contact, refuses either given to it
        (ValueError, :data:`TABLE_ONLY`), and keeps the defaults (marked as not given, as the
        resistances' below).
    rolling_resistance, pivoting_resistance : float
        Lengths ℓ_r, ℓ_p (m, 0 to 1 cm) of the torques ℓ F_n that resist the coin's rolling and
        its pivoting about the vertical while it touches the table
        (the rigid ending, :mod:`coinflight.core.rigid_contact`); assumptions, see
        :data:`DEFAULT_ROLLING_RESISTANCE` (the default of both). For ``"table"`` only: a catch
        in the hand refuses one given to it (ValueError, :data:`TABLE_ONLY`). A default is
        range-checked as a given value is, but marked as not given: ``Surface("table")`` equals
        ``Surface("table", rolling_resistance=1e-4)``, yet ``dataclasses.replace(...,
        kind="hand")`` accepts the first (its resistances are defaults) and refuses the second
        (a resistance given).
    contact_duration : float
        t_c of one impact of the coin's rim on the table, s (1 μs to 10 ms,
        :data:`CONTACT_DURATION`; default :data:`DEFAULT_CONTACT_DURATION`, Hertz's contact
        time, not measured for coins): a second rim point that meets the table within it makes
        one simultaneous impact with the first (:func:`coinflight.core.impact.
        simultaneous_point`). A physical parameter; it decides the
        landings that meet the table within about v t_c / 2r of flat or upright. For
        ``"table"`` only (a catch in the hand refuses one given, :data:`TABLE_ONLY`).

    A table landing whose bounces die out (a rebound slower than the rest speed) ends in the
    rigid, event-driven 3-D ending of :mod:`coinflight.core.rigid_ending`: rolling, sliding and
    pivoting on one rim point with the contact force of the constraint, exact Coulomb friction,
    the rolling and pivoting resistances, hops flown in closed form, impacts of the other rim,
    the coin on both rims of its band (status "settled in contact").

    Examples
    --------
    >>> Surface("table", drop_height=0.8).restitution
    0.5
    >>> Surface("table", restitution=1.5)
    Traceback (most recent call last):
    ...
    ValueError: restitution must be between 0 and 1, got 1.5
    >>> Surface("hand", restitution=0.7)  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: restitution 0.7 applies to --surface table only (Surface(kind='table') in ...
    >>> Surface("table", rolling_resistance=2e-4).rolling_resistance
    0.0002
    """

    kind: str = "hand"
    drop_height: float = _UNSET_DROP
    restitution: float = _UNSET_RESTITUTION
    friction: float = _UNSET_FRICTION
    rolling_resistance: float = _UNSET_ROLLING
    pivoting_resistance: float = _UNSET_PIVOTING
    contact_duration: float = _UNSET_DURATION

    def __post_init__(self) -> None:
        kind = surface_kind(self.kind)
        height = v.as_float_array("drop height", self.drop_height)
        if height.ndim == 0 and float(height) < 0:
            raise ValueError(
                f"drop height must be ≥ 0 m (how far the surface lies below the launch point), "
                f"got {float(height)!r}: a surface above the launch point is not allowed"
            )
        drop = DROP_HEIGHT.check(self.drop_height)
        given = {}  # the parameters the caller gave (not the marked defaults), described
        if not isinstance(self.drop_height, _Unset):  # given: kept as a plain float
            object.__setattr__(self, "drop_height", drop)
            given["drop_height"] = DROP_HEIGHT.describe(drop)
        e = v.in_range("restitution", self.restitution, 0.0, 1.0)
        if e.ndim:
            raise TypeError("restitution must be a single number")
        mu = _single("friction", self.friction, 0.0, MAX_FRICTION)
        for name, checked in (("restitution", float(e)), ("friction", mu)):
            if not isinstance(getattr(self, name), _Unset):  # given: kept as a plain float
                object.__setattr__(self, name, checked)
                given[name] = f"{name} {checked:g}"
        duration = CONTACT_DURATION.check(self.contact_duration)  # a default too
        if not isinstance(self.contact_duration, _Unset):  # given: kept as a plain float
            object.__setattr__(self, "contact_duration", duration)
            given["contact_duration"] = CONTACT_DURATION.describe(duration)
        for quantity in (ROLLING_RESISTANCE, PIVOTING_RESISTANCE):
            name = quantity.name.replace(" ", "_")
            value = getattr(self, name)
            checked = quantity.check(value)  # a default too (the _Unset mark is a float)
            if not isinstance(value, _Unset):  # given: kept as a plain float
                object.__setattr__(self, name, checked)
                given[name] = quantity.describe(checked)
        refused = [given[n] for n in TABLE_PARAMETERS if n in given and n not in kind.takes]
        if refused:
            raise ValueError(f"{', '.join(refused)} {kind.refusal}")

    def __repr__(self) -> str:
        """The call that rebuilds this surface: every field but the defaults not given.

        A default marked as not given (drop height, restitution, friction, the resistances, the
        contact duration) is left out, as the caller left it out: shown as a number it would be
        given back, and refused by a catch in the hand.
        ``eval(repr(s))`` equals ``s`` and refuses what ``s`` refuses (in
        :func:`dataclasses.replace`), no more.

        >>> Surface("hand")
        Surface(kind='hand')
        >>> Surface("table", 0.8, friction=0.2)
        Surface(kind='table', drop_height=0.8, friction=0.2)
        """
        given = (
            f"{field.name}={getattr(self, field.name)!r}"
            for field in fields(self)
            if not isinstance(getattr(self, field.name), _Unset)
        )
        return f"{type(self).__name__}({', '.join(given)})"

    @property
    def bounces(self) -> bool:
        """True for a hard surface (a table)."""
        return self.kind == "table"


CONTACT_RANGES = {
    "restitution": (0.0, 1.0),
    "friction": (0.0, MAX_FRICTION),
    "rolling_resistance": (ROLLING_RESISTANCE.low, ROLLING_RESISTANCE.high),
    "pivoting_resistance": (PIVOTING_RESISTANCE.low, PIVOTING_RESISTANCE.high),
    "contact_duration": (CONTACT_DURATION.low, CONTACT_DURATION.high),
}
"""The physical range of each contact parameter a distribution of tosses may spread: e in [0, 1] (no
contact gives energy back beyond elastic), μ in [0, :data:`MAX_FRICTION`], the rolling and pivoting
resistances ℓ_r, ℓ_p in [0, 1 cm] (m; :data:`ROLLING_RESISTANCE`), the contact duration t_c of an
impact in [1 μs, 10 ms] (s; :data:`CONTACT_DURATION`)."""

CONTACT_UNITS = {"rolling_resistance": "m", "pivoting_resistance": "m", "contact_duration": "s"}
"""Units of the contact parameters that have one (for messages and descriptions)."""


def contact_distribution(name: str, value: Distribution | float) -> Distribution:
    """``value`` as a distribution of the contact parameter ``name`` inside its physical range.

    A number or :class:`~coinflight.model.distributions.Fixed` value and a
    :class:`~coinflight.model.distributions.Uniform` range must lie inside
    :data:`CONTACT_RANGES` (else a ValueError naming the value and the range: no silent
    clipping). A :class:`~coinflight.model.distributions.Normal` one is *truncated* to the range
    (:class:`~coinflight.model.distributions.TruncatedNormal`: the mass outside is left out and
    the rest renormalised, said in its description), and refused when its mean lies outside
    the range.

    Examples
    --------
    >>> from coinflight.model.distributions import Normal
    >>> contact_distribution("friction", Normal(0.4, 0.1)).describe()
    'normal(0.4, sd 0.1) truncated to [0, 3] (100 % kept)'
    >>> contact_distribution("restitution", 1.2)
    Traceback (most recent call last):
    ...
    ValueError: restitution must be between 0 and 1, got 1.2
    """
    low, high = v.known("contact parameter", name, CONTACT_RANGES)
    dist = as_distribution(value, name)
    unit = CONTACT_UNITS.get(name, "")
    words = name.replace("_", " ")  # "rolling resistance", as the Surface names it
    allowed = (
        f"{words} must be between {low:g} and {high:g}{f' {unit}' if unit else ''}"
        if math.isfinite(high)
        else f"{words} must be non-negative"
    )
    if isinstance(dist, Fixed):  # one number: the Surface's own check and wording
        if math.isfinite(high):
            v.in_range(words, dist.value, low, high, unit)
        else:
            v.non_negative(words, dist.value)
        return dist
    if isinstance(dist, Normal):
        if not low <= dist.mean <= high:
            raise ValueError(
                f"{words} {dist.describe(unit)} has its mean outside the physical range; {allowed} "
                "(a normal one is truncated to the range, so its mean must lie inside)"
            )
        return TruncatedNormal(dist.mean, dist.sd, low, high)
    for end in dist.bounds:
        if not low <= end <= high:
            raise ValueError(f"{words} {dist.describe(unit)} reaches {end:g}; {allowed}")
    return dist


@dataclass(frozen=True)
class Drag:
    """Air resistance on the flying coin.

    Parameters
    ----------
    coefficient : float
        Drag coefficient C_d ≥ 0 of the quadratic drag F = −½ ρ C_d A |v| v on the centre of
        mass, with A the coin's area seen along its velocity, π r² |n·v̂| + 2 r h
        sqrt(1 − (n·v̂)²) (:mod:`coinflight.core.drag`). 1.17 is the value for a flat disc
        broadside on (Hoerner, *Fluid-Dynamic Drag*, 1965, ch. 3).
    spin_damping : float
        k ≥ 0 of the damping torque −k ω on the spin, N m s.
    air_density : float
        ρ > 0, kg/m³.

    Examples
    --------
    >>> Drag(coefficient=1.17).air_density
    1.2
    """

    coefficient: float = 0.0
    spin_damping: float = 0.0
    air_density: float = AIR_DENSITY

    def __post_init__(self) -> None:
        object.__setattr__(self, "coefficient", DRAG_COEFFICIENT.check(self.coefficient))
        object.__setattr__(self, "spin_damping", SPIN_DAMPING.check(self.spin_damping))
        object.__setattr__(self, "air_density", AIR_DENSITY_RANGE.check(self.air_density))

    @property
    def is_zero(self) -> bool:
        """True when there is no drag at all (the closed form applies)."""
        return self.coefficient == 0.0 and self.spin_damping == 0.0


__all__ = [
    "AIR_DENSITY",
    "CONTACT_DURATION",
    "CONTACT_RANGES",
    "CONTACT_UNITS",
    "DEFAULT_CONTACT_DURATION",
    "DROP_HEIGHT",
    "MAX_FRICTION",
    "TABLE_ONLY",
    "TABLE_PARAMETERS",
    "Drag",
    "Surface",
    "SurfaceKind",
    "contact_distribution",
    "surface_kind",
    "surface_kinds",
]
