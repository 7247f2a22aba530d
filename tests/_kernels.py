"""A coin's kernel records for the tests of core's landing and air kernels: the keyword lists
of ``Contact.build`` and ``Air.build`` filled from a :class:`coinflight.Coin` once, here."""

from __future__ import annotations

from typing import Any

from coinflight import Coin
from coinflight.core import bounce, drag
from coinflight.core.contact import Contact

G = 9.81


def coin_contact(
    coin: Coin,
    *,
    restitution: float = 0.5,
    friction: float = 0.3,
    drop_height: float = 0.8,
    g: float = G,
    rest_speed: float = bounce.REST_SPEED,
    **options: Any,
) -> Contact:
    """``Contact.build`` for ``coin`` (its radius, thickness, mass and moments); ``options``
    are its other keywords (``rolling_resistance``, ``ending``, ``corner_radius``, …)."""
    i1, i3 = coin.moments
    return Contact.build(
        radius=coin.radius,
        thickness=coin.thickness,
        mass=coin.mass,
        i1=float(i1),
        i3=float(i3),
        restitution=restitution,
        friction=friction,
        drop_height=drop_height,
        g=g,
        rest_speed=rest_speed,
        **options,
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
