"""Checks shared by every value object: one wording for every error a user can meet.

Every number a user gives goes through :func:`as_float_array` (booleans and strings are not
numbers), and every physical quantity with limits through a :class:`Quantity`: a hard range
(ValueError: ``radius must be between 1e-06 and 1000 (in m), got 1e-320``) that keeps the
arithmetic finite, and a usual range whose violation is only a :class:`PlausibilityWarning`
(most often a wrong unit: millimetres given as metres).
"""

from __future__ import annotations

import difflib
import math
import numbers
import warnings
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from decimal import Decimal
from typing import TypeVar

import numpy as np
from numpy.typing import ArrayLike, NDArray


class PlausibilityWarning(UserWarning):
    """A value inside its allowed range but unusual for a coin toss: most often a wrong unit.

    The command line prints it as one line (``coinflight: warning: …``) and goes on.
    """


T = TypeVar("T")


def _show(value: object) -> str:
    """A value for a message: one number as a plain number (200.0), several as an array on
    one line (a message is one line: ``[[1. 1. 1.] [1. 1. 1.]]``)."""
    arr = np.asarray(value)
    if arr.size == 1:
        return repr(arr.reshape(-1)[0].item())
    return " ".join(np.array2string(arr, threshold=6, max_line_width=200).split())


def shown(value: object) -> str:
    """Any value for a one-line message: an array as :func:`_show` writes it (its shape if it
    has more than a few entries), anything else as its repr, cut at 80 characters."""
    if isinstance(value, np.ndarray):
        return f"{_show(value)} (shape {value.shape})" if value.size > 6 else _show(value)
    text = repr(value)
    return " ".join(text.split()) if len(text) <= 80 else " ".join(text[:77].split()) + "..."


