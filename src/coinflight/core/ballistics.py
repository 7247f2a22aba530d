"""Vertical flight of the centre of mass under gravity, without drag."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray


def flight_time(launch_speed: ArrayLike, g: ArrayLike) -> NDArray[np.float64]:
    """Time to come back to launch height, T = 2 v0 / g (s). Stefan & Cheche eq 11."""
    return 2.0 * np.asarray(launch_speed, dtype=float) / np.asarray(g, dtype=float)


def launch_speed(flight_time: ArrayLike, g: ArrayLike) -> NDArray[np.float64]:
    """Launch speed v0 = g T / 2 (m/s) that brings the coin back to launch height after T."""
    return 0.5 * np.asarray(g, dtype=float) * np.asarray(flight_time, dtype=float)


def height(launch_speed: ArrayLike, g: ArrayLike, t: ArrayLike) -> NDArray[np.float64]:
    """Height of the centre of mass above the launch point, z(t) = v0 t − g t²/2 (m)."""
    v0 = np.asarray(launch_speed, dtype=float)
    t = np.asarray(t, dtype=float)
    return v0 * t - 0.5 * np.asarray(g, dtype=float) * t * t
