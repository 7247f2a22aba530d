"""A distribution of tosses: each initial condition fixed, ranged or random.

>>> from coinflight.model.distributions import Uniform
>>> d = TossDistribution(omega_x=Uniform(60, 90), flight_time=Uniform(0.6, 0.9))
>>> d.ranged  # omega_y and omega_z default to 0 rad/s, as on the command line
('omega_x', 'flight_time')
>>> d = TossDistribution(omega_x=80.0, launch_speed=Uniform(2.0, 3.0))  # v0 in m/s
>>> d.flight_time.describe("s")  # T = 2 v0 / g, g = 9.81 m/s²
'0.407747–0.611621 s'
"""

from __future__ import annotations

from dataclasses import KW_ONLY, dataclass, field
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from coinflight import _validation as v
from coinflight.core import ballistics
from coinflight.model.coin import DEFAULT_COIN, Coin
from coinflight.model.distributions import (
    Distribution,
    Fixed,
    Normal,
    as_distribution,
    unit_cube_values,
)
from coinflight.model.surface import CONTACT_UNITS, contact_distribution
from coinflight.model.toss import STANDARD_GRAVITY, Start, check_gravity

FloatArray = NDArray[np.float64]

PARAMETERS = ("omega_x", "omega_y", "omega_z", "flight_time")
"""Initial conditions in the order used by every estimator (rad/s, rad/s, rad/s, s)."""
NO_SPIN = Fixed(0.0)
"""Default of ``omega_y`` and ``omega_z``: no spin about that axis (as on the command line)."""
UNITS = {
    "omega_x": "rad/s",
    "omega_y": "rad/s",
    "omega_z": "rad/s",
    "flight_time": "s",
    "launch_speed": "m/s",
}
"""The unit of each toss parameter (:data:`PARAMETERS` and the launch speed that may give the
flight time)."""
CONTACT = (
    "restitution",
    "friction",
    "rolling_resistance",
    "pivoting_resistance",
    "contact_duration",
)
"""Contact parameters a distribution of tosses may spread (table landings); when set they
replace the surface's single value, toss by toss (:mod:`coinflight.outcomes.table`;
:attr:`coinflight.outcomes.table.TableLanding.contact_parameters`)."""

# A normal flight time must stay positive: below mean − 8 sd lies a probability 6e-16, far
# below anything an estimate can resolve, so such draws can never occur in practice.
_NORMAL_T_SIGMAS = 8.0