def as_float_array(name: str, value: ArrayLike) -> NDArray[np.float64]:
    """``value`` as a float array, or TypeError naming ``name``.

    Real numbers only: a bool (``True`` is not 1.0), a string (``"0.01"`` is text, however
    numeric it reads), a complex number or a ragged list is a TypeError.
    """
    try:
        arr = np.asarray(value)
        if arr.dtype.kind == "O":
            if not all(_is_real(x) for x in arr.flat):
                raise TypeError
        elif arr.dtype.kind not in "iuf":
            raise TypeError
        return np.asarray(arr, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(
            f"{name} must be a number or an array of numbers, got {_kind(value)} {shown(value)}"
        ) from None


def _is_real(x: object) -> bool:
    return isinstance(x, numbers.Real) and not isinstance(x, bool | np.bool_)


def _kind(value: object) -> str:
    """What a value is, for a TypeError: 'str', 'bool', 'array of bool'."""
    if isinstance(value, np.ndarray):
        return f"array of {value.dtype}"
    return type(value).__name__


def number(name: str, value: object, unit: str = "") -> float:
    """One finite real number (not a bool, not a string, not an array), else TypeError or
    ValueError naming ``name``."""
    arr = finite(name, value, unit)  # type: ignore[arg-type]
    if arr.ndim:
        raise TypeError(f"{name} must be a single number, got an array of shape {arr.shape}")
    return float(arr)


def count(name: str, value: object, minimum: int = 1, maximum: int | None = None) -> int:
    """A whole number in [minimum, maximum] (Python or NumPy int, not a bool, not 2.0 or 2.5),
    else TypeError or ValueError naming ``name``."""
    if isinstance(value, bool | np.bool_) or not isinstance(value, int | np.integer):
        raise TypeError(f"{name} must be an integer, got {_kind(value)} {shown(value)}")
    value = int(value)
    if value < minimum or (maximum is not None and value > maximum):
        allowed = f"at least {minimum}" if maximum is None else f"between {minimum} and {maximum}"
        raise ValueError(f"{name} must be {allowed}, got {value}")
    return value


def instance(name: str, value: object, kind: type, allowed: str = "") -> None:
    """TypeError naming ``name`` unless ``value`` is a ``kind``."""
    if not isinstance(value, kind):
        what = allowed or f"a {kind.__name__}"
        raise TypeError(f"{name} must be {what}, got {_kind(value)} {value!r:.60}")


def callable_or_none(name: str, value: object, allowed: str) -> None:
    """TypeError naming ``name`` unless ``value`` is None or callable."""
    if value is not None and not callable(value):
        raise TypeError(f"{name} must be {allowed} or None, got {_kind(value)} {value!r:.60}")


@dataclass(frozen=True)
class Quantity:
    """A physical quantity's limits: a hard range (an error outside) and a usual one (a warning).

    The hard range is what the arithmetic survives: the flight, the moments of inertia and the
    figures stay finite and well conditioned inside it. The usual range is what a coin toss
    looks like; a value outside it is accepted with a :class:`PlausibilityWarning`.

    Parameters
    ----------
    name : str
        The field, as errors name it ("radius", "g").
    unit : str
        SI unit, for messages.
    low, high : float
        Hard range, inclusive.
    usual : (float, float), optional
        Usual range, inclusive.
    usual_text : str
        What the usual range is, for the warning ("a coin's (1 mm to 10 cm)").
    """

    name: str
    unit: str
    low: float
    high: float
    usual: tuple[float, float] | None = None
    usual_text: str = ""

    def check(self, value: object, name: str | None = None) -> float:
        """``value`` as a float inside the hard range, else TypeError or ValueError."""
        arr = self.check_array(value, name)  # type: ignore[arg-type]
        if arr.ndim:
            raise TypeError(
                f"{name or self.name} must be a single number, got an array of shape {arr.shape}"
            )
        return float(arr)

    def check_array(self, value: ArrayLike, name: str | None = None) -> NDArray[np.float64]:
        """Every entry of ``value`` inside the hard range, else TypeError or ValueError."""
        return in_range(name or self.name, value, self.low, self.high, self.unit)

    def is_usual(self, value: ArrayLike) -> bool:
        """True if every entry lies in the usual range (or there is none)."""
        if self.usual is None:
            return True
        arr = np.asarray(value, dtype=float)
        return bool(np.all((arr >= self.usual[0]) & (arr <= self.usual[1])))

    @property
    def high_usual(self) -> float:
        """Top of the usual range (the hard top if there is none)."""
        return self.high if self.usual is None else self.usual[1]

    def describe(self, value: float) -> str:
        """``'radius 12.13 m'``: the field and the value, for a warning."""
        return f"{self.name} {value:g}{' ' + self.unit if self.unit else ''}"


def warn_unusual(message: str, stacklevel: int = 3) -> None:
    """Issue ``message`` as a :class:`PlausibilityWarning` (``stacklevel`` as for ``warn``)."""
    warnings.warn(message, PlausibilityWarning, stacklevel=stacklevel + 1)


def warn_outside(quantity: Quantity, value: float, hint: str = "", stacklevel: int = 3) -> None:
    """The warning of one quantity outside its usual range (nothing if inside)."""
    if quantity.is_usual(value):
        return
    tail = f": {hint}" if hint else ""
    warn_unusual(f"{quantity.describe(value)} is not {quantity.usual_text}{tail}", stacklevel + 1)


def finite(name: str, value: ArrayLike, unit: str = "") -> NDArray[np.float64]:
    """Float array whose entries are all finite, else ValueError naming the value."""
    arr = as_float_array(name, value)
    if not np.all(np.isfinite(arr)):
        bad = arr[~np.isfinite(arr)] if arr.ndim else arr
        raise ValueError(f"{name} must be finite{_unit(unit)}, got {_show(bad)}")
    return arr


def positive(name: str, value: ArrayLike, unit: str = "") -> NDArray[np.float64]:
    """Float array whose entries are all finite and > 0, else ValueError naming the value."""
    arr = as_float_array(name, value)
    ok = np.isfinite(arr) & (arr > 0)
    if not np.all(ok):
        bad = arr[~ok] if arr.ndim else arr
        raise ValueError(f"{name} must be positive and finite{_unit(unit)}, got {_show(bad)}")
    return arr


def non_negative(name: str, value: ArrayLike, unit: str = "") -> NDArray[np.float64]:
    """Float array whose entries are all finite and ≥ 0, else ValueError naming the value."""
    arr = as_float_array(name, value)
    ok = np.isfinite(arr) & (arr >= 0)
    if not np.all(ok):
        bad = arr[~ok] if arr.ndim else arr
        raise ValueError(f"{name} must be non-negative and finite{_unit(unit)}, got {_show(bad)}")
    return arr


def in_range(
    name: str, value: ArrayLike, low: float, high: float, unit: str = ""
) -> NDArray[np.float64]:
    """Float array with every entry in the closed interval [low, high]."""
    arr = as_float_array(name, value)
    ok = np.isfinite(arr) & (arr >= low) & (arr <= high)
    if not np.all(ok):
        bad = arr[~ok] if arr.ndim else arr
        raise ValueError(
            f"{name} must be between {low:g} and {high:g}{_unit(unit)}, got {_show(bad)}"
        )
    return arr


MAX_PHASE = 1e9
"""Largest spin × flight time, rad. The face depends on the phase ωp T modulo 2π: beyond 1e9 rad
(1.6e8 turns) float64 keeps fewer than 7 digits of it, and overflow waits further on."""


def phase_budget(spin: float, flight_time: float, what: str = "spin × flight time") -> None:
    """ValueError unless |spin| × flight time ≤ :data:`MAX_PHASE` (rad/s × s)."""
    with np.errstate(over="ignore"):
        phase = float(np.abs(np.float64(spin)) * np.abs(np.float64(flight_time)))
    if not phase <= MAX_PHASE:
        got, most = over_limit(phase, MAX_PHASE)
        raise ValueError(
            f"{what} must be at most {most} rad, got {got} rad "
            f"({quantity(significant(abs(float(spin))))} rad/s for "
            f"{quantity(significant(abs(float(flight_time))))} s): beyond that, "
            "rounding, not physics, would decide the face"
        )


def choice(name: str, value: object, allowed: Iterable[str]) -> str:
    """``value`` if it is one of ``allowed`` strings, else ValueError listing them."""
    allowed = list(allowed)
    if not isinstance(value, str) or value not in allowed:
        raise ValueError(f"{name} must be one of {', '.join(allowed)}; got {value!r}")
    return value


def known(what: str, name: str, table: Mapping[str, T]) -> T:
    """``table[name]``, else ValueError "unknown <what> 'name' (did you mean …?); known <what>s:
    …" with the closest known name (difflib)."""
    try:
        return table[name]
    except KeyError:
        hint = difflib.get_close_matches(str(name), table, n=1)
        maybe = f" (did you mean {hint[0]}?)" if hint else ""
        raise ValueError(
            f"unknown {what} {name!r}{maybe}; known {what}s: {', '.join(table)}"
        ) from None


def _unit(unit: str) -> str:
    return f" (in {unit})" if unit else ""


EXACT_BELOW = 10**15
"""Counts and amounts below this print in full (:func:`quantity`); float64 holds every integer
up to 2**53 ≈ 9.0e15 exactly."""


def quantity(x: float | int, decimals: int = 0) -> str:
    """A count or an amount for a message, the one format of every refusal of over-large work.

    Whole numbers below :data:`EXACT_BELOW` in full with thousands separators (``2,001``,
    ``1,000,000,000,000``); a fraction with 3 significant digits or ``decimals`` decimals,
    whichever shows more (``1,667`` for 1667.3, ``1.5``, ``0.125``; ``2,000.3`` with 1); from
    :data:`EXACT_BELOW` up in scientific notation with 3 + ``decimals`` significant digits
    (``9.22e+18``), a Python integer beyond float range too (``1.15e+602``). Trailing zeros
    are dropped, and a float never shows more digits than its shortest round-trip form
    (``repr``: 0.3 with 14 decimals reads ``0.3``, not ``0.29999999999999999``).
    :func:`over_limit` picks ``decimals``.
    """
    if isinstance(x, int | np.integer) and not isinstance(x, bool | np.bool_):
        whole = int(x)
        if abs(whole) < EXACT_BELOW:
            return f"{whole:,}"
        return _trimmed(f"{Decimal(whole):.{2 + decimals}e}")
    x = float(x)
    if not math.isfinite(x):
        return str(x)
    if abs(x) >= EXACT_BELOW:
        text = _trimmed(f"{x:.{2 + decimals}e}")
    elif x.is_integer():
        return f"{int(x):,}"
    elif abs(x) >= 1.0:
        places = max(decimals, 2 - math.floor(math.log10(abs(x))))
        text = _trimmed(f"{x:,.{places}f}")
    else:
        text = _trimmed(f"{x:.{3 + decimals}g}")
    shortest = repr(x) if not 1.0 <= abs(x) < EXACT_BELOW else f"{Decimal(repr(x)):,f}"
    # As many digits as the shortest form but not the same float (a tie rounded the other
    # way: 2⁻²⁴ to 16 digits is "…062e-08", another float): the shortest form.
    if _digits(text) > _digits(shortest) or (
        _digits(text) == _digits(shortest) and float(_read(text)) != x
    ):
        return shortest
    return text


def _digits(text: str) -> int:
    """How many significant digits the number ``text`` shows."""
    return len(_read(text).normalize().as_tuple().digits)


def significant(x: float, digits: int = 3) -> float:
    """``x`` rounded to ``digits`` significant digits: how an estimate is quoted (an estimated
    number of steps, seconds of work, a spin), ``94,300,000`` rather than ``94,308,161``."""
    return float(f"{x:.{digits}g}") if math.isfinite(x) else x


def _trimmed(text: str) -> str:
    """``text`` without the trailing zeros of its decimals ('2,000.30' → '2,000.3',
    '1.000e+15' → '1e+15')."""
    mantissa, e, exponent = text.partition("e")
    if "." in mantissa:
        mantissa = mantissa.rstrip("0").rstrip(".")
    return mantissa + e + exponent


def _read(text: str) -> Decimal:
    """The number ``text`` shows, exactly (an integer beyond 2**53 too)."""
    return Decimal(text.replace(",", ""))


def shortened(text: str, limit: int = 200) -> str:
    """``text`` whole up to ``limit`` characters, else its start and end around an ellipsis:
    how a message repeats a value the user gave (a 100 kB value, a path over the system's
    limit) without repeating all of it."""
    if len(text) <= limit:
        return text
    keep = (limit - 1) // 2
    return f"{text[:keep]}…{text[len(text) - keep :]}"


def over_limit(amount: float | int, limit: float | int) -> tuple[str, str]:
    """``amount`` and ``limit`` for a refusal (:func:`quantity`), with as few digits as make
    them read as different numbers in their order: an amount above its limit never prints as
    the limit or below it.

    An integer amount is an exact count and prints in full (``2,001`` against ``2,000``); a
    float amount is an estimate and prints with 3 significant digits (:func:`significant`,
    ``94,300,000`` steps), widened only as far as it takes to tell it from the limit (2000.3
    against 2000 reads ``2,000.3``, not ``2,000``), never beyond its shortest round-trip form
    (``repr``)."""
    counted = isinstance(amount, int | np.integer) and not isinstance(amount, bool | np.bool_)
    for extra in range(18):
        rounded = amount if counted else significant(float(amount), 3 + extra)
        shown = quantity(rounded, extra), quantity(limit, extra)
        apart = _read(shown[0]) != _read(shown[1])
        if amount == limit or (apart and (_read(shown[0]) > _read(shown[1])) == (amount > limit)):
            return shown  # alike only when equal, and in the same order as the two values
    return repr(amount), repr(limit)  # pragma: no cover - 17 digits part any two floats


def estimate(x: float) -> str:
    """An estimate (a rate, a duration) for a message: two significant digits, from 10 up
    printed as a whole number (:func:`quantity`: ``120``, ``25,000,000``), below 10 as is
    (``1.5``, ``0.25``)."""
    rounded = float(f"{x:.2g}")
    return quantity(rounded) if abs(rounded) >= 10.0 else f"{x:.2g}"


def duration(seconds: float) -> str:
    """A time for a message: '40 s', '12 min', '3.5 h', '45 days', '2,100 years'."""
    for size, unit, below in (
        (1, "s", 120),
        (60, "min", 120),
        (3600, "h", 48),
        (86400, "days", 730),
    ):
        if seconds / size < below:
            return f"{estimate(seconds / size)} {unit}"
    return f"{estimate(seconds / (365.25 * 86400))} years"


def work_bound(
    what: str,
    amount: float | int,
    limit: float,
    unit: str,
    way_on: str,
    rate: float | None = None,
) -> None:
    """The one refusal of over-large work, raised before anything is allocated or computed.

    ValueError unless ``amount`` ≤ ``limit`` (both in ``unit``: tosses, configurations,
    frames, bytes). The message names the request (``what``), the estimate (with the time at
    ``rate`` units a second on the reference 2-core machine, when given), the limit and the way
    on, the amounts as :func:`over_limit` prints them (in full below 10^15, never alike)::

        monte-carlo with n = 9223372036854775808 is 9.22e+18 tosses (about 12,000 years at
        25,000,000 tosses/s), more than the limit of 90,000,000,000 tosses (about 60 min); use
        a smaller n (the standard error is at most 0.5/√n)

    An integer beyond float range counts as infinite work (no OverflowError) and prints as
    itself (``1.15e+602``).
    """
    if amount <= limit:  # Python compares an int with a float exactly, at any size
        return
    try:
        work = float(amount)
    except OverflowError:  # an int beyond float range: refused like any other
        work = math.inf
    timing = limit_time = ""
    if rate:
        took, most_took = duration(work / rate), duration(limit / rate)
        at = f" at {estimate(rate)} {unit}/s"
        if took == most_took:  # two alike durations: the limit's alone
            limit_time = f" (about {most_took}{at})"
        else:
            timing, limit_time = f" (about {took}{at})", f" (about {most_took})"
    shown, most = over_limit(amount, limit)
    raise ValueError(
        f"{what} is {shown} {unit}{timing}, more than the limit of {most} {unit}"
        f"{limit_time}; {way_on}"
    )


UNREADABLE = {
    "float_parsing": "is not a number",
    "int_parsing": "is not a valid integer",
    "int_from_float": "is not a valid integer",
    "bool_parsing": "is not a valid boolean",
}
"""The words for a text that cannot be read as an option's type, by pydantic's error type
(typer and FastAPI both read options through pydantic): the command line and the web say
``Invalid value for '--seed': 'nan' is not a valid integer``, never pydantic's own
sentence."""
_BOUNDS = {
    "greater_than_equal": ("ge", "at least"),
    "greater_than": ("gt", "above"),
    "less_than_equal": ("le", "at most"),
    "less_than": ("lt", "below"),
}


def unreadable(error: Mapping[str, object]) -> str | None:
    """What is wrong with an option's text, from pydantic's first error about it (a mapping
    with ``type``, ``input`` and ``ctx``), in the words of :data:`UNREADABLE` or a bound
    (``'-1' must be at least 1``); None for an error of another kind."""
    kind = str(error.get("type"))
    text = error.get("input")
    if kind in UNREADABLE:
        return f"{text!r} {UNREADABLE[kind]}"
    if kind in _BOUNDS:
        key, words = _BOUNDS[kind]
        ctx = error.get("ctx")
        bound = ctx.get(key) if isinstance(ctx, Mapping) else None
        if bound is not None:
            return f"{text!r} must be {words} {bound}"
    return None


MAX_RUN_SECONDS = 3600.0
"""Longest run a size may ask for, s on the reference 2-core machine: Monte Carlo and QMC
tosses, table landings, convergence series (the grid keeps its own minute,
:data:`coinflight.probability.grid.MAX_WORK`)."""
