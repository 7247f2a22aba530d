"""Distributions of one initial condition (a spin component, the flight time, the launch speed).

A person's tosses spread over a range of launch speeds and spins (Stefan & Cheche §3). Each
parameter of a :class:`~coinflight.model.ensemble.TossDistribution` is one of these frozen value
objects. The probability methods use only the small protocol of :class:`Distribution`
(``sample``, ``ppf``, ``cdf``, ``is_fixed``, ``mean``, ``bounds``, ``affine``), so a new kind
of distribution needs no change to the methods.

>>> parse_distribution("60:90", "--omega-x", "rad/s")
Uniform(low=60.0, high=90.0)
>>> parse_distribution("normal:3.5,0.2", "--launch-speed", "m/s")
Normal(mean=3.5, sd=0.2)
"""

from __future__ import annotations

import math
from abc import ABC, abstractmethod
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

from coinflight import _validation as v

FloatArray = NDArray[np.float64]


class Distribution(ABC):
    """What every distribution of one initial condition provides (SI units).

    ``ppf`` (inverse CDF) maps the unit interval onto the parameter: Monte Carlo, quasi-Monte
    Carlo, the paper's method B and the grid (midpoints of N equal-probability cells,
    u_i = (i + ½)/N) all draw points in [0, 1) and map them through it.
    """

    @abstractmethod
    def sample(self, rng: np.random.Generator, size: int) -> FloatArray:
        """``size`` independent draws, shape (size,)."""

    @abstractmethod
    def ppf(self, u: ArrayLike) -> FloatArray:
        """Inverse CDF at probabilities ``u`` in (0, 1); broadcasts."""

    @abstractmethod
    def cdf(self, x: ArrayLike) -> FloatArray:
        """P(X ≤ x); broadcasts."""

    mean: float
    """Mean value (a field or a property of each kind)."""

    @property
    @abstractmethod
    def std(self) -> float:
        """Standard deviation (0 for a single value)."""

    @property
    def is_fixed(self) -> bool:
        """True for a single value (no spread)."""
        return False

    @property
    def bounds(self) -> tuple[float, float]:
        """(smallest, largest) possible value; ±inf where unbounded."""
        return (-math.inf, math.inf)

    @property
    def affine(self) -> tuple[float, float] | None:
        """(a, b) when ppf(u) = a + b u exactly (fast paths), else None."""
        return None

    @abstractmethod
    def scaled(self, factor: float) -> Distribution:
        """The distribution of ``factor · X`` for ``factor`` > 0 (e.g. v0 → T = 2 v0 / g)."""

    @abstractmethod
    def describe(self, unit: str = "") -> str:
        """Short text for reports, e.g. ``60–90 rad/s``."""

    def to_dict(self) -> dict[str, object]:
        """``{"kind": "uniform", "low": 60.0, "high": 90.0}`` and the like, for JSON."""
        from dataclasses import asdict, is_dataclass

        fields: dict[str, object] = asdict(self) if is_dataclass(self) else {}
        return {"kind": type(self).__name__.lower(), **fields}


def _u(u: ArrayLike) -> FloatArray:
    return np.asarray(u, dtype=float)


_LARGEST = float(np.finfo(float).max)
_SPAN = 10.0
"""A normal's quantiles reach mean ± 8.3 sd in double precision (u = 1 − 2⁻⁵³); mean ± 10 sd
must be finite for every one of them to be."""


@dataclass(frozen=True)
class Fixed(Distribution):
    """A single value: the parameter does not vary."""

    value: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "value", v.number("Fixed value", self.value))

    def sample(self, rng: np.random.Generator, size: int) -> FloatArray:
        return np.full(size, self.value)

    def ppf(self, u: ArrayLike) -> FloatArray:
        return np.full_like(_u(u), self.value)

    def cdf(self, x: ArrayLike) -> FloatArray:
        return np.where(_u(x) >= self.value, 1.0, 0.0)

    @property
    def mean(self) -> float:  # type: ignore[override]
        return self.value

    @property
    def std(self) -> float:
        return 0.0

    @property
    def is_fixed(self) -> bool:
        return True

    @property
    def bounds(self) -> tuple[float, float]:
        return (self.value, self.value)

    @property
    def affine(self) -> tuple[float, float]:
        return (self.value, 0.0)

    def scaled(self, factor: float) -> Fixed:
        return Fixed(self.value * factor)

    def describe(self, unit: str = "") -> str:
        return f"{self.value:g}{_space(unit)}"


