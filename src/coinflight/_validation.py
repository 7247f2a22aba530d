"""Checks shared by every value object: one wording for every error a user can meet."""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np
from numpy.typing import ArrayLike, NDArray


def _show(value: object) -> str:
    """A value for a message: one number as a plain number (200.0), several as an array."""
    arr = np.asarray(value)
    if arr.size == 1:
        return repr(arr.reshape(-1)[0].item())
    return np.array2string(arr, threshold=6)


def as_float_array(name: str, value: ArrayLike) -> NDArray[np.float64]:
    """``value`` as a float array, or TypeError naming ``name``."""
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be a number or an array of numbers, got {value!r}") from None
    return arr


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
        raise ValueError(
            f"{what} must be at most {MAX_PHASE:.0e} rad, got {phase:.3g} rad "
            f"({abs(float(spin)):.3g} rad/s for {abs(float(flight_time)):.3g} s): beyond that, "
            "rounding, not physics, would decide the face"
        )


def choice(name: str, value: object, allowed: Iterable[str]) -> str:
    """``value`` if it is one of ``allowed`` strings, else ValueError listing them."""
    allowed = list(allowed)
    if not isinstance(value, str) or value not in allowed:
        raise ValueError(f"{name} must be one of {', '.join(allowed)}; got {value!r}")
    return value


def _unit(unit: str) -> str:
    return f" (in {unit})" if unit else ""