@dataclass(frozen=True)
class TossDistribution:
    """Initial conditions of a population of tosses, caught at launch height.

    Parameters
    ----------
    omega_x, omega_y, omega_z : Distribution or float
        Body-frame spin components at launch, rad/s (x, y diameters; z the normal). A number
        means a fixed value; ``omega_y`` and ``omega_z`` default to 0 (as on the command line).
    flight_time : Distribution or float
        Flight time T = 2 v0 / g, s; must be positive with certainty. Give exactly one of
        ``flight_time`` and ``launch_speed``.
    coin : Coin
        The coin (default the US quarter).
    start : {"heads", "tails"}
        Face up at launch.
    g : float
        Gravitational acceleration, m/s².
    launch_speed : Distribution or float, keyword only
        The launch speed v0 of the centre of mass, m/s, instead of ``flight_time``: the flight
        time becomes T = 2 v0 / g (Stefan & Cheche eq 11, :func:`coinflight.core.ballistics.
        flight_time`). Kept on the object for reference; equality compares the flight times.
    restitution, friction : Distribution or float, keyword only
        What is not measured about the contact with a table: the coefficient of restitution
        (in [0, 1]) and of friction (in [0, :data:`coinflight.model.surface.MAX_FRICTION`]),
        drawn toss by toss, so that P(heads, tails, edge) integrates over them. None (default):
        the surface's single value. A normal one is truncated to that range
        (:func:`coinflight.model.surface.contact_distribution`).
        Only table landings take them (the estimators refuse them for other outcome models).
    rolling_resistance, pivoting_resistance : Distribution or float, keyword only
        The same for the rolling and pivoting resistance lengths ℓ_r, ℓ_p (m, in [0, 1 cm]) of
        the rigid ending, drawn toss by toss.
    contact_duration : Distribution or float, keyword only
        The same for the contact duration t_c of an impact (s, in [1 μs, 10 ms],
        :data:`coinflight.model.surface.CONTACT_DURATION`).

    Notes
    -----
    Stefan & Cheche §3: the outcome is deterministic in (ω, T); the probability of heads is
    the probability mass of the initial conditions that give heads.
    """

    omega_x: Distribution
    omega_y: Distribution = NO_SPIN
    omega_z: Distribution = NO_SPIN
    # None until __post_init__ derives it from launch_speed; a Distribution afterwards.
    flight_time: Distribution = None  # type: ignore[assignment]
    coin: Coin = field(default_factory=lambda: Coin.preset(DEFAULT_COIN))
    start: Start = "heads"
    g: float = STANDARD_GRAVITY
    _: KW_ONLY
    launch_speed: Distribution | None = field(default=None, compare=False)
    restitution: Distribution | None = None
    friction: Distribution | None = None
    rolling_resistance: Distribution | None = None
    pivoting_resistance: Distribution | None = None
    contact_duration: Distribution | None = None

    if TYPE_CHECKING:  # what callers may pass (numbers become Fixed); the dataclass builds it

        def __init__(
            self,
            omega_x: Distribution | float,
            omega_y: Distribution | float = NO_SPIN,
            omega_z: Distribution | float = NO_SPIN,
            flight_time: Distribution | float | None = None,
            coin: Coin = ...,
            start: Start = "heads",
            g: float = STANDARD_GRAVITY,
            *,
            launch_speed: Distribution | float | None = None,
            restitution: Distribution | float | None = None,
            friction: Distribution | float | None = None,
            rolling_resistance: Distribution | float | None = None,
            pivoting_resistance: Distribution | float | None = None,
            contact_duration: Distribution | float | None = None,
        ) -> None: ...

    def __post_init__(self) -> None:
        for name in PARAMETERS[:3]:
            object.__setattr__(self, name, as_distribution(getattr(self, name), name))
        v.choice("start", self.start, ("heads", "tails"))
        object.__setattr__(self, "g", check_gravity(self.g))
        self._set_flight_time()
        for name in CONTACT:
            value = getattr(self, name)
            if value is not None:
                object.__setattr__(self, name, contact_distribution(name, value))
        if not isinstance(self.coin, Coin):
            raise TypeError(f"coin must be a Coin, got {self.coin!r}")
        t = self.flight_time
        low = t.bounds[0]
        if isinstance(t, Normal):
            low = t.mean - _NORMAL_T_SIGMAS * t.sd
        if not low > 0.0:
            raise ValueError(
                f"flight time {t.describe('s')} reaches times ≤ 0 s; the flight time must be "
                f"positive (a normal one needs mean > {_NORMAL_T_SIGMAS:g} sd)"
            )
        spin = max(_largest(getattr(self, name)) for name in PARAMETERS[:3])
        v.phase_budget(spin, _largest(t), "largest spin component × largest flight time")

    def _set_flight_time(self) -> None:
        """``flight_time`` as a Distribution, from itself or from ``launch_speed`` (not both)."""
        if self.launch_speed is None:
            if self.flight_time is None:
                raise TypeError("give one of flight_time (s) and launch_speed (m/s)")
            object.__setattr__(
                self, "flight_time", as_distribution(self.flight_time, "flight_time")
            )
            return
        speed = check_launch_speed(as_distribution(self.launch_speed, "launch_speed"))
        # T = 2 v0 / g is linear in v0: the distribution of v0 scaled by T(v0 = 1 m/s).
        derived = speed.scaled(float(ballistics.flight_time(1.0, self.g)))
        if self.flight_time is not None and self.flight_time != derived:
            # dataclasses.replace passes both back; they agree unless one of them (or g) was
            # changed, and then the caller must say which one holds.
            given = as_distribution(self.flight_time, "flight_time").describe("s")
            raise TypeError(
                f"give exactly one of flight_time and launch_speed, not both: flight_time "
                f"{given} is not 2 v0 / g for launch_speed {speed.describe('m/s')} at "
                f"g = {self.g:g} m/s² (with dataclasses.replace, set the other one to None)"
            )
        object.__setattr__(self, "launch_speed", speed)
        object.__setattr__(self, "flight_time", derived)

    @classmethod
    def from_launch_speed(
        cls,
        omega_x: Distribution | float,
        omega_y: Distribution | float,
        omega_z: Distribution | float,
        launch_speed: Distribution | float,
        coin: Coin | None = None,
        start: Start = "heads",
        g: float = STANDARD_GRAVITY,
    ) -> TossDistribution:
        """From the launch speed v0 (m/s) instead of the flight time: T = 2 v0 / g (eq 11).

        The same as ``TossDistribution(omega_x, omega_y, omega_z, launch_speed=...)``.
        """
        return cls(
            omega_x,
            omega_y,
            omega_z,
            coin=coin if coin is not None else Coin.preset(DEFAULT_COIN),
            start=start,
            g=g,
            launch_speed=launch_speed,
        )

    @property
    def parameters(self) -> dict[str, Distribution]:
        """The four initial conditions by name, in :data:`PARAMETERS` order."""
        return {name: getattr(self, name) for name in PARAMETERS}

    def with_contact(
        self,
        restitution: Distribution | float | None = None,
        friction: Distribution | float | None = None,
        rolling_resistance: Distribution | float | None = None,
        pivoting_resistance: Distribution | float | None = None,
        contact_duration: Distribution | float | None = None,
    ) -> TossDistribution:
        """The same tosses with these contact distributions (:data:`CONTACT`; None: keep)."""
        import dataclasses

        given = (restitution, friction, rolling_resistance, pivoting_resistance, contact_duration)
        changes = {
            name: value for name, value in zip(CONTACT, given, strict=True) if value is not None
        }
        return dataclasses.replace(self, **changes) if changes else self  # type: ignore[arg-type]

    @property
    def contact(self) -> dict[str, Distribution]:
        """The contact parameters this distribution sets (:data:`CONTACT`), by name."""
        return {name: d for name in CONTACT if (d := getattr(self, name)) is not None}

    @property
    def ranged(self) -> tuple[str, ...]:
        """Names of the parameters that vary (not :class:`Fixed`): those of :data:`PARAMETERS`,
        then the contact parameters of :data:`CONTACT` that vary, in that order."""
        return tuple(name for name in PARAMETERS if not getattr(self, name).is_fixed) + tuple(
            name for name, d in self.contact.items() if not d.is_fixed
        )

    @property
    def start_sign(self) -> float:
        """+1 started heads up, −1 tails up."""
        return 1.0 if self.start == "heads" else -1.0

    @property
    def moments(self) -> tuple[float, float]:
        """The coin's principal moments (I1, I3), kg m²."""
        return self.coin.moments

    @property
    def spin_about_diameter(self) -> bool:
        """True when ω_z = 0 for every toss (the paper's cases a and b, ψ = 90°)."""
        return isinstance(self.omega_z, Fixed) and self.omega_z.value == 0.0

    def values(self, u: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
        """Initial conditions for points of the unit cube.

        Parameters
        ----------
        u : ndarray, shape (len(ranged), n)
            One row per ranged parameter (in :attr:`ranged` order), values in (0, 1).

        Returns
        -------
        (wx, wy, wz, t) : four arrays of shape (n,), rad/s and s.
        """
        u = np.asarray(u, dtype=float)
        ranged = self.ranged
        if u.ndim != 2 or u.shape[0] != len(ranged):
            raise ValueError(f"u must have shape ({len(ranged)}, n), got {u.shape}")
        out = unit_cube_values({name: getattr(self, name) for name in PARAMETERS}, ranged, u)
        return out["omega_x"], out["omega_y"], out["omega_z"], out["flight_time"]

    def contact_values(self, u: FloatArray) -> dict[str, FloatArray]:
        """The contact parameters this distribution sets, for points of the unit cube.

        ``u`` as for :meth:`values`; returns {name: array of shape (n,)} for each parameter of
        :attr:`contact` (a fixed one repeated).
        """
        return unit_cube_values(self.contact, self.ranged, np.asarray(u, dtype=float))

    def sample(
        self, rng: np.random.Generator, n: int
    ) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
        """``n`` random tosses: (wx, wy, wz, t), each of shape (n,)."""
        return self.values(rng.random((len(self.ranged), int(n))))

    def describe(self) -> str:
        """One line per parameter, for reports."""
        lines = [f"{self.coin.describe()}, started {self.start} up"]
        for name in PARAMETERS:
            lines.append(f"{name} = {getattr(self, name).describe(UNITS[name])}")
        for name, d in self.contact.items():
            unit = CONTACT_UNITS.get(name, "")
            lines.append(f"{name} = {d.describe(unit)} (toss by toss)")
        return "\n".join(lines)


def check_launch_speed(speed: Distribution, name: str = "launch speed") -> Distribution:
    """``speed`` (m/s) if it is positive with certainty, else a ValueError naming ``name``.

    A normal speed must have mean > 8 sd (as a normal flight time, which it becomes).
    """
    low = speed.mean - _NORMAL_T_SIGMAS * speed.sd if isinstance(speed, Normal) else speed.bounds[0]
    if not low > 0.0:
        extra = (
            f" (a normal one needs mean > {_NORMAL_T_SIGMAS:g} sd)"
            if isinstance(speed, Normal)
            else ""
        )
        raise ValueError(
            f"{name} {speed.describe('m/s')} reaches speeds ≤ 0 m/s; it must be positive{extra}"
        )
    return speed


def _largest(dist: Distribution) -> float:
    """Largest |value| a distribution reaches (a normal one: within ±8 sd, as for T)."""
    if isinstance(dist, Normal):
        return abs(dist.mean) + _NORMAL_T_SIGMAS * dist.sd
    lo, hi = dist.bounds
    return max(abs(lo), abs(hi))


__all__ = ["CONTACT", "NO_SPIN", "PARAMETERS", "TossDistribution", "check_launch_speed"]