@dataclass(frozen=True)
class Uniform(Distribution):
    """Uniform over [low, high], low < high (the paper's ranges, Stefan & Cheche §3)."""

    low: float
    high: float

    def __post_init__(self) -> None:
        lo = v.number("Uniform low", self.low)
        hi = v.number("Uniform high", self.high)
        if not lo < hi:
            what = "empty" if lo == hi else "reversed"
            raise ValueError(f"range {lo:g}:{hi:g} is {what}: the low end must be below the high")
        if not math.isfinite(hi - lo):  # its width and every quantile would be inf
            raise ValueError(
                f"range {lo:g}:{hi:g} is too wide: its ends must be less than {_LARGEST:.3g} "
                "apart (the largest float)"
            )
        object.__setattr__(self, "low", lo)
        object.__setattr__(self, "high", hi)

    def sample(self, rng: np.random.Generator, size: int) -> FloatArray:
        return rng.uniform(self.low, self.high, size)

    def ppf(self, u: ArrayLike) -> FloatArray:
        return self.low + (self.high - self.low) * _u(u)

    def cdf(self, x: ArrayLike) -> FloatArray:
        return np.clip((_u(x) - self.low) / (self.high - self.low), 0.0, 1.0)

    @property
    def mean(self) -> float:  # type: ignore[override]
        return 0.5 * (self.low + self.high)

    @property
    def std(self) -> float:
        return (self.high - self.low) / math.sqrt(12.0)

    @property
    def bounds(self) -> tuple[float, float]:
        return (self.low, self.high)

    @property
    def affine(self) -> tuple[float, float]:
        return (self.low, self.high - self.low)

    def scaled(self, factor: float) -> Uniform:
        return Uniform(self.low * factor, self.high * factor)

    def describe(self, unit: str = "") -> str:
        lo, hi = f"{self.low:g}", f"{self.high:g}"
        if lo == hi:  # a range narrower than 6 digits: show the digits that tell its ends apart
            lo, hi = repr(self.low), repr(self.high)
        return f"{lo}–{hi}{_space(unit)}"


@dataclass(frozen=True)
class Normal(Distribution):
    """Normal (Gaussian) with mean and standard deviation sd > 0."""

    mean: float
    sd: float

    def __post_init__(self) -> None:
        mean = v.number("Normal mean", self.mean)
        sd = float(
            v.positive("Normal standard deviation", v.number("Normal standard deviation", self.sd))
        )
        if not math.isfinite(abs(mean) + _SPAN * sd):  # its quantiles would be inf
            raise ValueError(
                f"normal({mean:g}, sd {sd:g}) is too wide: mean ± {_SPAN:g} sd must stay below "
                f"{_LARGEST:.3g} (the largest float)"
            )
        object.__setattr__(self, "mean", mean)
        object.__setattr__(self, "sd", sd)

    def sample(self, rng: np.random.Generator, size: int) -> FloatArray:
        return rng.normal(self.mean, self.sd, size)

    def ppf(self, u: ArrayLike) -> FloatArray:
        from scipy.special import ndtri

        return self.mean + self.sd * np.asarray(ndtri(_u(u)), dtype=float)

    def cdf(self, x: ArrayLike) -> FloatArray:
        from scipy.special import ndtr

        with np.errstate(over="ignore"):  # a subnormal sd: ±inf, the step that is the limit
            return np.asarray(ndtr((_u(x) - self.mean) / self.sd), dtype=float)

    @property
    def std(self) -> float:
        return self.sd

    def scaled(self, factor: float) -> Normal:
        return Normal(self.mean * factor, self.sd * factor)

    def describe(self, unit: str = "") -> str:
        return f"normal({self.mean:g}, sd {self.sd:g}){_space(unit)}"


