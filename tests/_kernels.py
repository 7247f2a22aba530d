"""A coin's kernel records for the tests of core's landing and air kernels: the contact record
through the library's :func:`coinflight.outcomes.table.contact_record` (as every landing builds
it), ``Air.build``'s keyword list filled from a :class:`coinflight.Coin` once, here, and the
contact state y = (z, v, n, L) of a coin touching the table (one builder for the tests of the
rigid ending's contact and the benchmarks' face predictors)."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from coinflight import Coin
from coinflight.core import bounce, drag
from coinflight.core.contact import Contact
from coinflight.core.impact import CONTACT_DURATION, lowest_depth
from coinflight.model.surface import Surface
from coinflight.outcomes.table import contact_record

G = 9.81


def coin_contact(
    coin: Coin,
    *,
    restitution: float = 0.5,
    friction: float = 0.3,
    drop_height: float = 0.8,
    g: float = G,
    rest_speed: float = bounce.REST_SPEED,
    rolling_resistance: float = 0.0,
    pivoting_resistance: float = 0.0,
    corner_radius: float | None = None,
) -> Contact:
    """The contact record of ``coin`` on a table with these values (``corner_radius``, when
    given, replaces the coin's), built by :func:`coinflight.outcomes.table.contact_record`."""
    if corner_radius is not None:
        coin = coin.with_corner_radius(corner_radius)
    surface = Surface(
        "table",
        drop_height,
        restitution,
        friction,
        rolling_resistance,
        pivoting_resistance,
    )
    return contact_record(coin, surface, g, rest_speed=rest_speed)


def impact_record(
    coin: Coin,
    restitution: float,
    friction: float,
    *,
    corner_radius: float = 0.0,
    contact_duration: float | None = None,
) -> Contact:
    """The contact record one impact reads (:func:`coinflight.core.impact.impact`): ``coin``'s
    r, h/2, m, I1, I3, e, μ, the corner radius (0, sharp, by default, whatever the coin's) and
    t_c (:data:`coinflight.core.impact.CONTACT_DURATION` by default; 0: the lowest point
    alone). Built directly, not through a Surface nor ``Contact.build``: the impact law's tests
    take values a table refuses (μ = 10, t_c = 0, a corner rounding the coin into a ball)."""
    i1, i3 = coin.moments
    return Contact(
        radius=coin.radius,
        half_thickness=0.5 * coin.thickness,
        mass=coin.mass,
        i1=float(i1),
        i3=float(i3),
        restitution=float(restitution),
        friction=float(friction),
        drop_height=0.0,
        g=G,
        rest_speed=bounce.REST_SPEED,
        reach=math.nan,  # the wells' fields, which no impact reads (a ball has none)
        edge_sine=math.nan,
        barrier=math.nan,
        corner_radius=float(corner_radius),
        contact_duration=CONTACT_DURATION if contact_duration is None else contact_duration,
    )


def coin_air(
    coin: Coin,
    *,
    drag_coefficient: float = 0.0,
    spin_damping: float = 0.0,
    air_density: float = 1.2,
    g: float = G,
    **options: Any,
) -> drag.Air:
    """``Air.build`` for ``coin``; ``options`` are its other keywords (``projected``)."""
    i1, i3 = coin.moments
    return drag.Air.build(
        mass=coin.mass,
        radius=coin.radius,
        thickness=coin.thickness,
        i1=float(i1),
        i3=float(i3),
        g=g,
        drag_coefficient=drag_coefficient,
        spin_damping=spin_damping,
        air_density=air_density,
        **options,
    )


def critical_spin(coin: Coin, g: float = G) -> float:
    """Ω_c of a disc rolling upright on a knife edge: upright rolling is stable for Ω > Ω_c,
    Ω_c² = m g r I1 / (I3 (I3 + m r²)) (Routh; O'Reilly, Nonlinear Dyn. 10:287, 1996;
    g / 3r for a thin uniform disc). Shared by the rigid contact's tests."""
    i1, i3 = (float(x) for x in coin.moments)
    m, r = coin.mass, coin.radius
    return math.sqrt(m * g * r * i1 / (i3 * (i3 + m * r * r)))


def touching_state(
    coin: Coin,
    tilt: float,
    azimuth: float = 0.0,
    v: Sequence[float] = (0.0, 0.0, 0.0),
    omega: Sequence[float] = (0.0, 0.0, 0.0),
    lift: float = 0.0,
) -> np.ndarray:
    """The contact phase's y = (z, v, n, L) of ``coin`` with its heads normal
    n = (sin tilt cos azimuth, sin tilt sin azimuth, cos tilt), its lowest point (sharp rim,
    :func:`coinflight.core.impact.lowest_depth`) ``lift`` m above the table (negative: pressed
    in), lab velocity ``v`` and lab angular velocity ``omega`` (L = I1 ω + (I3 − I1)(ω·n) n)."""
    n = np.array(
        [math.sin(tilt) * math.cos(azimuth), math.sin(tilt) * math.sin(azimuth), math.cos(tilt)]
    )
    i1, i3 = (float(x) for x in coin.moments)
    w = np.asarray(omega, dtype=float)
    lm = i1 * w + (i3 - i1) * (w @ n) * n
    z = lowest_depth(n[2], coin.radius, coin.thickness / 2) + lift
    return np.array([z, *v, *n, *lm])