@dataclass(frozen=True)
class TruncatedNormal(Distribution):
    """A normal distribution (mean, sd) restricted to [low, high] and renormalised there.

    What a normal restitution or friction becomes (:func:`coinflight.model.surface.
    contact_distribution`): the draws outside the physical range are not clipped onto its ends
    but left out, the density inside scaled up by 1 / (Φ(b) − Φ(a)), a = (low − mean)/sd,
    b = (high − mean)/sd (SciPy's ``truncnorm``). The mean must lie inside [low, high].
    """

    normal_mean: float
    sd: float
    low: float
    high: float

    def __post_init__(self) -> None:
        m = v.number("TruncatedNormal mean", self.normal_mean)
        sd = float(
            v.positive(
                "TruncatedNormal standard deviation",
                v.number("TruncatedNormal standard deviation", self.sd),
            )
        )
        lo, hi = float(self.low), float(self.high)
        if not lo < hi or math.isnan(lo) or math.isnan(hi):
            raise ValueError(f"truncation range [{lo:g}, {hi:g}] is empty")
        if not lo <= m <= hi:
            raise ValueError(
                f"normal({m:g}, sd {sd:g}) has its mean outside [{lo:g}, {hi:g}]: most of it "
                "would be cut away"
            )
        object.__setattr__(self, "normal_mean", m)
        object.__setattr__(self, "sd", sd)
        object.__setattr__(self, "low", lo)
        object.__setattr__(self, "high", hi)

    def _frozen(self) -> Any:
        from scipy.stats import truncnorm

        a = (self.low - self.normal_mean) / self.sd
        b = (self.high - self.normal_mean) / self.sd
        return truncnorm(a, b, loc=self.normal_mean, scale=self.sd)

    def sample(self, rng: np.random.Generator, size: int) -> FloatArray:
        return self.ppf(rng.random(size))

    def ppf(self, u: ArrayLike) -> FloatArray:
        return np.asarray(self._frozen().ppf(_u(u)), dtype=np.float64)

    def cdf(self, x: ArrayLike) -> FloatArray:
        return np.asarray(self._frozen().cdf(_u(x)), dtype=np.float64)

    @property
    def mean(self) -> float:  # type: ignore[override]
        return float(self._frozen().mean())

    @property
    def std(self) -> float:
        return float(self._frozen().std())

    @property
    def kept(self) -> float:
        """Probability mass of the untruncated normal inside [low, high]."""
        from scipy.special import ndtr

        a = (self.low - self.normal_mean) / self.sd
        b = (self.high - self.normal_mean) / self.sd
        return float(ndtr(b) - ndtr(a))

    @property
    def bounds(self) -> tuple[float, float]:
        return (self.low, self.high)

    def scaled(self, factor: float) -> TruncatedNormal:
        return TruncatedNormal(
            self.normal_mean * factor, self.sd * factor, self.low * factor, self.high * factor
        )

    def describe(self, unit: str = "") -> str:
        where = f"[{self.low:g}, {self.high:g}]" if math.isfinite(self.high) else f"≥ {self.low:g}"
        return (
            f"normal({self.normal_mean:g}, sd {self.sd:g}){_space(unit)} truncated to {where} "
            f"({100 * self.kept:.3g} % kept)"
        )

    def to_dict(self) -> dict[str, object]:
        return {
            "kind": "truncated-normal",
            "mean": self.normal_mean,
            "sd": self.sd,
            "low": self.low,
            "high": self.high if math.isfinite(self.high) else None,  # JSON has no infinity
        }


def _space(unit: str) -> str:
    return f" {unit}" if unit else ""


def as_distribution(value: Distribution | float | int, name: str = "value") -> Distribution:
    """A distribution as is; a plain number as :class:`Fixed`.

    ``name`` (e.g. ``"omega_x"``) is the parameter the value is for; errors name it.
    """
    if isinstance(value, Distribution):
        return value
    if isinstance(value, bool) or not isinstance(value, int | float | np.floating | np.integer):
        raise TypeError(
            f"{name}: expected a number or a Distribution (Fixed, Uniform, Normal), got "
            f"{v.shown(value)}"
        )
    return Fixed(float(v.finite(name, value)))


def parse_distribution(text: str, name: str, unit: str = "") -> Distribution:
    """Parse the command-line syntax of a distribution.

    ``"10"`` → :class:`Fixed`, ``"60:90"`` → :class:`Uniform`, ``"normal:MEAN,SD"`` →
    :class:`Normal`. Errors are ValueError naming the option ``name`` and the text.
    """
    raw = str(text).strip()
    where = f"{name} {raw!r}"
    try:
        if raw.lower().startswith("normal:"):
            parts = raw.split(":", 1)[1].split(",")
            if len(parts) != 2:
                raise ValueError("expected normal:MEAN,SD")
            return Normal(_num(parts[0]), _num(parts[1]))
        if ":" in raw:
            parts = raw.split(":")
            if len(parts) != 2:
                raise ValueError("expected LOW:HIGH")
            return Uniform(_num(parts[0]), _num(parts[1]))
        return Fixed(_num(raw))
    except (ValueError, TypeError) as exc:
        raise ValueError(
            f"{where}: {exc} (use a number, LOW:HIGH or normal:MEAN,SD{_in(unit)})"
        ) from None


def _num(text: str) -> float:
    try:
        x = float(text)
    except ValueError:
        raise ValueError(f"{text.strip()!r} is not a number") from None
    if not math.isfinite(x):
        raise ValueError(f"{text.strip()!r} is not finite")
    return x


def _in(unit: str) -> str:
    return f", in {unit}" if unit else ""


def unit_cube_values(
    dists: Mapping[str, Distribution], ranged: Sequence[str], u: NDArray[np.float64]
) -> dict[str, NDArray[np.float64]]:
    """Each distribution's values at points of the unit cube, by name.

    ``u`` has one row per name of ``ranged`` (in that order) and one column per point; a
    ranged distribution takes the inverse CDF of its row (``ppf``), one not in ``ranged`` (a
    fixed one) its mean, repeated. The one mapping of the estimators' (quasi-)random points
    to tosses (:meth:`coinflight.model.ensemble.TossDistribution.values`, its contact
    parameters, the conditional-on-spin mode's spins).
    """
    n = u.shape[1]
    return {
        name: np.asarray(d.ppf(u[ranged.index(name)]), dtype=float)
        if name in ranged
        else np.full(n, d.mean)
        for name, d in dists.items()
    }


__all__ = [
    "Distribution",
    "Fixed",
    "Normal",
    "TruncatedNormal",
    "Uniform",
    "as_distribution",
    "parse_distribution",
    "unit_cube_values",
]
